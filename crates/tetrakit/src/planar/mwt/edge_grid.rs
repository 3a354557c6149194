//! A uniform grid of segments (each stored in every cell its bounding box meets) for
//! crossing queries. Two crossing segments share a point of both bounding boxes, and the
//! float cell index is monotone in the coordinate, so they share a cell; the crossing
//! itself is decided exactly.

use crate::geom::Point2;
use rayon::prelude::*;

pub(crate) struct EdgeGrid {
    origin: Point2,
    cell: f64,
    nx: usize,
    ny: usize,
    start: Vec<u32>,
    items: Vec<u32>,
}

impl EdgeGrid {
    /// A grid over the edges `ids` of `edges`, cells about the mean edge length.
    pub fn new(points: &[Point2], edges: &[[u32; 2]], ids: &[u32]) -> EdgeGrid {
        let (lo, hi) = crate::geom::bounding_box(points);
        let len = |e: &[u32; 2]| {
            let (a, b) = (points[e[0] as usize], points[e[1] as usize]);
            (b[0] - a[0]).hypot(b[1] - a[1])
        };
        let mean =
            ids.iter().map(|&e| len(&edges[e as usize])).sum::<f64>() / ids.len().max(1) as f64;
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(f64::MIN_POSITIVE);
        let mut cell = if mean > 0.0 { mean } else { span };
        let limit = 2048.0;
        cell = cell.max(span / limit);
        let nx = (((hi[0] - lo[0]) / cell) as usize + 1).min(limit as usize + 1);
        let ny = (((hi[1] - lo[1]) / cell) as usize + 1).min(limit as usize + 1);
        let mut g = EdgeGrid {
            origin: lo,
            cell,
            nx,
            ny,
            start: Vec::new(),
            items: Vec::new(),
        };
        // Each edge's cells once (random reads of its ends), then the rows from them.
        let ranges: Vec<[u32; 4]> = (ids.par_iter())
            .map(|&e| g.range(points, &edges[e as usize]).map(|c| c as u32))
            .collect();
        let (start, items) = crate::rows::group(nx * ny, ids.len(), |i| {
            let ([x0, x1, y0, y1], e) = (ranges[i].map(|c| c as usize), ids[i]);
            (y0..=y1).flat_map(move |y| (x0..=x1).map(move |x| (y * nx + x, e)))
        });
        g.start = start.into_iter().map(|s| s as u32).collect();
        g.items = items;
        g
    }

    fn coord(&self, v: f64, k: usize, n: usize) -> usize {
        let c = ((v - self.origin[k]) / self.cell).floor();
        if c <= 0.0 { 0 } else { (c as usize).min(n - 1) }
    }

    fn range(&self, points: &[Point2], e: &[u32; 2]) -> [usize; 4] {
        let (a, b) = (points[e[0] as usize], points[e[1] as usize]);
        let x0 = self.coord(a[0].min(b[0]), 0, self.nx);
        let x1 = self.coord(a[0].max(b[0]), 0, self.nx);
        let y0 = self.coord(a[1].min(b[1]), 1, self.ny);
        let y1 = self.coord(a[1].max(b[1]), 1, self.ny);
        [x0, x1, y0, y1]
    }

    /// True when some stored edge crosses edge `e` properly.
    pub fn crossed(&self, points: &[Point2], edges: &[[u32; 2]], e: u32) -> bool {
        let [a, b] = edges[e as usize];
        let [x0, x1, y0, y1] = self.range(points, &edges[e as usize]);
        let p = |i: u32| &points[i as usize];
        for y in y0..=y1 {
            for x in x0..=x1 {
                let c = y * self.nx + x;
                for &f in &self.items[self.start[c] as usize..self.start[c + 1] as usize] {
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
        }
        false
    }
}
