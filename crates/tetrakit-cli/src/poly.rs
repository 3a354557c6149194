//! Chapter 3 commands: `mintetra`, `tetrahedralize`, and the polyhedron generators.

use crate::exit::{CliError, CmdResult, WriteContext};
use crate::progress::Run;
use std::path::Path;
use std::time::{Duration, Instant};
use tetrakit::control::Verdict;
use tetrakit::exact::{self, Domain, TetraOptions};
use tetrakit::mesh::Polyhedron;
use tetrakit::params::GenerateError;
use tetrakit::polyhedra::{self, Checks, MintetraOptions, generate, hard};
use tetrakit::{io, report};

pub fn mintetra(path: &Path, as_json: bool, output: Option<&Path>, confirm: bool) -> CmdResult {
    let start = Instant::now();
    let (input, poly) = io::read_polyhedron(path)?;
    let parsed = start.elapsed().as_secs_f64();
    let opts = MintetraOptions {
        confirm: confirm.then_some(Duration::from_secs(60)),
    };
    let run = Run::new(None, poly.points.len(), 1_000_000);
    let o = polyhedra::solve_mintetra(&poly, opts, &run.ctl).map_err(|e| {
        CliError::internal(format!("MINTETRA's tetrahedra fail the certificate: {e}"))
    })?;
    if let (Some(out), Verdict::Yes) = (output, o.verdict) {
        io::write_mesh(out, &poly.points, &o.tets, input.index_base).written(out)?;
    }
    let o = o.shifted(input.index_base);
    let seconds = start.elapsed().as_secs_f64();
    if as_json {
        let extra = [
            ("parse_seconds", parsed.into()),
            ("seconds", seconds.into()),
        ];
        out!("{}", report::json(&o, extra));
    } else {
        out!("{}", report::mintetra_text(&o, seconds).trim_end());
    }
    Ok(o.verdict)
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
    let opts = TetraOptions {
        minimal: a.minimal,
        unique: a.unique,
    };
    let run = Run::new(a.time_limit, 0, 1);
    let ctl = &run.ctl;
    let o = exact::tetrahedralize(domain, opts, ctl).map_err(|e| CliError::at(a.input, e))?;
    let proof = match (a.proof, o.verdict) {
        (Some(path), Verdict::No) => {
            Some(crate::constrain::write_proof(path, |formula, proof| {
                exact::prove_infeasible(domain, exact::Edges::default(), formula, proof, ctl)
            })?)
        }
        _ => None,
    };
    if let (Some(out), false) = (a.output, o.tets.is_empty()) {
        io::write_mesh(out, &input.points, &o.tets, input.index_base).written(out)?;
    }
    let o = o.shifted(input.index_base);
    let seconds = start.elapsed().as_secs_f64();
    if a.as_json {
        let extra = [
            ("faces_beside_not_read", faces_beside.into()),
            ("proof", serde_json::to_value(&proof).unwrap_or_default()),
            ("seconds", seconds.into()),
        ];
        out!("{}", report::json(&o, extra));
    } else {
        out!("{}", report::tetrahedralize_text(&o, seconds).trim_end());
        if let Some(p) = &proof {
            out!("{}", p.line());
        }
        if faces_beside {
            out!(
                "  domain: the convex hull of the .node's points (the .face beside it is not read; name the .face for the polyhedron)"
            );
        }
    }
    Ok(o.verdict)
}

/// `tetrahedralize --hamiltonian`: a convex polytope's points, tetrahedralized with a
/// Hamiltonian dual path.
pub fn hamiltonian(
    path: &Path,
    time_limit: Option<Duration>,
    as_json: bool,
    output: Option<&Path>,
) -> CmdResult {
    use tetrakit::dualpath::{PathError, PathOptions};
    let start = Instant::now();
    let input = io::read_input(path)?;
    if !input.faces.is_empty() || input.dim != 3 {
        return Err(CliError::at(
            path,
            "--hamiltonian takes a convex polytope's points in space (the surface is their hull; faces are not read)",
        ));
    }
    let run = Run::new(time_limit, 0, 1);
    let o = tetrakit::dualpath::hamiltonian(&input.points, &PathOptions::default(), &run.ctl)
        .map_err(|e| match e {
            PathError::Uncertified(_)
            | PathError::Internal(_)
            | PathError::Enumeration(_)
            | PathError::Exact(_) => CliError::new(e),
            PathError::Inside { index } => {
                let line = input.point_lines.get(index as usize).copied().unwrap_or(0);
                let what = tetrakit::numbering::renumber_text(&e.to_string(), input.index_base);
                match line {
                    0 => CliError::at(path, what),
                    l => CliError::new(format!("{}:{l}: {what}", input.point_file.display())),
                }
            }
            _ => CliError::at(
                path,
                tetrakit::numbering::renumber_text(&e.to_string(), input.index_base),
            ),
        })?;
    drop(run);
    if let (Some(out), Verdict::Yes) = (output, o.verdict) {
        io::write_mesh(out, &input.points, &o.tets, input.index_base).written(out)?;
    }
    let o = o.shifted(input.index_base);
    let seconds = start.elapsed().as_secs_f64();
    if as_json {
        out!("{}", report::json(&o, [("seconds", seconds.into())]));
    } else {
        out!("{}", report::hamiltonian_text(&o, seconds).trim_end());
    }
    Ok(o.verdict)
}

/// The polyhedron generators.
pub enum PolyGen {
    Stacked {
        n: usize,
    },
    Bipyramid {
        m: usize,
    },
    Bp(generate::BpParams),
    Schonhardt {
        twist: Option<f64>,
    },
    SchonhardtBp,
    ConvexTriangulated {
        shape: generate::ConvexShape,
        n: usize,
        facet_points: usize,
    },
    Tower {
        layers: usize,
        twist: f64,
    },
    Chazelle {
        grooves: usize,
    },
    Perturbed {
        n: usize,
        dent: f64,
    },
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
            let p = generate::twisted_prism(deg)?;
            let reflex = generate::reflex_edges(&p).len();
            (p, format!(", {reflex} reflex edge(s)"))
        }
        PolyGen::SchonhardtBp => (generate::schonhardt_bp(), String::new()),
        PolyGen::ConvexTriangulated {
            shape,
            n,
            facet_points,
        } => {
            let p = generate::convex_triangulated(shape, n, facet_points, seed)?;
            (p, ", every facet triangulated".to_string())
        }
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
fn hard_family(p: Result<Polyhedron, GenerateError>) -> Result<(Polyhedron, String), CliError> {
    let p = p?;
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
