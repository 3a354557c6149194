//! `tetrakit shell OUTER INNER`: the region between two nested convex polytopes (thesis
//! ch. 4), tetrahedralized without Steiner points and certified.

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use serde_json::json;
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::geom::Point3;
use tetrakit::io::{self, Input};
use tetrakit::shell::{Improvement, Method, Shell, ShellError, improve, tetrahedralize};

/// What `shell` was asked.
pub struct ShellArgs<'a> {
    pub outer: &'a Path,
    pub inner: &'a Path,
    pub method: Method,
    pub flips: bool,
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
        ShellError::Stopped | ShellError::Internal(_) => CliError::internal(e),
    }
}

pub fn shell(a: ShellArgs) -> CmdResult {
    let start = Instant::now();
    let (outer_in, inner_in) = (points(a.outer)?, points(a.inner)?);
    let shell = Shell::new(&outer_in.points, &inner_in.points)
        .map_err(|e| blame(e, &outer_in, &inner_in))?;
    let run = Run::new(a.time_limit, shell.outer.len(), 20_000);
    let result = tetrahedralize(&shell, a.method, &run.ctl).and_then(|mut mesh| {
        let done = if a.flips {
            improve(&shell.points, &mut mesh, &run.ctl)?
        } else {
            Improvement {
                before: mesh.tets.len(),
                ..Default::default()
            }
        };
        Ok((mesh, done))
    });
    drop(run);
    let (mesh, flips) = match result {
        Ok(m) => m,
        Err(ShellError::Stopped) => return undecided(&shell, a.method, a.as_json, start),
        Err(e) => return Err(blame(e, &outer_in, &inner_in)),
    };
    tetrakit::mesh::certify_shell(&shell.points, &mesh.tets, &shell.inner)
        .map_err(|p| CliError::internal(format!("the shell mesh failed its certificate: {p}")))?;
    if let Some(out) = a.output {
        io::write_mesh(out, &shell.points, &mesh.tets, 0).written(out)?;
    }
    let n = shell.n();
    let seconds = start.elapsed().as_secs_f64();
    let touching = shell.touching.len()
        + shell
            .inner
            .iter()
            .filter(|&&v| (v as usize) < shell.outer.len())
            .count();
    if a.as_json {
        out!(
            "{}",
            json!({
                "verdict": "yes",
                "n": n,
                "outer_vertices": shell.outer.len(),
                "inner_vertices": shell.inner.len(),
                "outer_ignored": shell.outer_ignored.len(),
                "inner_ignored": shell.inner_ignored.len(),
                "inner_on_outer": touching,
                "tetrahedra": mesh.tets.len(),
                "bound": 9 * n - 6,
                "interior_edges": mesh.interior_edges(),
                "steiner_points": 0,
                "pieces": mesh.pieces,
                "method": a.method.name(),
                "tetrahedra_before_flips": flips.before,
                "flips": flips_json(&flips, a.flips),
                "seconds": seconds,
            })
        );
    } else {
        out!(
            "YES: {} tetrahedra for the shell between {} outer and {} inner vertices (n = {n}, bound 9n − 6 = {}, {:.2} per vertex), no Steiner point, certified. [{seconds:.3} s]",
            mesh.tets.len(),
            shell.outer.len(),
            shell.inner.len(),
            9 * n - 6,
            mesh.tets.len() as f64 / n as f64
        );
        if flips.before != mesh.tets.len() {
            out!(
                "  the removals made {}; flips inside the shell took it to {}{}",
                flips.before,
                mesh.tets.len(),
                if flips.delaunay.is_some() {
                    " (Delaunay flips, then 3-2 flips)"
                } else {
                    " (3-2 flips)"
                }
            );
        }
        if shell.outer_ignored.len() + shell.inner_ignored.len() > 0 {
            out!(
                "  not vertices (inside a hull, or on it but not a corner, or repeated): {} outer and {} inner points",
                shell.outer_ignored.len(),
                shell.inner_ignored.len()
            );
        }
    }
    Ok(Verdict::Yes)
}

/// The improvement pass for JSON: `null` when skipped.
fn flips_json(f: &Improvement, ran: bool) -> serde_json::Value {
    if !ran {
        return serde_json::Value::Null;
    }
    json!({
        "three_two": f.three_two,
        "delaunay": f.delaunay.map(|d| json!({"two_three": d.two_three, "three_two": d.three_two})),
    })
}

fn undecided(shell: &Shell, method: Method, as_json: bool, start: Instant) -> CmdResult {
    let seconds = start.elapsed().as_secs_f64();
    if as_json {
        out!(
            "{}",
            json!({"verdict": "undecided", "n": shell.n(), "method": method.name(), "seconds": seconds})
        );
    } else {
        out!("UNDECIDED: stopped at the time limit after {seconds:.3} s");
    }
    Ok(Verdict::Undecided)
}

/// Writes two nested point sets, OUTER and INNER, as `.xyz` / `.node` / `.json`.
pub fn generate_nested(
    p: &tetrakit::shell::generate::NestedParams,
    outer: &Path,
    inner: &Path,
) -> CmdResult {
    let (o, i, radius) = tetrakit::shell::generate::nested(p).map_err(CliError::new)?;
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
    let (o, i) = tetrakit::shell::generate::bern_disk(ridge, ring, seed).map_err(CliError::new)?;
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
    let (o, i) =
        tetrakit::shell::generate::contact(kind, n_outer, n_inner, seed).map_err(CliError::new)?;
    write_pair(&o, outer, &i, inner, "")
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
