//! Exact dynamic programming over a polygon walk with nothing inside: the lightest
//! triangulation by usable diagonals, `O(D·m/64 + T)` for `D` valid diagonals and `T`
//! triangles (Gilbert; Klincsek), with lengths summed in double-double and exact
//! comparison of sums of square roots where the bounds cannot decide.

use super::cross;
use super::walks::in_wedge;
use crate::control::Control;
use crate::geom::{DoubleDouble, Interval, Point2, compare_root_sums, orient2d, squared_length};
use crate::planar::edge_key as key;
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::HashSet;

/// A solved face: its added edges (diagonals and cut edges) and their total length.
pub struct Solution {
    /// Edges added inside the face.
    pub edges: Vec<[u32; 2]>,
    /// Their total length.
    pub weight: Interval,
}

/// Exact comparison of two edge sets' total lengths.
pub fn cmp_edge_sets(points: &[Point2], a: &[[u32; 2]], b: &[[u32; 2]]) -> Ordering {
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    a.sort_unstable();
    b.sort_unstable();
    let (mut only_a, mut only_b) = (Vec::new(), Vec::new());
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        if j == b.len() || (i < a.len() && a[i] < b[j]) {
            only_a.push(a[i]);
            i += 1;
        } else if i == a.len() || b[j] < a[i] {
            only_b.push(b[j]);
            j += 1;
        } else {
            i += 1;
            j += 1;
        }
    }
    let sq = |v: &[[u32; 2]]| -> Vec<_> {
        v.iter()
            .map(|e| squared_length(&points[e[0] as usize], &points[e[1] as usize]))
            .collect()
    };
    compare_root_sums(&sq(&only_a), &sq(&only_b))
}

/// True when the segment `e` crosses no edge of `cuts` (edges already chosen).
pub(super) fn clear_of(points: &[Point2], cuts: &[[u32; 2]], e: &[u32; 2]) -> bool {
    !cuts.iter().any(|c| crosses(points, c, e))
}

/// Where the pair `i < j` of `0..m` is in an upper triangle stored row by row.
pub(super) fn upper_index(m: usize, i: usize, j: usize) -> usize {
    i * (2 * m - i - 1) / 2 + (j - i - 1)
}

/// True when the segments `a` and `b` share no end and cross.
pub(super) fn crosses(points: &[Point2], a: &[u32; 2], b: &[u32; 2]) -> bool {
    let p = |i: u32| &points[i as usize];
    a[0] != b[0]
        && a[0] != b[1]
        && a[1] != b[0]
        && a[1] != b[1]
        && cross(p(a[0]), p(a[1]), p(b[0]), p(b[1]))
}

/// Dynamic programming over a (weakly simple) polygon walk `poly` (counter-clockwise):
/// the lightest triangulation whose diagonals satisfy `usable`, leave and enter each
/// occurrence inside its wedge and cross no edge of `cuts`. The caller guarantees that
/// no usable segment crosses a side of the walk.
///
/// `O(D·m/64 + T)` for `D` valid diagonals and `T` triangles with three valid sides: the
/// apexes of a diagonal are the intersection of two bit rows. Each cell keeps the
/// weight of the sub-triangulation it chose in double-double with a certified error
/// bound; two options the bounds cannot order are compared exactly ([`cmp_edge_sets`]),
/// so the choice is optimal. `None` also once `ctl` is stopped (looked at between spans).
pub(crate) fn polygon_dp(
    points: &[Point2],
    poly: &[u32],
    cuts: &[[u32; 2]],
    usable: &(dyn Fn([u32; 2]) -> bool + Sync),
    ctl: &Control,
) -> Option<Solution> {
    let m = poly.len();
    if m < 3 {
        return None;
    }
    let p = |i: usize| &points[poly[i] as usize];
    if m == 3 {
        return (orient2d(p(0), p(1), p(2)) > 0).then(|| Solution {
            edges: Vec::new(),
            weight: Interval::ZERO,
        });
    }
    let rows = Rows::new(points, poly, cuts, usable);
    let mut dp = Table::new(m);
    let candidates = |dp: &Table, i: usize, j: usize| -> Cell {
        let mut cur = Cell::NONE;
        rows.common(i, j, |k| {
            let (a, b) = (dp.get(i, k), dp.get(k, j));
            if a.apex == NONE || b.apex == NONE || orient2d(p(i), p(k), p(j)) <= 0 {
                return;
            }
            let w = a.w.plus(b.w);
            let better = cur.apex == NONE
                || match w.certain_cmp(cur.w, j - i) {
                    Some(o) => o == Ordering::Less,
                    None => {
                        let ea = option_edges(dp, poly, i, k, j);
                        let eb = option_edges(dp, poly, i, cur.apex as usize, j);
                        cmp_edge_sets(points, &ea, &eb) == Ordering::Less
                    }
                };
            if better {
                cur = Cell { w, apex: k as u32 };
            }
        });
        if cur.apex != NONE && !(i == 0 && j == m - 1) {
            cur.w = cur.w.plus(DoubleDouble::length(p(i), p(j)));
        }
        cur
    };
    for span in 2..m {
        if ctl.is_stopped() {
            return None;
        }
        let solve = |i: usize| {
            let j = i + span;
            if rows.ok(i, j) {
                candidates(&dp, i, j)
            } else {
                Cell::NONE
            }
        };
        let cells: Vec<Cell> = if m >= PARALLEL_DP {
            (0..m - span).into_par_iter().map(solve).collect()
        } else {
            (0..m - span).map(solve).collect()
        };
        for (i, c) in cells.into_iter().enumerate() {
            dp.set(i, i + span, c);
        }
    }
    let top = dp.get(0, m - 1);
    if top.apex == NONE {
        return None;
    }
    let mut edges = Vec::new();
    collect(&dp, poly, 0, m - 1, &mut edges);
    Some(Solution {
        edges,
        weight: top.w.interval(m),
    })
}

/// Walks at least this long are solved with one parallel task per span.
const PARALLEL_DP: usize = 256;

/// Sentinel apex: no triangulation of the sub-polygon.
const NONE: u32 = u32::MAX;
/// Sentinel apex: a side of the walk (nothing to triangulate).
const SIDE: u32 = u32::MAX - 1;

/// The best sub-triangulation of `i..j`: its weight plus the length of the diagonal `ij`
/// (zero for a side; a sum of fewer than `j - i` lengths, in double-double) and the apex
/// of its triangle on `ij`.
#[derive(Clone, Copy)]
struct Cell {
    w: DoubleDouble,
    apex: u32,
}

impl Cell {
    const NONE: Cell = Cell {
        w: DoubleDouble::ZERO,
        apex: NONE,
    };
}

/// The cells of pairs `i < j`, stored as an upper triangle.
struct Table {
    m: usize,
    cells: Vec<Cell>,
}

impl Table {
    fn new(m: usize) -> Table {
        let mut t = Table {
            m,
            cells: vec![Cell::NONE; m * (m - 1) / 2],
        };
        for i in 0..m - 1 {
            t.set(
                i,
                i + 1,
                Cell {
                    w: DoubleDouble::ZERO,
                    apex: SIDE,
                },
            );
        }
        t
    }

    fn index(&self, i: usize, j: usize) -> usize {
        upper_index(self.m, i, j)
    }

    fn get(&self, i: usize, j: usize) -> Cell {
        self.cells[self.index(i, j)]
    }

    fn set(&mut self, i: usize, j: usize, c: Cell) {
        let k = self.index(i, j);
        self.cells[k] = c;
    }
}

/// Bit rows of the pairs of walk positions joined by a side or a valid diagonal.
pub(super) struct Rows {
    words: usize,
    bits: Vec<u64>,
}

impl Rows {
    pub(super) fn new(
        points: &[Point2],
        poly: &[u32],
        cuts: &[[u32; 2]],
        usable: &(dyn Fn([u32; 2]) -> bool + Sync),
    ) -> Rows {
        let m = poly.len();
        let words = m.div_ceil(64);
        let boundary: HashSet<[u32; 2]> = (0..m).map(|i| key(poly[i], poly[(i + 1) % m])).collect();
        let inside_at = |i: usize, j: usize| {
            in_wedge(
                points,
                poly[i],
                poly[(i + 1) % m],
                poly[(i + m - 1) % m],
                poly[j],
            )
        };
        let valid = |i: usize, j: usize| {
            let e = key(poly[i], poly[j]);
            j == i + 1
                || (i == 0 && j == m - 1)
                || (poly[i] != poly[j]
                    && !boundary.contains(&e)
                    && usable(e)
                    && inside_at(i, j)
                    && inside_at(j, i)
                    && clear_of(points, cuts, &e))
        };
        let upper: Vec<Vec<usize>> = (0..m)
            .into_par_iter()
            .map(|i| (i + 1..m).filter(|&j| valid(i, j)).collect())
            .collect();
        let mut bits = vec![0u64; m * words];
        for (i, js) in upper.iter().enumerate() {
            for &j in js {
                bits[i * words + j / 64] |= 1 << (j % 64);
                bits[j * words + i / 64] |= 1 << (i % 64);
            }
        }
        Rows { words, bits }
    }

    /// The bits of the positions joined to `i`.
    pub(super) fn row(&self, i: usize) -> &[u64] {
        &self.bits[i * self.words..(i + 1) * self.words]
    }

    pub(super) fn ok(&self, i: usize, j: usize) -> bool {
        self.bits[i * self.words + j / 64] >> (j % 64) & 1 == 1
    }

    /// Calls `f(k)` for every `i < k < j` joined to both `i` and `j`.
    pub(super) fn common(&self, i: usize, j: usize, mut f: impl FnMut(usize)) {
        let (ri, rj) = (i * self.words, j * self.words);
        let (lo, hi) = (i + 1, j - 1);
        for w in lo / 64..=hi / 64 {
            let mut x = self.bits[ri + w] & self.bits[rj + w];
            if w == lo / 64 {
                x &= !0u64 << (lo % 64);
            }
            if w == hi / 64 && hi % 64 < 63 {
                x &= (1u64 << (hi % 64 + 1)) - 1;
            }
            while x != 0 {
                f(w * 64 + x.trailing_zeros() as usize);
                x &= x - 1;
            }
        }
    }
}

/// Diagonals of the sub-polygon `i..j` when its triangle on `ij` has apex `k`.
fn option_edges(dp: &Table, poly: &[u32], i: usize, k: usize, j: usize) -> Vec<[u32; 2]> {
    let mut out = Vec::new();
    for (a, b) in [(i, k), (k, j)] {
        if b != a + 1 {
            out.push(key(poly[a], poly[b]));
        }
        collect(dp, poly, a, b, &mut out);
    }
    out
}

fn collect(dp: &Table, poly: &[u32], i: usize, j: usize, out: &mut Vec<[u32; 2]>) {
    let mut stack = vec![(i, j)];
    while let Some((i, j)) = stack.pop() {
        let k = dp.get(i, j).apex;
        if k == NONE || k == SIDE {
            continue;
        }
        let k = k as usize;
        for (a, b) in [(i, k), (k, j)] {
            if b != a + 1 {
                out.push(key(poly[a], poly[b]));
                stack.push((a, b));
            }
        }
    }
}
