//! Triangulations of coplanar points (a polytope's polygon facets), exact.

use super::{Point3, lex_cmp, orient2d_drop, projection_axis};
use crate::rng::Rng;
use std::collections::HashMap;

/// A triangulation of the coplanar points `on` (indices into `points`, spanning a plane)
/// using all of them: the placing triangulation in lexicographic order and, given `rng`,
/// random flips of strictly convex quadrilaterals after. Triangles are counter-clockwise
/// in the projection that drops the plane's `projection_axis`.
///
/// ```
/// use tetrakit::geom::triangulate_coplanar;
/// let square = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0], [1.0, 1.0, 1.0], [0.5, 0.5, 1.0]];
/// assert_eq!(triangulate_coplanar(&square, &[0, 1, 2, 3, 4], None).len(), 4);
/// ```
pub fn triangulate_coplanar(points: &[Point3], on: &[u32], rng: Option<&mut Rng>) -> Vec<[u32; 3]> {
    let p = |v: u32| &points[v as usize];
    let Some(axis) = (0..on.len()).find_map(|i| {
        (i + 1..on.len()).find_map(|j| {
            (j + 1..on.len()).find_map(|k| projection_axis(p(on[i]), p(on[j]), p(on[k])))
        })
    }) else {
        return Vec::new();
    };
    let orient = |a: u32, b: u32, c: u32| orient2d_drop(p(a), p(b), p(c), axis);
    let mut order = on.to_vec();
    order.sort_by(|&a, &b| lex_cmp(p(a), p(b)));
    let mut tris: Vec<[u32; 3]> = Vec::new();
    // The first points may be collinear: fan from the first point off their line.
    let first = (2..order.len())
        .find(|&k| orient(order[0], order[1], order[k]) != 0)
        .expect("the facet's points span a plane");
    for w in order[..first].windows(2) {
        tris.push(ccw(&orient, [w[0], w[1], order[first]]));
    }
    for &v in &order[first + 1..] {
        let boundary = boundary_edges(&tris);
        for (a, b) in boundary {
            if orient(a, b, v) < 0 {
                tris.push([b, a, v]);
            }
        }
    }
    if let Some(rng) = rng {
        for _ in 0..4 * tris.len() {
            random_flip(&mut tris, &orient, rng);
        }
    }
    tris
}

fn ccw(orient: &impl Fn(u32, u32, u32) -> i8, [a, b, c]: [u32; 3]) -> [u32; 3] {
    if orient(a, b, c) > 0 {
        [a, b, c]
    } else {
        [a, c, b]
    }
}

/// The directed edges of counter-clockwise triangles that no other triangle has reversed.
fn boundary_edges(tris: &[[u32; 3]]) -> Vec<(u32, u32)> {
    let mut count: HashMap<(u32, u32), usize> = HashMap::new();
    for t in tris {
        for k in 0..3 {
            *count.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    let mut out: Vec<(u32, u32)> = (count.keys().copied())
        .filter(|&(a, b)| !count.contains_key(&(b, a)))
        .collect();
    out.sort_unstable();
    out
}

/// Flips a random inner edge when its two triangles form a strictly convex quadrilateral.
fn random_flip(tris: &mut [[u32; 3]], orient: &impl Fn(u32, u32, u32) -> i8, rng: &mut Rng) {
    let i = rng.below(tris.len());
    let k = rng.below(3);
    let (a, b, c) = (tris[i][k], tris[i][(k + 1) % 3], tris[i][(k + 2) % 3]);
    let Some(j) = (0..tris.len()).find(|&j| {
        let t = tris[j];
        (0..3).any(|m| t[m] == b && t[(m + 1) % 3] == a)
    }) else {
        return;
    };
    let d = *tris[j]
        .iter()
        .find(|&&x| x != a && x != b)
        .expect("three corners");
    // `ab` crosses `cd` exactly when c and d are strictly apart and a, b too.
    if orient(c, d, a) * orient(c, d, b) < 0 {
        tris[i] = ccw(orient, [a, d, c]);
        tris[j] = ccw(orient, [d, b, c]);
    }
}
