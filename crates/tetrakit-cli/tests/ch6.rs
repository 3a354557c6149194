//! The chapter 6 commands (`flips`, `tetrahedralize --hamiltonian`): exit codes, the JSON
//! fields, the files written, the file's numbering and one clear line for every bad input.

mod common;
use common::*;

const CUBE: &str = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n";

#[test]
fn the_cube_is_connected_and_its_graph_is_written() {
    let d = dir("cube");
    let (pts, graph) = (d.join("cube.xyz"), d.join("g.json"));
    std::fs::write(&pts, CUBE).unwrap();
    let o = run(&[
        "flips",
        pts.to_str().unwrap(),
        "--json",
        "-o",
        graph.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(v["verdict"], "yes");
    assert_eq!(v["connected"], true);
    assert_eq!(
        (v["tetrahedralizations"].as_u64(), v["components"].as_u64()),
        (Some(74), Some(1))
    );
    assert_eq!(v["flips"]["total"], 152);
    let g: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&graph).unwrap()).unwrap();
    assert_eq!(g["tetrahedralizations"].as_array().unwrap().len(), 74);
    assert_eq!(g["flips"].as_array().unwrap().len(), 152);
    assert_eq!(g["points"].as_array().unwrap().len(), 8);
    // The text says the same.
    let o = run(&["flips", pts.to_str().unwrap()]);
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.starts_with("flip graph: YES, connected: 74 tetrahedralizations"),
        "{text}"
    );
}

/// `--count-only`: the cube's 74, each certified, and no graph; at a limit, undecided
/// (exit 3) with at least that many; with `--output`, a usage error.
#[test]
fn counting_only() {
    let d = dir("count");
    let pts = d.join("cube.xyz");
    std::fs::write(&pts, CUBE).unwrap();
    let o = run(&["flips", s(&pts), "--count-only", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(
        (v["verdict"].as_str(), v["tetrahedralizations"].as_u64()),
        (Some("yes"), Some(74))
    );
    assert!(v.get("flips").is_none() && v["certified"] == true && v["cut"].is_null());
    let o = run(&["flips", s(&pts), "--count-only", "--limit", "10", "--json"]);
    assert_eq!(o.status.code(), Some(3));
    assert_eq!(
        (
            json(&o)["tetrahedralizations"].as_u64(),
            json(&o)["cut"].as_str()
        ),
        (Some(10), Some("limit"))
    );
    let text = String::from_utf8(run(&["flips", s(&pts), "--count-only"]).stdout).unwrap();
    assert!(
        text.starts_with("74 tetrahedralizations of the 8 points"),
        "{text}"
    );
    let o = run(&["flips", s(&pts), "--count-only", "-o", s(&d.join("g.json"))]);
    assert_eq!(o.status.code(), Some(2));
    // A 3 × 2 × 2 grid (10,748 in all) cut by a zero time limit: at least that many.
    let grid = d.join("grid.xyz");
    let text: String = (0..12)
        .map(|i| format!("{} {} {}\n", i % 3, i / 3 % 2, i / 6))
        .collect();
    std::fs::write(&grid, text).unwrap();
    let o = run(&[
        "flips",
        s(&grid),
        "--count-only",
        "--time-limit",
        "0",
        "--json",
    ]);
    assert_eq!(
        (o.status.code(), json(&o)["cut"].as_str()),
        (Some(3), Some("time_limit"))
    );
    assert!(json(&o)["tetrahedralizations"].as_u64() < Some(10_748));
}

/// A 1-based TetGen file: the tetrahedralizations name its numbers.
#[test]
fn tetrahedra_are_in_the_files_numbering() {
    let d = dir("base");
    let node = d.join("t.node");
    // Four points: one tetrahedralization, with no flip.
    std::fs::write(&node, "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n").unwrap();
    let o = run(&["flips", node.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(v["tetrahedralizations"], 1);
    let lone = &v["isolated"][0][0];
    let mut corners: Vec<u64> = lone
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap())
        .collect();
    corners.sort_unstable();
    assert_eq!(corners, [1, 2, 3, 4]);
}

#[test]
fn a_limit_or_a_time_limit_is_undecided() {
    let d = dir("limit");
    let pts = d.join("grid.xyz");
    let grid: String = (0..12)
        .map(|i| format!("{} {} {}\n", i % 2, i / 2 % 2, i / 4))
        .collect();
    std::fs::write(&pts, grid).unwrap();
    let o = run(&["flips", pts.to_str().unwrap(), "--json", "--limit", "5"]);
    assert_eq!(o.status.code(), Some(3));
    let v = json(&o);
    assert_eq!(
        (v["verdict"].as_str(), v["cut"].as_str()),
        (Some("undecided"), Some("limit"))
    );
    assert_eq!(v["tetrahedralizations"], 5);
    assert!(v["connected"].is_null() && v.get("components").is_none());
    let o = run(&["flips", pts.to_str().unwrap(), "--time-limit", "0"]);
    assert_eq!(o.status.code(), Some(3));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.starts_with("flip graph: UNDECIDED"), "{text}");
}

/// Bad input: exit 2 and one line naming the file (and the line where there is one).
#[test]
fn bad_points_are_named() {
    let d = dir("bad");
    let cases: [(&str, &str, &str); 5] = [
        (
            "dup.xyz",
            "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 0\n",
            "dup.xyz:5: points 1 and 4 coincide",
        ),
        (
            "flat.xyz",
            "0 0 0\n1 0 0\n0 1 0\n1 1 0\n",
            "flat.xyz: the points are coplanar",
        ),
        ("few.xyz", "0 0 0\n1 0 0\n0 1 1\n", "few.xyz: 3 points"),
        (
            "planar.xyz",
            "0 0\n1 0\n0 1\n1 1\n",
            "planar.xyz: the points are planar",
        ),
        ("nan.xyz", "0 0 0\n1 0 0\n0 1 0\nnan 0 1\n", "nan.xyz:4"),
    ];
    for (name, text, expected) in cases {
        let f = d.join(name);
        std::fs::write(&f, text).unwrap();
        let o = run(&["flips", f.to_str().unwrap()]);
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(2), "{name}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{name}: {err}");
        assert!(err.contains(expected), "{name}: {err}");
    }
}

/// `tetrahedralize --hamiltonian`: the tetrahedra written in path order, each sharing a
/// triangle with the next; a point inside the hull is named at its line.
#[test]
fn a_hamiltonian_path_is_written_in_order() {
    let d = dir("hamiltonian");
    let (pts, out) = (d.join("cube.xyz"), d.join("path.json"));
    std::fs::write(&pts, CUBE).unwrap();
    let o = run(&[
        "tetrahedralize",
        pts.to_str().unwrap(),
        "--hamiltonian",
        "--json",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(
        (v["verdict"].as_str(), v["tetrahedra"].as_u64()),
        (Some("yes"), Some(6))
    );
    let written: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let tets: Vec<Vec<u64>> = serde_json::from_value(written["tets"].clone()).unwrap();
    assert_eq!(tets.len(), 6);
    for w in tets.windows(2) {
        assert_eq!(w[1].iter().filter(|x| w[0].contains(x)).count(), 3);
    }
    assert_eq!(serde_json::to_value(&tets).unwrap(), v["tets"]);
    let inside = d.join("inside.xyz");
    std::fs::write(&inside, format!("{CUBE}0.5 0.5 0.5\n")).unwrap();
    let o = run(&["tetrahedralize", inside.to_str().unwrap(), "--hamiltonian"]);
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("inside.xyz:9: point #8 lies inside the hull"),
        "{err}"
    );
    let o = run(&[
        "tetrahedralize",
        pts.to_str().unwrap(),
        "--hamiltonian",
        "--minimal",
    ]);
    assert_eq!(o.status.code(), Some(2));
}

/// The chapter 6 generators and `--hamiltonian` refuse what they cannot take: exit 2 and
/// one line naming the flag or the file.
#[test]
fn chapter_6_bad_inputs_are_named() {
    let d = dir("gen");
    let off = d.join("x.off");
    let xyz = d.join("x.xyz");
    let planar = d.join("planar.xyz");
    std::fs::write(&planar, "0 0\n1 0\n0 1\n1 1\n").unwrap();
    let (off, xyz, planar) = (
        off.to_str().unwrap(),
        xyz.to_str().unwrap(),
        planar.to_str().unwrap(),
    );
    let cases: [(&[&str], &str); 5] = [
        (
            &["generate", "points3d", "--n", "2", "-o", xyz],
            "--n must be between 4",
        ),
        (
            &[
                "generate",
                "convex-triangulated",
                "--facet-points",
                "20000",
                "-o",
                off,
            ],
            "--facet-points 20000",
        ),
        (
            &[
                "generate",
                "convex-triangulated",
                "--shape",
                "prism",
                "--n",
                "2",
                "-o",
                off,
            ],
            "--n 2",
        ),
        (
            &[
                "generate",
                "convex-triangulated",
                "--shape",
                "lattice",
                "--n",
                "3",
                "-o",
                off,
            ],
            "--n 3",
        ),
        (
            &["tetrahedralize", planar, "--hamiltonian"],
            "planar.xyz: --hamiltonian takes",
        ),
    ];
    for (args, expected) in cases {
        let o = run(args);
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(expected), "{args:?}: {err}");
    }
}

/// A triangulated prism that no tetrahedralization fits: the NO's witness names the
/// vertices of the smallest core of the refutation (in the file's numbering; four, a
/// facet and one vertex across it), and the text says what it covers and pairs.
#[test]
fn a_triangulated_no_names_its_core() {
    let d = dir("core");
    let off = d.join("prism.off");
    let g = run(&[
        "generate",
        "convex-triangulated",
        "--shape",
        "prism",
        "--n",
        "4",
        "--seed",
        "5",
        "-o",
        s(&off),
    ]);
    assert_eq!(g.status.code(), Some(0));
    let o = run(&["tetrahedralize", s(&off), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v = json(&o);
    let w = &v["witness"];
    let vertices = w["vertices"].as_array().unwrap();
    assert_eq!(w["kind"], "unsatisfiable", "{v}");
    assert_eq!(vertices.len(), 4, "{v}");
    assert!(
        w["detail"]
            .as_str()
            .unwrap()
            .contains("the smallest core (fewest vertices) of the refutation")
    );
    let text = String::from_utf8(run(&["tetrahedralize", s(&off)]).stdout).unwrap();
    assert!(text.contains("inner face(s), on"), "{text}");
}
