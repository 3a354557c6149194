//! The `check` capability: a tetrahedral mesh read from a file or given as arrays,
//! checked by [`verify`](super::verify) (with the convex hull of its points for
//! `convex`), optionally turned first (`reorient`) and held to a manifold boundary
//! (`manifold`), as one certified outcome that the CLI and Python print through the same
//! report layer ([`crate::report`]).

use super::{ProblemKind, Report, reorient, verify};
use crate::control::Verdict;
use crate::geom::{Hull3, Point3};
use serde::Serialize;
use std::collections::BTreeMap;

/// What [`check`] is asked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheckOptions {
    /// Certify that the tetrahedra tetrahedralize the convex hull of all the points.
    pub convex: bool,
    /// Non-manifold boundary edges are problems.
    pub manifold: bool,
    /// Turn negatively oriented tetrahedra (and count them) instead of reporting them.
    pub reorient: bool,
}

/// The outcome of [`check`]: the verdict with the first problem as its witness, every
/// problem kept (at most [`Report::LIMIT`]), and the per-cell and per-point problem codes
/// for a viewer. Serialized, it is the JSON of `tetrakit check --json` (without the
/// file's own fields: timings, other cells).
#[derive(Clone, Debug, Serialize)]
pub struct CheckOutcome {
    /// `yes` when the mesh passed every check.
    pub verdict: Verdict,
    /// Tetrahedra checked.
    pub tetrahedra: usize,
    /// Points given.
    pub vertices: usize,
    /// Faces on the boundary (of one tetrahedron only).
    pub boundary_faces: usize,
    /// Boundary edges of four or more boundary faces (valid unless `manifold`).
    pub non_manifold_edges: usize,
    /// Whether the convex hull was certified.
    pub convex: bool,
    /// Problems found (all of them, kept or not).
    pub problem_count: usize,
    /// The problems kept, from the most local check outwards.
    pub problems: Vec<super::Problem>,
    /// With `reorient`, how many tetrahedra were turned.
    pub reoriented: Option<usize>,
    /// The witness of a NO: the first problem.
    pub witness: Option<super::Problem>,
    /// The number of each problem kind in `cell_problems` and `point_problems`.
    pub problem_codes: BTreeMap<String, i32>,
    /// The first non-manifold edge, for the human text.
    #[serde(skip)]
    pub first_non_manifold: Option<super::Problem>,
    /// The tetrahedra, turned where `reorient` turned them.
    #[serde(skip)]
    pub tets: Vec<[u32; 4]>,
    /// The code of the first problem naming each tetrahedron (0 for none).
    #[serde(skip)]
    pub cell_problems: Vec<i32>,
    /// The code of the first problem naming each point (0 for none).
    #[serde(skip)]
    pub point_problems: Vec<i32>,
}

/// Checks the mesh of `points` and `tets` (see [`CheckOptions`]); every index must name
/// a point (a bad one is a problem, not a panic).
///
/// ```
/// use tetrakit::mesh::{CheckOptions, Verdict, check};
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let opts = CheckOptions { convex: true, ..Default::default() };
/// assert_eq!(check(&pts, vec![[0, 1, 2, 3]], opts).verdict, Verdict::Yes);
/// let bad = check(&pts, vec![[0, 2, 1, 3]], opts);
/// assert_eq!((bad.verdict, bad.witness.unwrap().kind.to_string()), (Verdict::No, "inverted".into()));
/// ```
pub fn check(points: &[Point3], mut tets: Vec<[u32; 4]>, opts: CheckOptions) -> CheckOutcome {
    let reoriented = opts.reorient.then(|| reorient(points, &mut tets));
    let hull = opts.convex.then(|| Hull3::new(points));
    let mut report = verify(points, &tets, hull.as_ref());
    if opts.manifold {
        report = report.require_manifold();
    }
    outcome(report, tets, points.len(), opts, reoriented)
}

/// The outcome of a check whose report is `report`, over `points` points.
pub(crate) fn outcome(
    report: Report,
    tets: Vec<[u32; 4]>,
    points: usize,
    opts: CheckOptions,
    reoriented: Option<usize>,
) -> CheckOutcome {
    let (cell_problems, point_problems) = report.fields(tets.len(), points);
    let Report {
        problems,
        problem_count,
        boundary_faces,
        non_manifold,
    } = report;
    CheckOutcome {
        verdict: if problem_count == 0 {
            Verdict::Yes
        } else {
            Verdict::No
        },
        tetrahedra: tets.len(),
        vertices: points,
        boundary_faces,
        non_manifold_edges: non_manifold.len(),
        convex: opts.convex,
        problem_count,
        witness: problems.first().cloned(),
        problems,
        reoriented,
        problem_codes: (ProblemKind::ALL.iter())
            .map(|k| (k.to_string(), k.code()))
            .collect(),
        first_non_manifold: non_manifold.into_iter().next(),
        tets,
        cell_problems,
        point_problems,
    }
}

impl CheckOutcome {
    /// The outcome with `found` (problems a reader found, such as
    /// [`ProblemKind::InterfaceMismatch`]) before the others: they count, they mark their
    /// cells and points, and any of them makes the verdict a NO.
    pub fn with_problems(mut self, found: Vec<super::Problem>) -> Self {
        if found.is_empty() {
            return self;
        }
        for p in &found {
            p.mark(&mut self.cell_problems, &mut self.point_problems);
        }
        self.problem_count += found.len();
        self.problems.splice(0..0, found);
        self.problems.truncate(Report::LIMIT);
        self.witness = self.problems.first().cloned();
        self.verdict = Verdict::No;
        self
    }

    /// True when the mesh passed every check.
    pub fn is_valid(&self) -> bool {
        self.verdict == Verdict::Yes
    }

    /// The outcome in a file's own numbering: vertex `v` becomes `vertex(v)`, cell `t`
    /// becomes `cell(t)`, in the problems' lists and texts (the code arrays stay indexed
    /// by position).
    pub fn relabeled(mut self, vertex: impl Fn(u32) -> u32, cell: impl Fn(u32) -> u32) -> Self {
        let all = (self.problems.iter_mut())
            .chain(self.witness.as_mut())
            .chain(self.first_non_manifold.as_mut());
        for p in all {
            p.relabel(&vertex, &cell);
        }
        self
    }
}
