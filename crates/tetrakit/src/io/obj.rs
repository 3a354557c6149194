//! Wavefront OBJ: `v x y z [w]` points, `l a b c ...` polylines (each consecutive pair a
//! segment) and `f a b c ...` faces (`a/t/n` forms and negative, relative indices
//! accepted). Texture coordinates, normals, groups, objects, smoothing and materials
//! (`vt vn vp g o s usemtl mtllib`) are skipped; any other statement is an error naming
//! its line (curves, surfaces, points and lines of other kinds would otherwise vanish).

use super::{Input, InputError, parse_coord, parse_int, read_text, token_lines};
use std::path::Path;

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let text = read_text(path)?;
    let mut input = Input {
        dim: 3,
        index_base: 1,
        point_file: path.to_path_buf(),
        ..Default::default()
    };
    let mut face_lines: Vec<(usize, Vec<i64>)> = Vec::new();
    let mut polylines: Vec<(usize, Vec<i64>)> = Vec::new();
    for (line, toks) in token_lines(&text) {
        match toks[0] {
            "v" => {
                if !(4..=5).contains(&toks.len()) {
                    return Err(InputError::new(
                        path,
                        line,
                        format!("'v' needs 3 coordinates, found {}", toks.len() - 1),
                    ));
                }
                if toks.len() == 5 && toks[4].parse::<f64>() != Ok(1.0) {
                    return Err(InputError::new(
                        path,
                        line,
                        "homogeneous weight w other than 1 is not supported",
                    ));
                }
                let p = [
                    parse_coord(toks[1], path, line)?,
                    parse_coord(toks[2], path, line)?,
                    parse_coord(toks[3], path, line)?,
                ];
                input.points.push(p);
                input.point_lines.push(line);
            }
            "l" | "f" => {
                let n = input.points.len() as i64;
                let mut refs = Vec::with_capacity(toks.len() - 1);
                for t in &toks[1..] {
                    let head = t.split('/').next().unwrap_or("");
                    let raw = parse_int(head, path, line, "vertex")?;
                    let abs = if raw < 0 { n + raw + 1 } else { raw };
                    if raw == 0 || abs < 1 || abs > n {
                        return Err(InputError::new(
                            path,
                            line,
                            format!("vertex {raw} is out of range ({n} vertices so far)"),
                        ));
                    }
                    refs.push(abs - 1);
                }
                let need = if toks[0] == "l" { 2 } else { 3 };
                if refs.len() < need {
                    return Err(InputError::new(
                        path,
                        line,
                        format!("'{}' needs at least {need} vertices", toks[0]),
                    ));
                }
                if toks[0] == "l" {
                    polylines.push((line, refs))
                } else {
                    face_lines.push((line, refs))
                }
            }
            "vt" | "vn" | "vp" | "g" | "o" | "s" | "usemtl" | "mtllib" => {}
            other => {
                return Err(InputError::new(
                    path,
                    line,
                    format!(
                        "unsupported OBJ statement {} (read: v, l, f; skipped: vt vn vp g o s usemtl mtllib)",
                        super::quote(other)
                    ),
                ));
            }
        }
    }
    if input.points.is_empty() {
        return Err(InputError::new(path, 0, "no vertices ('v' lines)"));
    }
    for (line, refs) in polylines {
        for w in refs.windows(2) {
            input.segments.push([w[0] as u32, w[1] as u32]);
            input.segment_lines.push(line as u32);
        }
    }
    for (line, refs) in face_lines {
        if refs.len() != 3 {
            return Err(InputError::new(
                path,
                line,
                format!(
                    "face with {} vertices: only triangles are supported",
                    refs.len()
                ),
            ));
        }
        input
            .faces
            .push([refs[0] as u32, refs[1] as u32, refs[2] as u32]);
    }
    Ok(input)
}
