//! Gmsh `.msh` binary (`file-type 1`, little-endian), the layouts `gmsh -bin` writes:
//! 4.1 (8-byte `size_t`; the same sections as the ASCII 4.1 reader, [`super::gmsh`],
//! with `int`, `size_t` and `double` fields in place of tokens) and 2.2 (`gmsh -bin
//! -format msh22`: a node is an `int` tag and three doubles; elements come in runs of
//! one type, each run a header of three `int`s, type, count and number of tags, then
//! per element its `int` tag, tags and nodes). `$Entities` is parsed to be skipped;
//! a partitioned file (`-part K`) is read in pieces as in ASCII (4.1's
//! `$PartitionedEntities` gives each volume's partition, 2.2's element tags each
//! tetrahedron's); other sections are skipped to their `$End…` line. The same cells are kept and
//! refused as in ASCII, by [`Cells`]. A count is checked against the bytes left before
//! anything is reserved for it; errors name the byte offset of the offending field.

use super::gmsh::{Cells, Totals, element_nodes};
use super::{Input, InputError};
use std::path::Path;

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let bytes = super::read_bytes(path)?;
    let mut r = Bytes {
        b: &bytes,
        at: 0,
        cells: Cells::new(path),
    };
    let v22 = r.format()?;
    while let Some(section) = r.header()? {
        match section.as_str() {
            "$Nodes" if v22 => r.nodes_22()?,
            "$Elements" if v22 => r.elements_22()?,
            "$Nodes" => r.nodes()?,
            "$Elements" => r.elements()?,
            "$Entities" => r.entities()?,
            "$PartitionedEntities" if !v22 => r.partitioned_entities()?,
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
    /// An error at the current byte.
    fn err(&self, message: impl Into<String>) -> InputError {
        InputError::at_byte(self.cells.path, self.at.min(self.b.len()), message)
    }

    /// An error at byte `at`.
    fn err_at(&self, at: usize, message: impl Into<String>) -> InputError {
        InputError::at_byte(self.cells.path, at, message)
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

    /// `$MeshFormat`, `4.1 1 8` or `2.2 1 8`, the binary 1, `$EndMeshFormat`; true for
    /// 2.2.
    fn format(&mut self) -> Result<bool, InputError> {
        if self.line().as_deref() != Some("$MeshFormat") {
            return Err(self.err("no $MeshFormat section: not a Gmsh file"));
        }
        let at = self.at;
        let version = self.line().unwrap_or_default();
        let fields: Vec<&str> = version.split_ascii_whitespace().collect();
        let v22 = match fields.as_slice() {
            ["4.1", "1", "8"] => false,
            ["2.2", "1", "8"] => true,
            _ => {
                let why = format!(
                    "binary Gmsh header {}: only 4.1 and 2.2 with 8-byte sizes are read",
                    super::quote(&version)
                );
                return Err(self.err_at(at, why));
            }
        };
        self.step(); // the newline after the header
        match self.int("the byte-order mark")? {
            1 => {}
            0x0100_0000 => {
                let why = "a big-endian binary .msh file: only little-endian is read";
                return Err(self.err_at(self.at - 4, why));
            }
            m => {
                let why = format!(
                    "the binary marker is {m:#x}, not 1: the header says binary but the file is not (an ASCII file labelled '1'?)"
                );
                return Err(self.err_at(self.at - 4, why));
            }
        }
        self.end("$MeshFormat")?;
        Ok(v22)
    }

    /// A section's count on its own text line (2.2), no more than the bytes left can
    /// hold at `width` bytes each.
    fn text_count(&mut self, width: usize, what: &str) -> Result<usize, InputError> {
        let at = self.at;
        let line = self.line().unwrap_or_default();
        self.step();
        let k: u64 = line
            .parse()
            .map_err(|_| self.err_at(at, format!("{} is not {what}", super::quote(&line))))?;
        let left = (self.b.len() - self.at) as u64;
        if k.saturating_mul(width as u64) > left {
            let why = format!("{what} {k} is more than the rest of the file holds");
            return Err(self.err_at(at, why));
        }
        Ok(k as usize)
    }

    /// 2.2 `$Nodes`: the count, then per node an `int` tag and three doubles.
    fn nodes_22(&mut self) -> Result<(), InputError> {
        for _ in 0..self.text_count(28, "the number of nodes")? {
            let at = self.at;
            let tag = self.int("a node tag")?;
            let mut p = [0.0; 3];
            for c in p.iter_mut() {
                *c = self.double("a coordinate")?;
            }
            self.cells.node(tag, p, 0).map_err(|e| self.err_at(at, e))?;
        }
        self.cells.end_nodes().map_err(|(_, e)| self.err(e))
    }

    /// 2.2 `$Elements`: the count, then runs of one type.
    fn elements_22(&mut self) -> Result<(), InputError> {
        let mut left = self.text_count(8, "the number of elements")?;
        while left > 0 {
            let kind = self.int("an element type")?;
            let at = self.at;
            let run = self.int("the number of elements of a run")?;
            let tags = self.int("the number of tags")?;
            let Some((nodes, name)) = element_nodes(kind) else {
                return Err(self.err_at(at - 4, format!("unknown element type {kind}")));
            };
            let (Ok(run), Ok(tags)) = (usize::try_from(run), usize::try_from(tags)) else {
                return Err(self.err_at(at, "a negative count in an element run's header"));
            };
            if run == 0 || run > left {
                let why = format!("a run of {run} elements where {left} are left of the total");
                return Err(self.err_at(at, why));
            }
            let width = 4usize.saturating_mul(1 + tags + nodes);
            if run.saturating_mul(width) > self.b.len() - self.at {
                return Err(self.err_at(
                    at,
                    format!("a run of {run} elements is more than the rest of the file holds"),
                ));
            }
            for _ in 0..run {
                let tag = self.int("an element tag")?;
                // Tags: physical, elementary, then (partitioned) the number of partitions
                // and the partitions, the first the element's own.
                let mut t = [0i64; 4];
                for j in 0..tags {
                    let x = self.int("an element's tag")?;
                    if let Some(slot) = t.get_mut(j) {
                        *slot = x;
                    }
                }
                let partition = if tags >= 4 && t[2] >= 1 { t[3] } else { 0 };
                let node = |r: &mut Self| r.int("a node tag");
                self.element(tag, name, nodes, [t[0], partition], node)?;
            }
            left -= run;
        }
        Ok(())
    }

    /// One element's `nodes` node tags (read by `tag`), kept or refused by [`Cells`].
    fn element(
        &mut self,
        tag: i64,
        name: &'static str,
        nodes: usize,
        [region, partition]: [i64; 2],
        tag_of: impl Fn(&mut Self) -> Result<i64, InputError>,
    ) -> Result<(), InputError> {
        let mut corners = [0u32; 27];
        for c in corners.iter_mut().take(nodes) {
            let at = self.at;
            let raw = tag_of(self)?;
            *c = self.cells.vertex(raw).map_err(|e| self.err_at(at, e))?;
        }
        self.cells
            .keep(0, tag, name, &corners[..nodes], region, partition)
            .map_err(|e| self.err(e.message))
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
                self.entity_box_and_tags(dim)?;
            }
        }
        Ok(())
    }

    /// An entity's box (a point's coordinates) and its tag lists (physical tags, then the
    /// bounding entities unless a point), as `$Entities` and `$PartitionedEntities` end
    /// each entity.
    fn entity_box_and_tags(&mut self, dim: usize) -> Result<(), InputError> {
        let doubles = if dim == 0 { 3 } else { 6 };
        self.take(8 * doubles, "an entity's box")?;
        let lists = if dim == 0 { 1 } else { 2 };
        for _ in 0..lists {
            let n = self.count(4, "the number of an entity's tags")?;
            self.take(4 * n, "an entity's tags")?;
        }
        Ok(())
    }

    /// 4.1 `$PartitionedEntities` (`gmsh -part K -bin`): the partition of each
    /// partitioned volume (its first partition tag); ghost entities, points, curves and
    /// surfaces are read past. Counts are `size_t`, tags `int`, coordinates `double`.
    fn partitioned_entities(&mut self) -> Result<(), InputError> {
        self.step();
        self.size("the number of partitions")?;
        let ghosts = self.count(8, "the number of ghost entities")?;
        self.take(8 * ghosts, "the ghost entities")?;
        let mut counts = [0; 4];
        for c in counts.iter_mut() {
            *c = self.count(20, "the number of entities")?;
        }
        for (dim, &k) in counts.iter().enumerate() {
            for _ in 0..k {
                let tag = self.int("an entity tag")?;
                self.take(8, "an entity's parent")?;
                let n = self.count(4, "the number of partitions of an entity")?;
                let first = match n {
                    0 => None,
                    _ => Some(self.int("a partition tag")?),
                };
                self.take(4 * n.saturating_sub(1), "an entity's partitions")?;
                self.entity_box_and_tags(dim)?;
                if let (3, Some(p)) = (dim, first) {
                    self.cells.volume_partition.insert(tag, p);
                }
            }
        }
        Ok(())
    }

    /// A 4.1 header's total and tag range (three `size_t`).
    fn totals(&mut self, what: &'static str) -> Result<Totals, InputError> {
        let at = self.at;
        let mut d = [0i64; 3];
        for x in d.iter_mut() {
            *x = i64::try_from(self.size("a section's totals")?).unwrap_or(-1);
        }
        Ok(Totals::declared(what, at, d))
    }

    fn nodes(&mut self) -> Result<(), InputError> {
        self.step();
        let blocks = self.count(20, "the number of node blocks")?;
        let mut totals = self.totals("nodes")?;
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
                let tag = i64::try_from(tag).unwrap_or(-1);
                let mut p = [0.0; 3];
                for c in p.iter_mut() {
                    *c = self.double("a coordinate")?;
                }
                totals.add(tag);
                let at = tags_at + 8 * j;
                self.cells.node(tag, p, 0).map_err(|e| self.err_at(at, e))?;
            }
        }
        totals.check().map_err(|(at, e)| self.err_at(at, e))?;
        self.cells.end_nodes().map_err(|(_, e)| self.err(e))
    }

    fn elements(&mut self) -> Result<(), InputError> {
        self.step();
        let blocks = self.count(20, "the number of element blocks")?;
        let mut totals = self.totals("elements")?;
        for _ in 0..blocks {
            self.int("an entity dimension")?;
            let region = self.int("an entity tag")?;
            let kind = self.int("an element type")?;
            let Some((nodes, name)) = element_nodes(kind) else {
                return Err(self.err_at(self.at - 4, format!("unknown element type {kind}")));
            };
            let k = self.count(8 * (1 + nodes), "the number of elements in a block")?;
            for _ in 0..k {
                let tag = i64::try_from(self.size("an element tag")?).unwrap_or(-1);
                totals.add(tag);
                let size = |r: &mut Self| Ok(i64::try_from(r.size("a node tag")?).unwrap_or(-1));
                let partition = self.cells.volume_partition.get(&region).copied();
                self.element(tag, name, nodes, [region, partition.unwrap_or(0)], size)?;
            }
        }
        totals.check().map_err(|(at, e)| self.err_at(at, e))
    }
}
