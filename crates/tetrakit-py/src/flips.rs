//! Chapter 6: `flips` (the flip graph of a point set's tetrahedralizations) and
//! `hamiltonian` (a tetrahedralization with a Hamiltonian dual path).

use crate::convert::{self, Json, Rows, array, value_error};
use numpy::{PyArray2, PyReadonlyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use tetrakit::flipgraph::{FlipError, FlipKind, FlipOptions, count, flip_graph};
use tetrakit::report;

type FlipsOut<'py> = (
    Json,
    Vec<Bound<'py, PyArray2<i64>>>,
    Bound<'py, PyArray2<i64>>,
    Vec<&'static str>,
);

/// Points in space, checked as the readers check a file's.
fn points_in_space(points: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<tetrakit::geom::Point3>> {
    let (pts, dim) = convert::points(points, "points")?;
    if dim != 3 {
        return Err(value_error(
            "the points are planar: this needs points in space",
        ));
    }
    Ok(convert::input(pts, dim, &Rows::default(), false)?.points)
}

/// A bug is a `RuntimeError`, anything else about the set a `ValueError`.
fn raised(e: FlipError) -> PyErr {
    match e {
        FlipError::FlipOutside { .. } | FlipError::Uncertified { .. } | FlipError::NoAnchor => {
            PyRuntimeError::new_err(format!("{e} (a bug: please report it)"))
        }
        _ => value_error(e),
    }
}

/// `count_tetrahedralizations(points, limit, time_limit)`: the count as JSON.
#[pyfunction]
#[pyo3(signature = (points, limit=usize::MAX, time_limit=None))]
pub fn count_tetrahedralizations(
    py: Python<'_>,
    points: PyReadonlyArray2<'_, f64>,
    limit: usize,
    time_limit: Option<f64>,
) -> PyResult<Json> {
    let ctl = convert::control(time_limit)?;
    let pts = points_in_space(&points)?;
    let c = convert::run(py, &ctl, || count(&pts, limit.max(1), &ctl))?.map_err(raised)?;
    Ok(report::json(&c, []).to_string())
}

/// `flips(points, limit, time_limit)`: the outcome as JSON, every tetrahedralization
/// found (one array of tetrahedra each), the flips as pairs of places in that list
/// (`i < j`) and each flip's kind (`"2-3"`, `"2-2"`, `"4-4"`).
#[pyfunction]
#[pyo3(signature = (points, limit=1_000_000, time_limit=None))]
pub fn flips<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    limit: usize,
    time_limit: Option<f64>,
) -> PyResult<FlipsOut<'py>> {
    let ctl = convert::control(time_limit)?;
    let pts = points_in_space(&points)?;
    let opts = FlipOptions {
        limit: limit.max(1),
        ..FlipOptions::default()
    };
    let g = convert::run(py, &ctl, || flip_graph(&pts, &opts, &ctl))?.map_err(raised)?;
    let all = (0..g.tetrahedralizations)
        .map(|i| array(py, &g.tetrahedralization(i)))
        .collect();
    let mut pairs = Vec::new();
    let mut kinds = Vec::new();
    for (i, ns) in g.neighbours.iter().enumerate() {
        for &(j, kind) in ns.iter().filter(|(j, _)| *j as usize > i) {
            pairs.push([i as u32, j]);
            kinds.push(match kind {
                FlipKind::TwoThree => "2-3",
                FlipKind::TwoTwo => "2-2",
                FlipKind::FourFour => "4-4",
            });
        }
    }
    Ok((
        report::json(&g, []).to_string(),
        all,
        array(py, &pairs),
        kinds,
    ))
}

/// `hamiltonian(points, time_limit)`: a tetrahedralization of a convex polytope's points
/// with its tetrahedra in a Hamiltonian dual path (JSON, and the tetrahedra in path
/// order).
#[pyfunction]
#[pyo3(signature = (points, time_limit=None))]
pub fn hamiltonian<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    time_limit: Option<f64>,
) -> PyResult<(Json, Bound<'py, PyArray2<i64>>)> {
    use tetrakit::dualpath::{PathError, PathOptions};
    let ctl = convert::control(time_limit)?;
    let pts = points_in_space(&points)?;
    let mut o = convert::run(py, &ctl, || {
        tetrakit::dualpath::hamiltonian(&pts, &PathOptions::default(), &ctl)
    })?
    .map_err(|e| match e {
        PathError::Uncertified(_) | PathError::Internal(_) | PathError::Enumeration(_) => {
            PyRuntimeError::new_err(e.to_string())
        }
        _ => value_error(e),
    })?;
    let tets = std::mem::take(&mut o.tets);
    Ok((report::json(&o, []).to_string(), array(py, &tets)))
}
