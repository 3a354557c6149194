//! STL surfaces (`.stl`), ASCII (`solid`, `facet normal`, `outer loop`, three `vertex x y
//! z`, `endloop`, `endfacet`, `endsolid`) and binary (an 80-byte header, a triangle
//! count, 50 bytes per triangle). A file is binary exactly when its size is
//! `84 + 50 × count` (an ASCII header may also begin with `solid`). STL lists each
//! triangle's corners by coordinates: corners with the same exact coordinates are one
//! vertex (binary `f32` values are widened to `f64` exactly), numbered in order of first
//! appearance, so messages name vertices 0-based in that order. Normals are ignored (the
//! orientation is the corners' order). A binary count is checked against the file's size
//! before anything is read.

use super::{Input, InputError, read_bytes, token_lines};
use crate::geom::{Point3, coordinate_in_range, point_key};
use rustc_hash::FxHashMap;
use std::path::Path;

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let bytes = read_bytes(path)?;
    let mut soup = Soup::new(path);
    if is_binary(&bytes) {
        for (k, t) in bytes[84..].chunks_exact(50).enumerate() {
            let f = |j: usize| f32::from_le_bytes([t[j], t[j + 1], t[j + 2], t[j + 3]]) as f64;
            let corners = [0, 1, 2].map(|c| [f(12 + 12 * c), f(16 + 12 * c), f(20 + 12 * c)]);
            soup.triangle(corners, 0, k)?;
        }
    } else {
        ascii(&bytes, &mut soup, path)?;
    }
    if soup.input.faces.is_empty() {
        return Err(InputError::new(path, 0, "no triangles"));
    }
    Ok(soup.input)
}

fn is_binary(bytes: &[u8]) -> bool {
    bytes.len() >= 84 && {
        let count = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as u64;
        84 + 50 * count == bytes.len() as u64
    }
}

/// Triangles by coordinates, merged into vertices.
struct Soup<'p> {
    input: Input,
    index: FxHashMap<[u64; 3], u32>,
    path: &'p Path,
}

impl<'p> Soup<'p> {
    fn new(path: &'p Path) -> Self {
        let input = Input {
            dim: 3,
            index_base: 0,
            point_file: path.to_path_buf(),
            ..Default::default()
        };
        Soup {
            input,
            index: FxHashMap::default(),
            path,
        }
    }

    /// Triangle `k` (read at `line`, 0 for binary files).
    fn triangle(&mut self, corners: [Point3; 3], line: usize, k: usize) -> Result<(), InputError> {
        let mut face = [0u32; 3];
        for (slot, p) in face.iter_mut().zip(corners) {
            if !p.iter().all(|&x| coordinate_in_range(x)) {
                let msg = format!(
                    "triangle {k} has a corner {p:?}, which is not finite or outside the exactly supported magnitude range [2^-142, 2^201]"
                );
                return Err(InputError::new(self.path, line, msg));
            }
            let next = self.input.points.len() as u32;
            *slot = *self.index.entry(point_key(&p)).or_insert(next);
            if *slot == next {
                self.input.points.push(p);
                self.input.point_lines.push(line);
            }
        }
        if face[0] == face[1] || face[1] == face[2] || face[0] == face[2] {
            let msg = format!("triangle {k} repeats a corner: {face:?}");
            return Err(InputError::new(self.path, line, msg));
        }
        self.input.faces.push(face);
        Ok(())
    }
}

/// The ASCII layout: keywords checked in order, three vertices per facet.
fn ascii(bytes: &[u8], soup: &mut Soup, path: &Path) -> Result<(), InputError> {
    let text = std::str::from_utf8(bytes).map_err(|_| {
        InputError::new(
            path,
            0,
            "neither binary STL (size 84 + 50 × count) nor UTF-8 text",
        )
    })?;
    let mut corners = Vec::new();
    let mut ended = false;
    for (line, toks) in token_lines(text) {
        let bad = |what: &str| InputError::new(path, line, what.to_string());
        if ended {
            return Err(bad("text after 'endsolid'"));
        }
        match toks[0] {
            "solid" if line == 1 => {}
            "facet" | "outer" | "endloop" => {}
            "vertex" if toks.len() == 4 => {
                let mut p = [0.0; 3];
                for (c, tok) in p.iter_mut().zip(&toks[1..]) {
                    *c = super::parse_coord(tok, path, line)?;
                }
                corners.push((line, p));
            }
            "vertex" => return Err(bad("a vertex needs three coordinates")),
            "endfacet" => {
                let [(l, a), (_, b), (_, c)] = corners[..] else {
                    return Err(bad(&format!(
                        "a facet with {} vertices (3 expected)",
                        corners.len()
                    )));
                };
                let k = soup.input.faces.len();
                soup.triangle([a, b, c], l, k)?;
                corners.clear();
            }
            "endsolid" => ended = true,
            other => return Err(bad(&format!("unknown keyword {}", super::quote(other)))),
        }
    }
    if !ended {
        return Err(InputError::new(path, 0, "missing 'endsolid'"));
    }
    Ok(())
}
