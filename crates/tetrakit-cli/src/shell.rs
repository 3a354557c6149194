//! `tetrakit shell OUTER INNER`: the region between two nested convex polytopes (thesis
//! ch. 4), tetrahedralized without Steiner points and certified.

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::geom::Point3;
use tetrakit::io::{self, Input};
use tetrakit::shell::{Method, Shell, ShellError, ShellOptions};

/// What `shell` was asked.
pub struct ShellArgs<'a> {
    pub outer: &'a Path,
    pub inner: &'a Path,
    pub method: Method,
    pub flips: bool,
    pub optimum: bool,
    pub time_limit: Option<Duration>,
    pub as_json: bool,
    pub output: Option<&'a Path>,
}

/// The points of a polytope file (any format with points; faces, if any, are not
/// needed: the polytope is the hull).
fn points(path: &Path) -> Result<Input, CliError> {
    let input = io::read_input(path)?;
    if input.dim != 3 {
        return Err(CliError::at(
            path,
            "the points are planar: a shell needs 3D polytopes",
        ));
    }
    Ok(input)
}

/// A shell error blamed on the file it is about, at the line of the point it names.
fn blame(e: ShellError, outer: &Input, inner: &Input) -> CliError {
    match e {
        ShellError::OuterFlat { .. } => CliError::at(&outer.point_file, e),
        ShellError::InnerFlat { .. } => CliError::at(&inner.point_file, e),
        ShellError::InnerOutside { index, .. } => {
            let line = inner.point_lines.get(index as usize).copied().unwrap_or(0);
            let file = inner.point_file.display();
            let what = format!(
                "point {} lies outside the outer hull",
                index + inner.index_base
            );
            if line > 0 {
                CliError::new(format!("{file}:{line}: {what}"))
            } else {
                CliError::new(format!("{file}: {what}"))
            }
        }
        ShellError::TooLargeForOptimum { .. } => CliError::new(format!("--optimum: {e}")),
        ShellError::Exact(_) => CliError::new(format!("--optimum: {e}")),
        // A bug: the library's sentence says so.
        ShellError::Internal(_) | ShellError::Uncertified(_) => CliError::new(e),
        ShellError::Stopped(_) => CliError::internal(e),
    }
}

pub fn shell(a: ShellArgs) -> CmdResult {
    let start = Instant::now();
    let (outer_in, inner_in) = rayon::join(|| points(a.outer), || points(a.inner));
    let (outer_in, inner_in) = (outer_in?, inner_in?);
    let shell = Shell::new(&outer_in.points, &inner_in.points)
        .map_err(|e| blame(e, &outer_in, &inner_in))?;
    let run = Run::new(a.time_limit, shell.outer.len(), 20_000);
    let opts = ShellOptions {
        method: a.method,
        flips: a.flips,
        optimum: a.optimum,
    };
    let o = tetrakit::shell::shell(&shell, opts, &run.ctl)
        .map_err(|e| blame(e, &outer_in, &inner_in))?;
    drop(run);
    if let (Some(out), Verdict::Yes) = (a.output, o.verdict) {
        io::write_mesh(out, &shell.points, &o.tets, 0).written(out)?;
    }
    let seconds = start.elapsed().as_secs_f64();
    if a.as_json {
        out!(
            "{}",
            tetrakit::report::json(&o, [("seconds", seconds.into())])
        );
    } else {
        out!("{}", tetrakit::report::shell_text(&o, seconds).trim_end());
    }
    Ok(o.verdict)
}

/// Writes two nested point sets, OUTER and INNER, as `.xyz` / `.node` / `.json`.
pub fn generate_nested(
    p: &tetrakit::shell::generate::NestedParams,
    outer: &Path,
    inner: &Path,
) -> CmdResult {
    let (o, i, radius) = tetrakit::shell::generate::nested(p)?;
    write_pair(&o, outer, &i, inner, &format!(" (radius {radius:.4})"))
}

/// Writes a Bern disk ([`tetrakit::shell::generate::bern_disk`]) as OUTER and INNER.
pub fn generate_bern_disk(
    ridge: usize,
    ring: usize,
    seed: u64,
    outer: &Path,
    inner: &Path,
) -> CmdResult {
    let (o, i) = tetrakit::shell::generate::bern_disk(ridge, ring, seed)?;
    write_pair(&o, outer, &i, inner, "")
}

/// `generate contact`.
pub fn generate_contact(
    kind: tetrakit::shell::generate::Contact,
    [n_outer, n_inner]: [usize; 2],
    seed: u64,
    outer: &Path,
    inner: &Path,
) -> CmdResult {
    let (o, i) = tetrakit::shell::generate::contact(kind, n_outer, n_inner, seed)?;
    write_pair(&o, outer, &i, inner, "")
}

/// `generate lemma41`: writes [`tetrakit::shell::lemma41::counterexample`] and reports
/// the check of `shell --method thesis` on it.
pub fn generate_lemma41(outer: &Path, inner: &Path, as_json: bool) -> CmdResult {
    let (o, i, _) = tetrakit::shell::lemma41::counterexample();
    io::write_points(outer, &o).written(outer)?;
    io::write_points(inner, &i).written(inner)?;
    let shell = Shell::new(&o, &i).map_err(CliError::internal)?;
    let opts = ShellOptions {
        method: Method::Thesis,
        flips: true,
        optimum: false,
    };
    let found = tetrakit::shell::shell(&shell, opts, &tetrakit::control::Control::new())
        .map_err(CliError::internal)?;
    let Some(w) = found.witness.as_ref() else {
        return Err(CliError::internal(
            "the stored counterexample to Lemma 4.1 does not fail it",
        ));
    };
    if as_json {
        let shown = |p: &Path| p.display().to_string().into();
        let extra = [
            ("outer_output", shown(outer)),
            ("inner_output", shown(inner)),
        ];
        out!("{}", tetrakit::report::json(&found, extra));
    } else {
        out!(
            "wrote {} outer points to {} and {} inner points to {}: tip {}\n{}",
            o.len(),
            outer.display(),
            i.len(),
            inner.display(),
            w.tip,
            w.detail
        );
    }
    Ok(Verdict::Yes)
}

fn write_pair(o: &[Point3], outer: &Path, i: &[Point3], inner: &Path, note: &str) -> CmdResult {
    io::write_points(outer, o).written(outer)?;
    io::write_points(inner, i).written(inner)?;
    out!(
        "wrote {} outer points to {} and {} inner points{note} to {}",
        o.len(),
        outer.display(),
        i.len(),
        inner.display()
    );
    Ok(Verdict::Yes)
}
