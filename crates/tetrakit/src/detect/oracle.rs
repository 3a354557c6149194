//! A brute-force oracle, independent of the link algorithm, for differential tests.
//!
//! Following Theorem 2.1's facet viewpoint: collect every non-degenerate tetrahedron whose
//! six edges are segments and which is *L-empty* (no segment meets its interior, no other
//! point lies in it); `L` forms a tetrahedralization exactly when these tetrahedra pass the
//! verifier and have `L` as their edge set. (If `L` is the edge set of a tetrahedralization
//! `T`, an L-empty tetrahedron on its vertices cannot be cut by a face of `T`, so it is a
//! tetrahedron of `T`.) Planar input uses L-empty triangles the same way.
//! `O(n^4 m)`: for small inputs only.

use crate::geom::{
    Hull3, Point3, orient2d, orient3d, point_in_closed_tetrahedron, segment_meets_open_tetrahedron,
    segment_meets_open_triangle,
};
use crate::mesh::{edges_of, verify, verify_triangulation};

/// True when `segments` is exactly the edge set of a tetrahedralization of `points` (or,
/// for coplanar points, of a triangulation), by brute force.
///
/// ```
/// use tetrakit::detect::oracle::forms_tetrahedralization;
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let all = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
/// assert!(forms_tetrahedralization(&pts, &all));
/// assert!(!forms_tetrahedralization(&pts, &all[1..]));
/// ```
pub fn forms_tetrahedralization(points: &[Point3], segments: &[[u32; 2]]) -> bool {
    let n = points.len();
    let mut adj = vec![false; n * n];
    for &[a, b] in segments {
        adj[a as usize * n + b as usize] = true;
        adj[b as usize * n + a as usize] = true;
    }
    let mut want: Vec<[u32; 2]> = segments
        .iter()
        .map(|&[a, b]| [a.min(b), a.max(b)])
        .collect();
    want.sort_unstable();
    let hull = Hull3::new(points);
    let e = |a: usize, b: usize| adj[a * n + b];
    let pt = |i: usize| &points[i];
    match hull.dimension {
        3 => {
            let mut tets = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    if !e(a, b) {
                        continue;
                    }
                    for c in b + 1..n {
                        if !(e(a, c) && e(b, c)) {
                            continue;
                        }
                        for d in c + 1..n {
                            if !(e(a, d) && e(b, d) && e(c, d)) {
                                continue;
                            }
                            let o = orient3d(pt(a), pt(b), pt(c), pt(d));
                            if o == 0 {
                                continue;
                            }
                            let t = [*pt(a), *pt(b), *pt(c), *pt(d)];
                            let empty = segments.iter().all(|&[p, q]| {
                                !segment_meets_open_tetrahedron(pt(p as usize), pt(q as usize), &t)
                            }) && (0..n)
                                .all(|x| !point_in_closed_tetrahedron(pt(x), &t));
                            if empty {
                                let (a, b, c, d) = (a as u32, b as u32, c as u32, d as u32);
                                tets.push(if o > 0 { [a, b, c, d] } else { [a, b, d, c] });
                            }
                        }
                    }
                }
            }
            verify(points, &tets, Some(&hull)).is_valid() && edges_of(&tets) == want
        }
        2 => {
            let Some(p2) = crate::geom::project_to_plane(points) else {
                return false;
            };
            let mut tris = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    if !e(a, b) {
                        continue;
                    }
                    for c in b + 1..n {
                        if !(e(a, c) && e(b, c)) {
                            continue;
                        }
                        let o = orient2d(&p2[a], &p2[b], &p2[c]);
                        if o == 0 {
                            continue;
                        }
                        let empty = segments.iter().all(|&[p, q]| {
                            !segment_meets_open_triangle(
                                pt(p as usize),
                                pt(q as usize),
                                pt(a),
                                pt(b),
                                pt(c),
                            )
                        }) && (0..n).filter(|&x| x != a && x != b && x != c).all(|x| {
                            let s = [
                                orient2d(&p2[a], &p2[b], &p2[x]),
                                orient2d(&p2[b], &p2[c], &p2[x]),
                                orient2d(&p2[c], &p2[a], &p2[x]),
                            ];
                            !s.iter().all(|&si| si * o >= 0)
                        });
                        if empty {
                            let (a, b, c) = (a as u32, b as u32, c as u32);
                            tris.push(if o > 0 { [a, b, c] } else { [a, c, b] });
                        }
                    }
                }
            }
            let mut te: Vec<[u32; 2]> = tris
                .iter()
                .flat_map(|t| {
                    [(t[0], t[1]), (t[1], t[2]), (t[0], t[2])].map(|(x, y)| [x.min(y), x.max(y)])
                })
                .collect();
            te.sort_unstable();
            te.dedup();
            verify_triangulation(&p2, &tris).is_valid() && te == want
        }
        _ => false,
    }
}

/// The Delaunay tetrahedra of points with no five on a sphere and no four in a plane: every
/// positively oriented `abcd` whose circumsphere has no point strictly inside, by brute
/// force (`O(n^5)`; for tests of the Delaunay route of [`super::detect`]). `None` when the
/// points are not in that general position.
///
/// ```
/// use tetrakit::detect::oracle::delaunay_tetrahedra;
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.1]];
/// assert_eq!(delaunay_tetrahedra(&pts).unwrap().len(), 2);
/// ```
pub fn delaunay_tetrahedra(points: &[Point3]) -> Option<Vec<[u32; 4]>> {
    let n = points.len() as u32;
    let p = |i: u32| &points[i as usize];
    let mut tets = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                for d in c + 1..n {
                    let t = match orient3d(p(a), p(b), p(c), p(d)) {
                        1 => [a, b, c, d],
                        -1 => [a, c, b, d],
                        _ => return None,
                    };
                    let mut empty = true;
                    for e in (0..n).filter(|e| !t.contains(e)) {
                        match crate::geom::insphere(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e)) {
                            1 => empty = false,
                            0 => return None,
                            _ => {}
                        }
                    }
                    if empty {
                        tets.push(t);
                    }
                }
            }
        }
    }
    Some(tets)
}
