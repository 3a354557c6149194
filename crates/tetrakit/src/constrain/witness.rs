//! The reasons for a NO, each checkable by a person from the named vertices and
//! segments.

use crate::control::Control;
use crate::exact::Obstacle;
use crate::geom::{Hull3, Point3, SegmentMeet, point_in_segment_interior, segments_meet};
use serde::Serialize;
use std::collections::HashSet;

/// The kind of reason.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WitnessKind {
    /// Two constraint segments meet other than at a shared endpoint.
    CrossingConstraints,
    /// A point lies in the relative interior of a constraint segment.
    ConstraintThroughVertex,
    /// Two consecutive points along an edge of the convex hull are not joined by a
    /// segment (every tetrahedralization has that edge).
    MissingHullEdge,
    /// A point is in no candidate tetrahedron (one with its edges allowed, no other point
    /// in it, meeting no constraint improperly), so no tetrahedralization uses it.
    UncoveredVertex,
    /// A constraint is an edge of no candidate tetrahedron.
    UnusableConstraint,
    /// There is no candidate tetrahedron at all.
    NoCandidate,
    /// The constraints hold a niche whose view holds no point (Theorem 2.10); the
    /// formula is unsatisfiable as well.
    EmptyNicheView,
    /// The formula of the candidates is unsatisfiable (`prove_infeasible` writes a DRAT
    /// proof of it).
    Unsatisfiable,
}

impl WitnessKind {
    /// Every kind, in declaration order (the order of the JSON contract's list).
    pub const ALL: [WitnessKind; 8] = [
        WitnessKind::CrossingConstraints,
        WitnessKind::ConstraintThroughVertex,
        WitnessKind::MissingHullEdge,
        WitnessKind::UncoveredVertex,
        WitnessKind::UnusableConstraint,
        WitnessKind::NoCandidate,
        WitnessKind::EmptyNicheView,
        WitnessKind::Unsatisfiable,
    ];
}

impl std::fmt::Display for WitnessKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::numbering::json_name(self, "witness"))
    }
}

/// A checkable reason for a NO (0-based point indices).
pub type Witness = crate::witness::Witness<WitnessKind>;

impl Witness {
    pub(super) fn unsatisfiable(candidates: usize) -> Self {
        Witness::new(
            WitnessKind::Unsatisfiable,
            vec![],
            vec![],
            format!(
                "no set of the {candidates} candidate tetrahedra covers the hull face to face (the SAT formula is unsatisfiable; `prove` writes it with a DRAT refutation)"
            ),
        )
    }
}

/// A pair of consecutive points along an edge of the hull of `points` that `allowed`
/// does not join.
pub(super) fn missing_hull_edge(points: &[Point3], allowed: &[[u32; 2]]) -> Option<Witness> {
    let have: HashSet<[u32; 2]> = allowed.iter().map(|&[a, b]| [a.min(b), a.max(b)]).collect();
    let hull = Hull3::new(points);
    for chain in hull.polytope_edges(points) {
        for w in chain.windows(2) {
            let e = [w[0].min(w[1]), w[0].max(w[1])];
            if !have.contains(&e) {
                return Some(Witness::new(
                    WitnessKind::MissingHullEdge,
                    e.to_vec(),
                    vec![e],
                    format!(
                        "#{} and #{} are consecutive points on an edge of the convex hull, so every tetrahedralization joins them, but no segment does",
                        e[0], e[1]
                    ),
                ));
            }
        }
    }
    None
}

/// A constraint through a point, or two constraints that meet improperly.
pub(super) fn bad_constraints(
    points: &[Point3],
    segments: &[[u32; 2]],
    ctl: &Control,
) -> Option<Witness> {
    let p = |i: u32| &points[i as usize];
    for &s in segments {
        let inside =
            (0..points.len() as u32).find(|&v| point_in_segment_interior(p(v), p(s[0]), p(s[1])));
        if let Some(v) = inside {
            return Some(Witness::new(
                WitnessKind::ConstraintThroughVertex,
                vec![v],
                vec![s],
                format!("point #{v} lies inside constraint (#{}, #{})", s[0], s[1]),
            ));
        }
    }
    for (i, &s) in segments.iter().enumerate() {
        if i % 256 == 0 && ctl.is_stopped() {
            return None;
        }
        for &t in &segments[i + 1..] {
            if let Some(how) = segments_meet(p(s[0]), p(s[1]), p(t[0]), p(t[1])) {
                let how = match how {
                    SegmentMeet::Cross => "cross",
                    SegmentMeet::Overlap => "overlap",
                    SegmentMeet::Touch => "touch",
                };
                return Some(Witness::new(
                    WitnessKind::CrossingConstraints,
                    vec![],
                    vec![s, t],
                    format!(
                        "constraints (#{}, #{}) and (#{}, #{}) {how}: no tetrahedralization has both as edges",
                        s[0], s[1], t[0], t[1]
                    ),
                ));
            }
        }
    }
    None
}

/// The niche explanation of a NO the solver proved (Theorem 2.10's premise asks the
/// base to be a face; the refutation does not depend on it).
pub(super) fn empty_niche_view(n: &super::Niche, candidates: usize) -> Witness {
    let ([a, b, c], [a1, b1, c1]) = (n.top, n.base);
    Witness::new(
        WitnessKind::EmptyNicheView,
        vec![a, b, c, a1, b1, c1],
        n.edges().to_vec(),
        format!(
            "the constraints hold a niche, Schönhardt's polyhedron on top (#{a}, #{b}, #{c}) and base (#{a1}, #{b1}, #{c1}) without its top face, and no point sees the whole base (Theorem 2.10); the SAT formula of the {candidates} candidates is unsatisfiable too (--proof)"
        ),
    )
}

/// The witness of an obstacle the solver found before searching (`n` input points; the
/// apex of a planar cone is never named).
pub(super) fn from_obstacle(o: &Obstacle, n: usize) -> Witness {
    match *o {
        Obstacle::NoCandidate => Witness::new(
            WitnessKind::NoCandidate,
            vec![],
            vec![],
            "no tetrahedron on the points is a candidate (edges allowed, no other point in it, no constraint crossing it)",
        ),
        Obstacle::UncoveredVertex(v) => Witness::new(
            WitnessKind::UncoveredVertex,
            vec![v],
            vec![],
            format!(
                "point #{v} is in no candidate tetrahedron (edges allowed, no other point in it, no constraint crossing it), so no tetrahedralization uses it"
            ),
        ),
        Obstacle::UnusableSegment(s) => Witness::new(
            WitnessKind::UnusableConstraint,
            vec![],
            vec![s],
            format!(
                "constraint (#{}, #{}) is an edge of no candidate tetrahedron",
                s[0], s[1]
            ),
        ),
        Obstacle::UncoveredFacet(f) => Witness::new(
            WitnessKind::NoCandidate,
            f.iter().copied().filter(|&v| (v as usize) < n).collect(),
            vec![],
            format!(
                "facet (#{}, #{}, #{}) is a face of no candidate",
                f[0], f[1], f[2]
            ),
        ),
    }
}
