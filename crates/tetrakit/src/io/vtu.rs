//! VTK XML `.vtu` (`UnstructuredGrid`), as VTK, ParaView and meshio write it: every
//! `Piece`'s `Points` and its `Cells` (`connectivity`, `offsets`, `types`), each
//! `DataArray` in any of the three forms VTK has: `format="ascii"` (numbers as text),
//! `format="binary"` (base64 inline) and `format="appended"` (an offset into the
//! `AppendedData` section, `encoding="raw"` or `"base64"`). Binary data may be
//! compressed (`compressor="vtkZLibDataCompressor"`, `"vtkLZMADataCompressor"` or
//! `"vtkLZ4DataCompressor"`, VTK's block layout), in either byte order, with 32- or
//! 64-bit headers (`header_type`). `PointData`/`CellData` arrays are not read. Cells are
//! filed as in legacy VTK ([`super::vtk`]): tetrahedra, triangles and lines are kept
//! (quadratic ones by their corners), other types are an error that counts them.
//!
//! Every array must hold exactly what its piece declares: `3 × NumberOfPoints`
//! coordinates, `NumberOfCells` offsets and types, and as many connectivity entries as
//! the last offset says. A binary array's header must declare exactly that many bytes
//! before anything is decoded or inflated, so nothing is allocated beyond what the
//! declared counts times the value width allow (and those counts are themselves bounded
//! by the file: a compressed block may not claim more than its compressor's maximum
//! ratio of its bytes). Errors name the line of the `DataArray` (or `Piece`) at fault.

use super::vtk::CellSorter;
use super::vtu_data::{
    Compressor, Layout, Values, ascii_values, binary_values, block, block_from_base64, width,
};
use super::{Input, InputError, read_bytes};
use crate::geom::{coordinate_in_range, point_key};
use quick_xml::events::{BytesStart, Event};
use rustc_hash::FxHashMap as HashMap;
use std::path::Path;

/// What a `DataArray` holds, by where it sits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Role {
    Points,
    Connectivity,
    Offsets,
    Types,
    /// `PointData`'s `GlobalNodeIds` (ParaView's D3, PETSc) or `GlobalPointIds` (VTK's
    /// `vtkGenerateGlobalIds`): one id per point, the same in every piece.
    GlobalIds,
}

/// Where an array's values are.
#[derive(Debug)]
enum Source {
    Ascii(String),
    Base64(String),
    Appended(usize),
}

/// One `DataArray` to decode once the whole file has been seen.
#[derive(Debug)]
struct Array {
    role: Role,
    piece: usize,
    ty: String,
    source: Source,
    line: usize,
}

/// A `Piece`: where it starts and what it declares.
#[derive(Clone, Copy, Debug)]
struct Piece {
    line: usize,
    points: usize,
    cells: usize,
}

/// The `AppendedData` section: raw bytes, or base64 text.
enum Appended<'a> {
    None,
    Raw(&'a [u8]),
    Base64(&'a [u8]),
}

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let mut merged = Merged::new(path);
    read_into(path, &mut merged)?;
    merged.finish(path)
}

/// Reads `files` as the pieces of one mesh: `.vtu` pieces (merged as a `.pvtu`'s), or
/// Gmsh's `-part_split` files (merged by node tag, named by node and element tags), or
/// other meshes (merged by exact coordinates).
pub(super) fn read_files(
    files: &[std::path::PathBuf],
    opts: super::ReadOptions,
) -> Result<Input, InputError> {
    let mut merged = Merged::new(&files[0]);
    for file in files {
        let ext = (file.extension().and_then(|e| e.to_str()))
            .unwrap_or("")
            .to_ascii_lowercase();
        if ext == "vtu" {
            read_into(file, &mut merged)?;
            continue;
        }
        let piece = super::read_input_with(file, opts)?;
        let ids = (ext == "msh").then(|| {
            (0..piece.points.len())
                .map(|k| i64::from(piece.point_label(k)))
                .collect()
        });
        merged.add_input(file, piece, ids)?;
    }
    merged.finish(&files[0])
}

/// Reads each `Piece` of one `.vtu` as a piece of a partitioned mesh, apart (a `.pvtu`'s
/// piece file may hold several, as `tetrakit check` counts them): its mesh, and each
/// point's global id where every point has one.
pub(super) fn read_pieces(path: &Path) -> Result<Vec<super::PieceRead>, InputError> {
    let mut read = Vec::new();
    for decoded in decode_file(path) {
        let mut merged = Merged::new(path);
        absorb(path, decoded?, &mut merged)?;
        let ids: Option<Vec<i64>> = (0..merged.input.points.len() as u32)
            .map(|k| merged.point_ids.get(&k).copied())
            .collect();
        read.push(match merged.input.points.is_empty() {
            // An empty piece (a partition without cells) is a piece, of either layout.
            true => (merged.input, None),
            false => (merged.finish(path)?, ids),
        });
    }
    Ok(read)
}

/// Pieces read so far, one mesh: a point of a later piece (or piece file) at the exact
/// coordinates of a point of an earlier one is that point (the interface vertices a
/// partition repeats in each piece), while points repeated inside one piece stay
/// apart, as in a single-piece file.
pub(super) struct Merged {
    input: Input,
    sorter: CellSorter,
    earlier: HashMap<[u64; 3], u32>,
    /// Where the current piece's points start.
    first: usize,
    /// Each local point of the current piece as an index into the merged points.
    local: Vec<u32>,
    /// The file being read.
    file: std::path::PathBuf,
    /// The current piece's global point ids, where it has them.
    ids: Option<Vec<i64>>,
    /// Each global id of the earlier pieces, with its point.
    earlier_ids: HashMap<i64, u32>,
    /// The global id of each merged point that had one.
    point_ids: HashMap<u32, i64>,
    /// How many points the pieces read so far hold (repeated ones counted).
    concat: u32,
    /// Name each point by its global id (Gmsh's node tags), not its place.
    by_id: bool,
    /// Whether each piece with points had global ids (all must, or none), by piece.
    with_ids: Vec<(usize, bool)>,
}

impl Merged {
    pub(super) fn new(path: &Path) -> Self {
        Merged {
            input: Input {
                dim: 3,
                point_file: path.to_path_buf(),
                tet_file: path.to_path_buf(),
                ..Default::default()
            },
            sorter: CellSorter::default(),
            earlier: HashMap::default(),
            first: 0,
            local: Vec::new(),
            file: path.to_path_buf(),
            ids: None,
            earlier_ids: HashMap::default(),
            point_ids: HashMap::default(),
            concat: 0,
            by_id: false,
            with_ids: Vec::new(),
        }
    }

    /// Adds a piece's points, sharing those of earlier pieces: by global id where the
    /// piece has ids (an id of an earlier piece at other coordinates is a new point and
    /// an [`IdMismatch`](super::IdMismatch)), else by exact coordinates.
    fn add_points(&mut self, coordinates: &[f64]) -> Result<(), InputError> {
        if let Some(k) = coordinates.iter().position(|&x| !coordinate_in_range(x)) {
            let piece = match self.input.pieces.len() {
                0 => String::new(),
                p => format!(" of piece {p}"),
            };
            let why = format!(
                "point {}{piece} has coordinate {:e}, which is not finite or outside the exactly supported magnitude range [2^-142, 2^201]",
                k / 3,
                coordinates[k]
            );
            return Err(InputError::new(&self.file, 0, why));
        }
        for k in self.first..self.input.points.len() {
            self.earlier
                .entry(point_key(&self.input.points[k]))
                .or_insert(k as u32);
            if let Some(&id) = self.point_ids.get(&(k as u32)) {
                self.earlier_ids.entry(id).or_insert(k as u32);
            }
        }
        self.first = self.input.points.len();
        self.local.clear();
        let ids = self.ids.take();
        if !coordinates.is_empty() {
            self.with_ids.push((self.input.pieces.len(), ids.is_some()));
        }
        for (i, c) in coordinates.chunks_exact(3).enumerate() {
            let p = [c[0], c[1], c[2]];
            let id = ids.as_ref().and_then(|ids| ids.get(i).copied());
            let same = match id {
                Some(id) => self.earlier_ids.get(&id).copied(),
                None => self.earlier.get(&point_key(&p)).copied(),
            };
            let k = match same {
                Some(k) if self.input.points[k as usize] == p => k,
                other => {
                    self.input.points.push(p);
                    let label = match id {
                        Some(id) if self.by_id => id as u32,
                        _ => self.concat + i as u32,
                    };
                    self.input.point_labels.push(label);
                    let k = (self.input.points.len() - 1) as u32;
                    if let (Some(first), Some(id)) = (other, id) {
                        let piece = self.input.pieces.len() as u32;
                        self.input.id_mismatches.push(super::IdMismatch {
                            id,
                            first,
                            second: k,
                            piece,
                        });
                    }
                    k
                }
            };
            if let Some(id) = id {
                self.point_ids.insert(k, id);
            }
            self.local.push(k);
        }
        self.concat += (coordinates.len() / 3) as u32;
        let first_tet = self.input.tets.len() as u32;
        let file = self.file.clone();
        self.input.pieces.push(super::Piece {
            file,
            first_tet,
            partition: None,
        });
        Ok(())
    }

    /// Adds a piece read by another reader from `file` (its points' global ids, where
    /// it has them): Gmsh's `-part_split` files, named by their node and element tags.
    pub(super) fn add_input(
        &mut self,
        file: &Path,
        piece: Input,
        ids: Option<Vec<i64>>,
    ) -> Result<(), InputError> {
        self.file = file.to_path_buf();
        self.by_id = ids.is_some();
        self.ids = ids;
        let coordinates: Vec<f64> = piece.points.iter().flatten().copied().collect();
        self.add_points(&coordinates)?;
        for (k, t) in piece.tets.iter().enumerate() {
            self.input.tets.push(t.map(|v| self.local[v as usize]));
            self.input.tet_labels.push(piece.tet_label(k));
        }
        if let Some(o) = piece.other_cells {
            let all = self.input.other_cells.get_or_insert(o.clone());
            if all.message != o.message || all.line != o.line {
                all.count += o.count;
            }
        }
        Ok(())
    }

    pub(super) fn finish(mut self, path: &Path) -> Result<Input, InputError> {
        let with = self.with_ids.iter().find(|w| w.1).map(|w| w.0);
        let without = self.with_ids.iter().find(|w| !w.1).map(|w| w.0);
        if let (Some(a), Some(b)) = (with, without) {
            let file = |k: usize| self.input.pieces[k].file.display().to_string();
            let why = format!(
                "piece {a} ({}) has global point ids but piece {b} ({}) has none: the pieces disagree in layout",
                file(a),
                file(b)
            );
            return Err(InputError::new(path, 0, why));
        }
        self.sorter.finish(&mut self.input);
        if self.input.pieces.len() == 1 {
            self.input.pieces.clear();
            self.input.point_labels.clear();
        }
        if self.input.points.is_empty() {
            return Err(InputError::new(path, 0, "no points"));
        }
        Ok(self.input)
    }
}

/// Reads the pieces of the `.vtu` at `path` into `merged`.
pub(super) fn read_into(path: &Path, merged: &mut Merged) -> Result<(), InputError> {
    merged.file = path.to_path_buf();
    merged.by_id = false;
    each_piece(path, |d, p, piece, arrays| {
        add_piece(d, p, piece, arrays, merged)
    })
}

/// Scans the `.vtu` at `path` and hands each `Piece`, in order, with its arrays to `add`.
fn each_piece(
    path: &Path,
    mut add: impl FnMut(&Decoder, usize, Piece, [Option<&Array>; 5]) -> Result<(), InputError>,
) -> Result<(), InputError> {
    let bytes = read_bytes(path)?;
    let lines = LineIndex::new(&bytes);
    let (xml, appended) = split_appended(&bytes, path, &lines)?;
    let xml = std::str::from_utf8(xml)
        .map_err(|e| InputError::new(path, lines.at(e.valid_up_to()), "not UTF-8 text"))?;
    let (layout, arrays, pieces) = scan(xml, path, &lines)?;
    let source = Decoder {
        path,
        layout,
        appended: &appended,
    };
    for (p, piece) in pieces.iter().enumerate() {
        let mut mine: [Option<&Array>; 5] = [None; 5];
        for a in arrays.iter().filter(|a| a.piece == p) {
            if mine[a.role as usize].replace(a).is_some() {
                let why = format!("a second {:?} array in piece {p}", a.role);
                return Err(InputError::new(path, a.line, why));
            }
        }
        add(&source, p, *piece, mine)?;
    }
    Ok(())
}

/// Line numbers of byte offsets.
struct LineIndex(Vec<usize>);

impl LineIndex {
    fn new(bytes: &[u8]) -> Self {
        LineIndex(
            bytes
                .iter()
                .enumerate()
                .filter(|(_, b)| **b == b'\n')
                .map(|(i, _)| i)
                .collect(),
        )
    }
    fn at(&self, pos: usize) -> usize {
        self.0.partition_point(|&nl| nl < pos) + 1
    }
}

/// The XML before the appended data, and the appended data after its `_` marker.
fn split_appended<'a>(
    bytes: &'a [u8],
    path: &Path,
    lines: &LineIndex,
) -> Result<(&'a [u8], Appended<'a>), InputError> {
    let Some(start) = find(bytes, b"<AppendedData") else {
        return Ok((bytes, Appended::None));
    };
    let tag_end = find(&bytes[start..], b">").map(|e| start + e);
    let underscore = tag_end.and_then(|e| find(&bytes[e..], b"_").map(|u| e + u));
    let (Some(tag_end), Some(u)) = (tag_end, underscore) else {
        let why = "AppendedData without its '_' marker";
        return Err(InputError::new(path, lines.at(start), why));
    };
    let tag = String::from_utf8_lossy(&bytes[start..tag_end]);
    let data = &bytes[u + 1..];
    let appended = if tag.contains("encoding=\"base64\"") {
        Appended::Base64(data)
    } else if tag.contains("encoding=\"raw\"") {
        Appended::Raw(data)
    } else {
        let why = "AppendedData needs encoding=\"raw\" or encoding=\"base64\"";
        return Err(InputError::new(path, lines.at(start), why));
    };
    Ok((&bytes[..start], appended))
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

/// The attribute `name` of `e`, if present.
fn attr(e: &BytesStart, name: &[u8]) -> Option<String> {
    e.attributes()
        .flatten()
        .find(|a| a.key.as_ref() == name)
        .map(|a| String::from_utf8_lossy(&a.value).into_owned())
}

/// Reads the XML: the layout, the arrays to decode, and the number of pieces.
fn scan(
    xml: &str,
    path: &Path,
    lines: &LineIndex,
) -> Result<(Layout, Vec<Array>, Vec<Piece>), InputError> {
    let mut reader = quick_xml::Reader::from_str(xml);
    let mut layout = None;
    let mut stack: Vec<Vec<u8>> = Vec::new();
    let mut arrays = Vec::new();
    let mut pieces: Vec<Piece> = Vec::new();
    let mut open: Option<Array> = None;
    loop {
        let pos = reader.buffer_position() as usize;
        let event = reader.read_event().map_err(|e| {
            let at = lines.at(reader.error_position() as usize);
            InputError::new(path, at, format!("malformed XML: {e}"))
        })?;
        let line = lines.at(pos);
        let err = |why: String| InputError::new(path, line, why);
        match event {
            Event::Start(ref e) | Event::Empty(ref e) => {
                let name = e.name().as_ref().to_vec();
                let empty = matches!(event, Event::Empty(_));
                match name.as_slice() {
                    b"VTKFile" => layout = Some(file_layout(e).map_err(err)?),
                    b"Piece" if stack.last().is_some_and(|p| p == b"UnstructuredGrid") => {
                        pieces.push(piece(e, line).map_err(err)?)
                    }
                    b"DataArray" => {
                        let role = role(&stack, e);
                        if let Some(role) = role {
                            let at = pieces.len().saturating_sub(1);
                            let a = data_array(e, role, at, line).map_err(err)?;
                            if empty || matches!(a.source, Source::Appended(_)) {
                                arrays.push(a);
                            } else {
                                open = Some(a);
                            }
                        }
                    }
                    _ => {}
                }
                if !empty {
                    stack.push(name);
                }
            }
            // Only the array's own text: VTK nests InformationKey elements in it.
            Event::Text(t) if stack.last().is_some_and(|n| n == b"DataArray") => {
                if let Some(a) = &mut open {
                    let text = std::str::from_utf8(&t).map_err(|_| err("not UTF-8 text".into()))?;
                    match &mut a.source {
                        Source::Ascii(s) | Source::Base64(s) => s.push_str(text),
                        Source::Appended(_) => {}
                    }
                }
            }
            Event::End(_) => {
                if stack.pop().is_some_and(|n| n == b"DataArray")
                    && let Some(a) = open.take()
                {
                    arrays.push(a);
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    let layout = layout.ok_or_else(|| InputError::new(path, 1, "no VTKFile element"))?;
    if pieces.is_empty() {
        let why = "no Piece inside an UnstructuredGrid element";
        return Err(InputError::new(path, lines.at(xml.len()), why));
    }
    Ok((layout, arrays, pieces))
}

fn file_layout(e: &BytesStart) -> Result<Layout, String> {
    match attr(e, b"type").as_deref() {
        Some("UnstructuredGrid") => {}
        other => {
            return Err(format!(
                "VTKFile type {}: only UnstructuredGrid (.vtu) is read",
                super::quote(other.unwrap_or(""))
            ));
        }
    }
    let big_endian = match attr(e, b"byte_order").as_deref() {
        None | Some("LittleEndian") => false,
        Some("BigEndian") => true,
        Some(o) => return Err(format!("byte_order {}", super::quote(o))),
    };
    let header_bytes = match attr(e, b"header_type").as_deref() {
        None | Some("UInt32") => 4,
        Some("UInt64") => 8,
        Some(h) => {
            return Err(format!(
                "header_type {}: expected UInt32 or UInt64",
                super::quote(h)
            ));
        }
    };
    let compressor = match attr(e, b"compressor").as_deref() {
        None | Some("") => Compressor::None,
        Some("vtkZLibDataCompressor") => Compressor::Zlib,
        Some("vtkLZMADataCompressor") => Compressor::Lzma,
        Some("vtkLZ4DataCompressor") => Compressor::Lz4,
        Some(c) => {
            return Err(format!(
                "compressor {}: vtkZLibDataCompressor, vtkLZMADataCompressor and vtkLZ4DataCompressor are read",
                super::quote(c)
            ));
        }
    };
    Ok(Layout {
        big_endian,
        header_bytes,
        compressor,
    })
}

/// A `Piece`'s declared counts.
fn piece(e: &BytesStart, line: usize) -> Result<Piece, String> {
    let count = |name: &[u8]| -> Result<usize, String> {
        let key = String::from_utf8_lossy(name);
        let v = attr(e, name).ok_or_else(|| format!("a Piece without {key}"))?;
        (v.trim().parse()).map_err(|_| format!("{key}={}: not a count", super::quote(&v)))
    };
    Ok(Piece {
        line,
        points: count(b"NumberOfPoints")?,
        cells: count(b"NumberOfCells")?,
    })
}

/// The role of a `DataArray` under the elements of `stack`, or `None` to skip it.
fn role(stack: &[Vec<u8>], e: &BytesStart) -> Option<Role> {
    match stack.last().map(Vec::as_slice) {
        Some(b"Points") => Some(Role::Points),
        Some(b"Cells") => match attr(e, b"Name").as_deref() {
            Some("connectivity") => Some(Role::Connectivity),
            Some("offsets") => Some(Role::Offsets),
            Some("types") => Some(Role::Types),
            _ => None,
        },
        Some(b"PointData") => match attr(e, b"Name").as_deref() {
            Some("GlobalNodeIds" | "GlobalPointIds") => Some(Role::GlobalIds),
            _ => None,
        },
        _ => None,
    }
}

fn data_array(e: &BytesStart, role: Role, piece: usize, line: usize) -> Result<Array, String> {
    let ty = attr(e, b"type").ok_or("a DataArray without a type")?;
    if width(&ty).is_none() {
        return Err(format!("DataArray type {}", super::quote(&ty)));
    }
    if role == Role::Points && attr(e, b"NumberOfComponents").as_deref().unwrap_or("1") != "3" {
        return Err("Points need NumberOfComponents=\"3\"".into());
    }
    let source = match attr(e, b"format").as_deref() {
        Some("ascii") => Source::Ascii(String::new()),
        Some("binary") => Source::Base64(String::new()),
        Some("appended") => {
            let off = attr(e, b"offset").ok_or("an appended DataArray without an offset")?;
            Source::Appended(
                off.trim()
                    .parse()
                    .map_err(|_| format!("offset {}", super::quote(&off)))?,
            )
        }
        f => {
            return Err(format!(
                "DataArray format {}",
                super::quote(f.unwrap_or(""))
            ));
        }
    };
    Ok(Array {
        role,
        piece,
        ty,
        source,
        line,
    })
}

/// Where the arrays' bytes are, to decode them.
struct Decoder<'a> {
    path: &'a Path,
    layout: Layout,
    appended: &'a Appended<'a>,
}

impl Decoder<'_> {
    /// Exactly `want` values of array `a`.
    fn values(&self, a: &Array, want: usize) -> Result<Values, InputError> {
        let err = |why: String| InputError::new(self.path, a.line, why);
        let what = format!("the {:?} array", a.role);
        let err_in = |why: String| err(format!("{what}: {why}"));
        if let Source::Ascii(text) = &a.source {
            return ascii_values(text, &a.ty, want).map_err(err_in);
        }
        let w = width(&a.ty).unwrap_or(1);
        let bytes = want
            .checked_mul(w)
            .ok_or_else(|| err_in(format!("{want} values of {w} bytes are too many")))?;
        let layout = self.layout;
        let payload = match (&a.source, self.appended) {
            (Source::Base64(text), _) => block_from_base64(text.as_bytes(), layout, bytes),
            (Source::Appended(off), Appended::Raw(data)) => match data.get(*off..) {
                Some(d) => block(d, layout, bytes),
                None => Err(format!("offset {off} is past the appended data")),
            },
            (Source::Appended(off), Appended::Base64(data)) => match data.get(*off..) {
                Some(d) => block_from_base64(d, layout, bytes),
                None => Err(format!("offset {off} is past the appended data")),
            },
            _ => Err("an appended DataArray but no AppendedData section".into()),
        }
        .map_err(err_in)?;
        binary_values(&payload, &a.ty, layout.big_endian).map_err(err_in)
    }

    /// Integer values of `a` (`want` of them), or none when there is no array and none
    /// are wanted.
    fn ints(&self, a: Option<&Array>, want: usize, piece: Piece) -> Result<Vec<i64>, InputError> {
        match a.map(|a| (a, self.values(a, want))) {
            None if want == 0 => Ok(Vec::new()),
            None => Err(InputError::new(
                self.path,
                piece.line,
                format!("a Piece of {} cells without its cell arrays", piece.cells),
            )),
            Some((_, Ok(Values::Int(v)))) => Ok(v),
            Some((a, Ok(Values::Float(_)))) => {
                let why = format!("floating-point values in the {:?} array", a.role);
                Err(InputError::new(self.path, a.line, why))
            }
            Some((_, Err(e))) => Err(e),
        }
    }
}

/// One piece's points and cells, added to `merged`.
fn add_piece(
    d: &Decoder,
    p: usize,
    piece: Piece,
    arrays: [Option<&Array>; 5],
    merged: &mut Merged,
) -> Result<(), InputError> {
    absorb(d.path, decode(d, p, piece, arrays), merged)
}

/// A piece's arrays decoded, each step's result kept: absorbing it ([`absorb`]) meets
/// the errors in the order reading the piece meets them.
pub(super) struct Decoded {
    p: usize,
    piece: Piece,
    ids: Result<Option<Vec<i64>>, InputError>,
    coordinates: Result<Vec<f64>, InputError>,
    cells: Result<Cells, InputError>,
}

/// A piece's cell arrays: offsets, types, and the connectivity's first `entries`
/// values (the array's line for messages).
struct Cells {
    offsets: Vec<i64>,
    types: Vec<i64>,
    conn: Vec<i64>,
    entries: usize,
    line: usize,
}

/// Decodes a piece's arrays (no merging: any number of pieces at once).
fn decode(
    d: &Decoder,
    p: usize,
    piece: Piece,
    [points, conn, offsets, types, ids]: [Option<&Array>; 5],
) -> Decoded {
    let line = conn.map_or(piece.line, |a| a.line);
    let cells = || {
        let offsets = d.ints(offsets, piece.cells, piece)?;
        let types = d.ints(types, piece.cells, piece)?;
        let last = offsets.last().copied().unwrap_or(0);
        let why = format!("piece {p}: the last offset is {last}");
        let entries = usize::try_from(last).map_err(|_| InputError::new(d.path, line, why))?;
        let conn = d.ints(conn, entries, piece)?;
        Ok(Cells {
            offsets,
            types,
            conn,
            entries,
            line,
        })
    };
    Decoded {
        p,
        piece,
        ids: ids.map(|_| d.ints(ids, piece.points, piece)).transpose(),
        coordinates: coordinates(d, piece, points),
        cells: cells(),
    }
}

/// Each piece of the `.vtu` at `path` decoded, in order; a fault in the file's layout
/// ends the list as an error.
pub(super) fn decode_file(path: &Path) -> Vec<Result<Decoded, InputError>> {
    let mut out = Vec::new();
    let each = each_piece(path, |d, p, piece, arrays| {
        out.push(Ok(decode(d, p, piece, arrays)));
        Ok(())
    });
    if let Err(e) = each {
        out.push(Err(e));
    }
    out
}

/// The pieces of `path` (the file a [`decode_file`] read) added to `merged`, in order.
pub(super) fn absorb_file(
    path: &Path,
    pieces: Vec<Result<Decoded, InputError>>,
    merged: &mut Merged,
) -> Result<(), InputError> {
    merged.file = path.to_path_buf();
    merged.by_id = false;
    pieces
        .into_iter()
        .try_for_each(|d| absorb(path, d?, merged))
}

/// A decoded piece's points and cells, added to `merged`.
fn absorb(path: &Path, d: Decoded, merged: &mut Merged) -> Result<(), InputError> {
    let (p, piece) = (d.p, d.piece);
    merged.ids = d.ids?;
    merged.add_points(&d.coordinates?)?;
    let c = d.cells?;
    let err = |why: String| InputError::new(path, c.line, why);
    let mut begin = 0usize;
    let mut cell = Vec::new();
    for (k, (&end, &t)) in c.offsets.iter().zip(&c.types).enumerate() {
        let Some(end) = usize::try_from(end)
            .ok()
            .filter(|&e| e >= begin && e <= c.entries)
        else {
            let why = format!(
                "cell {k} of piece {p}: offset {end} is not between the previous one ({begin}) and the last ({})",
                c.entries
            );
            return Err(err(why));
        };
        cell.clear();
        for &v in &c.conn[begin..end] {
            if v < 0 || v as usize >= piece.points {
                let why = format!(
                    "cell {k} of piece {p} names point {v}, but the piece has points 0..={}",
                    piece.points.saturating_sub(1)
                );
                return Err(err(why));
            }
            cell.push(merged.local[v as usize]);
        }
        merged
            .sorter
            .add(t, &cell, c.line, &mut merged.input)
            .map_err(|why| err(format!("cell {k} of piece {p}: {why}")))?;
        begin = end;
    }
    Ok(())
}

/// A piece's `Points`: exactly `3 × NumberOfPoints` coordinates.
fn coordinates(d: &Decoder, piece: Piece, points: Option<&Array>) -> Result<Vec<f64>, InputError> {
    let want = piece.points.saturating_mul(3);
    match points.map(|a| (a, d.values(a, want))) {
        Some((_, Ok(Values::Float(c)))) => Ok(c),
        Some((a, Ok(Values::Int(_)))) => {
            Err(InputError::new(d.path, a.line, "integer point coordinates"))
        }
        Some((_, Err(e))) => Err(e),
        None if piece.points == 0 => Ok(Vec::new()),
        None => {
            let why = format!("a Piece of {} points without Points", piece.points);
            Err(InputError::new(d.path, piece.line, why))
        }
    }
}
