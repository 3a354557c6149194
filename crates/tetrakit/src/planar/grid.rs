//! Planar points in the shared bucket grid ([`Grid2`]), with their coordinates kept in
//! cell order, for box queries whose boxes are computed in floating point: the cell range
//! is widened by one cell on each side, so a box that is off by less than a cell still
//! reaches every point it should (the exact predicates decide membership).

use crate::geom::{Grid2, Point2};

/// Points bucketed by cell, in compressed rows.
pub(crate) struct PointGrid {
    grid: Grid2,
    /// The coordinates of the grid's items, in the same order (reading a cell touches no
    /// other memory).
    coords: Vec<Point2>,
}

impl std::ops::Deref for PointGrid {
    type Target = Grid2;
    fn deref(&self) -> &Grid2 {
        &self.grid
    }
}

impl PointGrid {
    /// A grid of about `per_cell` points per cell over the bounding box of `points`.
    pub fn new(points: &[Point2], per_cell: f64) -> PointGrid {
        let grid = Grid2::of_points(points, per_cell);
        let coords = grid.items().iter().map(|&i| points[i as usize]).collect();
        PointGrid { grid, coords }
    }

    /// The slots of cell `(x, y)`: positions in [`Self::slots`].
    pub fn cell_slots(&self, x: usize, y: usize) -> std::ops::Range<usize> {
        self.row_slots(y, x, x)
    }

    /// Every point index and its coordinates, cell by cell (row-major): an order with
    /// spatial locality, and cell contents without lookups elsewhere.
    pub fn slots(&self) -> (&[u32], &[Point2]) {
        (self.items(), &self.coords)
    }

    /// Calls `f` on every point in cells meeting the box `[lo, hi]` widened by one cell
    /// (for boxes computed approximately); stops early when `f` returns true, and
    /// returns whether it did.
    pub fn any_in_box(&self, lo: Point2, hi: Point2, mut f: impl FnMut(u32) -> bool) -> bool {
        let (nx, ny) = self.dims();
        let [x0, x1, y0, y1] = self.cell_range(lo, hi);
        let (x0, x1) = (x0.saturating_sub(1), (x1 + 1).min(nx - 1));
        let (y0, y1) = (y0.saturating_sub(1), (y1 + 1).min(ny - 1));
        (y0..=y1).any(|y| {
            self.items()[self.row_slots(y, x0, x1)]
                .iter()
                .any(|&i| f(i))
        })
    }
}
