//! Prescribed edges end to end: `contains`, `constrained`, `reduce` and the hard families and niches they are tried on.

mod common;
use common::*;

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
