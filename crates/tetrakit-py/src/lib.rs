//! Python bindings of tetrakit: the module `tetrakit._core`, which the Python package
//! `tetrakit` (`python/tetrakit/__init__.py`) wraps in documented functions returning
//! dataclasses.
//!
//! Every function here takes numpy arrays (f64 points, int64 index rows, 0-based),
//! checks them as the file readers check files ([`tetrakit::io::from_arrays`]; a problem
//! is a `ValueError` with the reader's message), does its work with the GIL released
//! and Ctrl-C honoured (`convert::run`), and returns `(json, arrays...)`: the CLI's
//! JSON fields as text, and the cells as numpy arrays.
#![forbid(unsafe_code)]

mod constrain;
mod convert;
mod flips;
mod mesh;
mod mpi;
mod planar;
mod poly;

use pyo3::prelude::*;

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(mesh::check, m)?)?;
    m.add_function(wrap_pyfunction!(mesh::read, m)?)?;
    m.add_function(wrap_pyfunction!(mesh::detect, m)?)?;
    m.add_function(wrap_pyfunction!(constrain::decide, m)?)?;
    m.add_function(wrap_pyfunction!(poly::mintetra, m)?)?;
    m.add_function(wrap_pyfunction!(poly::tetrahedralize, m)?)?;
    m.add_function(wrap_pyfunction!(poly::shell, m)?)?;
    m.add_function(wrap_pyfunction!(flips::flips, m)?)?;
    m.add_function(wrap_pyfunction!(flips::count_tetrahedralizations, m)?)?;
    m.add_function(wrap_pyfunction!(flips::hamiltonian, m)?)?;
    m.add_function(wrap_pyfunction!(planar::skeleton, m)?)?;
    m.add_function(wrap_pyfunction!(planar::mwt, m)?)?;
    m.add_function(wrap_pyfunction!(planar::keil, m)?)?;
    m.add_class::<mpi::RankCheck>()?;
    Ok(())
}
