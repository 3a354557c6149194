//! `contains` and `constrained` (thesis ch. 2 §2.5–2.6, decided exactly by SAT).

use crate::convert::{self, Json, array, value_error};
use numpy::{PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;
use tetrakit::constrain::{self, Answer, Options, Question};
use tetrakit::detect::Cells;
use tetrakit::report;

/// `decide(question, points, segments, minimal, time_limit)`: `question` is
/// `"contains"` (TETRAD, TRID for coplanar points) or `"constrained"` (CT, every segment
/// an edge). The decision as JSON (the CLI's fields but the cell lists) and its
/// certified cells: tetrahedra, or triangles for coplanar points (an empty `(0, 4)`
/// array for a NO or undecided).
#[pyfunction]
#[pyo3(signature = (question, points, segments, minimal=false, time_limit=None))]
pub fn decide<'py>(
    py: Python<'py>,
    question: &str,
    points: PyReadonlyArray2<'py, f64>,
    segments: PyReadonlyArray2<'py, i64>,
    minimal: bool,
    time_limit: Option<f64>,
) -> PyResult<(Json, Bound<'py, PyArray2<i64>>)> {
    let question = match question {
        "contains" => Question::Contains,
        "constrained" => Question::Constrained,
        q => {
            let expected = "expected 'contains' or 'constrained'";
            return Err(value_error(format!("question '{q}': {expected}")));
        }
    };
    let solve = match question {
        Question::Contains => constrain::contains,
        Question::Constrained => constrain::constrained,
    };
    let input = convert::with_segments(&points, &segments)?;
    if input.segments.is_empty() && question == Question::Contains {
        return Err(value_error("no segments to test"));
    }
    let ctl = convert::control(time_limit)?;
    let opts = Options { minimal };
    let d = convert::run(py, &ctl, || {
        solve(&input.points, &input.segments, &opts, &ctl)
    })?
    .map_err(value_error)?;
    let cells = match &d.answer {
        Answer::Yes(Cells::Tetrahedra(t)) => array(py, t),
        Answer::Yes(Cells::Triangles(t)) => array(py, t),
        _ => array::<4>(py, &[]),
    };
    let size = [input.points.len(), input.segments.len()];
    Ok((
        report::constrain_json(&d, size, 0, false, []).to_string(),
        cells,
    ))
}
