//! The one error of the instance generators (`polyhedra::hard`, `polyhedra::generate`,
//! `shell::generate`, `constrain::generate`): a parameter out of range, named with its
//! value and the range it must be in, or parameters in range for which the shape cannot
//! be built.
//!
//! ```
//! use tetrakit::params::GenerateError;
//! let e = tetrakit::polyhedra::hard::chazelle(0).unwrap_err();
//! assert_eq!(e, GenerateError::range("grooves", 0, "between 1 and 1000"));
//! assert_eq!(e.to_string(), "grooves = 0: expected between 1 and 1000");
//! ```

use std::fmt;

/// Why a generator built nothing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum GenerateError {
    /// A parameter outside the range the generator takes.
    OutOfRange {
        /// The parameter (as the generator names it).
        parameter: &'static str,
        /// Its value.
        value: String,
        /// The range it must be in.
        expected: String,
    },
    /// The parameters are in range, but the shape they ask for cannot be built (a
    /// sentence saying why).
    Unbuildable(&'static str),
}

impl GenerateError {
    /// `parameter` = `value` is not in the range `expected`.
    pub fn range(
        parameter: &'static str,
        value: impl fmt::Display,
        expected: impl Into<String>,
    ) -> Self {
        GenerateError::OutOfRange {
            parameter,
            value: value.to_string(),
            expected: expected.into(),
        }
    }
}

impl fmt::Display for GenerateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GenerateError::OutOfRange {
                parameter,
                value,
                expected,
            } => write!(f, "{parameter} = {value}: expected {expected}"),
            GenerateError::Unbuildable(why) => f.write_str(why),
        }
    }
}

impl std::error::Error for GenerateError {}
