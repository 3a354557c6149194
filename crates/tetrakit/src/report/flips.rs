//! The text of the `flips` outcome (thesis ch. 6's flip graph), and the graph file
//! `--output G.json` writes.

use crate::control::Verdict;
use crate::flipgraph::{Count, Cut, FlipGraph, FlipKind};
use crate::geom::Point3;
use serde_json::{Value, json};
use std::fmt::Write;

/// The line a person reads for a count of tetrahedralizations made in `seconds`.
///
/// ```
/// use tetrakit::control::Control;
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0]];
/// let c = tetrakit::flipgraph::count(&pts, usize::MAX, &Control::new()).unwrap();
/// let text = tetrakit::report::flip_count_text(&c, 0.0);
/// assert!(text.starts_with("2 tetrahedralizations"));
/// ```
pub fn flip_count_text(c: &Count, seconds: f64) -> String {
    let n = c.tetrahedralizations;
    let what = match c.cut {
        None => format!("{n} tetrahedralizations"),
        Some(Cut::Limit) => {
            format!(
                "UNDECIDED: at least {n} tetrahedralizations (the enumeration stopped at the limit)"
            )
        }
        Some(_) => {
            format!("UNDECIDED: at least {n} tetrahedralizations (stopped at the time limit)")
        }
    };
    format!(
        "{what} of the {} points using every point, from {} empty tetrahedra, every one certified [{seconds:.3} s]",
        c.points, c.candidates
    )
}

/// The lines a person reads for a flip graph computed in `seconds`.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::flipgraph::{FlipOptions, flip_graph};
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0]];
/// let g = flip_graph(&pts, &FlipOptions::default(), &Control::new()).unwrap();
/// let text = tetrakit::report::flips_text(&g, 0.0);
/// assert!(text.starts_with("flip graph: YES, connected: 2 tetrahedralizations"));
/// ```
pub fn flips_text(g: &FlipGraph, seconds: f64) -> String {
    let mut s = String::new();
    let n = g.tetrahedralizations;
    let _ = match (g.verdict, g.cut) {
        (Verdict::Undecided, Some(Cut::Limit)) => writeln!(
            s,
            "flip graph: UNDECIDED: the enumeration stopped at the limit of {n} tetrahedralizations (there are at least that many)"
        ),
        (Verdict::Undecided, _) => writeln!(
            s,
            "flip graph: UNDECIDED: stopped at the time limit after {n} tetrahedralizations (there are at least that many)"
        ),
        (Verdict::No, _) => writeln!(s, "flip graph: NO, not connected: {n} tetrahedralizations"),
        _ => writeln!(s, "flip graph: YES, connected: {n} tetrahedralizations"),
    };
    let _ = writeln!(
        s,
        "  {} points, {} empty tetrahedra; {} to {} tetrahedra each, every one certified",
        g.points, g.candidates, g.min_tetrahedra, g.max_tetrahedra
    );
    if let Some(f) = &g.graph {
        let c = &f.flips;
        let _ = writeln!(
            s,
            "  {} flips ({} 2-3, {} 2-2, {} 4-4); {} to {} per tetrahedralization",
            c.total, c.two_three, c.two_two, c.four_four, f.min_flips, f.max_flips
        );
        if let Some(d) = f.diameter {
            let _ = writeln!(s, "  diameter: {d} flips");
        }
        if f.components > 1 {
            let _ = writeln!(
                s,
                "  {} components, sizes {:?}",
                f.components, f.component_sizes
            );
        }
        match f.isolated.len() {
            0 => {}
            k => {
                let _ = writeln!(s, "  {k} with no flip, the first: {}", tets(&f.isolated[0]));
            }
        }
    }
    if let Some(w) = &g.witness {
        let _ = writeln!(
            s,
            "  witness: no flips join {} (a component of {}) and {} (a component of {})",
            tets(&w.first),
            w.sizes[0],
            tets(&w.second),
            w.sizes[1]
        );
    }
    let _ = writeln!(s, "  time: {seconds:.3} s ({} search states)", g.states);
    s
}

fn tets(t: &[[u32; 4]]) -> String {
    let all: Vec<String> = t
        .iter()
        .map(|[a, b, c, d]| format!("{a} {b} {c} {d}"))
        .collect();
    format!("[{}]", all.join(", "))
}

/// The graph as one JSON object (`--output G.json`): the points, every
/// tetrahedralization found (tetrahedra in the outcome's numbering) and every flip as
/// `[i, j, kind]` with `i < j` places in the list (none when the enumeration was cut).
pub fn flip_graph_json(g: &FlipGraph, points: &[Point3]) -> Value {
    let name = |k: FlipKind| match k {
        FlipKind::TwoThree => "2-3",
        FlipKind::TwoTwo => "2-2",
        FlipKind::FourFour => "4-4",
    };
    let flips: Vec<Value> = (g.neighbours.iter().enumerate())
        .flat_map(|(i, ns)| {
            ns.iter()
                .filter(move |(j, _)| *j as usize > i)
                .map(move |&(j, k)| json!([i, j, name(k)]))
        })
        .collect();
    let all: Vec<Vec<[u32; 4]>> = (0..g.tetrahedralizations)
        .map(|i| g.tetrahedralization(i))
        .collect();
    json!({
        "points": points,
        "tetrahedralizations": all,
        "flips": flips,
    })
}
