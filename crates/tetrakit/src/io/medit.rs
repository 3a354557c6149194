//! Medit / INRIA `.mesh` (ASCII), as Gmsh, MMG, TetGen (`-g`) and meshio write it
//! (`MeshVersionFormatted 1`: coordinates in single precision, as libMeshb and meshio
//! read them):
//! `MeshVersionFormatted v`, `Dimension 3` (or 2: planar points), then sections, each a
//! keyword, a count and that many entries, until `End` (or the end of the file, which
//! libMeshb and meshio accept too). Read: `Vertices` (coordinates and
//! a reference), `Tetrahedra`, `Triangles` and `Edges` (1-based corners and a reference,
//! which is not kept). Sections that only annotate (`Corners`, `Ridges`, `Required…`,
//! `Normals`, `Tangents`, …) are skipped; cells other than tetrahedra and triangles
//! (`Quadrilaterals`, `Hexahedra`, `Prisms`, `Pyramids`) are an error that counts them,
//! never a silent drop. Tokens are read as a stream, so an entry may span lines; every
//! error names the line. Counts are checked against what is read, never used to size an
//! allocation.

use super::stream::Stream;
use super::{Input, InputError, parse_int, read_text, vertex_ref};
use std::path::Path;

/// Sections skipped, with the number of tokens of one entry (`None`: depends on the
/// dimension, one vector per entry).
const ANNOTATIONS: [(&str, Option<usize>); 10] = [
    ("Corners", Some(1)),
    ("Ridges", Some(1)),
    ("RequiredVertices", Some(1)),
    ("RequiredEdges", Some(1)),
    ("RequiredTriangles", Some(1)),
    ("RequiredTetrahedra", Some(1)),
    ("Normals", None),
    ("Tangents", None),
    ("NormalAtVertices", Some(2)),
    ("TangentAtVertices", Some(2)),
];

/// Cells this reader refuses.
/// Cells not kept, with their corners (each entry also has a reference).
const OTHER_CELLS: [(&str, usize); 4] = [
    ("Quadrilaterals", 4),
    ("Hexahedra", 8),
    ("Prisms", 6),
    ("Pyramids", 5),
];

impl Stream<'_> {
    /// `k` vertex references (1-based) then a reference number, checked.
    fn corners<const K: usize>(
        &mut self,
        n: usize,
        what: &str,
    ) -> Result<(usize, [u32; K]), InputError> {
        let mut out = [0u32; K];
        let mut at = self.line;
        for slot in out.iter_mut() {
            let (line, tok) = self.want(what)?;
            at = line;
            let raw = parse_int(tok, self.path, line, "vertex")?;
            *slot = vertex_ref(raw, 1, n, self.path, line)?;
        }
        let (line, tok) = self.want(&format!("the reference of a {what}"))?;
        parse_int(tok, self.path, line, "reference")?;
        Ok((at, out))
    }
}

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let text = read_text(path)?;
    let mut s = Stream::new(&text, 0, Some('#'), path);
    let mut input = Input {
        dim: 3,
        index_base: 1,
        point_file: path.to_path_buf(),
        tet_file: path.to_path_buf(),
        ..Default::default()
    };
    // Version 1 files hold single-precision reals (libMeshb, meshio).
    let mut single = false;
    while let Some((line, key)) = s.next() {
        match key {
            "MeshVersionFormatted" => {
                let (l, v) = s.want("the version")?;
                single = parse_int(v, path, l, "version")? == 1;
            }
            "Dimension" => {
                let (l, tok) = s.want("the dimension")?;
                input.dim = match parse_int(tok, path, l, "dimension")? {
                    d @ (2 | 3) if input.points.is_empty() => d as usize,
                    d @ (2 | 3) => {
                        return Err(InputError::new(
                            path,
                            l,
                            format!("'Dimension {d}' after the vertices"),
                        ));
                    }
                    d => {
                        return Err(InputError::new(
                            path,
                            l,
                            format!("dimension {d}: only 2 and 3 are meshes of points"),
                        ));
                    }
                };
            }
            "Vertices" => {
                if !input.points.is_empty() {
                    return Err(InputError::new(path, line, "a second 'Vertices' section"));
                }
                for _ in 0..s.count("vertices")? {
                    let (at, p) = s.point_in(input.dim, single)?;
                    let (l, tok) = s.want("the reference of a vertex")?;
                    parse_int(tok, path, l, "reference")?;
                    input.points.push(p);
                    input.point_lines.push(at);
                }
            }
            "Tetrahedra" => {
                for _ in 0..s.count("tetrahedra")? {
                    let (at, t) = s.corners::<4>(input.points.len(), "tetrahedron")?;
                    input.tets.push(t);
                    input.tet_lines.push(at as u32);
                }
            }
            "Triangles" => {
                for _ in 0..s.count("triangles")? {
                    let (_, t) = s.corners::<3>(input.points.len(), "triangle")?;
                    input.faces.push(t);
                }
            }
            "Edges" => {
                for _ in 0..s.count("edges")? {
                    let (at, e) = s.corners::<2>(input.points.len(), "edge")?;
                    input.segments.push(e);
                    input.segment_lines.push(at as u32);
                }
            }
            "End" => break,
            other => skip_or_refuse(&mut s, other, line, &mut input)?,
        }
    }
    if input.points.is_empty() {
        return Err(InputError::new(path, 0, "no 'Vertices' section"));
    }
    Ok(input)
}

/// Skips an annotation section, and other cells (counted in [`Input::other_cells`]);
/// refuses unknown keywords.
fn skip_or_refuse(
    s: &mut Stream,
    key: &str,
    line: usize,
    input: &mut Input,
) -> Result<(), InputError> {
    let skip = |s: &mut Stream, entries: usize| -> Result<(), InputError> {
        for _ in 0..entries {
            s.want(&format!("an entry of '{key}'"))?;
        }
        Ok(())
    };
    if let Some(&(_, per)) = ANNOTATIONS.iter().find(|(k, _)| *k == key) {
        let k = s.count(key)?;
        return skip(s, k * per.unwrap_or(input.dim));
    }
    if let Some(&(_, corners)) = OTHER_CELLS.iter().find(|(k, _)| *k == key) {
        let k = s.count(key)?;
        skip(s, k * (corners + 1))?;
        let o = input.other_cells.get_or_insert_with(|| super::OtherCells {
            line,
            ..Default::default()
        });
        o.count += k;
        let kinds = o.message.split(" besides").next().filter(|m| !m.is_empty());
        let listed = match kinds {
            Some(m) => format!("{m}, {k} {}", key.to_lowercase()),
            None => format!("{k} {}", key.to_lowercase()),
        };
        o.message = format!("{listed} besides tetrahedra and triangles: only those are read");
        return Ok(());
    }
    Err(InputError::new(
        s.path,
        line,
        format!("unknown keyword {}", super::quote(key)),
    ))
}
