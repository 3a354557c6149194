//! numpy arrays in and out, errors as Python exceptions, and work run with the GIL
//! released.

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use std::path::Path;
use std::sync::mpsc;
use std::time::Duration;
use tetrakit::control::Control;
use tetrakit::geom::Point3;
use tetrakit::io::{Arrays, Input, InputError, from_arrays};

/// What every binding returns: the JSON text and the arrays.
pub type Json = String;

/// A `ValueError` with the reader's message (the arrays have no file or line).
pub fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

fn input_error(e: InputError) -> PyErr {
    PyValueError::new_err(e.message)
}

/// The rows of a C-contiguous `(n, k)` array as `[T; K]`, or a `ValueError` naming `name`
/// and the shape.
pub fn rows<T: numpy::Element + Copy + Default, const K: usize>(
    a: &PyReadonlyArray2<'_, T>,
    name: &str,
) -> PyResult<Vec<[T; K]>> {
    let shape = a.shape();
    if shape[1] != K && shape[0] != 0 {
        return Err(value_error(format!(
            "{name} has shape ({}, {}): expected ({}, {K})",
            shape[0], shape[1], shape[0]
        )));
    }
    let flat = a.as_slice().map_err(value_error)?;
    Ok(flat
        .chunks_exact(K.max(1))
        .map(|c| std::array::from_fn(|i| c[i]))
        .collect())
}

/// Points of shape `(n, 3)`, or `(n, 2)` (then `z = 0` and the dimension is 2).
pub fn points(a: &PyReadonlyArray2<'_, f64>, name: &str) -> PyResult<(Vec<Point3>, usize)> {
    let (n, d) = (a.shape()[0], a.shape()[1]);
    let flat = a.as_slice().map_err(value_error)?;
    let pts = match d {
        3 => flat.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect(),
        2 => flat.chunks_exact(2).map(|c| [c[0], c[1], 0.0]).collect(),
        _ => {
            return Err(value_error(format!(
                "{name} has shape ({n}, {d}): expected (n, 3) or (n, 2)"
            )));
        }
    };
    Ok((pts, d))
}

/// Index rows of each kind, checked with the points as a file's would be.
#[derive(Default)]
pub struct Rows {
    pub segments: Vec<[i64; 2]>,
    pub faces: Vec<[i64; 3]>,
    pub tets: Vec<[i64; 4]>,
}

/// The [`Input`] of `points` and `rows`, checked by [`from_arrays`] (as a mesh to check
/// when `mesh`: see [`tetrakit::io::ReadOptions::mesh`]).
pub fn input(points: Vec<Point3>, dim: usize, r: &Rows, mesh: bool) -> PyResult<Input> {
    let arrays = Arrays {
        points,
        dim,
        segments: &r.segments,
        faces: &r.faces,
        tets: &r.tets,
        mesh,
    };
    from_arrays(Path::new("arrays"), arrays).map_err(input_error)
}

/// The [`Input`] of `points` and their `segments`, checked as [`input`] checks them.
pub fn with_segments(
    points: &PyReadonlyArray2<'_, f64>,
    segments: &PyReadonlyArray2<'_, i64>,
) -> PyResult<Input> {
    let (pts, dim) = self::points(points, "points")?;
    let rows = Rows {
        segments: self::rows(segments, "segments")?,
        ..Default::default()
    };
    input(pts, dim, &rows, false)
}

/// `(m, K)` int64 array of index rows.
pub fn array<'py, const K: usize>(py: Python<'py>, rows: &[[u32; K]]) -> Bound<'py, PyArray2<i64>> {
    let flat: Vec<i64> = rows.iter().flatten().map(|&v| i64::from(v)).collect();
    PyArray1::from_vec(py, flat)
        .reshape([rows.len(), K])
        .expect("the length is rows × K")
}

/// `(n, 3)` (or `(n, 2)`) float64 array of points.
pub fn point_array<'py, const D: usize>(
    py: Python<'py>,
    pts: &[[f64; D]],
) -> Bound<'py, PyArray2<f64>> {
    let flat: Vec<f64> = pts.iter().flatten().copied().collect();
    PyArray1::from_vec(py, flat)
        .reshape([pts.len(), D])
        .expect("the length is points × D")
}

/// A control with the optional time limit in seconds (a `ValueError` when negative or
/// not finite).
pub fn control(time_limit: Option<f64>) -> PyResult<Control> {
    let ctl = Control::new();
    Ok(match seconds(time_limit, "time_limit")? {
        Some(limit) => ctl.with_time_limit(limit),
        None => ctl,
    })
}

/// The optional seconds of the argument `name` (a `ValueError` when negative or not
/// finite).
pub fn seconds(s: Option<f64>, name: &str) -> PyResult<Option<Duration>> {
    match s {
        None => Ok(None),
        Some(s) if s.is_finite() && s >= 0.0 => Ok(Some(Duration::from_secs_f64(s))),
        Some(s) => Err(value_error(format!(
            "{name} = {s}: expected a finite number of seconds, at least 0"
        ))),
    }
}

/// Runs `work` on a thread of its own with the GIL released, checking for Python signals
/// every 50 ms: on Ctrl-C, `ctl` is stopped (every long loop of the library polls it),
/// the work is awaited, and `KeyboardInterrupt` is raised.
pub fn run<T: Send>(py: Python<'_>, ctl: &Control, work: impl FnOnce() -> T + Send) -> PyResult<T> {
    std::thread::scope(|s| {
        let (tx, rx) = mpsc::channel();
        let worker = s.spawn(move || {
            let _ = tx.send(work());
        });
        let mut rx = rx;
        loop {
            // The receiver goes into the GIL-free closure and back (it is Send, not Sync).
            let got;
            (got, rx) = py.detach(move || (rx.recv_timeout(Duration::from_millis(50)), rx));
            match got {
                Ok(v) => return Ok(v),
                Err(mpsc::RecvTimeoutError::Timeout) => {
                    if let Err(e) = py.check_signals() {
                        ctl.stop();
                        let _ = worker.join();
                        return Err(e);
                    }
                }
                Err(mpsc::RecvTimeoutError::Disconnected) => {
                    return Err(PyRuntimeError::new_err(
                        "tetrakit stopped with an internal error (please report it)",
                    ));
                }
            }
        }
    })
}
