//! The JSON and the text of a `contains` / `constrained` decision (TETRAD, TRID, CT).

use crate::constrain::{Answer, Decision, Question, Route, Witness};
use crate::control::Verdict;
use crate::detect::Cells;
use serde::Serialize;
use serde_json::Value;
use std::fmt::Write;

/// `contains --json` and `constrained --json`'s own fields.
#[derive(Serialize)]
struct DecisionJson {
    verdict: Verdict,
    vertices: usize,
    segments: usize,
    planar: bool,
    route: Route,
    candidates: usize,
    sat_calls: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    tetrahedra: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    triangles: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tets: Option<Vec<[u32; 4]>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tris: Option<Vec<[u32; 3]>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    minimum: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    certified: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    witness: Option<Witness>,
}

/// The JSON of `d` on `vertices` points and `segments` segments, numbered from `base`;
/// the cells themselves (`tets` or `tris`) when `cells`, then `extra` fields.
///
/// ```
/// use tetrakit::constrain::{Options, contains};
/// use tetrakit::control::Control;
/// let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let s = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
/// let d = contains(&p, &s, &Options::default(), &Control::new()).unwrap();
/// let v = tetrakit::report::constrain_json(&d, [4, 6], 1, true, []);
/// assert_eq!((v["verdict"].as_str(), v["tets"][0][0].as_u64()), (Some("yes"), Some(1)));
/// ```
pub fn constrain_json<'a>(
    d: &Decision,
    [vertices, segments]: [usize; 2],
    base: u32,
    cells: bool,
    extra: impl IntoIterator<Item = (&'a str, Value)>,
) -> Value {
    let yes = matches!(d.answer, Answer::Yes(_));
    let mut j = DecisionJson {
        verdict: d.verdict(),
        vertices,
        segments,
        planar: d.planar,
        route: d.route,
        candidates: d.stats.candidates,
        sat_calls: d.stats.calls,
        tetrahedra: None,
        triangles: None,
        tets: None,
        tris: None,
        minimum: yes.then_some(d.minimum),
        certified: yes.then_some(true),
        witness: None,
    };
    match &d.answer {
        Answer::Yes(Cells::Tetrahedra(t)) => {
            j.tetrahedra = Some(t.len());
            j.tets = cells.then(|| t.iter().map(|x| x.map(|v| v + base)).collect());
        }
        Answer::Yes(Cells::Triangles(t)) => {
            j.triangles = Some(t.len());
            j.tris = cells.then(|| t.iter().map(|x| x.map(|v| v + base)).collect());
        }
        Answer::No(w) => j.witness = Some(w.shifted(base)),
        Answer::Undecided => {}
    }
    super::json(&j, extra)
}

/// The lines a person reads for `d` (asked `question`, on `[vertices, segments]`,
/// numbered from `base`), found in `seconds`.
pub fn constrain_text(
    d: &Decision,
    question: Question,
    [vertices, segments]: [usize; 2],
    base: u32,
    seconds: f64,
) -> String {
    let mut s = String::new();
    let what = match question {
        Question::Contains => "the segments contain",
        Question::Constrained => "the points have",
    };
    let cell = match d.planar {
        true => "triangulation",
        false => "tetrahedralization",
    };
    match &d.answer {
        Answer::Yes(cells) => {
            let count = match cells {
                Cells::Tetrahedra(t) => t.len(),
                Cells::Triangles(t) => t.len(),
            };
            let with = match question {
                Question::Contains => "",
                Question::Constrained => " with every constraint as an edge",
            };
            let fewest = if d.minimum {
                " (the fewest possible)"
            } else {
                ""
            };
            let _ = writeln!(s, "YES: {what} a {cell}{with}: {count} cells{fewest}");
            let _ = writeln!(
                s,
                "  certified: orientation, face pairing, the convex hull, every point used, the edge rules"
            );
        }
        Answer::No(w) => {
            let w = w.shifted(base);
            let _ = writeln!(s, "NO: no {cell} obeys the segments");
            let _ = writeln!(s, "  witness ({}): {}", w.kind, w.detail);
        }
        Answer::Undecided => {
            let _ = writeln!(s, "undecided within the time limit");
        }
    }
    let _ = writeln!(
        s,
        "  {vertices} points, {segments} segments, route {}, {} candidates, {} SAT calls, {seconds:.3} s",
        crate::numbering::json_name(&d.route, ""),
        d.stats.candidates,
        d.stats.calls
    );
    s
}
