//! Chapter 5 commands: `skeleton`, `mwt`, `keil`, and `generate points2d`.

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::geom::{Point2, Ratio};
use tetrakit::planar::{self, Distribution, KeilOutcome, MwtOutcome, Region};
use tetrakit::{io, report};

/// Reads planar points and their heights. Without `xy` every z must be 0; with it the
/// points are projected to the xy-plane and their z kept.
pub fn read_points(path: &Path, xy: bool) -> Result<(Vec<Point2>, Vec<f64>), CliError> {
    let input = io::read_input(path)?;
    if !xy && let Some(i) = input.points.iter().position(|p| p[2] != 0.0) {
        let line = input.point_lines.get(i).copied().unwrap_or(0);
        return Err(CliError::new(format!(
            "{}:{line}: point {} has z = {}; planar commands need 2D points (--xy uses their projection)",
            input.point_file.display(),
            i as u32 + input.index_base,
            input.points[i][2]
        )));
    }
    let plane: Vec<Point2> = input.points.iter().map(|p| [p[0], p[1]]).collect();
    // Coinciding points are refused on reading; projected ones only here.
    if let Some([a, b]) = xy.then(|| planar::coincident_sites(&plane)).flatten() {
        let line = |i: u32| input.point_lines.get(i as usize).copied().unwrap_or(0);
        return Err(CliError::new(format!(
            "{}:{}: points {} and {} coincide in the xy-plane at {:?} (line {})",
            input.point_file.display(),
            line(b),
            a + input.index_base,
            b + input.index_base,
            plane[a as usize],
            line(a)
        )));
    }
    Ok((plane, input.points.iter().map(|p| p[2]).collect()))
}

pub fn parse_beta(text: &str) -> Result<Ratio, CliError> {
    text.parse::<Ratio>()
        .map_err(|e| CliError::new(format!("--beta: {e}")))
}

pub fn skeleton(
    path: &Path,
    xy: bool,
    beta: &str,
    lune: bool,
    as_json: bool,
    output: Option<&Path>,
    time_limit: Option<Duration>,
) -> CmdResult {
    let start = Instant::now();
    let beta = parse_beta(beta)?;
    let (points, _) = read_points(path, xy)?;
    let parsed = start.elapsed().as_secs_f64();
    let region = if lune { Region::Lune } else { Region::Circle };
    let t = Instant::now();
    // Below β = 1 each site's search may reach far: a bar from a few thousand sites.
    let below_one = beta.cmp_one() == std::cmp::Ordering::Less;
    let run = Run::new(
        time_limit,
        points.len(),
        if below_one { 5_000 } else { usize::MAX },
    );
    run.stage("β-skeleton sites");
    let sk = planar::beta_skeleton(&points, beta, region, &run.ctl).map_err(CliError::new)?;
    drop(run);
    let algorithm = t.elapsed().as_secs_f64();
    if let Some(out) = output.filter(|_| sk.complete) {
        io::write_planar_edges(out, &points, &sk.edges).written(out)?;
    }
    let n = points.len();
    if as_json {
        let extra = [
            ("seconds", start.elapsed().as_secs_f64().into()),
            ("parse_seconds", parsed.into()),
            ("algorithm_seconds", algorithm.into()),
        ];
        out!("{}", report::skeleton_json(&sk, beta, region, n, extra));
    } else {
        out!("{}", report::skeleton_text(&sk, beta, region, n, algorithm));
    }
    Ok(match sk.complete {
        true => Verdict::Yes,
        false => Verdict::Undecided,
    })
}

/// What `tetrakit mwt` was asked.
pub struct MwtArgs<'a> {
    pub input: &'a Path,
    pub xy: bool,
    pub as_json: bool,
    pub output: Option<&'a Path>,
    pub time_limit: Option<Duration>,
}

pub fn mwt(a: MwtArgs) -> CmdResult {
    let start = Instant::now();
    let (points, z) = read_points(a.input, a.xy)?;
    let parsed = start.elapsed().as_secs_f64();
    let t = Instant::now();
    let run = Run::new(a.time_limit, points.len(), 50_000);
    let m = planar::mwt_or_bounds(&points, &run.ctl).map_err(CliError::new)?;
    drop(run);
    let algorithm = t.elapsed().as_secs_f64();
    let (edges, triangles, verdict) = match &m {
        MwtOutcome::Solved(m) => (&m.edges, &m.triangles, Verdict::Yes),
        MwtOutcome::Stopped(b) => (&b.edges, &b.triangles, Verdict::Undecided),
    };
    if let Some(out) = a.output {
        io::write_planar_triangulation(out, &points, &z, edges, triangles).written(out)?;
    }
    let n = points.len();
    if a.as_json {
        let limit = a.time_limit.map(|l| l.as_secs_f64());
        let extra = [
            ("seconds", start.elapsed().as_secs_f64().into()),
            ("parse_seconds", parsed.into()),
            ("algorithm_seconds", algorithm.into()),
            ("time_limit", limit.into()),
        ];
        out!("{}", report::mwt_json(&m, n, extra));
    } else {
        let written = a.output.is_some();
        out!("{}", report::mwt_text(&m, n, algorithm, written));
    }
    Ok(verdict)
}

pub fn generate_points(dist: Distribution, n: usize, seed: u64, output: &Path) -> CmdResult {
    if !(1..=50_000_000).contains(&n) {
        return Err(CliError::new("--n must be between 1 and 50000000"));
    }
    let pts = planar::points2d(dist, n, seed);
    io::write_points2d(output, &pts).written(output)?;
    out!(
        "wrote {} {dist:?} points to {}",
        pts.len(),
        output.display()
    );
    Ok(Verdict::Yes)
}

pub struct KeilArgs<'a> {
    pub beta: &'a str,
    pub n: Option<usize>,
    pub as_json: bool,
    pub svg: Option<&'a Path>,
    pub output: Option<&'a Path>,
    pub check_random: Option<usize>,
    pub time_limit: Option<Duration>,
}

pub fn keil(a: KeilArgs) -> CmdResult {
    let start = Instant::now();
    let beta = parse_beta(a.beta)?;
    if a.n == Some(0) {
        return Err(CliError::new(
            "--n 0: at least one site per arc (or one point per random set)",
        ));
    }
    if let Some(sets) = a.check_random {
        return check_random(beta, sets, a.n.unwrap_or(200), a.as_json, start);
    }
    let run = Run::new(a.time_limit, 0, 1);
    let outcome = planar::keil(beta, a.n, &run.ctl).map_err(CliError::new)?;
    drop(run);
    let sites = &outcome.construction().sites;
    let verdict = match &outcome {
        KeilOutcome::Decided(_) => Verdict::Yes,
        KeilOutcome::Undecided(_) => Verdict::Undecided,
    };
    if let (Some(path), KeilOutcome::Decided(k)) = (a.svg, &outcome) {
        std::fs::write(path, tetrakit::report::keil_svg(k)).written(path)?;
    }
    if let Some(path) = a.output {
        io::write_points2d(path, sites).written(path)?;
    }
    if a.as_json {
        let shown = |p: Option<&Path>| p.map(|p| p.display().to_string());
        let extra = [
            ("output", shown(a.output).into()),
            (
                "svg",
                shown(a.svg.filter(|_| verdict == Verdict::Yes)).into(),
            ),
            ("seconds", start.elapsed().as_secs_f64().into()),
        ];
        out!("{}", report::keil_json(&outcome, extra));
    } else {
        out!("{}", report::keil_text(&outcome));
        if let Some(p) = a.svg.filter(|_| verdict == Verdict::Yes) {
            out!("  picture: {}", p.display());
        }
    }
    Ok(verdict)
}

fn check_random(beta: Ratio, sets: usize, n: usize, as_json: bool, start: Instant) -> CmdResult {
    if !planar::above_cheng_xu(beta) {
        return Err(CliError::new(format!(
            "--check-random needs β above the Cheng–Xu bound √(2√3+9)/3 ≈ 1.176823 (got {beta})"
        )));
    }
    let run = Run::new(None, sets, 20);
    run.stage("random sets");
    let (checked, bad) = planar::check_random(beta, sets, n, 1, &run.ctl).map_err(CliError::new)?;
    drop(run);
    let size = [sets, n, checked];
    if as_json {
        let extra = [("seconds", start.elapsed().as_secs_f64().into())];
        out!("{}", report::check_random_json(beta, size, &bad, extra));
    } else {
        out!("{}", report::check_random_text(beta, size, &bad));
    }
    Ok(Verdict::from(bad.is_empty()))
}
