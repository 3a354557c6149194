//! Chapter 5 commands: `skeleton`, `mwt`, `keil`, and `generate points2d`.

use crate::run::fail;
use indicatif::ProgressBar;
use serde_json::json;
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::{Duration, Instant};
use tetrakit::geom::{Point2, Ratio};
use tetrakit::io;
use tetrakit::planar::{self, Distribution, MwtOptions, Region};

/// Reads planar points and their heights. Without `xy` every z must be 0; with it the
/// points are projected to the xy-plane and their z kept.
pub fn read_points(path: &Path, xy: bool) -> Result<(Vec<Point2>, Vec<f64>), u8> {
    let input = io::read_input(path).map_err(fail)?;
    if !xy && let Some(i) = input.points.iter().position(|p| p[2] != 0.0) {
        let line = input.point_lines.get(i).copied().unwrap_or(0);
        return Err(fail(format!(
            "{}:{line}: point {} has z = {}; planar commands need 2D points (--xy uses their projection)",
            path.display(),
            i as u32 + input.index_base,
            input.points[i][2]
        )));
    }
    let plane: Vec<Point2> = input.points.iter().map(|p| [p[0], p[1]]).collect();
    // Coinciding points are refused on reading; projected ones only here.
    if let Some([a, b]) = xy.then(|| planar::coincident_sites(&plane)).flatten() {
        let line = |i: u32| input.point_lines.get(i as usize).copied().unwrap_or(0);
        return Err(fail(format!(
            "{}:{}: points {} and {} coincide in the xy-plane at {:?} (line {})",
            path.display(),
            line(b),
            a + input.index_base,
            b + input.index_base,
            plane[a as usize],
            line(a)
        )));
    }
    Ok((plane, input.points.iter().map(|p| p[2]).collect()))
}

pub fn parse_beta(text: &str) -> Result<Ratio, u8> {
    text.parse::<Ratio>()
        .map_err(|e| fail(format!("--beta: {e}")))
}

pub fn skeleton(
    path: &Path,
    xy: bool,
    beta: &str,
    lune: bool,
    as_json: bool,
    output: Option<&Path>,
) -> u8 {
    let start = Instant::now();
    let beta = match parse_beta(beta) {
        Ok(b) => b,
        Err(c) => return c,
    };
    let points = match read_points(path, xy) {
        Ok((p, _)) => p,
        Err(c) => return c,
    };
    let parsed = start.elapsed().as_secs_f64();
    let region = if lune { Region::Lune } else { Region::Circle };
    let t = Instant::now();
    // Below β = 1 each site's search may reach far: a bar from a few thousand sites.
    let bar = (beta.cmp_one() == std::cmp::Ordering::Less)
        .then(|| crate::run::progress_bar(points.len() as u64, 5_000, "β-skeleton sites"))
        .flatten();
    let report = |done: u64, _all: u64| {
        if let Some(b) = &bar {
            b.set_position(done);
        }
    };
    let sk = planar::beta_skeleton_with_progress(&points, beta, region, &report);
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let sk = match sk {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    let algorithm = t.elapsed().as_secs_f64();
    if let Some(out) = output
        && let Err(e) = io::write_planar_edges(out, &points, &sk.edges)
    {
        return fail(format!("{}: {e}", out.display()));
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
    0
}

/// What `tetrakit mwt` was asked.
pub struct MwtArgs<'a> {
    pub input: &'a Path,
    pub xy: bool,
    pub as_json: bool,
    pub output: Option<&'a Path>,
    pub time_limit: Option<Duration>,
}

pub fn mwt(a: MwtArgs) -> u8 {
    let start = Instant::now();
    let (points, z) = match read_points(a.input, a.xy) {
        Ok(pz) => pz,
        Err(c) => return c,
    };
    let parsed = start.elapsed().as_secs_f64();
    let t = Instant::now();
    let spinner = crate::run::stage_spinner(points.len());
    let m = match a.time_limit {
        None => planar::mwt_with_progress(&points, &MwtOptions::default(), &stage(&spinner)),
        Some(limit) => match solve_within(&points, limit, spinner.clone()) {
            Some(m) => m,
            None => {
                if let Some(b) = &spinner {
                    b.set_message("mwt: out of time, bounds");
                }
                let code = undecided(&a, &points, &z, start);
                if let Some(b) = spinner {
                    b.finish_and_clear();
                }
                return code;
            }
        },
    };
    if let Some(b) = spinner {
        b.finish_and_clear();
    }
    let (as_json, output) = (a.as_json, a.output);
    let m = match m {
        Ok(m) => m,
        Err(e) => return fail(e),
    };
    let algorithm = t.elapsed().as_secs_f64();
    if let Some(out) = output
        && let Err(e) = io::write_planar_triangulation(out, &points, &z, &m.edges, &m.triangles)
    {
        return fail(format!("{}: {e}", out.display()));
    }
    let s = &m.stats;
    if as_json {
        out!(
            "{}",
            json!({
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
    0
}

/// Names the solver's stage on the spinner.
fn stage(spinner: &Option<ProgressBar>) -> impl Fn(planar::MwtStage) + '_ {
    move |s| {
        if let Some(b) = spinner {
            b.set_message(format!("mwt: {s}"));
        }
    }
}

/// The exact solver on a thread of its own; `None` when it has not answered within
/// `limit`. It is then told to stop, and winds down at its next check (between sites,
/// edges or faces) while the caller computes bounds.
fn solve_within(
    points: &[Point2],
    limit: Duration,
    spinner: Option<ProgressBar>,
) -> Option<Result<planar::Mwt, planar::PlanarError>> {
    let (tx, rx) = mpsc::channel();
    let stop = Arc::new(AtomicBool::new(false));
    let (points, told) = (points.to_vec(), Arc::clone(&stop));
    std::thread::spawn(move || {
        let opts = MwtOptions::default();
        let m = planar::mwt_with_stop(&points, &opts, &stage(&spinner), &told);
        // The receiver is gone once the time is up; nothing waits for this answer then.
        let _ = tx.send(m);
    });
    match rx.recv_timeout(limit) {
        Ok(m) => Some(m),
        Err(RecvTimeoutError::Timeout) => {
            stop.store(true, Ordering::Relaxed);
            None
        }
        Err(RecvTimeoutError::Disconnected) => Some(Err(planar::PlanarError::new(
            "internal error, please report: the solver stopped without an answer",
        ))),
    }
}

/// Out of time: exit 3 with certified bounds on the minimum weight (the minimum
/// spanning tree's and a triangulation's: Delaunay, flipped shorter), writing that
/// triangulation.
fn undecided(a: &MwtArgs, points: &[Point2], z: &[f64], start: Instant) -> u8 {
    let b = match planar::mwt_bounds(points) {
        Ok(b) => b,
        Err(e) => return fail(e),
    };
    if let Some(out) = a.output
        && let Err(e) = io::write_planar_triangulation(out, points, z, &b.edges, &b.triangles)
    {
        return fail(format!("{}: {e}", out.display()));
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
                "upper_bound": b.upper.hi,
                "edges": b.edges.len(),
                "triangles": b.triangles.len(),
                "seconds": start.elapsed().as_secs_f64(),
            })
        );
    } else {
        out!(
            "undecided within the time limit ({limit} s): the minimum weight of a triangulation of {} sites is between {:.17e} (minimum spanning tree) and {:.17e} (Delaunay triangulation flipped shorter{})",
            points.len(),
            b.lower.lo,
            b.upper.hi,
            if a.output.is_some() { ", written" } else { "" }
        );
    }
    3
}

pub fn generate_points(dist: Distribution, n: usize, seed: u64, output: &Path) -> u8 {
    if !(1..=50_000_000).contains(&n) {
        return fail("--n must be between 1 and 50000000");
    }
    let pts = planar::points2d(dist, n, seed);
    if let Err(e) = io::write_points2d(output, &pts) {
        return fail(format!("{}: {e}", output.display()));
    }
    out!(
        "wrote {} {dist:?} points to {}",
        pts.len(),
        output.display()
    );
    0
}

pub struct KeilArgs<'a> {
    pub beta: &'a str,
    pub n: Option<usize>,
    pub as_json: bool,
    pub svg: Option<&'a Path>,
    pub check_random: Option<usize>,
}

pub fn keil(a: KeilArgs) -> u8 {
    let start = Instant::now();
    let beta = match parse_beta(a.beta) {
        Ok(b) => b,
        Err(c) => return c,
    };
    if let Some(sets) = a.check_random {
        return check_random(beta, sets, a.n.unwrap_or(200), a.as_json, start);
    }
    let k = match planar::keil(beta, a.n) {
        Ok(k) => k,
        Err(e) => return fail(e),
    };
    if let Some(path) = a.svg
        && let Err(e) = std::fs::write(path, keil_svg(&k))
    {
        return fail(format!("{}: {e}", path.display()));
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
    0
}

fn check_random(beta: Ratio, sets: usize, n: usize, as_json: bool, start: Instant) -> u8 {
    if !planar::above_cheng_xu(beta) {
        return fail(format!(
            "--check-random needs β above the Cheng–Xu bound √(2√3+9)/3 ≈ 1.176823 (got {beta})"
        ));
    }
    let (checked, bad) = match planar::check_random(beta, sets, n, 1) {
        Ok(x) => x,
        Err(e) => return fail(e),
    };
    if as_json {
        let v: Vec<_> = bad
            .iter()
            .map(|(k, s, e)| json!({"set": k, "seed": s, "edge": e}))
            .collect();
        out!(
            "{}",
            json!({"beta": beta.to_string(), "sets": sets, "points": n, "skeleton_edges_checked": checked, "violations": v, "seconds": start.elapsed().as_secs_f64()})
        );
    } else {
        out!(
            "β = {beta}: {checked} skeleton edges of {sets} random sets of {n} points checked against the exact MWT; {} violations",
            bad.len()
        );
        for (k, s, e) in &bad {
            out!("  violation: set {k} (seed {s}), edge {}-{}", e[0], e[1]);
        }
    }
    if bad.is_empty() { 0 } else { 1 }
}

/// How the two optima were found.
fn method(k: &planar::KeilResult) -> &'static str {
    if k.split {
        "split along L (Lemma 5.6: every side of L certified to be in every triangulation), exact polygon DP"
    } else {
        "general exact MWT solver"
    }
}

/// The picture: sites, the β-disks through x and y, the MWT, and xy.
pub(crate) fn keil_svg(k: &planar::KeilResult) -> String {
    let (x, y) = (k.sites[k.xy[0] as usize], k.sites[k.xy[1] as usize]);
    let mut view = k.sites.clone();
    let b = k.beta.to_f64();
    let h = (b * b - 1.0).sqrt();
    view.extend([[-b, h + b], [b, -h - b]]);
    let mut svg = io::Svg::new(&view);
    for c in [[0.0, h], [0.0, -h]] {
        svg.circle(&c, b, "disk");
    }
    for e in &k.mwt {
        svg.line(&k.sites[e[0] as usize], &k.sites[e[1] as usize], "mwt");
    }
    svg.line(&x, &y, "xy");
    for p in &k.sites {
        svg.site(p);
    }
    svg.label(&x, "x");
    svg.label(&y, "y");
    svg.finish(&format!(
        "β = {}: xy (dashed red) {} the β-skeleton, {} the MWT (blue); disks: the β-region of xy",
        k.beta,
        if k.xy_in_skeleton { "in" } else { "not in" },
        if k.xy_in_mwt { "in" } else { "not in" }
    ))
}
