//! `tetrakit flips PTS`: the flip graph of a point set's tetrahedralizations (thesis
//! ch. 6).

use crate::exit::{CliError, CmdResult, WriteContext};
use crate::progress::Run;
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::flipgraph::{FlipError, FlipOptions, count, flip_graph};
use tetrakit::{io, report};

/// What `flips` was asked.
pub struct FlipsArgs<'a> {
    pub input: &'a Path,
    pub limit: usize,
    pub time_limit: Option<Duration>,
    pub as_json: bool,
    pub output: Option<&'a Path>,
    pub count_only: bool,
}

pub fn flips(a: FlipsArgs) -> CmdResult {
    let start = Instant::now();
    let input = io::read_input(a.input)?;
    if input.dim != 3 {
        return Err(CliError::at(
            a.input,
            "the points are planar: the flip graph of tetrahedralizations needs 3D points",
        ));
    }
    let opts = FlipOptions {
        limit: a.limit.max(1),
        ..FlipOptions::default()
    };
    let run = Run::new(a.time_limit, input.points.len(), 12);
    if a.count_only {
        let c = count(&input.points, opts.limit, &run.ctl).map_err(|e| blame(e, &input))?;
        drop(run);
        let seconds = start.elapsed().as_secs_f64();
        match a.as_json {
            true => out!("{}", report::json(&c, [("seconds", seconds.into())])),
            false => out!("{}", report::flip_count_text(&c, seconds)),
        }
        return Ok(c.verdict);
    }
    let g = flip_graph(&input.points, &opts, &run.ctl).map_err(|e| blame(e, &input))?;
    drop(run);
    let g = g.shifted(input.index_base);
    if let Some(out) = a.output {
        let text = report::flip_graph_json(&g, &input.points).to_string();
        std::fs::write(out, text + "\n").written(out)?;
    }
    let seconds = start.elapsed().as_secs_f64();
    if a.as_json {
        out!("{}", report::json(&g, [("seconds", seconds.into())]));
    } else {
        out!("{}", report::flips_text(&g, seconds).trim_end());
    }
    Ok(g.verdict)
}

/// An error blamed on the file (the reader has refused repeated points already; the
/// rest are about the set as a whole) or, for a bug, reported as internal.
fn blame(e: FlipError, input: &io::Input) -> CliError {
    match e {
        FlipError::FlipOutside { .. } | FlipError::Uncertified { .. } | FlipError::NoAnchor => {
            CliError::internal(e)
        }
        _ => {
            let what = tetrakit::numbering::renumber_text(&e.to_string(), input.index_base);
            CliError::at(&input.point_file, what)
        }
    }
}

/// `generate points3d`.
pub fn generate_points(
    dist: tetrakit::generate::Distribution3,
    n: usize,
    seed: u64,
    output: &Path,
) -> CmdResult {
    if !(4..=10_000_000).contains(&n) {
        return Err(CliError::new("--n must be between 4 and 10000000"));
    }
    let pts = tetrakit::generate::points3d(dist, n, seed);
    io::write_points(output, &pts).written(output)?;
    out!(
        "wrote {} {dist:?} points to {}",
        pts.len(),
        output.display()
    );
    Ok(tetrakit::control::Verdict::Yes)
}
