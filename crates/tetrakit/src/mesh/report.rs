//! What the verifiers find: [`Problem`]s of a [`ProblemKind`], gathered in a [`Report`].

use crate::numbering::Sentence;
use serde::{Deserialize, Serialize};
use std::fmt;

/// What is wrong with a mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ProblemKind {
    /// A vertex index is out of range.
    BadIndex,
    /// A tetrahedron repeats a vertex.
    RepeatedVertex,
    /// A tetrahedron has zero volume.
    Degenerate,
    /// A tetrahedron is negatively oriented.
    Inverted,
    /// A triangle is a face of three or more tetrahedra.
    FaceSharedByMore,
    /// Two tetrahedra sharing a face lie on the same side of it (they overlap).
    SameSide,
    /// The boundary faces do not form a closed surface (an edge used unequally in the
    /// two directions).
    OpenBoundary,
    /// A boundary edge used by four or more boundary faces (a non-manifold domain); not a
    /// problem unless a manifold boundary is asked for.
    NonManifoldEdge,
    /// A boundary face does not lie on the convex hull.
    BoundaryNotOnHull,
    /// Tetrahedra overlap (the mesh covers part of the hull more than once).
    Overlap,
    /// A point is not a vertex of any tetrahedron.
    UnusedVertex,
    /// Two boundary faces intersect: the boundary surface is not embedded.
    BoundarySelfIntersection,
    /// The boundary of the tetrahedra is not the domain's surface (a facet not covered,
    /// a boundary triangle that is not a facet, or the wrong volume).
    BoundaryNotSurface,
    /// A vertex that is not on the domain's boundary surfaces (a Steiner point where none
    /// is allowed).
    SteinerPoint,
    /// Two vertices of tetrahedra at the same place: pieces meshed apart and not merged
    /// (a non-conforming assembly).
    CoincidentVertices,
    /// Two points of a partitioned mesh with one global id at different coordinates: the
    /// pieces disagree on an interface vertex.
    InterfaceMismatch,
}

impl ProblemKind {
    /// Every kind, in the order of their [`code`](Self::code)s (1, 2, …).
    pub const ALL: [ProblemKind; 16] = [
        ProblemKind::BadIndex,
        ProblemKind::RepeatedVertex,
        ProblemKind::Degenerate,
        ProblemKind::Inverted,
        ProblemKind::FaceSharedByMore,
        ProblemKind::SameSide,
        ProblemKind::OpenBoundary,
        ProblemKind::NonManifoldEdge,
        ProblemKind::BoundaryNotOnHull,
        ProblemKind::Overlap,
        ProblemKind::UnusedVertex,
        ProblemKind::BoundarySelfIntersection,
        ProblemKind::BoundaryNotSurface,
        ProblemKind::SteinerPoint,
        ProblemKind::CoincidentVertices,
        ProblemKind::InterfaceMismatch,
    ];

    /// The kind's number in the `problem` fields `check --output` writes for a viewer:
    /// 1 for the first kind of [`ALL`](Self::ALL), and so on; 0 is kept for "no problem".
    ///
    /// ```
    /// use tetrakit::mesh::ProblemKind;
    /// assert_eq!(ProblemKind::BadIndex.code(), 1);
    /// assert_eq!(ProblemKind::Inverted.code(), 4);
    /// ```
    pub fn code(self) -> i32 {
        self as i32 + 1
    }
}

impl fmt::Display for ProblemKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&crate::numbering::json_name(self, "problem"))
    }
}

/// One problem, naming the tetrahedra (indices into the tet list) and vertices involved.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Problem {
    /// What is wrong.
    pub kind: ProblemKind,
    /// The offending cells, as indices into the cell list: tetrahedra for [`verify`],
    /// triangles for [`verify_triangulation`] (written `"tets"` in JSON, the `check`
    /// command's field).
    ///
    /// [`verify`]: super::verify
    /// [`verify_triangulation`]: super::verify_triangulation
    #[serde(rename = "tets")]
    pub cells: Vec<u32>,
    /// Vertices involved (e.g. the shared face).
    pub vertices: Vec<u32>,
    /// A sentence for a person, naming vertices as `#12` and cells as `T12`.
    pub detail: Sentence,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.kind, self.detail)
    }
}

impl std::error::Error for Problem {}

impl Problem {
    /// Renames vertex `v` to `vertex(v)` and cell `t` to `cell(t)`, in the lists and the
    /// text.
    pub(crate) fn relabel(&mut self, vertex: &impl Fn(u32) -> u32, cell: &impl Fn(u32) -> u32) {
        self.cells.iter_mut().for_each(|t| *t = cell(*t));
        self.vertices.iter_mut().for_each(|v| *v = vertex(*v));
        self.detail = std::mem::take(&mut self.detail).map(vertex, cell);
    }

    /// Writes this problem's code on its cells and vertices where no earlier problem did.
    pub(crate) fn mark(&self, cells: &mut [i32], vertices: &mut [i32]) {
        let code = self.kind.code();
        let mark = |field: &mut [i32], k: u32| {
            if let Some(c) = field.get_mut(k as usize).filter(|c| **c == 0) {
                *c = code;
            }
        };
        self.cells.iter().for_each(|&t| mark(cells, t));
        self.vertices.iter().for_each(|&v| mark(vertices, v));
    }

    /// A problem of `kind` naming `cells` and `vertices`, with a sentence for a person.
    pub fn new(
        kind: ProblemKind,
        cells: Vec<u32>,
        vertices: Vec<u32>,
        detail: impl Into<Sentence>,
    ) -> Self {
        Problem {
            kind,
            cells,
            vertices,
            detail: detail.into(),
        }
    }
}

/// The result of [`verify`](super::verify) and [`verify_triangulation`](super::verify_triangulation).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Report {
    /// Problems found (at most [`Report::LIMIT`] are kept).
    pub problems: Vec<Problem>,
    /// Total number of problems found, kept or not.
    pub problem_count: usize,
    /// Number of boundary (unpaired) faces.
    pub boundary_faces: usize,
    /// Non-manifold boundary edges: valid in a tetrahedralization of a non-manifold
    /// domain, listed so a caller that needs a manifold boundary can refuse them.
    pub non_manifold: Vec<Problem>,
}

impl Report {
    /// How many problems are kept in detail.
    pub const LIMIT: usize = 1000;

    /// Shifts cell and vertex numbers by `base` (in the fields, and `T12` and `#12` in the
    /// texts).
    pub fn renumbered(self, base: u32) -> Self {
        self.relabeled(|v| v + base, |t| t + base)
    }

    /// The report in a file's own numbering: vertex `v` becomes `vertex(v)` (Gmsh node
    /// tags may have gaps) and cell `t` becomes `cell(t)` (a `.ele` may number its
    /// tetrahedra with gaps), in the cell and vertex lists and in the texts.
    pub fn relabeled(mut self, vertex: impl Fn(u32) -> u32, cell: impl Fn(u32) -> u32) -> Self {
        for p in self.problems.iter_mut().chain(&mut self.non_manifold) {
            p.relabel(&vertex, &cell);
        }
        self
    }

    /// The report of a check that also requires a manifold boundary: the non-manifold
    /// edges become problems.
    pub fn require_manifold(mut self) -> Self {
        for p in std::mem::take(&mut self.non_manifold) {
            self.push(p);
        }
        self
    }

    /// Per-cell and per-vertex problem codes for a viewer ([`ProblemKind::code`], 0 for
    /// none): each cell and vertex named by a kept problem gets the code of the first
    /// that names it (the checks run from the most local outwards), non-manifold edges
    /// included. Call it before [`relabeled`](Self::relabeled): the fields are indexed
    /// by position, `cells` and `vertices` long. Only the first [`Report::LIMIT`]
    /// problems are kept, so a mesh with more marks only theirs.
    ///
    /// ```
    /// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let report = tetrakit::mesh::verify(&pts, &[[0, 2, 1, 3]], None);
    /// let (cells, vertices) = report.fields(1, 4);
    /// assert_eq!(cells, [tetrakit::mesh::ProblemKind::Inverted.code()]);
    /// assert!(vertices.iter().all(|&c| c == cells[0]));
    /// ```
    pub fn fields(&self, cells: usize, vertices: usize) -> (Vec<i32>, Vec<i32>) {
        let mut cell_code = vec![0; cells];
        let mut vertex_code = vec![0; vertices];
        for p in self.problems.iter().chain(&self.non_manifold) {
            p.mark(&mut cell_code, &mut vertex_code);
        }
        (cell_code, vertex_code)
    }

    /// True when no problem was found: the mesh is certified.
    pub fn is_valid(&self) -> bool {
        self.problem_count == 0
    }

    pub(crate) fn push(&mut self, p: Problem) {
        self.problem_count += 1;
        if self.problems.len() < Self::LIMIT {
            self.problems.push(p);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The codes written for viewers follow `ALL`, and every kind is in it once.
    #[test]
    fn codes_follow_the_list_of_kinds() {
        for (k, kind) in ProblemKind::ALL.iter().enumerate() {
            assert_eq!(kind.code(), k as i32 + 1, "{kind}");
        }
        let names: std::collections::HashSet<String> =
            ProblemKind::ALL.iter().map(|k| k.to_string()).collect();
        assert_eq!(names.len(), ProblemKind::ALL.len());
    }
}
