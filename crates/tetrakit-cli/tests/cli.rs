//! End-to-end tests of the `tetrakit` binary: exit codes, JSON fields, numbering, and one
//! clear line for every bad input.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tetrakit"))
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tetrakit-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("binary runs")
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn json(o: &Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout).expect("stdout is one JSON object")
}

#[test]
fn generate_then_detect_yes_with_json_fields() {
    let d = dir("yes");
    let ele = d.join("k.ele");
    let o = run(&["generate", "kuhn", "--size", "3", "-o", s(&ele)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = run(&[
        "detect",
        s(&d.join("k.edge")),
        "--json",
        "--output",
        s(&d.join("t.vtk")),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(v["verdict"], "yes");
    assert_eq!(v["vertices"], 64);
    assert_eq!(v["tetrahedra"], 162);
    assert_eq!(v["hull_vertices"], 56);
    assert!(v["seconds"].as_f64().unwrap() >= 0.0);
    let vtk = std::fs::read_to_string(d.join("t.vtk")).unwrap();
    assert!(vtk.contains("CELL_TYPES 162"));
}

/// Both link methods give the same verdicts and tetrahedra on skew lines (huge links),
/// valid and corrupted; an unknown method is a usage error.
#[test]
fn link_methods_agree() {
    let d = dir("links");
    for corrupt in [None, Some("add-crossing"), Some("drop-edge")] {
        let ele = d.join(format!("s{}.ele", corrupt.unwrap_or("ok")));
        let mut args = vec!["generate", "skew-lines", "--points", "60", "-o", s(&ele)];
        args.extend(corrupt.map(|c| ["--corrupt", c]).into_iter().flatten());
        assert!(run(&args).status.success());
        let edge = ele.with_extension("edge");
        let out: Vec<serde_json::Value> = ["sweep", "table"]
            .iter()
            .map(|m| json(&run(&["detect", s(&edge), "--json", "--links", m])))
            .collect();
        assert_eq!(out[0]["verdict"], out[1]["verdict"], "{corrupt:?}");
        assert_eq!(out[0]["tetrahedra"], out[1]["tetrahedra"], "{corrupt:?}");
        let want = if corrupt.is_none() { "yes" } else { "no" };
        assert_eq!(out[0]["verdict"], want, "{corrupt:?}");
    }
    let o = run(&["detect", "x.edge", "--links", "fast"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn delaunay_route_and_links_only_agree() {
    // Two Delaunay tetrahedra glued on the face 1-2-3.
    let p = dir("route").join("two.json");
    let points = "[[0,0,0],[1,0,0],[0,1,0],[0,0,1],[1,1,1.1]]";
    let segs = "[[0,1],[0,2],[0,3],[1,2],[1,3],[2,3],[4,1],[4,2],[4,3]]";
    std::fs::write(
        &p,
        format!("{{\"points\": {points}, \"segments\": {segs}}}"),
    )
    .unwrap();
    let first = json(&run(&["detect", s(&p), "--json"]));
    let links = json(&run(&["detect", s(&p), "--json", "--links-only"]));
    assert_eq!(
        (&first["route"], &links["route"]),
        (&"delaunay".into(), &"links".into())
    );
    for v in [&first, &links] {
        assert_eq!(
            (&v["verdict"], &v["tetrahedra"]),
            (&"yes".into(), &2.into())
        );
    }
}

#[test]
fn corrupted_instances_give_no_with_witness_in_file_numbering() {
    let d = dir("no");
    for (k, kind) in [
        ("drop-edge", None),
        ("add-crossing", Some("crossing_segments")),
        ("add-overlap", None),
    ] {
        let ele = d.join(format!("{k}.ele"));
        let o = run(&[
            "generate",
            "kuhn",
            "--size",
            "2",
            "--corrupt",
            k,
            "-o",
            s(&ele),
        ]);
        assert!(
            o.status.success(),
            "{k}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let o = run(&["detect", s(&ele.with_extension("edge")), "--json"]);
        assert_eq!(o.status.code(), Some(1), "{k}");
        let v = json(&o);
        assert_eq!(v["verdict"], "no");
        let w = &v["witness"];
        assert!(w["detail"].as_str().unwrap().len() > 10);
        if let Some(kind) = kind {
            assert_eq!(w["kind"], kind, "{k}: {w}");
        }
        // TetGen files from `generate` are 1-based: no vertex 0 may be named.
        let verts: Vec<u64> = w["vertices"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap())
            .collect();
        assert!(verts.iter().all(|&x| (1..=27).contains(&x)), "{k}: {w}");
        let o = run(&["detect", s(&ele.with_extension("edge"))]);
        let text = String::from_utf8_lossy(&o.stdout);
        assert!(text.starts_with("NO") && text.contains("witness"), "{text}");
    }
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
    let text = std::fs::read_to_string(d.join("b22.msh")).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let k = lines
        .iter()
        .position(|l| l.split(' ').nth(1) == Some("4"))
        .unwrap();
    let mut f: Vec<&str> = lines[k].split(' ').collect();
    let n = f.len();
    f.swap(n - 1, n - 2);
    let tag = f[0].to_string();
    lines[k] = f.join(" ");
    std::fs::write(d.join("bad.msh"), lines.join("\n")).unwrap();
    let o = run(&["check", s(&d.join("bad.msh")), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let w = json(&o)["witness"].clone();
    assert_eq!(w["kind"], "inverted");
    assert_eq!(w["tets"][0].to_string(), tag, "{w}");
}

/// Gmsh's partitioned meshes in one file (`-part 3`, `.msh` 2.2 and 4.1): one piece per
/// partition, checked part by part with the tetrahedra of the unpartitioned mesh; a
/// tetrahedron turned inside out is named by its element tag and placed in its partition.
/// The binary 4.1 file is read as one mesh. Needs `gmsh` (as above).
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
    assert_eq!(facts, [(t, 1), (t, 3), (t, 3), (t, 1)]);
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
    let text = std::fs::read_to_string(d.join("p22.msh")).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let k = lines
        .iter()
        .rposition(|l| l.split(' ').nth(1) == Some("4"))
        .unwrap();
    let mut f: Vec<&str> = lines[k].split(' ').collect();
    let n = f.len();
    f.swap(n - 1, n - 2);
    let (tag, partition) = (f[0].to_string(), f[6].parse::<u64>().unwrap());
    lines[k] = f.join(" ");
    std::fs::write(d.join("bad.msh"), lines.join("\n")).unwrap();
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

#[test]
fn planar_input_is_a_triangulation_question() {
    let d = dir("planar");
    let p = d.join("sq.json");
    std::fs::write(
        &p,
        r#"{"points":[[0,0],[1,0],[1,1],[0,1]],"segments":[[0,1],[1,2],[2,3],[3,0],[0,2]]}"#,
    )
    .unwrap();
    let o = run(&["detect", s(&p), "--json"]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(json(&o)["triangles"], 2);
    std::fs::write(
        &p,
        r#"{"points":[[0,0],[1,0],[1,1],[0,1]],"segments":[[0,1],[1,2],[2,3],[3,0],[0,2],[1,3]]}"#,
    )
    .unwrap();
    let o = run(&["detect", s(&p), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json(&o)["witness"]["kind"], "crossing_segments");
}

#[test]
fn bad_input_exits_2_with_one_line_naming_file_and_line() {
    let d = dir("bad");
    let cases = [
        ("a.node", "3 3 0 0\n1 0 0 0\n2 1 x 0\n3 0 1 0\n", ":3:"),
        ("b.node", "3 3 0 0\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n", ":3:"),
        ("c.node", "4 3 0 0\n1 0 0 0\n", "truncated"),
        ("d.node", "", "empty"),
        ("e.node", "2 3 0 0\n1 0 0 0\n2 0 0 0\n", "coincide"),
    ];
    for (name, text, needle) in cases {
        let p = d.join(name);
        std::fs::write(&p, text).unwrap();
        let o = run(&["detect", s(&p)]);
        assert_eq!(o.status.code(), Some(2), "{name}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        assert!(err.contains(name) && err.contains(needle), "{name}: {err}");
    }
    let node = d.join("f.node");
    std::fs::write(&node, "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n").unwrap();
    for (text, needle) in [
        ("1 0\n1 1 7\n", "out of range"),
        ("1 0\n1 2 2\n", "itself"),
        ("2 0\n1 1 2\n2 2 1\n", "twice"),
    ] {
        let e = d.join("f.edge");
        std::fs::write(&e, text).unwrap();
        let o = run(&["detect", s(&e)]);
        assert_eq!(o.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&o.stderr).contains(needle));
    }
    let o = run(&["detect", "/nonexistent/x.edge"]);
    assert_eq!(o.status.code(), Some(2));
    let o = run(&["frobnicate"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn demo_runs() {
    let o = run(&["demo"]);
    assert!(o.status.success());
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("YES") && text.contains("NO") && text.contains("witness"));
}

#[test]
fn mintetra_yes_with_certified_minimum_and_json_fields() {
    let d = dir("mintetra");
    let p = d.join("bp.off");
    let g = run(&[
        "generate",
        "bp-polyhedron",
        "--core",
        "10",
        "--nets",
        "2",
        "-o",
        s(&p),
    ]);
    assert!(g.status.success(), "{}", String::from_utf8_lossy(&g.stderr));
    let o = run(&["mintetra", s(&p), "--json", "--confirm"]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(v["verdict"], "yes");
    assert_eq!(v["certified"], true);
    assert_eq!(v["minimality"], "confirmed");
    let n = v["vertices"].as_u64().unwrap();
    let polar = v["polar_edges"].as_array().unwrap().len() as u64;
    assert_eq!(v["tetrahedra"].as_u64().unwrap(), n - 3 + polar);
    assert_eq!(v["lower_bound"].as_u64().unwrap(), n - 3);
    assert!(v["levels"].as_u64().unwrap() >= 1);
    let ele = d.join("bp.ele");
    assert_eq!(
        run(&["mintetra", s(&p), "--output", s(&ele)]).status.code(),
        Some(0)
    );
    assert_eq!(run(&["check", s(&ele)]).status.code(), Some(0));
}

#[test]
fn schonhardt_is_a_proved_no_and_its_bp_version_is_not_a_bp_polyhedron() {
    let d = dir("schonhardt");
    let p = d.join("s.obj");
    assert!(
        run(&["generate", "schonhardt", "-o", s(&p)])
            .status
            .success()
    );
    let o = run(&["tetrahedralize", s(&p), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    // None of the 15 tetrahedra on its vertices lies inside it.
    let v = json(&o);
    assert_eq!(v["witness"]["kind"], "no_candidate");
    assert_eq!(v["witness"]["detail"], "no candidate tetrahedron exists");
    let q = d.join("sbp.off");
    assert!(
        run(&["generate", "schonhardt-bp", "-o", s(&q)])
            .status
            .success()
    );
    let o = run(&["mintetra", s(&q), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json(&o)["remaining_vertices"], 6);
    let o = run(&["tetrahedralize", s(&q), "--minimal", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(json(&o)["minimum"], 13);
}

#[test]
fn minimal_triangulation_of_points_in_convex_position() {
    let d = dir("points");
    let p = d.join("cube.xyz");
    std::fs::write(
        &p,
        "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n",
    )
    .unwrap();
    let o = run(&["tetrahedralize", s(&p), "--minimal", "--unique", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(v["minimum"], 5);
    assert_eq!(v["unique"], false); // the two corner-cutting ways
    assert_eq!(v["certified"], true);
}

#[test]
fn bad_polyhedra_exit_2_naming_line_or_faces() {
    let d = dir("badpoly");
    let short = d.join("short.off");
    std::fs::write(&short, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n").unwrap();
    let o = run(&["mintetra", s(&short)]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("short.off:5") && err.contains("ends early"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1);
    let quad = d.join("quad.off");
    std::fs::write(&quad, "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2 3\n").unwrap();
    let err = String::from_utf8_lossy(&run(&["mintetra", s(&quad)]).stderr).to_string();
    assert!(
        err.contains("quad.off:7") && err.contains("only triangles"),
        "{err}"
    );
    let open = d.join("open.obj");
    std::fs::write(&open, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 2 5 3\n").unwrap();
    let o = run(&["mintetra", s(&open)]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("face 1, 4, 5") && err.contains("edge-manifold"),
        "{err}"
    );
}

#[test]
fn time_limit_gives_exit_3_with_bounds() {
    let d = dir("timelimit");
    let p = d.join("pts.xyz");
    // Sixteen points near a sphere: about a second of search, far beyond a zero limit.
    let mut text = String::new();
    for i in 0..16 {
        let (a, z) = (i as f64 * 2.399_963, 1.0 - (2 * i + 1) as f64 / 16.0);
        let r = (1.0 - z * z).sqrt();
        text += &format!(
            "{} {} {}\n",
            (r * a.cos() * 1000.0).round(),
            (r * a.sin() * 1000.0).round(),
            (z * 1000.0).round()
        );
    }
    std::fs::write(&p, text).unwrap();
    let o = run(&[
        "tetrahedralize",
        s(&p),
        "--minimal",
        "--time-limit",
        "0",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(3),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let v = json(&o);
    assert_eq!(v["verdict"], "undecided");
    assert!(v["lower_bound"].as_u64().unwrap() >= 13);
}

/// `mwt --time-limit`: out of time, exit 3 with certified bounds around the optimum and
/// the Delaunay triangulation written; in time, the same answer as without a limit.
#[test]
fn mwt_time_limit_gives_exit_3_with_bounds() {
    let d = dir("mwtlimit");
    let p = d.join("ring.xyz");
    // A 400-gon round one site: about a second of exact work, far beyond a zero limit.
    let mut text = String::new();
    for i in 0..400 {
        let a = i as f64 * std::f64::consts::TAU / 400.0;
        text += &format!("{} {} 0\n", a.cos(), a.sin());
    }
    text += "0.1 0.2 0\n";
    std::fs::write(&p, text).unwrap();
    let off = d.join("t.off");
    let o = run(&[
        "mwt",
        s(&p),
        "--time-limit",
        "0",
        "--json",
        "--output",
        s(&off),
    ]);
    assert_eq!(
        o.status.code(),
        Some(3),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = json(&o);
    assert_eq!(v["verdict"], "undecided");
    assert_eq!(v["lower_bound_from"], "minimum spanning tree");
    assert_eq!(v["triangles"], 2 * 401 - 2 - 400);
    let (lo, hi) = (
        v["lower_bound"].as_f64().unwrap(),
        v["upper_bound"].as_f64().unwrap(),
    );
    let o = run(&["mwt", s(&p), "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let w = json(&o)["weight"].as_f64().unwrap();
    assert!(lo < w && w < hi, "{lo} {w} {hi}");
    let written = std::fs::read_to_string(&off).unwrap();
    assert!(
        written.starts_with("OFF") && written.contains("401 400 0"),
        "{written:.40}"
    );
    let small = d.join("small.xyz");
    std::fs::write(&small, "0 0 0\n4 0 0\n4 3 0\n0 3 0\n1 1.5 0\n").unwrap();
    let o = run(&["mwt", s(&small), "--time-limit", "600", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(json(&o)["edges"], 8);
    assert_eq!(json(&o)["verdict"], "yes");
}

/// A time limit that is not a finite, non-negative number of seconds is a usage error
/// (exit 2, naming the value), never a panic.
#[test]
fn bad_time_limits_are_usage_errors() {
    let d = dir("badlimit");
    let p = d.join("pts.xyz");
    std::fs::write(&p, "0 0 0\n1 0 0\n0 1 0\n0 0 1\n").unwrap();
    for bad in ["nan", "inf", "1e300", "-1", "soon"] {
        let o = run(&["tetrahedralize", s(&p), &format!("--time-limit={bad}")]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains(&format!("'{bad}'")) && !err.contains("panicked"),
            "{err}"
        );
    }
}

#[test]
fn planar_commands_json_fields_outputs_and_bad_input() {
    let d = dir("planar");
    let pts = d.join("p.xyz");
    let o = run(&[
        "generate",
        "points2d",
        "--dist",
        "gaussian",
        "--n",
        "300",
        "-o",
        s(&pts),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = run(&["mwt", s(&pts), "--json", "--output", s(&d.join("t.svg"))]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v = json(&o);
    for k in [
        "vertices",
        "edges",
        "weight",
        "weight_interval",
        "skeleton_edges",
        "faces_left",
        "seconds",
    ] {
        assert!(v.get(k).is_some(), "missing {k}");
    }
    let w = v["weight_interval"].as_array().unwrap();
    assert!(w[0].as_f64().unwrap() <= w[1].as_f64().unwrap());
    assert!(
        std::fs::read_to_string(d.join("t.svg"))
            .unwrap()
            .contains("<line")
    );
    let o = run(&[
        "skeleton",
        s(&pts),
        "--beta",
        "1.2",
        "--lune",
        "--json",
        "--output",
        s(&d.join("e.edge")),
    ]);
    assert!(o.status.success());
    assert!(json(&o)["edges"].as_u64().unwrap() > 0);
    assert!(d.join("e.node").exists());
    // Bad input: exit 2 and one line naming the problem.
    for (args, needle) in [
        (vec!["skeleton", s(&pts), "--beta", "abc"], "--beta"),
        (vec!["keil", "--beta", "1.3"], "does not apply"),
        (
            vec!["keil", "--beta", "1.16", "--check-random", "2"],
            "Cheng",
        ),
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(needle) && err.lines().count() == 1, "{err}");
    }
    let bad = d.join("z.xyz");
    std::fs::write(&bad, "0 0 0\n1 0 0\n0 1 5\n").unwrap();
    let o = run(&["mwt", s(&bad)]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("z.xyz:3") && err.contains("--xy"), "{err}");
    // --xy: the projection is triangulated and each z kept in the mesh (a TIN).
    std::fs::write(&bad, "0 0 0\n1 0 0\n0 1 5\n1 1 2\n0.4 0.5 7\n").unwrap();
    let tin = d.join("tin.obj");
    let o = run(&["mwt", s(&bad), "--xy", "--json", "--output", s(&tin)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(&tin).unwrap();
    let faces = text.lines().filter(|l| l.starts_with("f ")).count();
    assert_eq!(faces as u64, json(&o)["triangles"].as_u64().unwrap());
    assert!(
        text.contains("v 0 1 5") && text.contains("v 0.4 0.5 7"),
        "{text}"
    );
    let off = d.join("tin.off");
    assert!(
        run(&["mwt", s(&bad), "--xy", "--output", s(&off)])
            .status
            .success()
    );
    assert!(
        std::fs::read_to_string(&off)
            .unwrap()
            .starts_with("OFF\n5 4 0\n")
    );
    std::fs::write(&bad, "0 0 1\n1 0 2\n0 0 3\n").unwrap();
    for args in [
        vec!["mwt", s(&bad), "--xy"],
        vec!["skeleton", s(&bad), "--xy", "--beta", "1"],
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains("z.xyz:3") && err.contains("xy-plane") && err.lines().count() == 1,
            "{err}"
        );
    }
    let o = run(&["mwt", s(&pts), "--output", s(&d.join("t.ply"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains(".off or .obj"));
    let dup = d.join("d.xyz");
    std::fs::write(&dup, "0 0\n1 0\n0 0\n").unwrap();
    assert_eq!(
        run(&["skeleton", s(&dup), "--beta", "1"]).status.code(),
        Some(2)
    );
}

#[test]
fn keil_reports_exact_verdicts_and_checks_random_sets() {
    let d = dir("keil");
    let svg = d.join("k.svg");
    let o = run(&[
        "keil",
        "--beta",
        "1.16",
        "--n",
        "420",
        "--json",
        "--svg",
        s(&svg),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v = json(&o);
    assert_eq!(v["xy_in_skeleton"], true);
    assert_eq!(v["xy_in_mwt"], false);
    assert_eq!(v["refutes_keil"], true);
    assert_eq!(v["sites"], 844);
    let (with, without) = (
        &v["weight_with_xy_interval"],
        &v["weight_without_xy_interval"],
    );
    assert!(with[0].as_f64().unwrap() > without[1].as_f64().unwrap());
    for k in [
        "beta",
        "sites",
        "xy_in_mwt",
        "weight_with_xy",
        "weight_without_xy",
        "method",
    ] {
        assert!(v.get(k).is_some(), "missing {k}");
    }
    assert!(
        std::fs::read_to_string(&svg)
            .unwrap()
            .contains("class=\"xy\"")
    );
    let o = run(&[
        "keil",
        "--beta",
        "1.18",
        "--check-random",
        "3",
        "--n",
        "60",
        "--json",
    ]);
    assert!(o.status.success());
    assert_eq!(json(&o)["violations"].as_array().unwrap().len(), 0);
}

/// Generators keep their word or refuse: out-of-range parameters exit 2, corrupt
/// instances are checked NO before they are written, status lines use the user's words.
#[test]
fn generators_keep_their_word_or_refuse() {
    let d = dir("gen");
    for args in [
        vec!["generate", "bipyramid", "--m", "0"],
        vec!["generate", "stacked", "--n", "0"],
        vec![
            "generate",
            "random-tetrahedralization",
            "--points",
            "100",
            "--grid",
            "2",
        ],
    ] {
        let out = d.join("x.off");
        let mut a = args.clone();
        a.extend(["-o", s(&out)]);
        let o = run(&a);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(String::from_utf8_lossy(&o.stderr).lines().count(), 1);
    }
    let o = run(&["keil", "--beta", "1.155", "--n", "0"]);
    assert_eq!(o.status.code(), Some(2));
    // The drop-edge case the issue names, and add-overlap on skew lines: NO every time.
    for (instance, k) in [
        (
            vec![
                "random-tetrahedralization",
                "--points",
                "12",
                "--flips",
                "6",
                "--seed",
                "6",
            ],
            "drop-edge",
        ),
        (vec!["skew-lines", "--points", "40"], "add-overlap"),
    ] {
        let ele = d.join("c.ele");
        let mut a = vec!["generate"];
        a.extend(instance.iter());
        a.extend(["--corrupt", k, "-o", s(&ele)]);
        let o = run(&a);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("corrupted by {k}")));
        let o = run(&["detect", s(&ele.with_extension("edge"))]);
        assert_eq!(o.status.code(), Some(1), "{k}");
        if k == "add-overlap" {
            assert_eq!(run(&["check", s(&ele), "--convex"]).status.code(), Some(1));
        }
    }
}

/// Every NO carries a witness; keil writes its sites; a .node names the convex hull
/// even with a .face beside it.
#[test]
fn one_json_contract() {
    let d = dir("contract");
    let ele = d.join("o.ele");
    run(&[
        "generate",
        "kuhn",
        "--size",
        "2",
        "--corrupt",
        "add-overlap",
        "-o",
        s(&ele),
    ]);
    let v = json(&run(&["check", s(&ele), "--convex", "--json"]));
    assert_eq!(v["verdict"], "no");
    assert!(v["witness"]["kind"].is_string() && v["witness"]["detail"].is_string());
    let off = d.join("s.off");
    run(&["generate", "schonhardt-bp", "-o", s(&off)]);
    let v = json(&run(&["mintetra", s(&off), "--json"]));
    assert_eq!(v["verdict"], "no");
    assert_eq!(v["witness"]["kind"], "not_augmented_bp_polyhedron");
    let sites = d.join("k.xyz");
    let v = json(&run(&[
        "keil",
        "--beta",
        "1.1548",
        "--n",
        "20",
        "-o",
        s(&sites),
        "--json",
    ]));
    let xy = v["xy"].as_array().unwrap();
    let lines = std::fs::read_to_string(&sites).unwrap().lines().count();
    assert_eq!(lines as u64, v["sites"].as_u64().unwrap());
    assert!(xy.iter().all(|i| i.as_u64().unwrap() < lines as u64));
    let bad = run(&[
        "keil",
        "--beta",
        "1.1548",
        "--n",
        "20",
        "-o",
        s(&d.join("k.stl")),
    ]);
    assert_eq!(bad.status.code(), Some(2));
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(err.lines().count() == 1 && err.contains("k.stl"), "{err}");
    // check --manifold refuses what plain check accepts: two boxes along an edge.
    let boxes = tetrakit::generate::two_cubes([1.0, 1.0, 0.0]);
    let ele = d.join("boxes.ele");
    tetrakit::io::write_mesh(&ele, &boxes.points, &boxes.tets, 1).unwrap();
    let v = json(&run(&["check", s(&ele), "--json"]));
    assert_eq!(
        (&v["verdict"], &v["non_manifold_edges"]),
        (&"yes".into(), &1.into())
    );
    let o = run(&["check", s(&ele), "--manifold", "--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json(&o)["witness"]["kind"], "non_manifold_edge");
    let face = d.join("p.face");
    run(&["generate", "bipyramid", "--m", "5", "-o", s(&face)]);
    let v = json(&run(&[
        "tetrahedralize",
        s(&face.with_extension("node")),
        "--json",
    ]));
    assert_eq!(v["domain"], "convex hull");
    assert_eq!(v["faces_beside_not_read"], true);
    let v = json(&run(&["tetrahedralize", s(&face), "--json"]));
    assert_eq!(v["domain"], "polyhedron");
}

/// `shell`: generated nested spheres give a certified YES within 9n − 6 whose output
/// `check` validates; swapped files are one line naming the inner file's point.
#[test]
fn shell_between_nested_spheres() {
    let d = dir("shell");
    let (o, i) = (d.join("o.xyz"), d.join("i.node"));
    let g = run(&[
        "generate",
        "nested",
        "--n-outer",
        "60",
        "--n-inner",
        "30",
        "--gap",
        "0.4",
        "--outer-output",
        s(&o),
        "--inner-output",
        s(&i),
    ]);
    assert!(g.status.success(), "{}", String::from_utf8_lossy(&g.stderr));
    let out = d.join("s.ele");
    let r = run(&["shell", s(&o), s(&i), "--json", "-o", s(&out)]);
    assert_eq!(
        r.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&r.stderr)
    );
    let v = json(&r);
    assert_eq!(
        (v["verdict"].as_str(), v["n"].as_u64()),
        (Some("yes"), Some(90))
    );
    assert!(v["tetrahedra"].as_u64() <= v["bound"].as_u64());
    assert_eq!(v["steiner_points"], 0);
    assert_eq!(run(&["check", s(&out)]).status.code(), Some(0));
    let bad = run(&["shell", s(&i), s(&o)]);
    assert_eq!(bad.status.code(), Some(2));
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(
        err.contains("o.xyz:")
            && err.contains("outside the outer hull")
            && err.lines().count() == 1,
        "{err}"
    );
}

/// A box on a facet of a box where the removal leaves outer vertices no cap takes: the
/// shell is placed instead (`finished_by: "placing"`, said in the text), a certified YES
/// that `check` accepts, never an error.
#[test]
fn shell_finished_by_placing() {
    let d = dir("placing");
    let (o, i, out) = (d.join("o.xyz"), d.join("i.xyz"), d.join("s.ele"));
    let cube = |pts: &[[u8; 3]]| -> String {
        pts.iter()
            .map(|p| format!("{} {} {}\n", p[0], p[1], p[2]))
            .collect()
    };
    let outer: Vec<[u8; 3]> = (0..8u8)
        .map(|i| [i >> 2, (i >> 1) & 1, i & 1].map(|b| 4 * b))
        .collect();
    let inner: Vec<[u8; 3]> = (0..8u8)
        .map(|i| [2 * (i >> 2), 1 + ((i >> 1) & 1), 1 + (i & 1)])
        .collect();
    std::fs::write(&o, cube(&outer)).unwrap();
    std::fs::write(&i, cube(&inner)).unwrap();
    let r = run(&["shell", s(&o), s(&i), "--json", "-o", s(&out)]);
    let v = json(&r);
    assert_eq!(
        (v["verdict"].as_str(), v["finished_by"].as_str()),
        (Some("yes"), Some("placing")),
        "{v}"
    );
    assert_eq!(run(&["check", s(&out)]).status.code(), Some(0));
    let text = String::from_utf8_lossy(&run(&["shell", s(&o), s(&i)]).stdout).to_string();
    assert!(text.starts_with("YES") && text.contains("placed"), "{text}");
}

/// `shell` and `generate nested` on bad input: exit 2 with one line naming the file (and
/// the line where there is one); `--time-limit 0` is exit 3 with verdict "undecided".
#[test]
fn shell_bad_input_and_time_limit() {
    let d = dir("shellbad");
    let cube = "0 0 0\n4 0 0\n0 4 0\n4 4 0\n0 0 4\n4 0 4\n0 4 4\n4 4 4\n";
    let (o, i) = (d.join("o.xyz"), d.join("i.xyz"));
    std::fs::write(&o, cube).unwrap();
    let one_line = |out: &Output, needle: &str| {
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle) && err.lines().count() == 1, "{err}");
    };
    // A flat inner set, planar points, a bad number, a missing file.
    std::fs::write(&i, "1 1 1\n2 1 1\n1 2 1\n2 2 1\n").unwrap();
    one_line(
        &run(&["shell", s(&o), s(&i)]),
        "i.xyz: the inner points span 2",
    );
    std::fs::write(&i, "1 1\n2 1\n1 2\n").unwrap();
    one_line(&run(&["shell", s(&o), s(&i)]), "i.xyz");
    std::fs::write(&i, "1 1 1\n2 1 x\n1 2 1\n1 1 2\n").unwrap();
    one_line(&run(&["shell", s(&o), s(&i)]), "i.xyz:2:");
    one_line(&run(&["shell", s(&o), s(&d.join("none.xyz"))]), "none.xyz");
    // Out of time at once.
    std::fs::write(&i, "1 1 1\n2 1 1\n1 2 1\n1 1 2\n").unwrap();
    let t = run(&["shell", s(&o), s(&i), "--time-limit", "0", "--json"]);
    assert_eq!(t.status.code(), Some(3));
    assert_eq!(json(&t)["verdict"], "undecided");
    // Generator parameters out of range.
    let g = |extra: &[&str]| {
        let mut a = vec![
            "generate",
            "nested",
            "--outer-output",
            s(&o),
            "--inner-output",
            s(&i),
        ];
        a.extend_from_slice(extra);
        run(&a)
    };
    one_line(&g(&["--gap", "1.5"]), "--gap 1.5: expected in (0, 1)");
    one_line(
        &g(&["--outer", "cube", "--n-outer", "5"]),
        "at least 8 points",
    );
    let disk = |ridge: &str| {
        run(&[
            "generate",
            "bern-disk",
            "--ridge",
            ridge,
            "--ring",
            "10",
            "--outer-output",
            s(&o),
            "--inner-output",
            s(&i),
        ])
    };
    one_line(&disk("2"), "--ridge 2: expected at least 3");
    let touch = |kind: &str, n: &str| {
        run(&[
            "generate",
            "contact",
            "--kind",
            kind,
            "--n-inner",
            n,
            "--outer-output",
            s(&o),
            "--inner-output",
            s(&i),
        ])
    };
    one_line(&touch("edge", "3"), "--n-inner 3: expected at least 4");
    for kind in ["vertex", "edge", "facet", "facet-point"] {
        assert!(touch(kind, "12").status.success(), "{kind}");
        let v = json(&run(&["shell", s(&o), s(&i), "--json"]));
        assert_eq!(v["verdict"], "yes", "{kind}: {v}");
        assert!(
            v["tetrahedra"].as_u64() <= v["bound"].as_u64(),
            "{kind}: {v}"
        );
    }
}

/// A Bern disk: the removals exceed 9n − 6, the flips (on by default) bring the mesh
/// within it and say so in JSON; `--no-flips` leaves the removals' mesh and `flips` null.
#[test]
fn shell_flips_on_a_bern_disk() {
    let d = dir("bern");
    let (o, i) = (d.join("o.xyz"), d.join("i.xyz"));
    let g = run(&[
        "generate",
        "bern-disk",
        "--ridge",
        "2500",
        "--ring",
        "250",
        "--outer-output",
        s(&o),
        "--inner-output",
        s(&i),
    ]);
    assert!(g.status.success(), "{}", String::from_utf8_lossy(&g.stderr));
    let v = json(&run(&["shell", s(&o), s(&i), "--json"]));
    assert_eq!(v["verdict"], "yes");
    let (t, before, bound) = (
        v["tetrahedra"].as_u64(),
        v["tetrahedra_before_flips"].as_u64(),
        v["bound"].as_u64(),
    );
    assert!(before > bound && t <= bound, "{v}");
    assert!(v["flips"]["delaunay"].is_object(), "{v}");
    // The weights of §4.4 sum to the removal's interior edges (Lemma 4.9), and Theorem
    // 4.2's claim fails on this removal: the text says so too.
    let w = &v["weights"];
    assert_eq!(
        w["edges"]
            .as_u64()
            .map(|e| e + v["n"].as_u64().unwrap() - 6),
        before,
        "{v}"
    );
    assert!(
        w["max"].as_u64() > Some(8) && w["at_most_8"] == false,
        "{v}"
    );
    let out = run(&["shell", s(&o), s(&i)]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("ABOVE Theorem 4.2's 8"), "{text}");
    let raw = json(&run(&["shell", s(&o), s(&i), "--json", "--no-flips"]));
    assert_eq!(
        (raw["tetrahedra"].as_u64(), raw["flips"].is_null()),
        (before, true)
    );
}

/// `contains`: YES through detect on an exact edge set, NO with a witness in the file's
/// numbering and a DRAT proof beside it, YES from the solver when a diagonal is added.
#[test]
fn contains_answers_with_witness_and_proof() {
    let d = dir("contains");
    let pyramid = |extra: &str| {
        format!(
            "{{\"points\":[[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0.5,0.5,1]],\"segments\":[[0,1],[1,2],[2,3],[3,0],[0,4],[1,4],[2,4],[3,4]{extra}]}}"
        )
    };
    let no = d.join("no.json");
    std::fs::write(&no, pyramid("")).unwrap();
    let drat = d.join("no.drat");
    let o = run(&["contains", s(&no), "--json", "--proof", s(&drat)]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = json(&o);
    assert_eq!(v["verdict"], "no");
    assert_eq!(v["witness"]["kind"], "no_candidate");
    let cnf = std::fs::read_to_string(d.join("no.cnf")).unwrap();
    assert!(cnf.lines().any(|l| l.starts_with("p cnf ")));
    assert_eq!(v["proof"]["formula"], s(&d.join("no.cnf")));
    let yes = d.join("yes.json");
    std::fs::write(&yes, pyramid(",[0,2],[1,3]")).unwrap();
    let out = d.join("yes.ele");
    let o = run(&[
        "contains",
        s(&yes),
        "--json",
        "--minimal",
        "--output",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(
        (v["route"].as_str(), v["tetrahedra"].as_u64()),
        (Some("solver"), Some(2))
    );
    assert_eq!(v["minimum"], true);
    let o = run(&["check", s(&out), "--convex", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    // An exact edge set: detect answers.
    let exact = d.join("exact.json");
    std::fs::write(&exact, pyramid(",[0,2]")).unwrap();
    let v = json(&run(&["contains", s(&exact), "--json"]));
    assert_eq!(
        (v["verdict"].as_str(), v["route"].as_str()),
        (Some("yes"), Some("detect"))
    );
}

/// `constrained`: crossing constraints are a NO naming both in the file's (1-based)
/// numbering, read beside the points or from a second file; planar points get
/// triangles; a zero time limit is undecided (exit 3).
#[test]
fn constrained_witnesses_planar_and_time_limit() {
    let d = dir("constrained");
    let node = d.join("c.node");
    std::fs::write(
        &node,
        "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0.5 1\n",
    )
    .unwrap();
    std::fs::write(d.join("c.edge"), "2 0\n1 1 3\n2 2 4\n").unwrap();
    let o = run(&["constrained", s(&node), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v = json(&o);
    assert_eq!(v["witness"]["kind"], "crossing_constraints");
    assert_eq!(
        v["witness"]["segments"],
        serde_json::json!([[1, 3], [2, 4]])
    );
    assert!(
        v["witness"]["detail"]
            .as_str()
            .unwrap()
            .contains("(#1, #3)")
    );
    let flat = d.join("flat.json");
    std::fs::write(
        &flat,
        "{\"points\":[[0,0],[2,0],[2,2],[0,2],[1,0.5]],\"segments\":[[0,2]]}",
    )
    .unwrap();
    let o = run(&["constrained", s(&flat), "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(
        (v["planar"].as_bool(), v["triangles"].as_u64()),
        (Some(true), Some(4))
    );
    // The constraints from a second file on the same points.
    let o = run(&["constrained", s(&node), s(&d.join("c.edge")), "--json"]);
    assert_eq!(json(&o)["witness"]["kind"], "crossing_constraints");
    let o = run(&["constrained", s(&flat), "--time-limit", "0", "--json"]);
    assert_eq!(o.status.code(), Some(3));
    assert_eq!(json(&o)["verdict"], "undecided");
}

/// Bad input to the new commands: one line, exit 2.
#[test]
fn contains_and_constrained_bad_input() {
    let d = dir("constrain-bad");
    let bad = d.join("bad.json");
    std::fs::write(
        &bad,
        "{\"points\":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]],\"segments\":[[0,9]]}",
    )
    .unwrap();
    for cmd in ["contains", "constrained"] {
        let o = run(&[cmd, s(&bad)]);
        assert_eq!(o.status.code(), Some(2), "{cmd}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{cmd}: {err}");
        assert!(err.contains("bad.json"), "{err}");
    }
    let o = run(&[
        "generate",
        "schonhardt",
        "--twist",
        "-130",
        "-o",
        s(&d.join("x.off")),
    ]);
    assert_eq!(o.status.code(), Some(2));
}

/// `reduce trid-to-tetrad`: the spatial instance has the planar one's answer; collinear
/// points are refused with exit 2 and one line.
#[test]
fn trid_to_tetrad_keeps_the_answer() {
    let d = dir("reduce");
    let planar = d.join("e.json");
    let spokes = "[0,1],[1,2],[2,3],[3,0],[0,4],[1,4],[2,4]";
    for (extra, verdict) in [(",[3,4]", "yes"), ("", "no")] {
        std::fs::write(
            &planar,
            format!(
                "{{\"points\":[[0,0],[2,0],[2,2],[0,2],[1,0.5]],\"segments\":[{spokes}{extra}]}}"
            ),
        )
        .unwrap();
        let spatial = d.join("l.json");
        let o = run(&[
            "reduce",
            "trid-to-tetrad",
            s(&planar),
            s(&spatial),
            "--json",
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert_eq!(json(&o)["points"], 7);
        assert_eq!(
            json(&run(&["contains", s(&planar), "--json"]))["verdict"],
            verdict
        );
        assert_eq!(
            json(&run(&["contains", s(&spatial), "--json"]))["verdict"],
            verdict
        );
        // The thesis's construction: 5 upper, 5 lower points and x*, the same answer.
        let args = ["reduce", "trid-to-tetrad", s(&planar), s(&spatial)];
        let o = run(&[&args[..], &["--construction", "sphere", "--json"]].concat());
        let v = json(&o);
        assert_eq!(
            (v["points"].as_u64(), v["construction"].as_str()),
            (Some(11), Some("sphere"))
        );
        assert!(v["twist_radians"].as_f64().unwrap() > 0.0);
        assert_eq!(
            json(&run(&["contains", s(&spatial), "--json"]))["verdict"],
            verdict
        );
    }
    std::fs::write(
        &planar,
        "{\"points\":[[0,0],[1,0],[2,0],[0,1]],\"segments\":[[0,1]]}",
    )
    .unwrap();
    for construction in ["apexes", "sphere"] {
        let x = d.join("x.json");
        let o = run(&[
            "reduce",
            "trid-to-tetrad",
            s(&planar),
            s(&x),
            "--construction",
            construction,
        ]);
        assert_eq!(o.status.code(), Some(2));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.lines().count() == 1 && err.contains("e.json") && err.contains("collinear"),
            "{construction}: {err}"
        );
    }
}

/// `reduce quasi-prism`: a straight lens takes the thesis's vertex order, a twisted one
/// the SAT orientation, a strongly twisted one (not regular) the exact solver, each
/// certified and written; an odd number of points and a triangle on a lower point are
/// refused with exit 2 and one line naming the file.
#[test]
fn quasi_prism_routes() {
    let d = dir("quasi-prism");
    for (twist, route) in [("0", "order"), ("3", "orientation"), ("20", "exact")] {
        let f = d.join(format!("q{twist}.off"));
        let o = run(&[
            "generate",
            "quasi-prism",
            "--ring",
            "8",
            "--inner",
            "6",
            "--twist",
            twist,
            "-o",
            s(&f),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let ele = d.join(format!("q{twist}.ele"));
        let o = run(&["reduce", "quasi-prism", s(&f), "--json", "-o", s(&ele)]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let v = json(&o);
        assert_eq!(
            (v["route"].as_str(), v["certified"].as_bool()),
            (Some(route), Some(true))
        );
        assert_eq!(v["regular"], twist != "20");
        let check = run(&["check", s(&ele), "--json"]);
        assert_eq!(json(&check)["verdict"], "yes");
    }
    // Not regular, and no tetrahedralization keeps its edges: a NO with the exact
    // solver's witness; stopped at once: undecided.
    let f = d.join("no.off");
    let make = [
        "generate",
        "quasi-prism",
        "--ring",
        "3",
        "--inner",
        "2",
        "--twist",
        "20",
        "--seed",
        "30",
        "-o",
        s(&f),
    ];
    assert!(run(&make).status.success());
    let o = run(&["reduce", "quasi-prism", s(&f), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v = json(&o);
    assert_eq!(
        (v["verdict"].as_str(), v["route"].as_str()),
        (Some("no"), Some("exact"))
    );
    assert!(
        v["witness"]["detail"]
            .as_str()
            .unwrap()
            .contains("no candidate"),
        "{v}"
    );
    let o = run(&[
        "reduce",
        "quasi-prism",
        s(&d.join("q3.off")),
        "--time-limit",
        "0",
        "--json",
    ]);
    assert_eq!(
        (o.status.code(), json(&o)["verdict"].as_str()),
        (Some(3), Some("undecided"))
    );
    let bad = d.join("odd.off");
    std::fs::write(&bad, "OFF\n3 1 0\n0 0 1\n1 0 1\n0 1 1\n3 0 1 2\n").unwrap();
    let o = run(&["reduce", "quasi-prism", s(&bad)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        err.lines().count() == 1 && err.contains("odd.off") && err.contains("images"),
        "{err}"
    );
    std::fs::write(&bad, "OFF\n4 1 0\n0 0 1\n1 0 1\n0 0 0\n1 0 0\n3 0 1 2\n").unwrap();
    let err = String::from_utf8_lossy(&run(&["reduce", "quasi-prism", s(&bad)]).stderr).to_string();
    assert!(err.contains("#2, not an upper vertex"), "{err}");
}

/// The hard families' generators: Chazelle's polyhedron past 60 vertices and a
/// Schönhardt tower are NO for `tetrahedralize`, a dented convex polyhedron is YES, a
/// grid of gadgets is NO for `constrained` with the niche as witness; bad parameters
/// exit 2 with one line.
#[test]
fn hard_family_generators() {
    let d = dir("hard");
    let verdict = |args: &[&str], cmd: &str, file: &Path| {
        let o = run(args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        json(&run(&[cmd, s(file), "--json"]))
    };
    let f = d.join("c.off");
    let v = verdict(
        &["generate", "chazelle", "--grooves", "5", "-o", s(&f)],
        "tetrahedralize",
        &f,
    );
    assert_eq!(
        (v["verdict"].as_str(), v["vertices"].as_u64()),
        (Some("no"), Some(68))
    );
    let f = d.join("t.off");
    let v = verdict(
        &["generate", "schonhardt-tower", "--layers", "3", "-o", s(&f)],
        "tetrahedralize",
        &f,
    );
    assert_eq!(v["verdict"], "no");
    let f = d.join("p.off");
    let v = verdict(
        &[
            "generate",
            "perturbed",
            "--n",
            "30",
            "--seed",
            "2",
            "-o",
            s(&f),
        ],
        "tetrahedralize",
        &f,
    );
    assert_eq!(
        (v["verdict"].as_str(), v["certified"].as_bool()),
        (Some("yes"), Some(true))
    );
    let f = d.join("g.json");
    let v = verdict(
        &[
            "generate",
            "gadget-grid",
            "--rows",
            "1",
            "--cols",
            "2",
            "-o",
            s(&f),
        ],
        "constrained",
        &f,
    );
    assert_eq!(
        (v["verdict"].as_str(), v["witness"]["kind"].as_str()),
        (Some("no"), Some("empty_niche_view"))
    );
    for bad in [
        vec!["generate", "chazelle", "--grooves", "0", "-o", s(&f)],
        vec!["generate", "schonhardt-tower", "--twist", "70", "-o", s(&f)],
        vec![
            "generate",
            "perturbed",
            "--n",
            "10",
            "--dent",
            "1.5",
            "-o",
            s(&f),
        ],
        vec!["generate", "gadget-grid", "--spacing", "1", "-o", s(&f)],
    ] {
        let o = run(&bad);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
        assert_eq!(err.lines().count(), 1, "{bad:?}: {err}");
    }
}

/// `reduce hull-gap`: Schönhardt's polyhedron's gap to its hull is three tetrahedra; a
/// polyhedron with a vertex inside its hull is refused (Lemma 2.6's condition).
#[test]
fn hull_gap_command() {
    let d = dir("hull-gap");
    let f = d.join("s.off");
    assert!(
        run(&["generate", "schonhardt", "-o", s(&f)])
            .status
            .success()
    );
    let o = run(&[
        "reduce",
        "hull-gap",
        s(&f),
        "--json",
        "-o",
        s(&d.join("g.vtk")),
    ]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(json(&o)["tetrahedra"], 3);
    assert!(
        std::fs::read_to_string(d.join("g.vtk"))
            .unwrap()
            .contains("CELL_TYPES 3")
    );
    let o = run(&["reduce", "hull-gap", s(&f), "--time-limit", "0", "--json"]);
    assert_eq!(
        (o.status.code(), json(&o)["verdict"].as_str()),
        (Some(3), Some("undecided"))
    );
    // A tetrahedron with a dent: vertex 4 inside the hull.
    let dent = "OFF\n5 6 0\n0 0 0\n4 0 0\n0 4 0\n0 0 4\n1 1 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 4\n3 2 3 4\n3 3 1 4\n";
    std::fs::write(&f, dent).unwrap();
    let o = run(&["reduce", "hull-gap", s(&f)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2));
    assert!(err.lines().count() == 1 && err.contains("#4"), "{err}");
}

/// `generate niche`: without a point in the view the constraints are a NO explained by
/// the niche; with the centre they are tetrahedralizable; a twist whose faces cross is
/// refused.
#[test]
fn niche_instances() {
    let d = dir("niche");
    let no = d.join("no.json");
    assert!(
        run(&["generate", "niche", "--extra", "5", "-o", s(&no)])
            .status
            .success()
    );
    let o = run(&["constrained", s(&no), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(json(&o)["witness"]["kind"], "empty_niche_view");
    let yes = d.join("yes.edge");
    assert!(
        run(&["generate", "niche", "--in-view", "-o", s(&yes)])
            .status
            .success()
    );
    assert_eq!(
        run(&["constrained", s(&d.join("yes.node"))]).status.code(),
        Some(0)
    );
    let o = run(&["generate", "niche", "--twist", "70", "-o", s(&no)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("not a simple polyhedron"));
}

/// A planar NO speaks of triangles and triangulations, not of the cone's tetrahedra.
#[test]
fn planar_witnesses_speak_of_triangles() {
    let d = dir("planar-witness");
    let p = d.join("w.json");
    std::fs::write(
        &p,
        "{\"points\":[[0,0],[2,0],[2,2],[0,2],[1,0.5]],\"segments\":[[0,1],[1,2],[2,3],[3,0],[0,4],[1,4],[2,4]]}",
    )
    .unwrap();
    let o = run(&["contains", s(&p), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let detail = json(&o)["witness"]["detail"].as_str().unwrap().to_string();
    assert!(
        detail.contains("triangulation") && !detail.contains("tetrahedr"),
        "{detail}"
    );
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

/// The bad inputs of the commands this change added or changed: a `.pvtu` piece outside
/// its folder or missing, `shell --optimum` above the exact solver's size. Exit 2, one
/// line, naming the file (and the line).
#[test]
fn partitioned_and_shell_bad_inputs_exit_2_with_one_line() {
    let d = dir("pvtu-bad");
    let index = d.join("k.pvtu");
    let made = run(&[
        "generate",
        "kuhn",
        "--size",
        "2",
        "-o",
        s(&index),
        "--pieces",
        "2",
    ]);
    assert!(made.status.success());
    let text = std::fs::read_to_string(&index).unwrap();
    let one_line = |o: &Output, wants: &[&str]| {
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        for w in wants {
            assert!(err.contains(w), "{w} in {err}");
        }
    };
    std::fs::write(&index, text.replace("k_1.vtu", "/etc/passwd")).unwrap();
    one_line(
        &run(&["check", s(&index)]),
        &["k.pvtu:", "not a file inside"],
    );
    std::fs::write(&index, text.replace("k_1.vtu", "k_7.vtu")).unwrap();
    one_line(&run(&["check", s(&index)]), &["k_7.vtu"]);
    let (o, i) = (d.join("o.xyz"), d.join("i.xyz"));
    let args = [
        "generate",
        "nested",
        "--n-outer",
        "60",
        "--n-inner",
        "20",
        "--gap",
        "0.3",
    ];
    let made = run(&[
        &args[..],
        &["--outer-output", s(&o), "--inner-output", s(&i)],
    ]
    .concat());
    assert!(made.status.success());
    one_line(
        &run(&["shell", s(&o), s(&i), "--optimum"]),
        &["--optimum", "at most 60 vertices"],
    );
    let _ = std::fs::remove_dir_all(&d);
}
