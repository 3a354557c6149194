//! The text of the `reduce` outcomes (thesis ch. 2 §2.5).

use crate::control::Verdict;
use crate::reduce::{HullGapOutcome, QuasiPrismOutcome, QuasiPrismRoute, ReductionFacts};

/// The line a person reads for Lemma 2.6's flips.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::mesh::Polyhedron;
/// let pts = vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [2.0, 2.0, 0.5], [1.0, 1.0, 3.0]];
/// let faces = vec![[0, 2, 3], [0, 3, 1], [0, 1, 4], [1, 3, 4], [3, 2, 4], [2, 0, 4]];
/// let q = Polyhedron::new(pts, faces).unwrap();
/// let o = tetrakit::reduce::solve_hull_gap(&q, &Control::new()).unwrap();
/// assert!(tetrakit::report::hull_gap_text(&o).starts_with("YES: 1 tetrahedra fill the gap"));
/// ```
pub fn hull_gap_text(o: &HullGapOutcome) -> String {
    match o.verdict {
        Verdict::Yes => format!(
            "YES: {} tetrahedra fill the gap between the polyhedron ({} vertices) and its convex hull, by reflex-edge flips (Lemma 2.6); certified",
            o.tetrahedra.unwrap_or(0),
            o.vertices
        ),
        Verdict::No | Verdict::AssumptionFails => format!(
            "NO: {}",
            o.witness
                .as_ref()
                .map_or(String::new(), |w| w.detail.to_string())
        ),
        Verdict::Undecided => "UNDECIDED: the time limit stopped the flips".to_string(),
    }
}

/// The line a person reads for a quasi-prism.
pub fn quasi_prism_text(o: &QuasiPrismOutcome) -> String {
    let why = o
        .staircase
        .as_ref()
        .map_or(String::new(), |s| s.to_string());
    let prisms = o.prisms;
    let t = o.tetrahedra.unwrap_or(0);
    match (o.verdict, o.route) {
        (Verdict::Yes, Some(QuasiPrismRoute::Order)) => format!(
            "YES: {t} tetrahedra, three per prism ({prisms} prism(s)), by one vertex order (Algorithm QUASI-PRISM-TETRAHEDRALIZATION); certified"
        ),
        (Verdict::Yes, Some(QuasiPrismRoute::Orientation)) => format!(
            "YES: {t} tetrahedra, three per prism ({prisms} prism(s)), by an orientation of the sides' diagonals with no cyclic prism (SAT); certified"
        ),
        (Verdict::Yes, _) => format!(
            "YES: {t} tetrahedra from the exact solver ({prisms} prism(s); no staircase: {why}); certified"
        ),
        (Verdict::No | Verdict::AssumptionFails, _) => format!(
            "NO: no tetrahedralization keeps every edge of the quasi-prism: {} ({why})",
            o.witness
                .as_ref()
                .map_or(String::new(), |w| w.detail.to_string())
        ),
        (Verdict::Undecided, _) => format!("UNDECIDED: the time limit stopped the work {why}"),
    }
}

/// The line a person reads once a TRID → TETRAD instance of `planar_points` points is
/// written to `output`.
pub fn reduction_text(f: &ReductionFacts, planar_points: usize, output: &str) -> String {
    format!(
        "wrote {output}: {} points, {} segments (the {planar_points} planar points {}); conditions checked exactly",
        f.points, f.segments, f.how
    )
}
