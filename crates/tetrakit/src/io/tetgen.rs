//! TetGen's `.node`, `.edge`, `.ele` and `.face` formats (0- or 1-based, `#` comments,
//! attributes and boundary markers), read strictly. Rows of `.node`, `.edge` and `.face`
//! are numbered `base, base + 1, ...`; a `.ele` may number its tetrahedra with gaps, in
//! increasing order (TetGen and meshio ignore those numbers), and they are kept in
//! [`Input::tet_labels`] to name tetrahedra in witnesses.

use super::{Input, InputError, Tokens, parse_coord, parse_int, read_text, vertex_ref};
use crate::rows::split_at_offsets;
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// Reads a TetGen file set starting from any of its members.
pub(super) fn read(path: &Path, ext: &str) -> Result<Input, InputError> {
    let node = if ext == "node" {
        Some(path.to_path_buf())
    } else {
        sibling(path, "node")?
    };
    let Some(node) = node else {
        return Err(InputError::new(
            path,
            0,
            format!(
                "needs the point file {} beside it",
                path.with_extension("node").display()
            ),
        ));
    };
    let mut input = read_node(&node)?;
    let member = |e: &str| -> Result<Option<PathBuf>, InputError> {
        match (ext == e, ext == "node") {
            (true, _) => Ok(Some(path.to_path_buf())),
            (false, true) => sibling(path, e),
            (false, false) => Ok(None),
        }
    };
    if let Some(p) = member("edge")? {
        let (rows, lines, _) = read_rows::<2>(&p, &input, "edge", Numbering::Consecutive)?;
        (input.segments, input.segment_lines, input.segment_file) = (rows, lines, p);
    }
    if let Some(p) = member("ele")? {
        let (tets, lines, labels) = read_rows::<4>(&p, &input, "tetrahedron", Numbering::Gaps)?;
        let base = input.index_base;
        let plain = labels
            .iter()
            .enumerate()
            .all(|(k, &l)| l == k as u32 + base);
        input.tet_labels = if plain { Vec::new() } else { labels };
        (input.tets, input.tet_lines, input.tet_file) = (tets, lines, p);
    }
    if let Some(p) = member("face")? {
        input.faces = read_rows::<3>(&p, &input, "face", Numbering::Consecutive)?.0;
    }
    Ok(input)
}

/// The member of `path`'s file set with extension `ext` (lower case): the same stem with
/// `ext` in the case of `path`'s own extension (`m.ELE` → `m.NODE`) or in lower case,
/// whichever exists; `None` when neither does. Both existing as different files with
/// different contents is an error (which one the user meant cannot be told).
fn sibling(path: &Path, ext: &str) -> Result<Option<PathBuf>, InputError> {
    let own = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    let upper = !own.is_empty() && own.chars().all(|c| !c.is_ascii_lowercase());
    let same_case = path.with_extension(if upper {
        ext.to_ascii_uppercase()
    } else {
        ext.to_string()
    });
    let lower = path.with_extension(ext);
    match (same_case.is_file(), lower.is_file()) {
        (false, false) => Ok(None),
        (true, false) => Ok(Some(same_case)),
        (false, true) => Ok(Some(lower)),
        (true, true) if same_case == lower || same_file(&same_case, &lower) => Ok(Some(same_case)),
        (true, true) => Err(InputError::new(
            path,
            0,
            format!(
                "both {} and {} exist and differ: rename one (which belongs to this file cannot be told)",
                same_case.display(),
                lower.display()
            ),
        )),
    }
}

/// Whether two paths name one file, or files with the same contents.
fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) if x == y => return true,
        _ => {}
    }
    let len = |p: &Path| std::fs::metadata(p).map(|m| m.len()).ok();
    len(a) == len(b) && std::fs::read(a).ok() == std::fs::read(b).ok()
}

/// The header line (its number and values) and the body after it (with its first line
/// number).
fn split_header<'a>(
    path: &Path,
    text: &'a str,
) -> Result<(usize, Vec<i64>, &'a str, usize), InputError> {
    let mut offset = 0;
    for (i, raw) in text.split_inclusive('\n').enumerate() {
        offset += raw.len();
        let toks = Tokens::new(raw.split('#').next().unwrap_or(""));
        if toks.is_empty() {
            continue;
        }
        let line = i + 1;
        let vals = toks
            .iter()
            .map(|t| parse_int(t, path, line, "header value"))
            .collect::<Result<Vec<_>, _>>()?;
        if vals.iter().any(|&v| v < 0) {
            return Err(InputError::new(path, line, "negative number in the header"));
        }
        // Counts beyond u32 cannot be indexed; refusing them keeps every sum below exact.
        if let Some(v) = vals.iter().find(|&&v| v > i64::from(u32::MAX)) {
            return Err(InputError::new(
                path,
                line,
                format!(
                    "header value {v} is larger than {} (the most this reader indexes)",
                    u32::MAX
                ),
            ));
        }
        return Ok((line, vals, &text[offset..], line + 1));
    }
    Err(InputError::new(path, 0, "empty file: no header line"))
}

/// The first meaningful row of `body`: (line number, first token).
fn first_row(body: &str, first_line: usize) -> Option<(usize, &str)> {
    body.split_inclusive('\n').enumerate().find_map(|(i, raw)| {
        let t = raw
            .split('#')
            .next()
            .unwrap_or("")
            .split_ascii_whitespace()
            .next()?;
        Some((first_line + i, t))
    })
}

/// Parsed rows with their line numbers, or the first error.
type Rows<T> = Result<(Vec<T>, Vec<u32>), InputError>;

/// Parses the rows of `body` in parallel (`blank` fills the result before the rows are
/// written): `fast(bytes, ordinal)`, else `parse(tokens, line, ordinal)`, for every
/// meaningful line, in file order. The body is cut at line boundaries; a first pass counts
/// lines and rows per piece so that every row knows its line number and ordinal, so the
/// first error in file order is the one reported.
fn parse_body<T: Copy + Send + Sync>(
    body: &str,
    first_line: usize,
    blank: T,
    fast: impl Fn(&[u8], usize) -> Option<T> + Sync,
    parse: impl Fn(&[&str], usize, usize) -> Result<T, InputError> + Sync,
) -> Rows<T> {
    let target = (body.len() / 64).max(1 << 16);
    let bytes = body.as_bytes();
    let mut cuts = vec![0usize];
    while *cuts.last().unwrap_or(&0) < body.len() {
        let start = *cuts.last().unwrap_or(&0);
        let mut end = (start + target).min(body.len());
        while end < body.len() && bytes[end - 1] != b'\n' {
            end += 1;
        }
        cuts.push(end);
    }
    let pieces: Vec<&str> = cuts.windows(2).map(|w| &body[w[0]..w[1]]).collect();
    // A token before any `#` (the same test as `Tokens`, on bytes).
    let meaningful = |raw: &str| {
        raw.bytes()
            .take_while(|&b| b != b'#')
            .any(|b| !b.is_ascii_whitespace())
    };
    let counts: Vec<(usize, usize)> = pieces
        .par_iter()
        .map(|p| {
            (
                p.bytes().filter(|&b| b == b'\n').count(),
                p.split_inclusive('\n').filter(|r| meaningful(r)).count(),
            )
        })
        .collect();
    let mut starts = Vec::with_capacity(pieces.len());
    let (mut line, mut ordinal) = (first_line, 0usize);
    for &(lines, rows) in &counts {
        starts.push((line, ordinal));
        line += lines;
        ordinal += rows;
    }
    // Every piece writes its rows and their line numbers straight into its own range of
    // the result (the counting pass above applies the same "meaningful" rule as the
    // parser: a token before any `#`).
    let offsets: Vec<usize> = starts.iter().map(|s| s.1).chain([ordinal]).collect();
    let mut rows = vec![blank; ordinal];
    let mut lines = vec![0u32; ordinal];
    let outs = split_at_offsets(&mut rows, &offsets)
        .into_par_iter()
        .zip(split_at_offsets(&mut lines, &offsets));
    let results: Vec<Result<(), InputError>> = pieces
        .par_iter()
        .zip(&starts)
        .zip(outs)
        .map(|((piece, &(line0, ord0)), (out, out_lines))| {
            let mut k = 0;
            for (i, raw) in piece.split_inclusive('\n').enumerate() {
                let row = match fast(raw.as_bytes(), ord0 + k) {
                    Some(row) => row,
                    None => {
                        let toks = Tokens::new(raw.split('#').next().unwrap_or(""));
                        if toks.is_empty() {
                            continue;
                        }
                        parse(&toks, line0 + i, ord0 + k)?
                    }
                };
                out[k] = row;
                out_lines[k] = (line0 + i) as u32;
                k += 1;
            }
            Ok(())
        })
        .collect();
    results.into_iter().collect::<Result<(), _>>()?;
    Ok((rows, lines))
}

/// The TetGen numbering base given by the first row's index (0 or 1).
fn numbering_base(
    path: &Path,
    body: &str,
    first_line: usize,
    what: &str,
) -> Result<i64, InputError> {
    let Some((line, tok)) = first_row(body, first_line) else {
        return Ok(1);
    };
    let idx = parse_int(tok, path, line, "index")?;
    if idx != 0 && idx != 1 {
        return Err(InputError::new(
            path,
            line,
            format!("first {what} is numbered {idx}; TetGen numbering starts at 0 or 1"),
        ));
    }
    Ok(idx)
}

/// How the rows of a file are numbered: `base, base + 1, ...` (TetGen's rule, required
/// of `.node`, `.edge` and `.face`), or strictly increasing with gaps allowed (`.ele`, whose
/// row numbers TetGen and meshio ignore; kept to name tetrahedra in witnesses).
#[derive(Clone, Copy, PartialEq)]
enum Numbering {
    Consecutive,
    Gaps,
}

/// Reads a row's index and checks it (`base + ordinal` when consecutive, at most
/// `u32::MAX` otherwise) and that the header declared enough rows.
fn check_row_index(
    path: &Path,
    toks: &[&str],
    line: usize,
    ordinal: usize,
    (base, declared, what, numbering): (i64, usize, &str, Numbering),
) -> Result<u32, InputError> {
    let idx = parse_int(toks[0], path, line, "index")?;
    let expect = base + ordinal as i64;
    if numbering == Numbering::Consecutive && idx != expect {
        return Err(InputError::new(
            path,
            line,
            format!("{what} numbered {idx}, expected {expect}"),
        ));
    }
    let label = u32::try_from(idx).map_err(|_| {
        InputError::new(
            path,
            line,
            format!("{what} numbered {idx}: numbers run from 0 to {}", u32::MAX),
        )
    })?;
    if ordinal >= declared {
        return Err(InputError::new(
            path,
            line,
            format!("more {what}s than the {declared} the header declares"),
        ));
    }
    Ok(label)
}

/// Row numbers with gaps must increase, so that each names one row.
fn check_increasing(
    path: &Path,
    labels: &[u32],
    lines: &[u32],
    what: &str,
) -> Result<(), InputError> {
    match labels.windows(2).position(|w| w[1] <= w[0]) {
        None => Ok(()),
        Some(k) => Err(InputError::new(
            path,
            lines[k + 1] as usize,
            format!(
                "{what} numbered {} after {}: numbers must increase (gaps are allowed)",
                labels[k + 1],
                labels[k]
            ),
        )),
    }
}

/// The number of rows read must be the number the header declared.
fn check_row_count(
    path: &Path,
    found: usize,
    declared: usize,
    what: &str,
) -> Result<(), InputError> {
    if found != declared {
        return Err(InputError::new(
            path,
            0,
            format!("header declares {declared} {what}s but the file has {found} (truncated?)"),
        ));
    }
    Ok(())
}

fn read_node(path: &Path) -> Result<Input, InputError> {
    let text = read_text(path)?;
    let (hline, h, body, first_line) = split_header(path, &text)?;
    let declared = h[0] as usize;
    let dim = h.get(1).copied().unwrap_or(3) as usize;
    if !(2..=3).contains(&dim) {
        return Err(InputError::new(
            path,
            hline,
            format!("dimension {dim} is not 2 or 3"),
        ));
    }
    let extra = (h.get(2).copied().unwrap_or(0) + h.get(3).copied().unwrap_or(0)) as usize;
    let base = numbering_base(path, body, first_line, "point")?;
    let (points, lines) = parse_body(
        body,
        first_line,
        [0.0; 3],
        |_, _| None,
        |toks, line, ordinal| {
            if toks.len() < 1 + dim || toks.len() > 1 + dim + extra {
                return Err(InputError::new(
                    path,
                    line,
                    format!(
                        "expected an index, {dim} coordinates and {extra} attributes/markers, found {} values",
                        toks.len()
                    ),
                ));
            }
            let key = (base, declared, "point", Numbering::Consecutive);
            check_row_index(path, toks, line, ordinal, key)?;
            let mut p = [0.0; 3];
            for k in 0..dim {
                p[k] = parse_coord(toks[1 + k], path, line)?;
            }
            Ok(p)
        },
    )?;
    check_row_count(path, points.len(), declared, "point")?;
    if declared == 0 {
        return Err(InputError::new(path, hline, "no points"));
    }
    Ok(Input {
        dim,
        points,
        point_lines: lines.into_iter().map(|l| l as usize).collect(),
        index_base: base as u32,
        point_file: path.to_path_buf(),
        ..Default::default()
    })
}

/// The rows of an element file, their lines and their indices.
type ElementRows<const K: usize> = (Vec<[u32; K]>, Vec<u32>, Vec<u32>);

/// Reads a TetGen element file whose rows are `index v1 .. vK [extras]`.
fn read_rows<const K: usize>(
    path: &Path,
    nodes: &Input,
    what: &str,
    numbering: Numbering,
) -> Result<ElementRows<K>, InputError> {
    let text = read_text(path)?;
    let (hline, h, body, first_line) = split_header(path, &text)?;
    let declared = h[0] as usize;
    let per_row = if K == 4 {
        h.get(1).copied().unwrap_or(4) as usize
    } else {
        K
    };
    if K == 4 && per_row != 4 && per_row != 10 {
        return Err(InputError::new(
            path,
            hline,
            format!("{per_row} nodes per tetrahedron (expected 4 or 10)"),
        ));
    }
    let extra = if K == 4 {
        h.get(2).copied().unwrap_or(0) as usize
    } else {
        h.get(1).copied().unwrap_or(0) as usize
    };
    let base = match numbering {
        Numbering::Consecutive => numbering_base(path, body, first_line, what)?,
        Numbering::Gaps => 0,
    };
    let (lo, hi) = (1 + per_row.max(K), 1 + per_row + extra);
    let n = nodes.points.len() as u64;
    let node_base = u64::from(nodes.index_base);
    // A plain row (unsigned integers only) that passes every check below, without
    // tokenizing; anything else goes through the checks that name the problem.
    let fast = |raw: &[u8], ordinal: usize| -> Option<([u32; K], u32)> {
        let (vals, count) = uint_row::<16>(raw)?;
        let label = u32::try_from(vals[0]).ok()?;
        let label_ok = match numbering {
            Numbering::Consecutive => vals[0] == (base as u64) + ordinal as u64,
            Numbering::Gaps => true,
        };
        if !(lo..=hi).contains(&count) || !label_ok || ordinal >= declared {
            return None;
        }
        // Every node is range-checked (a 10-node tetrahedron's edge midpoints too); the
        // corners are kept.
        let in_range = |v: u64| v >= node_base && v - node_base < n;
        if !vals[1..1 + per_row.max(K)].iter().all(|&v| in_range(v)) {
            return None;
        }
        Some((
            std::array::from_fn(|k| (vals[1 + k] - node_base) as u32),
            label,
        ))
    };
    let blank = ([0; K], 0);
    let (rows, lines) = parse_body(body, first_line, blank, fast, |toks, line, ordinal| {
        if toks.len() < lo || toks.len() > hi {
            return Err(InputError::new(
                path,
                line,
                format!(
                    "expected an index and {per_row} vertices (plus {extra} attributes/markers), found {} values",
                    toks.len()
                ),
            ));
        }
        let key = (base, declared, what, numbering);
        let label = check_row_index(path, toks, line, ordinal, key)?;
        let mut r = [0u32; K];
        for k in 0..per_row.max(K) {
            let raw = parse_int(toks[1 + k], path, line, "vertex")?;
            let i = vertex_ref(raw, nodes.index_base, nodes.points.len(), path, line)?;
            if k < K {
                r[k] = i;
            }
        }
        Ok((r, label))
    })?;
    check_row_count(path, rows.len(), declared, what)?;
    let (rows, labels): (Vec<[u32; K]>, Vec<u32>) = rows.into_iter().unzip();
    check_increasing(path, &labels, &lines, what)?;
    Ok((rows, lines, labels))
}

/// The unsigned decimal integers of a line (at most `N`, at most 18 digits each), separated
/// by ASCII whitespace, and how many there are; `None` for anything else (a sign, a point,
/// a comment, more than `N` values), which the general reader then handles.
fn uint_row<const N: usize>(raw: &[u8]) -> Option<([u64; N], usize)> {
    let mut vals = [0u64; N];
    let (mut count, mut digits) = (0usize, 0usize);
    for &b in raw {
        if b.is_ascii_digit() {
            if digits == 0 {
                if count == N {
                    return None;
                }
                count += 1;
            }
            digits += 1;
            if digits > 18 {
                return None;
            }
            vals[count - 1] = vals[count - 1] * 10 + u64::from(b - b'0');
        } else if b.is_ascii_whitespace() {
            digits = 0;
        } else {
            return None;
        }
    }
    Some((vals, count))
}

#[cfg(test)]
mod tests {
    use super::uint_row;

    #[test]
    fn plain_integer_rows_only() {
        assert_eq!(uint_row::<4>(b"12 7\t9\r\n"), Some(([12, 7, 9, 0], 3)));
        assert_eq!(uint_row::<4>(b"  \n"), Some(([0; 4], 0)));
        for bad in [
            &b"1 -2 3"[..],
            b"1 2 # c",
            b"1 2.5",
            b"1 2 3 4 5",
            b"1 x",
            b"1 0000000000000000001",
        ] {
            assert_eq!(uint_row::<4>(bad), None, "{:?}", std::str::from_utf8(bad));
        }
    }
}
