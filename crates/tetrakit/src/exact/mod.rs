//! Exact minimal tetrahedralization by SAT (thesis ch. 3; Below, De Loera and
//! Richter-Gebert showed the problem NP-complete even for convex polyhedra).
//!
//! **Variables.** One per candidate tetrahedron: four vertices of the input spanning a
//! non-degenerate tetrahedron with no other vertex in its closed set (for a polyhedron,
//! also meeting no facet improperly and on the inner side of any facet it has). One per
//! interior edge, implied by the candidates containing it.
//!
//! **Clauses.** For every triangle of a candidate, the candidates on each side of its plane:
//! * at most one per side;
//! * a triangle inside the domain is used on both sides or on neither;
//! * a facet of the polyhedron is used exactly once, from inside; a triangle on the hull
//!   of a point set (its plane supports the set) at most once.
//!
//! For a point set, one *anchor* point strictly inside some candidate and on no candidate
//! triangle is covered by exactly one candidate.
//!
//! **Why this is exact.** Count, for a point `x`, the chosen tetrahedra containing it. The
//! count is constant off the chosen triangles, and crossing a triangle changes it by (uses
//! on one side) − (uses on the other), which the clauses make 0 inside the domain. So it is
//! constant on the domain's interior (connected), and equals 1: next to a facet (used once
//! from inside) for a polyhedron, at the anchor for a point set. Hence the chosen
//! tetrahedra cover the domain exactly once, meet face to face (an interior face is
//! matched by exactly one tetrahedron on the other side, and no candidate holds another
//! vertex), and form a tetrahedralization. Conversely every tetrahedralization satisfies
//! the clauses. The pairwise "interiors overlap" clauses of a direct encoding are
//! implied, which keeps the formula near-linear in the number of candidates. Every answer
//! is still certified afterwards by [`mesh::verify`].
//!
//! **Prescribed edges** ([`Edges`], thesis §2.5–2.6). With allowed segments (TETRAD) the
//! candidates are those whose six edges are allowed; with required segments (CT) those
//! that meet no required segment other than in shared vertices or as an edge. The
//! formula is still exact. A satisfying choice is a tetrahedralization, as above; its
//! edges are allowed, being candidates' edges; and each required segment is an edge of
//! it: a point inside the segment lies in some chosen tetrahedron, which the segment
//! meets only as one of its edges. Conversely a tetrahedralization obeying the rules
//! uses only candidates (its tetrahedra are empty, have allowed edges, and meet its own
//! edges face to face), so it satisfies the clauses. The clause "some chosen
//! tetrahedron has this required segment" is implied and added to help the solver.
//!
//! **A region with a hole** ([`Domain::Shell`], the region between nested polytopes
//! `Q ⊆ P`): candidates are also kept off the interior of `Q` (an exact separating-axis
//! test), triangles on a facet of `Q` (and on a facet of `P`, unless its triangles are
//! given) are used at most once, and an anchor is covered once, as for a point set. The
//! count is 0 inside `Q` (no candidate reaches it) and outside `P`, constant on the
//! region's interior (connected), 1 at the anchor; so the region is covered exactly
//! once, and its boundary triangles are those where the count changes.
//!
//! **Short pairs first.** When any tetrahedralization of a polyhedron of at least 40
//! vertices will do, the formula is first built over the candidates whose edges are short
//! (few vertices in their diametral ball) and solved; it is the same formula over fewer
//! candidates, so a model is a tetrahedralization by the argument above, and when it has
//! none the full formula decides. NOs and minima always come from the full formula.
//!
//! **Minimising.** By Euler's formula the number of tetrahedra is `e_i + c`, with `e_i`
//! the interior edges used. For a point set `c = 2·n_b − n − 3` (`n_b` vertices on the
//! boundary). For a region with boundary triangles `f_b` on `e_b` edges and Euler
//! characteristic `χ` (1 for a polyhedron, 2 for a shell whose polytopes share no facet), `4t = 2f_i + f_b` and
//! `n − e + f − t = χ` give `c = χ − n + e_b − f_b / 2`: the thesis's `t = e_i + n − 3`
//! for a polyhedron and Lemma 4.9's `t = e_i + n − 6` for disjoint simplicial shells.
//! So the solver bounds
//! a totalizer over the edge variables — far fewer than the tetrahedra — and searches
//! downward from each solution found until the bound is unsatisfiable.

mod certify;
mod core;
mod encode;
mod outcome;
pub(crate) mod path;
mod proof;
mod separate;

pub use certify::Uncertified;
pub use core::{FaceCore, SmallestCore, face_core, smallest_core};
pub use encode::{Domain, Edges, MAX_CANDIDATES};

pub use outcome::{TetraOptions, TetraOutcome, Witness, WitnessKind, tetrahedralize};
pub use path::{PathFound, hamiltonian_tetrahedralization};
pub use proof::{Proof, prove_infeasible};

use crate::control::Control;
use crate::mesh;
use encode::{Candidates, anchor, candidates};
use rustsat::encodings::card::{BoundUpper, BoundUpperIncremental, Totalizer};
use rustsat::instances::Cnf;
use rustsat::instances::{BasicVarManager, ManageVars};
use rustsat::solvers::{Solve, SolveIncremental, SolverResult};
use rustsat::types::{Clause, Lit, TernaryVal};

/// Options of [`minimal_tetrahedralization`].
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Also decide whether the minimum is attained by only one tetrahedralization.
    pub unique: bool,
    /// Stop at the first tetrahedralization found (decides existence only; the answer
    /// is then [`Outcome::Optimal`] only if it happens to meet the lower bound).
    pub any: bool,
}

/// The answer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// A minimum tetrahedralization (tetrahedra positively oriented).
    Optimal {
        /// The tetrahedra.
        tets: Vec<[u32; 4]>,
        /// With [`Options::unique`]: whether it is the only minimum one (`None` when the
        /// time ran out first).
        unique: Option<bool>,
        /// When not unique: another minimum tetrahedralization, as the witness.
        alternative: Option<Vec<[u32; 4]>>,
    },
    /// With [`Options::any`]: a tetrahedralization, not proven minimum.
    Found {
        /// The tetrahedra.
        tets: Vec<[u32; 4]>,
    },
    /// No tetrahedralization exists (the formula is unsatisfiable).
    Infeasible,
    /// The control was stopped (a time limit) first: the best bounds on the minimum
    /// number of tetrahedra.
    Undecided {
        /// The best tetrahedralization found, if any.
        best: Option<Vec<[u32; 4]>>,
        /// Proven lower bound.
        lower: usize,
    },
}

/// Size of the problem, reported alongside the outcome.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Candidate tetrahedra.
    pub candidates: usize,
    /// Candidate triangles.
    pub triangles: usize,
    /// Interior edges (the objective's variables).
    pub interior_edges: usize,
    /// SAT calls.
    pub calls: usize,
    /// With [`Outcome::Infeasible`]: the short reason found before any SAT call, if any.
    pub obstacle: Option<Obstacle>,
    /// `Some(m)` when the answer came from the formula over the short pairs with at most
    /// `m` vertices in their diametral ball (a large polyhedron, any tetrahedralization
    /// asked for); the sizes above are then that formula's.
    pub short: Option<usize>,
}

/// A short reason that no tetrahedralization exists, found from the candidates alone
/// (every vertex, required segment and facet must belong to a chosen tetrahedron).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Obstacle {
    /// No candidate tetrahedron at all.
    NoCandidate,
    /// This vertex is in no candidate.
    UncoveredVertex(u32),
    /// This required segment is an edge of no candidate.
    UnusableSegment([u32; 2]),
    /// This facet of the polyhedron is a face of no candidate.
    UncoveredFacet([u32; 3]),
}

impl std::fmt::Display for Obstacle {
    /// A sentence naming vertices `#v` (0-based).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Obstacle::NoCandidate => f.write_str("no candidate tetrahedron exists"),
            Obstacle::UncoveredVertex(v) => write!(f, "vertex #{v} is in no candidate tetrahedron"),
            Obstacle::UnusableSegment([a, b]) => {
                write!(
                    f,
                    "segment (#{a}, #{b}) is an edge of no candidate tetrahedron"
                )
            }
            Obstacle::UncoveredFacet([a, b, c]) => {
                write!(
                    f,
                    "facet (#{a}, #{b}, #{c}) is a face of no candidate tetrahedron"
                )
            }
        }
    }
}

impl Obstacle {
    /// The first obstacle of the candidates, if any.
    fn of(domain: Domain, edges: Edges, cand: &Candidates) -> Option<Obstacle> {
        if cand.tets.is_empty() {
            return Some(Obstacle::NoCandidate);
        }
        // A shell may have a vertex no tetrahedron uses: a corner of `Q` that fills the
        // corner of `P` it shares (the region is empty around it).
        let mut covered = vec![false; domain.points().len()];
        for &v in cand.tets.iter().flatten() {
            covered[v as usize] = true;
        }
        let shell = matches!(domain, Domain::Shell { .. });
        if let Some(v) = covered.iter().position(|&c| !c).filter(|_| !shell) {
            return Some(Obstacle::UncoveredVertex(v as u32));
        }
        if let Some(k) = cand.required.iter().position(|h| h.is_empty()) {
            return Some(Obstacle::UnusableSegment(edges.required[k]));
        }
        domain
            .faces()
            .iter()
            .find(|&&f| !cand.triangles.contains_key(&crate::mesh::sorted_face(f)))
            .map(|&f| Obstacle::UncoveredFacet(f))
    }
}

/// Why the solver could not run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ExactError {
    /// All points on a plane (or fewer than four): nothing to tetrahedralize.
    Flat,
    /// More vertices than the candidate enumeration handles.
    TooLarge(usize),
    /// More candidate tetrahedra (4-cliques of the allowed segments) than the solver
    /// takes.
    TooManyCandidates(usize),
    /// No anchor point could be placed (not expected; reported rather than guessed).
    NoAnchor,
    /// Writing a formula or proof failed (the writer's error kind; the caller knows the
    /// file).
    Io(std::io::ErrorKind),
    /// The solver's tetrahedra failed the independent certificate (a bug: please report
    /// the input).
    Uncertified(Uncertified),
}

impl std::fmt::Display for ExactError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ExactError::Flat => write!(f, "the points span no volume"),
            ExactError::TooLarge(n) => write!(
                f,
                "{n} vertices: the exact solver enumerates candidate tetrahedra and accepts at most {MAX_VERTICES} points (all C(n,4) subsets), {MAX_POLYHEDRON_VERTICES} polyhedron vertices, {MAX_RESTRICTED_VERTICES} with allowed segments"
            ),
            ExactError::TooManyCandidates(k) => write!(
                f,
                "more than {k} candidate tetrahedra (4-cliques of the segments): the exact solver takes at most {MAX_CANDIDATES}"
            ),
            ExactError::NoAnchor => {
                write!(f, "could not place an anchor point in general position")
            }
            ExactError::Io(e) => write!(f, "writing the formula or proof: {e}"),
            ExactError::Uncertified(e) => write!(
                f,
                "internal error, please report the input: the solver's tetrahedra fail the certificate: {e}"
            ),
        }
    }
}

impl std::error::Error for ExactError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ExactError::Uncertified(e) => Some(e),
            _ => None,
        }
    }
}

impl Domain<'_> {
    /// Certifies that `tets` tetrahedralize this domain: the convex hull with every point
    /// a vertex ([`mesh::certify_hull`]), or the polyhedron
    /// ([`mesh::certify_polyhedron`]). Returns the first problem found.
    ///
    /// ```
    /// use tetrakit::exact::Domain;
    /// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// assert!(Domain::Points(&pts).certify(&[[0, 1, 2, 3]]).is_ok());
    /// ```
    pub fn certify(&self, tets: &[[u32; 4]]) -> Result<(), mesh::Problem> {
        match self {
            Domain::Points(p) => mesh::certify_hull(p, tets),
            Domain::Polyhedron(p) => mesh::certify_polyhedron(p, tets),
            Domain::Shell { points, inner, .. } => mesh::certify_shell(points, tets, inner),
        }
    }
}

/// The largest input the candidate enumeration accepts when every 4-subset is a
/// candidate (no [`Edges::allowed`]).
pub const MAX_VERTICES: usize = 60;

/// The largest polyhedron (without [`Edges::allowed`]): its candidates are the
/// 4-cliques of the vertex pairs whose segment crosses no facet (found in `O(n² f)`), at
/// most [`MAX_CANDIDATES`] of them.
pub const MAX_POLYHEDRON_VERTICES: usize = 1000;

/// The largest input with [`Edges::allowed`] (its 4-cliques are the candidates, at most
/// [`MAX_CANDIDATES`] of them).
pub const MAX_RESTRICTED_VERTICES: usize = 1_000_000;

type Solver = crate::control::SatSolver;

/// The minimum number of tetrahedra over all tetrahedralizations of `domain` without
/// Steiner points, with one that attains it, or a proof that none exists. Once `ctl`
/// is stopped (the SAT solver asks it at its periodic checks) the answer is
/// [`Outcome::Undecided`] with the best bounds found.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::{Domain, Options, Outcome, minimal_tetrahedralization};
/// use tetrakit::polyhedra::generate;
/// let (opts, ctl) = (Options::default(), Control::new());
/// // Schönhardt's polyhedron has no tetrahedralization.
/// let s = generate::schonhardt();
/// let (out, _) = minimal_tetrahedralization(Domain::Polyhedron(&s), &opts, &ctl).unwrap();
/// assert_eq!(out, Outcome::Infeasible);
/// // A cube's corners: 5 tetrahedra at least.
/// let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64]).collect();
/// let (out, _) = minimal_tetrahedralization(Domain::Points(&cube), &opts, &ctl).unwrap();
/// let Outcome::Optimal { tets, .. } = out else { panic!() };
/// assert_eq!(tets.len(), 5);
/// ```
pub fn minimal_tetrahedralization(
    domain: Domain,
    options: &Options,
    ctl: &Control,
) -> Result<(Outcome, Stats), ExactError> {
    solve(domain, Edges::default(), options, ctl)
}

/// [`minimal_tetrahedralization`] among the tetrahedralizations whose edges obey
/// `edges`: only allowed segments (TETRAD, thesis §2.5), every required segment (CT,
/// §2.6). The same candidates, clauses and certificate; see the module docs for why the
/// formula is exact.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::{Edges, Options, Outcome, Domain, solve};
/// // A square pyramid: its base splits along one diagonal or the other.
/// let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 0.5, 1.0]];
/// let want = [[1, 3]];
/// let edges = Edges { required: &want, ..Edges::default() };
/// let (out, _) = solve(Domain::Points(&p), edges, &Options::default(), &Control::new()).unwrap();
/// let Outcome::Optimal { tets, .. } = out else { panic!() };
/// assert!(tets.iter().all(|t| t.contains(&1) && t.contains(&3)));
/// ```
pub fn solve(
    domain: Domain,
    edges: Edges,
    options: &Options,
    ctl: &Control,
) -> Result<(Outcome, Stats), ExactError> {
    let (outcome, stats) = solve_uncertified(domain, edges, options, ctl)?;
    for tets in outcome.tetrahedralizations() {
        certify::certify(domain, edges, tets).map_err(ExactError::Uncertified)?;
    }
    Ok((outcome, stats))
}

/// [`solve`] without the certificate.
fn solve_uncertified(
    domain: Domain,
    edges: Edges,
    options: &Options,
    ctl: &Control,
) -> Result<(Outcome, Stats), ExactError> {
    check_size(domain, edges)?;
    let Ok(pairs) = polyhedron_pairs(domain, edges, ctl) else {
        return Ok(stopped(domain));
    };
    let edges = restricted(edges, pairs.as_deref());
    if let Some(answer) = short_first(domain, edges, options, pairs.as_deref(), ctl)? {
        return Ok(answer);
    }
    let Some(f) = Formula::over(domain, edges, ctl)? else {
        return Ok(stopped(domain));
    };
    search(f, domain, edges, options, ctl)
}

/// The answer when `ctl` stopped before any formula was built.
fn stopped(domain: Domain) -> (Outcome, Stats) {
    let lower = encode::euler_offset(domain).max(1) as usize;
    (Outcome::Undecided { best: None, lower }, Stats::default())
}

/// The diametral-ball budgets of [`short_first`], tried in turn.
const SHORT_BUDGETS: [usize; 3] = [4, 8, 16];

/// Polyhedra from this many vertices try [`short_first`].
const SHORT_FROM: usize = 40;

/// A fast route to a YES for a large polyhedron when any tetrahedralization will do: the
/// formula over the candidates whose six edges are short unobstructed pairs (at most `m`
/// vertices inside their diametral ball, [`encode::short_pairs`], for each budget `m` of
/// [`SHORT_BUDGETS`]) and facet edges. A model of it is a tetrahedralization: its clauses
/// are those of the full formula restricted to fewer candidates, so the module's argument
/// applies unchanged. No model proves nothing, and `None` sends the caller on to the full
/// formula. Most candidates of a large polyhedron are long and crossed by many others, so
/// these formulas are far smaller (dented spheres of 120 vertices: 5,614 candidates at
/// `m = 4` against 813,295).
fn short_first(
    domain: Domain,
    edges: Edges,
    options: &Options,
    pairs: Option<&[[u32; 2]]>,
    ctl: &Control,
) -> Result<Option<(Outcome, Stats)>, ExactError> {
    let (Domain::Polyhedron(p), Some(pairs)) = (domain, pairs) else {
        return Ok(None);
    };
    if !options.any || !edges.required.is_empty() || p.points.len() < SHORT_FROM {
        return Ok(None);
    }
    for m in SHORT_BUDGETS {
        let short = encode::short_pairs(&p.points, pairs, &p.faces, m);
        if short.len() == pairs.len() {
            break; // the full formula itself
        }
        let sparse = Edges {
            allowed: Some(&short),
            ..edges
        };
        let Some(f) = Formula::over(domain, sparse, ctl)? else {
            return Ok(Some(stopped(domain)));
        };
        let (out, mut stats) = search(f, domain, sparse, options, ctl)?;
        if out != Outcome::Infeasible {
            stats.short = Some(m);
            return Ok(Some((out, stats)));
        }
    }
    Ok(None)
}

/// Fails when `domain` is too large for the candidate enumeration or spans no volume.
fn check_size(domain: Domain, edges: Edges) -> Result<(), ExactError> {
    let pts = domain.points();
    let limit = match (domain, edges.allowed) {
        (_, Some(_)) => MAX_RESTRICTED_VERTICES,
        (Domain::Polyhedron(_), None) => MAX_POLYHEDRON_VERTICES,
        _ => MAX_VERTICES,
    };
    if pts.len() > limit {
        return Err(ExactError::TooLarge(pts.len()));
    }
    if crate::geom::affine_dimension(pts) < 3 {
        return Err(ExactError::Flat);
    }
    Ok(())
}

/// A polyhedron's unobstructed vertex pairs ([`encode::unobstructed_pairs`]) when `edges`
/// allows every segment, else `None` (nothing to restrict). `Err` once `ctl` stops.
fn polyhedron_pairs(
    domain: Domain,
    edges: Edges,
    ctl: &Control,
) -> Result<Option<Vec<[u32; 2]>>, ()> {
    match (domain, edges.allowed) {
        (Domain::Polyhedron(p), None) => encode::unobstructed_pairs(&p.points, &p.faces, ctl)
            .map(Some)
            .ok_or(()),
        _ => Ok(None),
    }
}

/// `edges` with its allowed segments replaced by `pairs` when there are any.
fn restricted<'a>(edges: Edges<'a>, pairs: Option<&'a [[u32; 2]]>) -> Edges<'a> {
    match pairs {
        Some(p) => Edges {
            allowed: Some(p),
            ..edges
        },
        None => edges,
    }
}

/// Solves the formula `f` built for `domain` and `edges`: the search of [`solve`].
fn search(
    f: Formula,
    domain: Domain,
    edges: Edges,
    options: &Options,
    ctl: &Control,
) -> Result<(Outcome, Stats), ExactError> {
    let (cand, pts) = (&f.cand, domain.points());
    let mut stats = Stats {
        candidates: cand.tets.len(),
        triangles: cand.triangles.len(),
        interior_edges: cand.interior_edges.len(),
        calls: 0,
        obstacle: Obstacle::of(domain, edges, cand),
        short: None,
    };
    if stats.obstacle.is_some() {
        return Ok((Outcome::Infeasible, stats));
    }
    let (cand, mut solver, mut vars, tet_lits) = f.into_solver(ctl);
    let edge_lits: Vec<Lit> = cand
        .interior_edges
        .iter()
        .map(|(_, holders)| {
            let y = vars.new_lit();
            for &t in holders {
                add(&mut solver, &[!tet_lits[t as usize], y]);
            }
            y
        })
        .collect();
    let mut totalizer = Totalizer::from(edge_lits.clone());
    let lower = (cand.offset.max(1)) as usize;
    let mut best: Option<Vec<[u32; 4]>> = None;
    let mut bound: Option<usize> = None; // edges allowed
    loop {
        let assumptions = match bound {
            None => Vec::new(),
            Some(b) => {
                totalizer
                    .encode_ub_change(b..=b, &mut solver, &mut vars)
                    .expect("clause memory");
                totalizer.enforce_ub(b).expect("encoded")
            }
        };
        stats.calls += 1;
        match solver.solve_assumps(&assumptions).expect("batsat") {
            SolverResult::Sat => {
                let tets = chosen(&solver, &cand, &tet_lits, pts);
                let used = edge_count(&tets, &cand);
                best = Some(tets);
                if options.any && used > 0 {
                    return Ok((
                        Outcome::Found {
                            tets: best.unwrap_or_default(),
                        },
                        stats,
                    ));
                }
                if used == 0 {
                    break;
                }
                bound = Some(used - 1);
            }
            SolverResult::Unsat => break,
            SolverResult::Interrupted => {
                return Ok((Outcome::Undecided { best, lower }, stats));
            }
        }
    }
    let Some(tets) = best else {
        return Ok((Outcome::Infeasible, stats));
    };
    let mut alternative = None;
    let unique = if options.unique {
        let b = edge_count(&tets, &cand);
        totalizer
            .encode_ub_change(b..=b, &mut solver, &mut vars)
            .expect("clause memory");
        let mut assumptions = totalizer.enforce_ub(b).expect("encoded");
        // Block this solution: some chosen tetrahedron must go.
        let gate = vars.new_lit();
        let mut block: Vec<Lit> = chosen_indices(&tets, &cand).map(|i| !tet_lits[i]).collect();
        block.push(!gate);
        add(&mut solver, &block);
        assumptions.push(gate);
        stats.calls += 1;
        match solver.solve_assumps(&assumptions).expect("batsat") {
            SolverResult::Sat => {
                alternative = Some(chosen(&solver, &cand, &tet_lits, pts));
                Some(false)
            }
            SolverResult::Unsat => Some(true),
            SolverResult::Interrupted => None,
        }
    } else {
        None
    };
    Ok((
        Outcome::Optimal {
            tets,
            unique,
            alternative,
        },
        stats,
    ))
}

fn add(solver: &mut Solver, lits: &[Lit]) {
    solver
        .add_clause(lits.iter().copied().collect::<Clause>())
        .expect("batsat accepts clauses");
}

/// Each guarded triangle with the literal its clauses hold under
/// ([`Formula::guarded`]).
type Guards = Vec<([u32; 3], Lit)>;

/// The candidates of a problem and the formula saying "these candidates form a
/// tetrahedralization" (without the objective), one variable per candidate first.
struct Formula {
    cand: Candidates,
    cnf: Cnf,
    vars: BasicVarManager,
    tet_lits: Vec<Lit>,
}

impl Formula {
    /// The candidates, a solver (stopped by `ctl`) holding the formula, its variables
    /// and the candidates' literals.
    fn into_solver(self, ctl: &Control) -> (Candidates, Solver, BasicVarManager, Vec<Lit>) {
        let mut solver = crate::control::sat_solver(ctl);
        solver.add_cnf(self.cnf).expect("batsat accepts clauses");
        (self.cand, solver, self.vars, self.tet_lits)
    }

    /// `None` when `ctl` stopped the enumeration.
    fn new(domain: Domain, edges: Edges, ctl: &Control) -> Result<Option<Formula>, ExactError> {
        check_size(domain, edges)?;
        let Ok(pairs) = polyhedron_pairs(domain, edges, ctl) else {
            return Ok(None);
        };
        Formula::over(domain, restricted(edges, pairs.as_deref()), ctl)
    }

    /// [`Formula::new`] once the size is checked and a polyhedron's pairs restricted.
    fn over(domain: Domain, edges: Edges, ctl: &Control) -> Result<Option<Formula>, ExactError> {
        Formula::guarded(domain, edges, ctl, None)
    }

    /// [`Formula::over`]; with `guards`, each facet's covering clause and each inner
    /// face's pairing clauses hold only under a literal of their own, listed there (for
    /// [`core::face_core`]).
    fn guarded(
        domain: Domain,
        edges: Edges,
        ctl: &Control,
        guards: Option<&mut Guards>,
    ) -> Result<Option<Formula>, ExactError> {
        let cand = match candidates(domain, edges, ctl) {
            Ok(Some(c)) => c,
            Ok(None) => return Ok(None),
            Err(encode::TooMany(k)) => return Err(ExactError::TooManyCandidates(k)),
        };
        let mut vars = BasicVarManager::default();
        let tet_lits: Vec<Lit> = (0..cand.tets.len()).map(|_| vars.new_lit()).collect();
        let mut cnf = Cnf::new();
        if !cand.tets.is_empty() {
            let anchor = match domain {
                Domain::Points(p) | Domain::Shell { points: p, .. } => {
                    Some(anchor(p, &cand).ok_or(ExactError::NoAnchor)?)
                }
                Domain::Polyhedron(_) => None,
            };
            add_structure(
                (&mut cnf, &mut vars),
                &cand,
                &tet_lits,
                domain,
                (anchor.as_deref(), guards),
            );
        }
        Ok(Some(Formula {
            cand,
            cnf,
            vars,
            tet_lits,
        }))
    }
}

fn push(cnf: &mut Cnf, lits: &[Lit]) {
    cnf.add_clause(lits.iter().copied().collect::<Clause>());
}

/// At most one of `lits` (pairwise for few, sequential counter otherwise).
fn at_most_one(solver: &mut Cnf, vars: &mut BasicVarManager, lits: &[Lit]) {
    if lits.len() <= 6 {
        for i in 0..lits.len() {
            for j in i + 1..lits.len() {
                push(solver, &[!lits[i], !lits[j]]);
            }
        }
        return;
    }
    let s: Vec<Lit> = (0..lits.len() - 1).map(|_| vars.new_lit()).collect();
    for i in 0..lits.len() {
        if i + 1 < lits.len() {
            push(solver, &[!lits[i], s[i]]);
        }
        if i > 0 {
            push(solver, &[!s[i - 1], !lits[i]]);
            if i + 1 < lits.len() {
                push(solver, &[!s[i - 1], s[i]]);
            }
        }
    }
}

fn add_structure(
    (solver, vars): (&mut Cnf, &mut BasicVarManager),
    cand: &Candidates,
    tet: &[Lit],
    domain: Domain,
    (anchor, mut guards): (Option<&[u32]>, Option<&mut Guards>),
) {
    let facets: std::collections::HashSet<[u32; 3]> = domain
        .faces()
        .iter()
        .map(|&f| crate::mesh::sorted_face(f))
        .collect();
    let lits = |ids: &[u32]| -> Vec<Lit> { ids.iter().map(|&i| tet[i as usize]).collect() };
    // A new guard for triangle `key`'s clauses (its negation, to add to each), where
    // there are guards.
    let mut guard = |vars: &mut BasicVarManager, key: [u32; 3]| {
        guards.as_deref_mut().map(|g| {
            let s = vars.new_lit();
            g.push((key, s));
            !s
        })
    };
    let mut keys: Vec<&[u32; 3]> = cand.triangles.keys().collect();
    keys.sort_unstable();
    for key in keys {
        let usage = &cand.triangles[key];
        let (pos, neg) = (lits(&usage.pos), lits(&usage.neg));
        at_most_one(solver, vars, &pos);
        at_most_one(solver, vars, &neg);
        if facets.contains(key) {
            // Candidates on a facet were filtered to its inner side: all on one side.
            let inner = if pos.is_empty() { &neg } else { &pos };
            match guard(vars, *key) {
                Some(g) => push(solver, &[inner.as_slice(), &[g]].concat()),
                None => push(solver, inner),
            }
            continue;
        }
        if usage.on_hull {
            continue;
        }
        // The face's pairing clauses, under its guard where there are guards.
        let guard = guard(vars, *key);
        for (side, other) in [(&pos, &neg), (&neg, &pos)] {
            for &t in side.iter() {
                let mut c = vec![!t];
                c.extend(other.iter().copied());
                c.extend(guard);
                push(solver, &c);
            }
        }
    }
    // A facet no candidate has: no tetrahedralization.
    if facets.iter().any(|f| !cand.triangles.contains_key(f)) {
        push(solver, &[]);
    }
    // A required segment is an edge of some chosen tetrahedron (implied, as no
    // candidate crosses it; stated to help the solver, and empty when none has it).
    for holders in &cand.required {
        push(solver, &lits(holders));
    }
    if let Some(holders) = anchor {
        let l = lits(holders);
        push(solver, &l);
        at_most_one(solver, vars, &l);
    }
}

fn chosen(
    solver: &Solver,
    cand: &Candidates,
    tet: &[Lit],
    pts: &[crate::geom::Point3],
) -> Vec<[u32; 4]> {
    cand.tets
        .iter()
        .zip(tet)
        .filter(|&(_, &l)| solver.lit_val(l).expect("sat") == TernaryVal::True)
        .map(|(t, _)| {
            let [a, b, c, d] = t.map(|v| &pts[v as usize]);
            if crate::geom::orient3d(a, b, c, d) > 0 {
                *t
            } else {
                [t[0], t[2], t[1], t[3]]
            }
        })
        .collect()
}

fn chosen_indices<'a>(
    tets: &'a [[u32; 4]],
    cand: &'a Candidates,
) -> impl Iterator<Item = usize> + 'a {
    tets.iter().map(move |t| {
        let mut s = *t;
        s.sort_unstable();
        cand.tets.binary_search(&s).expect("chosen from candidates")
    })
}

/// The interior edges `tets` use (the totalizer's variables that are true), counted on
/// the tetrahedra themselves so that the search never depends on Euler's offset.
fn edge_count(tets: &[[u32; 4]], cand: &Candidates) -> usize {
    let mut edges: Vec<[u32; 2]> = tets
        .iter()
        .flat_map(|t| {
            [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)].map(|(i, j)| {
                let (a, b) = (t[i], t[j]);
                [a.min(b), a.max(b)]
            })
        })
        .collect();
    edges.sort_unstable();
    edges.dedup();
    edges
        .iter()
        .filter(|e| {
            cand.interior_edges
                .binary_search_by(|(x, _)| x.cmp(e))
                .is_ok()
        })
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Stopped before the first SAT call, the solver answers `Undecided` with the
    /// lower bound and no tetrahedralization; a live control finds the minimum.
    #[test]
    fn a_stopped_control_gives_undecided() {
        let cube: Vec<[f64; 3]> = (0..8)
            .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64])
            .collect();
        let opts = Options::default();
        let stopped = Control::new();
        stopped.stop();
        let (out, _) = minimal_tetrahedralization(Domain::Points(&cube), &opts, &stopped).unwrap();
        assert!(
            matches!(out, Outcome::Undecided { best: None, .. }),
            "{out:?}"
        );
        let (out, _) =
            minimal_tetrahedralization(Domain::Points(&cube), &opts, &Control::new()).unwrap();
        assert!(matches!(out, Outcome::Optimal { ref tets, .. } if tets.len() == 5));
    }

    /// Large dented polyhedra are answered from the short pairs' formula, certified; a
    /// polyhedron with no tetrahedralization still gets its NO from the full formula
    /// (the short formulas prove nothing); and asking for the minimum never takes the
    /// short route.
    #[test]
    fn short_pairs_answer_large_polyhedra_and_never_decide_a_no() {
        let any = Options {
            any: true,
            ..Options::default()
        };
        let ctl = Control::new();
        for seed in 0..4 {
            let p = crate::polyhedra::hard::perturbed(90, 0.5, seed).unwrap();
            let (out, stats) = solve(Domain::Polyhedron(&p), Edges::default(), &any, &ctl).unwrap();
            let tets = match out {
                Outcome::Found { tets } | Outcome::Optimal { tets, .. } => tets,
                other => panic!("seed {seed}: {other:?}"),
            };
            assert!(stats.short.is_some(), "seed {seed}");
            mesh::certify_polyhedron(&p, &tets).unwrap();
        }
        let c = crate::polyhedra::hard::chazelle(3).unwrap();
        let (out, stats) = solve(Domain::Polyhedron(&c), Edges::default(), &any, &ctl).unwrap();
        assert_eq!((out, stats.short), (Outcome::Infeasible, None));
        let small = crate::polyhedra::hard::perturbed(44, 0.5, 1).unwrap();
        let brief = Control::new().with_time_limit(std::time::Duration::from_millis(300));
        let (_, stats) =
            minimal_tetrahedralization(Domain::Polyhedron(&small), &Options::default(), &brief)
                .unwrap();
        assert_eq!(stats.short, None);
    }
}
