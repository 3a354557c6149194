//! The exact stage: the faces of the certain edges that still hold undecided edges are
//! triangulated optimally.
//!
//! A face is given by its boundary walk (counter-clockwise, face on the left, vertices
//! possibly repeated where certain edges dangle into it) and its holes (clockwise walks
//! of certain-edge components, or isolated sites). Without holes, dynamic programming
//! over the walk's occurrences (`O(m³)`) finds the optimum among the alive edges that
//! leave and enter each occurrence inside its wedge. With holes, every triangulation
//! has an edge joining the outer walk to some hole (the triangulation is connected);
//! branching over those edges and cutting the face along the chosen one (the edge is
//! walked twice) reduces the number of holes by one, so the minimum over the branches
//! is exact. Costs are compared as certified intervals, with the exact comparison of
//! sums of square roots when two intervals overlap (ties on grids, regular polygons).

use super::cross;
use super::walks::in_wedge;
use crate::geom::{DoubleDouble, Interval, Point2, compare_root_sums, orient2d, squared_length};
use crate::planar::edge_key as key;
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::HashSet;

/// A face to triangulate.
pub struct Face {
    /// Outer walk, counter-clockwise.
    pub outer: Vec<u32>,
    /// Hole walks (face on their left) and isolated sites (walks of length one).
    pub holes: Vec<Vec<u32>>,
}

/// Limits on the branching over holes.
pub const BRANCH_LIMIT: usize = 100_000;

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

/// Solves a face exactly. `chords` are the alive edges usable inside it.
pub fn solve(
    points: &[Point2],
    face: &Face,
    chords: &HashSet<[u32; 2]>,
    budget: &mut usize,
) -> Option<Solution> {
    solve_cut(
        points,
        face.outer.clone(),
        face.holes.clone(),
        &[],
        chords,
        budget,
    )
}

fn solve_cut(
    points: &[Point2],
    outer: Vec<u32>,
    holes: Vec<Vec<u32>>,
    cuts: &[[u32; 2]],
    chords: &HashSet<[u32; 2]>,
    budget: &mut usize,
) -> Option<Solution> {
    if *budget == 0 {
        return None;
    }
    *budget -= 1;
    if holes.is_empty() {
        return polygon_dp(points, &outer, cuts, &|e| chords.contains(&e));
    }
    // Branch on the hole with the fewest connecting edges.
    let on_outer: HashSet<u32> = outer.iter().copied().collect();
    let links = |h: &Vec<u32>| -> Vec<[u32; 2]> {
        let mut v: Vec<[u32; 2]> = chords
            .iter()
            .copied()
            .filter(|e| {
                (on_outer.contains(&e[0]) && h.contains(&e[1]))
                    || (on_outer.contains(&e[1]) && h.contains(&e[0]))
            })
            .filter(|e| !cuts.iter().any(|c| crosses(points, c, e)))
            .collect();
        v.sort_unstable();
        v
    };
    let (hi, options) = holes
        .iter()
        .enumerate()
        .map(|(i, h)| (i, links(h)))
        .min_by_key(|(_, l)| l.len())
        .expect("holes");
    let mut best: Option<Solution> = None;
    for e in options {
        let (w, h) = if on_outer.contains(&e[0]) && holes[hi].contains(&e[1]) {
            (e[0], e[1])
        } else {
            (e[1], e[0])
        };
        let Some(walk) = splice(points, &outer, &holes[hi], w, h) else {
            continue;
        };
        let mut rest = holes.clone();
        rest.remove(hi);
        let mut c = cuts.to_vec();
        c.push(e);
        let mut chords2 = chords.clone();
        chords2.remove(&e);
        let Some(mut sol) = solve_cut(points, walk, rest, &c, &chords2, budget) else {
            if *budget == 0 {
                return None;
            }
            continue;
        };
        sol.edges.push(e);
        sol.weight = sol.weight.plus(Interval::length(
            &points[e[0] as usize],
            &points[e[1] as usize],
        ));
        best = Some(match best {
            None => sol,
            Some(b) => match sol.weight.certain_cmp(b.weight) {
                Some(Ordering::Less) => sol,
                Some(_) => b,
                None if cmp_edge_sets(points, &sol.edges, &b.edges) == Ordering::Less => sol,
                None => b,
            },
        });
    }
    best
}

fn crosses(points: &[Point2], a: &[u32; 2], b: &[u32; 2]) -> bool {
    let p = |i: u32| &points[i as usize];
    a[0] != b[0]
        && a[0] != b[1]
        && a[1] != b[0]
        && a[1] != b[1]
        && cross(p(a[0]), p(a[1]), p(b[0]), p(b[1]))
}

/// The outer walk with the hole spliced in along `w–h`.
fn splice(points: &[Point2], outer: &[u32], hole: &[u32], w: u32, h: u32) -> Option<Vec<u32>> {
    let m = outer.len();
    let i = (0..m).find(|&i| {
        outer[i] == w && in_wedge(points, w, outer[(i + 1) % m], outer[(i + m - 1) % m], h)
    })?;
    let k = hole.len();
    let j = if k == 1 {
        0
    } else {
        (0..k).find(|&j| {
            hole[j] == h && in_wedge(points, h, hole[(j + 1) % k], hole[(j + k - 1) % k], w)
        })?
    };
    let mut out: Vec<u32> = outer[..=i].to_vec();
    out.extend((0..k).map(|t| hole[(j + t) % k]));
    if k > 1 {
        out.push(h);
    }
    out.push(w);
    out.extend_from_slice(&outer[i + 1..]);
    Some(out)
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
/// so the choice is optimal.
pub(crate) fn polygon_dp(
    points: &[Point2],
    poly: &[u32],
    cuts: &[[u32; 2]],
    usable: &(dyn Fn([u32; 2]) -> bool + Sync),
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
        i * (2 * self.m - i - 1) / 2 + (j - i - 1)
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
struct Rows {
    words: usize,
    bits: Vec<u64>,
}

impl Rows {
    fn new(
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
                    && !cuts.iter().any(|c| crosses(points, c, &e)))
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

    fn ok(&self, i: usize, j: usize) -> bool {
        self.bits[i * self.words + j / 64] >> (j % 64) & 1 == 1
    }

    /// Calls `f(k)` for every `i < k < j` joined to both `i` and `j`.
    fn common(&self, i: usize, j: usize, mut f: impl FnMut(usize)) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Hull2;
    use crate::rng::Rng;

    /// A convex polygon with isolated interior sites as holes, solved by hole branching
    /// directly, against the full pipeline (itself checked against exhaustive search).
    #[test]
    fn holes_are_solved_exactly_by_branching() {
        let mut rng = Rng::new(21);
        let mut with_two_holes = 0;
        for _ in 0..150 {
            let m = 5 + rng.below(4);
            let mut pts: Vec<Point2> = (0..m)
                .map(|i| {
                    let a = std::f64::consts::TAU * (i as f64 + 0.3 * rng.unit()) / m as f64;
                    [(8.0 * a.cos()).round(), (8.0 * a.sin()).round()]
                })
                .collect();
            for _ in 0..1 + rng.below(3) {
                pts.push([rng.below(7) as f64 - 3.0, rng.below(7) as f64 - 3.0]);
            }
            pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
            pts.dedup();
            let hull = Hull2::new(&pts);
            if hull.vertices.len() < 3
                || hull.on_boundary.iter().filter(|&&b| b).count() != hull.vertices.len()
            {
                continue;
            }
            let inner: Vec<u32> = (0..pts.len() as u32)
                .filter(|&i| !hull.on_boundary[i as usize])
                .collect();
            if inner.is_empty() {
                continue;
            }
            let n = pts.len() as u32;
            let hull_set: HashSet<[u32; 2]> = (0..hull.vertices.len())
                .map(|i| {
                    key(
                        hull.vertices[i],
                        hull.vertices[(i + 1) % hull.vertices.len()],
                    )
                })
                .collect();
            let blocked = crate::planar::blocked_pairs(&pts);
            let chords: HashSet<[u32; 2]> = (0..n)
                .flat_map(|a| (a + 1..n).map(move |b| [a, b]))
                .filter(|e| !hull_set.contains(e) && !blocked.contains(e))
                .collect();
            let face = Face {
                outer: hull.vertices.clone(),
                holes: inner.iter().map(|&v| vec![v]).collect(),
            };
            let mut budget = BRANCH_LIMIT;
            let sol = solve(&pts, &face, &chords, &mut budget).expect("a triangulation exists");
            let mut edges: Vec<[u32; 2]> = sol.edges.clone();
            edges.extend(hull_set.iter().copied());
            let best = crate::planar::mwt(&pts).unwrap();
            assert_eq!(
                cmp_edge_sets(&pts, &edges, &best.edges),
                Ordering::Equal,
                "{pts:?}"
            );
            edges.sort_unstable();
            edges.dedup();
            assert_eq!(edges.len(), 3 * pts.len() - 3 - hull.vertices.len());
            with_two_holes += usize::from(inner.len() >= 2);
        }
        assert!(with_two_holes > 20);
    }
}
