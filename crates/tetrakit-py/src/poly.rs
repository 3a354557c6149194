//! `mintetra`, `tetrahedralize` and `shell` (thesis ch. 3 and 4).

use crate::convert::{self, Json, Rows, array, point_array, value_error};
use numpy::{PyArray2, PyReadonlyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use serde_json::json;
use tetrakit::control::Control;
use tetrakit::exact::{self, Domain, Options, Outcome};
use tetrakit::mesh::Polyhedron;
use tetrakit::polyhedra;
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

/// `mintetra(points, faces)`: MINTETRA's answer as JSON and its certified tetrahedra.
#[pyfunction]
pub fn mintetra<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    faces: PyReadonlyArray2<'py, i64>,
) -> PyResult<Cells<'py>> {
    let poly = polyhedron(&points, &faces)?;
    let ctl = Control::new();
    let (m, _) = convert::run(py, &ctl, || polyhedra::mintetra_certified(&poly))?
        .map_err(|e| internal(format!("MINTETRA's tetrahedra fail the certificate: {e}")))?;
    let n = poly.points.len();
    let mut v = json!({
        "verdict": if m.yes { "yes" } else { "no" },
        "vertices": n,
        "faces": poly.faces.len(),
        "lower_bound": n.saturating_sub(3),
        "levels": m.levels,
        "trims_per_level": m.trims_per_level,
        "polar_edges": m.polar_edges,
    });
    if m.yes {
        let status = polyhedra::minimality(&poly, &m);
        v["certified"] = json!(true);
        v["tetrahedra"] = json!(m.tets.len());
        v["minimality"] = json!(status);
        v["conjectured_minimal"] = json!(status == "conjectured");
    } else {
        v["reason"] = json!(m.reason);
        v["remaining_faces"] = json!(m.remaining);
        v["witness"] = json!({
            "kind": "not_augmented_bp_polyhedron",
            "detail": m.reason,
            "remaining_faces": m.remaining,
        });
    }
    Ok((v.to_string(), array(py, &m.tets)))
}

/// `tetrahedralize(points, faces, minimal, unique, time_limit)`: the exact solver's
/// answer (`yes`, `no` with a witness, or `undecided` with bounds) and its certified
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
    let (domain, n) = match &faces {
        Some(f) => {
            poly = polyhedron(&points, f)?;
            (Domain::Polyhedron(&poly), poly.points.len())
        }
        None => {
            let (p, dim) = convert::points(&points, "points")?;
            pts = convert::input(p, dim, &Rows::default(), false)?.points;
            (Domain::Points(&pts), pts.len())
        }
    };
    let opts = Options {
        unique,
        any: !minimal,
    };
    let (outcome, stats) = convert::run(py, &ctl, || {
        exact::minimal_tetrahedralization(domain, &opts, &ctl)
    })?
    .map_err(value_error)?;
    let mut v = json!({
        "vertices": n,
        "domain": if faces.is_some() { "polyhedron" } else { "convex hull" },
        "candidates": stats.candidates,
        "sat_calls": stats.calls,
    });
    let tets = match outcome {
        Outcome::Optimal { tets, unique, .. } => {
            v["verdict"] = json!("yes");
            v["minimum"] = json!(tets.len());
            v["unique"] = json!(unique);
            Some(tets)
        }
        Outcome::Found { tets } => {
            v["verdict"] = json!("yes");
            Some(tets)
        }
        Outcome::Infeasible => {
            v["verdict"] = json!("no");
            v["witness"] = match &stats.obstacle {
                Some(o) => json!({"kind": "obstacle", "detail": o.to_string()}),
                None => json!({"kind": "unsatisfiable"}),
            };
            None
        }
        Outcome::Undecided { best, lower } => {
            v["verdict"] = json!("undecided");
            v["lower_bound"] = json!(lower);
            v["upper_bound"] = json!(best.as_ref().map(Vec::len));
            best
        }
    };
    let tets = tets.unwrap_or_default();
    if !tets.is_empty() {
        domain
            .certify(&tets)
            .map_err(|e| internal(format!("the solver's tetrahedra fail the certificate: {e}")))?;
        v["tetrahedra"] = json!(tets.len());
        v["certified"] = json!(true);
    }
    Ok((v.to_string(), array(py, &tets)))
}

type ShellOut<'py> = (Json, Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

/// `shell(outer, inner, method, flips, time_limit)`: the region between the hulls of two
/// nested point sets, its JSON, its points (outer vertices, then inner) and its certified
/// tetrahedra on them (none when undecided).
#[pyfunction]
#[pyo3(signature = (outer, inner, method="cap", flips=true, time_limit=None))]
pub fn shell<'py>(
    py: Python<'py>,
    outer: PyReadonlyArray2<'py, f64>,
    inner: PyReadonlyArray2<'py, f64>,
    method: &str,
    flips: bool,
    time_limit: Option<f64>,
) -> PyResult<ShellOut<'py>> {
    let method = match method {
        "cap" => Method::Cap,
        "bigcap" => Method::Bigcap,
        m => {
            return Err(value_error(format!(
                "method '{m}': expected 'cap' or 'bigcap'"
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
    let opts = ShellOptions { method, flips };
    let outcome =
        convert::run(py, &ctl, || tetrakit::shell::shell(&shell, opts, &ctl))?.map_err(internal)?;
    Ok((
        tetrakit::report::json(&outcome, []).to_string(),
        point_array(py, &shell.points),
        array(py, &outcome.tets),
    ))
}
