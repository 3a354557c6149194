//! Chapter 2 §2.5–2.6 commands: `contains` (TETRAD, TRID for planar input) and
//! `constrained` (CT).

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use tetrakit::constrain::{self, Answer, Options, Question};
use tetrakit::detect::Cells;
use tetrakit::exact::Proof;
use tetrakit::io;
use tetrakit::report::{self, ProofFiles};

pub struct Args<'a> {
    pub question: Question,
    pub input: &'a Path,
    /// For `constrained`: the constraints from this file instead (same points).
    pub segments: Option<&'a Path>,
    pub minimal: bool,
    pub time_limit: Option<Duration>,
    pub as_json: bool,
    pub output: Option<&'a Path>,
    pub proof: Option<&'a Path>,
}

pub fn run(a: Args) -> CmdResult {
    let start = Instant::now();
    let input = io::read_input(a.input)?;
    let segments = match a.segments {
        None => input.segments.clone(),
        Some(path) => segments_from(path, &input.points)?,
    };
    if segments.is_empty() && a.question == Question::Contains {
        return Err(CliError::at(
            a.input,
            "no segments (give an .edge file, OBJ 'l' lines or JSON \"segments\")",
        ));
    }
    let run = Run::new(a.time_limit, input.points.len(), 40);
    run.stage(match a.question {
        Question::Contains => "contains: candidates and SAT",
        Question::Constrained => "constrained: candidates and SAT",
    });
    let options = Options { minimal: a.minimal };
    let decide = match a.question {
        Question::Contains => constrain::contains,
        Question::Constrained => constrain::constrained,
    };
    let d = decide(&input.points, &segments, &options, &run.ctl)
        .map_err(|e| CliError::at(a.input, e))?;
    let base = input.index_base;
    if let (Some(out), Answer::Yes(cells)) = (a.output, &d.answer) {
        match cells {
            Cells::Tetrahedra(t) => io::write_mesh(out, &input.points, t, base),
            Cells::Triangles(t) => io::write_triangulation(out, &input.points, t),
        }
        .written(out)?;
    }
    let mut proof = None;
    if let (Some(path), Answer::No(_)) = (a.proof, &d.answer) {
        run.stage("writing the DRAT proof");
        proof = Some(write_proof(path, |formula, proof| {
            constrain::prove(
                a.question,
                &input.points,
                &segments,
                formula,
                proof,
                &run.ctl,
            )
        })?);
    }
    drop(run);
    let seconds = start.elapsed().as_secs_f64();
    let size = [input.points.len(), segments.len()];
    if a.as_json {
        let extra = [
            ("proof", serde_json::to_value(&proof).unwrap_or_default()),
            ("seconds", seconds.into()),
        ];
        out!("{}", report::constrain_json(&d, size, base, true, extra));
    } else {
        let text = report::constrain_text(&d, a.question, size, base, seconds);
        out!("{}", text.trim_end());
        if let Some(p) = &proof {
            out!("{}", p.line());
        }
    }
    Ok(d.verdict())
}

/// The constraints of `path`, whose points must be those of the first input.
fn segments_from(path: &Path, points: &[[f64; 3]]) -> Result<Vec<[u32; 2]>, CliError> {
    let s = io::read_input(path)?;
    if s.segments.is_empty() {
        return Err(CliError::at(path, "no segments in this file"));
    }
    if s.points != points {
        return Err(CliError::at(
            path,
            format!(
                "its points ({}) are not those of the first input ({}): give the constraints on the same points",
                s.points.len(),
                points.len()
            ),
        ));
    }
    Ok(s.segments)
}

/// `P.drat` and the formula beside it, `P.cnf`, written by `prove` (given the formula's
/// and the proof's writers); what they hold.
pub fn write_proof<E: std::fmt::Display>(
    path: &Path,
    prove: impl FnOnce(&mut std::fs::File, std::io::BufWriter<std::fs::File>) -> Result<Proof, E>,
) -> Result<ProofFiles, CliError> {
    let cnf_path: PathBuf = path.with_extension("cnf");
    if cnf_path == path {
        return Err(CliError::at(
            path,
            "name the proof .drat (the formula goes to .cnf beside it)",
        ));
    }
    let mut formula = std::fs::File::create(&cnf_path).written(&cnf_path)?;
    let proof = std::io::BufWriter::new(std::fs::File::create(path).written(path)?);
    let r = prove(&mut formula, proof).map_err(|e| CliError::at(path, e))?;
    Ok(match r {
        Proof::Refuted { variables, clauses } => ProofFiles::Written {
            formula: cnf_path.display().to_string(),
            drat: path.display().to_string(),
            variables,
            clauses,
        },
        Proof::Stopped => ProofFiles::STOPPED,
        Proof::Satisfiable => {
            return Err(CliError::internal(
                "the proof solver found the formula satisfiable after a NO",
            ));
        }
    })
}

/// A generated CT instance: points and constraints, numbered from 1 where the format
/// numbers.
fn write_constraints(output: &Path, pts: &[[f64; 3]], segs: &[[u32; 2]]) -> Result<(), CliError> {
    io::write_edges(output, pts, segs, 1).written(output)
}

/// `generate gadget-grid`.
pub fn generate_gadget_grid(
    rows: usize,
    cols: usize,
    layers: usize,
    twist: f64,
    spacing: f64,
    output: &Path,
) -> CmdResult {
    let (pts, segs) = constrain::generate::gadget_grid(rows, cols, layers, twist, spacing)?;
    write_constraints(output, &pts, &segs)?;
    out!(
        "wrote {}: {} points, {} constraints ({rows} × {cols} towers of {layers} Schönhardt gadget(s))",
        output.display(),
        pts.len(),
        segs.len()
    );
    Ok(Verdict::Yes)
}

/// `generate niche`.
pub fn generate_niche(
    twist: f64,
    extra: usize,
    in_view: bool,
    seed: u64,
    output: &Path,
) -> CmdResult {
    let g = constrain::generate::niche(twist, extra, in_view, seed)?;
    let (pts, segs, n) = (g.points, g.constraints, g.niche);
    write_constraints(output, &pts, &segs)?;
    out!(
        "wrote {}: {} points, {} constraints; niche top {:?}, base {:?} (0-based), {} point in its view",
        output.display(),
        pts.len(),
        segs.len(),
        n.top,
        n.base,
        if n.vertex_in_view(&pts).is_some() {
            "a"
        } else {
            "no"
        }
    );
    Ok(Verdict::Yes)
}
