//! `check` and `detect` (thesis ch. 2 and the mesh validator).

use crate::convert::{self, Json, Rows, array, value_error};
use numpy::{PyArray1, PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;
use tetrakit::detect::{Cells, Options};
use tetrakit::mesh;

type CheckOut<'py> = (
    Json,
    Bound<'py, PyArray2<i64>>,
    Bound<'py, PyArray1<i32>>,
    Bound<'py, PyArray1<i32>>,
);

/// `check(points, tets, convex, manifold, reorient)`: the report as JSON, the tets (turned
/// where `reorient`), and the problem code of each tet and of each point (0 = none).
#[pyfunction]
#[pyo3(signature = (points, tets, convex=false, manifold=false, reorient=false))]
pub fn check<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    tets: PyReadonlyArray2<'py, i64>,
    convex: bool,
    manifold: bool,
    reorient: bool,
) -> PyResult<CheckOut<'py>> {
    let (pts, dim) = convert::points(&points, "points")?;
    let rows = Rows {
        tets: convert::rows(&tets, "tets")?,
        ..Default::default()
    };
    let mut input = convert::input(pts, dim, &rows, true)?;
    if input.tets.is_empty() {
        return Err(value_error("no tetrahedra to check"));
    }
    let opts = mesh::CheckOptions {
        convex,
        manifold,
        reorient,
    };
    let ctl = tetrakit::control::Control::new();
    let tets = std::mem::take(&mut input.tets);
    let o = convert::run(py, &ctl, || mesh::check(&input.points, tets, opts))?;
    let text = tetrakit::report::json(&o, []).to_string();
    Ok((
        text,
        array(py, &o.tets),
        PyArray1::from_vec(py, o.cell_problems),
        PyArray1::from_vec(py, o.point_problems),
    ))
}

type ReadOut<'py> = (
    Json,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<i64>>,
    Bound<'py, PyArray2<i64>>,
    Bound<'py, PyArray2<i64>>,
);

/// `read(path, tets_only)`: a mesh file read as `tetrakit check` reads it
/// ([`tetrakit::io::ReadOptions::mesh`]): the counts and numbering as JSON, then the
/// points, tetrahedra, triangles and segments (0-based). A bad file is a `ValueError`
/// with the CLI's one-line message (file, line or byte, problem).
#[pyfunction]
#[pyo3(signature = (path, tets_only=false))]
pub fn read<'py>(
    py: Python<'py>,
    path: std::path::PathBuf,
    tets_only: bool,
) -> PyResult<ReadOut<'py>> {
    let opts = tetrakit::io::ReadOptions {
        tets_only,
        mesh: true,
    };
    let ctl = tetrakit::control::Control::new();
    let input = convert::run(py, &ctl, || tetrakit::io::read_input_with(&path, opts))?
        .map_err(value_error)?;
    let facts = tetrakit::report::json(&tetrakit::report::mesh_facts(&input), []);
    Ok((
        facts.to_string(),
        convert::point_array(py, &input.points),
        array(py, &input.tets),
        array(py, &input.faces),
        array(py, &input.segments),
    ))
}

/// `detect(points, segments, time_limit)`: the verdict as JSON and the cells of a YES
/// (tetrahedra, or triangles for coplanar points; an empty `(0, 4)` array for a NO or
/// when out of time).
#[pyfunction]
#[pyo3(signature = (points, segments, time_limit=None))]
pub fn detect<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    segments: PyReadonlyArray2<'py, i64>,
    time_limit: Option<f64>,
) -> PyResult<(Json, Bound<'py, PyArray2<i64>>)> {
    let input = convert::with_segments(&points, &segments)?;
    if input.segments.is_empty() {
        return Err(value_error("no segments to test"));
    }
    let ctl = convert::control(time_limit)?;
    let d = convert::run(py, &ctl, || {
        tetrakit::detect::detect(&input.points, &input.segments, &Options::default(), &ctl)
    })?
    .map_err(value_error)?;
    let v = tetrakit::report::detect_json(&d, |v| v, []);
    let cells = match d.answer.cells() {
        Some(Cells::Tetrahedra(t)) => array(py, t),
        Some(Cells::Triangles(t)) => array(py, t),
        None => array::<4>(py, &[]),
    };
    Ok((v.to_string(), cells))
}
