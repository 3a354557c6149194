//! The `tetrahedralize` capability as one call: the exact solver on a point set's hull or
//! a polyhedron, its answer certified ([`solve`](super::solve) certifies every
//! tetrahedralization it returns) and every NO given its witness, as one outcome that the
//! CLI and Python print through [`crate::report`].

use super::{Domain, Edges, ExactError, Obstacle, Options, Outcome, Stats, solve};
use crate::control::{Control, Verdict};
use serde::Serialize;

/// What [`tetrahedralize`] is asked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TetraOptions {
    /// The fewest tetrahedra (else the first tetrahedralization found).
    pub minimal: bool,
    /// With `minimal`: also decide whether the minimum is attained only once.
    pub unique: bool,
}

/// What a witness of a NO shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WitnessKind {
    /// No tetrahedron on the vertices is a candidate.
    NoCandidate,
    /// A vertex is in no candidate tetrahedron.
    UncoveredVertex,
    /// A required segment is an edge of no candidate.
    UnusableSegment,
    /// A facet is a face of no candidate.
    UncoveredFacet,
    /// The formula over the candidates is unsatisfiable ([`super::prove_infeasible`]
    /// writes it with a DRAT refutation).
    Unsatisfiable,
}

impl WitnessKind {
    /// Every kind, in declaration order (the order of the JSON contract's list).
    pub const ALL: [WitnessKind; 5] = [
        WitnessKind::NoCandidate,
        WitnessKind::UncoveredVertex,
        WitnessKind::UnusableSegment,
        WitnessKind::UncoveredFacet,
        WitnessKind::Unsatisfiable,
    ];
}

impl std::fmt::Display for WitnessKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::numbering::json_name(self, "witness"))
    }
}

/// Why no tetrahedralization without Steiner points exists: a short obstacle found from
/// the candidates alone, or the unsatisfiable formula. Its vertices are a vertex, a
/// segment's ends or a facet's corners; its segments the unusable segment.
pub type Witness = crate::witness::Witness<WitnessKind>;

impl Witness {
    /// The witness of a NO with these `stats`.
    pub fn of(stats: &Stats) -> Witness {
        let (kind, vertices, segments) = match &stats.obstacle {
            None => (WitnessKind::Unsatisfiable, Vec::new(), Vec::new()),
            Some(Obstacle::NoCandidate) => (WitnessKind::NoCandidate, Vec::new(), Vec::new()),
            Some(Obstacle::UncoveredVertex(v)) => (WitnessKind::UncoveredVertex, vec![*v], vec![]),
            Some(Obstacle::UnusableSegment(s)) => {
                (WitnessKind::UnusableSegment, s.to_vec(), vec![*s])
            }
            Some(Obstacle::UncoveredFacet(f)) => (WitnessKind::UncoveredFacet, f.to_vec(), vec![]),
        };
        let detail = match &stats.obstacle {
            Some(o) => o.to_string(),
            None => format!(
                "no set of the {} candidate tetrahedra (no other vertex inside, on the inner side of the boundary) satisfies the face-pairing clauses: no tetrahedralization without Steiner points exists",
                stats.candidates
            ),
        };
        Witness::new(kind, vertices, segments, detail)
    }
}

/// Polyhedra with at most this many vertices whose NO needs the SAT refutation name
/// the vertices of a minimal core of it ([`super::face_core`]: a few more SAT calls);
/// larger ones keep the formula's witness alone.
const CORE_UP_TO: usize = 40;

/// Polyhedra with at most this many vertices name the core with the fewest vertices
/// ([`super::smallest_core`], every vertex set tried: at most 0.03 s measured).
const SMALLEST_UP_TO: usize = 12;

/// The witness of a NO: [`Witness::of`], with the vertices and facets of a core of the
/// refutation where the domain is a polyhedron of at most [`CORE_UP_TO`] vertices (the
/// smallest core up to [`SMALLEST_UP_TO`], a minimal one beyond) and the core is found
/// before `ctl` stops.
fn no_witness(domain: Domain, stats: &Stats, ctl: &Control) -> Result<Witness, ExactError> {
    let w = Witness::of(stats);
    let Domain::Polyhedron(p) = domain else {
        return Ok(w);
    };
    if w.kind != WitnessKind::Unsatisfiable || p.points.len() > CORE_UP_TO {
        return Ok(w);
    }
    let n = p.points.len();
    let (core, which) = match n <= SMALLEST_UP_TO {
        true => {
            let s = super::smallest_core(p, n, ctl)?;
            (
                s.and_then(|s| s.core),
                "the smallest core (fewest vertices)",
            )
        }
        false => (super::face_core(p, ctl)?, "a minimal core"),
    };
    let Some(core) = core else {
        return Ok(w);
    };
    let facets: Vec<String> = (core.facets.iter())
        .map(|f| format!("#{} #{} #{}", f[0], f[1], f[2]))
        .collect();
    let detail = format!(
        "no set of the {} candidate tetrahedra (no other vertex inside, on the inner side of the boundary) satisfies the face-pairing clauses; {which} of the refutation covers the {} facet(s) {} and pairs {} inner face(s), on {} vertices: no tetrahedralization without Steiner points exists",
        stats.candidates,
        core.facets.len(),
        facets.join(", "),
        core.faces.len(),
        core.vertices.len()
    );
    Ok(Witness::new(w.kind, core.vertices, Vec::new(), detail))
}

/// The outcome of [`tetrahedralize`]: `yes` with certified tetrahedra (the minimum when
/// asked), `no` with a [`Witness`], or `undecided` (stopped) with bounds on the minimum
/// and the best tetrahedralization found. Serialized, the JSON of
/// `tetrakit tetrahedralize --json` without the file's fields and timing.
#[derive(Clone, Debug, Serialize)]
pub struct TetraOutcome {
    /// `yes`, `no`, or `undecided` when stopped.
    pub verdict: Verdict,
    /// Vertices of the domain.
    pub vertices: usize,
    /// `"convex hull"` (of a point set, every point a vertex), `"polyhedron"` or
    /// `"shell"`.
    pub domain: &'static str,
    /// Candidate tetrahedra of the formula that decided.
    pub candidates: usize,
    /// SAT calls.
    pub sat_calls: usize,
    /// When the answer came from the formula over short pairs: its diametral-ball budget.
    pub short_pairs_budget: Option<usize>,
    /// With `minimal`, a YES: the fewest tetrahedra.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub minimum: Option<usize>,
    /// With `unique`, a YES: whether the minimum is attained only once (`null` when the
    /// time ran out first).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unique: Option<Option<bool>>,
    /// With `unique` and not unique: another minimum tetrahedralization, certified.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alternative: Option<Vec<[u32; 4]>>,
    /// Undecided: the proven lower bound on the minimum.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lower_bound: Option<usize>,
    /// Undecided: the size of the best tetrahedralization found.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub upper_bound: Option<usize>,
    /// The size of `tets`, when there are any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tetrahedra: Option<usize>,
    /// True when `tets` were certified (always, when there are any).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub certified: Option<bool>,
    /// The reason for a NO.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<Witness>,
    /// The certified tetrahedra (of a YES, or the best found when undecided).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tets: Vec<[u32; 4]>,
}

impl TetraOutcome {
    /// The outcome in an input's numbering from `base`.
    ///
    /// ```
    /// use tetrakit::control::Control;
    /// use tetrakit::exact::{Domain, TetraOptions, tetrahedralize};
    /// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// let o = tetrahedralize(Domain::Points(&pts), TetraOptions::default(), &Control::new());
    /// assert_eq!(o.unwrap().shifted(1).tets, [[1, 2, 3, 4]]);
    /// ```
    pub fn shifted(mut self, base: u32) -> TetraOutcome {
        let shift = |t: &mut Vec<[u32; 4]>| t.iter_mut().for_each(|t| *t = t.map(|v| v + base));
        shift(&mut self.tets);
        self.alternative.as_mut().map(shift);
        self.witness = self.witness.map(|w| w.shifted(base));
        self
    }
}

/// Tetrahedralizes `domain` without Steiner points, exactly (see [`TetraOptions`]): the
/// answer is certified, and every NO carries its [`Witness`]. Stopped by `ctl`, the
/// outcome is `undecided`. An error is an input the solver cannot take (too large,
/// flat), or a bug (a failed certificate).
///
/// ```
/// use tetrakit::control::{Control, Verdict};
/// use tetrakit::exact::{Domain, TetraOptions, WitnessKind, tetrahedralize};
/// use tetrakit::polyhedra::generate::schonhardt;
/// let (s, ctl) = (schonhardt(), Control::new());
/// let no = tetrahedralize(Domain::Polyhedron(&s), TetraOptions::default(), &ctl).unwrap();
/// assert_eq!((no.verdict, no.witness.unwrap().kind), (Verdict::No, WitnessKind::NoCandidate));
/// let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64]).collect();
/// let opts = TetraOptions { minimal: true, unique: false };
/// assert_eq!(tetrahedralize(Domain::Points(&cube), opts, &ctl).unwrap().minimum, Some(5));
/// ```
pub fn tetrahedralize(
    domain: Domain,
    opts: TetraOptions,
    ctl: &Control,
) -> Result<TetraOutcome, ExactError> {
    let options = Options {
        unique: opts.unique,
        any: !opts.minimal,
    };
    let (outcome, stats) = solve(domain, Edges::default(), &options, ctl)?;
    let mut o = TetraOutcome {
        verdict: Verdict::Yes,
        vertices: domain.points().len(),
        domain: match domain {
            Domain::Points(_) => "convex hull",
            Domain::Polyhedron(_) => "polyhedron",
            Domain::Shell { .. } => "shell",
        },
        candidates: stats.candidates,
        sat_calls: stats.calls,
        short_pairs_budget: stats.short,
        minimum: None,
        unique: None,
        alternative: None,
        lower_bound: None,
        upper_bound: None,
        tetrahedra: None,
        certified: None,
        witness: None,
        tets: Vec::new(),
    };
    let tets = match outcome {
        Outcome::Optimal {
            tets,
            unique,
            alternative,
        } => {
            o.minimum = Some(tets.len());
            o.unique = options.unique.then_some(unique);
            o.alternative = alternative;
            tets
        }
        Outcome::Found { tets } => tets,
        Outcome::Infeasible => {
            o.verdict = Verdict::No;
            o.witness = Some(no_witness(domain, &stats, ctl)?);
            Vec::new()
        }
        Outcome::Undecided { best, lower } => {
            o.verdict = Verdict::Undecided;
            o.lower_bound = Some(lower);
            o.upper_bound = best.as_ref().map(Vec::len);
            best.unwrap_or_default()
        }
    };
    if !tets.is_empty() {
        (o.tetrahedra, o.certified) = (Some(tets.len()), Some(true));
    }
    o.tets = tets;
    Ok(o)
}
