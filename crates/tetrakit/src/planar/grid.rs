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
    #[cfg(test)]
    pub fn dims(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// Calls `f` on the cells at Chebyshev distance `r` from cell `(cx, cy)`: the bottom
    /// and top rows of the ring, then its two sides (plain loops: this is the inner walk
    /// of the searches that visit rings of cells around a site).
    pub fn for_ring(&self, (cx, cy): (usize, usize), r: usize, mut f: impl FnMut(usize, usize)) {
        let (nx, ny) = (self.nx, self.ny);
        let (x0, x1) = (cx.saturating_sub(r), (cx + r).min(nx - 1));
        if r == 0 {
            return f(cx, cy);
        }
        for y in [cy.checked_sub(r), Some(cy + r).filter(|&y| y < ny)]
            .into_iter()
            .flatten()
        {
            for x in x0..=x1 {
                f(x, y);
            }
        }
        // Rows strictly inside the ring.
        let (y0, y1) = ((cy + 1).saturating_sub(r), (cy + r - 1).min(ny - 1));
        for x in [cx.checked_sub(r), Some(cx + r).filter(|&x| x < nx)]
            .into_iter()
            .flatten()
        {
            for y in y0..=y1 {
                f(x, y);
            }
        }
    }

    /// Whether ring `r` around cell `(cx, cy)` reaches every edge of the grid (the rings
    /// up to it cover all cells).
    pub fn ring_covers_all(&self, (cx, cy): (usize, usize), r: usize) -> bool {
        r >= cx && r >= cy && cx + r >= self.nx - 1 && cy + r >= self.ny - 1
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every cell of the grid is in exactly one ring around any cell, and the rings cover
    /// all cells exactly from the first that reaches every edge.
    #[test]
    fn rings_partition_the_grid() {
        let pts: Vec<Point2> = (0..70)
            .map(|i| [(i % 10) as f64, (i / 10) as f64 * 0.7])
            .collect();
        let grid = PointGrid::new(&pts, 1.0);
        let (nx, ny) = grid.dims();
        for c in [(0, 0), (nx / 2, ny / 2), (nx - 1, 0), (nx - 1, ny - 1)] {
            let mut seen = vec![0; nx * ny];
            for r in 0..nx.max(ny) {
                let far = [c.0, c.1, nx - 1 - c.0, ny - 1 - c.1];
                assert_eq!(grid.ring_covers_all(c, r), far.iter().all(|&f| f <= r));
                grid.for_ring(c, r, |x, y| {
                    assert_eq!(x.abs_diff(c.0).max(y.abs_diff(c.1)), r);
                    seen[y * nx + x] += 1;
                });
            }
            assert!(seen.iter().all(|&k| k == 1), "{c:?}: {seen:?}");
        }
    }
}
