//! A small SVG builder for pictures a reader can check by eye: a [`Svg`] panel draws
//! sites, segments and circles of the plane in a window of data coordinates (y up), and a
//! [`Figure`] places panels side by side, each clipped to its frame, with titles and a
//! caption. Segments are clipped to their panel's window before they are written
//! (Liang–Barsky), so a magnified panel holds only what it shows and no coordinate is
//! far outside the page.

use crate::geom::Point2;
use std::fmt::Write as _;

/// The style sheet of every figure: one class per kind of mark.
const STYLE: &str = "line.edge { stroke: #555; stroke-width: 0.8 }
line.mwt { stroke: #2a6fdb; stroke-width: 1.2 }
line.xy { stroke: #d62728; stroke-width: 2.5; stroke-dasharray: 8 5 }
line.best { stroke: #ff7f0e; stroke-width: 1.2; stroke-dasharray: 4 3 }
circle.site { fill: #111 }
circle.disk { fill: none; stroke: #d62728; stroke-width: 1 }
circle.disk1 { fill: none; stroke: #999; stroke-width: 1; stroke-dasharray: 3 3 }
rect.zoom { fill: none; stroke: #2ca02c; stroke-width: 1.5 }
rect.frame { fill: none; stroke: #888; stroke-width: 1 }
text { font: 14px sans-serif; fill: #111 }
";

/// One drawing of the plane: a data window mapped onto a rectangle of the page.
///
/// ```
/// use tetrakit::io::Svg;
/// let mut svg = Svg::new(&[[0.0, 0.0], [1.0, 1.0]]);
/// svg.line(&[0.0, 0.0], &[1.0, 1.0], "edge");
/// svg.site(&[0.0, 0.0]);
/// let text = svg.finish("a diagonal");
/// assert!(text.contains(r#"<line class="edge""#) && text.contains("a diagonal"));
/// ```
pub struct Svg {
    lo: Point2,
    hi: Point2,
    scale: f64,
    width: f64,
    height: f64,
    body: String,
}

impl Svg {
    /// A 900-pixel-wide drawing whose window fits `points` with a margin of 8 %.
    pub fn new(points: &[Point2]) -> Svg {
        let (mut lo, mut hi) = crate::geom::bounding_box(points);
        if points.is_empty() {
            (lo, hi) = ([0.0; 2], [1.0; 2]);
        }
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-300);
        let m = 0.08 * span;
        Svg::window([lo[0] - m, lo[1] - m], [hi[0] + m, hi[1] + m], 900.0)
    }

    /// A drawing of the data window `lo..hi`, `width` pixels wide (the height keeps the
    /// aspect ratio).
    pub fn window(lo: Point2, hi: Point2, width: f64) -> Svg {
        let scale = width / (hi[0] - lo[0]).max(1e-300);
        Svg {
            lo,
            hi,
            scale,
            width,
            height: (hi[1] - lo[1]) * scale,
            body: String::new(),
        }
    }

    /// The size of the drawing in pixels.
    pub fn size(&self) -> (f64, f64) {
        (self.width, self.height)
    }

    /// How many pixels one unit of data length takes.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    fn xy(&self, p: &Point2) -> (f64, f64) {
        (
            (p[0] - self.lo[0]) * self.scale,
            self.height - (p[1] - self.lo[1]) * self.scale,
        )
    }

    /// A segment with a CSS class (`edge`, `mwt`, `xy`, `best`, ...), clipped to the
    /// window; nothing is written when it misses the window.
    pub fn line(&mut self, a: &Point2, b: &Point2, class: &str) {
        let Some((a, b)) = clip(a, b, &self.lo, &self.hi) else {
            return;
        };
        let ((x1, y1), (x2, y2)) = (self.xy(&a), self.xy(&b));
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

    /// An outlined rectangle with corners `lo` and `hi`, at least 12 pixels a side around
    /// its centre (class `zoom` marks the window of a magnified panel).
    pub fn rect(&mut self, lo: &Point2, hi: &Point2, class: &str) {
        let ((x1, y1), (x2, y2)) = (self.xy(lo), self.xy(hi));
        let (w, h) = ((x2 - x1).max(12.0), (y1 - y2).max(12.0));
        let (cx, cy) = ((x1 + x2) / 2.0, (y1 + y2) / 2.0);
        let _ = writeln!(
            self.body,
            r#"<rect class="{class}" fill="none" stroke="black" x="{:.3}" y="{:.3}" width="{w:.3}" height="{h:.3}"/>"#,
            cx - w / 2.0,
            cy - h / 2.0
        );
    }

    /// A site (a dot of fixed size), if it is in the window.
    pub fn site(&mut self, p: &Point2) {
        if !inside(p, &self.lo, &self.hi) {
            return;
        }
        let (x, y) = self.xy(p);
        let _ = writeln!(
            self.body,
            r#"<circle class="site" cx="{x:.3}" cy="{y:.3}" r="3"/>"#
        );
    }

    /// A label next to a point, if it is in the window.
    pub fn label(&mut self, p: &Point2, text: &str) {
        if !inside(p, &self.lo, &self.hi) {
            return;
        }
        let (x, y) = self.xy(p);
        let _ = writeln!(
            self.body,
            r#"<text x="{:.3}" y="{:.3}">{text}</text>"#,
            x + 5.0,
            y - 5.0
        );
    }

    /// The document of this drawing alone, with `caption` under it.
    pub fn finish(self, caption: &str) -> String {
        let mut f = Figure::new(self.width, self.height);
        let _ = writeln!(f.body, "{}", self.body);
        f.finish(caption)
    }
}

fn inside(p: &Point2, lo: &Point2, hi: &Point2) -> bool {
    (0..2).all(|i| lo[i] <= p[i] && p[i] <= hi[i])
}

/// The part of segment `ab` inside the box `lo..hi` (Liang–Barsky), if any.
fn clip(a: &Point2, b: &Point2, lo: &Point2, hi: &Point2) -> Option<(Point2, Point2)> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for i in 0..2 {
        for (p, q) in [(-d[i], a[i] - lo[i]), (d[i], hi[i] - a[i])] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
    }
    // The ends inside the box are kept as they are (no rounding at t = 0 or 1).
    let at = |t: f64, end: &Point2, te: f64| {
        if t == te {
            *end
        } else {
            [a[0] + t * d[0], a[1] + t * d[1]]
        }
    };
    (t0 <= t1).then(|| (at(t0, a, 0.0), at(t1, b, 1.0)))
}

/// A page of panels, each placed at a pixel offset, framed, titled and clipped.
///
/// ```
/// use tetrakit::io::{Figure, Svg};
/// let mut left = Svg::window([0.0, 0.0], [1.0, 1.0], 200.0);
/// left.line(&[0.0, 0.0], &[2.0, 2.0], "edge"); // clipped to the window
/// let mut f = Figure::new(420.0, 230.0);
/// f.panel(left, (0.0, 30.0), "(a) a diagonal");
/// let text = f.finish("one panel");
/// assert!(text.contains(r#"x2="200.000" y2="0.000""#));
/// ```
pub struct Figure {
    width: f64,
    height: f64,
    panels: usize,
    body: String,
}

impl Figure {
    /// An empty page of `width` by `height` pixels (the caption goes below).
    pub fn new(width: f64, height: f64) -> Figure {
        Figure {
            width,
            height,
            panels: 0,
            body: String::new(),
        }
    }

    /// Places `svg` with its top left corner at `at`, clipped to its frame, with `title`
    /// above it.
    pub fn panel(&mut self, svg: Svg, at: (f64, f64), title: &str) {
        self.panels += 1;
        let (id, (w, h)) = (self.panels, svg.size());
        let _ = write!(
            self.body,
            r#"<text x="{:.1}" y="{:.1}">{title}</text>
<g transform="translate({:.1} {:.1})">
<clipPath id="panel{id}"><rect width="{w:.1}" height="{h:.1}"/></clipPath>
<g clip-path="url(#panel{id})">
{}</g>
<rect class="frame" fill="none" stroke="black" width="{w:.1}" height="{h:.1}"/>
</g>
"#,
            at.0,
            at.1 - 8.0,
            at.0,
            at.1,
            svg.body
        );
    }

    /// The document, with `caption` (one line per `\n`) under the panels.
    pub fn finish(self, caption: &str) -> String {
        let lines: Vec<&str> = caption.lines().collect();
        let h = self.height + 20.0 + 20.0 * lines.len() as f64;
        let mut text = String::new();
        for (i, l) in lines.iter().enumerate() {
            let y = self.height + 22.0 + 20.0 * i as f64;
            let _ = writeln!(text, r#"<text x="10" y="{y:.0}">{l}</text>"#);
        }
        format!(
            r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}">
<style>
{STYLE}</style>
<rect width="100%" height="100%" fill="white"/>
{}{text}</svg>
"##,
            self.body,
            w = self.width,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_keeps_the_part_inside_and_drops_the_rest() {
        let (lo, hi) = ([0.0, 0.0], [1.0, 1.0]);
        assert_eq!(
            clip(&[-1.0, 0.5], &[2.0, 0.5], &lo, &hi),
            Some(([0.0, 0.5], [1.0, 0.5]))
        );
        assert_eq!(clip(&[-1.0, 2.0], &[2.0, 2.0], &lo, &hi), None);
        assert_eq!(clip(&[2.0, -1.0], &[3.0, 5.0], &lo, &hi), None);
        let inner = ([0.2, 0.3], [0.4, 0.9]);
        assert_eq!(clip(&inner.0, &inner.1, &lo, &hi), Some(inner));
    }
}
