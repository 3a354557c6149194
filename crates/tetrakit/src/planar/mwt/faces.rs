//! The exact stage: the faces of the certain edges that still hold undecided edges are
//! triangulated optimally.
//!
//! A face is given by its boundary walk (counter-clockwise, face on the left, vertices
//! possibly repeated where certain edges dangle into it) and its holes (clockwise walks
//! of certain-edge components, or isolated sites). Without holes, dynamic programming
//! over the walk's occurrences (`O(m³)`) finds the optimum among the alive edges that
//! leave and enter each occurrence inside its wedge. With holes, every triangulation is
//! connected, so the hole with the fewest joining edges is joined by one of them to the
//! outer walk or to another hole (not necessarily to the outer walk: a site can be
//! ringed by other holes). Branching over those edges and splicing the two walks along
//! the chosen one (the edge is walked twice) removes one hole per level, so the minimum
//! over the branches is exact; a branch whose joining edges already outweigh the best
//! solution found is dropped. Costs are compared as certified intervals, with the exact
//! comparison of sums of square roots when two intervals overlap (ties on grids,
//! regular polygons).

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

/// Solves a face exactly. `chords` are the alive edges usable inside it. `None` when
/// the face has no triangulation with them.
///
/// Exponential in the number of holes in the worst case (one branch per joining edge
/// and hole); the faces the LMT-skeleton leaves have at most one hole in practice.
pub fn solve(points: &[Point2], face: &Face, chords: &HashSet<[u32; 2]>) -> Option<Solution> {
    let mut search = Search { points, best: None };
    let mut cuts = Vec::new();
    search.branch(
        face.outer.clone(),
        face.holes.clone(),
        &mut cuts,
        Interval::ZERO,
        chords,
    );
    search.best
}

/// Branch and bound over the edges that join holes to the rest of the face.
struct Search<'a> {
    points: &'a [Point2],
    /// The lightest complete solution so far (cut edges included).
    best: Option<Solution>,
}

impl Search<'_> {
    /// Every triangulation of the face is connected, so the hole with the fewest
    /// joining edges is joined, by one of them, to the outer walk or to another hole.
    /// Branching over those edges and splicing the two walks along the chosen one
    /// removes one hole per level, so every triangulation is reached. `spent` is the
    /// length of `cuts`; a branch already heavier than the best solution is dropped.
    fn branch(
        &mut self,
        outer: Vec<u32>,
        holes: Vec<Vec<u32>>,
        cuts: &mut Vec<[u32; 2]>,
        spent: Interval,
        chords: &HashSet<[u32; 2]>,
    ) {
        if self.heavier(spent) {
            return;
        }
        if holes.is_empty() {
            if let Some(sol) = polygon_dp(self.points, &outer, cuts, &|e| chords.contains(&e)) {
                let mut edges = sol.edges;
                edges.extend_from_slice(cuts);
                self.offer(Solution {
                    edges,
                    weight: sol.weight.plus(spent),
                });
            }
            return;
        }
        let (hi, mut options) = (0..holes.len())
            .map(|i| (i, self.joins(&outer, &holes, i, cuts, chords)))
            .min_by_key(|(_, o)| o.len())
            .expect("holes");
        // Short joins first: a light solution early prunes more.
        let points = self.points;
        let len = |e: &Join| {
            let (a, b) = (&points[e.from as usize], &points[e.to as usize]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        };
        options.sort_by(|a, b| len(a).total_cmp(&len(b)));
        for j in options {
            let mut rest = holes.clone();
            let hole = rest.remove(hi);
            let walk = |target: &[u32]| splice(points, target, &hole, j.to, j.from);
            let outer2 = match j.target {
                None => walk(&outer),
                Some(t) => {
                    let t = t - usize::from(t > hi);
                    let Some(merged) = walk(&rest[t]) else {
                        continue;
                    };
                    rest[t] = merged;
                    Some(outer.clone())
                }
            };
            let Some(outer2) = outer2 else {
                continue;
            };
            let e = key(j.from, j.to);
            let mut chords2 = chords.clone();
            chords2.remove(&e);
            cuts.push(e);
            let spent2 = spent.plus(Interval::length(
                &points[e[0] as usize],
                &points[e[1] as usize],
            ));
            self.branch(outer2, rest, cuts, spent2, &chords2);
            cuts.pop();
        }
    }

    /// The usable edges from hole `i` to the outer walk (`target` `None`) or to another
    /// hole, crossing no cut.
    fn joins(
        &self,
        outer: &[u32],
        holes: &[Vec<u32>],
        i: usize,
        cuts: &[[u32; 2]],
        chords: &HashSet<[u32; 2]>,
    ) -> Vec<Join> {
        let mut out = Vec::new();
        let targets = std::iter::once((None, outer)).chain(
            (0..holes.len())
                .filter(|&t| t != i)
                .map(|t| (Some(t), &holes[t][..])),
        );
        let sites = dedup(&holes[i]);
        for (target, walk) in targets {
            let ends = dedup(walk);
            for &from in &sites {
                for &to in &ends {
                    let e = key(from, to);
                    if chords.contains(&e) && !cuts.iter().any(|c| crosses(self.points, c, &e)) {
                        out.push(Join { from, to, target });
                    }
                }
            }
        }
        out
    }

    /// True when `w` is certainly heavier than the best solution so far.
    fn heavier(&self, w: Interval) -> bool {
        (self.best.as_ref()).is_some_and(|b| w.certain_cmp(b.weight) == Some(Ordering::Greater))
    }

    /// Keeps `sol` if it is lighter than the best so far (exactly).
    fn offer(&mut self, sol: Solution) {
        let better = match &self.best {
            None => true,
            Some(b) => match sol.weight.certain_cmp(b.weight) {
                Some(o) => o == Ordering::Less,
                None => cmp_edge_sets(self.points, &sol.edges, &b.edges) == Ordering::Less,
            },
        };
        if better {
            self.best = Some(sol);
        }
    }
}

/// An edge from a hole site `from` to a site `to` of the outer walk (`target` `None`)
/// or of another hole.
struct Join {
    from: u32,
    to: u32,
    target: Option<usize>,
}

/// The distinct sites of a walk.
fn dedup(walk: &[u32]) -> Vec<u32> {
    let mut v = walk.to_vec();
    v.sort_unstable();
    v.dedup();
    v
}

fn crosses(points: &[Point2], a: &[u32; 2], b: &[u32; 2]) -> bool {
    let p = |i: u32| &points[i as usize];
    a[0] != b[0]
        && a[0] != b[1]
        && a[1] != b[0]
        && a[1] != b[1]
        && cross(p(a[0]), p(a[1]), p(b[0]), p(b[1]))
}

/// The walk `target` (the outer walk or a hole) with `hole` spliced in along the edge
/// `w–h` (`w` on `target`, `h` on `hole`): the edge is walked once each way, at the
/// occurrences of `w` and `h` whose wedges hold it. `None` if the edge leaves no
/// occurrence inside its wedge.
fn splice(points: &[Point2], target: &[u32], hole: &[u32], w: u32, h: u32) -> Option<Vec<u32>> {
    // The occurrence of `v` in `walk` whose wedge (face side) holds the direction to `d`.
    let at = |walk: &[u32], v: u32, d: u32| -> Option<usize> {
        let k = walk.len();
        if k == 1 {
            return Some(0);
        }
        (0..k).find(|&i| {
            walk[i] == v && in_wedge(points, v, walk[(i + 1) % k], walk[(i + k - 1) % k], d)
        })
    };
    let (i, j) = (at(target, w, h)?, at(hole, h, w)?);
    let k = hole.len();
    let mut out: Vec<u32> = target[..=i].to_vec();
    out.extend((0..k).map(|t| hole[(j + t) % k]));
    if k > 1 {
        out.push(h);
    }
    if target.len() > 1 {
        out.push(w);
    }
    out.extend_from_slice(&target[i + 1..]);
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

    /// The face of a convex polygon whose interior sites are holes: isolated sites, or
    /// with `pair`, the first two joined by a fixed edge (a hole walked both ways) when
    /// no site blocks it. Every other segment through no site and across no fixed edge
    /// is usable. Returns the optimum of the face stage and the fixed edges.
    fn solve_face(pts: &[Point2], pair: bool) -> Option<[Vec<[u32; 2]>; 2]> {
        let hull = Hull2::new(pts);
        if hull.vertices.len() < 3
            || hull.on_boundary.iter().filter(|&&b| b).count() != hull.vertices.len()
        {
            return None;
        }
        let h = hull.vertices.len();
        let mut fixed: Vec<[u32; 2]> = (0..h)
            .map(|i| key(hull.vertices[i], hull.vertices[(i + 1) % h]))
            .collect();
        let n = pts.len() as u32;
        let inner: Vec<u32> = (0..n).filter(|&v| !hull.on_boundary[v as usize]).collect();
        let blocked = crate::planar::blocked_pairs(pts);
        let mut holes: Vec<Vec<u32>> = inner.iter().map(|&v| vec![v]).collect();
        if pair && inner.len() >= 2 && !blocked.contains(&key(inner[0], inner[1])) {
            fixed.push(key(inner[0], inner[1]));
            holes.drain(..2);
            holes.push(vec![inner[0], inner[1]]);
        }
        let chords: HashSet<[u32; 2]> = (0..n)
            .flat_map(|a| (a + 1..n).map(move |b| [a, b]))
            .filter(|e| !fixed.contains(e) && !blocked.contains(e))
            .filter(|e| !fixed.iter().any(|f| crosses(pts, f, e)))
            .collect();
        let face = Face {
            outer: hull.vertices.clone(),
            holes,
        };
        let sol = solve(pts, &face, &chords).expect("a triangulation exists");
        let mut edges = sol.edges;
        edges.extend(&fixed);
        edges.sort_unstable();
        Some([edges, fixed])
    }

    /// The lightest triangulation containing `fixed`, by exhaustive search.
    fn lightest(pts: &[Point2], fixed: &[[u32; 2]]) -> Vec<[u32; 2]> {
        let all = crate::planar::triangulations(pts);
        let with = all
            .into_iter()
            .filter(|t| fixed.iter().all(|f| t.contains(f)));
        with.reduce(|best, t| {
            if cmp_edge_sets(pts, &t, &best) == Ordering::Less {
                t
            } else {
                best
            }
        })
        .expect("a triangulation with the fixed edges")
    }

    /// Faces with up to four holes against exhaustive search, including sites that an
    /// optimum joins only to other holes (a ring around a centre site).
    #[test]
    fn faces_with_holes_match_exhaustive_search() {
        let mut rng = Rng::new(21);
        let mut cases: Vec<Vec<Point2>> = Vec::new();
        for _ in 0..120 {
            let m = 4 + rng.below(4);
            let mut pts: Vec<Point2> = (0..m)
                .map(|i| {
                    let a = std::f64::consts::TAU * (i as f64 + 0.3 * rng.unit()) / m as f64;
                    [(8.0 * a.cos()).round(), (8.0 * a.sin()).round()]
                })
                .collect();
            for _ in 0..1 + rng.below(4) {
                pts.push([rng.below(7) as f64 - 3.0, rng.below(7) as f64 - 3.0]);
            }
            cases.push(pts);
        }
        // A centre joined to a ring of three: no edge from the centre leaves the ring.
        let ring = vec![
            [10.0, 0.0],
            [0.0, 10.0],
            [-10.0, 0.0],
            [0.0, -10.0],
            [0.0, 0.0],
            [1.0, 0.0],
            [-1.0, 1.0],
            [-1.0, -1.0],
        ];
        cases.push(ring.clone());
        cases.push(ring);
        // The same with the centre's segments to three hull sites blocked by the ring:
        // its one edge to the hull crosses the ring.
        cases.push(vec![
            [10.0, 0.0],
            [-5.0, 10.0],
            [-5.0, -10.0],
            [-9.0, 0.0],
            [0.0, 0.0],
            [2.0, 0.0],
            [-1.0, 2.0],
            [-1.0, -2.0],
        ]);
        let (mut with_two_holes, mut with_a_walk) = (0, 0);
        for (i, mut pts) in cases.into_iter().enumerate() {
            pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
            pts.dedup();
            let Some([edges, fixed]) = solve_face(&pts, i % 2 == 1) else {
                continue;
            };
            assert_eq!(
                cmp_edge_sets(&pts, &edges, &lightest(&pts, &fixed)),
                Ordering::Equal,
                "{pts:?} fixed {fixed:?}"
            );
            let hull = Hull2::new(&pts).vertices.len();
            let mut distinct = edges.clone();
            distinct.dedup();
            assert_eq!(distinct.len(), edges.len(), "{pts:?}");
            assert_eq!(edges.len(), 3 * pts.len() - 3 - hull, "{pts:?}");
            let inner = pts.len() - hull;
            with_two_holes += usize::from(inner >= 3 || (inner == 2 && fixed.len() == hull));
            with_a_walk += usize::from(inner >= 3 && fixed.len() > hull);
        }
        assert!(with_two_holes > 40 && with_a_walk > 20);
    }
}
