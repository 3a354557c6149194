//! The JSON input of the README ("Inputs"): `{"points": [[x,y,z],...], "segments": [[i,j],...],
//! "tets": [[i,j,k,l],...], "faces": [[i,j,k],...]}`, 0-based.

use super::{Input, InputError, read_text};
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
    let dim = doc.points.first().map_or(3, Vec::len);
    let mut points = Vec::with_capacity(doc.points.len());
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
        points.push([p[0], p[1], p.get(2).copied().unwrap_or(0.0)]);
    }
    let arrays = super::Arrays {
        points,
        dim,
        segments: &doc.segments,
        faces: &doc.faces,
        tets: &doc.tets,
        mesh: false,
    };
    super::arrays_input(path, arrays)
}
