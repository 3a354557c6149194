//! The `reduce` capabilities as one call each, with outcomes the CLI prints through
//! [`crate::report`]: Lemma 2.6's flips ([`solve_hull_gap`]), a quasi-prism by staircases
//! or, without one, by the exact solver with every edge required
//! ([`QuasiPrism::solve`]), and the facts of a TRID → TETRAD construction
//! ([`Reduction::facts`], [`SphereReduction::facts`]).

use super::{HullGapError, QuasiPrism, QuasiPrismError, Reduction, SphereReduction, hull_gap};
use crate::control::{Control, Verdict};
use crate::exact::{self, Domain, Edges, Outcome};
use crate::mesh::Polyhedron;
use crate::numbering::Sentence;
use serde::Serialize;

/// The witness of a NO from [`solve_hull_gap`]: reflex edges remain and none flips.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct StuckWitness {
    /// Always `stuck`.
    pub kind: &'static str,
    /// The first reflex edge that no flip removes.
    pub edge: [u32; 2],
    /// A sentence for a person.
    pub detail: Sentence,
}

/// The outcome of [`solve_hull_gap`] (`reduce hull-gap --json` without the timing).
#[derive(Clone, Debug, Serialize)]
pub struct HullGapOutcome {
    /// `yes` (the gap filled, certified), `no` (stuck) or `undecided` (stopped).
    pub verdict: Verdict,
    /// Vertices of the polyhedron.
    pub vertices: usize,
    /// Its facets.
    pub faces: usize,
    /// A YES: the tetrahedra of the gap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tetrahedra: Option<usize>,
    /// A YES: always true.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub certified: Option<bool>,
    /// A NO: the reflex edge that no flip removes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<StuckWitness>,
    /// A YES: the certified tetrahedra filling `CH(Q) − Q`.
    #[serde(skip)]
    pub tets: Vec<[u32; 4]>,
}

impl HullGapOutcome {
    /// The outcome in an input's numbering from `base`.
    pub fn shifted(mut self, base: u32) -> Self {
        self.tets.iter_mut().flatten().for_each(|v| *v += base);
        if let Some(w) = &mut self.witness {
            w.edge = w.edge.map(|v| v + base);
            w.detail = std::mem::take(&mut w.detail).shifted(base);
        }
        self
    }
}

/// Lemma 2.6 on `q` as an outcome: the gap's certified tetrahedra, a NO naming the stuck
/// reflex edge, or `undecided` when `ctl` stops. An error is an input the lemma does not
/// cover (a vertex inside the hull) or a bug (a failed certificate).
///
/// ```
/// use tetrakit::control::{Control, Verdict};
/// use tetrakit::mesh::Polyhedron;
/// use tetrakit::reduce::solve_hull_gap;
/// let pts = vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [2.0, 2.0, 0.5], [1.0, 1.0, 3.0]];
/// let faces = vec![[0, 2, 3], [0, 3, 1], [0, 1, 4], [1, 3, 4], [3, 2, 4], [2, 0, 4]];
/// let o = solve_hull_gap(&Polyhedron::new(pts, faces).unwrap(), &Control::new()).unwrap();
/// assert_eq!((o.verdict, o.tetrahedra), (Verdict::Yes, Some(1)));
/// ```
pub fn solve_hull_gap(q: &Polyhedron, ctl: &Control) -> Result<HullGapOutcome, HullGapError> {
    let mut o = HullGapOutcome {
        verdict: Verdict::Yes,
        vertices: q.points.len(),
        faces: q.faces.len(),
        tetrahedra: None,
        certified: None,
        witness: None,
        tets: Vec::new(),
    };
    match hull_gap(q, ctl) {
        Ok(tets) => {
            (o.tetrahedra, o.certified) = (Some(tets.len()), Some(true));
            o.tets = tets;
        }
        Err(e @ HullGapError::Stuck(edge)) => {
            o.verdict = Verdict::No;
            o.witness = Some(StuckWitness {
                kind: "stuck",
                edge,
                detail: e.to_string().into(),
            });
        }
        Err(HullGapError::Stopped(_)) => o.verdict = Verdict::Undecided,
        Err(e) => return Err(e),
    }
    Ok(o)
}

/// How [`QuasiPrism::solve`] answered.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum QuasiPrismRoute {
    /// One vertex order (Algorithm QUASI-PRISM-TETRAHEDRALIZATION).
    Order,
    /// An orientation of the sides' diagonals with no cyclic prism (SAT).
    Orientation,
    /// No staircase: the exact solver on the boundary, every edge required.
    Exact,
}

/// The outcome of [`QuasiPrism::solve`] (`reduce quasi-prism --json` without the timing).
#[derive(Clone, Debug, Serialize)]
pub struct QuasiPrismOutcome {
    /// `yes` (certified), `no` (the exact solver's witness) or `undecided` (stopped).
    pub verdict: Verdict,
    /// Points: `S₁`'s, then their images.
    pub points: usize,
    /// Prisms: the triangles of `S₁`.
    pub prisms: usize,
    /// Whether the quasi-prism is regular (Definition before Lemma 2.7).
    pub regular: bool,
    /// How it was answered (none when stopped before the staircases).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub route: Option<QuasiPrismRoute>,
    /// Why no staircase exists, when the exact solver answered.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub staircase: Option<Sentence>,
    /// The exact solver's candidate tetrahedra, when it ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub candidates: Option<usize>,
    /// A YES: the tetrahedra.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tetrahedra: Option<usize>,
    /// A YES: always true.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub certified: Option<bool>,
    /// A NO: the exact solver's witness.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<exact::Witness>,
    /// A YES: the certified tetrahedra, every edge of the quasi-prism among their edges.
    #[serde(skip)]
    pub tets: Vec<[u32; 4]>,
}

impl QuasiPrismOutcome {
    /// The outcome in an input's numbering from `base`.
    pub fn shifted(mut self, base: u32) -> Self {
        self.tets.iter_mut().flatten().for_each(|v| *v += base);
        self.staircase = self.staircase.map(|s| s.shifted(base));
        self.witness = self.witness.map(|w| w.shifted(base));
        self
    }
}

impl QuasiPrism {
    /// Tetrahedralizes the quasi-prism keeping every one of its edges: by staircases
    /// ([`QuasiPrism::tetrahedralize`]) when it is regular and they exist, else by the exact
    /// solver on its boundary with [`QuasiPrism::edges`] required (whose answers are
    /// certified, a NO with its witness). Stopped by `ctl`: `undecided`.
    ///
    /// ```
    /// use tetrakit::control::{Control, Verdict};
    /// use tetrakit::reduce::QuasiPrism;
    /// let q = QuasiPrism::lens(8, 6, 3.0, 2);
    /// let o = q.solve(&Control::new()).unwrap();
    /// assert_eq!((o.verdict, o.tetrahedra), (Verdict::Yes, Some(3 * q.triangles.len())));
    /// ```
    pub fn solve(&self, ctl: &Control) -> Result<QuasiPrismOutcome, QuasiPrismError> {
        let mut o = QuasiPrismOutcome {
            verdict: Verdict::Yes,
            points: self.points.len(),
            prisms: self.triangles.len(),
            regular: true,
            route: None,
            staircase: None,
            candidates: None,
            tetrahedra: None,
            certified: None,
            witness: None,
            tets: Vec::new(),
        };
        match self.tetrahedralize(ctl) {
            Ok(s) => {
                o.route = Some(match s.by_order {
                    true => QuasiPrismRoute::Order,
                    false => QuasiPrismRoute::Orientation,
                });
                o.tets = s.tets;
            }
            Err(e @ (QuasiPrismError::Irregular { .. } | QuasiPrismError::NoStaircase)) => {
                o.regular = !matches!(e, QuasiPrismError::Irregular { .. });
                o.staircase = Some(e.to_string().into());
                o.route = Some(QuasiPrismRoute::Exact);
                self.by_exact(ctl, &mut o)?;
            }
            Err(QuasiPrismError::Stopped(_)) => o.verdict = Verdict::Undecided,
            Err(e) => return Err(e),
        }
        if !o.tets.is_empty() {
            (o.tetrahedra, o.certified) = (Some(o.tets.len()), Some(true));
        }
        Ok(o)
    }

    /// The exact solver on the boundary with every edge required (its answers are
    /// certified by [`exact::solve`], the required edges included).
    fn by_exact(&self, ctl: &Control, o: &mut QuasiPrismOutcome) -> Result<(), QuasiPrismError> {
        let poly = self.boundary()?;
        let required = self.edges();
        let edges = Edges {
            allowed: None,
            required: &required,
        };
        let opts = exact::Options {
            any: true,
            ..exact::Options::default()
        };
        let (outcome, stats) = exact::solve(Domain::Polyhedron(&poly), edges, &opts, ctl)
            .map_err(QuasiPrismError::Exact)?;
        o.candidates = Some(stats.candidates);
        match outcome {
            Outcome::Optimal { tets, .. } | Outcome::Found { tets } => o.tets = tets,
            Outcome::Infeasible => {
                o.verdict = Verdict::No;
                o.witness = Some(exact::Witness::of(&stats));
            }
            Outcome::Undecided { .. } => o.verdict = Verdict::Undecided,
        }
        Ok(())
    }
}

/// What a TRID → TETRAD construction built and checked (`reduce trid-to-tetrad --json`
/// without the file's fields).
#[derive(Clone, Debug, Serialize)]
pub struct ReductionFacts {
    /// `apexes` or `sphere`.
    pub construction: &'static str,
    /// The apex height.
    pub apex_height: f64,
    /// The sphere's radius (`sphere`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// The lower copy's twist in radians (`sphere`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub twist_radians: Option<f64>,
    /// The conditions checked exactly.
    pub checked: &'static [&'static str],
    /// Points of the TETRAD instance.
    pub points: usize,
    /// Segments of the TETRAD instance.
    pub segments: usize,
    /// How the planar points were placed, for a person.
    #[serde(skip)]
    pub how: String,
}

impl Reduction {
    /// What this construction built and checked.
    pub fn facts(&self) -> ReductionFacts {
        ReductionFacts {
            construction: "apexes",
            apex_height: self.height,
            radius: None,
            twist_radians: None,
            checked: &[
                "no three planar points collinear",
                "every orientation kept from both apexes",
                "every lifted point a vertex of the upper hull",
            ],
            points: self.points.len(),
            segments: self.segments.len(),
            how: format!("lifted to a paraboloid, apexes at height ±{}", self.height),
        }
    }
}

impl SphereReduction {
    /// What this construction built and checked.
    pub fn facts(&self) -> ReductionFacts {
        ReductionFacts {
            construction: "sphere",
            apex_height: self.height,
            radius: Some(self.radius),
            twist_radians: Some(self.twist),
            checked: &[
                "no three planar points collinear",
                "no four points coplanar",
                "every prism over a triangle of E a regular quasi-prism",
                "x* sees the upper points as the plane does",
                "every hull edge a segment (or a missing planar hull edge lifted)",
            ],
            points: self.points.len(),
            segments: self.segments.len(),
            how: format!(
                "on a sphere of radius {}, the lower copy twisted by {} rad, x* at height {}",
                self.radius, self.twist, self.height
            ),
        }
    }
}
