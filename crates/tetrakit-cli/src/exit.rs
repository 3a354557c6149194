//! What a command ends with, and the one place it becomes an exit code.

use std::fmt;
use std::path::Path;

/// What a command found: the library's verdict (exit 0, 1 or 3).
pub use tetrakit::control::Verdict;

/// The exit code of the CLI contract for `v`.
pub fn code(v: Verdict) -> u8 {
    match v {
        Verdict::Yes => 0,
        Verdict::No | Verdict::AssumptionFails => 1,
        Verdict::Undecided => 3,
    }
}

/// Why a command could not answer: bad input or usage, or a file that could not be
/// written (exit 2, one line on stderr).
#[derive(Debug)]
pub struct CliError(String);

impl CliError {
    /// An error with the line to print.
    pub fn new(message: impl fmt::Display) -> Self {
        CliError(message.to_string())
    }

    /// An error about `path`: `"<path>: <message>"`.
    pub fn at(path: &Path, message: impl fmt::Display) -> Self {
        CliError(format!("{}: {message}", path.display()))
    }

    /// A library result that failed its certificate: a bug, never a user's fault.
    pub fn internal(message: impl fmt::Display) -> Self {
        CliError(format!("internal error, please report: {message}"))
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl From<tetrakit::io::InputError> for CliError {
    fn from(e: tetrakit::io::InputError) -> Self {
        CliError::new(e)
    }
}

/// A generator's refusal, its parameter named as the command-line flag (`--n-outer 3:
/// expected at least 4`).
impl From<tetrakit::params::GenerateError> for CliError {
    fn from(e: tetrakit::params::GenerateError) -> Self {
        use tetrakit::params::GenerateError;
        match e {
            GenerateError::OutOfRange {
                parameter,
                value,
                expected,
            } => {
                let flag = match parameter.contains(' ') {
                    true => parameter.to_string(),
                    false => format!("--{}", parameter.replace('_', "-")),
                };
                CliError(format!("{flag} {value}: expected {expected}"))
            }
            GenerateError::Unbuildable(why) => CliError::new(why),
        }
    }
}

/// What every command returns.
pub type CmdResult = Result<Verdict, CliError>;

/// Adds the path to an I/O error from writing `path`.
pub trait WriteContext<T> {
    /// `"<path>: <error>"` on failure.
    fn written(self, path: &Path) -> Result<T, CliError>;
}

impl<T> WriteContext<T> for std::io::Result<T> {
    fn written(self, path: &Path) -> Result<T, CliError> {
        self.map_err(|e| CliError::at(path, e))
    }
}
