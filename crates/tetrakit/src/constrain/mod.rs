//! Tetrahedralizations with prescribed edges, decided exactly (thesis ch. 2 §2.5–2.6):
//! both problems are NP-complete (Theorems 2.9 and 2.11), so the answer comes from the
//! SAT formula of [`crate::exact`], after the cheap checks that settle most inputs.
//!
//! * [`contains`] (TETRAD, §2.5): does a segment set `L` *contain* the edge set of a
//!   tetrahedralization of its points (their convex hull, every point a vertex)? Segments
//!   of `L` that are not used may cross anything. When `L` is exactly an edge set,
//!   [`crate::detect`] answers at any size; otherwise the candidates are the tetrahedra
//!   with all six edges in `L` and no other point in them.
//! * [`constrained`] (CT, §2.6): is there a tetrahedralization of the points that has
//!   every given segment as an edge? Constraints that cross, or pass through a point, are
//!   a NO before any search; otherwise the candidates are the empty tetrahedra that meet
//!   no constraint improperly.
//! * Planar input (TRID, Lloyd): points in one plane are coned from an apex off the plane,
//!   joined to every point (the reduction at the start of §2.5). The tetrahedralizations
//!   of the cone are exactly the apex joined to the triangulations of the points, so the
//!   same solver decides the planar problem, and the answer is given as triangles.
//!
//! Every YES is certified by [`crate::exact::solve`] (on the points, or the cone: the hull, its
//! edges allowed, every required one an edge); every NO carries a [`Witness`]: a short one
//! when the checks find it, otherwise the
//! formula's unsatisfiability, which [`crate::exact::prove_infeasible`] turns into a DRAT
//! proof.

pub mod generate;
mod niche;
mod witness;

pub use niche::{Niche, find_niches};
pub use witness::{Witness, WitnessKind};

use crate::control::Control;
use crate::detect::{self, Cells, Graph, SegmentError};
use crate::exact::{self, Domain, Edges, ExactError, Outcome, Stats};
use crate::geom::{Point3, orient2d};

/// What to look for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// A tetrahedralization with the fewest tetrahedra among the allowed ones (otherwise
    /// any; a YES from [`crate::detect`] is the only one and so the minimum).
    pub minimal: bool,
}

/// The answer of [`contains`] or [`constrained`]: the cells (certified), a witness, or
/// undecided when the control stopped the search first ([`detect`]'s answer over this
/// module's kinds of witness).
pub type Answer = detect::Answer<WitnessKind>;

/// Which step answered.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Route {
    /// [`crate::detect`]: the segments are exactly the edge set of a tetrahedralization.
    Detect,
    /// A check before the search (crossing constraints, a missing hull edge, a vertex in
    /// no candidate, ...).
    Precheck,
    /// The SAT solver.
    Solver,
}

/// The answer with how it was found.
#[derive(Clone, Debug, PartialEq)]
pub struct Decision {
    /// The answer.
    pub answer: Answer,
    /// Which step gave it.
    pub route: Route,
    /// The solver's problem size (zero when it did not run).
    pub stats: Stats,
    /// Whether a YES is proven to have the fewest tetrahedra (triangles) allowed.
    pub minimum: bool,
    /// The points were coplanar: solved on the cone from an apex (vertex `n`), answer
    /// given as triangles.
    pub planar: bool,
}

impl Decision {
    /// The verdict of the answer: `yes`, `no` (with its witness), or `undecided`.
    pub fn verdict(&self) -> crate::control::Verdict {
        self.answer.verdict()
    }
}

/// Why no decision could be made.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ConstrainError {
    /// A segment names a missing vertex, joins a vertex to itself, or is repeated.
    Segments(SegmentError),
    /// Two points coincide.
    Duplicate([u32; 2]),
    /// The solver cannot take the input (too large, collinear points).
    Exact(ExactError),
}

impl std::fmt::Display for ConstrainError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ConstrainError::Segments(e) => e.fmt(f),
            ConstrainError::Duplicate([a, b]) => {
                write!(f, "points #{a} and #{b} coincide")
            }
            ConstrainError::Exact(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for ConstrainError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ConstrainError::Segments(e) => Some(e),
            ConstrainError::Exact(e) => Some(e),
            ConstrainError::Duplicate(_) => None,
        }
    }
}

impl From<ExactError> for ConstrainError {
    fn from(e: ExactError) -> Self {
        ConstrainError::Exact(e)
    }
}

/// TETRAD: does `segments` contain the edge set of a tetrahedralization of `points` (or,
/// for coplanar points, of a triangulation)?
///
/// ```
/// use tetrakit::constrain::{Answer, Options, contains};
/// use tetrakit::control::Control;
/// // A square pyramid and both diagonals of its base: either diagonal will do.
/// let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5, 1.0]];
/// let mut l = vec![[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [1, 4], [2, 4], [3, 4], [0, 2]];
/// let yes = contains(&p, &l, &Options::default(), &Control::new()).unwrap();
/// assert!(matches!(yes.answer, Answer::Yes(_)));
/// l.pop(); // no diagonal: the base cannot be split
/// let no = contains(&p, &l, &Options::default(), &Control::new()).unwrap();
/// assert!(matches!(no.answer, Answer::No(_)));
/// ```
pub fn contains(
    points: &[Point3],
    segments: &[[u32; 2]],
    options: &Options,
    ctl: &Control,
) -> Result<Decision, ConstrainError> {
    validate(points, segments)?;
    let d = detect::detect(points, segments, &detect::Options::default(), ctl)
        .map_err(ConstrainError::Segments)?;
    match d.answer {
        detect::Answer::Yes(cells) => {
            let planar = d.dimension == 2;
            return Ok(decided(Answer::Yes(cells), Route::Detect, true, planar));
        }
        detect::Answer::Undecided => {
            return Ok(decided(Answer::Undecided, Route::Detect, false, false));
        }
        detect::Answer::No(_) => {}
    }
    let problem = Problem::new(points, segments)?;
    if let Some(w) = witness::missing_hull_edge(&problem.points, &problem.allowed) {
        return Ok(problem.decided(Answer::No(w), Route::Precheck));
    }
    problem.solve(problem.edges(Question::Contains, segments), options, ctl)
}

/// CT: is there a tetrahedralization of `points` (every point a vertex) with every one of
/// `segments` as an edge (for coplanar points, a triangulation)?
///
/// ```
/// use tetrakit::constrain::{Answer, Options, WitnessKind, constrained};
/// use tetrakit::control::Control;
/// let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5, 1.0]];
/// let yes = constrained(&p, &[[1, 3]], &Options::default(), &Control::new()).unwrap();
/// assert!(matches!(yes.answer, Answer::Yes(_)));
/// // The two diagonals of the base cross.
/// let no = constrained(&p, &[[1, 3], [0, 2]], &Options::default(), &Control::new()).unwrap();
/// let Answer::No(w) = no.answer else { panic!() };
/// assert_eq!(w.kind, WitnessKind::CrossingConstraints);
/// ```
pub fn constrained(
    points: &[Point3],
    segments: &[[u32; 2]],
    options: &Options,
    ctl: &Control,
) -> Result<Decision, ConstrainError> {
    validate(points, segments)?;
    let problem = Problem::new(points, &[])?;
    if let Some(w) = witness::bad_constraints(points, segments, ctl) {
        return Ok(problem.decided(Answer::No(w), Route::Precheck));
    }
    let mut d = problem.solve(problem.edges(Question::Constrained, segments), options, ctl)?;
    if let Answer::No(w) = &mut d.answer
        && w.kind == WitnessKind::Unsatisfiable
        && let Some(n) = find_niches(points, segments)
            .into_iter()
            .find(|n| n.vertex_in_view(points).is_none())
    {
        *w = witness::empty_niche_view(&n, d.stats.candidates);
    }
    Ok(d)
}

/// Which of the two problems.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Question {
    /// [`contains`].
    Contains,
    /// [`constrained`].
    Constrained,
}

/// Writes the formula that [`contains`] or [`constrained`] decides (DIMACS, each
/// candidate named in a comment) and, when it is unsatisfiable, a DRAT refutation
/// ([`exact::prove_infeasible`]). Every NO of either has one, short witnesses included:
/// the formula is unsatisfiable whenever no tetrahedralization obeys the edge rules.
///
/// ```
/// use tetrakit::constrain::{Question, prove};
/// use tetrakit::control::Control;
/// use tetrakit::exact::Proof;
/// let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5, 1.0]];
/// let (mut cnf, mut drat) = (Vec::new(), Vec::new());
/// let r = prove(Question::Constrained, &p, &[[1, 3], [0, 2]], &mut cnf, &mut drat, &Control::new());
/// assert!(matches!(r, Ok(Proof::Refuted { .. })));
/// ```
pub fn prove(
    question: Question,
    points: &[Point3],
    segments: &[[u32; 2]],
    formula: &mut impl std::io::Write,
    proof: impl std::io::Write,
    ctl: &Control,
) -> Result<exact::Proof, ConstrainError> {
    validate(points, segments)?;
    let allowed: &[[u32; 2]] = match question {
        Question::Contains => segments,
        Question::Constrained => &[],
    };
    let problem = Problem::new(points, allowed)?;
    let edges = problem.edges(question, segments);
    Ok(exact::prove_infeasible(
        Domain::Points(&problem.points),
        edges,
        formula,
        proof,
        ctl,
    )?)
}

fn decided(answer: Answer, route: Route, minimum: bool, planar: bool) -> Decision {
    Decision {
        answer,
        route,
        stats: Stats::default(),
        minimum,
        planar,
    }
}

/// Segments must name existing, distinct vertices once each; points must be distinct.
fn validate(points: &[Point3], segments: &[[u32; 2]]) -> Result<(), ConstrainError> {
    Graph::new(points.len(), segments).map_err(ConstrainError::Segments)?;
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    order.sort_by(|&i, &j| crate::geom::lex_cmp(&points[i as usize], &points[j as usize]));
    for w in order.windows(2) {
        if points[w[0] as usize] == points[w[1] as usize] {
            return Err(ConstrainError::Duplicate([w[0].min(w[1]), w[0].max(w[1])]));
        }
    }
    Ok(())
}

/// The points the solver sees (with the apex for planar input) and the allowed segments
/// (with the apex's spokes).
struct Problem {
    points: Vec<Point3>,
    allowed: Vec<[u32; 2]>,
    /// The input's point count (the apex is vertex `n` when planar).
    n: usize,
    planar: bool,
}

impl Problem {
    fn new(points: &[Point3], segments: &[[u32; 2]]) -> Result<Problem, ExactError> {
        let n = points.len();
        let mut pts = points.to_vec();
        let mut allowed = segments.to_vec();
        let planar = match crate::geom::affine_dimension(points) {
            3 => false,
            2 => {
                pts.push(apex(points).ok_or(ExactError::Flat)?);
                allowed.extend((0..n as u32).map(|v| [v, n as u32]));
                true
            }
            _ => return Err(ExactError::Flat),
        };
        Ok(Problem {
            points: pts,
            allowed,
            n,
            planar,
        })
    }

    /// The edge rules of `question` on this problem.
    fn edges<'a>(&'a self, question: Question, segments: &'a [[u32; 2]]) -> Edges<'a> {
        match question {
            Question::Contains => Edges {
                allowed: Some(&self.allowed),
                required: &[],
            },
            Question::Constrained => Edges {
                allowed: None,
                required: segments,
            },
        }
    }

    fn decided(&self, answer: Answer, route: Route) -> Decision {
        decided(answer, route, false, self.planar)
    }

    fn solve(
        &self,
        edges: Edges,
        options: &Options,
        ctl: &Control,
    ) -> Result<Decision, ConstrainError> {
        let opts = exact::Options {
            unique: false,
            any: !options.minimal,
        };
        // `exact::solve` certifies its tetrahedralizations, the edge rules included.
        let (outcome, stats) = exact::solve(Domain::Points(&self.points), edges, &opts, ctl)?;
        let (answer, minimum) = match outcome {
            Outcome::Optimal { tets, .. } => (Answer::Yes(self.cells(tets)), true),
            Outcome::Found { tets } => (Answer::Yes(self.cells(tets)), false),
            Outcome::Infeasible => {
                let mut w = match &stats.obstacle {
                    Some(o) => witness::from_obstacle(o, self.n),
                    None => Witness::unsatisfiable(stats.candidates),
                };
                if self.planar {
                    // The cone's tetrahedra are the apex over the plane's triangles.
                    w.detail = w
                        .detail
                        .replace("tetrahedralization", "triangulation")
                        .replace("tetrahedron", "triangle")
                        .replace("tetrahedra", "triangles");
                }
                (Answer::No(w), false)
            }
            Outcome::Undecided { .. } => (Answer::Undecided, false),
        };
        let route = match stats.obstacle {
            Some(_) => Route::Precheck,
            None => Route::Solver,
        };
        Ok(Decision {
            answer,
            route,
            stats,
            minimum,
            planar: self.planar,
        })
    }

    /// The solver's tetrahedra as the answer's cells: for planar input, the triangles
    /// under the apex, counter-clockwise in [`crate::geom::project_to_plane`]'s plane.
    fn cells(&self, tets: Vec<[u32; 4]>) -> Cells {
        if !self.planar {
            return Cells::Tetrahedra(tets);
        }
        let flat = crate::geom::project_to_plane(&self.points[..self.n]).expect("planar");
        let apex = self.n as u32;
        let tris = tets
            .iter()
            .map(|t| {
                let mut f = [0u32; 3];
                for (k, &v) in t.iter().filter(|&&v| v != apex).enumerate() {
                    f[k] = v;
                }
                let [a, b, c] = f.map(|v| &flat[v as usize]);
                if orient2d(a, b, c) > 0 {
                    f
                } else {
                    [f[0], f[2], f[1]]
                }
            })
            .collect();
        Cells::Triangles(tris)
    }
}

/// A point off the plane of coplanar `points`: above their centroid along the normal of
/// a non-degenerate triple, at the scale of the points (checked exactly).
fn apex(points: &[Point3]) -> Option<Point3> {
    let a = points[0];
    let b = *points.iter().find(|p| **p != a)?;
    let c = *points
        .iter()
        .find(|c| crate::geom::projection_axis(&a, &b, c).is_some())?;
    let (u, v) = (sub(&b, &a), sub(&c, &a));
    let normal = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let (lo, hi) = crate::geom::bounding_box(points);
    let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    let len = normal.iter().map(|x| x * x).sum::<f64>().sqrt();
    let centre: Point3 = std::array::from_fn(|k| (lo[k] + hi[k]) / 2.0);
    let x: Point3 = std::array::from_fn(|k| centre[k] + normal[k] / len * size);
    let ok = x.iter().all(|&t| crate::geom::coordinate_in_range(t))
        && crate::geom::orient3d(&a, &b, &c, &x) != 0;
    ok.then_some(x)
}

fn sub(p: &Point3, q: &Point3) -> [f64; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}
