//! The partitioned check's side of one MPI rank (`python3 -m tetrakit.mpi`): the Rust
//! [`tetrakit::distributed::RankCheck`], its rounds run with the GIL released; Python's
//! mpi4py carries the messages (`alltoall`).

use crate::convert::run;
use numpy::PyReadonlyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use tetrakit::control::Control;
use tetrakit::distributed;
use tetrakit::mesh::CheckOptions;

/// One rank of a partitioned check of a `.pvtu`: `start()`, then `step(inbox)` with the
/// messages every rank sent until it returns `None`, then `printed(json, seconds)`.
#[pyclass(module = "tetrakit._core")]
pub struct RankCheck {
    inner: distributed::RankCheck,
}

/// Messages as one buffer, rank after rank, and each one's length (for `Alltoallv`).
type Messages<'py> = (Bound<'py, PyBytes>, Vec<usize>);

fn to_py<'py>(py: Python<'py>, out: Vec<Vec<u8>>) -> Messages<'py> {
    let counts = out.iter().map(Vec::len).collect();
    (PyBytes::new(py, &out.concat()), counts)
}

#[pymethods]
impl RankCheck {
    #[new]
    #[pyo3(signature = (index, rank, size, convex=false, manifold=false, reorient=false, tets_only=false, output=None))]
    #[allow(clippy::too_many_arguments)] // Python's keyword arguments
    fn new(
        index: std::path::PathBuf,
        rank: usize,
        size: usize,
        convex: bool,
        manifold: bool,
        reorient: bool,
        tets_only: bool,
        output: Option<std::path::PathBuf>,
    ) -> Self {
        let opts = CheckOptions {
            convex,
            manifold,
            reorient,
        };
        let inner = distributed::RankCheck::new(&index, rank, size, opts, tets_only);
        RankCheck {
            inner: match output {
                Some(out) => inner.with_output(&out),
                None => inner,
            },
        }
    }

    /// The first messages, to every rank (this rank reads its pieces): `(buffer, counts)`.
    fn start<'py>(&mut self, py: Python<'py>) -> PyResult<Messages<'py>> {
        let inner = &mut self.inner;
        let out = run(py, &Control::new(), || inner.start())?;
        Ok(to_py(py, out))
    }

    /// The next messages given what every rank sent this one, `buffer` (a uint8 array)
    /// holding rank 0's message, then rank 1's, … (`counts` long each); `None` when over.
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        buffer: PyReadonlyArray1<'py, u8>,
        counts: Vec<usize>,
    ) -> PyResult<Option<Messages<'py>>> {
        let bytes = buffer.as_slice()?;
        if counts.iter().sum::<usize>() != bytes.len() {
            return Err(PyValueError::new_err(
                "the counts do not add up to the buffer",
            ));
        }
        let mut inbox = Vec::with_capacity(counts.len());
        let mut at = 0;
        for c in counts {
            inbox.push(&bytes[at..at + c]);
            at += c;
        }
        let inner = &mut self.inner;
        let out = run(py, &Control::new(), || inner.step(&inbox))?;
        Ok(out.map(|out| to_py(py, out)))
    }

    /// Bytes this rank sent so far.
    #[getter]
    fn bytes_sent(&self) -> usize {
        self.inner.bytes_sent
    }

    /// On rank 0 when over: `(exit code, text)`, what `tetrakit check` prints (JSON or
    /// text) and its exit code (0 valid, 1 not, 2 bad input: the text is the error).
    /// Other ranks: `(code, "")` with the failure's code, or 0.
    fn printed(&self, json: bool, seconds: f64, parsed: f64) -> (i32, String) {
        if let Some(f) = self.inner.failure() {
            return (2, f.to_string());
        }
        match self.inner.outcome() {
            None => (0, String::new()),
            Some(o) => {
                let code = if o.is_valid() { 0 } else { 1 };
                let input = self.inner.input();
                let text =
                    tetrakit::report::check_printed(o.clone(), &input, seconds, parsed, json);
                (code, text)
            }
        }
    }
}
