//! Certificates of a NO answer.

use serde::Serialize;
use std::fmt;

/// The kind of reason why a segment set is not the edge set of a tetrahedralization
/// (or, for planar input, of a triangulation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WitnessKind {
    /// Two segments whose relative interiors meet (cross at a point or overlap).
    CrossingSegments,
    /// A vertex lies in the relative interior of a segment.
    VertexOnSegment,
    /// Fewer than four affinely independent points (or three, in the plane).
    Degenerate,
    /// The segment graph is not connected (or a point is on no segment).
    Disconnected,
    /// Two consecutive points along an edge of the convex hull are not joined.
    MissingHullEdge,
    /// A vertex whose puncture-free link is not a (closed) triangulated surface.
    BadLink,
    /// A tetrahedron found from fewer than four of its vertices.
    UnconfirmedTetrahedron,
    /// The candidate tetrahedra failed the independent verifier (should not happen; the
    /// detail names the problem).
    Inconsistent,
}

impl WitnessKind {
    /// Every kind, in declaration order (the order of the JSON contract's list).
    pub const ALL: [WitnessKind; 8] = [
        WitnessKind::CrossingSegments,
        WitnessKind::VertexOnSegment,
        WitnessKind::Degenerate,
        WitnessKind::Disconnected,
        WitnessKind::MissingHullEdge,
        WitnessKind::BadLink,
        WitnessKind::UnconfirmedTetrahedron,
        WitnessKind::Inconsistent,
    ];
}

impl fmt::Display for WitnessKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&crate::numbering::json_name(self, "witness"))
    }
}

/// A checkable reason for a NO: the named vertices and segments and what is wrong.
/// Indices are 0-based point indices.
pub type Witness = crate::witness::Witness<WitnessKind>;

impl Witness {
    /// Segments `va` and `vb` overlap because `a` and `b` lie on one ray from `v`.
    pub(crate) fn overlap_on_ray(v: u32, a: u32, b: u32) -> Self {
        Witness::new(
            WitnessKind::CrossingSegments,
            vec![v, a, b],
            vec![[v, a], [v, b]],
            format!(
                "segments (#{v}, #{a}) and (#{v}, #{b}) overlap: #{a} and #{b} lie on one ray from #{v}"
            ),
        )
    }

    /// Rank used to pick the most telling witness among several: crossings first.
    pub(crate) fn rank(&self) -> u8 {
        match self.kind {
            WitnessKind::CrossingSegments | WitnessKind::VertexOnSegment => 0,
            _ => 1,
        }
    }
}
