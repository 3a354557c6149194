//! The inner vertices not yet on the current surface, bucketed in a uniform 3D grid so
//! that a removal finds the ones under a cap by its bounding box. The grid only
//! proposes: cells are computed in floating point (monotone in each coordinate, clamped,
//! so a point inside a box is in a cell of the box's range), and the box test on the
//! points it returns is exact.

use crate::geom::{Point3, bounding_box};

/// Hidden inner vertices by grid cell.
pub(super) struct Bins {
    lo: Point3,
    inv: [f64; 3],
    side: usize,
    cells: Vec<Vec<u32>>,
    hidden: Vec<bool>,
}

impl Bins {
    /// Bins for the points `ids` of `points` (all hidden at first).
    pub(super) fn new(points: &[Point3], ids: &[u32]) -> Bins {
        let sub: Vec<Point3> = ids.iter().map(|&i| points[i as usize]).collect();
        let (lo, hi) = bounding_box(&sub);
        let side = ((ids.len() as f64).cbrt().ceil() as usize).clamp(1, 128);
        let inv = [0, 1, 2].map(|k| {
            let w = hi[k] - lo[k];
            let r = side as f64 / w;
            if w > 0.0 && r.is_finite() { r } else { 0.0 }
        });
        let mut bins = Bins {
            lo,
            inv,
            side,
            cells: vec![Vec::new(); side * side * side],
            hidden: vec![false; points.len()],
        };
        for &i in ids {
            let c = bins.cell(&points[i as usize]);
            let c = bins.index(c);
            bins.cells[c].push(i);
            bins.hidden[i as usize] = true;
        }
        bins
    }

    fn cell(&self, p: &Point3) -> [usize; 3] {
        [0, 1, 2].map(|k| {
            let x = (p[k] - self.lo[k]) * self.inv[k];
            // NaN and negatives clamp to 0; the cast saturates.
            (x.max(0.0) as usize).min(self.side - 1)
        })
    }

    fn index(&self, c: [usize; 3]) -> usize {
        (c[0] * self.side + c[1]) * self.side + c[2]
    }

    /// True while `v` is a hidden inner vertex.
    pub(super) fn is_hidden(&self, v: u32) -> bool {
        self.hidden.get(v as usize).copied().unwrap_or(false)
    }

    /// The hidden vertices inside the closed box `[lo, hi]`.
    pub(super) fn in_box(&self, points: &[Point3], lo: &Point3, hi: &Point3) -> Vec<u32> {
        let (a, b) = (self.cell(lo), self.cell(hi));
        let mut out = Vec::new();
        for x in a[0]..=b[0] {
            for y in a[1]..=b[1] {
                for z in a[2]..=b[2] {
                    let cell = &self.cells[self.index([x, y, z])];
                    out.extend(cell.iter().copied().filter(|&i| {
                        let p = &points[i as usize];
                        (0..3).all(|k| lo[k] <= p[k] && p[k] <= hi[k])
                    }));
                }
            }
        }
        out
    }

    /// `v` is on the surface now.
    pub(super) fn expose(&mut self, points: &[Point3], v: u32) {
        if !self.is_hidden(v) {
            return;
        }
        self.hidden[v as usize] = false;
        let c = self.index(self.cell(&points[v as usize]));
        self.cells[c].retain(|&i| i != v);
    }

    /// How many inner vertices are still hidden.
    pub(super) fn count(&self) -> usize {
        self.cells.iter().map(Vec::len).sum()
    }
}
