//! Object File Format (`.off`): an `OFF` header, a counts line `nv nf ne`, `nv` vertex
//! lines and `nf` face lines `k i1 … ik` with 0-based indices. Only triangles are
//! accepted; colours after the indices are ignored. The counts are checked against what
//! is read, never used to size an allocation.

use super::{Input, InputError, parse_coord, parse_int, read_text, token_lines, vertex_ref};
use std::path::Path;

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let text = read_text(path)?;
    let mut lines = token_lines(&text);
    let mut input = Input {
        dim: 3,
        index_base: 0,
        point_file: path.to_path_buf(),
        ..Default::default()
    };
    let (hline, header) = lines
        .next()
        .ok_or_else(|| InputError::new(path, 0, "empty file (expected 'OFF')"))?;
    // "OFF" may share its line with the counts.
    let counts_from_header = header.len() > 1;
    if header[0] != "OFF" {
        return Err(InputError::new(
            path,
            hline,
            format!("expected 'OFF', found {}", super::quote(header[0])),
        ));
    }
    let (cline, counts): (usize, Vec<String>) = if counts_from_header {
        (
            hline,
            (1..header.len()).map(|i| header[i].to_string()).collect(),
        )
    } else {
        let (l, t) = lines.next().ok_or_else(|| {
            InputError::new(
                path,
                hline,
                "missing the counts line 'vertices faces edges'",
            )
        })?;
        (l, (0..t.len()).map(|i| t[i].to_string()).collect())
    };
    if counts.len() < 2 {
        return Err(InputError::new(
            path,
            cline,
            "the counts line needs 'vertices faces [edges]'",
        ));
    }
    let nv = parse_int(&counts[0], path, cline, "vertex count")?;
    let nf = parse_int(&counts[1], path, cline, "face count")?;
    if nv < 0 || nf < 0 {
        return Err(InputError::new(path, cline, "negative count"));
    }
    let mut last = cline;
    for (line, toks) in lines {
        last = line;
        if (input.points.len() as i64) < nv {
            if toks.len() != 3 {
                return Err(InputError::new(
                    path,
                    line,
                    format!("a vertex needs 3 coordinates, found {}", toks.len()),
                ));
            }
            input.points.push([
                parse_coord(toks[0], path, line)?,
                parse_coord(toks[1], path, line)?,
                parse_coord(toks[2], path, line)?,
            ]);
            input.point_lines.push(line);
        } else if (input.faces.len() as i64) < nf {
            let k = parse_int(toks[0], path, line, "face size")?;
            if k != 3 {
                return Err(InputError::new(
                    path,
                    line,
                    format!("face with {k} vertices: only triangles are supported"),
                ));
            }
            if toks.len() < 4 {
                return Err(InputError::new(
                    path,
                    line,
                    "a triangle needs 3 vertex indices",
                ));
            }
            let mut f = [0u32; 3];
            for (j, slot) in f.iter_mut().enumerate() {
                let raw = parse_int(toks[1 + j], path, line, "vertex")?;
                *slot = vertex_ref(raw, 0, nv as usize, path, line)?;
            }
            input.faces.push(f);
        } else {
            return Err(InputError::new(
                path,
                line,
                "more lines than the counts announce",
            ));
        }
    }
    if (input.points.len() as i64) < nv || (input.faces.len() as i64) < nf {
        return Err(InputError::new(
            path,
            last,
            format!(
                "file ends early: {} of {nv} vertices and {} of {nf} faces",
                input.points.len(),
                input.faces.len()
            ),
        ));
    }
    Ok(input)
}
