//! Chapter 5 commands: `skeleton`, `mwt`, `keil`, and `generate points2d`.

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use serde_json::json;
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::control::Control;
use tetrakit::geom::{Point2, Ratio};
use tetrakit::io;
use tetrakit::planar::{self, Distribution, MwtBounds, MwtOutcome, Region};

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
        None,
        points.len(),
        if below_one { 5_000 } else { usize::MAX },
    );
    run.stage("β-skeleton sites");
    let sk = planar::beta_skeleton(&points, beta, region, &run.ctl).map_err(CliError::new)?;
    drop(run);
    let algorithm = t.elapsed().as_secs_f64();
    if let Some(out) = output {
        io::write_planar_edges(out, &points, &sk.edges).written(out)?;
    }
    let region_name = if lune { "lune" } else { "circle" };
    if as_json {
        out!(
            "{}",
            json!({
                "beta": beta.to_string(),
                "region": region_name,
                "vertices": points.len(),
                "edges": sk.edges.len(),
                "candidates": sk.candidates,
                "cell_diameters": sk.cell_diameters,
                "seconds": start.elapsed().as_secs_f64(),
                "seconds_parse": parsed,
                "seconds_algorithm": algorithm,
            })
        );
    } else {
        out!(
            "{region_name}-based β-skeleton, β = {beta}: {} edges on {} sites ({} candidates tested exactly) in {:.3} s",
            sk.edges.len(),
            points.len(),
            sk.candidates,
            algorithm
        );
    }
    Ok(Verdict::Yes)
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
    let m = match planar::mwt_or_bounds(&points, &run.ctl).map_err(CliError::new)? {
        MwtOutcome::Solved(m) => m,
        MwtOutcome::Stopped(b) => {
            drop(run);
            return undecided(&a, &points, &z, &b, start);
        }
    };
    drop(run);
    let (as_json, output) = (a.as_json, a.output);
    let algorithm = t.elapsed().as_secs_f64();
    if let Some(out) = output {
        io::write_planar_triangulation(out, &points, &z, &m.edges, &m.triangles).written(out)?;
    }
    let s = &m.stats;
    if as_json {
        out!(
            "{}",
            json!({
                "verdict": "yes",
                "vertices": points.len(),
                "edges": m.edges.len(),
                "triangles": m.triangles.len(),
                "weight": m.weight.mid(),
                "weight_interval": [m.weight.lo, m.weight.hi],
                "candidates": s.candidates,
                "skeleton_edges": s.skeleton_edges,
                "undecided_edges": s.undecided_edges,
                "faces_left": s.faces_left,
                "faces_with_holes": s.faces_with_holes,
                "largest_face": s.largest_face,
                "seconds": start.elapsed().as_secs_f64(),
                "seconds_parse": parsed,
                "seconds_stages": { "diamond": s.seconds[0], "lmt": s.seconds[1], "exact": s.seconds[2] },
                "seconds_algorithm": algorithm,
            })
        );
    } else {
        let fixed = 100.0 * s.skeleton_edges as f64 / m.edges.len().max(1) as f64;
        out!(
            "minimum weight triangulation of {} sites: {} edges, {} triangles, weight {:.12} (certified in [{:.17e}, {:.17e}])",
            points.len(),
            m.edges.len(),
            m.triangles.len(),
            m.weight.mid(),
            m.weight.lo,
            m.weight.hi
        );
        out!(
            "  {} candidates after the diamond test; LMT-skeleton fixed {} edges ({fixed:.1}%); {} faces left to the exact stage ({} with holes, largest {}); {:.3} s",
            s.candidates,
            s.skeleton_edges,
            s.faces_left,
            s.faces_with_holes,
            s.largest_face,
            algorithm
        );
    }
    Ok(Verdict::Yes)
}

/// Out of time: exit 3 with certified bounds on the minimum weight (the better of the
/// minimum spanning tree's and the solver's, and a triangulation's: Delaunay, flipped
/// shorter), writing that triangulation.
fn undecided(
    a: &MwtArgs,
    points: &[Point2],
    z: &[f64],
    b: &MwtBounds,
    start: Instant,
) -> CmdResult {
    if let Some(out) = a.output {
        io::write_planar_triangulation(out, points, z, &b.edges, &b.triangles).written(out)?;
    }
    let limit = a.time_limit.unwrap_or_default().as_secs_f64();
    if a.as_json {
        out!(
            "{}",
            json!({
                "verdict": "undecided",
                "vertices": points.len(),
                "time_limit": limit,
                "lower_bound": b.lower.lo,
                "lower_bound_from": b.lower_source.to_string(),
                "upper_bound": b.upper.hi,
                "edges": b.edges.len(),
                "triangles": b.triangles.len(),
                "seconds": start.elapsed().as_secs_f64(),
            })
        );
    } else {
        out!(
            "undecided within the time limit ({limit} s): the minimum weight of a triangulation of {} sites is between {:.17e} ({}) and {:.17e} (Delaunay triangulation flipped shorter{})",
            points.len(),
            b.lower.lo,
            b.lower_source,
            b.upper.hi,
            if a.output.is_some() { ", written" } else { "" }
        );
    }
    Ok(Verdict::Undecided)
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
    let k = planar::keil(beta, a.n, &Control::new()).map_err(CliError::new)?;
    if let Some(path) = a.svg {
        std::fs::write(path, io::keil_svg(&k)).written(path)?;
    }
    if let Some(path) = a.output {
        io::write_points2d(path, &k.sites).written(path)?;
    }
    let iv = |w: &tetrakit::geom::Interval| [w.lo, w.hi];
    let refuted = k.xy_in_skeleton && !k.xy_in_mwt;
    if a.as_json {
        out!(
            "{}",
            json!({
                "beta": beta.to_string(),
                "n": k.n,
                "sites": k.sites.len(),
                "xy": k.xy,
                "output": a.output.map(|p| p.display().to_string()),
                "lemma_5_8_bound": k.lemma_bound,
                "xy_in_skeleton": k.xy_in_skeleton,
                "xy_in_mwt": k.xy_in_mwt,
                "refutes_keil": refuted,
                "weight_with_xy": k.with_xy.0.mid(),
                "weight_with_xy_interval": iv(&k.with_xy.0),
                "weight_without_xy": k.without_xy.0.mid(),
                "weight_without_xy_interval": iv(&k.without_xy.0),
                "with_minus_without_sign": k.with_vs_without as i8,
                "method": method(&k),
                "svg": a.svg.map(|p| p.display().to_string()),
                "seconds": start.elapsed().as_secs_f64(),
            })
        );
    } else {
        out!(
            "Keil construction (thesis §5.2), β = {beta}, n = {} ({} sites; Lemma 5.8 asks n > {:.1}):",
            k.n,
            k.sites.len(),
            k.lemma_bound
        );
        out!("  method: {}", method(&k));
        out!("  xy in the β-skeleton: {} (exact)", k.xy_in_skeleton);
        out!(
            "  xy in the minimum weight triangulation: {} (exact)",
            k.xy_in_mwt
        );
        out!("  best triangulation with xy:    {:.15}", k.with_xy.0.mid());
        out!(
            "  best triangulation without xy: {:.15}",
            k.without_xy.0.mid()
        );
        out!(
            "  verdict: {}",
            if refuted {
                "xy is a β-skeleton edge in no MWT: Keil's conjecture fails here".to_string()
            } else {
                format!(
                    "this realization does not separate xy yet at n = {}; try a larger --n (Lemma 5.8: n > {:.1} suffices)",
                    k.n, k.lemma_bound
                )
            }
        );
        if let Some(p) = a.svg {
            out!("  picture: {}", p.display());
        }
    }
    Ok(Verdict::Yes)
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
    if as_json {
        let v: Vec<_> = bad
            .iter()
            .map(|(k, s, e)| json!({"set": k, "seed": s, "edge": e}))
            .collect();
        let mut v = json!({
            "verdict": if bad.is_empty() { "yes" } else { "no" },
            "beta": beta.to_string(),
            "sets": sets,
            "points": n,
            "skeleton_edges_checked": checked,
            "violations": v,
            "seconds": start.elapsed().as_secs_f64(),
        });
        if let Some((k, s, e)) = bad.first() {
            v["witness"] = json!({
                "kind": "skeleton_edge_not_in_mwt",
                "detail": format!("edge {}-{} of the β-skeleton of random set {k} (seed {s}) is in no minimum weight triangulation", e[0], e[1]),
                "set": k,
                "seed": s,
                "segments": [e],
            });
        }
        out!("{v}");
    } else {
        out!(
            "β = {beta}: {checked} skeleton edges of {sets} random sets of {n} points checked against the exact MWT; {} violations",
            bad.len()
        );
        for (k, s, e) in &bad {
            out!("  violation: set {k} (seed {s}), edge {}-{}", e[0], e[1]);
        }
    }
    Ok(Verdict::from(bad.is_empty()))
}

/// How the two optima were found.
fn method(k: &planar::KeilResult) -> &'static str {
    if k.split {
        "split along L (Lemma 5.6: every side of L certified to be in every triangulation), exact polygon DP"
    } else {
        "general exact MWT solver"
    }
}
