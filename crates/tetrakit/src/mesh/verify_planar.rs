//! The certificate check of a planar triangulation: the 2D counterpart of
//! [`super::verify`], with the same degree argument (boundary edges on the hull, no two
//! boundary edges overlapping on one hull edge, edges shared by two triangles on opposite
//! sides, every point a vertex).

use super::report::{Problem, ProblemKind, Report};
use crate::geom::{Hull2, Point2, orient2d};
use crate::numbering::ids;
use rayon::prelude::*;

/// Verifies that counter-clockwise triangles `tris` triangulate the convex hull of
/// `points` with every point a vertex.
///
/// ```
/// use tetrakit::mesh::verify_triangulation;
/// let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// assert!(verify_triangulation(&pts, &[[0, 1, 2], [0, 2, 3]]).is_valid());
/// assert!(!verify_triangulation(&pts, &[[0, 1, 2]]).is_valid());
/// ```
pub fn verify_triangulation(points: &[Point2], tris: &[[u32; 3]]) -> Report {
    let mut r = Report::default();
    let n = points.len() as u32;
    for (i, t) in tris.iter().enumerate() {
        let i = i as u32;
        if t.iter().any(|&v| v >= n) || t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            r.push(Problem::new(
                ProblemKind::BadIndex,
                vec![i],
                t.to_vec(),
                format!("triangle T{i} {} has a bad or repeated vertex", ids(t)),
            ));
            return r;
        }
        let p = |k: usize| &points[t[k] as usize];
        match orient2d(p(0), p(1), p(2)) {
            1 => {}
            0 => r.push(Problem::new(
                ProblemKind::Degenerate,
                vec![i],
                t.to_vec(),
                format!("triangle T{i} {} is degenerate", ids(t)),
            )),
            _ => r.push(Problem::new(
                ProblemKind::Inverted,
                vec![i],
                t.to_vec(),
                format!("triangle T{i} {} is clockwise", ids(t)),
            )),
        }
    }
    let boundary = pair_sides(tris, &mut |(a, b), [u, t]| {
        r.push(Problem::new(
            ProblemKind::SameSide,
            vec![u, t],
            vec![a, b],
            format!("triangles T{u} and T{t} lie on the same side of edge (#{a}, #{b})"),
        ))
    });
    r.boundary_faces = boundary.len();
    let hull = Hull2::new(points);
    let sides_of = hull_sides(points, &hull);
    let on_hull_edge = |a: u32, b: u32| {
        let [sa, sb] = [sides_of[a as usize], sides_of[b as usize]];
        sa.into_iter().find(|&k| k != NO_SIDE && sb.contains(&k))
    };
    let sides: Vec<Option<u32>> = boundary
        .iter()
        .map(|&(a, b, _)| on_hull_edge(a, b))
        .collect();
    for (&(a, b, t), s) in boundary.iter().zip(&sides) {
        if s.is_none() {
            r.push(Problem::new(ProblemKind::BoundaryNotOnHull, vec![t], vec![a, b], format!("edge (#{a}, #{b}) of triangle T{t} has no neighbour but is not on the convex hull")));
        }
    }
    let mut used = vec![false; points.len()];
    tris.iter().flatten().for_each(|&v| used[v as usize] = true);
    for v in (0..n).filter(|&v| !used[v as usize]) {
        r.push(Problem::new(
            ProblemKind::UnusedVertex,
            vec![],
            vec![v],
            format!("point #{v} is not a vertex of any triangle"),
        ));
    }
    if r.is_valid() && !boundary.is_empty() {
        let (a0, b0, t0) = boundary[0];
        let key = |v: u32| {
            let p = points[v as usize];
            (p[0], p[1])
        };
        let span = |a: u32, b: u32| {
            let (x, y) = (key(a), key(b));
            if x.0 != y.0 {
                (x.0.min(y.0), x.0.max(y.0))
            } else {
                (x.1.min(y.1), x.1.max(y.1))
            }
        };
        let s0 = span(a0, b0);
        for (&(a, b, t), s) in boundary.iter().zip(&sides).skip(1) {
            let sp = span(a, b);
            if *s == sides[0] && sp.0.max(s0.0) < sp.1.min(s0.1) {
                r.push(Problem::new(ProblemKind::Overlap, vec![t0, t], vec![a0, b0, a, b], format!("boundary edges (#{a0}, #{b0}) and (#{a}, #{b}) overlap, so triangles T{t0} and T{t} overlap")));
            }
        }
    }
    r
}

/// Pairs the triangle sides: `same_side((a, b), [u, t])` for each repeat of a directed
/// side `a → b` (triangles `u`, `t` on the same side of it), and returns the boundary
/// sides, those whose reverse is in no triangle, as `(a, b, triangle)`.
///
/// One parallel sort of the sides by undirected edge, then one pass.
fn pair_sides(
    tris: &[[u32; 3]],
    same_side: &mut dyn FnMut((u32, u32), [u32; 2]),
) -> Vec<(u32, u32, u32)> {
    // (low end, high end, walked from high to low, triangle)
    let mut sides: Vec<(u32, u32, bool, u32)> = (tris.par_iter().enumerate())
        .flat_map_iter(|(i, t)| {
            (0..3).map(move |k| {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                (a.min(b), a.max(b), a > b, i as u32)
            })
        })
        .collect();
    sides.par_sort_unstable();
    let mut boundary = Vec::new();
    for group in sides.chunk_by(|x, y| (x.0, x.1) == (y.0, y.1)) {
        let split = group.partition_point(|x| !x.2);
        let (up, down) = group.split_at(split);
        for (dir, other) in [(up, down), (down, up)] {
            let Some(&(lo, hi, back, t)) = dir.first() else {
                continue;
            };
            let ab = if back { (hi, lo) } else { (lo, hi) };
            if other.is_empty() {
                boundary.push((ab.0, ab.1, t));
            }
            for w in dir.windows(2) {
                same_side(ab, [w[0].3, w[1].3]);
            }
        }
    }
    boundary
}

/// Marks a point on no hull edge.
const NO_SIDE: u32 = u32::MAX;

/// For each point, the hull edges (`vertices[k] → vertices[k+1]`, as `k`) it lies on:
/// two for a hull vertex, one for another boundary point, none inside.
fn hull_sides(points: &[Point2], hull: &Hull2) -> Vec<[u32; 2]> {
    let mut sides = vec![[NO_SIDE; 2]; points.len()];
    for (k, chain) in hull.boundary_chains(points).iter().enumerate() {
        for &v in chain {
            let s = &mut sides[v as usize];
            let slot = usize::from(s[0] != NO_SIDE);
            s[slot] = k as u32;
        }
    }
    sides
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::Control;
    use crate::planar::MwtOptions;
    use crate::planar::{Distribution, mwt, points2d};

    fn has(r: &Report, kind: ProblemKind) -> bool {
        r.problems.iter().any(|p| p.kind == kind)
    }

    /// Minimum weight triangulations (collinear hull points on grids, cocircular
    /// sites) pass; a repeated, a missing or a clockwise triangle is named.
    #[test]
    fn triangulations_pass_and_defects_are_named() {
        use Distribution::*;
        for dist in [Uniform, Grid, Convex, Regular, Clustered] {
            let pts = points2d(dist, 60, 1);
            let t = mwt(&pts, &MwtOptions::default(), &Control::new())
                .unwrap()
                .triangles;
            let r = verify_triangulation(&pts, &t);
            assert!(r.is_valid(), "{dist:?}");
            assert_eq!(
                r.boundary_faces,
                Hull2::new(&pts)
                    .boundary_chains(&pts)
                    .iter()
                    .map(|c| c.len() - 1)
                    .sum::<usize>()
            );
            let mut twice = t.clone();
            twice.push(t[7]);
            assert!(has(
                &verify_triangulation(&pts, &twice),
                ProblemKind::SameSide
            ));
            let mut missing = t.clone();
            missing.remove(7);
            assert!(has(
                &verify_triangulation(&pts, &missing),
                ProblemKind::BoundaryNotOnHull
            ));
            let mut flipped = t.clone();
            flipped[7].swap(0, 1);
            assert!(has(
                &verify_triangulation(&pts, &flipped),
                ProblemKind::Inverted
            ));
        }
    }
}
