//! The one shape of a checkable NO: what kind of reason, the vertices and segments it
//! names, and a sentence for a person that names them as `#12`.
//!
//! Each capability has its own list of kinds (`detect::WitnessKind`,
//! `constrain::WitnessKind`, `exact::WitnessKind`) and its witness is a [`Witness`] of
//! that kind; a mesh's problems (`mesh::Problem`) name cells as well and stay their own
//! type. Indices are 0-based point indices; [`Witness::shifted`] gives a file's numbering,
//! in the lists and in the sentence.
//!
//! ```
//! use tetrakit::detect::{Witness, WitnessKind};
//! let w = Witness::new(
//!     WitnessKind::VertexOnSegment,
//!     vec![4],
//!     vec![[1, 2]],
//!     "vertex #4 lies inside segment (#1, #2)",
//! );
//! let w = w.shifted(1);
//! assert_eq!((w.vertices, w.segments), (vec![5], vec![[2, 3]]));
//! assert_eq!(w.detail.to_string(), "vertex #5 lies inside segment (#2, #3)");
//! ```

use crate::numbering::Sentence;
use serde::Serialize;

/// A checkable reason for a NO, of a capability's kind `K` (see the module documentation).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Witness<K> {
    /// What kind of reason.
    pub kind: K,
    /// The vertices it names.
    pub vertices: Vec<u32>,
    /// The segments it names.
    pub segments: Vec<[u32; 2]>,
    /// A sentence for a person, naming vertices as `#12`.
    pub detail: Sentence,
}

impl<K> Witness<K> {
    /// A witness of `kind`.
    pub fn new(
        kind: K,
        vertices: Vec<u32>,
        segments: Vec<[u32; 2]>,
        detail: impl Into<Sentence>,
    ) -> Self {
        Witness {
            kind,
            vertices,
            segments,
            detail: detail.into(),
        }
    }

    /// Renames every vertex `v` to `f(v)`, in the lists and in the sentence.
    pub fn mapped(mut self, f: impl Fn(u32) -> u32) -> Self {
        self.vertices.iter_mut().for_each(|v| *v = f(*v));
        self.segments.iter_mut().flatten().for_each(|v| *v = f(*v));
        self.detail = self.detail.map(f, |t| t);
        self
    }

    /// The witness in an input's numbering from `base` (0 or 1): vertices and any cell
    /// named `T12` in the sentence shifted.
    pub fn shifted(&self, base: u32) -> Self
    where
        K: Clone,
    {
        let mut w = self.clone();
        w.vertices.iter_mut().for_each(|v| *v += base);
        w.segments.iter_mut().flatten().for_each(|v| *v += base);
        w.detail = w.detail.shifted(base);
        w
    }
}
