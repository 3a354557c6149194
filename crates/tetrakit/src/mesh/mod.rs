//! Tetrahedral meshes and their independent certificate check.
//!
//! [`verify`] is the check that every tetrahedralization tetrakit prints must pass
//! (ARCHITECTURE.md, "Invariants"). It shares no code with the algorithms that produce
//! tetrahedra, only the exact predicates of [`crate::geom`].

mod certify;
mod check;
mod embed;
pub(crate) mod grid;
mod partitioned;
mod report;
mod shell_degree;
pub(crate) mod surface;
mod verify;
mod verify_planar;

pub use crate::control::Verdict;
pub(crate) use certify::boundary_faces;
pub use certify::{
    ShellHulls, certify_boundary, certify_hull, certify_polyhedron, certify_shell, verify_dual_path,
};
pub(crate) use check::outcome;
pub use check::{CheckOptions, CheckOutcome, check};
pub(crate) use embed::{SELF_INTERSECTIONS, face_components, nested_problem, self_intersection};
pub use partitioned::check_pieces;
pub(crate) use partitioned::{Part, PartFaces, assemble_faces, first_hits};
pub use report::{Problem, ProblemKind, Report};
pub use surface::{Polyhedron, SurfaceError};
pub use verify::verify;
pub(crate) use verify::verify_faces;
pub(crate) use verify::{BoundaryFace, coincident_runs, hull_faces, unused_vertex};
pub use verify_planar::verify_triangulation;

use crate::geom::{Point3, orient3d};
use rayon::slice::ParallelSliceMut;

/// A set of points and tetrahedra over them (indices into `points`).
///
/// ```
/// use tetrakit::mesh::Tetrahedralization;
/// let t = Tetrahedralization {
///     points: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
///     tets: vec![[0, 1, 2, 3]],
/// };
/// assert_eq!(t.edges().len(), 6);
/// assert!(t.verify_convex().is_valid());
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tetrahedralization {
    /// The vertices.
    pub points: Vec<Point3>,
    /// The tetrahedra, each positively oriented in a valid tetrahedralization.
    pub tets: Vec<[u32; 4]>,
}

impl Tetrahedralization {
    /// The sorted, deduplicated edge set `(i, j)` with `i < j`.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        edges_of(&self.tets)
    }

    /// Checks that the tetrahedra form a tetrahedralization of the convex hull of all the
    /// points (every point a vertex).
    pub fn verify_convex(&self) -> Report {
        let hull = crate::geom::Hull3::new(&self.points);
        verify(&self.points, &self.tets, Some(&hull))
    }

    /// Reorders the vertices of every tetrahedron so that it is positively oriented
    /// (degenerate tetrahedra are left as they are); see [`reorient`].
    pub fn orient_positively(&mut self) {
        reorient(&self.points, &mut self.tets);
    }
}

/// Swaps the last two vertices of every negatively oriented tetrahedron (exact
/// `orient3d`), for generators that do not orient their cells (scipy's and Qhull's
/// Delaunay); returns how many were turned. Degenerate tetrahedra and those naming a
/// vertex out of range are left for [`verify`] to report.
///
/// ```
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let mut tets = [[0, 2, 1, 3], [0, 1, 2, 3], [0, 1, 2, 9]];
/// assert_eq!(tetrakit::mesh::reorient(&pts, &mut tets), 1);
/// assert_eq!(tets[0], [0, 2, 3, 1]);
/// ```
pub fn reorient(points: &[Point3], tets: &mut [[u32; 4]]) -> usize {
    let mut turned = 0;
    for t in tets {
        if t.iter().any(|&i| i as usize >= points.len()) {
            continue;
        }
        let p = t.map(|i| &points[i as usize]);
        if orient3d(p[0], p[1], p[2], p[3]) < 0 {
            t.swap(2, 3);
            turned += 1;
        }
    }
    turned
}

/// The sorted, deduplicated edge set of a list of tetrahedra.
pub fn edges_of(tets: &[[u32; 4]]) -> Vec<[u32; 2]> {
    let pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    let keys = tets.iter().flat_map(|t| pairs.map(|(i, j)| [t[i], t[j]]));
    distinct_edges(keys)
        .into_iter()
        .map(|k| [(k >> 32) as u32, k as u32])
        .collect()
}

/// The distinct undirected edges of `edges`, each `(a, b)` with `a < b` as the integer
/// `a << 32 | b`, sorted (in parallel: the keys are plain integers, so the order is one).
pub(crate) fn distinct_edges(edges: impl Iterator<Item = [u32; 2]>) -> Vec<u64> {
    let key = |[a, b]: [u32; 2]| u64::from(a.min(b)) << 32 | u64::from(a.max(b));
    let mut e: Vec<u64> = edges.map(key).collect();
    e.par_sort_unstable();
    e.dedup();
    e
}

/// `f` and `low` (a tetrahedron's number, below 2^32 like every index here) as one
/// integer ordered as the pair `(f, low)`: sorting these is several times faster than
/// sorting tuples of arrays.
pub(crate) fn face_key(f: [u32; 3], low: usize) -> u128 {
    let [a, b, c] = f.map(u128::from);
    (a << 96) | (b << 64) | (c << 32) | low as u128
}

/// A triangle's vertices in increasing order (its key regardless of orientation).
pub(crate) fn sorted_face(mut f: [u32; 3]) -> [u32; 3] {
    f.sort_unstable();
    f
}

/// A triangle's rotation starting at its smallest vertex (its key with orientation).
pub(crate) fn rotated_face(f: [u32; 3]) -> [u32; 3] {
    let i = (0..3).min_by_key(|&i| f[i]).unwrap_or(0);
    [f[i], f[(i + 1) % 3], f[(i + 2) % 3]]
}
