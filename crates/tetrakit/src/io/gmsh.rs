//! Gmsh `.msh` in ASCII, in the two layouts Gmsh and meshio write: 2.2 (`$Nodes` as
//! `tag x y z` lines, `$Elements` as `tag type ntags tags… nodes…`) and 4.1 (entity
//! blocks: a block's node tags, then its coordinates; a block's elements, each a tag
//! and its nodes). Read: 4-node tetrahedra (type 4) and the corners of 10-node ones
//! (type 11: the first four nodes are the corners), triangles (2, and the corners of 9)
//! and lines (1, and the corners of 8); points (15) are ignored. Each tetrahedron keeps
//! its region ([`Input::regions`]): its first tag in 2.2 (the physical group, as Gmsh
//! writes them), the entity tag of its block in 4.1. Any other element (quadrangles,
//! hexahedra, prisms, pyramids, higher orders) is an error that counts them, at the
//! line of the first. Other sections (`$PhysicalNames`, `$Entities`, `$NodeData`, …)
//! are skipped. A partitioned mesh in one file (`gmsh -part K`: 2.2 element tags `physical
//! elementary count partition…`, 4.1 `$PartitionedEntities` volumes) is read in pieces, one
//! per partition ([`Input::pieces`], the tetrahedra grouped by partition), by the binary
//! reader as well.
//!
//! Node tags may be any distinct positive numbers below 2^32, in any order (Gmsh leaves
//! gaps after boolean operations and with physical groups); messages name vertices by
//! their tags ([`Input::point_labels`]) and tetrahedra by their element tags. Binary
//! files (`file-type 1`, 2.2 and 4.1) are read by `io::gmsh_binary` (chosen by
//! [`is_binary`]). Counts are checked against what is read (4.1's totals and tag ranges
//! too), never used to size an allocation; every error names the line.

use super::stream::Stream;
use super::{Input, InputError, parse_int};
use std::path::Path;

/// Nodes of a Gmsh element type, for the types this reader knows: what it keeps, and
/// the names of the cells it refuses.
pub(super) fn element_nodes(kind: i64) -> Option<(usize, &'static str)> {
    Some(match kind {
        1 => (2, "line"),
        2 => (3, "triangle"),
        3 => (4, "quadrangle"),
        4 => (4, "tetrahedron"),
        5 => (8, "hexahedron"),
        6 => (6, "prism"),
        7 => (5, "pyramid"),
        8 => (3, "line"),
        9 => (6, "triangle"),
        10 => (9, "quadrangle"),
        11 => (10, "tetrahedron"),
        12 => (27, "hexahedron"),
        13 => (18, "prism"),
        14 => (14, "pyramid"),
        15 => (1, "point"),
        16 => (8, "quadrangle"),
        17 => (20, "hexahedron"),
        18 => (15, "prism"),
        19 => (13, "pyramid"),
        _ => return None,
    })
}

/// True when the file's header says binary (file type 1), read from its first bytes.
pub(super) fn is_binary(path: &Path) -> bool {
    use std::io::Read;
    let mut head = Vec::new();
    let read = std::fs::File::open(path).and_then(|f| f.take(64).read_to_end(&mut head));
    let head = String::from_utf8_lossy(&head);
    let mut lines = head.lines();
    read.is_ok()
        && lines.next().map(str::trim) == Some("$MeshFormat")
        && lines.next().and_then(|l| l.split_ascii_whitespace().nth(1)) == Some("1")
}

/// What is built while reading, by the ASCII and the binary reader alike.
pub(super) struct Cells<'p> {
    pub(super) input: Input,
    /// Every node's tag, kept only once a tag is not the next of `1..=N` (then the
    /// lookup below is built when the nodes end).
    tags: Option<Vec<u64>>,
    /// `(tag, index)` sorted by tag, for sparse tags.
    lookup: Vec<(u64, u32)>,
    /// Cells refused, by name, with their counts and the line of the first.
    refused: Vec<(&'static str, usize, usize)>,
    /// Each tetrahedron's partition (0 for none), and the partition of each 4.1
    /// partitioned volume entity.
    partitions: Vec<i64>,
    pub(super) volume_partition: std::collections::HashMap<i64, i64>,
    pub(super) path: &'p Path,
}

/// The ASCII reader: a token stream and what it has built.
struct Reader<'a, 'p> {
    s: Stream<'a>,
    cells: Cells<'p>,
}

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let text = super::read_text(path)?;
    let mut r = Reader {
        s: Stream::new(&text, 0, None, path),
        cells: Cells::new(path),
    };
    let mut version = None;
    while let Some((line, key)) = r.s.next() {
        match key {
            "$MeshFormat" => version = Some(r.format()?),
            "$Nodes" if version == Some(2) => r.nodes_22()?,
            "$Nodes" if version == Some(4) => r.nodes_41()?,
            "$Elements" if version == Some(2) => r.elements_22()?,
            "$Elements" if version == Some(4) => r.elements_41()?,
            "$PartitionedEntities" if version == Some(4) => r.partitioned_entities()?,
            "$Nodes" | "$Elements" => {
                return Err(r.err(line, format!("{key} before $MeshFormat")));
            }
            k if k.starts_with('$') && !k.starts_with("$End") => r.skip(line, k)?,
            other => {
                return Err(r.err(line, format!("{} outside a section", super::quote(other))));
            }
        }
        let partitioned = key == "$PartitionedEntities" && version == Some(4);
        if matches!(key, "$Nodes" | "$Elements") || partitioned {
            r.end(key)?;
        }
    }
    if version.is_none() {
        return Err(r.err(0, "no $MeshFormat section: not a Gmsh file".into()));
    }
    r.cells.finish()
}

impl<'p> Cells<'p> {
    pub(super) fn new(path: &'p Path) -> Self {
        Cells {
            input: Input {
                dim: 3,
                index_base: 1,
                point_file: path.to_path_buf(),
                tet_file: path.to_path_buf(),
                ..Default::default()
            },
            refused: Vec::new(),
            partitions: Vec::new(),
            volume_partition: Default::default(),
            tags: None,
            lookup: Vec::new(),
            path,
        }
    }

    fn err(&self, line: usize, message: String) -> InputError {
        InputError::new(self.path, line, message)
    }

    /// The input, once every section is read: some nodes, no refused cell, segments
    /// checked.
    pub(super) fn finish(mut self) -> Result<Input, InputError> {
        if self.input.points.is_empty() {
            return Err(self.err(0, "no nodes ($Nodes section)".into()));
        }
        if let Some(&(_, _, first)) = self.refused.first() {
            let all: Vec<String> = (self.refused.iter())
                .map(|(n, k, _)| format!("{k} {n}"))
                .collect();
            self.input.other_cells = Some(super::OtherCells {
                count: self.refused.iter().map(|r| r.1).sum(),
                line: first,
                message: format!(
                    "{} element(s) besides tetrahedra, triangles and lines: only those are read",
                    all.join(", ")
                ),
            });
        }
        self.split_partitions();
        Ok(self.input)
    }

    /// A partitioned mesh (Gmsh's `-part K` in one file): its tetrahedra grouped by
    /// partition (stable, each keeping its element tag), one piece per partition.
    fn split_partitions(&mut self) {
        let parts = std::mem::take(&mut self.partitions);
        let mut tags: Vec<i64> = parts.clone();
        tags.sort_unstable();
        tags.dedup();
        if tags.len() < 2 || parts.len() != self.input.tets.len() {
            return;
        }
        let mut order: Vec<usize> = (0..parts.len()).collect();
        order.sort_by_key(|&k| parts[k]);
        let i = &mut self.input;
        let pick = |v: &mut Vec<_>| *v = order.iter().map(|&k| v[k]).collect();
        pick(&mut i.tets);
        if i.tet_lines.len() == order.len() {
            i.tet_lines = order.iter().map(|&k| i.tet_lines[k]).collect();
        }
        i.tet_labels = order.iter().map(|&k| i.tet_labels[k]).collect();
        i.regions = order.iter().map(|&k| i.regions[k]).collect();
        let mut first = 0;
        for tag in tags {
            i.pieces.push(super::Piece {
                file: self.path.to_path_buf(),
                first_tet: first as u32,
                partition: Some(tag),
            });
            first += parts.iter().filter(|&&p| p == tag).count();
        }
    }

    /// One node, `tag` a positive number below 2^32 (checked for repeats by
    /// [`Cells::end_nodes`]); the error is the message alone, for the caller to place.
    pub(super) fn node(
        &mut self,
        tag: i64,
        p: crate::geom::Point3,
        at: usize,
    ) -> Result<(), String> {
        let k = self.input.points.len();
        let tag = u64::try_from(tag)
            .ok()
            .filter(|t| (1..=u64::from(u32::MAX)).contains(t))
            .ok_or_else(|| format!("node tag {tag}: tags are numbers from 1 to 2^32 − 1"))?;
        if self.tags.is_none() && tag != k as u64 + 1 {
            self.tags = Some((1..=k as u64).collect());
        }
        if let Some(tags) = &mut self.tags {
            tags.push(tag);
        }
        self.input.points.push(p);
        self.input.point_lines.push(at);
        Ok(())
    }

    /// The nodes are all read: with sparse tags, the lookup from tags to points (a tag
    /// given twice is an error naming it, with the later node's index) and the points'
    /// labels.
    pub(super) fn end_nodes(&mut self) -> Result<(), (usize, String)> {
        let Some(tags) = self.tags.take() else {
            return Ok(());
        };
        let mut lookup: Vec<(u64, u32)> = (tags.iter().enumerate())
            .map(|(k, &t)| (t, k as u32))
            .collect();
        lookup.sort_unstable();
        if let Some(w) = lookup.windows(2).find(|w| w[0].0 == w[1].0) {
            let (a, b) = (w[0].1.min(w[1].1), w[0].1.max(w[1].1));
            let why = format!(
                "node tag {} is given twice (nodes {} and {} of the section)",
                w[0].0,
                a + 1,
                b + 1
            );
            return Err((b as usize, why));
        }
        self.input.point_labels = tags.iter().map(|&t| t as u32).collect();
        self.lookup = lookup;
        Ok(())
    }

    /// The point of node `tag`, or the message saying there is none.
    pub(super) fn vertex(&self, tag: i64) -> Result<u32, String> {
        let n = self.input.points.len();
        let missing = || format!("node {tag} is not among the {n} nodes of $Nodes");
        if self.input.point_labels.is_empty() {
            return usize::try_from(tag)
                .ok()
                .filter(|t| (1..=n).contains(t))
                .map(|t| t as u32 - 1)
                .ok_or_else(missing);
        }
        let tag = u64::try_from(tag).map_err(|_| missing())?;
        match self.lookup.binary_search_by_key(&tag, |e| e.0) {
            Ok(k) => Ok(self.lookup[k].1),
            Err(_) => Err(missing()),
        }
    }

    /// One element: its `name` (from [`element_nodes`]), tag, node indices and region.
    pub(super) fn keep(
        &mut self,
        line: usize,
        tag: i64,
        name: &'static str,
        corners: &[u32],
        region: i64,
        partition: i64,
    ) -> Result<(), InputError> {
        let label = u32::try_from(tag)
            .map_err(|_| self.err(line, format!("element tag {tag} is out of range")))?;
        match name {
            "tetrahedron" => {
                let i = &mut self.input;
                i.tets
                    .push([corners[0], corners[1], corners[2], corners[3]]);
                i.tet_lines.push(line as u32);
                i.tet_labels.push(label);
                i.regions.push(region);
                self.partitions.push(partition);
            }
            "triangle" => self.input.faces.push([corners[0], corners[1], corners[2]]),
            "line" => {
                self.input.segments.push([corners[0], corners[1]]);
                self.input.segment_lines.push(line as u32);
            }
            "point" => {}
            other => match self.refused.iter_mut().find(|(n, _, _)| *n == other) {
                Some((_, k, _)) => *k += 1,
                None => self.refused.push((other, 1, line)),
            },
        }
        Ok(())
    }
}

impl Reader<'_, '_> {
    fn err(&self, line: usize, message: String) -> InputError {
        self.cells.err(line, message)
    }

    /// An integer token.
    fn int(&mut self, what: &str) -> Result<(usize, i64), InputError> {
        let (line, tok) = self.s.want(what)?;
        Ok((line, parse_int(tok, self.cells.path, line, what)?))
    }

    /// A count: a non-negative integer.
    fn count(&mut self, what: &str) -> Result<usize, InputError> {
        let (line, k) = self.int(what)?;
        usize::try_from(k).map_err(|_| self.err(line, format!("negative {what}")))
    }

    /// `$MeshFormat`: the major version (2 or 4), ASCII only.
    fn format(&mut self) -> Result<u8, InputError> {
        let (l, v) = self.s.want("the format version")?;
        let major = match v {
            "2.2" => 2,
            "4.1" => 4,
            other => {
                return Err(self.err(
                    l,
                    format!(
                        "Gmsh format {}: only 2.2 and 4.1 are read",
                        super::quote(other)
                    ),
                ));
            }
        };
        let (l, kind) = self.int("the file type")?;
        if kind != 0 {
            return Err(self.err(
                l,
                format!("file type {kind}: 0 (ASCII) or 1 (binary) expected"),
            ));
        }
        self.s.want("the data size")?;
        self.end("$MeshFormat")?;
        Ok(major)
    }

    /// The `$End…` of `section`.
    fn end(&mut self, section: &str) -> Result<(), InputError> {
        let want = format!("$End{}", &section[1..]);
        let (l, tok) = self.s.want(&want)?;
        if tok != want {
            return Err(self.err(
                l,
                format!("{} where {want} was expected", super::quote(tok)),
            ));
        }
        Ok(())
    }

    /// Skips a section this reader does not use.
    fn skip(&mut self, line: usize, section: &str) -> Result<(), InputError> {
        let want = format!("$End{}", &section[1..]);
        while let Some((_, tok)) = self.s.next() {
            if tok == want {
                return Ok(());
            }
        }
        Err(self.err(line, format!("{section} has no {want}")))
    }

    /// One node's coordinates after its tag, read on `line`.
    fn node(&mut self, line: usize, tag: i64) -> Result<(), InputError> {
        let (at, p) = self.s.point(3)?;
        self.cells.node(tag, p, at).map_err(|e| self.err(line, e))
    }

    /// The end of `$Nodes`: the lookup of sparse tags.
    fn end_nodes(&mut self) -> Result<(), InputError> {
        let Err((k, e)) = self.cells.end_nodes() else {
            return Ok(());
        };
        let line = self.cells.input.point_lines.get(k).copied().unwrap_or(0);
        Err(self.err(line, e))
    }

    fn nodes_22(&mut self) -> Result<(), InputError> {
        for _ in 0..self.count("the number of nodes")? {
            let (line, tag) = self.int("a node tag")?;
            self.node(line, tag)?;
        }
        self.end_nodes()
    }

    /// A 4.1 section's header: the number of blocks, the total and the tag range, with
    /// the line; checked against what the blocks hold by [`Totals::check`].
    fn totals(&mut self, what: &'static str) -> Result<(usize, Totals), InputError> {
        let blocks = self.count("the number of entity blocks")?;
        let (line, total) = self.int(&format!("the number of {what}"))?;
        let (_, min) = self.int(&format!("the smallest {what} tag"))?;
        let (_, max) = self.int(&format!("the largest {what} tag"))?;
        let declared = Totals::declared(what, line, [total, min, max]);
        Ok((blocks, declared))
    }

    fn nodes_41(&mut self) -> Result<(), InputError> {
        let (blocks, mut totals) = self.totals("nodes")?;
        for _ in 0..blocks {
            self.int("an entity dimension")?;
            self.int("an entity tag")?;
            let (l, parametric) = self.int("the parametric flag")?;
            if parametric != 0 {
                return Err(self.err(l, "parametric nodes are not read".into()));
            }
            let mut tags = Vec::new();
            for _ in 0..self.count("the number of nodes in a block")? {
                tags.push(self.int("a node tag")?);
            }
            for (line, tag) in tags {
                totals.add(tag);
                self.node(line, tag)?;
            }
        }
        totals.check().map_err(|(l, e)| self.err(l, e))?;
        self.end_nodes()
    }

    /// One element of `kind` with its tag, region and node tags read from the stream.
    fn element(
        &mut self,
        line: usize,
        tag: i64,
        kind: i64,
        [region, partition]: [i64; 2],
    ) -> Result<(), InputError> {
        let Some((n, name)) = element_nodes(kind) else {
            return Err(self.err(line, format!("element {tag} has unknown type {kind}")));
        };
        let mut corners = Vec::with_capacity(n);
        for _ in 0..n {
            let (l, t) = self.int("a node tag of an element")?;
            corners.push(self.cells.vertex(t).map_err(|e| self.err(l, e))?);
        }
        self.cells
            .keep(line, tag, name, &corners, region, partition)
    }

    fn elements_22(&mut self) -> Result<(), InputError> {
        for _ in 0..self.count("the number of elements")? {
            let (line, tag) = self.int("an element tag")?;
            let (_, kind) = self.int("an element type")?;
            let mut tags = Vec::new();
            for _ in 0..self.count("the number of tags")? {
                tags.push(self.int("a tag")?.1);
            }
            // Tags: physical, elementary, then (partitioned) the number of partitions
            // and the partitions, the first the element's own.
            let region = tags.first().copied().unwrap_or(0);
            let partition = match tags.get(2) {
                Some(&k) if k >= 1 => tags.get(3).copied().unwrap_or(0),
                _ => 0,
            };
            self.element(line, tag, kind, [region, partition])?;
        }
        Ok(())
    }

    /// 4.1 `$PartitionedEntities`: the partition of each partitioned volume (its first
    /// partition tag); ghost entities, points, curves and surfaces are read past.
    fn partitioned_entities(&mut self) -> Result<(), InputError> {
        self.count("the number of partitions")?;
        for _ in 0..self.count("the number of ghost entities")? {
            self.int("a ghost entity tag")?;
            self.int("a ghost entity's partition")?;
        }
        let mut counts = [0usize; 4];
        for (d, c) in counts.iter_mut().enumerate() {
            *c = self.count(
                [
                    "the number of points",
                    "the number of curves",
                    "the number of surfaces",
                    "the number of volumes",
                ][d],
            )?;
        }
        for (dim, &count) in counts.iter().enumerate() {
            for _ in 0..count {
                let (_, tag) = self.int("an entity tag")?;
                self.int("a parent dimension")?;
                self.int("a parent tag")?;
                let mut partitions = Vec::new();
                for _ in 0..self.count("the number of partitions of an entity")? {
                    partitions.push(self.int("a partition tag")?.1);
                }
                let coordinates = if dim == 0 { 3 } else { 6 };
                for _ in 0..coordinates {
                    self.s.want("a bounding coordinate")?;
                }
                for _ in 0..self.count("the number of physical tags")? {
                    self.int("a physical tag")?;
                }
                if dim > 0 {
                    for _ in 0..self.count("the number of bounding entities")? {
                        self.int("a bounding entity tag")?;
                    }
                }
                if let (3, Some(&p)) = (dim, partitions.first()) {
                    self.cells.volume_partition.insert(tag, p);
                }
            }
        }
        Ok(())
    }

    fn elements_41(&mut self) -> Result<(), InputError> {
        let (blocks, mut totals) = self.totals("elements")?;
        for _ in 0..blocks {
            self.int("an entity dimension")?;
            let (_, entity) = self.int("an entity tag")?;
            let (_, kind) = self.int("an element type")?;
            for _ in 0..self.count("the number of elements in a block")? {
                let (line, tag) = self.int("an element tag")?;
                totals.add(tag);
                let partition = self.cells.volume_partition.get(&entity).copied();
                self.element(line, tag, kind, [entity, partition.unwrap_or(0)])?;
            }
        }
        totals.check().map_err(|(l, e)| self.err(l, e))
    }
}

/// A 4.1 `$Nodes` or `$Elements` header's total and tag range, and what the blocks held.
pub(super) struct Totals {
    what: &'static str,
    line: usize,
    declared: [i64; 3],
    found: (i64, i64, i64),
}

impl Totals {
    /// The header's `[total, smallest tag, largest tag]` of `what`, read at `line`.
    pub(super) fn declared(what: &'static str, line: usize, declared: [i64; 3]) -> Self {
        Totals {
            what,
            line,
            declared,
            found: (0, i64::MAX, i64::MIN),
        }
    }

    pub(super) fn add(&mut self, tag: i64) {
        let f = &mut self.found;
        (f.0, f.1, f.2) = (f.0 + 1, f.1.min(tag), f.2.max(tag));
    }

    /// The declared total equals the count found, and the tag range the one found (when
    /// there are any).
    pub(super) fn check(&self) -> Result<(), (usize, String)> {
        let [total, min, max] = self.declared;
        let (count, lo, hi) = self.found;
        let what = self.what;
        if total != count {
            let why = format!("the header declares {total} {what}, the blocks hold {count}");
            return Err((self.line, why));
        }
        if count > 0 && (min, max) != (lo, hi) {
            let why = format!(
                "the header declares {what} tags {min}..={max}, the blocks hold {lo}..={hi}"
            );
            return Err((self.line, why));
        }
        Ok(())
    }
}
