//! Bad input never panics: arbitrary and mutated files given to every reader yield either
//! an input or an `InputError` naming the file, and `detect` on whatever parses answers.

mod common;

use proptest::prelude::*;
use tetrakit::control::Control;
use tetrakit::io::read_input;

const NODE: &str = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";
const EDGE: &str = "9 0\n1 1 2\n2 1 3\n3 1 4\n4 2 3\n5 2 4\n6 3 4\n7 2 5\n8 3 5\n9 4 5\n";
const VTK4: &str = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\nCELLS 3 13\n4 0 1 2 3\n4 1 2 3 4\n2 0 4\nCELL_TYPES 3\n10\n10\n3\nCELL_DATA 3\n";
const VTK5: &str = "# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n0 0 0 1 0 0 0 1 0\n0 0 1 1 1 1\nCELLS 4 11\nOFFSETS vtktypeint64\n0 4 8 11\nCONNECTIVITY vtktypeint64\n0 1 2 3\n1 2 3 4\n0 1 2\nCELL_TYPES 3\n10 10 5\n";
const MSH22: &str = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 7 \"solid\"\n$EndPhysicalNames\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n$Elements\n5\n1 15 2 0 1 1\n2 1 2 0 1 1 5\n3 2 2 0 1 1 2 3\n4 4 2 7 1 1 2 3 4\n5 11 2 7 1 2 3 4 5 1 1 1 1 1 1\n$EndElements\n";
const MSH41: &str = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n$Nodes\n2 5 1 5\n3 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n3 1 0 2\n4\n5\n0 0 1\n1 1 1\n$EndNodes\n$Elements\n3 4 1 4\n1 2 1 1\n1 1 5\n2 3 2 1\n2 1 2 3\n3 1 4 2\n3 1 2 3 4\n4 2 3 4 5\n$EndElements\n";
/// A binary Gmsh 4.1 file (as `gmsh -bin` writes it): five nodes in one block, an empty
/// `$Entities`, two tetrahedra and a triangle.
fn msh41_binary() -> Vec<u8> {
    let mut b = b"$MeshFormat\n4.1 1 8\n".to_vec();
    b.extend(1i32.to_le_bytes());
    b.extend(b"\n$EndMeshFormat\n$Entities\n");
    (0..4).for_each(|_| b.extend(0u64.to_le_bytes()));
    b.extend(b"\n$EndEntities\n$Nodes\n");
    let size = |b: &mut Vec<u8>, v: &[u64]| v.iter().for_each(|x| b.extend(x.to_le_bytes()));
    let int = |b: &mut Vec<u8>, v: &[i32]| v.iter().for_each(|x| b.extend(x.to_le_bytes()));
    size(&mut b, &[1, 5, 1, 5]);
    int(&mut b, &[3, 1, 0]);
    size(&mut b, &[5, 1, 2, 3, 4, 5]);
    for p in [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0f64, 1.0, 1.0],
    ] {
        p.iter().for_each(|x| b.extend(x.to_le_bytes()));
    }
    b.extend(b"\n$EndNodes\n$Elements\n");
    size(&mut b, &[2, 3, 1, 3]);
    int(&mut b, &[2, 1, 2]);
    size(&mut b, &[1, 1, 1, 2, 3]);
    int(&mut b, &[3, 1, 4]);
    size(&mut b, &[2, 2, 1, 2, 3, 4, 3, 2, 3, 4, 5]);
    b.extend(b"\n$EndElements\n");
    b
}

const MESH: &str = "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n1 1 1 1\nTetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nTriangles\n1\n1 2 3 0\nEdges\n1\n1 5 0\nCorners\n1\n1\nEnd\n";

fn write(name: &str, text: &str) -> std::path::PathBuf {
    let p = dir_file(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The path of `name` in this run's directory.
fn dir_file(name: &str) -> std::path::PathBuf {
    common::scratch().join(name)
}

/// A valid file with one token replaced, one line dropped or duplicated, or text appended.
fn mutate(base: &'static str) -> impl Strategy<Value = String> {
    let tokens = prop_oneof![
        Just("x".to_string()),
        Just("nan".to_string()),
        Just("-1".to_string()),
        Just("0".to_string()),
        Just("1e400".to_string()),
        Just("99999999999999999999".to_string()),
        Just("".to_string()),
        "[ -~]{0,6}",
    ];
    (0usize..200, tokens, 0usize..4).prop_map(move |(pos, tok, how)| {
        let mut lines: Vec<String> = base.lines().map(String::from).collect();
        let l = pos % lines.len();
        match how {
            0 => {
                let mut t: Vec<String> = lines[l].split_whitespace().map(String::from).collect();
                if !t.is_empty() {
                    let k = pos % t.len();
                    t[k] = tok;
                }
                lines[l] = t.join(" ");
            }
            1 => {
                lines.remove(l);
            }
            2 => {
                let dup = lines[l].clone();
                lines.insert(l, dup);
            }
            _ => lines.push(tok),
        }
        lines.join("\n") + "\n"
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn mutated_tetgen_files_never_panic(node in mutate(NODE), edge in mutate(EDGE)) {
        write("m.node", &node);
        let p = write("m.edge", &edge);
        match read_input(&p) {
            Ok(input) => {
                // Whatever parses is well-formed, so detect answers without error.
                prop_assert!(tetrakit::detect::detect(&input.points, &input.segments, &Default::default(), &Control::new()).is_ok());
            }
            Err(e) => prop_assert!(e.file.ends_with(".node") || e.file.ends_with(".edge")),
        }
    }

    #[test]
    fn mutated_medit_files_never_panic(mesh in mutate(MESH)) {
        let p = write("m.mesh", &mesh);
        if let Err(e) = read_input(&p) {
            prop_assert!(e.file.ends_with("m.mesh") && e.line <= mesh.lines().count());
        }
    }

    #[test]
    fn mutated_vtk_files_never_panic(v4 in mutate(VTK4), v5 in mutate(VTK5)) {
        for (name, text) in [("m4.vtk", &v4), ("m5.vtk", &v5)] {
            if let Err(e) = read_input(&write(name, text)) {
                prop_assert!(e.file.ends_with(name) && e.line <= text.lines().count());
            }
        }
    }

    #[test]
    fn mutated_gmsh_files_never_panic(a in mutate(MSH22), b in mutate(MSH41)) {
        for (name, text) in [("m22.msh", &a), ("m41.msh", &b)] {
            if let Err(e) = read_input(&write(name, text)) {
                prop_assert!(e.file.ends_with(name) && e.line <= text.lines().count());
            }
        }
    }

    #[test]
    fn damaged_binary_gmsh_files_never_panic(at in 0usize..400, byte in any::<u8>(), cut in 0usize..600) {
        let mut b = msh41_binary();
        let at = at % b.len();
        b[at] = byte;
        b.truncate(cut.max(1));
        let p = dir_file("mb.msh");
        std::fs::write(&p, &b).unwrap();
        if let Err(e) = read_input(&p) {
            prop_assert!(e.file.ends_with("mb.msh") && e.line <= 1 + b.iter().filter(|&&c| c == b'\n').count());
        }
    }

    #[test]
    fn damaged_vtk_written_files_never_panic(k in 0usize..10, at in 0usize..2000, byte in any::<u8>(), cut in 0usize..2000) {
        let (name, mut b) = vtk_fixtures().swap_remove(k);
        let at = at % b.len();
        b[at] = byte;
        b.truncate(cut.max(1));
        let p = dir_file(&format!("damaged-{name}"));
        std::fs::write(&p, &b).unwrap();
        if let Err(e) = read_input(&p) {
            prop_assert!(e.line <= 1 + b.iter().filter(|&&c| c == b'\n').count(), "{e}");
        }
    }

    #[test]
    fn arbitrary_text_never_panics(text in "[ -~\n]{0,200}", ext in prop::sample::select(vec!["node", "edge", "ele", "obj", "json", "xyz", "mesh", "vtk", "vtu", "msh", "stl"])) {
        write("a.node", NODE);
        let p = write(&format!("a.{ext}"), &text);
        let _ = read_input(&p);
    }
}

/// Medit `.mesh`: a valid file reads with its sections (1-based corners, references
/// dropped, annotations skipped); each kind of damage is one error naming the line.
#[test]
fn medit_files_read_and_fail_with_the_line() {
    let input = read_input(&write("ok.mesh", MESH)).unwrap();
    assert_eq!(
        (
            input.points.len(),
            input.tets.clone(),
            input.faces.len(),
            input.segments.clone()
        ),
        (5, vec![[0, 1, 2, 3], [1, 2, 3, 4]], 1, vec![[0, 4]])
    );
    let cases = [
        ("1 0 0 1", "1 0 x 1", 6, "'x' is not a number"),
        ("2 3 4 5 0", "2 3 4 6 0", 13, "vertex 6 is out of range"),
        (
            "Corners\n1\n1\n",
            "Hexahedra\n1\n1 2 3 4 5 1 2 3 0\n",
            20,
            "1 hexahedra besides tetrahedra and triangles: only those are read (--tets-only",
        ),
        ("Corners", "Bricks", 20, "unknown keyword 'Bricks'"),
        (
            "Tetrahedra\n2",
            "Tetrahedra\n-2",
            11,
            "negative number of tetrahedra",
        ),
        ("Dimension 3", "Dimension 4", 2, "dimension 4"),
    ];
    // With --tets-only, a mixed mesh reads: its tetrahedra, the other cells counted.
    let mixed = MESH.replacen(
        "Corners\n1\n1\n",
        "Hexahedra\n1\n1 2 3 4 5 1 2 3 0\nPrisms\n2\n1 2 3 4 5 1 0\n1 2 3 4 5 2 0\n",
        1,
    );
    let opts = tetrakit::io::ReadOptions {
        tets_only: true,
        ..Default::default()
    };
    let m = tetrakit::io::read_input_with(&write("mixed.mesh", &mixed), opts).unwrap();
    let o = m.other_cells.unwrap();
    assert_eq!((m.tets.len(), o.count, o.line), (2, 3, 20));
    assert_eq!(
        o.message,
        "1 hexahedra, 2 prisms besides tetrahedra and triangles: only those are read"
    );
    for (from, to, line, needle) in cases {
        let e = read_input(&write("bad.mesh", &MESH.replacen(from, to, 1))).unwrap_err();
        assert!(
            e.line == line && e.message.contains(needle),
            "{from} -> {to}: {e}"
        );
    }
}

/// Gmsh `.msh` 2.2 and 4.1 (ASCII) read the same cells: tetrahedra (the 10-node one by
/// its corners) named by their element tags, with their regions, triangles and lines;
/// points ignored. Damage is one error naming the line.
#[test]
fn gmsh_files_read_and_fail_with_the_line() {
    let old = read_input(&write("ok22.msh", MSH22)).unwrap();
    let new = read_input(&write("ok41.msh", MSH41)).unwrap();
    for (input, labels, regions) in [(&old, [4, 5], [7, 7]), (&new, [3, 4], [1, 1])] {
        assert_eq!(input.points.len(), 5);
        assert_eq!(input.tets, vec![[0, 1, 2, 3], [1, 2, 3, 4]]);
        assert_eq!(
            (input.tet_label(0), input.tet_label(1)),
            (labels[0], labels[1])
        );
        assert_eq!(input.regions, regions);
        assert_eq!(
            (input.faces.clone(), input.segments.clone()),
            (vec![[0, 1, 2]], vec![[0, 4]])
        );
    }
    let cases = [
        (MSH22, "2 1 0 0\n", "2 1 x 0\n", 11, "'x' is not a number"),
        (
            MSH22,
            "4 4 2 7 1 1 2 3 4",
            "4 4 2 7 1 1 2 3 9",
            21,
            "node 9 is not among the 5 nodes",
        ),
        (
            MSH22,
            "3 2 2 0 1 1 2 3",
            "3 3 2 0 1 1 2 3 4",
            20,
            "1 quadrangle element(s) besides",
        ),
        (
            MSH22,
            "3 0 1 0\n",
            "2 0 1 0\n",
            12,
            "node tag 2 is given twice (nodes 2 and 3",
        ),
        (
            MSH22,
            "2.2 0 8",
            "2.2 1 8",
            0,
            "the header says binary but the file is not",
        ),
        (MSH22, "2.2 0 8", "3.0 0 8", 2, "only 2.2 and 4.1"),
        (
            MSH22,
            "$EndNodes",
            "$EndNode",
            15,
            "where $EndNodes was expected",
        ),
        (
            MSH41,
            "3 1 4 2",
            "3 1 4 3",
            32,
            "'$EndElements' is not an integer",
        ),
        (
            MSH41,
            "2 3 2 1\n2 1 2 3\n",
            "2 3 6 1\n2 1 2 3 4 5 1\n",
            28,
            "1 prism element(s)",
        ),
        (MSH41, "3 1 0 2", "3 1 1 2", 17, "parametric nodes"),
    ];
    for (base, from, to, line, needle) in cases {
        let e = read_input(&write("bad.msh", &base.replacen(from, to, 1))).unwrap_err();
        assert!(
            e.line == line && e.message.contains(needle),
            "{from} -> {to}: {e}"
        );
    }
}

/// Binary Gmsh 4.1 reads the same cells as ASCII; a count beyond the file, a node out of
/// range and a big-endian mark are errors with a reason.
#[test]
fn binary_gmsh_files_read_and_fail() {
    let p = dir_file("ok.msh");
    let b = msh41_binary();
    std::fs::write(&p, &b).unwrap();
    let input = read_input(&p).unwrap();
    assert_eq!(input.tets, vec![[0, 1, 2, 3], [1, 2, 3, 4]]);
    assert_eq!((input.tet_label(1), input.regions.clone()), (3, vec![1, 1]));
    assert_eq!(input.faces, vec![[0, 1, 2]]);
    let at = |pat: &[u8]| b.windows(pat.len()).position(|w| w == pat).unwrap();
    let mut big = b.clone();
    let k = at(b"$Nodes\n") + 7;
    big[k..k + 8].copy_from_slice(&u64::MAX.to_le_bytes());
    let mut far = b.clone();
    let k = far.len() - 14 - 8;
    far[k..k + 8].copy_from_slice(&9u64.to_le_bytes());
    let mut endian = b.clone();
    let k = at(b"4.1 1 8\n") + 8;
    endian[k..k + 4].copy_from_slice(&1i32.to_be_bytes());
    for (bytes, needle) in [
        (big, "more than the rest of the file holds"),
        (far, "node 9 is not among the 5 nodes"),
        (endian, "big-endian"),
    ] {
        std::fs::write(&p, &bytes).unwrap();
        let e = read_input(&p).unwrap_err();
        assert!(e.message.contains(needle), "{e}");
    }
}

/// STL, ASCII and binary: a tetrahedron's four triangles by coordinates read as one
/// polyhedron of four vertices (corners merged exactly), the same in both; damage is one
/// error naming the line.
#[test]
fn stl_files_read_as_polyhedra_and_fail_with_the_line() {
    let v = [
        [0.0f32, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    let mut text = String::from("solid t\n");
    let mut bin = vec![0u8; 80];
    bin.extend(4u32.to_le_bytes());
    for f in faces {
        text.push_str("facet normal 0 0 0\nouter loop\n");
        bin.extend([0u8; 12]);
        for k in f {
            let p = v[k];
            text.push_str(&format!("vertex {} {} {}\n", p[0], p[1], p[2]));
            p.iter().for_each(|x| bin.extend(x.to_le_bytes()));
        }
        text.push_str("endloop\nendfacet\n");
        bin.extend([0u8; 2]);
    }
    text.push_str("endsolid t\n");
    let a = tetrakit::io::read_polyhedron(&write("t.stl", &text))
        .unwrap()
        .1;
    let p = dir_file("b.stl");
    std::fs::write(&p, &bin).unwrap();
    let b = tetrakit::io::read_polyhedron(&p).unwrap().1;
    assert_eq!((a.points.len(), a.faces.len()), (4, 4));
    assert_eq!((&a.points, &a.faces), (&b.points, &b.faces));
    let cases = [
        ("vertex 1 0 0\n", "vertex 1 x 0\n", 6, "'x' is not a number"),
        (
            "endloop\nendfacet\nfacet",
            "endloop\nendfacet\nfacte",
            9,
            "unknown keyword 'facte'",
        ),
        (
            "vertex 0 1 0\nendloop",
            "endloop",
            21,
            "a facet with 2 vertices",
        ),
        ("endsolid t\n", "", 0, "missing 'endsolid'"),
        ("vertex 0 1 0\n", "vertex 0 0 0\n", 4, "repeats a corner"),
    ];
    for (from, to, line, needle) in cases {
        let e = read_input(&write("bad.stl", &text.replacen(from, to, 1))).unwrap_err();
        assert!(
            e.line == line && e.message.contains(needle),
            "{from} -> {to}: {e}"
        );
    }
    bin.pop();
    std::fs::write(&p, &bin).unwrap();
    let e = read_input(&p).unwrap_err();
    assert!(e.message.contains("neither binary STL"), "{e}");
}

/// Legacy VTK in both layouts (4.x cell lists, 5.x offsets and connectivity) reads the
/// same cells; tetrakit's own writer reads back; damage is one error naming the line.
#[test]
fn vtk_files_read_and_fail_with_the_line() {
    let old = read_input(&write("ok4.vtk", VTK4)).unwrap();
    assert_eq!(
        (old.points.len(), old.tets.clone(), old.segments.clone()),
        (5, vec![[0, 1, 2, 3], [1, 2, 3, 4]], vec![[0, 4]])
    );
    let new = read_input(&write("ok5.vtk", VTK5)).unwrap();
    assert_eq!(
        (new.tets.clone(), new.faces.clone()),
        (old.tets.clone(), vec![[0, 1, 2]])
    );
    let path = write("own.vtk", "");
    tetrakit::io::write_vtk(&path, &old.points, &old.tets).unwrap();
    assert_eq!(read_input(&path).unwrap().tets, old.tets);
    let cases = [
        (VTK4, "1 0 0\n0 1", "1 0 x\n0 1", 7, "'x' is not a number"),
        (VTK4, "4 1 2 3 4", "4 1 2 3 5", 13, "out of range"),
        (VTK4, "10\n3", "12\n3", 13, "1 cells of VTK type 12"),
        (
            VTK4,
            "CELL_TYPES 3",
            "CELL_TYPES 2",
            15,
            "2 cell types for 3 cells",
        ),
        (VTK4, "ASCII", "TEXT", 3, "expected 'ASCII' or 'BINARY'"),
        (VTK5, "0 4 8 11", "0 8 4 11", 10, "offset 4 out of order"),
        (
            VTK5,
            "DATASET UNSTRUCTURED_GRID",
            "DATASET POLYDATA",
            4,
            "only UNSTRUCTURED_GRID",
        ),
    ];
    for (base, from, to, line, needle) in cases {
        let e = read_input(&write("bad.vtk", &base.replacen(from, to, 1))).unwrap_err();
        assert!(
            e.line == line && e.message.contains(needle),
            "{from} -> {to}: {e}"
        );
    }
}

/// The files VTK 9 itself wrote (`tests/data/vtk`, made with VTK's Python writers): one
/// cube of six tetrahedra, three of them negatively oriented, in every layout of `.vtu`
/// (ASCII; base64 inline; appended raw and base64; zlib or not; both byte orders; 32- and
/// 64-bit headers) and of legacy `.vtk` (ASCII 5.1, binary 5.1 and 4.2).
fn vtk_fixtures() -> Vec<(String, Vec<u8>)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/vtk");
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .map(|p| {
            (
                p.file_name().unwrap().to_string_lossy().into_owned(),
                std::fs::read(&p).unwrap(),
            )
        })
        .collect();
    files.sort();
    let names: Vec<&str> = files.iter().map(|f| f.0.as_str()).collect();
    assert_eq!(files.len(), 10, "{names:?}");
    files
}

#[test]
fn every_layout_vtk_writes_reads_to_one_mesh() {
    let mut seen = None;
    for (name, bytes) in vtk_fixtures() {
        let p = dir_file(&name);
        std::fs::write(&p, &bytes).unwrap();
        let input = read_input(&p).unwrap_or_else(|e| panic!("{name}: {e}"));
        let r = tetrakit::mesh::verify(&input.points, &input.tets, None);
        let inverted: Vec<u32> = r.problems.iter().flat_map(|p| p.cells.clone()).collect();
        let got = (input.points.clone(), input.tets.clone(), inverted);
        assert_eq!(got.2, vec![1, 2, 5], "{name}");
        match &seen {
            None => seen = Some(got),
            Some(first) => assert_eq!(&got, first, "{name}"),
        }
    }
}

/// `.vtu` damage: each case is one error naming the line of the element at fault.
#[test]
fn vtu_files_fail_with_the_line() {
    let ascii = String::from_utf8(
        std::fs::read(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/vtk/ascii.vtu"),
        )
        .unwrap(),
    )
    .unwrap();
    let b64 = String::from_utf8(
        std::fs::read(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("tests/data/vtk/appended_b64_zlib64.vtu"),
        )
        .unwrap(),
    )
    .unwrap();
    let conn_line = 1 + ascii
        .lines()
        .position(|l| l.contains("Name=\"connectivity\""))
        .unwrap();
    let cases: Vec<(&str, String, usize, &str)> = vec![
        (
            &ascii,
            ascii.replacen("UnstructuredGrid", "PolyData", 1),
            0,
            "only UnstructuredGrid",
        ),
        (
            &ascii,
            ascii.replacen("<Points>", "<Points><bad", 1),
            0,
            "malformed XML",
        ),
        (
            &ascii,
            ascii.replacen(
                "type=\"UnstructuredGrid\"",
                "type=\"UnstructuredGrid\" compressor=\"vtkBZip2DataCompressor\"",
                1,
            ),
            0,
            "vtkLZ4DataCompressor are read",
        ),
        (
            &ascii,
            ascii.replacen("format=\"ascii\"", "format=\"hex\"", 1),
            0,
            "DataArray format 'hex'",
        ),
        (
            &b64,
            b64.replacen("encoding=\"base64\"", "encoding=\"gzip\"", 1),
            0,
            "encoding",
        ),
        (
            &b64,
            b64.replacen("offset=\"0\"", "offset=\"999999\"", 1),
            0,
            "past the appended data",
        ),
    ];
    for (base, text, line, needle) in cases {
        assert_ne!(&text, base, "the case must change the file: {needle}");
        let e = read_input(&write("bad.vtu", &text)).unwrap_err();
        assert!(
            e.message.contains(needle) && (line == 0 || e.line == line),
            "{needle}: {e}"
        );
        assert!(
            e.line > 0 || needle == "past the appended data",
            "{needle}: no line in {e}"
        );
    }
    // An offset past the last one, or before the previous one, names the connectivity's
    // line (the fuzzer's 3925868552 once sliced past the 24 entries).
    for offsets in ["4 8 3925868552 16 20 24", "4 8 12 10 20 24"] {
        let bad = ascii.replacen("4 8 12 16 20 24", offsets, 1);
        assert_ne!(bad, ascii);
        let e = read_input(&write("bad.vtu", &bad)).unwrap_err();
        assert!(
            e.line == conn_line && e.message.contains("is not between the previous one"),
            "{e}"
        );
    }
    // A point index out of range names the connectivity's line.
    let bad = ascii.replacen("0 4 6 7 0 4", "9 4 6 7 0 4", 1);
    assert_ne!(bad, ascii);
    let e = read_input(&write("bad.vtu", &bad)).unwrap_err();
    assert!(
        e.line == conn_line && e.message.contains("names point 9"),
        "{e}"
    );
}

/// A compressed block may not claim more than zlib could make of its bytes, and a
/// header may not claim more than the file holds: no allocation follows from either.
#[test]
fn vtu_headers_cannot_size_an_allocation() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/vtk");
    let raw = std::fs::read(dir.join("appended_raw_zlib.vtu")).unwrap();
    let tag = raw.windows(13).position(|w| w == b"<AppendedData").unwrap();
    let at = tag + raw[tag..].iter().position(|&c| c == b'_').unwrap() + 1;
    // The first array's header: blocks, block size, last size (u32, little-endian).
    let mut bomb = raw.clone();
    bomb[at + 4..at + 8].copy_from_slice(&u32::MAX.to_le_bytes());
    bomb[at + 8..at + 12].copy_from_slice(&u32::MAX.to_le_bytes());
    let p = dir_file("bomb.vtu");
    std::fs::write(&p, &bomb).unwrap();
    let e = read_input(&p).unwrap_err();
    assert!(e.message.contains("where 96 bytes are declared"), "{e}");
    let mut many = raw;
    many[at..at + 4].copy_from_slice(&u32::MAX.to_le_bytes());
    std::fs::write(&p, &many).unwrap();
    let e = read_input(&p).unwrap_err();
    assert!(e.message.contains("blocks"), "{e}");
}
