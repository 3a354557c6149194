//! Certificates that tetrahedra tetrahedralize a given domain: the convex hull of a point
//! set (every point a vertex), a region given by its boundary (a polyhedron's facets;
//! the outer and reversed inner facets of a shell), or the region between two nested
//! convex polytopes whatever the triangulation of their facets ([`certify_shell`]). All
//! rest on [`verify`]; every tetrahedralization a solver returns passes one of them.

use super::report::{Problem, ProblemKind};
use super::shell_degree::{OuterFace, check_inner_degree, check_outer_degree, used_vertices};
use super::verify::BoundaryFace;
use super::{Polyhedron, Report, face_key, rotated_face, sorted_face, verify, verify_faces};
use crate::geom::point_key;
use crate::geom::{Hull3, Point3, orient2d_drop, projection_axis};
use crate::numbering::ids;
use rayon::prelude::*;
use rustc_hash::FxHashSet as HashSet;

/// Certifies that `tets` tetrahedralize the convex hull of `points` with every point a
/// vertex ([`verify`] with the hull). Returns the first problem found.
///
/// ```
/// use tetrakit::mesh::certify_hull;
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// assert_eq!(certify_hull(&pts, &[[0, 1, 2, 3]]), Ok(()));
/// assert!(certify_hull(&pts, &[[0, 2, 1, 3]]).is_err()); // inverted
/// ```
pub fn certify_hull(points: &[Point3], tets: &[[u32; 4]]) -> Result<(), Problem> {
    let hull = Hull3::new(points);
    first_problem(verify(points, tets, Some(&hull)).problems)
}

/// Certifies that `tets` tetrahedralize `poly`: [`certify_boundary`] with the
/// polyhedron's facets.
///
/// ```
/// use tetrakit::mesh::certify_polyhedron;
/// use tetrakit::polyhedra::{Checks, generate, mintetra};
/// let p = generate::stacked(8, 3);
/// let m = mintetra(&p, Checks::Shelling);
/// assert_eq!(certify_polyhedron(&p, &m.tets), Ok(()));
/// assert!(certify_polyhedron(&p, &m.tets[1..]).is_err());
/// ```
pub fn certify_polyhedron(poly: &Polyhedron, tets: &[[u32; 4]]) -> Result<(), Problem> {
    certify_boundary(&poly.points, tets, &poly.faces)
}

/// Certifies that `tets` tetrahedralize the region whose boundary is exactly `faces`,
/// each oriented outward from the region: [`verify`] (orientation, face pairing, no
/// overlap near any vertex, an embedded boundary, no nested piece) and the boundary
/// triangles of the tetrahedra are exactly `faces` with their orientation. A region with
/// holes is given by all its boundary surfaces: the shell between nested polytopes by
/// the outer facets and the inner ones reversed. Returns the first problem found.
///
/// ```
/// use tetrakit::mesh::certify_boundary;
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// assert_eq!(certify_boundary(&pts, &[[0, 1, 2, 3]], &faces), Ok(()));
/// assert!(certify_boundary(&pts, &[[0, 1, 2, 3]], &faces[1..]).is_err());
/// ```
pub fn certify_boundary(
    points: &[Point3],
    tets: &[[u32; 4]],
    faces: &[[u32; 3]],
) -> Result<(), Problem> {
    first_problem(verify(points, tets, None).problems)?;
    let boundary = boundary_faces(tets);
    let mut want: Vec<[u32; 3]> = faces.iter().map(|&f| rotated_face(f)).collect();
    want.sort_unstable();
    if boundary == want {
        return Ok(());
    }
    let missing = want.iter().find(|f| boundary.binary_search(f).is_err());
    let extra = boundary.iter().find(|f| want.binary_search(f).is_err());
    let name = |f: Option<&[u32; 3]>| f.map_or("none".to_string(), |f| ids(f));
    Err(Problem::new(
        ProblemKind::BoundaryNotSurface,
        Vec::new(),
        missing
            .into_iter()
            .chain(extra)
            .flatten()
            .copied()
            .collect(),
        format!(
            "the boundary of the tetrahedra is not the given surface (face {} not covered, boundary triangle {} not a given face)",
            name(missing),
            name(extra)
        ),
    ))
}

/// Certifies that `tets` tetrahedralize the closed region `P − int(Q)` between the convex
/// hulls `P = CH(points)` and `Q = CH(points[inner])`, with no Steiner point, however the
/// tetrahedra triangulate the polygon facets of `P` and `Q` (thesis ch. 4; `Q` must be
/// full-dimensional and inside `P`, and may touch it).
///
/// The checks, all exact:
/// 1. conditions 1–3 of [`verify`]: every tetrahedron positively oriented, faces paired on
///    opposite sides, the boundary closed; no two vertices at one point;
/// 2. every vertex of a tetrahedron lies on `∂P` or `∂Q` (no Steiner point);
/// 3. every boundary triangle lies in a facet of `P`, facing out of `P`, or in a facet of
///    `Q`, facing into `Q`;
/// 4. the covering degree just inside `∂P` is 1 on every component of `∂P − Q`, read off
///    one corner of `P` per component (`shell_degree`'s module docs give the argument);
/// 5. the volumes: `Σ vol(t) = vol(P) − vol(Q)` exactly (sums of exact determinants),
///    which with 4 leaves no tetrahedron over `Q`.
///
/// Together they make the number of tetrahedra over a point 1 on `P − Q` and 0 elsewhere,
/// without the vertex-by-vertex overlap test a domain of unknown shape needs.
///
/// ```
/// use tetrakit::mesh::certify_shell;
/// // The unit cube around a small tetrahedron: the tetrahedron itself is not the shell.
/// let mut pts: Vec<[f64; 3]> =
///     (0..8).map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64]).collect();
/// pts.extend([[0.25, 0.25, 0.25], [0.5, 0.25, 0.25], [0.25, 0.5, 0.25], [0.25, 0.25, 0.5]]);
/// assert!(certify_shell(&pts, &[[8, 9, 10, 11]], &[8, 9, 10, 11]).is_err());
/// ```
pub fn certify_shell(points: &[Point3], tets: &[[u32; 4]], inner: &[u32]) -> Result<(), Problem> {
    let (hulls, faces) = rayon::join(
        || ShellHulls::new(points, inner),
        || verify_faces(points, tets),
    );
    hulls.certify(tets, faces)
}

/// The two hulls [`certify_shell`] measures a mesh against, computed from the points
/// alone: a mesher can build them while it meshes (they are most of the certificate's
/// time), and they owe nothing to the mesh or to how it was made.
///
/// ```
/// use tetrakit::mesh::ShellHulls;
/// let mut pts: Vec<[f64; 3]> =
///     (0..8).map(|i| [(i & 1) as f64 * 4.0, ((i >> 1) & 1) as f64 * 4.0, (i >> 2) as f64 * 4.0]).collect();
/// pts.extend([[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 2.0]]);
/// let hulls = ShellHulls::new(&pts, &[8, 9, 10, 11]);
/// // The small tetrahedron alone is not the region between the two hulls.
/// assert!(hulls.certify_shell(&[[8, 9, 10, 11]]).is_err());
/// ```
pub struct ShellHulls<'a> {
    points: &'a [Point3],
    inner: &'a [u32],
    inner_points: Vec<Point3>,
    outer_hull: Hull3,
    inner_hull: Hull3,
}

impl<'a> ShellHulls<'a> {
    /// The hulls of `points` and of `points[inner]`, built side by side.
    pub fn new(points: &'a [Point3], inner: &'a [u32]) -> Self {
        let inner_points: Vec<Point3> = inner.iter().map(|&i| points[i as usize]).collect();
        let (outer_hull, inner_hull) =
            rayon::join(|| Hull3::new(points), || Hull3::new(&inner_points));
        ShellHulls {
            points,
            inner,
            inner_points,
            outer_hull,
            inner_hull,
        }
    }

    /// [`certify_shell`] of `tets` against these hulls.
    pub fn certify_shell(&self, tets: &[[u32; 4]]) -> Result<(), Problem> {
        self.certify(tets, verify_faces(self.points, tets))
    }

    fn certify(
        &self,
        tets: &[[u32; 4]],
        (report, boundary): (Report, Vec<BoundaryFace>),
    ) -> Result<(), Problem> {
        first_problem(report.problems)?;
        let used = used_vertices(self.points, tets)?;
        if self.outer_hull.dimension < 3 || self.inner_hull.dimension < 3 {
            return Err(shell_problem(
                Vec::new(),
                "the outer or inner hull is flat".into(),
            ));
        }
        let mut local = vec![u32::MAX; self.points.len()];
        for (k, &i) in self.inner.iter().enumerate() {
            local[i as usize] = k as u32;
        }
        let on_surface =
            |v: u32| self.outer_hull.on_boundary(v as usize) || self.on_inner(&local, v);
        if let Some(&v) = tets.iter().flatten().find(|&&v| !on_surface(v)) {
            return Err(Problem::new(
                ProblemKind::SteinerPoint,
                Vec::new(),
                vec![v],
                format!("vertex #{v} lies on neither the outer nor the inner surface"),
            ));
        }
        let sides: Vec<Side> = boundary.par_iter().map(|f| self.side(&local, f)).collect();
        if let Some(k) = sides.iter().position(|s| matches!(s, Side::Neither)) {
            let f = &boundary[k].v;
            return Err(shell_problem(
                f.to_vec(),
                format!(
                    "boundary triangle {} lies neither in a facet of the outer hull facing out nor in a facet of the inner hull facing in",
                    ids(f)
                ),
            ));
        }
        let off_p = sides
            .iter()
            .any(|s| matches!(s, Side::Inner { off_p: true }));
        let outer_faces: Vec<OuterFace> = sides
            .into_iter()
            .filter_map(|s| match s {
                Side::Outer(f) => Some(f),
                _ => None,
            })
            .collect();
        let in_q: HashSet<[u64; 3]> = self.inner_points.iter().map(point_key).collect();
        let components = check_outer_degree(
            self.points,
            &self.outer_hull,
            self.inner,
            &in_q,
            &used,
            &outer_faces,
        )?;
        check_inner_degree(components, tets.len(), off_p)
    }

    /// Vertex `v` is on `∂Q` (`local`: each point's index among the inner ones).
    fn on_inner(&self, local: &[u32], v: u32) -> bool {
        let l = local[v as usize];
        l != u32::MAX && self.inner_hull.on_boundary(l as usize)
    }

    /// Where the boundary triangle `f` lies: in a facet of `P` facing out, in a facet of
    /// `Q` facing in, or neither.
    fn side(&self, local: &[u32], f: &BoundaryFace) -> Side {
        let (points, outer, inner) = (self.points, &self.outer_hull, &self.inner_hull);
        let [a, b, c] = f.v.map(|v| v as usize);
        let tri = f.v.map(|v| &points[v as usize]);
        let outer_facet = outer.common_facet(a, b, c);
        if let Some(facet) = outer_facet
            && same_way(points, outer.facet_planes[facet as usize], tri)
        {
            return Side::Outer(OuterFace {
                v: f.v,
                facet,
                tet: f.tet,
            });
        }
        if !f.v.iter().all(|&v| self.on_inner(local, v)) {
            return Side::Neither;
        }
        let l = f.v.map(|v| local[v as usize] as usize);
        // Facing into Q: the reversed triangle faces out of it.
        let reversed = [tri[0], tri[2], tri[1]];
        match inner.common_facet(l[0], l[1], l[2]) {
            Some(g) if same_way(&self.inner_points, inner.facet_planes[g as usize], reversed) => {
                Side::Inner {
                    off_p: outer_facet.is_none(),
                }
            }
            _ => Side::Neither,
        }
    }
}

/// A triangle in a facet's plane faces the same way as the facet's plane triple `plane`
/// (indices into `pts`) when the two have the same orientation seen along an axis the
/// plane is not parallel to.
fn same_way(pts: &[Point3], plane: [u32; 3], f: [&Point3; 3]) -> bool {
    let q = |k: usize| &pts[plane[k] as usize];
    projection_axis(q(0), q(1), q(2)).is_some_and(|axis| {
        orient2d_drop(q(0), q(1), q(2), axis) == orient2d_drop(f[0], f[1], f[2], axis)
    })
}

/// Where a boundary triangle lies.
enum Side {
    /// In a facet of `P`, facing out.
    Outer(OuterFace),
    /// In a facet of `Q`, facing in; `off_p` when not also in a facet of `P`.
    Inner { off_p: bool },
    /// Anywhere else: not a shell.
    Neither,
}

fn shell_problem(vertices: Vec<u32>, detail: String) -> Problem {
    Problem::new(
        ProblemKind::BoundaryNotSurface,
        Vec::new(),
        vertices,
        detail,
    )
}

fn first_problem(problems: Vec<Problem>) -> Result<(), Problem> {
    match problems.into_iter().next() {
        None => Ok(()),
        Some(p) => Err(p),
    }
}

/// The faces of exactly one tetrahedron, outward and rotated to their smallest vertex,
/// sorted. A positively oriented tet (a,b,c,d) has outward faces (a,c,b), (a,b,d),
/// (a,d,c), (b,c,d).
pub(crate) fn boundary_faces(tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
    let mut faces: Vec<u128> = (tets.iter().enumerate())
        .flat_map(|(t, tet)| (0..4).map(move |k| face_key(sorted_face(face(tet, k)), t)))
        .collect();
    faces.par_sort_unstable();
    let mut boundary = Vec::new();
    for run in faces.chunk_by(|x, y| x >> 32 == y >> 32) {
        if let [x] = run {
            let tet = &tets[*x as u32 as usize];
            let f = [(x >> 96) as u32, (x >> 64) as u32, (x >> 32) as u32];
            let k = tet.iter().position(|v| !f.contains(v)).unwrap_or(0);
            boundary.push(rotated_face(face(tet, k)));
        }
    }
    boundary.sort_unstable();
    boundary
}

/// The face of `t` opposite its `k`-th vertex, oriented outward (for `orient3d(t) > 0`).
fn face(t: &[u32; 4], k: usize) -> [u32; 3] {
    let [a, b, c, d] = *t;
    [[b, c, d], [a, d, c], [a, b, d], [a, c, b]][k]
}

/// Checks that each tetrahedron shares a triangle (three corners) with the next: with
/// `tets` a tetrahedralization, that their order is a Hamiltonian path of its dual graph.
/// The error is the first `i` whose tetrahedra `i` and `i + 1` do not.
///
/// ```
/// use tetrakit::mesh::verify_dual_path;
/// assert_eq!(verify_dual_path(&[[0, 1, 2, 3], [1, 2, 3, 4], [2, 3, 4, 5]]), Ok(()));
/// assert_eq!(verify_dual_path(&[[0, 1, 2, 3], [1, 2, 3, 4], [0, 1, 5, 6]]), Err(1));
/// ```
pub fn verify_dual_path(tets: &[[u32; 4]]) -> Result<(), usize> {
    match tets
        .windows(2)
        .position(|w| w[1].iter().filter(|v| w[0].contains(v)).count() != 3)
    {
        Some(i) => Err(i),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 3 × 3 × 3 Kuhn block without its middle cube is a tetrahedralization of the
    /// shell between two cubes: its boundary is the outer faces and the middle cube's
    /// faces reversed, and neither surface alone will do.
    #[test]
    fn a_shell_is_certified_by_both_surfaces() {
        let block = crate::generate::kuhn(3);
        let p = |t: &[u32; 4]| t.map(|v| block.points[v as usize]);
        let middle = |t: &[u32; 4]| p(t).iter().flatten().all(|&x| (1.0..=2.0).contains(&x));
        let (inner, shell): (Vec<[u32; 4]>, Vec<[u32; 4]>) =
            block.tets.iter().partition(|t| middle(t));
        assert_eq!((inner.len(), shell.len()), (6, 156));
        let outer = boundary_faces(&block.tets);
        let hole: Vec<[u32; 3]> = boundary_faces(&inner)
            .iter()
            .map(|f| [f[0], f[2], f[1]])
            .collect();
        let both: Vec<[u32; 3]> = outer.iter().chain(&hole).copied().collect();
        assert_eq!(certify_boundary(&block.points, &shell, &both), Ok(()));
        assert!(certify_boundary(&block.points, &shell, &outer).is_err());
        // The hole filled is not the shell.
        assert!(certify_boundary(&block.points, &block.tets, &both).is_err());
        // The same by the hulls alone, whatever the facets' triangulation.
        let inner: Vec<u32> = (0..block.points.len() as u32)
            .filter(|&v| {
                block.points[v as usize]
                    .iter()
                    .all(|&x| (1.0..=2.0).contains(&x))
            })
            .collect();
        assert_eq!(inner.len(), 8);
        assert_eq!(certify_shell(&block.points, &shell, &inner), Ok(()));
        assert!(certify_shell(&block.points, &block.tets, &inner).is_err());
        assert!(certify_shell(&block.points, &shell[1..], &inner).is_err());
        assert!(
            certify_shell(&block.points, &inner_tets_only(&inner, &block.tets), &inner).is_err()
        );
    }

    /// A cube around the tetrahedron on four of its corners leaves four corner regions.
    /// Meshing one of them twice and another not at all keeps orientation, pairing, the
    /// boundary's sides and the volume; only the covering degree tells.
    #[test]
    fn a_corner_covered_twice_and_one_left_empty_is_refused() {
        let [a, b, c, d, e] = [
            [2.0, 0.0, 0.0],
            [0.0; 3],
            [2.0, 2.0, 0.0],
            [2.0, 0.0, 2.0],
            [0.0, 2.0, 2.0],
        ];
        let (f, g, h) = ([0.0, 2.0, 0.0], [0.0, 0.0, 2.0], [2.0, 2.0, 2.0]);
        // 0 a, 1 b, 2 c, 3 d, 4 e, 5..7 the other corners, 8 m = mid ab, 9 m' = mid cd.
        let pts = vec![a, b, c, d, e, f, g, h, [1.0, 0.0, 0.0], [2.0, 1.0, 1.0]];
        let inner = [1, 2, 3, 4, 9]; // m' lies on a facet of Q
        let positive = |t: [u32; 4]| {
            let q = t.map(|v| &pts[v as usize]);
            if crate::geom::orient3d(q[0], q[1], q[2], q[3]) > 0 {
                t
            } else {
                [t[1], t[0], t[2], t[3]]
            }
        };
        let corners = [[0, 1, 2, 3], [5, 1, 2, 4], [6, 1, 3, 4], [7, 2, 3, 4]].map(positive);
        assert_eq!(certify_shell(&pts, &corners, &inner), Ok(()));
        let twice: Vec<[u32; 4]> = [[0, 8, 2, 3], [8, 1, 2, 3], [0, 1, 2, 9], [0, 1, 9, 3]]
            .map(positive)
            .into_iter()
            .chain([corners[1], corners[2]])
            .collect();
        assert!(verify_faces(&pts, &twice).0.is_valid());
        let err = certify_shell(&pts, &twice, &inner).unwrap_err();
        assert_eq!(err.kind, ProblemKind::Overlap, "{err:?}");
        assert!(!verify(&pts, &twice, None).is_valid());
    }

    fn inner_tets_only(inner: &[u32], tets: &[[u32; 4]]) -> Vec<[u32; 4]> {
        tets.iter()
            .filter(|t| t.iter().all(|v| inner.contains(v)))
            .copied()
            .collect()
    }
}
