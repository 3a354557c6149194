//! The one error for "this cannot happen": a check that the construction guarantees
//! failed. It is a bug in tetrakit, never the input's fault, and it is reported (with
//! what failed and where) rather than turned into an answer.
//!
//! Every capability's error type has one variant holding a [`Bug`]; a result that fails
//! the independent verifier is not a `Bug` but the verifier's own typed problem
//! (`mesh::Problem`), in a variant named `Uncertified`.
//!
//! ```
//! use tetrakit::bug::Bug;
//! let b = Bug::at("consecutive tetrahedra of the path share a triangle", [3, 4]);
//! assert_eq!(
//!     b.to_string(),
//!     "internal error, please report the input: consecutive tetrahedra of the path share a triangle (failed at 3, 4)"
//! );
//! ```

use std::fmt;

/// A check the construction guarantees failed (see the module documentation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Bug {
    /// What should have held, as a sentence.
    pub check: &'static str,
    /// Where it failed: vertices, cells or edges as `check` names them, 0-based in the
    /// library's numbering (empty when there is nothing to name).
    pub at: Vec<u32>,
}

impl Bug {
    /// `check` failed, with nothing to name.
    pub fn new(check: &'static str) -> Self {
        Bug {
            check,
            at: Vec::new(),
        }
    }

    /// `check` failed at `at`.
    pub fn at(check: &'static str, at: impl IntoIterator<Item = u32>) -> Self {
        Bug {
            check,
            at: at.into_iter().collect(),
        }
    }
}

impl fmt::Display for Bug {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "internal error, please report the input: {}", self.check)?;
        if let Some((first, rest)) = self.at.split_first() {
            write!(f, " (failed at {first}")?;
            for x in rest {
                write!(f, ", {x}")?;
            }
            f.write_str(")")?;
        }
        Ok(())
    }
}

impl std::error::Error for Bug {}
