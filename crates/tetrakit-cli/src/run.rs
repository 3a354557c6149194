//! The commands: read, call the library, print.

use crate::exit::{CliError, CmdResult, Verdict, WriteContext};
use crate::progress::Run;
use crate::{CorruptKind, GenCommon, GenKind};
use std::path::PathBuf;
use std::time::Instant;
use tetrakit::detect::{Cells, Options};
use tetrakit::generate::{self, Corruption};
use tetrakit::io;
use tetrakit::mesh::{self, Tetrahedralization};

pub fn detect(a: &crate::DetectArgs) -> CmdResult {
    let (path, as_json, output) = (a.input.as_path(), a.json, a.output.as_deref());
    let opts = Options {
        delaunay_first: !a.links_only,
        links: a.links,
    };
    let start = Instant::now();
    let input = io::read_input(path)?;
    let parsed = start.elapsed().as_secs_f64();
    let (segments, from_tets) = if !input.segments.is_empty() {
        (input.segments.clone(), false)
    } else if !input.tets.is_empty() {
        // A tetrahedron that repeats a vertex has no edge set: name it where it was read.
        if let Some(k) = input
            .tets
            .iter()
            .position(|t| (0..4).any(|i| (i + 1..4).any(|j| t[i] == t[j])))
        {
            let t = input.tets[k].map(|v| v + input.index_base);
            return Err(CliError::new(format!(
                "{}: tetrahedron {} repeats a vertex ({} {} {} {}): it has no edge set to test",
                input.tet_origin(k),
                input.tet_label(k),
                t[0],
                t[1],
                t[2],
                t[3]
            )));
        }
        (mesh::edges_of(&input.tets), true)
    } else {
        return Err(CliError::at(
            path,
            "no segments to test (give an .edge file, OBJ 'l' lines or JSON \"segments\")",
        ));
    };
    let run = Run::new(a.time_limit, input.points.len(), 50_000);
    let d = tetrakit::detect::detect(&input.points, &segments, &opts, &run.ctl)
        .map_err(|e| CliError::at(path, e))?;
    drop(run);
    let seconds = start.elapsed().as_secs_f64();
    if let (Some(out), Some(cells)) = (output, d.answer.cells()) {
        match cells {
            Cells::Tetrahedra(t) => io::write_mesh(out, &input.points, t, input.index_base),
            Cells::Triangles(t) => io::write_triangulation(out, &input.points, t),
        }
        .written(out)?;
    }
    let label = |v: u32| input.point_label(v as usize);
    if as_json {
        let extra = [
            ("seconds", seconds.into()),
            ("parse_seconds", parsed.into()),
        ];
        out!("{}", tetrakit::report::detect_json(&d, label, extra));
    } else {
        let text = tetrakit::report::detect_text(&d, label, from_tets, seconds);
        out!("{}", text.trim_end());
    }
    Ok(d.verdict())
}

pub fn check(a: &crate::CheckArgs) -> CmdResult {
    let (path, convex, as_json) = (a.input.as_path(), a.convex, a.json);
    let start = Instant::now();
    if let Some(out) = &a.output {
        let ext = out.extension().and_then(|e| e.to_str()).unwrap_or("");
        if !matches!(ext.to_ascii_lowercase().as_str(), "vtk" | "vtu" | "pvtu") {
            let why =
                "--output takes a .vtk, .vtu or .pvtu file (the mesh with its problem fields)";
            return Err(CliError::at(out, why));
        }
    }
    let opts = io::ReadOptions {
        tets_only: a.tets_only,
        mesh: true,
    };
    let files: Vec<PathBuf> = std::iter::once(&a.input).chain(&a.more).cloned().collect();
    let mut input = io::read_files(&files, opts)?;
    let parsed = start.elapsed().as_secs_f64();
    if input.tets.is_empty() {
        let others = match &input.other_cells {
            Some(o) => format!(", {} other cells", o.count),
            None => String::new(),
        };
        let why = format!(
            "no tetrahedra to check: it holds {} points, {} triangles, {} segments{others} and no tetrahedron (give a volume mesh, an .ele file or JSON \"tets\")",
            input.points.len(),
            input.faces.len(),
            input.segments.len()
        );
        return Err(CliError::at(path, &why));
    }
    let opts = mesh::CheckOptions {
        convex,
        manifold: a.manifold,
        reorient: a.reorient,
    };
    // A partitioned mesh is checked part by part (the merged mesh's answer).
    let first: Vec<u32> = input.pieces.iter().map(|p| p.first_tet).collect();
    let tets = std::mem::take(&mut input.tets);
    let outcome = mesh::check_pieces(&input.points, tets, &first, opts)
        .with_problems(input.interface_problems());
    if let Some(out) = &a.output {
        io::write_check_output(out, &input, &outcome).written(out)?;
    }
    let verdict = Verdict::from(outcome.is_valid());
    let seconds = start.elapsed().as_secs_f64();
    let printed = tetrakit::report::check_printed(outcome, &input, seconds, parsed, as_json);
    out!("{printed}");
    Ok(verdict)
}

pub fn generate(kind: GenKind) -> CmdResult {
    let (name, mesh, common) = match kind {
        GenKind::Kuhn { size, common } => {
            if size == 0 || size > 200 {
                return Err(CliError::new("--size must be between 1 and 200"));
            }
            (format!("kuhn --size {size}"), generate::kuhn(size), common)
        }
        GenKind::RandomTetrahedralization {
            points,
            flips,
            grid,
            common,
        } => {
            if !(4..=10_000).contains(&points) {
                return Err(CliError::new(
                    "--points must be between 4 and 10000 (the generator locates points by brute force; use TetGen for larger meshes)",
                ));
            }
            if let Some(g) = grid
                && (g < 2 || (g as u64).pow(3) < points as u64)
            {
                return Err(CliError::new(format!(
                    "--grid {g} has {} integer points, fewer than --points {points} (and at least 2 a side are needed)",
                    (g as u64).pow(3)
                )));
            }
            let t = generate::random_tetrahedralization(points, flips, common.seed, grid);
            if t.tets.is_empty() {
                return Err(CliError::new(
                    "the random points are coplanar; use more points or a larger --grid",
                ));
            }
            (
                format!("random-tetrahedralization --points {points} --flips {flips}"),
                t,
                common,
            )
        }
        GenKind::SkewLines { points, common } => {
            if !(4..=20_000).contains(&points) {
                return Err(CliError::new("--points must be between 4 and 20000"));
            }
            (
                format!("skew-lines --points {points}"),
                generate::skew_lines(points),
                common,
            )
        }
        _ => {
            return Err(CliError::internal(
                "a polyhedron generator reached the mesh writer",
            ));
        }
    };
    write_generated(&name, mesh, &common)
}

fn write_generated(name: &str, mut mesh: Tetrahedralization, c: &GenCommon) -> CmdResult {
    let mut edges = mesh.edges();
    if let Some(k) = c.corrupt {
        (mesh, edges) = corrupted(mesh, &edges, k, c.seed)?;
    }
    let out = &c.output;
    let partitioned = out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("pvtu"));
    if partitioned {
        let pieces = tetrakit::generate::slabs(&mesh.points, &mesh.tets, c.pieces);
        io::write_pieces(out, &mesh.points, &mesh.tets, &pieces, None).written(out)?;
    } else {
        io::write_instance(out, &mesh.points, &mesh.tets, &edges).written(out)?;
    }
    let corrupted = c
        .corrupt
        .map(|k| format!(", corrupted by {}", user_name(k)))
        .unwrap_or_default();
    out!(
        "wrote {name}: {} points, {} segments, {} tetrahedra{corrupted} to {}",
        mesh.points.len(),
        edges.len(),
        mesh.tets.len(),
        out.display()
    );
    Ok(Verdict::Yes)
}

/// The corruption as the user wrote it (`add-crossing`).
fn user_name(k: CorruptKind) -> String {
    use clap::ValueEnum;
    k.to_possible_value()
        .map_or_else(|| format!("{k:?}"), |v| v.get_name().to_string())
}

/// `mesh` and its `edges` corrupted by `k`, checked before anything is written: the
/// segments are no tetrahedralization's edge set (`detect` says NO) and, for
/// add-overlap, the tetrahedra fail the verifier. Up to 32 seeds from `seed` are tried;
/// an instance that cannot be corrupted so is an error, never a valid file.
fn corrupted(
    mesh: Tetrahedralization,
    edges: &[[u32; 2]],
    k: CorruptKind,
    seed: u64,
) -> Result<(Tetrahedralization, Vec<[u32; 2]>), CliError> {
    let kind = match k {
        CorruptKind::DropEdge => Corruption::DropEdge,
        CorruptKind::AddCrossing => Corruption::AddCrossing,
        CorruptKind::AddOverlap => Corruption::AddOverlap,
    };
    let ctl = tetrakit::control::Control::new();
    for s in (0..32).map(|i| seed.wrapping_add(i)) {
        let Some(bad_edges) = generate::corrupt_edges(&mesh.points, edges, kind, s) else {
            break;
        };
        let bad_mesh = match k {
            CorruptKind::AddOverlap => match generate::add_overlapping_tet(&mesh, s) {
                Some(m) if !m.verify_convex().is_valid() => m,
                _ => continue,
            },
            _ => mesh.clone(),
        };
        let d = tetrakit::detect::detect(&mesh.points, &bad_edges, &Options::default(), &ctl)
            .map_err(CliError::internal)?;
        if !d.is_yes() {
            return Ok((bad_mesh, bad_edges));
        }
    }
    Err(CliError::new(format!(
        "cannot apply {} to this instance: every attempt left a valid instance or found no segment to cross or overlap (points in general position?); try --grid, another --seed or drop-edge",
        user_name(k)
    )))
}
