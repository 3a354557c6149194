//! The JSON and the text of a `detect` outcome.

use crate::control::Verdict;
use crate::detect::{Answer, Cells, Detection, Route, Witness};
use serde::Serialize;
use serde_json::Value;
use std::fmt::Write;

/// `detect --json`'s own fields.
#[derive(Serialize)]
struct DetectJson {
    verdict: Verdict,
    vertices: usize,
    segments: usize,
    hull_vertices: usize,
    dimension: usize,
    route: Route,
    #[serde(skip_serializing_if = "Option::is_none")]
    tetrahedra: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    triangles: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    witness: Option<Witness>,
}

/// The JSON of `d`, vertices named by `label` (the file's numbering), with `extra`
/// fields (timings) after.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::detect::{Options, detect};
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let segs = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
/// let d = detect(&pts, &segs, &Options::default(), &Control::new()).unwrap();
/// let v = tetrakit::report::detect_json(&d, |v| v + 1, []);
/// assert_eq!((v["verdict"].as_str(), v["tetrahedra"].as_u64()), (Some("yes"), Some(1)));
/// ```
pub fn detect_json<'a>(
    d: &Detection,
    label: impl Fn(u32) -> u32,
    extra: impl IntoIterator<Item = (&'a str, Value)>,
) -> Value {
    let (mut tetrahedra, mut triangles, mut witness) = (None, None, None);
    match &d.answer {
        Answer::Yes(Cells::Tetrahedra(t)) => tetrahedra = Some(t.len()),
        Answer::Yes(Cells::Triangles(t)) => triangles = Some(t.len()),
        Answer::No(w) => witness = Some(w.clone().mapped(label)),
        Answer::Undecided => {}
    }
    let fields = DetectJson {
        verdict: d.verdict(),
        vertices: d.vertices,
        segments: d.segments,
        hull_vertices: d.hull_vertices,
        dimension: d.dimension,
        route: d.route,
        tetrahedra,
        triangles,
        witness,
    };
    super::json(&fields, extra)
}

/// The lines a person reads for `d`, vertices named by `label`; `from_tets` when the
/// segments were the edges of given tetrahedra.
pub fn detect_text(
    d: &Detection,
    label: impl Fn(u32) -> u32,
    from_tets: bool,
    seconds: f64,
) -> String {
    let src = match from_tets {
        true => " (the edges of the given tetrahedra)",
        false => "",
    };
    let mut s = String::new();
    let (n, m, h) = (d.vertices, d.segments, d.hull_vertices);
    let _ = match &d.answer {
        Answer::Yes(Cells::Tetrahedra(t)) => writeln!(
            s,
            "YES: the {m} segments{src} on {n} points form a tetrahedralization with {} tetrahedra ({h} points on the hull). [{seconds:.3} s]",
            t.len()
        ),
        Answer::Yes(Cells::Triangles(t)) => writeln!(
            s,
            "YES: the {m} segments{src} on {n} coplanar points form a triangulation with {} triangles ({h} points on the hull). [{seconds:.3} s]",
            t.len()
        ),
        Answer::No(w) => no_text(&mut s, d, &w.clone().mapped(label), src, seconds),
        Answer::Undecided => writeln!(
            s,
            "UNDECIDED: stopped at the time limit before the {m} segments{src} on {n} points were decided. [{seconds:.3} s]"
        ),
    };
    s
}

fn no_text(
    s: &mut String,
    d: &Detection,
    w: &Witness,
    src: &str,
    seconds: f64,
) -> std::fmt::Result {
    let what = match d.dimension {
        2 => "triangulation",
        _ => "tetrahedralization",
    };
    writeln!(
        s,
        "NO: the {} segments{src} on {} points are not the edge set of a {what}.",
        d.segments, d.vertices
    )?;
    writeln!(s, "  witness: {}: {}", w.kind, w.detail)?;
    if !w.vertices.is_empty() {
        let v: Vec<String> = w.vertices.iter().map(|x| x.to_string()).collect();
        writeln!(s, "  vertices: {}", v.join(" "))?;
    }
    if !w.segments.is_empty() {
        let e: Vec<String> = w
            .segments
            .iter()
            .map(|e| format!("{}-{}", e[0], e[1]))
            .collect();
        writeln!(s, "  segments: {}", e.join(" "))?;
    }
    writeln!(s, "  [{seconds:.3} s]")
}
