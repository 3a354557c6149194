//! An anchor: a point that every tetrahedralization covers with exactly one tetrahedron,
//! for the exact solver's point-set formula and the enumeration of tetrahedralizations.

use super::{Point3, orient2d_drop, orient3d, projection_axis};
use crate::rng::Rng;

/// A point strictly inside one of `tets` and on none of `triangles` (closed), found by
/// seeded random barycentric weights and checked exactly: when `tets` are every empty
/// tetrahedron of a point set and `triangles` their faces, the point is interior to
/// exactly one tetrahedron of every tetrahedralization of the set. Returns the indices of
/// the tetrahedra containing it; `None` when 200 tries fail (not expected).
pub(crate) fn anchor(
    pts: &[Point3],
    tets: &[[u32; 4]],
    triangles: &[[u32; 3]],
) -> Option<Vec<u32>> {
    let mut rng = Rng::new(0x5eed);
    for attempt in 0..200 {
        let t = tets.get(if attempt == 0 {
            0
        } else {
            rng.below(tets.len())
        })?;
        let geo = t.map(|v| pts[v as usize]);
        let w: [f64; 4] = if attempt == 0 {
            [0.25; 4]
        } else {
            let r = [0, 1, 2, 3].map(|_| 0.5 + rng.unit());
            let s: f64 = r.iter().sum();
            r.map(|x| x / s)
        };
        let x: Point3 = [0, 1, 2].map(|i| (0..4).map(|k| w[k] * geo[k][i]).sum());
        if !strictly_inside(&x, &geo) {
            continue;
        }
        let on_triangle = triangles.iter().any(|f| {
            let [a, b, cc] = f.map(|v| &pts[v as usize]);
            orient3d(a, b, cc, &x) == 0 && in_closed_triangle(&x, a, b, cc)
        });
        if on_triangle {
            continue;
        }
        let holders = tets
            .iter()
            .enumerate()
            .filter(|(_, t)| strictly_inside(&x, &t.map(|v| pts[v as usize])))
            .map(|(i, _)| i as u32)
            .collect();
        return Some(holders);
    }
    None
}

fn strictly_inside(x: &Point3, t: &[Point3; 4]) -> bool {
    let s = orient3d(&t[0], &t[1], &t[2], &t[3]);
    [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)]
        .iter()
        .all(|&(a, b, c)| s * orient3d(&t[a], &t[b], &t[c], x) < 0)
}

fn in_closed_triangle(x: &Point3, a: &Point3, b: &Point3, c: &Point3) -> bool {
    let Some(axis) = projection_axis(a, b, c) else {
        return false;
    };
    let s = orient2d_drop(a, b, c, axis);
    [(a, b), (b, c), (c, a)]
        .iter()
        .all(|(p, q)| s * orient2d_drop(p, q, x, axis) >= 0)
}
