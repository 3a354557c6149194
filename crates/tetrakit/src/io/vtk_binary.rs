//! Legacy VTK `.vtk` in `BINARY` (what VTK's writer and meshio write by default): the
//! sections of the ASCII reader ([`super::vtk`]), keyword lines in ASCII, each followed by
//! its values as big-endian binary (`float`, `double`, `int`, `vtktypeint64`, ... as the
//! line names them). Both cell layouts (4.x `CELLS` lists, 5.x `OFFSETS` and
//! `CONNECTIVITY`); `METADATA` blocks are skipped to their blank line; reading stops at
//! `POINT_DATA`/`CELL_DATA`. Cells are filed by [`CellSorter`]. A count is checked
//! against the bytes left before anything is read for it, and every block of values must
//! be followed by the line break VTK and meshio write after it (or the end of the file),
//! so a block shorter or longer than declared is an error, not a misread. Errors in a
//! keyword line name the line; errors in binary data name the byte offset or the cell.

use super::vtk::CellSorter;
use super::{Input, InputError};
use std::path::Path;

/// Reads a binary legacy VTK file whose first three lines have been checked.
pub(super) fn read(path: &Path, bytes: &[u8]) -> Result<Input, InputError> {
    let mut r = Cursor {
        b: bytes,
        at: 0,
        path,
    };
    for _ in 0..3 {
        r.line();
    }
    let mut input = Input {
        dim: 3,
        point_file: path.to_path_buf(),
        tet_file: path.to_path_buf(),
        ..Default::default()
    };
    let (mut cells, mut cell_line) = (Vec::new(), 0);
    let mut sorter = CellSorter::default();
    while let Some(line) = r.line() {
        let at = r.line_no() - 1;
        let words: Vec<&str> = line.split_ascii_whitespace().collect();
        match words.first().copied() {
            None => {}
            Some("DATASET") if words.get(1) == Some(&"UNSTRUCTURED_GRID") => {}
            Some("POINTS") => {
                let n = r.count(words.get(1), "points")?;
                let c = r.values(n.saturating_mul(3), words.get(2), "point coordinates")?;
                input
                    .points
                    .extend(c.chunks_exact(3).map(|c| [c[0], c[1], c[2]]));
            }
            Some("METADATA") => while r.line().is_some_and(|l| !l.trim().is_empty()) {},
            Some("CELLS") => {
                (cells, cell_line) = (r.cells(&words, input.points.len())?, at);
            }
            Some("CELL_TYPES") => {
                let m = r.count(words.get(1), "cell types")?;
                if m != cells.len() {
                    let why = format!("{m} cell types for {} cells", cells.len());
                    return Err(r.err_line(why));
                }
                let types = r.values(m, Some(&"int"), "cell types")?;
                for (k, (cell, t)) in cells.iter().zip(types).enumerate() {
                    sorter
                        .add(t as i64, cell, cell_line, &mut input)
                        .map_err(|why| {
                            InputError::new(path, cell_line, format!("cell {k}: {why}"))
                        })?;
                }
            }
            Some("POINT_DATA" | "CELL_DATA" | "FIELD") => break,
            Some(_) => {
                let why = format!("unexpected line {}", super::quote(line.trim()));
                return Err(InputError::new(path, at, why));
            }
        }
    }
    sorter.finish(&mut input);
    if input.points.is_empty() {
        return Err(InputError::new(path, 0, "no POINTS"));
    }
    Ok(input)
}

struct Cursor<'b, 'p> {
    b: &'b [u8],
    at: usize,
    path: &'p Path,
}

impl Cursor<'_, '_> {
    /// The line of the current byte.
    fn line_no(&self) -> usize {
        self.b[..self.at.min(self.b.len())]
            .iter()
            .filter(|&&c| c == b'\n')
            .count()
            + 1
    }

    /// An error at the current byte.
    fn err(&self, why: impl Into<String>) -> InputError {
        InputError::at_byte(self.path, self.at.min(self.b.len()), why)
    }

    /// An error in the keyword line just read.
    fn err_line(&self, why: impl Into<String>) -> InputError {
        InputError::new(self.path, self.line_no() - 1, why)
    }

    /// The next line as text (lossy), without its line end.
    fn line(&mut self) -> Option<String> {
        let rest = self.b.get(self.at..).filter(|r| !r.is_empty())?;
        let end = rest.iter().position(|&c| c == b'\n').unwrap_or(rest.len());
        self.at += (end + 1).min(rest.len());
        Some(String::from_utf8_lossy(&rest[..end]).into_owned())
    }

    fn count(&self, word: Option<&&str>, what: &str) -> Result<usize, InputError> {
        word.and_then(|w| w.parse().ok())
            .ok_or_else(|| self.err_line(format!("expected the number of {what}")))
    }

    /// `n` big-endian values of the named type, as `f64` (exact for every type up to
    /// 32-bit integers and for doubles; 64-bit indices are checked to fit below 2^53).
    fn values(&mut self, n: usize, ty: Option<&&str>, what: &str) -> Result<Vec<f64>, InputError> {
        let ty = ty.copied().unwrap_or("");
        let size = match ty {
            "unsigned_char" | "char" => 1,
            "short" | "unsigned_short" => 2,
            "int" | "unsigned_int" | "float" => 4,
            "double" | "long" | "unsigned_long" | "vtktypeint64" | "vtktypeuint64" => 8,
            _ => return Err(self.err_line(format!("{what}: data type {}", super::quote(ty)))),
        };
        let bytes = n
            .checked_mul(size)
            .and_then(|len| self.b.get(self.at..).and_then(|r| r.get(..len)))
            .ok_or_else(|| self.err(format!("{n} {what} claimed, but the file ends first")))?;
        let v = bytes.chunks_exact(size).map(|c| decode(c, ty)).collect();
        self.at += n * size;
        // The values end with a line break before the next keyword (or the file ends).
        match self.b.get(self.at) {
            Some(b'\n') => self.at += 1,
            None => {}
            Some(_) => {
                return Err(self.err(format!(
                    "the {n} {what} end here without the line break that follows binary data: the block is shorter or longer than declared"
                )));
            }
        }
        let v: Vec<f64> = v;
        // Coordinates are checked where every reader's are (`io::validate`); integers
        // of 64 bits must be exact as `f64`.
        let integer = !matches!(ty, "float" | "double");
        if let Some(x) = v.iter().find(|x| integer && size == 8 && x.abs() >= 9.0e15) {
            return Err(self.err(format!("{what}: value {x} out of range")));
        }
        Ok(v)
    }

    /// Indices (checked against `n` points) from values read as `f64`; an error names
    /// the entry and the line of the section.
    fn indices(&self, v: &[f64], n: usize, line: usize) -> Result<Vec<u32>, InputError> {
        (v.iter().enumerate())
            .map(|(k, &x)| {
                (x >= 0.0 && x < n as f64 && x.fract() == 0.0)
                    .then_some(x as u32)
                    .ok_or_else(|| {
                        let why = format!("entry {k} names point {x}, but there are {n} points");
                        InputError::new(self.path, line, why)
                    })
            })
            .collect()
    }

    /// The cells after a `CELLS` line, in the 4.x or the 5.x layout.
    fn cells(&mut self, words: &[&str], n: usize) -> Result<Vec<Vec<u32>>, InputError> {
        let m = self.count(words.get(1), "cells")?;
        let size = self.count(words.get(2), "cell list entries")?;
        let line = self.line_no() - 1;
        let at_line = |why: String| InputError::new(self.path, line, why);
        let save = self.at;
        let next = self.line().unwrap_or_default();
        let head: Vec<&str> = next.split_ascii_whitespace().collect();
        if head.first() != Some(&"OFFSETS") {
            self.at = save;
            let list = self.values(size, Some(&"int"), "cell list entries")?;
            let mut cells = Vec::new();
            let mut rest = &list[..];
            for c in 0..m {
                let k = rest.first().copied().unwrap_or(-1.0);
                if !(1.0..=27.0).contains(&k) || rest.len() <= k as usize {
                    let why = format!("cell {c} has {k} points in a list of {size} entries");
                    return Err(at_line(why));
                }
                cells.push(self.indices(&rest[1..=k as usize], n, line)?);
                rest = &rest[k as usize + 1..];
            }
            if !rest.is_empty() {
                let why = format!(
                    "the CELLS list declares {size} entries, its {m} cells use {}",
                    size - rest.len()
                );
                return Err(at_line(why));
            }
            return Ok(cells);
        }
        let offsets = self.values(m, head.get(1), "offsets")?;
        let conn_line = self.line().unwrap_or_default();
        let conn_head: Vec<&str> = conn_line.split_ascii_whitespace().collect();
        if conn_head.first() != Some(&"CONNECTIVITY") {
            return Err(self.err("expected CONNECTIVITY"));
        }
        let conn = self.values(size, conn_head.get(1), "connectivity")?;
        let conn = self.indices(&conn, n, line)?;
        let ends = (offsets.first(), offsets.last());
        if m > 0 && ends != (Some(&0.0), Some(&(size as f64))) {
            let why = format!(
                "the offsets run from {} to {}, where 0 and the {size} connectivity entries are declared",
                ends.0.unwrap_or(&0.0),
                ends.1.unwrap_or(&0.0)
            );
            return Err(at_line(why));
        }
        (offsets.windows(2).enumerate())
            .map(|(c, w)| {
                let (a, b) = (w[0] as usize, w[1] as usize);
                conn.get(a..b)
                    .map(<[u32]>::to_vec)
                    .filter(|_| a <= b)
                    .ok_or_else(|| at_line(format!("cell {c}: offsets {a}..{b} are out of order")))
            })
            .collect()
    }
}

fn decode(c: &[u8], ty: &str) -> f64 {
    let a = |k: usize| -> [u8; 8] {
        let mut b = [0; 8];
        b[..k].copy_from_slice(&c[..k]);
        b
    };
    match ty {
        "unsigned_char" => f64::from(c[0]),
        "char" => f64::from(c[0] as i8),
        "short" => f64::from(i16::from_be_bytes([c[0], c[1]])),
        "unsigned_short" => f64::from(u16::from_be_bytes([c[0], c[1]])),
        "int" => f64::from(i32::from_be_bytes([c[0], c[1], c[2], c[3]])),
        "unsigned_int" => f64::from(u32::from_be_bytes([c[0], c[1], c[2], c[3]])),
        "float" => f64::from(f32::from_be_bytes([c[0], c[1], c[2], c[3]])),
        "double" => f64::from_be_bytes(a(8)),
        "vtktypeuint64" | "unsigned_long" => u64::from_be_bytes(a(8)) as f64,
        _ => i64::from_be_bytes(a(8)) as f64,
    }
}
