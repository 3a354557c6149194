//! Chapter 5 end to end: `skeleton`, `mwt` (with its bounds at the time limit) and `keil`.

mod common;
use common::*;

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

/// `skeleton` and `keil` out of time: exit 3, verdict undecided with what is known (the
/// edges found so far; the sites and the skeleton test), nothing but the sites written.
#[test]
fn skeleton_and_keil_time_limits_are_undecided() {
    let d = dir("limits");
    let p = d.join("u.xyz");
    assert!(
        run(&["generate", "points2d", "--n", "3000", "--output", s(&p)])
            .status
            .success()
    );
    let out = d.join("e.json");
    let o = run(&[
        "skeleton",
        s(&p),
        "--beta",
        "0.5",
        "--time-limit",
        "0",
        "--json",
        "--output",
        s(&out),
    ]);
    assert_eq!(
        o.status.code(),
        Some(3),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = json(&o);
    assert_eq!(
        (v["verdict"].as_str(), v["vertices"].as_u64()),
        (Some("undecided"), Some(3000))
    );
    assert!(!out.exists());
    let o = run(&[
        "skeleton",
        s(&p),
        "--beta",
        "0.5",
        "--time-limit",
        "600",
        "--json",
    ]);
    assert_eq!(
        (o.status.code(), json(&o)["verdict"].as_str()),
        (Some(0), Some("yes"))
    );
    assert!(json(&o)["edges"].as_u64().unwrap() > v["edges"].as_u64().unwrap());
    let (svg, sites) = (d.join("k.svg"), d.join("k.xyz"));
    let args = [
        "keil",
        "--beta",
        "1.16",
        "--time-limit",
        "0",
        "--svg",
        s(&svg),
        "-o",
        s(&sites),
    ];
    let o = run(&[&args[..], &["--json"]].concat());
    assert_eq!(
        o.status.code(),
        Some(3),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v = json(&o);
    assert_eq!(
        (v["verdict"].as_str(), v["xy_in_skeleton"].as_bool()),
        (Some("undecided"), Some(true))
    );
    assert!(v.get("xy_in_mwt").is_none() && v["svg"].is_null() && !svg.exists());
    assert_eq!(
        std::fs::read_to_string(&sites).unwrap().lines().count(),
        2906
    );
    let text = String::from_utf8_lossy(&run(&args).stdout).into_owned();
    assert!(
        text.starts_with("UNDECIDED: stopped at the time limit"),
        "{text}"
    );
    let o = run(&[
        "keil",
        "--beta",
        "1.16",
        "--check-random",
        "2",
        "--time-limit",
        "1",
    ]);
    assert_eq!(o.status.code(), Some(2));
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
