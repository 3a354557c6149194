//! A uniform bucket grid over the plane: square cells over a bounding box, and the
//! items of each cell in compressed rows. The one spatial index of the planar code (the
//! point grid of the β-skeleton and MWT searches, the segment grid of the LMT's crossing
//! test). It only proposes: cells are computed in floating point and every decision
//! about the items it returns is made by an exact predicate.
//!
//! **Safe for any input the readers accept.** Cell counts are computed in floating
//! point and clamped before any cast, so sets spanning 10^-300 to 10^300 (or a single
//! point, or collinear points) give a grid of at least one and at most `max_side` cells
//! per side, never an overflow. Coordinates outside the box (or NaN) map to the border
//! cells; the index is monotone in each coordinate, so a point inside a box is in a cell
//! of the box's cell range.
//!
//! The 3D triangle grid of `mesh` is a different structure on purpose: hashed cells
//! filled incrementally while faces are inserted, where these are dense rows built once.

use super::Point2;
use crate::rows;

/// A uniform grid of square cells with items bucketed by cell (row-major).
#[derive(Clone, Debug)]
pub(crate) struct Grid2 {
    origin: Point2,
    cell: f64,
    nx: usize,
    ny: usize,
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Grid2 {
    /// An empty grid over the box `[lo, hi]` with cells of side `cell` or more, at most
    /// `max_side` cells along each side (the cell grows to cover the box).
    fn frame(lo: Point2, hi: Point2, cell: f64, max_side: usize) -> Grid2 {
        let (w, h) = (span(lo[0], hi[0]), span(lo[1], hi[1]));
        let cell = if cell.is_finite() && cell > 0.0 {
            cell
        } else {
            w.max(h).max(f64::MIN_POSITIVE)
        };
        let cells_along = |len: f64| -> usize {
            let c = (len / cell).floor();
            if c >= (max_side - 1) as f64 {
                max_side
            } else if c > 0.0 {
                c as usize + 1
            } else {
                1
            }
        };
        let (nx, ny) = (cells_along(w), cells_along(h));
        let cell = cell.max(w / nx as f64).max(h / ny as f64);
        Grid2 {
            origin: lo,
            cell,
            nx,
            ny,
            start: vec![0; nx * ny + 1],
            items: Vec::new(),
        }
    }

    /// `points` bucketed, about `per_cell` of them per cell (at most 2^14 cells a side).
    pub fn of_points(points: &[Point2], per_cell: f64) -> Grid2 {
        let (lo, hi) = super::bounding_box(points);
        let (w, h) = (span(lo[0], hi[0]), span(lo[1], hi[1]));
        let cells = (points.len() as f64 / per_cell).clamp(1.0, 4e7);
        let mut cell = ((w * h) / cells).sqrt();
        if !cell.is_finite() || cell <= 0.0 {
            cell = (w.max(h) / cells).max(f64::MIN_POSITIVE);
        }
        let mut g = Grid2::frame(lo, hi, cell, 1 << 14);
        let keys = points.iter().enumerate().map(|(i, p)| (g.key(p), i as u32));
        (g.start, g.items) = rows::buckets(g.nx * g.ny, keys);
        g
    }

    /// The items `ids` bucketed into every cell their box `bounds(id)` meets, over the
    /// box `[lo, hi]` with cells of side `cell` or more (at most `max_side` a side).
    pub fn of_boxes(
        (lo, hi): (Point2, Point2),
        cell: f64,
        max_side: usize,
        ids: &[u32],
        bounds: impl Fn(u32) -> (Point2, Point2) + Sync,
    ) -> Grid2 {
        use rayon::prelude::*;
        let mut g = Grid2::frame(lo, hi, cell, max_side);
        // Each item's cells once (its bounds may read at random), then the rows.
        let ranges: Vec<[u32; 4]> = (ids.par_iter())
            .map(|&id| {
                let (a, b) = bounds(id);
                g.cell_range(a, b).map(|c| c as u32)
            })
            .collect();
        let nx = g.nx;
        let (start, items) = rows::group(nx * g.ny, ids.len(), |i| {
            let ([x0, x1, y0, y1], id) = (ranges[i].map(|c| c as usize), ids[i]);
            (y0..=y1).flat_map(move |y| (x0..=x1).map(move |x| (y * nx + x, id)))
        });
        g.start = start.into_iter().map(|s| s as u32).collect();
        g.items = items;
        g
    }

    /// The cell index along axis `k` of coordinate `v` (clamped to the grid).
    #[inline]
    pub fn coord(&self, v: f64, k: usize) -> usize {
        let n = if k == 0 { self.nx } else { self.ny };
        let c = ((v - self.origin[k]) / self.cell).floor();
        if c >= (n - 1) as f64 {
            n - 1
        } else if c > 0.0 {
            c as usize
        } else {
            0
        }
    }

    #[inline]
    fn key(&self, p: &Point2) -> usize {
        self.coord(p[1], 1) * self.nx + self.coord(p[0], 0)
    }

    /// Side length of a cell.
    pub fn cell(&self) -> f64 {
        self.cell
    }

    /// Grid dimensions in cells.
    pub fn dims(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// The cell `(x, y)` holding `p`.
    #[inline]
    pub fn cell_of(&self, p: &Point2) -> (usize, usize) {
        (self.coord(p[0], 0), self.coord(p[1], 1))
    }

    /// The cells `[x0, x1, y0, y1]` (inclusive) meeting the box `[lo, hi]`.
    #[inline]
    pub fn cell_range(&self, lo: Point2, hi: Point2) -> [usize; 4] {
        [
            self.coord(lo[0].min(hi[0]), 0),
            self.coord(lo[0].max(hi[0]), 0),
            self.coord(lo[1].min(hi[1]), 1),
            self.coord(lo[1].max(hi[1]), 1),
        ]
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

    /// Positions (in [`Self::items`]) of the items of the cells `x0..=x1` of row `y`.
    #[inline]
    pub fn row_slots(&self, y: usize, x0: usize, x1: usize) -> std::ops::Range<usize> {
        let row = y * self.nx;
        self.start[row + x0] as usize..self.start[row + x1 + 1] as usize
    }

    /// Every item, cell by cell (row-major).
    pub fn items(&self) -> &[u32] {
        &self.items
    }

    /// Calls `f` on the cells at Chebyshev distance `r` from cell `(cx, cy)`: the bottom
    /// and top rows of the ring, then its two sides (plain loops: this is the inner walk
    /// of the searches that visit rings of cells around a site).
    pub fn for_ring(&self, (cx, cy): (usize, usize), r: usize, mut f: impl FnMut(usize, usize)) {
        let (nx, ny) = (self.nx, self.ny);
        let (x0, x1) = (cx.saturating_sub(r), cx.saturating_add(r).min(nx - 1));
        if r == 0 {
            return f(cx, cy);
        }
        for y in [cy.checked_sub(r), cy.checked_add(r).filter(|&y| y < ny)]
            .into_iter()
            .flatten()
        {
            for x in x0..=x1 {
                f(x, y);
            }
        }
        // Rows strictly inside the ring.
        let (y0, y1) = ((cy + 1).saturating_sub(r), (cy + r - 1).min(ny - 1));
        for x in [cx.checked_sub(r), cx.checked_add(r).filter(|&x| x < nx)]
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
}

/// The extent `hi − lo` of a box side, 0 for an empty or NaN side, finite otherwise
/// (`f64::MAX` when the difference overflows).
fn span(lo: f64, hi: f64) -> f64 {
    let w = hi - lo;
    if w > 0.0 { w.min(f64::MAX) } else { 0.0 }
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
        let grid = Grid2::of_points(&pts, 1.0);
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

    /// Extreme spreads (one tall thin set, huge and tiny magnitudes, one point, equal
    /// points) give a grid of 1..=2^14 cells a side holding every point once, in the
    /// cell its coordinates say.
    #[test]
    fn any_spread_gives_a_bounded_grid() {
        let sets: Vec<Vec<Point2>> = vec![
            vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1e39]],
            vec![[-1e300, -1e300], [1e300, 1e300], [0.0, 1e-300]],
            vec![[1e-300, 0.0], [2e-300, 1e-300], [0.0, 3e-300]],
            vec![[5.0, 5.0]],
            vec![[1.0, 2.0]; 4],
            (0..1000).map(|i| [i as f64, 0.0]).collect(),
            (0..1000).map(|i| [0.0, (i as f64).powi(9)]).collect(),
        ];
        for pts in sets {
            let g = Grid2::of_points(&pts, 2.0);
            let (nx, ny) = g.dims();
            assert!((1..=1 << 14).contains(&nx) && (1..=1 << 14).contains(&ny));
            let mut items = g.items().to_vec();
            items.sort_unstable();
            assert_eq!(items, (0..pts.len() as u32).collect::<Vec<_>>());
            for (i, p) in pts.iter().enumerate() {
                let (x, y) = g.cell_of(p);
                assert!(g.items()[g.row_slots(y, x, x)].contains(&(i as u32)));
            }
        }
    }

    /// A box's items are in the cells of its range.
    #[test]
    fn boxes_are_in_every_cell_they_meet() {
        let boxes = [
            ([0.0, 0.0], [3.0, 0.5]),
            ([2.5, 2.5], [2.5, 2.5]),
            ([0.0, 0.0], [4.0, 4.0]),
        ];
        let ids = [0, 1, 2];
        let g = Grid2::of_boxes(([0.0, 0.0], [4.0, 4.0]), 1.0, 64, &ids, |i| {
            boxes[i as usize]
        });
        assert_eq!(g.dims(), (5, 5));
        let count = |i: u32| g.items().iter().filter(|&&x| x == i).count();
        assert_eq!((count(0), count(1), count(2)), (4, 1, 25));
    }
}
