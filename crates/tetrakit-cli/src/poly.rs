//! Chapter 3 commands: `mintetra`, `tetrahedralize`, and the polyhedron generators.

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use serde_json::{Value, json};
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::control::Control;
use tetrakit::exact::{self, Domain, Options, Outcome};
use tetrakit::io;
use tetrakit::mesh::Polyhedron;
use tetrakit::polyhedra::{self, Checks, generate, hard};

fn shift<const N: usize>(v: &[[u32; N]], base: u32) -> Vec<[u32; N]> {
    v.iter().map(|x| x.map(|i| i + base)).collect()
}

pub fn mintetra(path: &Path, as_json: bool, output: Option<&Path>, confirm: bool) -> CmdResult {
    let start = Instant::now();
    let (input, poly) = io::read_polyhedron(path)?;
    let parsed = start.elapsed().as_secs_f64();
    let (m, secs) = polyhedra::mintetra_certified(&poly).map_err(|e| {
        CliError::internal(format!("MINTETRA's tetrahedra fail the certificate: {e}"))
    })?;
    let base = input.index_base;
    let n = poly.points.len();
    let mut v = json!({
        "verdict": if m.yes { "yes" } else { "no" },
        "vertices": n,
        "faces": poly.faces.len(),
        "lower_bound": n.saturating_sub(3),
        "levels": m.levels,
        "trims_per_level": m.trims_per_level,
        "polar_edges": shift(&m.polar_edges, base),
        "mintetra_seconds": secs.trimming,
        "parse_seconds": parsed,
    });
    if m.yes {
        v["verify_seconds"] = json!(secs.certificate);
        v["certified"] = json!(true);
        v["tetrahedra"] = json!(m.tets.len());
        v["tets"] = json!(shift(&m.tets, base));
        let mut status = polyhedra::minimality(&poly, &m);
        if confirm {
            match confirm_with_solver(&poly, m.tets.len()) {
                Ok(Some((true, unique))) => {
                    status = "confirmed";
                    v["unique"] = json!(unique);
                }
                Ok(Some((false, _))) => status = "refuted",
                Ok(None) => v["confirm"] = json!("time limit"),
                Err(e) => v["confirm"] = json!(e),
            }
        }
        v["minimality"] = json!(status);
        v["conjectured_minimal"] = json!(status == "conjectured");
        if let Some(out) = output {
            io::write_mesh(out, &poly.points, &m.tets, base).written(out)?;
        }
    } else {
        v["reason"] = json!(m.reason);
        v["remaining_faces"] = json!(shift(&m.remaining, base));
        let mut left: Vec<u32> = m.remaining.iter().flatten().copied().collect();
        left.sort_unstable();
        left.dedup();
        v["remaining_vertices"] = json!(left.len());
        v["witness"] = json!({
            "kind": "not_augmented_bp_polyhedron",
            "detail": m.reason,
            "remaining_faces": shift(&m.remaining, base),
        });
    }
    v["seconds"] = json!(start.elapsed().as_secs_f64());
    if as_json {
        out!("{v}");
    } else {
        print_mintetra(&v, m.yes);
    }
    Ok(Verdict::from_bool(m.yes))
}

/// Runs the exact solver: `(mintetra count is minimum, unique)`, `None` on time-out.
fn confirm_with_solver(
    poly: &Polyhedron,
    count: usize,
) -> Result<Option<(bool, Option<bool>)>, String> {
    let opts = Options {
        unique: true,
        any: false,
    };
    let ctl = Control::new().with_time_limit(Duration::from_secs(60));
    match exact::minimal_tetrahedralization(Domain::Polyhedron(poly), &opts, &ctl) {
        Ok((Outcome::Optimal { tets, unique, .. }, _)) => Ok(Some((tets.len() == count, unique))),
        Ok((Outcome::Undecided { .. }, _)) => Ok(None),
        Ok((other, _)) => Err(format!("solver answered {other:?}")),
        Err(e) => Err(e.to_string()),
    }
}

fn print_mintetra(v: &Value, yes: bool) {
    if yes {
        match v["levels"].as_u64() {
            Some(0) => out!("MINTETRA: YES: a stacked polyhedron (no diagonal needed)"),
            Some(h) => out!("MINTETRA: YES: an augmented BP-polyhedron with {h} level(s)"),
            None => {}
        }
        out!(
            "  {} vertices, {} tetrahedra (lower bound n - 3 = {}), {} polar edge(s): {}",
            v["vertices"],
            v["tetrahedra"],
            v["lower_bound"],
            v["polar_edges"].as_array().map_or(0, |a| a.len()),
            v["polar_edges"]
        );
        let why = match v["minimality"].as_str() {
            Some("proven") => {
                "proven (Theorem 3.5 / Corollary 3.6: its proper BP-nets are disjoint)"
            }
            Some("confirmed") => "confirmed by the exact solver",
            Some("refuted") => "REFUTED by the exact solver (please report this polyhedron)",
            _ => "conjectured (§3.5; run with --confirm to check with the exact solver)",
        };
        out!("  minimality: {why}");
        out!("  certified: orientation, face pairing, no overlap, boundary = the facets");
    } else {
        out!("MINTETRA: NO: not an augmented BP-polyhedron");
        out!("  {}", v["reason"].as_str().unwrap_or(""));
        out!(
            "  left: {} vertices, {} facets (see --json for them)",
            v["remaining_vertices"],
            v["remaining_faces"].as_array().map_or(0, |a| a.len())
        );
    }
    out!("  time: {:.3} s", v["seconds"].as_f64().unwrap_or(0.0));
}

pub struct TetraArgs<'a> {
    pub input: &'a Path,
    pub minimal: bool,
    pub unique: bool,
    pub time_limit: Option<Duration>,
    pub as_json: bool,
    pub output: Option<&'a Path>,
    pub proof: Option<&'a Path>,
}

pub fn tetrahedralize(a: TetraArgs) -> CmdResult {
    let start = Instant::now();
    let mut input = io::read_input(a.input)?;
    // The named file decides the domain: a TetGen point file means its points' convex
    // hull even with a .face file beside it (name the .face for the polyhedron).
    let named_node = (a.input.extension().and_then(|e| e.to_str()))
        .is_some_and(|e| e.eq_ignore_ascii_case("node"));
    let faces_beside = named_node && !input.faces.is_empty();
    if named_node {
        input.faces.clear();
    }
    let poly;
    let domain = if input.faces.is_empty() {
        Domain::Points(&input.points)
    } else {
        poly = Polyhedron::new(input.points.clone(), input.faces.clone()).map_err(|e| {
            let why = e.describe(input.index_base);
            CliError::at(a.input, format!("not a simple polyhedron: {why}"))
        })?;
        Domain::Polyhedron(&poly)
    };
    let opts = Options {
        unique: a.unique,
        any: !a.minimal,
    };
    let mut ctl = Control::new();
    if let Some(limit) = a.time_limit {
        ctl = ctl.with_time_limit(limit);
    }
    let (outcome, stats) = exact::minimal_tetrahedralization(domain, &opts, &ctl)
        .map_err(|e| CliError::at(a.input, e))?;
    let n = input.points.len();
    let mut v = json!({
        "vertices": n,
        "domain": if input.faces.is_empty() { "convex hull" } else { "polyhedron" },
        "faces_beside_not_read": faces_beside,
        "candidates": stats.candidates,
        "sat_calls": stats.calls,
        "short_pairs_budget": stats.short,
    });
    let base = input.index_base;
    let (verdict, tets) = match &outcome {
        Outcome::Optimal {
            tets,
            unique,
            alternative,
        } => {
            v["verdict"] = json!("yes");
            v["minimum"] = json!(tets.len());
            if let Some(u) = unique {
                v["unique"] = json!(u);
            }
            if let Some(alt) = alternative {
                v["alternative"] = json!(shift(alt, base));
            }
            (Verdict::Yes, Some(tets))
        }
        Outcome::Found { tets } => {
            v["verdict"] = json!("yes");
            (Verdict::Yes, Some(tets))
        }
        Outcome::Infeasible => {
            v["verdict"] = json!("no");
            v["witness"] = exact_witness(&stats, base);
            if let Some(path) = a.proof {
                v["proof"] = crate::constrain::write_proof(path, |formula, proof| {
                    exact::prove_infeasible(domain, exact::Edges::default(), formula, proof, &ctl)
                })?;
            }
            (Verdict::No, None)
        }
        Outcome::Undecided { best, lower } => {
            v["verdict"] = json!("undecided");
            v["lower_bound"] = json!(lower);
            if let Some(b) = best {
                v["upper_bound"] = json!(b.len());
            }
            (Verdict::Undecided, best.as_ref())
        }
    };
    if let Some(tets) = tets {
        domain.certify(tets).map_err(|e| {
            CliError::internal(format!("the solver's tetrahedra fail the certificate: {e}"))
        })?;
        v["tetrahedra"] = json!(tets.len());
        v["tets"] = json!(shift(tets, base));
        v["certified"] = json!(true);
        if let Some(out) = a.output {
            io::write_mesh(out, &input.points, tets, base).written(out)?;
        }
    }
    v["seconds"] = json!(start.elapsed().as_secs_f64());
    if a.as_json {
        out!("{v}");
    } else {
        print_tetrahedralize(&v);
    }
    Ok(verdict)
}

/// The witness of the exact solver's NO: the short obstacle found before any SAT call,
/// or the unsatisfiable formula (`--proof` writes its refutation).
pub fn exact_witness(stats: &exact::Stats, base: u32) -> Value {
    match &stats.obstacle {
        Some(o) => json!({
            "kind": "obstacle",
            "detail": tetrakit::numbering::renumber_text(&o.to_string(), base),
        }),
        None => json!({
            "kind": "unsatisfiable",
            "detail": "no set of candidate tetrahedra (no other vertex inside, on the inner side of the boundary) satisfies the face-pairing clauses: no tetrahedralization without Steiner points exists",
        }),
    }
}

fn print_tetrahedralize(v: &Value) {
    match v["verdict"].as_str() {
        Some("yes") => {
            if v.get("minimum").is_some() {
                out!(
                    "minimum: {} tetrahedra for {} vertices ({}){}",
                    v["minimum"],
                    v["vertices"],
                    v["domain"].as_str().unwrap_or(""),
                    match v["unique"].as_bool() {
                        Some(true) => ", unique",
                        Some(false) => ", not unique (see --json for another)",
                        None => "",
                    }
                );
            } else {
                out!("tetrahedralizable: {} tetrahedra found", v["tetrahedra"]);
            }
            out!("  certified: orientation, face pairing, no overlap, boundary");
        }
        Some("no") => {
            out!(
                "NO: {} cannot be tetrahedralized without Steiner points",
                v["domain"].as_str().unwrap_or("")
            );
            if v["witness"]["kind"] == "obstacle" {
                out!("  proof: {}", v["witness"]["detail"].as_str().unwrap_or(""));
            } else {
                out!(
                    "  proof: the SAT formula is unsatisfiable ({} candidate tetrahedra)",
                    v["candidates"]
                );
            }
            if let Some(p) = v["proof"].get("drat") {
                out!(
                    "  DRAT refutation: {} of {}",
                    p.as_str().unwrap_or(""),
                    v["proof"]["formula"].as_str().unwrap_or("")
                );
            }
        }
        _ => match v["upper_bound"].as_u64() {
            Some(upper) => out!(
                "undecided within the time limit: minimum between {} and {upper}",
                v["lower_bound"]
            ),
            None => out!(
                "undecided within the time limit: minimum at least {} (no tetrahedralization found yet)",
                v["lower_bound"]
            ),
        },
    }
    out!(
        "  {} candidate tetrahedra, {} SAT calls, {:.3} s",
        v["candidates"],
        v["sat_calls"],
        v["seconds"].as_f64().unwrap_or(0.0)
    );
    if v["faces_beside_not_read"].as_bool() == Some(true) {
        out!(
            "  domain: the convex hull of the .node's points (the .face beside it is not read; name the .face for the polyhedron)"
        );
    }
}

/// The polyhedron generators.
pub enum PolyGen {
    Stacked { n: usize },
    Bipyramid { m: usize },
    Bp(generate::BpParams),
    Schonhardt { twist: Option<f64> },
    SchonhardtBp,
    Tower { layers: usize, twist: f64 },
    Chazelle { grooves: usize },
    Perturbed { n: usize, dent: f64 },
}

pub fn generate(kind: PolyGen, seed: u64, output: &Path) -> CmdResult {
    match kind {
        PolyGen::Stacked { n } if !(4..=50_000_000).contains(&n) => {
            return Err(CliError::new(format!(
                "--n {n}: a stacked polyhedron has between 4 and 50000000 vertices"
            )));
        }
        PolyGen::Bipyramid { m } if !(3..=50_000_000).contains(&m) => {
            return Err(CliError::new(format!(
                "--m {m}: a bipyramid's middle polygon has between 3 and 50000000 vertices"
            )));
        }
        _ => {}
    }
    if let PolyGen::Bp(params) = &kind {
        if !(1..=12).contains(&params.levels) {
            return Err(CliError::new(
                "--levels must be between 1 and 12 (each level can double the nets)",
            ));
        }
        if params.core > 50_000_000 || params.nets > params.core.max(4) {
            return Err(CliError::new(
                "--core must be at most 5e7 and --nets at most --core",
            ));
        }
    }
    let (p, note) = match kind {
        PolyGen::Stacked { n } => (generate::stacked(n, seed), String::new()),
        PolyGen::Bipyramid { m } => (generate::bipyramid(m, seed), String::new()),
        PolyGen::Bp(params) => {
            let (p, polar, seed) = bp_with_levels(params)?;
            let note = if seed == params.seed {
                String::new()
            } else {
                format!(
                    " (seed {seed}: the first from --seed with {} levels)",
                    params.levels
                )
            };
            (p, format!(", {polar} BP-net(s) glued{note}"))
        }
        PolyGen::Schonhardt { twist: None } => (generate::schonhardt(), String::new()),
        PolyGen::Schonhardt { twist: Some(deg) } => {
            let p =
                generate::twisted_prism(deg).map_err(|e| CliError::new(format!("--twist: {e}")))?;
            let reflex = generate::reflex_edges(&p).len();
            (p, format!(", {reflex} reflex edge(s)"))
        }
        PolyGen::SchonhardtBp => (generate::schonhardt_bp(), String::new()),
        PolyGen::Tower { layers, twist } => hard_family(hard::schonhardt_tower(layers, twist))?,
        PolyGen::Chazelle { grooves } => hard_family(hard::chazelle(grooves))?,
        PolyGen::Perturbed { n, dent } => hard_family(hard::perturbed(n, dent, seed))?,
    };
    io::write_surface(output, &p.points, &p.faces, 1).written(output)?;
    out!(
        "wrote {}: {} vertices, {} faces{note}",
        output.display(),
        p.points.len(),
        p.faces.len()
    );
    Ok(Verdict::Yes)
}

/// A polyhedron of [`hard`] with its reflex edges counted, or its refusal.
fn hard_family(p: Result<Polyhedron, String>) -> Result<(Polyhedron, String), CliError> {
    let p = p.map_err(CliError::new)?;
    let reflex = generate::reflex_edges(&p).len();
    Ok((p, format!(", {reflex} reflex edge(s)")))
}

/// An augmented BP-polyhedron with the levels asked for: MINTETRA must find exactly
/// `params.levels` of them (a small core may not hide a second level's nets). Up to 32
/// seeds from `params.seed` are tried; returns the polyhedron, its nets and the seed.
fn bp_with_levels(params: generate::BpParams) -> Result<(Polyhedron, usize, u64), CliError> {
    for seed in (0..32).map(|i| params.seed.wrapping_add(i)) {
        let (p, polar) = generate::bp_polyhedron(generate::BpParams { seed, ..params });
        if params.levels <= 1
            || polyhedra::mintetra(&p, Checks::Shelling).levels as usize == params.levels
        {
            return Ok((p, polar, seed));
        }
    }
    Err(CliError::new(format!(
        "no polyhedron with {} levels from --core {} --nets {} at 32 seeds from {}: give a larger --core or more --nets",
        params.levels, params.core, params.nets, params.seed
    )))
}
