//! The text of the chapter 3 outcomes: `mintetra` and `tetrahedralize`; and the files of
//! a DRAT refutation, shared by every command that writes one.

use crate::control::Verdict;
use crate::dualpath::HamiltonianOutcome;
use crate::exact::{TetraOutcome, WitnessKind};
use crate::polyhedra::{Minimality, MintetraOutcome};
use serde::Serialize;
use std::fmt::Write;

/// The files `--proof` wrote (the JSON's `proof`): the formula and its DRAT refutation,
/// or that the time limit stopped the proof.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum ProofFiles {
    /// The formula (DIMACS CNF) and its refutation.
    Written {
        /// The formula's path.
        formula: String,
        /// The refutation's path.
        drat: String,
        /// The formula's variables.
        variables: u32,
        /// The formula's clauses.
        clauses: usize,
    },
    /// Stopped by the time limit (the files are incomplete).
    Stopped(&'static str),
}

impl ProofFiles {
    /// The files, once the time limit stopped the proof.
    pub const STOPPED: ProofFiles =
        ProofFiles::Stopped("stopped by the time limit (the files are incomplete)");

    /// The line a person reads.
    pub fn line(&self) -> String {
        match self {
            ProofFiles::Written {
                formula,
                drat,
                variables,
                clauses,
            } => format!(
                "  proof: {drat} refutes {formula} ({variables} variables, {clauses} clauses)"
            ),
            ProofFiles::Stopped(why) => format!("  proof: {why}"),
        }
    }
}

/// The lines a person reads for a MINTETRA outcome, found in `seconds`.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::polyhedra::{MintetraOptions, generate, solve_mintetra};
/// let p = generate::bipyramid(5, 1);
/// let o = solve_mintetra(&p, MintetraOptions::default(), &Control::new()).unwrap();
/// let text = tetrakit::report::mintetra_text(&o, 0.0);
/// assert!(text.starts_with("MINTETRA: YES: an augmented BP-polyhedron with 1 level(s)"));
/// ```
pub fn mintetra_text(o: &MintetraOutcome, seconds: f64) -> String {
    let mut s = String::new();
    if o.verdict == Verdict::Yes {
        let _ = match o.levels {
            0 => writeln!(
                s,
                "MINTETRA: YES: a stacked polyhedron (no diagonal needed)"
            ),
            h => writeln!(
                s,
                "MINTETRA: YES: an augmented BP-polyhedron with {h} level(s)"
            ),
        };
        let polar: Vec<String> = o
            .polar_edges
            .iter()
            .map(|[a, b]| format!("[{a},{b}]"))
            .collect();
        let _ = writeln!(
            s,
            "  {} vertices, {} tetrahedra (lower bound n - 3 = {}), {} polar edge(s): [{}]",
            o.vertices,
            o.tetrahedra.unwrap_or(0),
            o.lower_bound,
            o.polar_edges.len(),
            polar.join(",")
        );
        let why = match o.minimality {
            Some(Minimality::Proven) => {
                "proven (Theorem 3.5 / Corollary 3.6: its proper BP-nets are disjoint)"
            }
            Some(Minimality::Confirmed) => "confirmed by the exact solver",
            Some(Minimality::Refuted) => {
                "REFUTED by the exact solver (please report this polyhedron)"
            }
            _ => "conjectured (§3.5; run with --confirm to check with the exact solver)",
        };
        let _ = writeln!(s, "  minimality: {why}");
        if let Some(c) = &o.confirm {
            let _ = writeln!(s, "  the exact solver did not confirm it: {c}");
        }
        let _ = writeln!(
            s,
            "  certified: orientation, face pairing, no overlap, boundary = the facets"
        );
    } else {
        let _ = writeln!(s, "MINTETRA: NO: not an augmented BP-polyhedron");
        let _ = writeln!(s, "  {}", o.reason.as_deref().unwrap_or(""));
        let _ = writeln!(
            s,
            "  left: {} vertices, {} facets (see --json for them)",
            o.remaining_vertices.unwrap_or(0),
            o.remaining_faces.as_ref().map_or(0, Vec::len)
        );
    }
    let _ = writeln!(s, "  time: {seconds:.3} s");
    s
}

/// The lines a person reads for a `tetrahedralize` outcome, found in `seconds`.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::{Domain, TetraOptions, tetrahedralize};
/// let s = tetrakit::polyhedra::generate::schonhardt();
/// let o = tetrahedralize(Domain::Polyhedron(&s), TetraOptions::default(), &Control::new());
/// let text = tetrakit::report::tetrahedralize_text(&o.unwrap(), 0.0);
/// assert!(text.starts_with("NO: polyhedron cannot be tetrahedralized without Steiner points"));
/// ```
pub fn tetrahedralize_text(o: &TetraOutcome, seconds: f64) -> String {
    let mut s = String::new();
    match o.verdict {
        Verdict::Yes => {
            let _ = match o.minimum {
                Some(m) => writeln!(
                    s,
                    "minimum: {m} tetrahedra for {} vertices ({}){}",
                    o.vertices,
                    o.domain,
                    match o.unique {
                        Some(Some(true)) => ", unique",
                        Some(Some(false)) => ", not unique (see --json for another)",
                        _ => "",
                    }
                ),
                None => writeln!(s, "tetrahedralizable: {} tetrahedra found", o.tets.len()),
            };
            let _ = writeln!(
                s,
                "  certified: orientation, face pairing, no overlap, boundary"
            );
        }
        Verdict::No | Verdict::AssumptionFails => {
            let _ = writeln!(
                s,
                "NO: {} cannot be tetrahedralized without Steiner points",
                o.domain
            );
            let _ = match &o.witness {
                // The formula's own witness names its core's vertices where it has one.
                Some(w) if w.kind != WitnessKind::Unsatisfiable || !w.vertices.is_empty() => {
                    writeln!(s, "  proof: {}", w.detail)
                }
                _ => writeln!(
                    s,
                    "  proof: the SAT formula is unsatisfiable ({} candidate tetrahedra)",
                    o.candidates
                ),
            };
        }
        Verdict::Undecided => {
            let lower = o.lower_bound.unwrap_or(0);
            let _ = match o.upper_bound {
                Some(upper) => writeln!(
                    s,
                    "undecided within the time limit: minimum between {lower} and {upper}"
                ),
                None => writeln!(
                    s,
                    "undecided within the time limit: minimum at least {lower} (no tetrahedralization found yet)"
                ),
            };
        }
    }
    let _ = writeln!(
        s,
        "  {} candidate tetrahedra, {} SAT calls, {seconds:.3} s",
        o.candidates, o.sat_calls
    );
    s
}

/// The lines a person reads for `tetrahedralize --hamiltonian`, found in `seconds`.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::dualpath::{PathOptions, hamiltonian};
/// let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64]).collect();
/// let o = hamiltonian(&cube, &PathOptions::default(), &Control::new()).unwrap();
/// let text = tetrakit::report::hamiltonian_text(&o, 0.0);
/// assert!(text.starts_with("YES: 6 tetrahedra in a Hamiltonian dual path"));
/// ```
pub fn hamiltonian_text(o: &HamiltonianOutcome, seconds: f64) -> String {
    let mut s = String::new();
    let ordinary = o
        .ordinary_tetrahedra
        .map_or("no apex is eligible".to_string(), |k| {
            format!("an ordinary cone has {k}")
        });
    let enumerated = match o.enumerated {
        Some(e) if e.complete => {
            format!(
                "; all {} tetrahedralizations enumerated",
                e.tetrahedralizations
            )
        }
        Some(e) => format!(
            "; the enumeration stopped after {} tetrahedralizations",
            e.tetrahedralizations
        ),
        None => String::new(),
    };
    let refuted = match o.cones_refuted {
        0 => String::new(),
        k => format!(" ({k} cones before it proven by SAT to have none)"),
    };
    let _ = match (o.verdict, o.apex, &o.witness) {
        (Verdict::Yes, Some(v), _) => writeln!(
            s,
            "YES: {} tetrahedra in a Hamiltonian dual path (each shares a triangle with the next), a cone from vertex {v}{refuted}; {ordinary}",
            o.tetrahedra
        ),
        (Verdict::Yes, None, _) => writeln!(
            s,
            "YES: {} tetrahedra in a Hamiltonian dual path (each shares a triangle with the next), found {} over every tetrahedralization ({} of {} cones refuted); {ordinary}",
            o.tetrahedra,
            match o.found_by {
                Some("sat") => "by SAT",
                _ => "by enumeration",
            },
            o.cones_refuted,
            o.apexes
        ),
        (Verdict::No, _, Some(w)) => writeln!(s, "NO: {}; {ordinary}", w.detail),
        _ => writeln!(
            s,
            "UNDECIDED: no Hamiltonian dual path found ({} of {} eligible apexes tried, {} of them refuted by SAT; {} search steps, {} cuts){enumerated}; {ordinary}",
            o.apexes_tried, o.apexes, o.cones_refuted, o.steps, o.cuts
        ),
    };
    if o.certified {
        let _ = writeln!(
            s,
            "  certified: the hull tetrahedralized, every point a vertex; the order checked"
        );
    }
    let _ = writeln!(s, "  {} vertices, {seconds:.3} s", o.vertices);
    s
}
