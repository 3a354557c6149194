//! The certificate check of a planar triangulation: the 2D counterpart of
//! [`super::verify`], with the same degree argument (boundary edges on the hull, no two
//! boundary edges overlapping on one hull edge, edges shared by two triangles on opposite
//! sides, every point a vertex).

use super::verify::{Problem, ProblemKind, Report};
use crate::detect::ids;
use crate::geom::{Hull2, Point2, orient2d};

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
    let pb = |kind, t: Vec<u32>, v: Vec<u32>, detail: String| Problem {
        kind,
        tets: t,
        vertices: v,
        detail,
    };
    for (i, t) in tris.iter().enumerate() {
        let i = i as u32;
        if t.iter().any(|&v| v >= n) || t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            r.push(pb(
                ProblemKind::BadIndex,
                vec![i],
                t.to_vec(),
                format!("triangle #{i} {} has a bad or repeated vertex", ids(t)),
            ));
            return r;
        }
        let p = |k: usize| &points[t[k] as usize];
        match orient2d(p(0), p(1), p(2)) {
            1 => {}
            0 => r.push(pb(
                ProblemKind::Degenerate,
                vec![i],
                t.to_vec(),
                format!("triangle #{i} {} is degenerate", ids(t)),
            )),
            _ => r.push(pb(
                ProblemKind::Inverted,
                vec![i],
                t.to_vec(),
                format!("triangle #{i} {} is clockwise", ids(t)),
            )),
        }
    }
    let mut directed: Vec<(u32, u32, u32)> = tris
        .iter()
        .enumerate()
        .flat_map(|(i, t)| (0..3).map(move |k| (t[k], t[(k + 1) % 3], i as u32)))
        .collect();
    directed.sort_unstable();
    let find = |a: u32, b: u32| {
        directed
            .binary_search_by(|e| (e.0, e.1).cmp(&(a, b)))
            .is_ok()
    };
    let mut boundary = Vec::new();
    for (k, &(a, b, t)) in directed.iter().enumerate() {
        if k > 0 && (directed[k - 1].0, directed[k - 1].1) == (a, b) {
            let u = directed[k - 1].2;
            r.push(pb(
                ProblemKind::SameSide,
                vec![u, t],
                vec![a, b],
                format!("triangles #{u} and #{t} lie on the same side of edge (#{a}, #{b})"),
            ));
        } else if !find(b, a) {
            boundary.push((a, b, t));
        }
    }
    r.boundary_faces = boundary.len();
    let hull = Hull2::new(points);
    let h = &hull.vertices;
    let on_hull_edge = |a: u32, b: u32| {
        (0..h.len()).find(|&i| {
            let (x, y) = (
                &points[h[i] as usize],
                &points[h[(i + 1) % h.len()] as usize],
            );
            orient2d(x, y, &points[a as usize]) == 0 && orient2d(x, y, &points[b as usize]) == 0
        })
    };
    let sides: Vec<Option<usize>> = boundary
        .iter()
        .map(|&(a, b, _)| on_hull_edge(a, b))
        .collect();
    for (&(a, b, t), s) in boundary.iter().zip(&sides) {
        if s.is_none() {
            r.push(pb(ProblemKind::BoundaryNotOnHull, vec![t], vec![a, b], format!("edge (#{a}, #{b}) of triangle #{t} has no neighbour but is not on the convex hull")));
        }
    }
    let mut used = vec![false; points.len()];
    tris.iter().flatten().for_each(|&v| used[v as usize] = true);
    for v in (0..n).filter(|&v| !used[v as usize]) {
        r.push(pb(
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
                r.push(pb(ProblemKind::Overlap, vec![t0, t], vec![a0, b0, a, b], format!("boundary edges (#{a0}, #{b0}) and (#{a}, #{b}) overlap, so triangles #{t0} and #{t} overlap")));
            }
        }
    }
    r
}
