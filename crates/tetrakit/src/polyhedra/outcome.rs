//! The `mintetra` capability as one call: MINTETRA certified
//! ([`mintetra_certified`](super::mintetra_certified)), what its answer proves about
//! minimality (Theorem 3.5, Corollary 3.6, or the conjecture of §3.5), optionally
//! confirmed by the exact solver, and the witness of a NO, as one outcome that the CLI
//! and Python print through [`crate::report`].

use super::{Mintetra, Polyhedron, minimality, mintetra_certified};
use crate::control::{Control, Verdict};
use crate::exact::{Domain, TetraOptions, tetrahedralize};
use serde::Serialize;
use std::time::Duration;

/// What [`solve_mintetra`] is asked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MintetraOptions {
    /// Confirm a YES's minimality with the exact solver, given this long (a conjectured
    /// one becomes `confirmed` or `refuted`, and uniqueness is decided).
    pub confirm: Option<Duration>,
}

/// What a YES proves about minimality.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Minimality {
    /// Theorem 3.5 / Corollary 3.6: at most one level and disjoint proper BP-nets.
    Proven,
    /// Multi-level or overlapping nets: minimal by the conjecture of §3.5 only.
    Conjectured,
    /// The exact solver's minimum equals MINTETRA's count.
    Confirmed,
    /// The exact solver found fewer tetrahedra (MINTETRA is not minimal here).
    Refuted,
}

/// The witness of a NO: the polyhedron is not an augmented (multi-level) BP-polyhedron,
/// and the facets left after every trim show it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct MintetraWitness {
    /// Always `not_augmented_bp_polyhedron`.
    pub kind: &'static str,
    /// Why nothing more could be trimmed.
    pub detail: String,
    /// The facets of what is left.
    pub remaining_faces: Vec<[u32; 3]>,
}

/// The outcome of [`solve_mintetra`]. Serialized, the JSON of `tetrakit mintetra --json`
/// without the file's timing.
#[derive(Clone, Debug, Serialize)]
pub struct MintetraOutcome {
    /// `yes` (trimmed away: certified tetrahedra) or `no`.
    pub verdict: Verdict,
    /// Vertices of the polyhedron.
    pub vertices: usize,
    /// Its facets.
    pub faces: usize,
    /// `n − 3`, the fewest tetrahedra any polyhedron of `n` vertices needs.
    pub lower_bound: usize,
    /// The highest BP level (0: stacked).
    pub levels: u32,
    /// For every level from 1, its BP trims.
    pub trims_per_level: Vec<usize>,
    /// The polar edges added (the diagonals of the tetrahedralization).
    pub polar_edges: Vec<[u32; 2]>,
    /// Seconds trimming.
    pub mintetra_seconds: f64,
    /// A YES: seconds certifying.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verify_seconds: Option<f64>,
    /// A YES: always true (the tetrahedra passed the certificate).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub certified: Option<bool>,
    /// A YES: the number of tetrahedra.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tetrahedra: Option<usize>,
    /// A YES: what it proves about minimality.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub minimality: Option<Minimality>,
    /// A YES: `minimality` is `conjectured`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conjectured_minimal: Option<bool>,
    /// Confirmed: whether the minimum is attained only once.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unique: Option<bool>,
    /// Asked to confirm, and the solver did not decide: why (`time limit`, or the solver's
    /// refusal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub confirm: Option<String>,
    /// A NO: why nothing more could be trimmed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// A NO: the facets left.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub remaining_faces: Option<Vec<[u32; 3]>>,
    /// A NO: the vertices of the facets left.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub remaining_vertices: Option<usize>,
    /// A NO: its witness.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<MintetraWitness>,
    /// A YES: the certified tetrahedra.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tets: Vec<[u32; 4]>,
}

impl MintetraOutcome {
    /// The outcome in an input's numbering from `base`.
    pub fn shifted(mut self, base: u32) -> MintetraOutcome {
        let up = |v: &mut u32| *v += base;
        self.polar_edges.iter_mut().flatten().for_each(up);
        self.tets.iter_mut().flatten().for_each(up);
        if let Some(f) = &mut self.remaining_faces {
            f.iter_mut().flatten().for_each(up);
        }
        if let Some(w) = &mut self.witness {
            w.remaining_faces.iter_mut().flatten().for_each(up);
        }
        self
    }
}

/// MINTETRA on `p` (thesis §3.4), certified, with what its answer proves about
/// minimality (see [`MintetraOptions`]); `ctl` bounds the confirmation. An error is a
/// bug: tetrahedra that fail the certificate.
///
/// ```
/// use tetrakit::control::{Control, Verdict};
/// use tetrakit::polyhedra::{Minimality, MintetraOptions, generate, solve_mintetra};
/// let p = generate::bipyramid(6, 1);
/// let o = solve_mintetra(&p, MintetraOptions::default(), &Control::new()).unwrap();
/// assert_eq!((o.verdict, o.minimality), (Verdict::Yes, Some(Minimality::Proven)));
/// assert_eq!(o.tetrahedra, Some(o.lower_bound + 1));
/// ```
pub fn solve_mintetra(
    p: &Polyhedron,
    opts: MintetraOptions,
    ctl: &Control,
) -> Result<MintetraOutcome, crate::mesh::Problem> {
    let (m, secs) = mintetra_certified(p)?;
    let n = p.points.len();
    let mut o = MintetraOutcome {
        verdict: Verdict::from(m.yes),
        vertices: n,
        faces: p.faces.len(),
        lower_bound: n.saturating_sub(3),
        levels: m.levels,
        trims_per_level: m.trims_per_level.clone(),
        polar_edges: m.polar_edges.clone(),
        mintetra_seconds: secs.trimming,
        verify_seconds: None,
        certified: None,
        tetrahedra: None,
        minimality: None,
        conjectured_minimal: None,
        unique: None,
        confirm: None,
        reason: None,
        remaining_faces: None,
        remaining_vertices: None,
        witness: None,
        tets: Vec::new(),
    };
    if m.yes {
        yes(p, m, secs.certificate, opts, ctl, &mut o);
    } else {
        no(m, &mut o);
    }
    Ok(o)
}

fn yes(
    p: &Polyhedron,
    m: Mintetra,
    certificate: f64,
    opts: MintetraOptions,
    ctl: &Control,
    o: &mut MintetraOutcome,
) {
    let mut status = minimality(p, &m);
    if let Some(limit) = opts.confirm {
        let child = ctl.child().with_time_limit(limit);
        let ask = TetraOptions {
            minimal: true,
            unique: true,
        };
        match tetrahedralize(Domain::Polyhedron(p), ask, &child) {
            Ok(t) if t.verdict == Verdict::Yes => {
                if t.minimum == Some(m.tets.len()) {
                    status = Minimality::Confirmed;
                    o.unique = t.unique.flatten();
                } else {
                    status = Minimality::Refuted;
                }
            }
            Ok(t) if t.verdict == Verdict::Undecided => o.confirm = Some("time limit".into()),
            Ok(_) => o.confirm = Some("the solver found no tetrahedralization".into()),
            Err(e) => o.confirm = Some(e.to_string()),
        }
    }
    o.verify_seconds = Some(certificate);
    o.certified = Some(true);
    o.tetrahedra = Some(m.tets.len());
    o.minimality = Some(status);
    o.conjectured_minimal = Some(status == Minimality::Conjectured);
    o.tets = m.tets;
}

fn no(m: Mintetra, o: &mut MintetraOutcome) {
    let mut left: Vec<u32> = m.remaining.iter().flatten().copied().collect();
    left.sort_unstable();
    left.dedup();
    o.remaining_vertices = Some(left.len());
    o.witness = Some(MintetraWitness {
        kind: "not_augmented_bp_polyhedron",
        detail: m.reason.clone(),
        remaining_faces: m.remaining.clone(),
    });
    o.reason = Some(m.reason);
    o.remaining_faces = Some(m.remaining);
}
