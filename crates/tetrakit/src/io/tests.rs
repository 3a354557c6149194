//! Malformed-input tests: each bad file gives an error naming the line and the problem.

use super::*;

/// This run's scratch directory: new and empty, so no earlier run's files (left by a
/// process that had the same id) can be in the way.
fn scratch() -> &'static std::path::Path {
    static DIR: std::sync::OnceLock<tempfile::TempDir> = std::sync::OnceLock::new();
    DIR.get_or_init(|| {
        tempfile::Builder::new()
            .prefix("tetrakit-io-")
            .tempdir()
            .unwrap()
    })
    .path()
}

fn tmp(name: &str, content: &str) -> PathBuf {
    let p = scratch().join(name);
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

/// A `.ele` numbered with gaps (or from another base than its `.node`) is read as TetGen
/// and meshio read it, and its numbers are kept to name tetrahedra; they must increase.
#[test]
fn ele_numbering_with_gaps_is_kept() {
    let two = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";
    tmp("gaps.node", two);
    let input = read_input(&tmp("gaps.ele", "2 4 0\n10 1 2 3 4\n30 2 3 4 5\n")).unwrap();
    assert_eq!(input.tets, [[0, 1, 2, 3], [1, 2, 3, 4]]);
    assert_eq!((input.tet_label(0), input.tet_label(1)), (10, 30));
    tmp("plain.node", two);
    let input = read_input(&tmp("plain.ele", "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n")).unwrap();
    assert!(input.tet_labels.is_empty());
    assert_eq!(input.tet_label(1), 2);
    // A 0-based .ele beside a 1-based .node names its tetrahedra from 0.
    tmp("mixed0.node", two);
    let input = read_input(&tmp("mixed0.ele", "2 4 0\n0 1 2 3 4\n1 2 3 4 5\n")).unwrap();
    assert_eq!(input.tet_label(0), 0);
    tmp("down.node", two);
    let e = err("down.ele", "2 4 0\n10 1 2 3 4\n# c\n7 2 3 4 5\n");
    assert_eq!(e.line, 4);
    assert!(e.message.contains("numbered 7 after 10"), "{e}");
    tmp("neg.node", two);
    let e = err("neg.ele", "1 4 0\n-3 1 2 3 4\n");
    assert!(e.message.contains("numbered -3"), "{e}");
    // Point, edge and face files keep TetGen's consecutive numbering.
    let e = err("gapnode.node", "2 3 0 0\n1 0 0 0\n3 1 1 1\n");
    assert!(e.message.contains("expected 2"), "{e}");
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
    // -0 is 0: the repeat is found though a point at x = -0 sorts between them when
    // -0 and 0 are told apart (they were, until `lex_cmp` tied them).
    let e = err("dupz.xyz", "-0 1 2\n-0 5 5\n0 1 2\n3 3 3\n");
    assert!(e.message.contains("coincide") && e.line == 3, "{e}");
    let e = err("dupz2.xyz", "1 0 -0\n1 -0 7\n1 -0 0\n");
    assert!(e.message.contains("coincide") && e.line == 3, "{e}");
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
    let dir = scratch();
    write_mesh(&dir.join("m.ele"), &pts, &[[0, 1, 2, 3]], 1).unwrap();
    let back = read_input(&dir.join("m.ele")).unwrap();
    assert_eq!(back.points, pts);
    assert_eq!(back.tets, vec![[0, 1, 2, 3]]);
    write_edges(&dir.join("m.obj"), &pts, &[[0, 1], [2, 3]], 1).unwrap();
    assert_eq!(
        read_input(&dir.join("m.obj")).unwrap().segments,
        vec![[0, 1], [2, 3]]
    );
}

/// Siblings keep the named file's stem and case: `M.ELE` reads `M.NODE`, not `m.node`,
/// and two differing candidates are an error, not a silent choice.
#[test]
fn siblings_keep_the_case_of_the_named_file() {
    tmp("case.NODE", NODE);
    let one_tet = "1 4 0\n1 1 2 3 4\n";
    let ele = tmp("case.ELE", one_tet);
    let input = read_input(&ele).unwrap();
    assert_eq!(input.point_file, ele.with_extension("NODE"));
    // A lower-case point file with other contents beside the upper-case one.
    tmp("case.node", "4 3 0 0\n1 0 0 0\n2 2 0 0\n3 0 2 0\n4 0 0 2\n");
    let e = read_input(&ele).unwrap_err();
    assert!(
        e.message.contains("both") && e.message.contains("differ"),
        "{e}"
    );
    // The same contents under both names is one file set.
    tmp("case.node", NODE);
    assert!(read_input(&ele).is_ok());
    // Only a lower-case sibling: it is used.
    tmp("low.node", NODE);
    let input = read_input(&tmp("low.ELE", one_tet)).unwrap();
    assert_eq!(input.point_file, ele.with_file_name("low.node"));
}

/// Values the reader would change, drop or pad are errors.
#[test]
fn nothing_is_silently_changed_or_dropped() {
    // A 10-node tetrahedron: its edge midpoints are range-checked too.
    tmp("quad.node", NODE);
    let e = err("quad.ele", "1 10 0\n1 1 2 3 4 1 2 3 4 1 99\n");
    assert_eq!(e.line, 2);
    assert!(e.message.contains("99"), "{e}");
    tmp("quad2.node", NODE);
    let ok = read_input(&tmp("quad2.ele", "1 10 0\n1 1 2 3 4 1 2 3 4 1 2\n")).unwrap();
    assert_eq!(ok.tets, [[0, 1, 2, 3]]);
    // A JSON point with two coordinates among 3D points is not padded.
    let e = err("mixed.json", r#"{"points": [[0,0,0],[1,0,0],[0,1]]}"#);
    assert!(e.message.contains("points[2]"), "{e}");
    // A decimal that rounds to 0 is refused like one just outside the range.
    let e = err("tiny.xyz", "0 0 0\n1 0 0\n0 1e-400 0\n");
    assert_eq!(e.line, 3);
    assert!(e.message.contains("round to 0"), "{e}");
    assert!(read_input(&tmp("zero.xyz", "0 0 0\n1 0e-400 0\n0 0.000 1\n")).is_ok());
    // An OBJ statement that is neither read nor ignorable names its line.
    let e = err("curve.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\ncurv 0 1 1 2\n");
    assert_eq!(e.line, 4);
    assert!(e.message.contains("curv"), "{e}");
    assert!(
        read_input(&tmp(
            "ok.obj",
            "mtllib a.mtl\no x\nv 0 0 0\nvn 0 0 1\nv 1 0 0\ns off\nv 0 1 0\nf 1 2 3\n"
        ))
        .is_ok()
    );
}

/// Messages quote tokens escaped and cut, and never show a wrapped integer.
#[test]
fn messages_are_one_short_line() {
    let esc = err("esc.xyz", "0 0 0\n1 \u{1b}[31m 0\n");
    assert!(!esc.to_string().contains('\u{1b}'), "{esc}");
    let long = format!("0 0 0\n1 {} 0\n", "7".repeat(5000));
    let e = err("long.xyz", &long);
    assert!(
        e.to_string().len() < 300,
        "{} characters",
        e.to_string().len()
    );
    let e = err(
        "wrap.node",
        "4 3 9223372036854775807 9223372036854775807\n1 0 0 0\n",
    );
    assert!(!e.to_string().contains("18446744073709551"), "{e}");
    assert_eq!(e.line, 1);
}

/// A byte-order mark is read; CR-only line ends, non-UTF-8 bytes and files that are not
/// regular files are refused by name.
#[test]
fn encodings_and_special_files() {
    let bom = read_input(&tmp("bom.xyz", "\u{feff}0 0 0\n1 0 0\n0 1 0\n")).unwrap();
    assert_eq!(bom.points.len(), 3);
    let e = err("cr.xyz", "0 0 0\r1 0 0\r0 1 0\r");
    assert!(e.message.contains("CR"), "{e}");
    let bin = tmp("bin.xyz", "");
    std::fs::write(&bin, b"0 0 0\n1 0 \xff\n").unwrap();
    let e = read_input(&bin).unwrap_err();
    assert_eq!(e.line, 2);
    assert!(e.message.contains("UTF-8"), "{e}");
    let dir = tmp("d.xyz", "");
    std::fs::remove_file(&dir).unwrap();
    std::fs::create_dir_all(&dir).unwrap();
    assert!(
        read_input(&dir)
            .unwrap_err()
            .message
            .contains("regular file")
    );
    if Path::new("/dev/zero").exists() {
        let e = read_text(Path::new("/dev/zero")).unwrap_err();
        assert!(e.message.contains("regular file"), "{e}");
    }
}
