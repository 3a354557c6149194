//! The JSON input of the README ("Inputs"): `{"points": [[x,y,z],...], "segments": [[i,j],...],
//! "tets": [[i,j,k,l],...], "faces": [[i,j,k],...]}`, 0-based.

use super::{Input, InputError, check_segments, coordinate_in_range, read_text};
use serde::Deserialize;
use std::path::Path;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Doc {
    points: Vec<Vec<f64>>,
    #[serde(default)]
    segments: Vec<[i64; 2]>,
    #[serde(default)]
    faces: Vec<[i64; 3]>,
    #[serde(default)]
    tets: Vec<[i64; 4]>,
}

pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let text = read_text(path)?;
    let doc: Doc = serde_json::from_str(&text)
        .map_err(|e| InputError::new(path, e.line(), format!("invalid JSON input: {e}")))?;
    let mut input = Input {
        dim: 3,
        point_file: path.to_path_buf(),
        ..Default::default()
    };
    let dim = doc.points.first().map_or(3, Vec::len);
    for (k, p) in doc.points.iter().enumerate() {
        if !(2..=3).contains(&p.len()) {
            return Err(InputError::new(
                path,
                0,
                format!("points[{k}] has {} coordinates (expected 2 or 3)", p.len()),
            ));
        }
        if p.len() != dim {
            return Err(InputError::new(
                path,
                0,
                format!(
                    "points[{k}] has {} coordinates but points[0] has {dim}: every point needs the same number",
                    p.len()
                ),
            ));
        }
        if let Some(x) = p.iter().find(|x| !coordinate_in_range(**x)) {
            return Err(InputError::new(
                path,
                0,
                format!(
                    "points[{k}] coordinate {x} is outside the exactly supported range [2^-142, 2^201]"
                ),
            ));
        }
        input
            .points
            .push([p[0], p[1], p.get(2).copied().unwrap_or(0.0)]);
    }
    if doc.points.is_empty() {
        return Err(InputError::new(path, 0, "no points"));
    }
    input.dim = dim;
    let n = input.points.len();
    fn idx<const K: usize>(
        rows: &[[i64; K]],
        n: usize,
        field: &str,
        path: &Path,
    ) -> Result<Vec<[u32; K]>, InputError> {
        rows.iter()
            .enumerate()
            .map(|(k, r)| {
                let mut out = [0u32; K];
                for (o, &v) in out.iter_mut().zip(r) {
                    if v < 0 || v as usize >= n {
                        return Err(InputError::new(
                            path,
                            0,
                            format!(
                                "{field}[{k}] names vertex {v}, but points are numbered 0..={}",
                                n - 1
                            ),
                        ));
                    }
                    *o = v as u32;
                }
                Ok(out)
            })
            .collect()
    }
    input.segments = idx(&doc.segments, n, "segments", path)?;
    input.faces = idx(&doc.faces, n, "faces", path)?;
    input.tets = idx(&doc.tets, n, "tets", path)?;
    input.tet_file = path.to_path_buf();
    let lines = vec![0; input.segments.len()];
    check_segments(&input.segments, &lines, 0, path)?;
    Ok(input)
}
