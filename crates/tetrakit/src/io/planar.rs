//! Planar output: point sets (`.xyz`, `.node`, `.json`), edge sets (`.edge` with `.node`,
//! `.json`, `.svg`) and a small SVG builder for pictures a reader can check by eye.

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
/// (`points`, `segments`, 0-based) or `.svg` (a drawing of sites and edges).
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
            save(path, svg.finish(""))
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

/// A minimal SVG drawing in data coordinates (y up), scaled to about 900 pixels.
pub struct Svg {
    lo: Point2,
    scale: f64,
    height: f64,
    body: String,
}

impl Svg {
    /// A drawing whose view fits `points` (plus a margin).
    pub fn new(points: &[Point2]) -> Svg {
        let (mut lo, mut hi) = crate::geom::bounding_box(points);
        if points.is_empty() {
            (lo, hi) = ([0.0; 2], [1.0; 2]);
        }
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-300);
        let margin = 0.08 * span;
        let scale = 900.0 / (span + 2.0 * margin);
        Svg {
            lo: [lo[0] - margin, lo[1] - margin],
            scale,
            height: (hi[1] - lo[1] + 2.0 * margin) * scale,
            body: String::new(),
        }
    }

    fn xy(&self, p: &Point2) -> (f64, f64) {
        (
            (p[0] - self.lo[0]) * self.scale,
            self.height - (p[1] - self.lo[1]) * self.scale,
        )
    }

    /// A segment with a CSS class (`edge`, `mwt`, `skeleton`, `xy`, ...).
    pub fn line(&mut self, a: &Point2, b: &Point2, class: &str) {
        let ((x1, y1), (x2, y2)) = (self.xy(a), self.xy(b));
        let _ = writeln!(
            self.body,
            r#"<line class="{class}" stroke="black" x1="{x1:.3}" y1="{y1:.3}" x2="{x2:.3}" y2="{y2:.3}"/>"#
        );
    }

    /// An outlined circle of data radius `r`. The presentation attributes stand in for
    /// the style sheet in renderers without CSS; the style sheet overrides them.
    pub fn circle(&mut self, c: &Point2, r: f64, class: &str) {
        let (x, y) = self.xy(c);
        let _ = writeln!(
            self.body,
            r#"<circle class="{class}" fill="none" stroke="black" cx="{x:.3}" cy="{y:.3}" r="{:.3}"/>"#,
            r * self.scale
        );
    }

    /// A site (a dot of fixed size).
    pub fn site(&mut self, p: &Point2) {
        let (x, y) = self.xy(p);
        let _ = writeln!(
            self.body,
            r#"<circle class="site" cx="{x:.3}" cy="{y:.3}" r="3"/>"#
        );
    }

    /// A label next to a point.
    pub fn label(&mut self, p: &Point2, text: &str) {
        let (x, y) = self.xy(p);
        let _ = writeln!(
            self.body,
            r#"<text x="{:.3}" y="{:.3}">{text}</text>"#,
            x + 5.0,
            y - 5.0
        );
    }

    /// The document, with `caption` under the drawing.
    pub fn finish(self, caption: &str) -> String {
        let h = self.height + 40.0;
        format!(
            r##"<svg xmlns="http://www.w3.org/2000/svg" width="900" height="{h:.0}" viewBox="0 0 900 {h:.0}">
<style>
line.edge {{ stroke: #555; stroke-width: 0.8 }}
line.mwt {{ stroke: #2a6fdb; stroke-width: 1.2 }}
line.xy {{ stroke: #d62728; stroke-width: 2.5; stroke-dasharray: 8 5 }}
line.best {{ stroke: #2ca02c; stroke-width: 1.2; stroke-dasharray: 4 3 }}
circle.site {{ fill: #111 }}
circle.disk {{ fill: none; stroke: #d62728; stroke-width: 1 }}
circle.disk1 {{ fill: none; stroke: #999; stroke-width: 1; stroke-dasharray: 3 3 }}
text {{ font: 14px sans-serif; fill: #111 }}
</style>
<rect width="100%" height="100%" fill="white"/>
{}<text x="10" y="{:.0}">{caption}</text>
</svg>
"##,
            self.body,
            h - 12.0
        )
    }
}

/// The picture of the Keil construction (thesis §5.2): the sites, the β-disks through
/// `x` and `y`, the MWT, and `xy`, as SVG text.
pub fn keil_svg(k: &crate::planar::KeilResult) -> String {
    let (x, y) = (k.sites[k.xy[0] as usize], k.sites[k.xy[1] as usize]);
    let mut view = k.sites.clone();
    let b = k.beta.to_f64();
    let h = (b * b - 1.0).sqrt();
    view.extend([[-b, h + b], [b, -h - b]]);
    let mut svg = Svg::new(&view);
    for c in [[0.0, h], [0.0, -h]] {
        svg.circle(&c, b, "disk");
    }
    for e in &k.mwt {
        svg.line(&k.sites[e[0] as usize], &k.sites[e[1] as usize], "mwt");
    }
    svg.line(&x, &y, "xy");
    for p in &k.sites {
        svg.site(p);
    }
    svg.label(&x, "x");
    svg.label(&y, "y");
    svg.finish(&format!(
        "β = {}: xy (dashed red) {} the β-skeleton, {} the MWT (blue); disks: the β-region of xy",
        k.beta,
        if k.xy_in_skeleton { "in" } else { "not in" },
        if k.xy_in_mwt { "in" } else { "not in" }
    ))
}
