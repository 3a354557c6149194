//! TetGen's `.node`, `.edge`, `.ele` and `.face` formats (0- or 1-based, `#` comments,
//! attributes and boundary markers), read strictly.

use super::{
    Input, InputError, check_segments, parse_coord, parse_int, read_text, token_lines, vertex_ref,
};
use std::path::Path;

/// Reads a TetGen file set starting from any of its members.
pub(super) fn read(path: &Path, ext: &str) -> Result<Input, InputError> {
    let node = path.with_extension("node");
    if ext != "node" && !node.exists() {
        return Err(InputError::new(
            path,
            0,
            format!("needs the point file {} beside it", node.display()),
        ));
    }
    let mut input = read_node(&node)?;
    let sibling = |e: &str| {
        let p = path.with_extension(e);
        (ext == e || (ext == "node" && p.exists())).then_some(p)
    };
    if let Some(p) = sibling("edge") {
        let (rows, lines) = read_rows::<2>(&p, &input, "edge", 2)?;
        check_segments(&rows, &lines, input.index_base, &p)?;
        input.segments = rows;
    }
    if let Some(p) = sibling("ele") {
        input.tets = read_rows::<4>(&p, &input, "tetrahedron", 4)?.0;
    }
    if let Some(p) = sibling("face") {
        input.faces = read_rows::<3>(&p, &input, "face", 3)?.0;
    }
    Ok(input)
}

fn header<'a>(
    path: &Path,
    lines: &mut impl Iterator<Item = (usize, super::Tokens<'a>)>,
) -> Result<(usize, Vec<i64>), InputError> {
    let Some((line, toks)) = lines.next() else {
        return Err(InputError::new(path, 0, "empty file: no header line"));
    };
    let vals = toks
        .iter()
        .map(|t| parse_int(t, path, line, "header value"))
        .collect::<Result<Vec<_>, _>>()?;
    if vals.iter().any(|&v| v < 0) {
        return Err(InputError::new(path, line, "negative number in the header"));
    }
    Ok((line, vals))
}

fn read_node(path: &Path) -> Result<Input, InputError> {
    let text = read_text(path)?;
    let mut lines = token_lines(&text);
    let (hline, h) = header(path, &mut lines)?;
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
    let mut input = Input {
        dim,
        point_file: path.to_path_buf(),
        ..Default::default()
    };
    for (line, toks) in lines {
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
        let idx = parse_int(toks[0], path, line, "point index")?;
        if input.points.is_empty() {
            if idx != 0 && idx != 1 {
                return Err(InputError::new(
                    path,
                    line,
                    format!("first point is numbered {idx}; TetGen numbering starts at 0 or 1"),
                ));
            }
            input.index_base = idx as u32;
        }
        let expect = input.points.len() as i64 + input.index_base as i64;
        if idx != expect {
            return Err(InputError::new(
                path,
                line,
                format!("point numbered {idx}, expected {expect}"),
            ));
        }
        let mut p = [0.0; 3];
        for k in 0..dim {
            p[k] = parse_coord(toks[1 + k], path, line)?;
        }
        input.points.push(p);
        input.point_lines.push(line);
        if input.points.len() > declared {
            return Err(InputError::new(
                path,
                line,
                format!("more points than the {declared} the header declares"),
            ));
        }
    }
    if input.points.len() != declared {
        return Err(InputError::new(
            path,
            0,
            format!(
                "header declares {declared} points but the file has {} (truncated?)",
                input.points.len()
            ),
        ));
    }
    if declared == 0 {
        return Err(InputError::new(path, hline, "no points"));
    }
    Ok(input)
}

/// Reads a TetGen element file whose rows are `index v1 .. vK [extras]`.
fn read_rows<const K: usize>(
    path: &Path,
    nodes: &Input,
    what: &str,
    min_per_row: usize,
) -> Result<(Vec<[u32; K]>, Vec<usize>), InputError> {
    let text = read_text(path)?;
    let mut lines = token_lines(&text);
    let (hline, h) = header(path, &mut lines)?;
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
    let mut rows = Vec::new();
    let mut row_lines = Vec::new();
    let mut base = None;
    for (line, toks) in lines {
        if toks.len() < 1 + per_row.max(min_per_row) || toks.len() > 1 + per_row + extra {
            return Err(InputError::new(
                path,
                line,
                format!(
                    "expected an index and {per_row} vertices (plus {extra} attributes/markers), found {} values",
                    toks.len()
                ),
            ));
        }
        let idx = parse_int(toks[0], path, line, "index")?;
        let b = *base.get_or_insert(idx);
        if (b != 0 && b != 1) || idx != b + rows.len() as i64 {
            return Err(InputError::new(
                path,
                line,
                format!(
                    "{what} numbered {idx}, expected {}",
                    if b == 0 || b == 1 {
                        b + rows.len() as i64
                    } else {
                        1
                    }
                ),
            ));
        }
        let mut r = [0u32; K];
        for k in 0..K {
            let raw = parse_int(toks[1 + k], path, line, "vertex")?;
            r[k] = vertex_ref(raw, nodes.index_base, nodes.points.len(), path, line)?;
        }
        rows.push(r);
        row_lines.push(line);
        if rows.len() > declared {
            return Err(InputError::new(
                path,
                line,
                format!("more rows than the {declared} the header declares"),
            ));
        }
    }
    if rows.len() != declared {
        return Err(InputError::new(
            path,
            0,
            format!(
                "header declares {declared} {what}s but the file has {} (truncated?)",
                rows.len()
            ),
        ));
    }
    Ok((rows, row_lines))
}
