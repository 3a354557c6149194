//! `reduce`: the constructions of thesis ch. 2 §2.5 (Theorem 2.9's reduction, Lemma
//! 2.6's flips, Algorithm QUASI-PRISM-TETRAHEDRALIZATION).

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use serde_json::{Value, json};
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::exact::{self, Domain, Edges, Outcome};
use tetrakit::io;
use tetrakit::numbering::renumber_text;
use tetrakit::reduce::{QuasiPrism, QuasiPrismError};

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
    let (points, segments, mut v, how) = match construction {
        Construction::Apexes => {
            let r = tetrakit::reduce::trid_to_tetrad(&flat, &inp.segments).map_err(refused)?;
            let v = json!({
                "construction": "apexes",
                "apex_height": r.height,
                "checked": ["no three planar points collinear", "every orientation kept from both apexes", "every lifted point a vertex of the upper hull"],
            });
            let how = format!("lifted to a paraboloid, apexes at height ±{}", r.height);
            (r.points, r.segments, v, how)
        }
        Construction::Sphere => {
            let r = tetrakit::reduce::sphere_reduction(&flat, &inp.segments).map_err(refused)?;
            let v = json!({
                "construction": "sphere",
                "radius": r.radius,
                "twist_radians": r.twist,
                "apex_height": r.height,
                "checked": ["no three planar points collinear", "no four points coplanar", "every prism over a triangle of E a regular quasi-prism", "x* sees the upper points as the plane does", "every hull edge a segment (or a missing planar hull edge lifted)"],
            });
            let how = format!(
                "on a sphere of radius {}, the lower copy twisted by {} rad, x* at height {}",
                r.radius, r.twist, r.height
            );
            (r.points, r.segments, v, how)
        }
    };
    let pairs: Vec<(u32, u32)> = segments.iter().map(|&[a, b]| (a, b)).collect();
    io::write_edges(output, &points, &pairs, inp.index_base).written(output)?;
    for (key, value) in [
        ("verdict", json!("written")),
        ("points", json!(points.len())),
        ("segments", json!(segments.len())),
        ("planar_points", json!(flat.len())),
        ("planar_segments", json!(inp.segments.len())),
        ("output", json!(output.display().to_string())),
        ("seconds", json!(start.elapsed().as_secs_f64())),
    ] {
        v[key] = value;
    }
    if as_json {
        out!("{v}");
    } else {
        out!(
            "wrote {}: {} points, {} segments (the {} planar points {how}); conditions checked exactly",
            output.display(),
            points.len(),
            segments.len(),
            flat.len(),
        );
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
    use tetrakit::reduce::HullGapError;
    let start = Instant::now();
    let (inp, poly) = io::read_polyhedron(input)?;
    let base = inp.index_base;
    let run = Run::new(time_limit, poly.points.len(), 2000);
    run.stage("flipping reflex edges");
    let mut v = json!({ "vertices": poly.points.len(), "faces": poly.faces.len() });
    let verdict = match tetrakit::reduce::hull_gap(&poly, &run.ctl) {
        Ok(tets) => {
            if let Some(out) = output {
                io::write_mesh(out, &poly.points, &tets, base).written(out)?;
            }
            v["verdict"] = json!("yes");
            v["tetrahedra"] = json!(tets.len());
            v["certified"] = json!(true);
            Verdict::Yes
        }
        Err(e @ HullGapError::Stuck([a, b])) => {
            v["verdict"] = json!("no");
            v["witness"] = json!({
                "kind": "stuck",
                "edge": [a + base, b + base],
                "detail": renumber_text(&e.to_string(), base),
            });
            Verdict::No
        }
        Err(HullGapError::Stopped) => {
            v["verdict"] = json!("undecided");
            Verdict::Undecided
        }
        Err(HullGapError::Uncertified(e)) => return Err(CliError::internal(e)),
        Err(e) => return Err(CliError::at(input, renumber_text(&e.to_string(), base))),
    };
    v["seconds"] = json!(start.elapsed().as_secs_f64());
    emit(&v, as_json, |v| match verdict {
        Verdict::Yes => format!(
            "YES: {} tetrahedra fill the gap between the polyhedron ({} vertices) and its convex hull, by reflex-edge flips (Lemma 2.6); certified",
            v["tetrahedra"], v["vertices"]
        ),
        Verdict::No => format!("NO: {}", v["witness"]["detail"].as_str().unwrap_or("")),
        Verdict::Undecided => "UNDECIDED: the time limit stopped the flips".to_string(),
    });
    Ok(verdict)
}

/// One JSON object, or the text `line` makes of it.
fn emit(v: &Value, as_json: bool, line: impl Fn(&Value) -> String) {
    if as_json {
        out!("{v}");
    } else {
        out!("{}", line(v));
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
    let at = |e: &dyn std::fmt::Display| CliError::at(input, renumber_text(&e.to_string(), base));
    if inp.points.len() % 2 == 1 {
        return Err(at(&format!(
            "{} points: a quasi-prism has S₁'s vertices, then as many images",
            inp.points.len()
        )));
    }
    let n = inp.points.len() / 2;
    let q = QuasiPrism::new(
        inp.points[..n].to_vec(),
        inp.points[n..].to_vec(),
        inp.faces.clone(),
    )
    .map_err(|e| at(&e))?;
    let run = Run::new(time_limit, q.points.len(), 40);
    run.stage("staircases");
    let mut v = json!({
        "points": q.points.len(),
        "prisms": q.triangles.len(),
        "regular": true,
    });
    let (verdict, tets) = match q.tetrahedralize(&run.ctl) {
        Ok(s) => {
            v["verdict"] = json!("yes");
            v["route"] = json!(if s.by_order { "order" } else { "orientation" });
            (Verdict::Yes, Some(s.tets))
        }
        Err(e @ (QuasiPrismError::Irregular { .. } | QuasiPrismError::NoStaircase)) => {
            v["regular"] = json!(!matches!(e, QuasiPrismError::Irregular { .. }));
            v["staircase"] = json!(renumber_text(&e.to_string(), base));
            v["route"] = json!("exact");
            run.stage("exact solver");
            by_exact(&q, &run, base, &mut v).map_err(|e| at(&e))?
        }
        Err(QuasiPrismError::Stopped) => {
            v["verdict"] = json!("undecided");
            (Verdict::Undecided, None)
        }
        Err(QuasiPrismError::Uncertified(e)) => return Err(CliError::internal(e)),
        Err(e) => return Err(at(&e)),
    };
    if let Some(tets) = &tets {
        v["tetrahedra"] = json!(tets.len());
        v["certified"] = json!(true);
        if let Some(out) = output {
            io::write_mesh(out, &q.points, tets, base).written(out)?;
        }
    }
    v["seconds"] = json!(start.elapsed().as_secs_f64());
    emit(&v, as_json, quasi_prism_line);
    Ok(verdict)
}

type Tets = Vec<[u32; 4]>;

/// The exact solver on the quasi-prism's boundary with all its edges required.
fn by_exact(
    q: &QuasiPrism,
    run: &Run,
    base: u32,
    v: &mut Value,
) -> Result<(Verdict, Option<Tets>), String> {
    let poly = q.boundary().map_err(|e| e.to_string())?;
    let required = q.edges();
    let edges = Edges {
        allowed: None,
        required: &required,
    };
    let opts = exact::Options {
        any: true,
        ..exact::Options::default()
    };
    let (outcome, stats) = exact::solve(Domain::Polyhedron(&poly), edges, &opts, &run.ctl)
        .map_err(|e| e.to_string())?;
    v["candidates"] = json!(stats.candidates);
    Ok(match outcome {
        Outcome::Optimal { tets, .. } | Outcome::Found { tets } => {
            q.certify(&poly, &tets).map_err(|e| e.to_string())?;
            v["verdict"] = json!("yes");
            (Verdict::Yes, Some(tets))
        }
        Outcome::Infeasible => {
            v["verdict"] = json!("no");
            v["witness"] = crate::poly::exact_witness(&stats, base);
            (Verdict::No, None)
        }
        Outcome::Undecided { .. } => {
            v["verdict"] = json!("undecided");
            (Verdict::Undecided, None)
        }
    })
}

/// The text line of `reduce quasi-prism`.
fn quasi_prism_line(v: &Value) -> String {
    let prisms = &v["prisms"];
    let why = v["staircase"].as_str().unwrap_or("");
    match (v["verdict"].as_str(), v["route"].as_str()) {
        (Some("yes"), Some(route @ ("order" | "orientation"))) => format!(
            "YES: {} tetrahedra, three per prism ({prisms} prism(s)), by {}; certified",
            v["tetrahedra"],
            if route == "order" {
                "one vertex order (Algorithm QUASI-PRISM-TETRAHEDRALIZATION)"
            } else {
                "an orientation of the sides' diagonals with no cyclic prism (SAT)"
            }
        ),
        (Some("yes"), _) => format!(
            "YES: {} tetrahedra from the exact solver ({prisms} prism(s); no staircase: {why}); certified",
            v["tetrahedra"]
        ),
        (Some("no"), _) => format!(
            "NO: no tetrahedralization keeps every edge of the quasi-prism: {} ({why})",
            v["witness"]["detail"].as_str().unwrap_or("")
        ),
        _ => format!("UNDECIDED: the time limit stopped the work {why}"),
    }
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
