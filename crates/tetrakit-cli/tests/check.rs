//! `check` end to end: verdicts and problems on valid, corrupted, mixed, Gmsh and partitioned meshes, the fields written for a viewer, numbering, and memory limits.

mod common;
use common::*;

/// `from`, a Gmsh 2.2 ASCII mesh, written to `to` with its first (or, with `last`, its
/// last) tetrahedron turned inside out (its last two nodes swapped): that element line's
/// fields.
fn turned_inside_out(from: &Path, to: &Path, last: bool) -> Vec<String> {
    let text = std::fs::read_to_string(from).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let tet = |l: &String| l.split(' ').nth(1) == Some("4");
    let k = match last {
        true => lines.iter().rposition(tet),
        false => lines.iter().position(tet),
    }
    .unwrap();
    let mut f: Vec<String> = lines[k].split(' ').map(String::from).collect();
    let n = f.len();
    f.swap(n - 1, n - 2);
    lines[k] = f.join(" ");
    std::fs::write(to, lines.join("\n")).unwrap();
    f
}

#[test]
fn check_valid_and_overlapping_meshes() {
    let d = dir("check");
    let ele = d.join("r.ele");
    assert!(
        run(&[
            "generate",
            "random-tetrahedralization",
            "--points",
            "60",
            "--flips",
            "50",
            "-o",
            s(&ele)
        ])
        .status
        .success()
    );
    let o = run(&["check", s(&ele), "--convex", "--json"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    assert_eq!(json(&o)["verdict"], "yes");
    let bad = d.join("bad.ele");
    assert!(
        run(&[
            "generate",
            "random-tetrahedralization",
            "--points",
            "60",
            "--flips",
            "50",
            "--corrupt",
            "add-overlap",
            "--grid",
            "5",
            "-o",
            s(&bad)
        ])
        .status
        .success()
    );
    let o = run(&["check", s(&bad), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v = json(&o);
    assert!(v["problem_count"].as_u64().unwrap() > 0);
    assert!(!v["problems"][0]["tets"].as_array().unwrap().is_empty());
}

/// A `.ele` numbered with gaps is checked, and its problems name the tetrahedra by the
/// file's numbers (fields and text); a tet with a repeated vertex is named the same way.
#[test]
fn check_names_tetrahedra_by_the_files_numbers() {
    let d = dir("labels");
    let node = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";
    std::fs::write(d.join("g.node"), node).unwrap();
    // Two copies of one tetrahedron: they overlap.
    std::fs::write(d.join("g.ele"), "2 4 0\n100 1 2 3 4\n205 1 2 4 3\n").unwrap();
    let o = run(&["check", s(&d.join("g.ele")), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let w = json(&o)["witness"].clone();
    let tets: Vec<u64> = serde_json::from_value(w["tets"].clone()).unwrap();
    assert!(tets.iter().all(|t| [100, 205].contains(t)), "{w}");
    let detail = w["detail"].as_str().unwrap();
    assert!(
        detail.contains("T100") || detail.contains("T205"),
        "{detail}"
    );
    assert!(
        !detail.contains("T0") && !detail.contains("T1 "),
        "{detail}"
    );
    std::fs::write(d.join("g.ele"), "1 4 0\n7 1 2 2 4\n").unwrap();
    let o = run(&["detect", s(&d.join("g.ele"))]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("g.ele:2: tetrahedron 7 repeats"), "{err}");
}

/// `check --reorient` turns the inverted cells of an unoriented mesh and counts them;
/// `check --output` writes the mesh with the problem codes of its cells and points, in
/// positions (not the file's labels), readable by the VTK reader.
/// A mixed mesh (tetrahedra and a hexahedron) is refused with the count and the line;
/// `--tets-only` checks its tetrahedra and counts the rest; the `.vtu` tetrakit writes
/// reads back to the same verdict.
#[test]
fn tets_only_checks_the_tetrahedra_of_a_mixed_mesh() {
    let d = dir("mixed");
    let vtk = "# vtk DataFile Version 4.2\nmixed\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 9 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n2 0 0\n3 0 0\n3 1 0\n2 1 0\nCELLS 3 19\n4 0 1 2 3\n4 1 2 3 4\n8 5 6 7 8 5 6 7 8\nCELL_TYPES 3\n10\n10\n12\n";
    let f = d.join("m.vtk");
    std::fs::write(&f, vtk).unwrap();
    let o = run(&["check", s(&f)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("m.vtk:18: 1 cells of VTK type 12") && err.contains("--tets-only"),
        "{err}"
    );
    let o = run(&["check", s(&f), "--tets-only", "--json"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = json(&o);
    assert_eq!(
        (v["tetrahedra"].as_u64(), v["other_cells"].as_u64()),
        (Some(2), Some(1))
    );
    let out = d.join("m.vtu");
    let o = run(&["check", s(&f), "--tets-only", "--output", s(&out)]);
    assert_eq!(o.status.code(), Some(0));
    let o = run(&["check", s(&out), "--json"]);
    assert_eq!(
        (o.status.code(), json(&o)["tetrahedra"].as_u64()),
        (Some(0), Some(2))
    );
    let o = run(&[
        "check",
        s(&f),
        "--tets-only",
        "--output",
        s(&d.join("m.ele")),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("m.ele: --output takes a .vtk, .vtu or .pvtu"),
        "{err}"
    );
}

#[test]
fn check_reorients_and_writes_problem_fields_for_a_viewer() {
    let d = dir("fields");
    let node = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 -1\n";
    std::fs::write(d.join("g.node"), node).unwrap();
    // Two tetrahedra sharing face 1 2 3 (labels 10 and 20), the second inverted.
    std::fs::write(d.join("g.ele"), "2 4 0\n10 1 2 3 4\n20 1 2 3 5\n").unwrap();
    let ele = d.join("g.ele");
    let o = run(&["check", s(&ele), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json(&o)["witness"]["kind"], "inverted");
    let o = run(&["check", s(&ele), "--reorient", "--json"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    assert_eq!(json(&o)["reoriented"], 1);
    for ext in ["vtu", "vtk"] {
        let out = d.join(format!("p.{ext}"));
        let o = run(&["check", s(&ele), "--json", "--output", s(&out)]);
        assert_eq!(o.status.code(), Some(1));
        assert_eq!(json(&o)["problem_codes"]["inverted"], 4);
        let text = std::fs::read_to_string(&out).unwrap();
        let cells = if ext == "vtu" {
            text.split("<CellData>")
                .nth(1)
                .unwrap()
                .lines()
                .nth(2)
                .unwrap()
        } else {
            text.split("LOOKUP_TABLE default\n")
                .nth(1)
                .unwrap()
                .lines()
                .next()
                .unwrap()
        };
        assert_eq!(cells, "0 4", "{ext}");
    }
    // The legacy file reads back as the same mesh, with the same verdict.
    let o = run(&["check", s(&d.join("p.vtk")), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json(&o)["tetrahedra"], 2);
    let o = run(&["check", s(&ele), "--output", s(&d.join("p.ele"))]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("p.ele") && err.contains(".vtk, .vtu or .pvtu"),
        "{err}"
    );
}

/// Meshes written by the real Gmsh (a box with a spherical hole, first and second order,
/// `.msh` 2.2, 4.1 and 4.1 binary, and Medit `.mesh`) read with the same verdict and the same
/// tetrahedra; a tetrahedron turned inside out in the `.msh` is named by its element tag.
/// Needs `gmsh` on the PATH (`.ci/run` installs it and sets `TETRAKIT_REQUIRE_GMSH`).
#[test]
fn gmsh_meshes_read_with_one_verdict() {
    let available = Command::new("gmsh").arg("--version").output().is_ok();
    if !available {
        assert!(
            std::env::var_os("TETRAKIT_REQUIRE_GMSH").is_none(),
            "gmsh is required here but not on the PATH"
        );
        eprintln!("gmsh not on the PATH: skipped");
        return;
    }
    let d = dir("gmsh");
    let geo = "SetFactory(\"OpenCASCADE\");\nBox(1) = {0,0,0, 1,1,1};\nSphere(2) = {0.5,0.5,0.5, 0.3};\nBooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }\nPhysical Volume(\"solid\", 5) = {1};\nMesh.MeshSizeMax = 0.2;\n";
    std::fs::write(d.join("b.geo"), geo).unwrap();
    let mut counts = Vec::new();
    for (name, args) in [
        ("b22.msh", &["-format", "msh22"][..]),
        ("b41.msh", &["-format", "msh41"]),
        ("b2.msh", &["-format", "msh41", "-order", "2"]),
        ("bbin.msh", &["-format", "msh41", "-bin"]),
        ("b2bin.msh", &["-format", "msh41", "-bin", "-order", "2"]),
        ("b.mesh", &["-format", "mesh"]),
    ] {
        let out = d.join(name);
        let g = Command::new("gmsh")
            .arg(d.join("b.geo"))
            .arg("-3")
            .args(args)
            .arg("-o")
            .arg(&out)
            .output()
            .unwrap();
        assert!(g.status.success(), "{}", String::from_utf8_lossy(&g.stderr));
        let o = run(&["check", s(&out), "--json"]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{name}: {}",
            String::from_utf8_lossy(&o.stdout)
        );
        counts.push(json(&o)["tetrahedra"].as_u64().unwrap());
    }
    assert!(
        counts[0] > 100 && counts.iter().all(|&c| c == counts[0]),
        "{counts:?}"
    );
    // Turn the first tetrahedron of the 2.2 file inside out: swap its last two nodes.
    let f = turned_inside_out(&d.join("b22.msh"), &d.join("bad.msh"), false);
    let tag = f[0].clone();
    let o = run(&["check", s(&d.join("bad.msh")), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let w = json(&o)["witness"].clone();
    assert_eq!(w["kind"], "inverted");
    assert_eq!(w["tets"][0].to_string(), tag, "{w}");
}

/// Gmsh's partitioned meshes in one file (`-part 3`, `.msh` 2.2 and 4.1): one piece per
/// partition, checked part by part with the tetrahedra of the unpartitioned mesh; a
/// tetrahedron turned inside out is named by its element tag and placed in its partition.
/// Binary files (`-bin`, 4.1 and 2.2) are read in the same pieces, tetrahedron for
/// tetrahedron. Needs `gmsh` (as above).
#[test]
fn gmsh_partitioned_meshes_are_read_in_pieces() {
    if Command::new("gmsh").arg("--version").output().is_err() {
        assert!(
            std::env::var_os("TETRAKIT_REQUIRE_GMSH").is_none(),
            "gmsh is required here"
        );
        return;
    }
    let d = dir("gmsh-part");
    let geo = "SetFactory(\"OpenCASCADE\");\nBox(1) = {0,0,0, 1,1,1};\nMesh.MeshSizeMax = 0.25;\n";
    std::fs::write(d.join("p.geo"), geo).unwrap();
    let mut facts = Vec::new();
    for (name, args) in [
        ("p.msh", &["-format", "msh41"][..]),
        ("p22.msh", &["-format", "msh22", "-part", "3"]),
        ("p41.msh", &["-format", "msh41", "-part", "3"]),
        ("pbin.msh", &["-format", "msh41", "-bin", "-part", "3"]),
        ("pbin22.msh", &["-format", "msh22", "-bin", "-part", "3"]),
    ] {
        let out = d.join(name);
        let g = Command::new("gmsh")
            .arg(d.join("p.geo"))
            .arg("-3")
            .args(args)
            .arg("-o")
            .arg(&out)
            .output()
            .unwrap();
        assert!(g.status.success(), "{}", String::from_utf8_lossy(&g.stderr));
        let o = run(&["check", s(&out), "--json"]);
        assert_eq!(o.status.code(), Some(0), "{name}");
        let j = json(&o);
        facts.push((
            j["tetrahedra"].as_u64().unwrap(),
            j["pieces"].as_u64().unwrap_or(1),
        ));
    }
    let t = facts[0].0;
    assert_eq!(facts, [(t, 1), (t, 3), (t, 3), (t, 3), (t, 3)]);
    // Binary and ASCII: the same tetrahedra, tags and partitions, piece for piece.
    let read = |name: &str| {
        let opts = tetrakit::io::ReadOptions {
            mesh: true,
            ..Default::default()
        };
        let i = tetrakit::io::read_input_with(&d.join(name), opts).unwrap();
        let pieces: Vec<(u32, Option<i64>)> = i
            .pieces
            .iter()
            .map(|p| (p.first_tet, p.partition))
            .collect();
        (i.tets, i.tet_labels, pieces)
    };
    assert_eq!(read("pbin.msh"), read("p41.msh"));
    assert_eq!(read("pbin22.msh"), read("p22.msh"));
    // The other layout: one file per partition (`-part_split`), given together.
    let split = d.join("s.msh");
    let g = Command::new("gmsh")
        .arg(d.join("p.geo"))
        .arg("-3")
        .args(["-part", "3", "-part_split", "-format", "msh41", "-o"])
        .arg(&split)
        .output()
        .unwrap();
    assert!(g.status.success());
    let files: Vec<PathBuf> = (1..=3).map(|k| d.join(format!("s_{k}.msh"))).collect();
    let o = run(&["check", s(&files[0]), s(&files[1]), s(&files[2]), "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let j = json(&o);
    assert_eq!(
        (j["tetrahedra"].as_u64(), j["pieces"].as_u64()),
        (Some(t), Some(3))
    );
    let missing = run(&["check", s(&files[0]), s(&d.join("s_9.msh"))]);
    let err = String::from_utf8_lossy(&missing.stderr);
    assert!(
        missing.status.code() == Some(2) && err.contains("s_9.msh") && err.lines().count() == 1,
        "{err}"
    );
    // Turn a tetrahedron of the partitioned 2.2 file inside out.
    let f = turned_inside_out(&d.join("p22.msh"), &d.join("bad.msh"), true);
    let (tag, partition) = (f[0].clone(), f[6].parse::<u64>().unwrap());
    let o = run(&["check", s(&d.join("bad.msh")), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let j = json(&o);
    assert_eq!(j["witness"]["tets"][0].to_string(), tag);
    assert_eq!(
        j["problem_pieces"][0][0][0].as_u64(),
        Some(partition - 1),
        "{j}"
    );
    let text = run(&["check", s(&d.join("bad.msh"))]);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains(&format!("bad.msh, partition {partition})")),
        "{text}"
    );
}

/// `check X.pvtu --output P.pvtu` writes one `.vtu` per piece with its `problem` fields
/// and the vertices' numbers as `GlobalNodeIds`: read back, the same mesh and problems.
#[test]
fn partitioned_problems_are_written_per_piece() {
    let d = dir("pvtu-output");
    let parts = d.join("parts.pvtu");
    let g = run(&[
        "generate",
        "kuhn",
        "--size",
        "3",
        "--corrupt",
        "add-overlap",
        "-o",
        s(&parts),
        "--pieces",
        "3",
    ]);
    assert_eq!(g.status.code(), Some(0));
    let out = d.join("out.pvtu");
    let first = run(&["check", s(&parts), "--json", "--output", s(&out)]);
    assert_eq!(first.status.code(), Some(1));
    for k in 0..3 {
        let piece = std::fs::read_to_string(d.join(format!("out_{k}.vtu"))).unwrap();
        assert!(piece.contains("Name=\"problem\"") && piece.contains("Name=\"GlobalNodeIds\""));
    }
    let again = run(&["check", s(&out), "--json"]);
    let (a, b) = (json(&first), json(&again));
    for key in [
        "tetrahedra",
        "vertices",
        "problem_count",
        "problems",
        "pieces",
        "problem_pieces",
    ] {
        assert_eq!(a[key], b[key], "{key}");
    }
}

/// Under memory limits too tight for the worker threads (a batch scheduler's), a command
/// runs on one thread and answers, where rayon's refused pool used to panic and the
/// panic, unable to allocate its backtrace, deadlocked. Each run is killed after 60 s: a
/// hang fails the test, not CI's clock. Needs util-linux's `prlimit`.
#[test]
fn tight_memory_limits_run_on_one_thread_and_never_hang() {
    let prlimit = Path::new("/usr/bin/prlimit");
    if !prlimit.exists() {
        return;
    }
    let d = dir("tight");
    let ele = d.join("k.ele");
    let made = run(&["generate", "kuhn", "--size", "2", "-o", s(&ele)]);
    assert!(made.status.success());
    for mib in [2u64, 4, 5, 6, 8, 12] {
        let mut child = Command::new(prlimit)
            .arg(format!("--data={}", mib << 20))
            .arg(env!("CARGO_BIN_EXE_tetrakit"))
            .args(["check", s(&ele)])
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let start = std::time::Instant::now();
        while child.try_wait().unwrap().is_none() {
            if start.elapsed() > std::time::Duration::from_secs(60) {
                let _ = child.kill();
                panic!("check hung under a {mib} MiB data limit");
            }
            std::thread::sleep(std::time::Duration::from_millis(10));
        }
        let out = child.wait_with_output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success() && text.starts_with("VALID"),
            "{mib} MiB: {text} {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// `--output` writes the certified tetrahedra of an input numbered from 1 (OBJ) in the
/// output's own numbering, whatever the command: every written mesh checks valid with
/// the count the JSON gives.
#[test]
fn written_meshes_keep_the_numbering_of_their_format() {
    let d = dir("numbering");
    let obj = d.join("b.obj");
    let g = run(&["generate", "bipyramid", "--m", "6", "-o", s(&obj)]);
    assert!(g.status.success());
    let schonhardt = d.join("s.obj");
    assert!(
        run(&["generate", "schonhardt", "-o", s(&schonhardt)])
            .status
            .success()
    );
    let cases: [(&[&str], &Path); 3] = [
        (&["mintetra"], &obj),
        (&["tetrahedralize", "--minimal"], &obj),
        (&["reduce", "hull-gap"], &schonhardt),
    ];
    for (command, input) in cases {
        for ext in ["vtu", "ele", "vtk", "json"] {
            let out = d.join(format!("{}.{ext}", command.join("-")));
            let mut args = command.to_vec();
            args.extend([s(input), "--json", "--output", s(&out)]);
            let o = run(&args);
            assert_eq!(o.status.code(), Some(0), "{command:?}");
            let v = json(&o);
            let c = run(&["check", s(&out), "--json"]);
            assert_eq!(c.status.code(), Some(0), "{command:?} .{ext}");
            assert_eq!(
                json(&c)["tetrahedra"],
                v["tetrahedra"],
                "{command:?} .{ext}"
            );
        }
    }
}
