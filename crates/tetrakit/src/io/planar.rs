//! Planar output: point sets (`.xyz`, `.node`, `.json`), edge sets (`.edge` with `.node`,
//! `.json`, `.svg`).

use super::svg::Svg;
use super::write::{ext, save, unsupported};
use crate::geom::Point2;
use std::fmt::Write as _;
use std::io;
use std::path::Path;

fn node2_text(points: &[Point2]) -> String {
    let mut s = format!("{} 2 0 0\n", points.len());
    for (i, p) in points.iter().enumerate() {
        let _ = writeln!(s, "{} {:?} {:?}", i + 1, p[0], p[1]);
    }
    s
}

/// Writes planar points: `.xyz`/`.txt` (`x y` per line), `.node` (TetGen, 1-based) or
/// `.json` (`{"points": [[x, y], ...]}`). Coordinates are written so they read back exactly.
///
/// ```
/// let path = std::env::temp_dir().join("tetrakit-doc-pts.xyz");
/// tetrakit::io::write_points2d(&path, &[[0.1, 2.0], [3.0, 4.5]]).unwrap();
/// let back = tetrakit::io::read_input(&path).unwrap();
/// assert_eq!((back.dim, back.points[0][0]), (2, 0.1));
/// ```
pub fn write_points2d(path: &Path, points: &[Point2]) -> io::Result<()> {
    match ext(path).as_str() {
        "xyz" | "txt" => {
            let mut s = String::new();
            for p in points {
                let _ = writeln!(s, "{:?} {:?}", p[0], p[1]);
            }
            save(path, s)
        }
        "node" => save(path, node2_text(points)),
        "json" => save(path, serde_json::json!({ "points": points }).to_string()),
        other => Err(unsupported(other, ".xyz, .txt, .node or .json")),
    }
}

/// Writes a planar edge set: `.edge` (with `.node` beside it, 1-based), `.json`
/// (`points`, `segments`, 0-based) or `.svg` (a drawing of sites and edges, counted in its caption).
pub fn write_planar_edges(path: &Path, points: &[Point2], edges: &[[u32; 2]]) -> io::Result<()> {
    match ext(path).as_str() {
        "edge" => {
            save(&path.with_extension("node"), node2_text(points))?;
            let mut s = format!("{} 0\n", edges.len());
            for (i, e) in edges.iter().enumerate() {
                let _ = writeln!(s, "{} {} {}", i + 1, e[0] + 1, e[1] + 1);
            }
            save(path, s)
        }
        "json" => save(
            path,
            serde_json::json!({ "points": points, "segments": edges }).to_string(),
        ),
        "svg" => {
            let mut svg = Svg::new(points);
            for e in edges {
                svg.line(&points[e[0] as usize], &points[e[1] as usize], "edge");
            }
            for p in points {
                svg.site(p);
            }
            let caption = format!("{} sites, {} edges", points.len(), edges.len());
            save(path, svg.finish(&caption))
        }
        other => Err(unsupported(other, ".edge, .json or .svg")),
    }
}

/// Writes a planar triangulation: its triangles as `.off` or `.obj` (counter-clockwise
/// seen from above, site `i` at height `z[i]`, or 0 when `z` is empty: a TIN of terrain
/// points), or its edges as `.edge`, `.json` or `.svg` ([`write_planar_edges`]).
///
/// ```
/// let path = std::env::temp_dir().join("tetrakit-doc-tin.obj");
/// let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
/// tetrakit::io::write_planar_triangulation(&path, &pts, &[1.0, 2.0, 3.0], &[], &[[0, 1, 2]])
///     .unwrap();
/// let text = std::fs::read_to_string(&path).unwrap();
/// assert!(text.contains("v 0 1 3") && text.contains("f 1 2 3"));
/// ```
pub fn write_planar_triangulation(
    path: &Path,
    points: &[Point2],
    z: &[f64],
    edges: &[[u32; 2]],
    triangles: &[[u32; 3]],
) -> io::Result<()> {
    match ext(path).as_str() {
        "off" | "obj" => {
            let lifted: Vec<crate::geom::Point3> = (points.iter().enumerate())
                .map(|(i, p)| [p[0], p[1], z.get(i).copied().unwrap_or(0.0)])
                .collect();
            super::write_surface(path, &lifted, triangles, 1)
        }
        "edge" | "json" | "svg" => write_planar_edges(path, points, edges),
        other => Err(unsupported(other, ".edge, .json, .svg, .off or .obj")),
    }
}
