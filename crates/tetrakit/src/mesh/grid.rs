//! A uniform hash grid over triangle bounding boxes: the spatial filter in front of the
//! exact triangle tests (self-intersection of a surface, tetrahedra against the current
//! surface in MINTETRA). A filter only: it may return triangles that do not meet the query
//! box, never miss one that does. Cell indices are computed in floating point, but the
//! map x ↦ clamp(floor((x − origin)·inv)) is monotone, so two boxes that meet exactly get
//! cell ranges that meet; the only geometric decisions are the exact tests behind it.

use crate::geom::Point3;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// Multiply-shift hashing for packed cell keys.
#[derive(Default)]
pub(crate) struct CellHasher(u64);

impl Hasher for CellHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ b as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        }
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (x ^ (x >> 29)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    }
}

/// Axis-aligned box `(min, max)`.
pub(crate) type Aabb = (Point3, Point3);

/// The bounding box of some points.
pub(crate) fn aabb(pts: &[&Point3]) -> Aabb {
    let mut lo = *pts[0];
    let mut hi = *pts[0];
    for p in &pts[1..] {
        for i in 0..3 {
            lo[i] = lo[i].min(p[i]);
            hi[i] = hi[i].max(p[i]);
        }
    }
    (lo, hi)
}

/// True when two closed boxes meet.
pub(crate) fn boxes_meet(a: &Aabb, b: &Aabb) -> bool {
    (0..3).all(|i| a.0[i] <= b.1[i] && b.0[i] <= a.1[i])
}

/// Triangles (as vertex triples) bucketed by the grid cells their boxes meet.
pub(crate) struct TriangleGrid {
    origin: Point3,
    inv: f64,
    cells: HashMap<u64, Vec<[u32; 3]>, BuildHasherDefault<CellHasher>>,
    /// Triangles whose boxes cover more than [`MAX_CELLS`] cells: checked by every query.
    big: Vec<[u32; 3]>,
}

/// Beyond this many cells a triangle goes to the `big` list and a query scans all cells.
const MAX_CELLS: i64 = 512;

impl TriangleGrid {
    fn coord(&self, x: f64, i: usize) -> i64 {
        (((x - self.origin[i]) * self.inv).floor() as i64).clamp(-(1 << 20), 1 << 20)
    }

    fn span(&self, b: &Aabb) -> ([i64; 3], [i64; 3], i64) {
        let lo = [0, 1, 2].map(|i| self.coord(b.0[i], i));
        let hi = [0, 1, 2].map(|i| self.coord(b.1[i], i));
        let count = (0..3).map(|i| hi[i] - lo[i] + 1).product();
        (lo, hi, count)
    }

    fn cells_of(&self, b: &Aabb) -> impl Iterator<Item = u64> + use<> {
        let (lo, hi, _) = self.span(b);
        (lo[0]..=hi[0]).flat_map(move |x| {
            (lo[1]..=hi[1]).flat_map(move |y| {
                (lo[2]..=hi[2]).map(move |z| {
                    let k = |v: i64| (v + (1 << 20)) as u64;
                    (k(x) << 42) | (k(y) << 21) | k(z)
                })
            })
        })
    }

    /// A grid whose cells are about the size of the larger faces (90th percentile), so that a cell
    /// holds O(1) faces of a surface whatever its overall shape (a bounding-box based
    /// size puts a long or crumpled surface into few cells).
    pub(crate) fn sized_for(points: &[Point3], faces: &[[u32; 3]]) -> Self {
        let step = (faces.len() / 4096).max(1);
        let mut sizes: Vec<f64> = faces
            .iter()
            .step_by(step)
            .map(|f| {
                let b = aabb(&[
                    &points[f[0] as usize],
                    &points[f[1] as usize],
                    &points[f[2] as usize],
                ]);
                (0..3).map(|i| b.1[i] - b.0[i]).fold(0.0f64, f64::max)
            })
            .collect();
        let at = sizes.len() * 9 / 10;
        let large = if sizes.is_empty() {
            1.0
        } else {
            *sizes.select_nth_unstable_by(at, f64::total_cmp).1
        };
        Self::with_cell(points, 1.5 * large)
    }

    /// A grid sized for `faces` (see [`TriangleGrid::sized_for`]) holding all of them.
    pub(crate) fn of_faces(points: &[Point3], faces: &[[u32; 3]]) -> Self {
        let mut grid = Self::sized_for(points, faces);
        for f in faces {
            grid.insert(points, *f);
        }
        grid
    }

    /// True when a stored triangle for which `live` holds meets the closed tetrahedron
    /// `tet` anywhere other than in the vertices and edges they share (exact). `live` is
    /// asked first, so it should be the cheap test (e.g. "still on the surface and not
    /// one of the faces being replaced").
    pub(crate) fn blocks_tet(
        &self,
        points: &[Point3],
        tet: &[u32; 4],
        live: impl Fn(&[u32; 3]) -> bool,
    ) -> bool {
        let geo = tet.map(|v| points[v as usize]);
        let b = aabb(&[&geo[0], &geo[1], &geo[2], &geo[3]]);
        self.visit(&b, |f| {
            if !live(f) {
                return false;
            }
            let tri = f.map(|v| points[v as usize]);
            boxes_meet(&b, &aabb(&[&tri[0], &tri[1], &tri[2]]))
                && crate::geom::triangle_meets_tet(&tri, *f, &geo, tet)
        })
    }

    /// A grid with cells of side `cell` (a non-positive or non-finite size means 1).
    pub(crate) fn with_cell(points: &[Point3], cell: f64) -> Self {
        let (lo, _) = crate::geom::bounding_box(points);
        let cell = if cell > 0.0 && cell.is_finite() {
            cell
        } else {
            1.0
        };
        TriangleGrid {
            origin: lo,
            inv: 1.0 / cell,
            cells: HashMap::default(),
            big: Vec::new(),
        }
    }

    /// Adds a triangle.
    pub(crate) fn insert(&mut self, points: &[Point3], t: [u32; 3]) {
        let b = aabb(&[
            &points[t[0] as usize],
            &points[t[1] as usize],
            &points[t[2] as usize],
        ]);
        self.insert_item(&b, t);
    }

    /// Adds an item (a triangle, or any three words a caller keys by) under box `b`.
    pub(crate) fn insert_item(&mut self, b: &Aabb, t: [u32; 3]) {
        let b = *b;
        if self.span(&b).2 > MAX_CELLS {
            self.big.push(t);
            return;
        }
        for key in self.cells_of(&b) {
            self.cells.entry(key).or_default().push(t);
        }
    }

    /// Calls `f` on every stored triangle whose cells meet the box (a triangle may be
    /// visited more than once).
    pub(crate) fn visit(&self, b: &Aabb, mut f: impl FnMut(&[u32; 3]) -> bool) -> bool {
        if self.big.iter().any(&mut f) {
            return true;
        }
        if self.span(b).2 > MAX_CELLS.max(self.cells.len() as i64) {
            return self.cells.values().flatten().any(f);
        }
        for key in self.cells_of(b) {
            if let Some(list) = self.cells.get(&key) {
                for t in list {
                    if f(t) {
                        return true;
                    }
                }
            }
        }
        false
    }
}

/// Pairs `(i, j)`, `i < j`, of triangles that meet other than in shared vertices and the
/// edge between them (exact), at most `limit` of them, smallest first. Hash-grid
/// candidates, tested in parallel: about linear for a surface whose triangles are of
/// comparable size, whatever its overall shape.
pub(crate) fn improper_pairs(
    points: &[Point3],
    faces: &[[u32; 3]],
    limit: usize,
) -> Vec<(usize, usize)> {
    use rayon::prelude::*;
    let tri = |f: &[u32; 3]| f.map(|v| points[v as usize]);
    let boxes: Vec<Aabb> = faces
        .iter()
        .map(|f| {
            let t = tri(f);
            aabb(&[&t[0], &t[1], &t[2]])
        })
        .collect();
    // Items are face indices: [i, 0, 0].
    let mut grid = TriangleGrid::sized_for(points, faces);
    for (i, b) in boxes.iter().enumerate() {
        grid.insert_item(b, [i as u32, 0, 0]);
    }
    let mut pairs: Vec<(usize, usize)> = (0..faces.len())
        .into_par_iter()
        .flat_map_iter(|i| {
            let f = faces[i];
            let t = tri(&f);
            let mut found = Vec::new();
            grid.visit(&boxes[i], |item| {
                let j = item[0] as usize;
                if j > i && boxes_meet(&boxes[i], &boxes[j]) && !found.contains(&j) {
                    let g = faces[j];
                    if crate::geom::triangles_meet_improperly(&t, f, &tri(&g), g) {
                        found.push(j);
                    }
                }
                false
            });
            found.into_iter().map(move |j| (i, j))
        })
        .collect();
    pairs.sort_unstable();
    pairs.truncate(limit);
    pairs
}
