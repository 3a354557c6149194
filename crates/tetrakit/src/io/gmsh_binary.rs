//! Gmsh `.msh` 4.1 binary (`file-type 1`, little-endian, 8-byte `size_t`), the layout
//! `gmsh -bin` writes: the same sections as the ASCII 4.1 reader ([`super::gmsh`]), with
//! `int`, `size_t` and `double` fields in place of tokens. `$Entities` is parsed to be
//! skipped; other sections are skipped to their `$End…` line. The same cells are kept
//! and refused as in ASCII, by [`Cells`]. A count is checked against the bytes left
//! before anything is reserved for it; errors name the line the offending byte is on
//! (counting newlines, as a text viewer would).

use super::gmsh::{Cells, element_nodes};
use super::{Input, InputError, vertex_ref};
use std::path::Path;

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let bytes = super::read_bytes(path)?;
    let mut r = Bytes {
        b: &bytes,
        at: 0,
        cells: Cells::new(path),
    };
    r.format()?;
    while let Some(section) = r.header()? {
        match section.as_str() {
            "$Nodes" => r.nodes()?,
            "$Elements" => r.elements()?,
            "$Entities" => r.entities()?,
            _ => {
                r.skip(&section)?;
                continue;
            }
        }
        r.end(&section)?;
    }
    r.cells.finish()
}

/// A cursor over the file's bytes and what has been built.
struct Bytes<'b, 'p> {
    b: &'b [u8],
    at: usize,
    cells: Cells<'p>,
}

impl Bytes<'_, '_> {
    /// An error at the current byte, named by its line.
    fn err(&self, message: impl Into<String>) -> InputError {
        let at = self.at.min(self.b.len());
        let line = 1 + self.b[..at].iter().filter(|&&c| c == b'\n').count();
        InputError::new(self.cells.path, line, message)
    }

    /// Past the newline that ends a section's header line.
    fn step(&mut self) {
        self.at = (self.at + 1).min(self.b.len());
    }

    fn take(&mut self, k: usize, what: &str) -> Result<&[u8], InputError> {
        if self.b.len() - self.at < k {
            return Err(self.err(format!("the file ends inside {what}")));
        }
        self.at += k;
        Ok(&self.b[self.at - k..self.at])
    }

    fn int(&mut self, what: &str) -> Result<i64, InputError> {
        let b = self.take(4, what)?;
        Ok(i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as i64)
    }

    fn size(&mut self, what: &str) -> Result<u64, InputError> {
        let b = self.take(8, what)?;
        Ok(u64::from_le_bytes(b.try_into().unwrap_or([0; 8])))
    }

    fn double(&mut self, what: &str) -> Result<f64, InputError> {
        let b = self.take(8, what)?;
        Ok(f64::from_le_bytes(b.try_into().unwrap_or([0; 8])))
    }

    /// A count of items of `width` bytes each, no more than the bytes left can hold.
    fn count(&mut self, width: usize, what: &str) -> Result<usize, InputError> {
        let k = self.size(what)?;
        let left = (self.b.len() - self.at) as u64;
        if k.saturating_mul(width as u64) > left {
            return Err(self.err(format!(
                "{what} {k} is more than the rest of the file holds"
            )));
        }
        Ok(k as usize)
    }

    /// The next text line (without its newline), after any blank bytes.
    fn line(&mut self) -> Option<String> {
        while self.at < self.b.len() && self.b[self.at].is_ascii_whitespace() {
            self.step();
        }
        if self.at >= self.b.len() {
            return None;
        }
        let end = self.b[self.at..]
            .iter()
            .position(|&c| c == b'\n')
            .map_or(self.b.len(), |k| self.at + k);
        let text = String::from_utf8_lossy(&self.b[self.at..end])
            .trim()
            .to_string();
        self.at = end;
        Some(text)
    }

    /// The next section's `$Name`, or `None` at the end of the file.
    fn header(&mut self) -> Result<Option<String>, InputError> {
        match self.line() {
            None => Ok(None),
            Some(l) if l.starts_with('$') && !l.starts_with("$End") => Ok(Some(l)),
            Some(l) => Err(self.err(format!("{} outside a section", super::quote(&l)))),
        }
    }

    fn end(&mut self, section: &str) -> Result<(), InputError> {
        let want = format!("$End{}", &section[1..]);
        match self.line() {
            Some(l) if l == want => Ok(()),
            Some(l) => Err(self.err(format!("{} where {want} was expected", super::quote(&l)))),
            None => Err(self.err(format!("the file ends where {want} was expected"))),
        }
    }

    /// `$MeshFormat`, `4.1 1 8`, the binary 1, `$EndMeshFormat`.
    fn format(&mut self) -> Result<(), InputError> {
        if self.line().as_deref() != Some("$MeshFormat") {
            return Err(self.err("no $MeshFormat section: not a Gmsh file"));
        }
        let version = self.line().unwrap_or_default();
        let fields: Vec<&str> = version.split_ascii_whitespace().collect();
        if fields != ["4.1", "1", "8"] {
            return Err(self.err(format!(
                "binary Gmsh header {}: only 4.1 with 8-byte sizes is read",
                super::quote(&version)
            )));
        }
        self.step(); // the newline after the header
        if self.int("the byte-order mark")? != 1 {
            return Err(self.err("a big-endian binary .msh file: only little-endian is read"));
        }
        self.end("$MeshFormat")
    }

    /// Skips a section this reader does not use, to its `$End…` line.
    fn skip(&mut self, section: &str) -> Result<(), InputError> {
        let want = format!("\n$End{}", &section[1..]);
        let found = self.b[self.at..]
            .windows(want.len())
            .position(|w| w == want.as_bytes());
        match found {
            Some(k) => {
                self.at += k + want.len();
                Ok(())
            }
            None => Err(self.err(format!("{section} has no {}", &want[1..]))),
        }
    }

    /// `$Entities`: points, curves, surfaces and volumes with their tags, boxes and
    /// bounding entities, read only to be passed.
    fn entities(&mut self) -> Result<(), InputError> {
        self.step();
        let mut counts = [0; 4];
        for c in counts.iter_mut() {
            *c = self.count(4, "the number of entities")?;
        }
        for (dim, &k) in counts.iter().enumerate() {
            for _ in 0..k {
                self.int("an entity tag")?;
                let doubles = if dim == 0 { 3 } else { 6 };
                self.take(8 * doubles, "an entity's box")?;
                let lists = if dim == 0 { 1 } else { 2 };
                for _ in 0..lists {
                    let n = self.count(4, "the number of an entity's tags")?;
                    self.take(4 * n, "an entity's tags")?;
                }
            }
        }
        Ok(())
    }

    fn nodes(&mut self) -> Result<(), InputError> {
        self.step();
        let blocks = self.count(20, "the number of node blocks")?;
        self.take(24, "the node counts")?;
        for _ in 0..blocks {
            self.take(8, "a node block's entity")?;
            if self.int("the parametric flag")? != 0 {
                return Err(self.err("parametric nodes are not read"));
            }
            let k = self.count(32, "the number of nodes in a block")?;
            let tags_at = self.at;
            self.take(8 * k, "the node tags")?;
            for j in 0..k {
                let t = &self.b[tags_at + 8 * j..tags_at + 8 * j + 8];
                let tag = u64::from_le_bytes(t.try_into().unwrap_or([0; 8]));
                let mut p = [0.0; 3];
                for c in p.iter_mut() {
                    *c = self.double("a coordinate")?;
                    if !crate::geom::coordinate_in_range(*c) {
                        return Err(self.err(format!(
                            "coordinate {c} of node {tag} is not a finite number in the exact range"
                        )));
                    }
                }
                let tag = i64::try_from(tag).unwrap_or(-1);
                self.cells
                    .node(0, tag, p, 0)
                    .map_err(|e| self.err(e.message))?;
            }
        }
        Ok(())
    }

    fn elements(&mut self) -> Result<(), InputError> {
        self.step();
        let blocks = self.count(20, "the number of element blocks")?;
        self.take(24, "the element counts")?;
        let n = self.cells.input.points.len();
        for _ in 0..blocks {
            self.int("an entity dimension")?;
            let region = self.int("an entity tag")?;
            let kind = self.int("an element type")?;
            let Some((nodes, name)) = element_nodes(kind) else {
                return Err(self.err(format!("unknown element type {kind}")));
            };
            let k = self.count(8 * (1 + nodes), "the number of elements in a block")?;
            let mut corners = Vec::with_capacity(nodes);
            for _ in 0..k {
                let tag = self.size("an element tag")? as i64;
                corners.clear();
                for _ in 0..nodes {
                    let raw = self.size("a node tag")?;
                    let raw = i64::try_from(raw).unwrap_or(-1);
                    let v = vertex_ref(raw, 1, n, self.cells.path, 0)
                        .map_err(|e| self.err(e.message))?;
                    corners.push(v);
                }
                self.cells
                    .keep(0, tag, name, &corners, region)
                    .map_err(|e| self.err(e.message))?;
            }
        }
        Ok(())
    }
}
