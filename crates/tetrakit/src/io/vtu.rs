//! VTK XML `.vtu` (`UnstructuredGrid`), as VTK, ParaView and meshio write it: every
//! `Piece`'s `Points` and its `Cells` (`connectivity`, `offsets`, `types`), each
//! `DataArray` in any of the three forms VTK has: `format="ascii"` (numbers as text),
//! `format="binary"` (base64 inline) and `format="appended"` (an offset into the
//! `AppendedData` section, `encoding="raw"` or `"base64"`). Binary data may be
//! zlib-compressed (`compressor="vtkZLibDataCompressor"`, VTK's block layout), in either
//! byte order, with 32- or 64-bit headers (`header_type`). `PointData`/`CellData` arrays
//! are not read. Cells are filed as in legacy VTK ([`super::vtk`]): tetrahedra, triangles
//! and lines are kept, other types are an error that counts them.
//!
//! Nothing is sized from a header: every count is checked against the data decoded, and a
//! compressed block may not claim more than zlib's maximum ratio (1032:1) of its bytes.
//! Errors name the line of the `DataArray` (or element) at fault.

use super::vtk::CellSorter;
use super::{Input, InputError, check_segments, read_bytes};
use base64::Engine;
use quick_xml::events::{BytesStart, Event};
use std::io::Read;
use std::path::Path;

/// What a `DataArray` holds, by where it sits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Role {
    Points,
    Connectivity,
    Offsets,
    Types,
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

/// The `VTKFile` element's settings.
#[derive(Clone, Copy, Debug)]
struct Layout {
    big_endian: bool,
    header_bytes: usize,
    compressed: bool,
}

/// The `AppendedData` section: raw bytes, or base64 text.
enum Appended<'a> {
    None,
    Raw(&'a [u8]),
    Base64(&'a [u8]),
}

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let bytes = read_bytes(path)?;
    let lines = LineIndex::new(&bytes);
    let (xml, appended) = split_appended(&bytes, path, &lines)?;
    let xml = std::str::from_utf8(xml)
        .map_err(|e| InputError::new(path, lines.at(e.valid_up_to()), "not UTF-8 text"))?;
    let (layout, arrays, pieces) = scan(xml, path, &lines)?;
    let mut per_piece: Vec<[Option<Values>; 4]> = (0..pieces).map(|_| Default::default()).collect();
    for a in &arrays {
        let v = decode(a, layout, &appended, path)?;
        per_piece[a.piece][a.role as usize] = Some(v);
    }
    assemble(path, per_piece, &arrays)
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
) -> Result<(Layout, Vec<Array>, usize), InputError> {
    let mut reader = quick_xml::Reader::from_str(xml);
    let mut layout = None;
    let mut stack: Vec<Vec<u8>> = Vec::new();
    let mut arrays = Vec::new();
    let mut pieces = 0usize;
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
                        pieces += 1
                    }
                    b"DataArray" => {
                        let role = role(&stack, e);
                        if let Some(role) = role {
                            let a =
                                data_array(e, role, pieces.saturating_sub(1), line).map_err(err)?;
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
    if pieces == 0 {
        return Err(InputError::new(path, 0, "no UnstructuredGrid Piece"));
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
    let compressed = match attr(e, b"compressor").as_deref() {
        None | Some("") => false,
        Some("vtkZLibDataCompressor") => true,
        Some(c) => {
            return Err(format!(
                "compressor {}: only vtkZLibDataCompressor (zlib) is read",
                super::quote(c)
            ));
        }
    };
    Ok(Layout {
        big_endian,
        header_bytes,
        compressed,
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
        _ => None,
    }
}

fn data_array(e: &BytesStart, role: Role, piece: usize, line: usize) -> Result<Array, String> {
    let ty = attr(e, b"type").ok_or("a DataArray without a type")?;
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

/// An array's values: coordinates as `f64`, indices and types as `i64`.
#[derive(Debug)]
enum Values {
    Float(Vec<f64>),
    Int(Vec<i64>),
}

fn decode(
    a: &Array,
    layout: Layout,
    appended: &Appended,
    path: &Path,
) -> Result<Values, InputError> {
    let err = |why: String| InputError::new(path, a.line, why);
    if let Source::Ascii(text) = &a.source {
        return ascii_values(text, &a.ty).map_err(err);
    }
    let payload = match (&a.source, appended) {
        (Source::Base64(text), _) => block_from_base64(text.as_bytes(), layout),
        (Source::Appended(off), Appended::Raw(data)) => match data.get(*off..) {
            Some(d) => block(d, layout),
            None => Err(format!("offset {off} is past the appended data")),
        },
        (Source::Appended(off), Appended::Base64(data)) => match data.get(*off..) {
            Some(d) => block_from_base64(d, layout),
            None => Err(format!("offset {off} is past the appended data")),
        },
        _ => Err("an appended DataArray but no AppendedData section".into()),
    }
    .map_err(err)?;
    binary_values(&payload, &a.ty, layout.big_endian).map_err(err)
}

fn ascii_values(text: &str, ty: &str) -> Result<Values, String> {
    let toks = text.split_ascii_whitespace();
    if ty.starts_with("Float") {
        toks.map(|t| {
            t.parse::<f64>()
                .map_err(|_| format!("{} is not a number", super::quote(t)))
        })
        .collect::<Result<_, _>>()
        .map(Values::Float)
    } else {
        toks.map(|t| {
            t.parse::<i64>()
                .map_err(|_| format!("{} is not an integer", super::quote(t)))
        })
        .collect::<Result<_, _>>()
        .map(Values::Int)
    }
}

/// An unsigned header word.
fn word(bytes: &[u8], big_endian: bool) -> u64 {
    let mut b = [0u8; 8];
    if big_endian {
        b[8 - bytes.len()..].copy_from_slice(bytes);
        u64::from_be_bytes(b)
    } else {
        b[..bytes.len()].copy_from_slice(bytes);
        u64::from_le_bytes(b)
    }
}

/// The `k` header words at the start of `data`.
fn header(data: &[u8], k: usize, layout: Layout) -> Result<Vec<usize>, String> {
    let w = layout.header_bytes;
    let bytes = data.get(..k * w).ok_or("the data ends inside its header")?;
    Ok(bytes
        .chunks_exact(w)
        .map(|c| word(c, layout.big_endian) as usize)
        .collect())
}

/// Compressed-block header: `[blocks, block size, last block size, sizes...]`, and the
/// uncompressed size of each block.
fn block_sizes(h: &[usize]) -> Vec<usize> {
    let (n, size, last) = (h[0], h[1], h[2]);
    (0..n)
        .map(|i| if i + 1 == n && last != 0 { last } else { size })
        .collect()
}

/// The data of one binary block (its header, then the bytes; compressed or not).
fn block(d: &[u8], layout: Layout) -> Result<Vec<u8>, String> {
    let w = layout.header_bytes;
    if !layout.compressed {
        let n = header(d, 1, layout)?[0];
        return d
            .get(w..)
            .and_then(|r| r.get(..n))
            .map(<[u8]>::to_vec)
            .ok_or_else(|| {
                format!(
                    "the header claims {n} bytes but {} follow",
                    d.len().saturating_sub(w)
                )
            });
    }
    let blocks = header(d, 3, layout)?[0];
    if blocks > d.len() {
        return Err(format!(
            "the header claims {blocks} blocks in {} bytes",
            d.len()
        ));
    }
    let h = header(d, 3 + blocks, layout)?;
    inflate(&h, &d[(3 + blocks) * w..])
}

/// Inflates the blocks `h` describes from `data`.
fn inflate(h: &[usize], data: &[u8]) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    let mut at = 0usize;
    for (k, (&raw, &packed)) in block_sizes(h).iter().zip(&h[3..]).enumerate() {
        let chunk = data
            .get(at..at.saturating_add(packed))
            .ok_or_else(|| format!("block {k} claims {packed} bytes past the end of the data"))?;
        if raw > packed.saturating_mul(1032).saturating_add(64) {
            return Err(format!(
                "block {k} claims {raw} bytes from {packed} compressed bytes"
            ));
        }
        let before = out.len();
        flate2::read::ZlibDecoder::new(chunk)
            .take(raw as u64 + 1)
            .read_to_end(&mut out)
            .map_err(|e| format!("block {k} is not zlib data: {e}"))?;
        if out.len() - before != raw {
            return Err(format!(
                "block {k} inflates to {} bytes, not {raw}",
                out.len() - before
            ));
        }
        at += packed;
    }
    Ok(out)
}

/// Decodes the first `max_groups` 4-character groups of base64 made of one or more
/// padded runs (VTK encodes a header and its data as two runs, meshio as one): each run
/// ends at a group with padding.
fn base64_runs(text: &[u8], max_groups: usize) -> Result<Vec<u8>, String> {
    let base64 = |c: &u8| c.is_ascii_alphanumeric() || b"+/=".contains(c);
    let chars: Vec<u8> = text
        .iter()
        .copied()
        .filter(|c| !c.is_ascii_whitespace())
        .take_while(base64)
        .take(max_groups.saturating_mul(4))
        .collect();
    let mut out = Vec::with_capacity(chars.len() / 4 * 3);
    let engine = base64::engine::general_purpose::STANDARD;
    let mut start = 0;
    for (g, quad) in chars.chunks(4).enumerate() {
        let end = g * 4 + quad.len();
        if quad.contains(&b'=') || end == chars.len() {
            engine
                .decode_vec(&chars[start..end], &mut out)
                .map_err(|e| format!("bad base64: {e}"))?;
            start = end;
        }
    }
    Ok(out)
}

/// A block (header, then data) from base64. A decoded prefix is a prefix of header ++
/// data whether the two were one run or two (then one more group at most), so the
/// header is decoded first and then exactly the groups the data needs.
fn block_from_base64(text: &[u8], layout: Layout) -> Result<Vec<u8>, String> {
    let w = layout.header_bytes;
    let prefix = |bytes: usize| base64_runs(text, bytes.div_ceil(3) + 1);
    let words = match layout.compressed {
        true => 3usize.saturating_add(header(&prefix(3 * w)?, 1, layout)?[0]),
        false => 1,
    };
    if words > text.len() {
        return Err(format!(
            "the header claims {} blocks in {} characters",
            words - 3,
            text.len()
        ));
    }
    let head_bytes = words * w;
    let h = header(&prefix(head_bytes)?, words, layout)?;
    let data_bytes = match layout.compressed {
        true => h[3..].iter().fold(0usize, |a, &b| a.saturating_add(b)),
        false => h[0],
    };
    if data_bytes > text.len() {
        return Err(format!(
            "the header claims {data_bytes} bytes in {} characters",
            text.len()
        ));
    }
    let all = base64_runs(text, head_bytes.div_ceil(3) + data_bytes.div_ceil(3) + 1)?;
    let data = all
        .get(head_bytes..head_bytes + data_bytes)
        .ok_or("the data ends early")?;
    match layout.compressed {
        true => inflate(&h, data),
        false => Ok(data.to_vec()),
    }
}

fn binary_values(bytes: &[u8], ty: &str, big_endian: bool) -> Result<Values, String> {
    macro_rules! each {
        ($t:ty, $wrap:path, $conv:expr) => {{
            let size = std::mem::size_of::<$t>();
            if bytes.len() % size != 0 {
                return Err(format!(
                    "{} bytes are not a whole number of {ty} values",
                    bytes.len()
                ));
            }
            let conv = $conv;
            let v = bytes.chunks_exact(size).map(|c| {
                let a = c.try_into().expect("chunks of the size");
                conv(if big_endian {
                    <$t>::from_be_bytes(a)
                } else {
                    <$t>::from_le_bytes(a)
                })
            });
            $wrap(v.collect::<Result<Vec<_>, String>>()?)
        }};
    }
    let too_big = |v: u64| i64::try_from(v).map_err(|_| format!("{v} is too large"));
    Ok(match ty {
        "Float32" => each!(f32, Values::Float, |x: f32| Ok(f64::from(x))),
        "Float64" => each!(f64, Values::Float, |x: f64| Ok(x)),
        "Int8" => each!(i8, Values::Int, |x: i8| Ok(i64::from(x))),
        "UInt8" => each!(u8, Values::Int, |x: u8| Ok(i64::from(x))),
        "Int16" => each!(i16, Values::Int, |x: i16| Ok(i64::from(x))),
        "UInt16" => each!(u16, Values::Int, |x: u16| Ok(i64::from(x))),
        "Int32" => each!(i32, Values::Int, |x: i32| Ok(i64::from(x))),
        "UInt32" => each!(u32, Values::Int, |x: u32| Ok(i64::from(x))),
        "Int64" => each!(i64, Values::Int, |x: i64| Ok(x)),
        "UInt64" => each!(u64, Values::Int, too_big),
        _ => return Err(format!("DataArray type {}", super::quote(ty))),
    })
}

/// The pieces' points and cells, in order, as one [`Input`].
fn assemble(
    path: &Path,
    pieces: Vec<[Option<Values>; 4]>,
    arrays: &[Array],
) -> Result<Input, InputError> {
    let line_of = |piece: usize, role: Role| {
        arrays
            .iter()
            .find(|a| a.piece == piece && a.role == role)
            .map_or(0, |a| a.line)
    };
    let mut input = Input {
        dim: 3,
        point_file: path.to_path_buf(),
        tet_file: path.to_path_buf(),
        ..Default::default()
    };
    let mut sorter = CellSorter::default();
    let mut seg_lines = Vec::new();
    let mut cell = Vec::new();
    for (p, [points, conn, offsets, types]) in pieces.into_iter().enumerate() {
        let err = |role: Role, why: String| InputError::new(path, line_of(p, role), why);
        let first = input.points.len();
        match points {
            Some(Values::Float(c)) => {
                if c.len() % 3 != 0 {
                    return Err(err(
                        Role::Points,
                        format!("{} coordinates are not triples", c.len()),
                    ));
                }
                input
                    .points
                    .extend(c.chunks_exact(3).map(|c| [c[0], c[1], c[2]]));
            }
            Some(Values::Int(_)) => {
                return Err(err(Role::Points, "integer point coordinates".into()));
            }
            None => return Err(InputError::new(path, 0, format!("piece {p} has no Points"))),
        }
        let ints = |v: Option<Values>, role: Role, name: &str| match v {
            Some(Values::Int(v)) => Ok(v),
            None => Ok(Vec::new()),
            Some(Values::Float(_)) => Err(err(role, format!("floating-point {name}"))),
        };
        let conn = ints(conn, Role::Connectivity, "connectivity")?;
        let offsets = ints(offsets, Role::Offsets, "offsets")?;
        let types = ints(types, Role::Types, "types")?;
        if offsets.len() != types.len() {
            let why = format!("{} offsets for {} cell types", offsets.len(), types.len());
            return Err(err(Role::Offsets, why));
        }
        let n = input.points.len() - first;
        let at = line_of(p, Role::Connectivity);
        let mut begin = 0usize;
        for (k, (&end, &t)) in offsets.iter().zip(&types).enumerate() {
            let end = usize::try_from(end)
                .ok()
                .filter(|&e| e >= begin && e <= conn.len());
            let Some(end) = end else {
                let why = format!(
                    "offset {} of cell {k} is out of order or past the connectivity",
                    offsets[k]
                );
                return Err(err(Role::Offsets, why));
            };
            cell.clear();
            for &v in &conn[begin..end] {
                if v < 0 || v as usize >= n {
                    let why = format!(
                        "cell {k} names point {v}, but piece {p} has points 0..={}",
                        n.saturating_sub(1)
                    );
                    return Err(err(Role::Connectivity, why));
                }
                cell.push((first + v as usize) as u32);
            }
            sorter
                .add(t, &cell, at, &mut input, &mut seg_lines)
                .map_err(|why| InputError::new(path, at, why))?;
            begin = end;
        }
    }
    sorter.finish(&mut input);
    if input.points.is_empty() {
        return Err(InputError::new(path, 0, "no points"));
    }
    check_segments(&input.segments, &seg_lines, 0, path)?;
    Ok(input)
}
