//! `reduce`: the constructions of thesis ch. 2 §2.5 (Theorem 2.9's reduction, Lemma
//! 2.6's flips, Algorithm QUASI-PRISM-TETRAHEDRALIZATION).

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::numbering::renumber_text;
use tetrakit::reduce::{HullGapError, QuasiPrism, QuasiPrismError};
use tetrakit::{io, report};

/// Which construction `reduce trid-to-tetrad` builds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Construction {
    /// The lifted points between two apexes (`reduce::trid_to_tetrad`).
    Apexes,
    /// The thesis's sphere and twisted lower copy (`reduce::sphere_reduction`).
    Sphere,
}

/// `reduce trid-to-tetrad IN OUT [--construction]`.
pub fn trid_to_tetrad(
    input: &Path,
    output: &Path,
    construction: Construction,
    as_json: bool,
) -> CmdResult {
    let start = Instant::now();
    let inp = io::read_input(input)?;
    if let Some(k) = inp.points.iter().position(|p| p[2] != 0.0) {
        return Err(CliError::at(
            input,
            format!(
                "point {} has z = {}: TRID is planar (z = 0)",
                k as u32 + inp.index_base,
                inp.points[k][2]
            ),
        ));
    }
    let flat: Vec<[f64; 2]> = inp.points.iter().map(|p| [p[0], p[1]]).collect();
    let refused = |e: tetrakit::reduce::ReduceError| {
        CliError::at(input, renumber_text(&e.to_string(), inp.index_base))
    };
    let (points, segments, facts) = match construction {
        Construction::Apexes => {
            let r = tetrakit::reduce::trid_to_tetrad(&flat, &inp.segments).map_err(refused)?;
            let facts = r.facts();
            (r.points, r.segments, facts)
        }
        Construction::Sphere => {
            let r = tetrakit::reduce::sphere_reduction(&flat, &inp.segments).map_err(refused)?;
            let facts = r.facts();
            (r.points, r.segments, facts)
        }
    };
    io::write_edges(output, &points, &segments, inp.index_base).written(output)?;
    let shown = output.display().to_string();
    if as_json {
        let extra = [
            ("verdict", "written".into()),
            ("planar_points", flat.len().into()),
            ("planar_segments", inp.segments.len().into()),
            ("output", shown.into()),
            ("seconds", start.elapsed().as_secs_f64().into()),
        ];
        out!("{}", report::json(&facts, extra));
    } else {
        out!("{}", report::reduction_text(&facts, flat.len(), &shown));
    }
    Ok(Verdict::Yes)
}

/// `reduce hull-gap POLY`: Lemma 2.6's reflex-edge flips fill `CH(Q) − Q`. A vertex
/// inside the hull is refused (exit 2: the lemma does not apply); flips that all fail
/// their exact checks are a NO naming the first reflex edge (exit 1).
pub fn hull_gap(
    input: &Path,
    output: Option<&Path>,
    as_json: bool,
    time_limit: Option<Duration>,
) -> CmdResult {
    let start = Instant::now();
    let (inp, poly) = io::read_polyhedron(input)?;
    let base = inp.index_base;
    let run = Run::new(time_limit, poly.points.len(), 2000);
    run.stage("flipping reflex edges");
    let o = tetrakit::reduce::solve_hull_gap(&poly, &run.ctl).map_err(|e| match e {
        HullGapError::Uncertified(_) | HullGapError::Internal(_) => CliError::new(e),
        e => refusal(input, e, base),
    })?;
    drop(run);
    if let (Some(out), Verdict::Yes) = (output, o.verdict) {
        io::write_mesh(out, &poly.points, &o.tets, base).written(out)?;
    }
    let o = o.shifted(base);
    let seconds = start.elapsed().as_secs_f64();
    emit(&o, as_json, seconds, report::hull_gap_text(&o));
    Ok(o.verdict)
}

/// An error of the library about `input` (vertices in its numbering).
fn refusal(input: &Path, e: impl std::fmt::Display, base: u32) -> CliError {
    CliError::at(input, renumber_text(&e.to_string(), base))
}

/// The outcome as JSON (with its timing) or as its line.
fn emit<T: tetrakit::report::Serialize>(o: &T, as_json: bool, seconds: f64, line: String) {
    if as_json {
        out!("{}", report::json(o, [("seconds", seconds.into())]));
    } else {
        out!("{line}");
    }
}

/// `reduce quasi-prism FILE`: the points are `S₁`'s then their images, the faces `S₁`'s.
pub fn quasi_prism(
    input: &Path,
    output: Option<&Path>,
    as_json: bool,
    time_limit: Option<Duration>,
) -> CmdResult {
    let start = Instant::now();
    let inp = io::read_input(input)?;
    let base = inp.index_base;
    if inp.points.len() % 2 == 1 {
        let what = format!(
            "{} points: a quasi-prism has S₁'s vertices, then as many images",
            inp.points.len()
        );
        return Err(CliError::at(input, what));
    }
    let n = inp.points.len() / 2;
    let q = QuasiPrism::new(
        inp.points[..n].to_vec(),
        inp.points[n..].to_vec(),
        inp.faces.clone(),
    )
    .map_err(|e| refusal(input, e, base))?;
    let run = Run::new(time_limit, q.points.len(), 40);
    run.stage("staircases, then the exact solver");
    let o = q.solve(&run.ctl).map_err(|e| match e {
        QuasiPrismError::Uncertified(_) | QuasiPrismError::MissingEdge(_) => CliError::new(e),
        e => refusal(input, e, base),
    })?;
    drop(run);
    if let (Some(out), Verdict::Yes) = (output, o.verdict) {
        io::write_mesh(out, &q.points, &o.tets, base).written(out)?;
    }
    let o = o.shifted(base);
    let seconds = start.elapsed().as_secs_f64();
    emit(&o, as_json, seconds, report::quasi_prism_text(&o));
    Ok(o.verdict)
}

/// `generate quasi-prism`.
pub fn generate_quasi_prism(
    ring: usize,
    inner: usize,
    twist: f64,
    seed: u64,
    output: &Path,
) -> CmdResult {
    if !(3..=1_000_000).contains(&ring) || inner > 1_000_000 {
        return Err(CliError::new(
            "--ring must be between 3 and 1000000 and --inner at most 1000000",
        ));
    }
    if twist.is_nan() || twist.abs() >= 90.0 {
        return Err(CliError::new(format!(
            "--twist {twist}: a turn in (-90°, 90°)"
        )));
    }
    let q = QuasiPrism::lens(ring, inner, twist, seed);
    io::write_surface(output, &q.points, &q.triangles, 1).written(output)?;
    out!(
        "wrote {}: {} points (the upper {} first, then their images), {} triangles",
        output.display(),
        q.points.len(),
        q.n(),
        q.triangles.len()
    );
    Ok(Verdict::Yes)
}
