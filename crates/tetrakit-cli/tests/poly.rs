//! Chapter 3 end to end: `mintetra`, `tetrahedralize` (minimal, proved NOs, bounds at the time limit) and bad polyhedra.

mod common;
use common::*;

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
