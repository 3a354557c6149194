//! Embedding checks for meshes of non-convex domains (no hull to compare with).
//!
//! With oriented-face pairing in place, a mesh is embedded (its tetrahedra do not overlap)
//! when it is injective near every vertex and its boundary surface does not intersect
//! itself: then the mesh is a local homeomorphism that is injective on its boundary. Near a
//! vertex `v`, injectivity means the cones at `v` of the tetrahedra around it do not
//! overlap: for an interior vertex the covering degree of its link is constant, so one cone
//! against all others decides; a boundary vertex's cones are tested pairwise.
//!
//! **Nested components.** Local injectivity and an embedded boundary still allow a
//! separate piece of mesh inside another (two boundary components nested with the same
//! orientation). The covering number (how many tetrahedra contain a point) is constant
//! off the boundary, since paired faces keep it, and rises by one across a boundary face
//! from its outer to its inner side. So the mesh is embedded exactly when it is 0 just
//! outside every boundary component. If it is not 0 just outside a component `S`, a
//! tetrahedron `T` covers points just outside `S` next to any vertex `v` of `S`, so `v`
//! lies in the closed `T`, and `T` is not incident to `v` (the star of `v` lies inside
//! `S` near `v`, by local injectivity). In a valid mesh no vertex lies in a closed
//! tetrahedron other than as its corner, so [`nested_overlaps`] tests one vertex per
//! component against every tetrahedron near it, exactly.

use super::grid::{Aabb, TriangleGrid, aabb, boxes_meet};
use super::report::{Problem, ProblemKind};
use crate::geom::{Point3, cones_overlap, point_in_closed_tetrahedron};
use crate::numbering::ids;
use crate::partition;
use rayon::prelude::*;

/// Overlaps near vertices. `tets` are positively oriented (degenerate ones are skipped by
/// the caller); `on_boundary[v]` tells whether `v` is a vertex of a boundary face; only
/// the vertices `v` with `which(v)` are tested.
pub(super) fn vertex_overlaps(
    points: &[Point3],
    tets: &[[u32; 4]],
    on_boundary: &[bool],
    which: &(dyn Fn(usize) -> bool + Sync),
) -> Vec<Problem> {
    let n = points.len();
    let mut start = vec![0usize; n + 1];
    for t in tets {
        for &v in t {
            start[v as usize + 1] += 1;
        }
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut star = vec![0u32; start[n]];
    for (i, t) in tets.iter().enumerate() {
        for &v in t {
            star[fill[v as usize]] = i as u32;
            fill[v as usize] += 1;
        }
    }
    (0..n)
        .into_par_iter()
        .filter(|&v| which(v))
        .filter_map(|v| {
            let around = &star[start[v]..start[v + 1]];
            let cone = |t: u32| {
                let tet = tets[t as usize];
                let k = tet.iter().position(|&x| x as usize == v).unwrap_or(0);
                std::array::from_fn(|i| points[tet[(k + 1 + i) % 4] as usize])
            };
            let caps: Vec<Cap> = around
                .iter()
                .map(|&t| Cap::new(&points[v], &cone(t)))
                .collect();
            let firsts = if on_boundary[v] {
                around.len()
            } else {
                around.len().min(1)
            };
            for (i, &t) in around.iter().enumerate().take(firsts) {
                let ct = cone(t);
                for (j, &u) in around.iter().enumerate().skip(i + 1) {
                    if caps[i].apart(&caps[j]) {
                        continue;
                    }
                    if cones_overlap(&points[v], &ct, &cone(u)) {
                        return Some(Problem::new(
                            ProblemKind::Overlap,
                            vec![t, u],
                            vec![v as u32],
                            format!(
                                "tetrahedra T{t} and T{u} overlap near their common vertex #{v}"
                            ),
                        ));
                    }
                }
            }
            None
        })
        .collect()
}

/// A spherical cap containing a cone's directions: mean direction and angular radius. A
/// float filter only: caps are padded by far more than their rounding, and a cap of 90°
/// or more (not convex) never rules anything out.
struct Cap {
    axis: Point3,
    /// Cosine and sine of the padded radius; `cos = -2` marks a cap that rules nothing out.
    cos: f64,
    sin: f64,
}

impl Cap {
    fn new(v: &Point3, gens: &[Point3; 3]) -> Self {
        let unit = |p: &Point3| {
            let d = [p[0] - v[0], p[1] - v[1], p[2] - v[2]];
            let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            [d[0] / l, d[1] / l, d[2] / l]
        };
        let u = gens.map(|g| unit(&g));
        let sum: Point3 = std::array::from_fn(|k| u[0][k] + u[1][k] + u[2][k]);
        let l = (sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]).sqrt();
        let axis = sum.map(|x| x / l);
        let radius = u
            .iter()
            .map(|x| dot(&axis, x).clamp(-1.0, 1.0).acos())
            .fold(0.0, f64::max)
            + 1e-6;
        if radius.is_finite() && radius < std::f64::consts::FRAC_PI_2 {
            Cap {
                axis,
                cos: radius.cos(),
                sin: radius.sin(),
            }
        } else {
            Cap {
                axis,
                cos: -2.0,
                sin: 0.0,
            }
        }
    }

    /// True when the caps are certainly disjoint (then so are the cones): the angle between
    /// the axes exceeds the sum of the radii, compared through cosines with a margin.
    fn apart(&self, other: &Cap) -> bool {
        if self.cos < -1.0 || other.cos < -1.0 {
            return false;
        }
        let cos_sum = self.cos * other.cos - self.sin * other.sin;
        dot(&self.axis, &other.axis) < cos_sum - 1e-9
    }
}

fn dot(a: &Point3, b: &Point3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Pairs of boundary faces that meet other than in shared vertices and edges (sweep over
/// bounding boxes, exact tests). `faces[i] = (vertices, tetrahedron)`.
pub(crate) fn boundary_self_intersections(
    points: &[Point3],
    faces: &[([u32; 3], u32)],
) -> Vec<Problem> {
    let plain: Vec<[u32; 3]> = faces.iter().map(|f| f.0).collect();
    super::grid::improper_pairs(points, &plain, SELF_INTERSECTIONS)
        .into_iter()
        .map(|(i, j)| self_intersection(faces[i], faces[j]))
        .collect()
}

/// The most boundary self-intersections a check reports: the first pairs in the order
/// of the boundary faces sorted by their sorted vertices.
pub(crate) const SELF_INTERSECTIONS: usize = 100;

/// Boundary faces `fi` and `fj` (`(vertices, tetrahedron)`) intersect.
pub(crate) fn self_intersection(fi: ([u32; 3], u32), fj: ([u32; 3], u32)) -> Problem {
    Problem::new(
        ProblemKind::BoundarySelfIntersection,
        vec![fi.1, fj.1],
        fi.0.iter().chain(&fj.0).copied().collect(),
        format!(
            "boundary faces {} (of tetrahedron T{}) and {} (of tetrahedron T{}) intersect",
            ids(&fi.0),
            fi.1,
            ids(&fj.0),
            fj.1
        ),
    )
}

/// Pieces of mesh nested inside others: for one vertex `v` of each boundary component
/// (the first face of the component, as `(vertex, tet)`), the first tetrahedron not
/// incident to `v` whose closure contains it (exact; see [`containing_tets`]).
pub(super) fn nested_overlaps(
    points: &[Point3],
    tets: &[[u32; 4]],
    reps: &[(u32, u32)],
) -> Vec<Problem> {
    let queries: Vec<(Point3, u32)> = reps.iter().map(|&(v, _)| (points[v as usize], v)).collect();
    let hits = containing_tets(points, tets, &queries);
    (reps.iter().zip(hits))
        .filter_map(|(&(v, own), t)| t.map(|t| nested_problem(v, own, t, &tets[t as usize])))
        .collect()
}

/// For each query `(x, v)`, the smallest index of a tetrahedron of `tets` that does not
/// have `v` as a corner and whose closure contains `x` (exact; a hash grid of
/// tetrahedron boxes). `v` may name no point of `points` (`u32::MAX`).
pub(super) fn containing_tets(
    points: &[Point3],
    tets: &[[u32; 4]],
    queries: &[(Point3, u32)],
) -> Vec<Option<u32>> {
    let corners = |t: &[u32; 4]| t.map(|v| points[v as usize]);
    let boxes: Vec<Aabb> = tets
        .par_iter()
        .map(|t| {
            let c = corners(t);
            aabb(&[&c[0], &c[1], &c[2], &c[3]])
        })
        .collect();
    let mean_size = boxes
        .iter()
        .map(|b| (0..3).map(|i| b.1[i] - b.0[i]).fold(0.0, f64::max))
        .sum::<f64>()
        / boxes.len().max(1) as f64;
    let mut grid = TriangleGrid::with_cell(points, mean_size);
    for (i, b) in boxes.iter().enumerate() {
        grid.insert_item(b, [i as u32, 0, 0]); // keyed by tetrahedron index
    }
    queries
        .par_iter()
        .map(|&(x, v)| {
            let mut found: Option<u32> = None;
            grid.visit(&(x, x), |item| {
                let t = &tets[item[0] as usize];
                let hit = !t.contains(&v)
                    && found.is_none_or(|f| item[0] < f)
                    && boxes_meet(&boxes[item[0] as usize], &(x, x))
                    && point_in_closed_tetrahedron(&x, &corners(t));
                if hit {
                    found = Some(item[0]);
                }
                false
            });
            found
        })
        .collect()
}

/// Vertex `v` of the boundary component of tetrahedron `own` lies in tetrahedron `t`
/// (corners `tet`).
pub(crate) fn nested_problem(v: u32, own: u32, t: u32, tet: &[u32; 4]) -> Problem {
    let detail = format!(
        "vertex #{v} of a boundary component lies in tetrahedron T{t} ({}): a separate piece of mesh overlaps another",
        ids(tet)
    );
    Problem::new(ProblemKind::Overlap, vec![t, own], vec![v], detail)
}

/// One `(vertex, tet)` per connected component of the boundary surface (faces joined
/// across edges), in the order of the components' first faces: the first vertex of the
/// component's first face and that face's tetrahedron.
pub(crate) fn boundary_components(faces: &[([u32; 3], u32)]) -> Vec<(u32, u32)> {
    let vertices: Vec<[u32; 3]> = faces.iter().map(|f| f.0).collect();
    let (_, firsts) = face_components(&vertices);
    firsts
        .into_iter()
        .map(|i| (faces[i].0[0], faces[i].1))
        .collect()
}

/// The components of faces joined across edges: each face's component, numbered in the
/// order of their first faces, and each component's first face.
pub(crate) fn face_components(faces: &[[u32; 3]]) -> (Vec<u32>, Vec<usize>) {
    let mut parent = partition::singletons(faces.len());
    let mut by_edge: std::collections::HashMap<(u32, u32), u32> = std::collections::HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3]));
            if let Some(&j) = by_edge.get(&(a, b)) {
                partition::union(&mut parent, i as u32, j);
            } else {
                by_edge.insert((a, b), i as u32);
            }
        }
    }
    let mut number = vec![u32::MAX; faces.len()];
    let (mut of, mut firsts) = (Vec::with_capacity(faces.len()), Vec::new());
    for i in 0..faces.len() {
        let root = partition::find(&mut parent, i as u32) as usize;
        if number[root] == u32::MAX {
            number[root] = firsts.len() as u32;
            firsts.push(i);
        }
        of.push(number[root]);
    }
    (of, firsts)
}
