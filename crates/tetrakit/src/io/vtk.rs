//! Legacy VTK `.vtk`, ASCII, `DATASET UNSTRUCTURED_GRID` (what tetrakit, meshio with
//! `binary=False`, ParaView and VTK write): `POINTS n type`, then `CELLS` in the 4.x
//! layout (`CELLS m size`, one `k i0 … ik−1` per cell) or the 5.x one (`CELLS m+1 size`
//! with `OFFSETS` and `CONNECTIVITY` arrays), then `CELL_TYPES`. Indices are 0-based.
//! Tetrahedra (type 10) and triangles (5) are read, lines (3) as segments and vertices (1)
//! ignored, quadratic tetrahedra, triangles and lines (24, 22, 21) by their corners; any other cell type is an error that counts the cells of that type.
//! `POINT_DATA`/`CELL_DATA` and what follows are not read; `METADATA` is skipped. Binary
//! files ([`is_binary`]) are read by `vtk_binary`. Counts are checked against what is read, never used to size an
//! allocation.

use super::stream::Stream;
use super::{Input, InputError, parse_int, text_of, vertex_ref};
use std::path::Path;

/// The keywords that start a section of an unstructured grid.
const SECTIONS: [&str; 6] = [
    "POINTS",
    "CELLS",
    "CELL_TYPES",
    "POINT_DATA",
    "CELL_DATA",
    "FIELD",
];

/// Whether `bytes` are a legacy VTK file in `BINARY` (its third line says so).
pub(super) fn is_binary(bytes: &[u8]) -> bool {
    let third = bytes.split(|&b| b == b'\n').nth(2).map(|l| l.trim_ascii());
    third == Some(b"BINARY") && bytes.starts_with(b"# vtk DataFile Version")
}

/// Reads an ASCII legacy VTK file from its bytes.
pub(super) fn read(path: &Path, bytes: Vec<u8>) -> Result<Input, InputError> {
    let text = text_of(path, bytes)?;
    let mut head = text.lines();
    let version = head.next().unwrap_or("");
    if !version.starts_with("# vtk DataFile Version") {
        return Err(InputError::new(
            path,
            1,
            "expected '# vtk DataFile Version …'",
        ));
    }
    head.next(); // the title
    match head.next().map(str::trim) {
        Some("ASCII") => {}
        Some(_) => return Err(InputError::new(path, 3, "expected 'ASCII' or 'BINARY'")),
        None => {
            let why = "the file ends before its third line ('ASCII' or 'BINARY')";
            return Err(InputError::new(path, 0, why));
        }
    }
    let rest = text.splitn(4, '\n').nth(3).unwrap_or("");
    let mut s = Stream::new(rest, 3, None, path);
    let mut input = Input {
        dim: 3,
        index_base: 0,
        point_file: path.to_path_buf(),
        tet_file: path.to_path_buf(),
        ..Default::default()
    };
    let (mut cells, mut cell_lines) = (Vec::new(), Vec::new());
    let mut pending = None;
    while let Some((line, key)) = pending.take().or_else(|| s.next()) {
        match key {
            // VTK 9 writes array metadata (names, norms) after POINTS and CELLS: skipped
            // up to the next section.
            "METADATA" => {
                pending = std::iter::from_fn(|| s.next()).find(|(_, k)| SECTIONS.contains(k));
            }
            "DATASET" => {
                let (l, kind) = s.want("the dataset type")?;
                if kind != "UNSTRUCTURED_GRID" {
                    return Err(InputError::new(
                        path,
                        l,
                        format!(
                            "dataset {}: only UNSTRUCTURED_GRID is read",
                            super::quote(kind)
                        ),
                    ));
                }
            }
            "POINTS" => {
                let n = s.count("points")?;
                let (_, ty) = s.want("the coordinate type")?;
                let single = ty == "float";
                for _ in 0..n {
                    let (at, p) = s.point_in(3, single)?;
                    input.points.push(p);
                    input.point_lines.push(at);
                }
            }
            "CELLS" => (cells, cell_lines) = read_cells(&mut s, input.points.len())?,
            "CELL_TYPES" => {
                read_types(&mut s, line, &cells, &cell_lines, &mut input)?;
            }
            "POINT_DATA" | "CELL_DATA" | "FIELD" => break,
            other => {
                return Err(InputError::new(
                    path,
                    line,
                    format!("unknown keyword {}", super::quote(other)),
                ));
            }
        }
    }
    if input.points.is_empty() {
        return Err(InputError::new(path, 0, "no POINTS"));
    }
    Ok(input)
}

/// Cells' points and each cell's line.
type CellList = Result<(Vec<Vec<u32>>, Vec<usize>), InputError>;

/// The `CELLS` section in either layout: each cell's points and its line; the declared
/// number of list entries must be what the cells hold.
fn read_cells(s: &mut Stream, n: usize) -> CellList {
    let m = s.count("cells")?;
    let line = s.line;
    let size = s.count("cell list entries")?;
    let (cells, lines) = read_cell_list(s, n, m)?;
    let used = match lines.len() < m {
        true => cells.iter().map(Vec::len).sum(),
        false => cells.iter().map(|c| c.len() + 1).sum::<usize>(),
    };
    if used != size {
        let why = format!("the CELLS line declares {size} list entries, the cells hold {used}");
        return Err(InputError::new(s.path, line, why));
    }
    Ok((cells, lines))
}

/// The cells of a `CELLS` section (`m` in the 4.x layout; `m − 1` in the 5.x one, where
/// `m` counts the offsets).
fn read_cell_list(s: &mut Stream, n: usize, m: usize) -> CellList {
    let mut cells = Vec::new();
    let mut lines = Vec::new();
    let vertex = |s: &mut Stream| -> Result<u32, InputError> {
        let (l, tok) = s.want("a point index")?;
        vertex_ref(parse_int(tok, s.path, l, "point index")?, 0, n, s.path, l)
    };
    // A cell of `k` points and the line its first point is on.
    let cell = |s: &mut Stream, k: i64| -> Result<(Vec<u32>, usize), InputError> {
        let mut at = s.line;
        let mut c = Vec::new();
        for j in 0..k {
            c.push(vertex(s)?);
            if j == 0 {
                at = s.line;
            }
        }
        Ok((c, at))
    };
    let Some((l, first)) = s.next() else {
        return Ok((cells, lines));
    };
    if first != "OFFSETS" {
        // 4.x: `k i0 … ik−1` per cell; `first` is the first cell's `k`.
        let mut k_tok = Some((l, first));
        for _ in 0..m {
            let (l, tok) = match k_tok.take() {
                Some(t) => t,
                None => s.want("a cell's point count")?,
            };
            let k = parse_int(tok, s.path, l, "cell size")?;
            if !(1..=27).contains(&k) {
                return Err(InputError::new(s.path, l, format!("a cell of {k} points")));
            }
            cells.push(cell(s, k)?.0);
            lines.push(l);
        }
        return Ok((cells, lines));
    }
    // 5.x: OFFSETS type, m offsets (the first 0), CONNECTIVITY type, the indices.
    s.want("the offsets' type")?;
    let mut offsets = Vec::new();
    for _ in 0..m {
        let (l, tok) = s.want("an offset")?;
        let o = parse_int(tok, s.path, l, "offset")?;
        if o < offsets.last().copied().unwrap_or(0) || (offsets.is_empty() && o != 0) {
            return Err(InputError::new(
                s.path,
                l,
                format!("offset {o} out of order"),
            ));
        }
        offsets.push(o);
    }
    let (l, key) = s.want("CONNECTIVITY")?;
    if key != "CONNECTIVITY" {
        return Err(InputError::new(
            s.path,
            l,
            format!("expected CONNECTIVITY, found {}", super::quote(key)),
        ));
    }
    s.want("the connectivity's type")?;
    for w in offsets.windows(2) {
        let (c, at) = cell(s, w[1] - w[0])?;
        cells.push(c);
        lines.push(at);
    }
    Ok((cells, lines))
}

/// The `CELL_TYPES` section: files each cell of `cells` (on `lines`) as a tetrahedron,
/// triangle or segment of `input`, or refuses the first other type with its count.
fn read_types(
    s: &mut Stream,
    line: usize,
    cells: &[Vec<u32>],
    lines: &[usize],
    input: &mut Input,
) -> Result<(), InputError> {
    let m = s.count("cell types")?;
    if m != cells.len() {
        let why = format!("{m} cell types for {} cells", cells.len());
        return Err(InputError::new(s.path, line, why));
    }
    let mut sorter = CellSorter::default();
    for (cell, &at) in cells.iter().zip(lines) {
        let (l, tok) = s.want("a cell type")?;
        let t = parse_int(tok, s.path, l, "cell type")?;
        sorter
            .add(t, cell, at, input)
            .map_err(|why| InputError::new(s.path, at, why))?;
    }
    sorter.finish(input);
    Ok(())
}

/// Files VTK cells (legacy or XML) by type: tetrahedra (10, and the corners of quadratic
/// ones, 24), triangles (5, and 22) and lines (3, and 21) into an [`Input`], vertices (1)
/// ignored, any other type counted; the first of those types is the error of
/// [`CellSorter::finish`].
#[derive(Default)]
pub(super) struct CellSorter {
    other: Option<(i64, usize, usize)>,
    more: usize,
}

impl CellSorter {
    /// Files one cell of type `t` found on line `at`; a known type with the wrong number
    /// of points is an error.
    pub(super) fn add(
        &mut self,
        t: i64,
        cell: &[u32],
        at: usize,
        input: &mut Input,
    ) -> Result<(), String> {
        match (t, cell.len()) {
            // Quadratic cells (24 tetrahedron, 22 triangle, 21 edge) by their corners,
            // which come first.
            (10, 4) | (24, 10) => {
                input.tets.push([cell[0], cell[1], cell[2], cell[3]]);
                input.tet_lines.push(at as u32);
            }
            (5, 3) | (22, 6) => input.faces.push([cell[0], cell[1], cell[2]]),
            (3, 2) | (21, 3) => {
                input.segments.push([cell[0], cell[1]]);
                input.segment_lines.push(at as u32);
            }
            (1, 1) => {}
            (10 | 5 | 3 | 1 | 24 | 22 | 21, k) => {
                return Err(format!("a cell of type {t} with {k} points"));
            }
            _ => match &mut self.other {
                Some((ty, count, _)) if *ty == t => *count += 1,
                Some(_) => self.more += 1,
                None => self.other = Some((t, 1, at)),
            },
        }
        Ok(())
    }

    /// The other types, counted, for [`Input::other_cells`].
    pub(super) fn finish(self, input: &mut Input) {
        if let Some((t, count, line)) = self.other {
            input.other_cells = Some(super::OtherCells {
                count: count + self.more,
                line,
                message: format!(
                    "{count} cells of VTK type {t} (not a tetrahedron, triangle or line){}: only those are read",
                    if self.more > 0 {
                        format!(" and {} of other types", self.more)
                    } else {
                        String::new()
                    }
                ),
            });
        }
    }
}
