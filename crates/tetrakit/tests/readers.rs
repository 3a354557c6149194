//! Regressions of the readers, by class: coordinates no reader may let through, headers
//! that may not size an allocation, declared counts that must match the data, what Gmsh
//! and VTK really write, and one-line messages.

mod common;

use base64::Engine;
use std::io::Write;
use std::path::PathBuf;
use tetrakit::io::{InputError, ReadOptions, read_input, read_input_with};
use tetrakit::mesh::{ProblemKind, verify};

fn dir_file(name: &str) -> PathBuf {
    common::scratch().join(name)
}

fn write(name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
    let p = dir_file(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

fn fails(name: &str, bytes: impl AsRef<[u8]>) -> InputError {
    let e = read_input(&write(name, bytes)).unwrap_err();
    assert!(!e.to_string().contains('\n'), "two lines: {e}");
    e
}

const MESH_OPTS: ReadOptions = ReadOptions {
    tets_only: false,
    mesh: true,
};

/// The unit tetrahedron with point 3 at `(0, 0, z)`.
fn tet(z: f64) -> [[f64; 3]; 4] {
    [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, z],
    ]
}

/// A `.vtu` with one piece: inline base64 arrays, uncompressed, 32-bit headers.
fn vtu(
    points: &[[f64; 3]],
    conn: &[i64],
    offsets: &[i64],
    types: &[u8],
    decl: (usize, usize),
) -> String {
    let b64 = |bytes: Vec<u8>| {
        let mut all = (bytes.len() as u32).to_le_bytes().to_vec();
        all.extend(bytes);
        base64::engine::general_purpose::STANDARD.encode(all)
    };
    let f: Vec<u8> = points
        .iter()
        .flatten()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let c: Vec<u8> = conn.iter().flat_map(|x| x.to_le_bytes()).collect();
    let o: Vec<u8> = offsets.iter().flat_map(|x| x.to_le_bytes()).collect();
    format!(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">{}</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"binary\">{}</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">{}</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">{}</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n",
        decl.0,
        decl.1,
        b64(f),
        b64(c),
        b64(o),
        b64(types.to_vec())
    )
}

/// A binary legacy `.vtk` (4.x cell list), big-endian, as VTK writes it.
fn vtk_binary(points: &[[f64; 3]], cells: &[&[i32]], types: &[i32]) -> Vec<u8> {
    let mut b = format!(
        "# vtk DataFile Version 4.2\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS {} double\n",
        points.len()
    )
    .into_bytes();
    points
        .iter()
        .flatten()
        .for_each(|x| b.extend(x.to_be_bytes()));
    let size: usize = cells.iter().map(|c| c.len() + 1).sum();
    b.extend(format!("\nCELLS {} {size}\n", cells.len()).bytes());
    for c in cells {
        b.extend((c.len() as i32).to_be_bytes());
        c.iter().for_each(|v| b.extend(v.to_be_bytes()));
    }
    b.extend(format!("\nCELL_TYPES {}\n", types.len()).bytes());
    types.iter().for_each(|t| b.extend(t.to_be_bytes()));
    b.push(b'\n');
    b
}

/// A binary Gmsh 4.1 file of `points` in one block and tetrahedra in one block.
fn msh41_binary(points: &[[f64; 3]], tets: &[[u64; 4]], totals: (u64, u64)) -> Vec<u8> {
    let mut b = b"$MeshFormat\n4.1 1 8\n".to_vec();
    b.extend(1i32.to_le_bytes());
    b.extend(b"\n$EndMeshFormat\n$Nodes\n");
    let n = points.len() as u64;
    [1, totals.0, 1, n]
        .iter()
        .for_each(|x| b.extend(x.to_le_bytes()));
    [3i32, 1, 0].iter().for_each(|x| b.extend(x.to_le_bytes()));
    b.extend(n.to_le_bytes());
    (1..=n).for_each(|t| b.extend(t.to_le_bytes()));
    points
        .iter()
        .flatten()
        .for_each(|x| b.extend(x.to_le_bytes()));
    b.extend(b"\n$EndNodes\n$Elements\n");
    let m = tets.len() as u64;
    [1, totals.1, 1, m]
        .iter()
        .for_each(|x| b.extend(x.to_le_bytes()));
    [3i32, 1, 4].iter().for_each(|x| b.extend(x.to_le_bytes()));
    b.extend(m.to_le_bytes());
    for (k, t) in tets.iter().enumerate() {
        b.extend((k as u64 + 1).to_le_bytes());
        t.iter().for_each(|x| b.extend(x.to_le_bytes()));
    }
    b.extend(b"\n$EndElements\n");
    b
}

/// Class 1: one out-of-range coordinate is refused by every reader, in the same words,
/// naming the point.
#[test]
fn no_reader_lets_a_coordinate_out_of_range_through() {
    for z in [1e200, 1e-200, f64::NAN, f64::INFINITY, 5e-324, -1e-300] {
        let p = tet(z);
        let text = |f: &dyn Fn(&[f64; 3]) -> String| p.iter().map(f).collect::<String>();
        let xyz = text(&|q| format!("{:e} {:e} {:e}\n", q[0], q[1], q[2]));
        let node = format!("4 3 0 0\n{}", {
            let rows: Vec<String> = (p.iter().enumerate())
                .map(|(k, q)| format!("{} {:e} {:e} {:e}\n", k + 1, q[0], q[1], q[2]))
                .collect();
            rows.concat()
        });
        write("t.node", &node);
        let json = format!(
            "{{\"points\": [[0,0,0],[1,0,0],[0,1,0],[0,0,{}]], \"tets\": [[0,1,2,3]]}}",
            if z.is_finite() {
                format!("{z:e}")
            } else {
                "1e999".into()
            }
        );
        let mut files: Vec<(&str, Vec<u8>)> = vec![
            ("t.xyz", xyz.into_bytes()),
            ("t.ele", b"1 4 0\n1 1 2 3 4\n".to_vec()),
            (
                "t.vtu",
                vtu(&p, &[0, 1, 2, 3], &[4], &[10], (4, 1)).into_bytes(),
            ),
            ("t.vtk", vtk_binary(&p, &[&[0, 1, 2, 3]], &[10])),
            ("t.msh", msh41_binary(&p, &[[1, 2, 3, 4]], (4, 1))),
        ];
        if z.is_finite() || z.is_infinite() {
            files.push(("t.json", json.into_bytes()));
        }
        for (name, bytes) in files {
            let e = read_input_with(&write(name, bytes), MESH_OPTS).unwrap_err();
            let said = e.message.contains("outside the exactly supported")
                || e.message.contains("below the exactly supported")
                || e.message.contains("not a number")
                || e.message.contains("invalid JSON");
            assert!(said, "{name} with z = {z}: {e}");
        }
    }
}

/// Class 2: a compressed block that declares 2^29 bytes for a one-cell `types` array is
/// refused before anything is inflated.
#[test]
fn a_vtu_header_cannot_inflate_past_the_declared_counts() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/vtk");
    let text = std::fs::read_to_string(dir.join("inline_zlib.vtu")).unwrap();
    let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
    z.write_all(&vec![10u8; 1 << 20]).unwrap();
    let packed = z.finish().unwrap();
    let mut head = Vec::new();
    for w in [1u32, 1 << 29, 1 << 29, packed.len() as u32] {
        head.extend(w.to_le_bytes());
    }
    let engine = base64::engine::general_purpose::STANDARD;
    let bomb = format!("{}{}", engine.encode(&head), engine.encode(&packed));
    let e = fails(
        "bomb.vtu",
        text.replacen("AQAAAACAAAAGAAAACwAAAA==eF7j4gIBAADYAD0=", &bomb, 1),
    );
    assert!(
        e.message
            .contains("where 6 bytes are declared by the piece"),
        "{e}"
    );
}

/// Class 3: counts that disagree with the data are errors naming both.
#[test]
fn declared_counts_must_match_the_data() {
    let p = tet(1.0);
    let ok = vtu(&p, &[0, 1, 2, 3], &[4], &[10], (4, 1));
    assert_eq!(read_input(&write("ok.vtu", &ok)).unwrap().tets.len(), 1);
    for (text, needle) in [
        (
            vtu(&p, &[0, 1, 2, 3], &[4], &[10], (5, 1)),
            "where 120 are declared",
        ),
        (
            vtu(&p, &[0, 1, 2, 3], &[4], &[10], (3, 1)),
            "where 72 are declared",
        ),
        (
            vtu(&p, &[0, 1, 2, 3], &[4], &[10], (4, 2)),
            "where 16 are declared",
        ),
        (
            vtu(&p, &[0, 1, 2, 3, 0], &[4], &[10], (4, 1)),
            "where 32 are declared",
        ),
    ] {
        let e = fails("bad.vtu", text);
        assert!(e.message.contains(needle), "{needle}: {e}");
    }
    // A binary .vtk whose POINTS block is one byte short.
    let good = vtk_binary(&p, &[&[0, 1, 2, 3]], &[10]);
    assert_eq!(read_input(&write("ok.vtk", &good)).unwrap().tets.len(), 1);
    let at = good.windows(6).position(|w| w == b"\nCELLS").unwrap();
    let mut short = good.clone();
    short.remove(at - 1);
    let e = fails("short.vtk", short);
    assert!(
        e.message.contains("shorter or longer than declared") && e.byte.is_some(),
        "{e}"
    );
    // Gmsh 4.1 totals.
    for (totals, needle) in [
        ((5, 1), "declares 5 nodes, the blocks hold 4"),
        ((4, 2), "declares 2 elements, the blocks hold 1"),
    ] {
        let e = fails("totals.msh", msh41_binary(&p, &[[1, 2, 3, 4]], totals));
        assert!(e.message.contains(needle), "{e}");
    }
}

/// Class 4: what Gmsh writes reads: sparse tags, lines listed once per physical group,
/// degenerate lines, unused duplicate nodes; coincident tetrahedron vertices are a NO
/// with a witness, not a bad file.
#[test]
fn what_gmsh_writes_reads_and_coincident_vertices_are_a_no() {
    let text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n6\n3 0 0 0\n7 1 0 0\n8 0 1 0\n12 0 0 1\n13 0 0 0\n20 0 0 1\n$EndNodes\n$Elements\n5\n1 1 2 1 1 3 7\n2 1 2 2 1 3 7\n3 1 2 3 2 13 13\n4 15 2 1 1 13\n9 4 2 1 1 3 7 8 12\n$EndElements\n";
    let p = write("gmsh.msh", text);
    let m = read_input_with(&p, MESH_OPTS).unwrap();
    assert_eq!(m.tets, vec![[0, 1, 2, 3]]);
    assert_eq!(
        (m.point_label(3), m.point_label(4), m.tet_label(0)),
        (12, 13, 9)
    );
    assert!(verify(&m.points, &m.tets, None).is_valid());
    // The same file for a command that reads points and segments: the repeat is named.
    let e = read_input(&p).unwrap_err();
    assert!(
        e.message.contains("joins vertex 13 to itself") || e.message.contains("listed twice"),
        "{e}"
    );
    // Two tetrahedra meshed apart, sharing a face by coordinates only.
    let apart = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 0\n6 0 1 0\n7 0 0 1\n8 1 1 1\n$EndNodes\n$Elements\n2\n1 4 2 1 1 1 2 3 4\n2 4 2 2 2 5 7 6 8\n$EndElements\n";
    let m = read_input_with(&write("apart.msh", apart), MESH_OPTS).unwrap();
    let r = verify(&m.points, &m.tets, None);
    let pairs: Vec<_> = (r.problems.iter())
        .filter(|p| p.kind == ProblemKind::CoincidentVertices)
        .map(|p| (p.vertices.clone(), p.cells.clone()))
        .collect();
    assert_eq!(pairs.len(), 3, "{r:?}");
    assert_eq!(pairs[0], (vec![3, 6], vec![0, 1]));
    assert!(read_input(&write("apart2.msh", apart)).is_err());
    // The same with -0 in the second copy: -0 is 0, so the same three pairs.
    let signed = apart.replace("5 1 0 0\n6 0 1 0\n7 0 0 1", "5 1 -0 0\n6 -0 1 0\n7 -0 0 1");
    let m = read_input_with(&write("signed.msh", signed), MESH_OPTS).unwrap();
    let r = verify(&m.points, &m.tets, None);
    let coincident = (r.problems.iter()).filter(|p| p.kind == ProblemKind::CoincidentVertices);
    assert_eq!(coincident.count(), 3, "{r:?}");
}

/// Class 4: Medit without `End`, quadratic VTK tetrahedra by their corners.
#[test]
fn medit_without_end_and_quadratic_vtk_cells_read() {
    let mesh = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nTetrahedra\n1\n1 2 3 4 0\n";
    assert_eq!(
        read_input(&write("noend.mesh", mesh)).unwrap().tets,
        vec![[0, 1, 2, 3]]
    );
    let mut pts = tet(1.0).to_vec();
    let mid =
        |a: usize, b: usize, p: &[[f64; 3]]| std::array::from_fn(|i| (p[a][i] + p[b][i]) / 2.0);
    for (a, b) in [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)] {
        let q = mid(a, b, &pts);
        pts.push(q);
    }
    let conn: Vec<i64> = (0..10).collect();
    let m = read_input(&write("quad.vtu", vtu(&pts, &conn, &[10], &[24], (10, 1)))).unwrap();
    assert_eq!(m.tets, vec![[0, 1, 2, 3]]);
    let cell: Vec<i32> = (0..10).collect();
    let m = read_input(&write("quad.vtk", vtk_binary(&pts, &[&cell], &[24]))).unwrap();
    assert_eq!(m.tets, vec![[0, 1, 2, 3]]);
}

/// Class 5: an XML error quoting a tag with its line break is one line; binary errors
/// name a byte, not a line.
#[test]
fn messages_are_one_line_and_binary_ones_name_a_byte() {
    let e = fails(
        "xml.vtu",
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"1\"\nNumberOfCells=\"0\">\n</Points>\n",
    );
    assert!(e.line > 0, "{e}");
    let e = fails("far.msh", msh41_binary(&tet(1.0), &[[1, 2, 3, 9]], (4, 1)));
    assert!(
        e.byte.is_some() && e.line == 0 && e.to_string().contains(": byte "),
        "{e}"
    );
}

/// Single-precision arrays hold the decimal rounded to `f32`, as VTK, ParaView and meshio
/// read them: `0.1` in a `Float32` array is the point `0.1f32`; a decimal past the `f32`
/// range is refused, not read as a double.
#[test]
fn single_precision_arrays_read_as_every_tool_reads_them() {
    let f = f64::from(0.1f32);
    let vtk = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n0.1 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
    assert_eq!(read_input(&write("f.vtk", vtk)).unwrap().points[0][0], f);
    let dbl = vtk.replace("4 float", "4 double");
    assert_eq!(read_input(&write("d.vtk", dbl)).unwrap().points[0][0], 0.1);
    let medit = "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0.1 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";
    assert_eq!(
        read_input(&write("v1.mesh", medit)).unwrap().points[0][0],
        f
    );
    let v2 = medit.replace("Formatted 1", "Formatted 2");
    assert_eq!(read_input(&write("v2.mesh", v2)).unwrap().points[0][0], 0.1);
    let vtu = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/vtk/ascii.vtu"),
    )
    .unwrap();
    assert!(vtu.contains("type=\"Float32\""));
    let at = vtu.find("0 0 0 0 0 1").unwrap();
    let tenth = [&vtu[..at], "0.1 0 0 0 0 1", &vtu[at + 11..]].concat();
    assert_eq!(read_input(&write("f.vtu", &tenth)).unwrap().points[0][0], f);
    for big in ["1e39", "1e-50"] {
        let e = fails("big.vtk", vtk.replacen("0.1", big, 1));
        assert!(e.message.contains("single-precision range"), "{e}");
        let e = fails(
            "big.vtu",
            [&vtu[..at], big, " 0 0 0 0 1", &vtu[at + 11..]].concat(),
        );
        assert!(e.message.contains("single-precision range"), "{e}");
    }
}
