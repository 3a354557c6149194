//! A uniform grid of segments (each stored in every cell its bounding box meets) for
//! crossing queries. Two crossing segments share a point of both bounding boxes, and the
//! float cell index is monotone in the coordinate, so they share a cell; the crossing
//! itself is decided exactly.

use crate::geom::{Grid2, Point2};

/// Segments in the shared bucket grid ([`Grid2`]), each in every cell its bounding box
/// meets.
pub(crate) struct EdgeGrid {
    grid: Grid2,
}

impl EdgeGrid {
    /// A grid over the edges `ids` of `edges`, cells about the mean edge length (at
    /// most 2049 a side).
    pub fn new(points: &[Point2], edges: &[[u32; 2]], ids: &[u32]) -> EdgeGrid {
        let len = |e: &[u32; 2]| {
            let (a, b) = (points[e[0] as usize], points[e[1] as usize]);
            (b[0] - a[0]).hypot(b[1] - a[1])
        };
        let mean =
            ids.iter().map(|&e| len(&edges[e as usize])).sum::<f64>() / ids.len().max(1) as f64;
        let (lo, hi) = crate::geom::bounding_box(points);
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(f64::MIN_POSITIVE);
        let cell = if mean > 0.0 { mean } else { span }.max(span / 2048.0);
        let ends = |e: u32| {
            let [a, b] = edges[e as usize];
            (points[a as usize], points[b as usize])
        };
        EdgeGrid {
            grid: Grid2::of_boxes((lo, hi), cell, 2049, ids, ends),
        }
    }

    /// True when some stored edge crosses edge `e` properly.
    pub fn crossed(&self, points: &[Point2], edges: &[[u32; 2]], e: u32) -> bool {
        let [a, b] = edges[e as usize];
        let p = |i: u32| &points[i as usize];
        let [x0, x1, y0, y1] = self.grid.cell_range(*p(a), *p(b));
        for y in y0..=y1 {
            for &f in &self.grid.items()[self.grid.row_slots(y, x0, x1)] {
                let [c0, c1] = edges[f as usize];
                if f != e
                    && c0 != a
                    && c0 != b
                    && c1 != a
                    && c1 != b
                    && super::cross(p(a), p(b), p(c0), p(c1))
                {
                    return true;
                }
            }
        }
        false
    }
}
