//! `mintetra`, `tetrahedralize` and `shell` (thesis ch. 3 and 4).

use crate::convert::{self, Json, Rows, array, point_array, value_error};
use numpy::{PyArray2, PyReadonlyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use tetrakit::control::Control;
use tetrakit::exact::{self, Domain, TetraOptions};
use tetrakit::mesh::Polyhedron;
use tetrakit::polyhedra::{self, MintetraOptions};
use tetrakit::report;
use tetrakit::shell::{Method, Shell, ShellOptions};

type Cells<'py> = (Json, Bound<'py, PyArray2<i64>>);

/// A simple polyhedron from points and triangles, or the reader's error.
fn polyhedron(
    points: &PyReadonlyArray2<'_, f64>,
    faces: &PyReadonlyArray2<'_, i64>,
) -> PyResult<Polyhedron> {
    let (pts, dim) = convert::points(points, "points")?;
    let rows = Rows {
        faces: convert::rows(faces, "faces")?,
        ..Default::default()
    };
    let input = convert::input(pts, dim, &rows, false)?;
    Polyhedron::new(input.points, input.faces)
        .map_err(|e| value_error(format!("not a simple polyhedron: {}", e.describe(0))))
}

fn internal(what: impl std::fmt::Display) -> PyErr {
    PyRuntimeError::new_err(format!("{what} (a bug: please report it)"))
}

/// `mintetra(points, faces, confirm)`: MINTETRA's outcome as JSON and its certified
/// tetrahedra; `confirm` gives the exact solver that many seconds to confirm minimality.
#[pyfunction]
#[pyo3(signature = (points, faces, confirm=None))]
pub fn mintetra<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    faces: PyReadonlyArray2<'py, i64>,
    confirm: Option<f64>,
) -> PyResult<Cells<'py>> {
    let poly = polyhedron(&points, &faces)?;
    let opts = MintetraOptions {
        confirm: convert::seconds(confirm, "confirm")?,
    };
    let ctl = Control::new();
    let mut o = convert::run(py, &ctl, || polyhedra::solve_mintetra(&poly, opts, &ctl))?
        .map_err(|e| internal(format!("MINTETRA's tetrahedra fail the certificate: {e}")))?;
    let tets = std::mem::take(&mut o.tets);
    Ok((report::json(&o, []).to_string(), array(py, &tets)))
}

/// `tetrahedralize(points, faces, minimal, unique, time_limit)`: the exact solver's
/// outcome (`yes`, `no` with a witness, or `undecided` with bounds) and its certified
/// tetrahedra (the best found when undecided).
#[pyfunction]
#[pyo3(signature = (points, faces=None, minimal=false, unique=false, time_limit=None))]
pub fn tetrahedralize<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    faces: Option<PyReadonlyArray2<'py, i64>>,
    minimal: bool,
    unique: bool,
    time_limit: Option<f64>,
) -> PyResult<Cells<'py>> {
    let ctl = convert::control(time_limit)?;
    let (poly, pts);
    let domain = match &faces {
        Some(f) => {
            poly = polyhedron(&points, f)?;
            Domain::Polyhedron(&poly)
        }
        None => {
            let (p, dim) = convert::points(&points, "points")?;
            pts = convert::input(p, dim, &Rows::default(), false)?.points;
            Domain::Points(&pts)
        }
    };
    let opts = TetraOptions { minimal, unique };
    let mut o = convert::run(py, &ctl, || exact::tetrahedralize(domain, opts, &ctl))?
        .map_err(value_error)?;
    let tets = std::mem::take(&mut o.tets);
    Ok((report::json(&o, []).to_string(), array(py, &tets)))
}

type ShellOut<'py> = (Json, Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

/// `shell(outer, inner, method, flips, optimum, time_limit)`: the region between the hulls of two
/// nested point sets, its JSON, its points (outer vertices, then inner) and its certified
/// tetrahedra on them (none when undecided).
#[pyfunction]
#[pyo3(signature = (outer, inner, method="cap", flips=true, optimum=false, time_limit=None))]
pub fn shell<'py>(
    py: Python<'py>,
    outer: PyReadonlyArray2<'py, f64>,
    inner: PyReadonlyArray2<'py, f64>,
    method: &str,
    flips: bool,
    optimum: bool,
    time_limit: Option<f64>,
) -> PyResult<ShellOut<'py>> {
    let method = match method {
        "cap" => Method::Cap,
        "bigcap" => Method::Bigcap,
        "thesis" => Method::Thesis,
        m => {
            return Err(value_error(format!(
                "method '{m}': expected 'cap', 'bigcap' or 'thesis'"
            )));
        }
    };
    let three_d = |a: &PyReadonlyArray2<'_, f64>, name: &str| -> PyResult<Vec<[f64; 3]>> {
        let (p, dim) = convert::points(a, name)?;
        if dim != 3 {
            return Err(value_error(format!(
                "{name} are planar: a shell needs 3D polytopes"
            )));
        }
        Ok(convert::input(p, dim, &Rows::default(), false)?.points)
    };
    let (o, i) = (three_d(&outer, "outer")?, three_d(&inner, "inner")?);
    let shell = Shell::new(&o, &i).map_err(value_error)?;
    let ctl = convert::control(time_limit)?;
    let opts = ShellOptions {
        method,
        flips,
        optimum,
    };
    let outcome =
        convert::run(py, &ctl, || tetrakit::shell::shell(&shell, opts, &ctl))?.map_err(internal)?;
    Ok((
        report::json(&outcome, []).to_string(),
        point_array(py, &shell.points),
        array(py, &outcome.tets),
    ))
}
