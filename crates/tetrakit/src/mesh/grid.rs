//! A uniform hash grid over triangle bounding boxes: the spatial filter in front of the
//! exact triangle tests (self-intersection of a surface, tetrahedra against the current
//! surface in MINTETRA). A filter only: it may return triangles that do not meet the query
//! box, never miss one that does.

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
}

impl TriangleGrid {
    /// A grid over `points` with about one cell per expected triangle.
    pub(crate) fn new(points: &[Point3], expected: usize) -> Self {
        let (lo, hi) = crate::geom::bounding_box(points);
        let ext = (0..3).map(|i| hi[i] - lo[i]).fold(0.0f64, f64::max);
        let per_axis = (expected.max(1) as f64).cbrt().ceil().max(1.0);
        let cell = if ext > 0.0 { ext / per_axis } else { 1.0 };
        TriangleGrid {
            origin: lo,
            inv: 1.0 / cell,
            cells: HashMap::default(),
        }
    }

    fn coord(&self, x: f64, i: usize) -> i64 {
        (((x - self.origin[i]) * self.inv).floor() as i64).clamp(-(1 << 20), 1 << 20)
    }

    fn cells_of(&self, b: &Aabb) -> impl Iterator<Item = u64> + use<> {
        let lo = [0, 1, 2].map(|i| self.coord(b.0[i], i));
        let hi = [0, 1, 2].map(|i| self.coord(b.1[i], i));
        (lo[0]..=hi[0]).flat_map(move |x| {
            (lo[1]..=hi[1]).flat_map(move |y| {
                (lo[2]..=hi[2]).map(move |z| {
                    let k = |v: i64| (v + (1 << 20)) as u64;
                    (k(x) << 42) | (k(y) << 21) | k(z)
                })
            })
        })
    }

    /// Adds a triangle.
    pub(crate) fn insert(&mut self, points: &[Point3], t: [u32; 3]) {
        let b = aabb(&[
            &points[t[0] as usize],
            &points[t[1] as usize],
            &points[t[2] as usize],
        ]);
        for key in self.cells_of(&b) {
            self.cells.entry(key).or_default().push(t);
        }
    }

    /// Calls `f` on every stored triangle whose cells meet the box (a triangle may be
    /// visited more than once).
    pub(crate) fn visit(&self, b: &Aabb, mut f: impl FnMut(&[u32; 3]) -> bool) -> bool {
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
