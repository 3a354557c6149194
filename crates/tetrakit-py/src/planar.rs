//! `skeleton`, `mwt` and `keil` (thesis ch. 5).

use crate::convert::{self, Json, array, point_array, value_error};
use numpy::{PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;
use tetrakit::geom::{Point2, Ratio};
use tetrakit::planar::{self, MwtOutcome, Region};
use tetrakit::report;

/// Planar sites from an `(n, 2)` array (or `(n, 3)` with every z = 0), checked as a
/// file's points are.
fn sites(a: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<Point2>> {
    let (p, dim) = convert::points(a, "points")?;
    let input = convert::input(p, dim, &convert::Rows::default(), false)?;
    if let Some(i) = input.points.iter().position(|p| p[2] != 0.0) {
        return Err(value_error(format!(
            "points[{i}] has z = {}; planar functions need 2D points",
            input.points[i][2]
        )));
    }
    Ok(input.points.iter().map(|p| [p[0], p[1]]).collect())
}

/// β as a rational: a decimal or `a/b` string, or a float (its exact binary value).
fn beta(text: &str) -> PyResult<Ratio> {
    text.parse::<Ratio>()
        .map_err(|e| value_error(format!("beta: {e}")))
}

/// `skeleton(points, beta, lune, time_limit)`: the exact β-skeleton's JSON and its edges
/// (out of time, `undecided` with the edges found so far).
#[pyfunction]
#[pyo3(signature = (points, beta_text, lune=false, time_limit=None))]
pub fn skeleton<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    beta_text: &str,
    lune: bool,
    time_limit: Option<f64>,
) -> PyResult<(Json, Bound<'py, PyArray2<i64>>)> {
    let (pts, b) = (sites(&points)?, beta(beta_text)?);
    let region = if lune { Region::Lune } else { Region::Circle };
    let ctl = convert::control(time_limit)?;
    let sk = convert::run(py, &ctl, || planar::beta_skeleton(&pts, b, region, &ctl))?
        .map_err(value_error)?;
    let v = report::skeleton_json(&sk, b, region, pts.len(), []);
    Ok((v.to_string(), array(py, &sk.edges)))
}

type MwtOut<'py> = (Json, Bound<'py, PyArray2<i64>>, Bound<'py, PyArray2<i64>>);

/// `mwt(points, time_limit)`: the exact minimum weight triangulation's JSON, edges and
/// triangles; out of time, `undecided` with certified bounds and the upper bound's
/// triangulation.
#[pyfunction]
#[pyo3(signature = (points, time_limit=None))]
pub fn mwt<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    time_limit: Option<f64>,
) -> PyResult<MwtOut<'py>> {
    let pts = sites(&points)?;
    let ctl = convert::control(time_limit)?;
    let m = convert::run(py, &ctl, || planar::mwt_or_bounds(&pts, &ctl))?.map_err(value_error)?;
    let (edges, triangles) = match &m {
        MwtOutcome::Solved(m) => (&m.edges, &m.triangles),
        MwtOutcome::Stopped(b) => (&b.edges, &b.triangles),
    };
    let v = report::mwt_json(&m, pts.len(), []);
    Ok((v.to_string(), array(py, edges), array(py, triangles)))
}

/// `keil(beta, n, time_limit)`: the §5.2 construction's exact verdicts as JSON, and its
/// sites (out of time, `undecided` with the sites and the skeleton test).
#[pyfunction]
#[pyo3(signature = (beta_text, n=None, time_limit=None))]
pub fn keil<'py>(
    py: Python<'py>,
    beta_text: &str,
    n: Option<usize>,
    time_limit: Option<f64>,
) -> PyResult<(Json, Bound<'py, PyArray2<f64>>)> {
    let b = beta(beta_text)?;
    if n == Some(0) {
        return Err(value_error("n = 0: at least one site per arc"));
    }
    let ctl = convert::control(time_limit)?;
    let k = convert::run(py, &ctl, || planar::keil(b, n, &ctl))?.map_err(value_error)?;
    Ok((
        report::keil_json(&k, []).to_string(),
        point_array(py, &k.construction().sites),
    ))
}
