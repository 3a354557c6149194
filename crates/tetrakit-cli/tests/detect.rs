//! `detect` end to end: the YES with its JSON, the methods agreeing, witnesses in the file's numbering, planar input.

mod common;
use common::*;

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

/// A time limit reached before the answer is UNDECIDED (exit 3) with the counts known,
/// and nothing written; a generous one answers.
#[test]
fn a_time_limit_leaves_detect_undecided() {
    let d = dir("limit");
    let ele = d.join("k.ele");
    assert!(
        run(&["generate", "kuhn", "--size", "4", "-o", s(&ele)])
            .status
            .success()
    );
    let (edge, out) = (d.join("k.edge"), d.join("t.vtk"));
    let o = run(&[
        "detect",
        s(&edge),
        "--links-only",
        "--time-limit",
        "0",
        "--json",
        "--output",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(3));
    let v = json(&o);
    assert_eq!(
        (v["verdict"].as_str(), v["vertices"].as_u64()),
        (Some("undecided"), Some(125))
    );
    assert!(v.get("witness").is_none() && v.get("tetrahedra").is_none() && !out.exists());
    let o = run(&["detect", s(&edge), "--links-only", "--time-limit", "0"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.starts_with("UNDECIDED: stopped at the time limit"),
        "{text}"
    );
    let o = run(&["detect", s(&edge), "--time-limit", "600", "--json"]);
    assert_eq!(
        (o.status.code(), json(&o)["verdict"].as_str()),
        (Some(0), Some("yes"))
    );
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
