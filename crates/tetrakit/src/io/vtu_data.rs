//! The values of one `.vtu` `DataArray`: ASCII numbers, or binary blocks (a header of
//! byte counts, then the bytes), inline in base64 or appended (raw or base64), plain or
//! compressed in VTK's block layout (`[blocks, block size, last block size, compressed
//! sizes…]`, then each block compressed alone) by zlib, LZMA (xz streams) or LZ4 (raw
//! blocks).
//!
//! The caller says how many values the array must hold (from the piece's declared
//! counts); a binary header that declares another number of bytes is an error before a
//! byte is decoded or inflated, and a compressed block may not claim more than
//! [`MAX_RATIO`] times its compressed bytes. So the bytes produced never exceed what the
//! declared counts times the value width allow, nor the ratio times the file.

use base64::Engine;
use std::io::Read;

/// The most a compressed block may inflate to, per compressed byte (zlib's own limit is
/// 1032:1, LZ4's 255:1; VTK's 32 KiB blocks stay far below it with LZMA too), plus
/// [`SLACK`] bytes for tiny blocks.
pub(super) const MAX_RATIO: usize = 1032;
const SLACK: usize = 64;

/// How binary data is compressed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Compressor {
    None,
    Zlib,
    Lzma,
    Lz4,
}

/// The `VTKFile` element's settings for binary data.
#[derive(Clone, Copy, Debug)]
pub(super) struct Layout {
    pub(super) big_endian: bool,
    pub(super) header_bytes: usize,
    pub(super) compressor: Compressor,
}

/// An array's values: coordinates as `f64`, indices and types as `i64`.
#[derive(Debug)]
pub(super) enum Values {
    Float(Vec<f64>),
    Int(Vec<i64>),
}

/// The bytes of one value of VTK type `ty`, or `None` for a type this reader does not
/// know.
pub(super) fn width(ty: &str) -> Option<usize> {
    Some(match ty {
        "Int8" | "UInt8" => 1,
        "Int16" | "UInt16" => 2,
        "Int32" | "UInt32" | "Float32" => 4,
        "Int64" | "UInt64" | "Float64" => 8,
        _ => return None,
    })
}

/// Exactly `want` numbers of type `ty` from ASCII text.
pub(super) fn ascii_values(text: &str, ty: &str, want: usize) -> Result<Values, String> {
    let found = text.split_ascii_whitespace().count();
    if found != want {
        return Err(format!("holds {found} values where {want} are declared"));
    }
    let toks = text.split_ascii_whitespace();
    if ty == "Float32" {
        return (toks.map(super::parse_coord32))
            .collect::<Result<_, _>>()
            .map(Values::Float);
    }
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
    let bytes = (k.checked_mul(w))
        .and_then(|n| data.get(..n))
        .ok_or("the data ends inside its header")?;
    Ok(bytes
        .chunks_exact(w)
        .map(|c| usize::try_from(word(c, layout.big_endian)).unwrap_or(usize::MAX))
        .collect())
}

/// The uncompressed size of each block of a compressed array's header `[blocks, block
/// size, last block size, …]`, checked to add up to `want` bytes.
fn block_sizes(h: &[usize], want: usize) -> Result<Vec<usize>, String> {
    let (n, size, last) = (h[0], h[1], h[2]);
    let last = if last == 0 { size } else { last };
    let total = match n {
        0 => Some(0),
        _ => (n - 1).checked_mul(size).and_then(|t| t.checked_add(last)),
    };
    if total != Some(want) || last > size {
        return Err(format!(
            "the header declares {n} blocks of {size} bytes (the last {last}), where {want} bytes are declared by the piece"
        ));
    }
    Ok((0..n)
        .map(|i| if i + 1 == n { last } else { size })
        .collect())
}

/// The `want` data bytes of one binary block at the start of `d` (its header, then the
/// bytes; compressed or not).
pub(super) fn block(d: &[u8], layout: Layout, want: usize) -> Result<Vec<u8>, String> {
    let w = layout.header_bytes;
    if layout.compressor == Compressor::None {
        let n = header(d, 1, layout)?[0];
        if n != want {
            return Err(format!(
                "the header declares {n} bytes where {want} are declared by the piece"
            ));
        }
        return d
            .get(w..)
            .and_then(|r| r.get(..n))
            .map(<[u8]>::to_vec)
            .ok_or_else(|| {
                format!(
                    "{n} bytes declared but {} follow",
                    d.len().saturating_sub(w)
                )
            });
    }
    let blocks = header(d, 3, layout)?[0];
    if blocks > d.len() {
        let why = format!("the header declares {blocks} blocks in {} bytes", d.len());
        return Err(why);
    }
    let h = header(d, 3 + blocks, layout)?;
    inflate(&h, &d[(3 + blocks) * w..], layout.compressor, want)
}

/// Inflates the blocks `h` describes from `data`: exactly `want` bytes. Every block's
/// claim is checked (its bytes present, at most [`MAX_RATIO`] to one) before the output
/// is reserved, at its exact size.
fn inflate(h: &[usize], data: &[u8], how: Compressor, want: usize) -> Result<Vec<u8>, String> {
    let sizes = block_sizes(h, want)?;
    let mut at = 0usize;
    for (k, (&raw, &packed)) in sizes.iter().zip(&h[3..]).enumerate() {
        at = at.saturating_add(packed);
        if at > data.len() {
            return Err(format!(
                "block {k} claims {packed} bytes past the end of the data"
            ));
        }
        if raw > packed.saturating_mul(MAX_RATIO).saturating_add(SLACK) {
            return Err(format!(
                "block {k} claims {raw} bytes from {packed} compressed bytes (more than {MAX_RATIO}:1)"
            ));
        }
    }
    let mut out = Vec::with_capacity(want);
    let mut at = 0usize;
    for (k, (&raw, &packed)) in sizes.iter().zip(&h[3..]).enumerate() {
        let chunk = &data[at..at + packed];
        let before = out.len();
        unpack(chunk, how, raw, &mut out).map_err(|e| format!("block {k}: {e}"))?;
        if out.len() - before != raw {
            let got = out.len() - before;
            return Err(format!("block {k} inflates to {got} bytes, not {raw}"));
        }
        at += packed;
    }
    Ok(out)
}

/// Appends to `out` what `chunk` decompresses to, stopping one byte past `raw`.
fn unpack(chunk: &[u8], how: Compressor, raw: usize, out: &mut Vec<u8>) -> Result<(), String> {
    match how {
        Compressor::Zlib => flate2::read::ZlibDecoder::new(chunk)
            .take(raw as u64 + 1)
            .read_to_end(out)
            .map(drop)
            .map_err(|e| format!("not zlib data: {e}")),
        Compressor::Lzma => {
            let mut sink = Bounded { out, left: raw + 1 };
            lzma_rs::xz_decompress(&mut std::io::BufReader::new(chunk), &mut sink)
                .map_err(|e| format!("not LZMA (xz) data: {e}"))
        }
        Compressor::Lz4 => {
            let start = out.len();
            out.resize(start + raw, 0);
            match lz4_flex::block::decompress_into(chunk, &mut out[start..]) {
                Ok(n) => {
                    out.truncate(start + n);
                    Ok(())
                }
                Err(e) => Err(format!("not LZ4 data: {e}")),
            }
        }
        Compressor::None => {
            out.extend_from_slice(chunk);
            Ok(())
        }
    }
}

/// A writer into a vector that refuses to grow it past `left` more bytes.
struct Bounded<'a> {
    out: &'a mut Vec<u8>,
    left: usize,
}

impl std::io::Write for Bounded<'_> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if buf.len() > self.left {
            return Err(std::io::Error::other("more bytes than the header declares"));
        }
        self.left -= buf.len();
        self.out.extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
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

/// A block (header, then `want` data bytes) from base64. A decoded prefix is a prefix of
/// header ++ data whether the two were one run or two (then one more group at most), so
/// the header is decoded first and then exactly the groups the data needs.
pub(super) fn block_from_base64(
    text: &[u8],
    layout: Layout,
    want: usize,
) -> Result<Vec<u8>, String> {
    let w = layout.header_bytes;
    let compressed = layout.compressor != Compressor::None;
    let prefix = |bytes: usize| base64_runs(text, bytes.div_ceil(3) + 1);
    let words = match compressed {
        true => 3usize.saturating_add(header(&prefix(3 * w)?, 1, layout)?[0]),
        false => 1,
    };
    if words > text.len() {
        let why = format!(
            "the header declares {} blocks in {} characters",
            words - 3,
            text.len()
        );
        return Err(why);
    }
    let head_bytes = words * w;
    let h = header(&prefix(head_bytes)?, words, layout)?;
    let data_bytes = match compressed {
        true => {
            block_sizes(&h, want)?;
            h[3..].iter().fold(0usize, |a, &b| a.saturating_add(b))
        }
        false if h[0] != want => {
            let n = h[0];
            return Err(format!(
                "the header declares {n} bytes where {want} are declared by the piece"
            ));
        }
        false => h[0],
    };
    if data_bytes > text.len() {
        let why = format!(
            "the header declares {data_bytes} bytes in {} characters",
            text.len()
        );
        return Err(why);
    }
    let all = base64_runs(text, head_bytes.div_ceil(3) + data_bytes.div_ceil(3) + 1)?;
    let data = all
        .get(head_bytes..head_bytes + data_bytes)
        .ok_or("the data ends early")?;
    match compressed {
        true => inflate(&h, data, layout.compressor, want),
        false => Ok(data.to_vec()),
    }
}

/// The values of type `ty` in `bytes` (a whole number of them: the caller has checked
/// the byte count).
pub(super) fn binary_values(bytes: &[u8], ty: &str, big_endian: bool) -> Result<Values, String> {
    macro_rules! each {
        ($t:ty, $wrap:path, $conv:expr) => {{
            let size = std::mem::size_of::<$t>();
            let conv = $conv;
            let mut v = Vec::with_capacity(bytes.len() / size);
            for c in bytes.chunks_exact(size) {
                let a = c.try_into().expect("chunks of the size");
                let x: Result<_, String> = conv(if big_endian {
                    <$t>::from_be_bytes(a)
                } else {
                    <$t>::from_le_bytes(a)
                });
                v.push(x?);
            }
            $wrap(v)
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
