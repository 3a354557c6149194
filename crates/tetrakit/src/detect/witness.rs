//! Certificates of a NO answer.

use crate::numbering::map_text;
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
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Witness {
    /// What kind of reason.
    pub kind: WitnessKind,
    /// The vertices it names.
    pub vertices: Vec<u32>,
    /// The segments it names.
    pub segments: Vec<[u32; 2]>,
    /// A sentence for a person.
    pub detail: String,
}

impl Witness {
    /// A witness of `kind`.
    pub fn new(
        kind: WitnessKind,
        vertices: Vec<u32>,
        segments: Vec<[u32; 2]>,
        detail: String,
    ) -> Self {
        Witness {
            kind,
            vertices,
            segments,
            detail,
        }
    }

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

    /// Shifts every vertex number by `base` (0 or 1), in the fields and in the text, where
    /// vertex numbers are written `#12`, so the witness names vertices as the input file did.
    ///
    /// ```
    /// use tetrakit::detect::{Witness, WitnessKind};
    /// let w = Witness::new(WitnessKind::VertexOnSegment, vec![4], vec![[1, 2]], "vertex #4 lies inside segment (#1, #2)".into());
    /// assert_eq!(w.renumbered(1).detail, "vertex #5 lies inside segment (#2, #3)");
    /// ```
    pub fn renumbered(self, base: u32) -> Self {
        self.mapped(|v| v + base)
    }

    /// Renames every vertex `v` to `f(v)`, in the fields and in the text.
    pub fn mapped(mut self, f: impl Fn(u32) -> u32) -> Self {
        self.vertices.iter_mut().for_each(|v| *v = f(*v));
        self.segments.iter_mut().flatten().for_each(|v| *v = f(*v));
        self.detail = map_text(&self.detail, f);
        self
    }

    /// Rank used to pick the most telling witness among several: crossings first.
    pub(crate) fn rank(&self) -> u8 {
        match self.kind {
            WitnessKind::CrossingSegments | WitnessKind::VertexOnSegment => 0,
            _ => 1,
        }
    }
}
