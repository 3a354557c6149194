//! The partitioned check's side of one MPI rank (`python3 -m tetrakit.mpi`): the Rust
//! [`tetrakit::distributed::RankCheck`], its rounds run with the GIL released; Python's
//! mpi4py carries the messages (`alltoall`).

use crate::convert::run;
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

type Messages<'py> = Vec<Bound<'py, PyBytes>>;

fn to_py<'py>(py: Python<'py>, out: Vec<Vec<u8>>) -> Messages<'py> {
    out.iter().map(|b| PyBytes::new(py, b)).collect()
}

#[pymethods]
impl RankCheck {
    #[new]
    #[pyo3(signature = (index, rank, size, convex=false, manifold=false, reorient=false))]
    fn new(
        index: std::path::PathBuf,
        rank: usize,
        size: usize,
        convex: bool,
        manifold: bool,
        reorient: bool,
    ) -> Self {
        let opts = CheckOptions {
            convex,
            manifold,
            reorient,
        };
        RankCheck {
            inner: distributed::RankCheck::new(&index, rank, size, opts),
        }
    }

    /// The first messages, one per rank (this rank reads its pieces).
    fn start<'py>(&mut self, py: Python<'py>) -> PyResult<Messages<'py>> {
        let inner = &mut self.inner;
        let out = run(py, &Control::new(), || inner.start())?;
        Ok(to_py(py, out))
    }

    /// The next messages given `inbox` (`inbox[r]` from rank `r`); `None` when over.
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        inbox: Vec<Vec<u8>>,
    ) -> PyResult<Option<Messages<'py>>> {
        let inner = &mut self.inner;
        let out = run(py, &Control::new(), || inner.step(inbox))?;
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
