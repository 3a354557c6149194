//! Malformed-input tests: each bad file gives an error naming the line and the problem.

use super::*;

fn tmp(name: &str, content: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tetrakit-io-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, content).unwrap();
    p
}

fn err(name: &str, content: &str) -> InputError {
    read_input(&tmp(name, content)).expect_err("should be rejected")
}

const NODE: &str = "# a tetrahedron\n4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";

#[test]
fn reads_tetgen_one_based_with_comments() {
    let node = tmp("ok1.node", NODE);
    tmp(
        "ok1.edge",
        "6 1\n1 1 2 0\n2 1 3 0\n3 1 4 0\n4 2 3 0\n5 2 4 0\n6 3 4 0 # last\n",
    );
    let input = read_input(&node.with_extension("edge")).unwrap();
    assert_eq!(input.points.len(), 4);
    assert_eq!(input.index_base, 1);
    assert_eq!(input.segments[0], [0, 1]);
}

#[test]
fn reads_zero_based_ele() {
    tmp("ok0.node", "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
    let input = read_input(&tmp("ok0.ele", "1 4 0\n0 0 1 2 3\n")).unwrap();
    assert_eq!(input.tets, vec![[0, 1, 2, 3]]);
}

#[test]
fn rejects_non_numeric_nan_and_range() {
    let e = err("bad1.node", "2 3 0 0\n1 0 0 x\n2 1 1 1\n");
    assert_eq!((e.line, e.message.contains("not a number")), (2, true));
    let e = err("bad2.node", "2 3 0 0\n1 0 0 NaN\n2 1 1 1\n");
    assert!(e.message.contains("not finite"), "{e}");
    let e = err("bad3.node", "2 3 0 0\n1 0 0 1e300\n2 1 1 1\n");
    assert!(e.message.contains("range"), "{e}");
}

#[test]
fn separators_are_ascii_whitespace() {
    // Tabs, carriage returns and form feeds separate tokens; a no-break space does not,
    // and a line holding only one is a row (not a blank line) whose text is named.
    assert_eq!(
        read_input(&tmp(
            "ws.node",
            "4\t3 0 0\r\n1 0\x0c0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
        ))
        .unwrap()
        .points
        .len(),
        4
    );
    let e = err("nbsp.node", "2 3 0 0\n1 0\u{a0}0 0\n2 1 1 1\n");
    assert_eq!(e.line, 2, "{e}");
    let e = err("nbsp2.node", "2 3 0 0\n\u{a0}\n1 0 0 0\n2 1 1 1\n");
    assert_eq!(e.line, 2, "{e}");
}

#[test]
fn rejects_truncated_and_empty() {
    let e = err("trunc.node", "5 3 0 0\n1 0 0 0\n2 1 0 0\n");
    assert!(e.message.contains("truncated"), "{e}");
    let e = err("empty.node", "# nothing\n\n");
    assert!(e.message.contains("empty"), "{e}");
    let e = err("empty.xyz", "");
    assert!(e.message.contains("no points"), "{e}");
}

#[test]
fn rejects_bad_edges() {
    tmp("e.node", NODE);
    let e = err("e.edge", "1 0\n1 1 9\n");
    assert!(e.message.contains("out of range") && e.line == 2, "{e}");
    tmp("loop.node", NODE);
    let e = err("loop.edge", "1 0\n1 2 2\n");
    assert!(e.message.contains("itself"), "{e}");
    tmp("dup.node", NODE);
    let e = err("dup.edge", "2 0\n1 1 2\n2 2 1\n");
    assert!(e.message.contains("twice") && e.line == 3, "{e}");
    let e = err("missing.edge", "1 0\n1 1 2\n");
    assert!(e.message.contains("needs the point file"), "{e}");
}

#[test]
fn rejects_duplicate_points() {
    let e = err("dupp.node", "3 3 0 0\n1 0 0 0\n2 1 1 1\n3 0 0 0\n");
    assert!(e.message.contains("coincide") && e.line == 4, "{e}");
}

#[test]
fn obj_and_json() {
    let input = read_input(&tmp(
        "a.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\nf 1/1 2/2 -1\n",
    ))
    .unwrap();
    assert_eq!(input.segments, vec![[0, 1], [1, 2]]);
    assert_eq!(input.faces, vec![[0, 1, 2]]);
    let e = err("b.obj", "v 0 0 0\nl 1 5\n");
    assert_eq!(e.line, 2);
    let input = read_input(&tmp(
        "a.json",
        r#"{"points":[[0,0,0],[1,0,0]],"segments":[[0,1]]}"#,
    ))
    .unwrap();
    assert_eq!(input.segments, vec![[0, 1]]);
    let e = err(
        "b.json",
        "{\"points\": [[0,0,0],\n [1,0,0]],\n \"segments\": [[0,7]]}",
    );
    assert!(e.message.contains("segments[0]"), "{e}");
    let e = err("c.json", "{\"points\": [[0,0,0],\n [1,0,\"a\"]]}");
    assert_eq!(e.line, 2, "{e}");
}

#[test]
fn written_files_read_back_exactly() {
    let pts = vec![
        [0.1, 0.2, 0.3],
        [1.0 / 3.0, 0.0, 0.0],
        [0.0, 1e-30, 0.0],
        [0.0, 0.0, 7.0],
    ];
    let dir = std::env::temp_dir().join(format!("tetrakit-io-rt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    write_mesh(&dir.join("m.ele"), &pts, &[[0, 1, 2, 3]], 1).unwrap();
    let back = read_input(&dir.join("m.ele")).unwrap();
    assert_eq!(back.points, pts);
    assert_eq!(back.tets, vec![[0, 1, 2, 3]]);
    write_edges(&dir.join("m.obj"), &pts, &[(0, 1), (2, 3)], 1).unwrap();
    assert_eq!(
        read_input(&dir.join("m.obj")).unwrap().segments,
        vec![[0, 1], [2, 3]]
    );
}
