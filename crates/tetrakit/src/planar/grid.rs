//! A uniform bucket grid over planar points for box queries whose boxes are computed
//! in floating point: the cell range is widened by one cell on each side, so a box that
//! is off by less than a cell still reaches every point it should (the exact predicates
//! decide membership).

use crate::geom::Point2;

/// Points bucketed by cell, in compressed rows.
pub(crate) struct PointGrid {
    origin: Point2,
    cell: f64,
    nx: usize,
    ny: usize,
    start: Vec<u32>,
    items: Vec<u32>,
    /// The coordinates of `items`, in the same order (reading a cell touches no other
    /// memory).
    coords: Vec<Point2>,
}

impl PointGrid {
    /// A grid of about `per_cell` points per cell over the bounding box of `points`.
    pub fn new(points: &[Point2], per_cell: f64) -> PointGrid {
        let (lo, hi) = crate::geom::bounding_box(points);
        let (w, h) = ((hi[0] - lo[0]).max(0.0), (hi[1] - lo[1]).max(0.0));
        let cells = (points.len() as f64 / per_cell).clamp(1.0, 4e7);
        let mut cell = ((w * h) / cells).sqrt();
        if !cell.is_finite() || cell <= 0.0 {
            cell = (w.max(h) / cells).max(f64::MIN_POSITIVE);
        }
        let nx = ((w / cell) as usize + 1).min(1 << 14);
        let ny = ((h / cell) as usize + 1).min(1 << 14);
        let cell = cell.max(w / nx as f64).max(h / ny as f64);
        let mut g = PointGrid {
            origin: lo,
            cell,
            nx,
            ny,
            start: Vec::new(),
            items: Vec::new(),
            coords: Vec::new(),
        };
        let keys = points.iter().enumerate().map(|(i, p)| (g.key(p), i as u32));
        (g.start, g.items) = crate::rows::buckets(nx * ny, keys);
        g.coords = g.items.iter().map(|&i| points[i as usize]).collect();
        g
    }

    fn coord(&self, x: f64, k: usize, n: usize) -> usize {
        let c = ((x - self.origin[k]) / self.cell).floor();
        if c <= 0.0 { 0 } else { (c as usize).min(n - 1) }
    }

    fn key(&self, p: &Point2) -> usize {
        self.coord(p[1], 1, self.ny) * self.nx + self.coord(p[0], 0, self.nx)
    }

    /// Side length of a cell.
    pub fn cell(&self) -> f64 {
        self.cell
    }

    /// The cell `(x, y)` holding `p`.
    pub fn cell_of(&self, p: &Point2) -> (usize, usize) {
        (self.coord(p[0], 0, self.nx), self.coord(p[1], 1, self.ny))
    }

    /// The box of cell `(x, y)`, widened by a millionth of a cell against rounding.
    pub fn cell_box(&self, x: usize, y: usize) -> (Point2, Point2) {
        let e = 1e-6 * self.cell;
        let lo = [
            self.origin[0] + x as f64 * self.cell,
            self.origin[1] + y as f64 * self.cell,
        ];
        (
            [lo[0] - e, lo[1] - e],
            [lo[0] + self.cell + e, lo[1] + self.cell + e],
        )
    }

    /// Grid dimensions in cells.
    pub fn dims(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// The slots of cell `(x, y)`: positions in [`Self::slots`].
    pub fn cell_slots(&self, x: usize, y: usize) -> std::ops::Range<usize> {
        let c = y * self.nx + x;
        self.start[c] as usize..self.start[c + 1] as usize
    }

    /// Every point index and its coordinates, cell by cell (row-major): an order with
    /// spatial locality, and cell contents without lookups elsewhere.
    pub fn slots(&self) -> (&[u32], &[Point2]) {
        (&self.items, &self.coords)
    }

    /// Calls `f` on every point in cells meeting the box `[lo, hi]` widened by one cell
    /// (for boxes computed approximately); stops early when `f` returns true, and
    /// returns whether it did.
    pub fn any_in_box(&self, lo: Point2, hi: Point2, f: impl FnMut(u32) -> bool) -> bool {
        let x0 = self.coord(lo[0], 0, self.nx).saturating_sub(1);
        let y0 = self.coord(lo[1], 1, self.ny).saturating_sub(1);
        let x1 = (self.coord(hi[0], 0, self.nx) + 1).min(self.nx - 1);
        let y1 = (self.coord(hi[1], 1, self.ny) + 1).min(self.ny - 1);
        self.any_in_cells(x0, x1, y0, y1, f)
    }

    fn any_in_cells(
        &self,
        x0: usize,
        x1: usize,
        y0: usize,
        y1: usize,
        mut f: impl FnMut(u32) -> bool,
    ) -> bool {
        for y in y0..=y1 {
            let row = y * self.nx;
            let (a, b) = (
                self.start[row + x0] as usize,
                self.start[row + x1 + 1] as usize,
            );
            if self.items[a..b].iter().any(|&i| f(i)) {
                return true;
            }
        }
        false
    }
}
