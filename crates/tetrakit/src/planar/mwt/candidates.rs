//! Candidate edges of a minimum weight triangulation: the diamond test.
//!
//! Drysdale, McElfresh and Snoeyink (2001) proved that an edge `pq` of an MWT has at
//! least one of its two *diamonds* (the isosceles triangles on `pq` with base angle
//! π/4.6) empty. We use the slightly smaller diamonds of base angle `θ = atan(13/16)`
//! ([`diamond_hit`]), which are exact rational regions inside the true ones, so
//! excluding an edge is always justified. An edge with a site on its open segment is
//! excluded too (it is no triangulation edge).
//!
//! **Search.** Each pair is examined from its lexicographically smaller end `p`, so the
//! partners `q` of `p` lie right of it (or straight above). A site more than `θ` beyond
//! that half-plane lies in no diamond of such a pair, so those directions are never
//! searched. Sites are visited in order of distance (grid rings) and kept sorted by
//! angle around `p`. Angles are pseudo-angles (monotone, in `[0, 4)`); a rotation by
//! `±θ` is the rational map `(16x ∓ 13y, ±13x + 16y)` up to scale.
//!
//! **Dead directions.** A site `r` at distance `ρ` and at angle `ψ ∈ (0, θ)` from the
//! direction of `q` lies in a diamond of `pq` once `|pq| > ρ(cos ψ + sin ψ cot θ) =
//! ρ sin(θ + ψ) / sin θ`, which is at most `2ρ cos θ`. So when the visited sites (all
//! within distance `ρ`) include `l` counter-clockwise and `r` clockwise of a direction,
//! both within `θ` of it, every `q` in that direction farther than `2ρ cos θ` has both
//! diamonds occupied. Each pair of angular neighbours gives such an interval of
//! directions; the direction of a visited site `x` itself is dead too when both its
//! neighbours are within `θ` of it (just clockwise of `x`, `x` is in the left diamond
//! and its clockwise neighbour in the right one; on the ray, `x` is on the segment).
//! The intervals, active from distance `2ρ cos θ · 1.001`, are merged into a set of
//! dead directions. Then:
//! - a visited site in a dead direction is excluded without a test;
//! - a grid cell all of whose directions are dead is not visited;
//! - the search ends when every direction is dead, or when every cell of a ring is dead
//!   or outside the grid: a ray from `p` to a farther cell crosses the ring in a cell
//!   inside the grid (the grid is convex), so that cell's directions, dead, include it.
//!
//! **Sites left out.** A visited site `x` all of whose directions within `θ` are dead
//! (at its distance, so at every later one) is not kept among the visited sites: it
//! cannot lie in a diamond of any later pair `pq` in a live direction (that direction
//! is more than `θ` from `x`'s), and the dead intervals it would add lie within `θ` of
//! it, dead already. Leaving a site out is safe in any case: a dead interval rests on
//! the two sites that bound it, whatever lies between them, and a missing blocker only
//! keeps a pair. On clustered sets this keeps the angular list short for sites on a
//! cluster's rim, which look into empty space past hundreds of sites (10 % off the
//! search there, the same candidates).
//!
//! A visited site in a live direction gets the exact test against the visited sites
//! within `θ` of its direction, nearest in angle first. Only sites closer than `q` can
//! lie in a diamond of `pq`, and they have all been visited unless their direction is
//! dead at their distance, and so at `q`'s (a blocker missed, or left out as above,
//! only keeps a pair).
//!
//! **Why the floating-point search is exact.** Every exclusion is decided one of two
//! ways: by exact hits ([`diamond_hit`] on two sites, one per diamond, or one on the
//! segment), or by a dead direction. Only the second uses floating-point distances and
//! pseudo-angles, with margins far above their rounding errors:
//! - [`mwt`](super::mwt) admits only coordinates in the exact range (zero or magnitude
//!   in `[2^-142, 2^201]`), so a non-zero coordinate difference is at least `2^-194` and
//!   a squared distance at most `2^405`: nothing underflows or overflows, and each
//!   distance and pseudo-angle carries an error below `2^-45` (relative for distances,
//!   absolute for pseudo-angles, whose range is `[0, 4)`).
//! - The margins: `10^-9` in pseudo-angle at every end of a dead interval and around
//!   every cell's directions (twice that around a site's own direction, so that it
//!   overlaps the intervals beside it); 0.1% on the activation distance; cells widened by a
//!   millionth of a cell (a site's cell index is off by at most one near a cell
//!   boundary, by under `2^-37` cells).
//! - Keeping a pair the exact test would exclude is always safe (the LMT-skeleton and
//!   the exact stage optimise over the candidates, a superset of the MWT's edges), so the
//!   order in which sites are visited, by rounded distance, only affects speed.

use crate::control::Control;
use crate::geom::{Point2, diamond_hit};
use crate::planar::grid::PointGrid;
use crate::planar::{PlanarError, check_sites, edge_key};
use rayon::prelude::*;
use std::cmp::Reverse;
use std::collections::{BinaryHeap, VecDeque};
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

/// A monotone stand-in for the angle of `(dx, dy)`, in `[0, 4)`.
fn pseudo_angle(dx: f64, dy: f64) -> f64 {
    if dy >= 0.0 {
        if dx >= 0.0 {
            dy / (dx + dy)
        } else {
            1.0 - dx / (dy - dx)
        }
    } else if dx < 0.0 {
        2.0 - dy / (-dx - dy)
    } else {
        3.0 + dx / (dx - dy)
    }
}

/// Margin in pseudo-angle (errors are below `2^-45`).
const EPS: f64 = 1e-9;

/// Beyond `2 cos θ · ρ` (with a 0.1% margin), a site at distance `ρ` within `θ` of a
/// direction is in a diamond of every pair in that direction (`cos θ = 16/√425`).
const ACTIVATION: f64 = 2.0 * 16.0 / 20.615_528_128_088_304 * 1.001;

/// How far counter-clockwise pseudo-angle `to` is from `from` (both in `[0, 4)`, up to
/// the margins), in `[0, 4)`.
fn ccw_from(from: f64, to: f64) -> f64 {
    let d = to - from;
    if d < 0.0 { d + 4.0 } else { d }
}

/// A visited site: its slot, pseudo-angle, and the pseudo-angle widths of `θ`
/// clockwise (`back`) and counter-clockwise (`fwd`) of it.
#[derive(Clone, Copy, Debug)]
struct Seen {
    pa: f64,
    back: f64,
    fwd: f64,
    slot: u32,
}

impl Seen {
    fn new(dx: f64, dy: f64, slot: u32) -> Seen {
        let pa = pseudo_angle(dx, dy);
        let cw = pseudo_angle(16.0 * dx + 13.0 * dy, 16.0 * dy - 13.0 * dx);
        let ccw = pseudo_angle(16.0 * dx - 13.0 * dy, 13.0 * dx + 16.0 * dy);
        Seen {
            pa,
            back: ccw_from(cw, pa),
            fwd: ccw_from(pa, ccw),
            slot,
        }
    }
}

/// Directions strictly between `r` and its counter-clockwise neighbour `l` and within `θ`
/// of both, as `(lo, hi)` with `lo` in `[0, 4)` (`hi` may pass 4).
fn between(r: &Seen, l: &Seen) -> Option<(f64, f64)> {
    let g = ccw_from(r.pa, l.pa);
    let lo = (g - l.back).max(0.0) + EPS;
    let hi = g.min(r.fwd) - EPS;
    (lo <= hi).then_some((r.pa + lo, r.pa + hi))
}

/// The direction of `x` (with its margin), when its neighbours `r` (clockwise) and `l`
/// are both within `θ` of it.
fn through(r: &Seen, x: &Seen, l: &Seen) -> Option<(f64, f64)> {
    let (g0, g1) = (ccw_from(r.pa, x.pa), ccw_from(x.pa, l.pa));
    // Twice the margin, so that it overlaps the intervals on either side by `EPS`.
    let m = 3.0 * EPS;
    let ok = g0 > m && g1 > m && g1 < l.back - m && g0 < r.fwd - m;
    ok.then_some((x.pa - 2.0 * EPS, x.pa + 2.0 * EPS))
}

/// The nearest sites clockwise and counter-clockwise of entry `i` whose directions are
/// more than `3 EPS` from its own: sites in the same direction (a grid's rows) are
/// skipped, so that the direction of a whole collinear run can die.
fn distinct_neighbours(around: &[Seen], i: usize) -> Option<(Seen, Seen)> {
    let (n, x) = (around.len(), around[i].pa);
    let (cw, ccw) = (around[(i + n - 1) % n], around[(i + 1) % n]);
    if ccw_from(cw.pa, x) > 3.0 * EPS && ccw_from(x, ccw.pa) > 3.0 * EPS {
        return Some((cw, ccw));
    }
    Some((
        first_apart(around, i, false)?,
        first_apart(around, i, true)?,
    ))
}

/// The first entry from `i` (counter-clockwise or clockwise) whose direction is more than
/// `3 EPS` from entry `i`'s. Walking away from `i` the gap grows, except that the entries
/// sharing `i`'s pseudo-angle met after going round come last (gap 0): they are left
/// out, and the rest is bisected (a scan would walk whole runs of one direction, such as
/// a scan line's row).
#[cold]
fn first_apart(around: &[Seen], i: usize, ccw: bool) -> Option<Seen> {
    let (n, x) = (around.len(), around[i].pa);
    let at = |k: usize| around[if ccw { (i + k) % n } else { (i + n - k) % n }];
    let apart = |k: usize| {
        let s = at(k).pa;
        (if ccw { ccw_from(x, s) } else { ccw_from(s, x) }) > 3.0 * EPS
    };
    let same = if ccw {
        i - around[..i].partition_point(|s| s.pa < x)
    } else {
        around[i + 1..].partition_point(|s| s.pa <= x)
    };
    let (mut a, mut b) = (1, n - same);
    while a < b {
        let m = (a + b) / 2;
        if apart(m) { b = m } else { a = m + 1 }
    }
    (a < n - same).then(|| at(a))
}

/// Closed pseudo-angle intervals, disjoint and sorted, within `[0, 4]`.
#[derive(Default)]
struct Directions(Vec<(f64, f64)>);

impl Directions {
    /// Calls `f` on `[lo, hi]` (`lo` in `[-4, 8)`, a width below 4) cut into parts in `[0, 4]`.
    fn parts(lo: f64, hi: f64, mut f: impl FnMut(f64, f64) -> bool) -> bool {
        let shift = if lo < 0.0 {
            -4.0
        } else if lo >= 4.0 {
            4.0
        } else {
            0.0
        };
        let (lo, hi) = (lo - shift, hi - shift);
        if hi > 4.0 {
            f(lo, 4.0) && f(0.0, hi - 4.0)
        } else {
            f(lo, hi)
        }
    }

    fn insert(&mut self, lo: f64, hi: f64) {
        Self::parts(lo, hi, |lo, hi| {
            let v = &mut self.0;
            let i = v.partition_point(|e| e.1 < lo);
            let j = v.partition_point(|e| e.0 <= hi);
            if i == j {
                v.insert(i, (lo, hi));
            } else {
                v[i] = (lo.min(v[i].0), hi.max(v[j - 1].1));
                v.drain(i + 1..j);
            }
            true
        });
    }

    fn covers(&self, lo: f64, hi: f64) -> bool {
        Self::parts(lo, hi, |lo, hi| {
            let i = self.0.partition_point(|e| e.0 <= lo);
            i > 0 && self.0[i - 1].1 >= hi
        })
    }

    fn full(&self) -> bool {
        self.0
            .first()
            .is_some_and(|&(lo, hi)| lo <= 0.0 && hi >= 4.0)
    }
}

/// Gathered sites `(squared distance, slot)`, nearest on top; the distance is kept as
/// its bits, which order non-negative floats as the floats.
type Pending = BinaryHeap<Reverse<(u64, u32)>>;

/// Per-thread scratch space.
#[derive(Default)]
struct Scratch {
    /// Visited sites by pseudo-angle.
    around: Vec<Seen>,
    /// Active dead directions.
    dead: Directions,
    /// Dead intervals `(activation distance, lo, hi)` not active yet, by activation.
    waiting: VecDeque<(f64, f64, f64)>,
    /// Gathered sites not visited yet.
    pending: Pending,
}

impl Scratch {
    fn reset(&mut self) {
        self.around.clear();
        self.dead.0.clear();
        self.waiting.clear();
        self.pending.clear();
        // More than `θ` behind the half-plane `x ≥ 0`: no partner, no blocker.
        let behind = (pseudo_angle(-13.0, 16.0), pseudo_angle(-13.0, -16.0));
        self.dead.insert(behind.0 + EPS, behind.1 - EPS);
    }

    /// Activates the dead intervals valid at distance `d`.
    fn activate(&mut self, d: f64) {
        while let Some(&(act, lo, hi)) = self.waiting.front() {
            if act > d {
                break;
            }
            self.waiting.pop_front();
            self.dead.insert(lo, hi);
        }
    }

    /// Adds a visited site at distance `d` (the farthest so far) and the dead directions
    /// it completes.
    fn add(&mut self, x: Seen, d: f64) {
        let i = self.around.partition_point(|s| s.pa < x.pa);
        self.around.insert(i, x);
        let n = self.around.len() as isize;
        if n < 2 {
            return;
        }
        let at = |k: isize| self.around[(i as isize + k).rem_euclid(n) as usize];
        let act = d * ACTIVATION;
        let mut found = [
            between(&at(-1), &at(0)),
            between(&at(0), &at(1)),
            None,
            None,
            None,
        ];
        if n >= 3 {
            for k in -1..=1 {
                let j = (i as isize + k).rem_euclid(n) as usize;
                found[(k + 3) as usize] = distinct_neighbours(&self.around, j)
                    .and_then(|(r, l)| through(&r, &self.around[j], &l));
            }
        }
        for (lo, hi) in found.into_iter().flatten() {
            self.waiting.push_back((act, lo, hi));
        }
    }
}

/// All candidate edges `[p, q]` (`p < q`) of distinct sites, sorted: the pairs with an
/// empty diamond and no site on the open segment (a few more pairs with both diamonds
/// occupied may be kept, never fewer; never a pair with a site on its open segment).
/// An error names coinciding sites or a coordinate outside the exact range.
///
/// ```
/// use tetrakit::planar::candidate_edges;
/// // The long diagonal 0-2 of this thin rhombus has a site deep in each diamond.
/// let pts = [[0.0, 0.0], [4.0, -1.0], [8.0, 0.0], [4.0, 1.0]];
/// let c = candidate_edges(&pts).unwrap();
/// assert!(c.contains(&[1, 3]) && !c.contains(&[0, 2]));
/// assert!(candidate_edges(&[[0.0, 0.0], [0.0, -0.0]]).is_err());
/// ```
pub fn candidate_edges(points: &[Point2]) -> Result<Vec<[u32; 2]>, PlanarError> {
    check_sites(points)?;
    search(points, super::MAX_CANDIDATES, &Control::new())
        .ok_or_else(|| super::too_many_candidates(points.len()))
}

/// [`candidate_edges`] for checked sites; `None` once there are more than `limit` (the
/// search stops there, before the list outgrows memory) or once `ctl` is stopped.
pub(super) fn search(points: &[Point2], limit: usize, ctl: &Control) -> Option<Vec<[u32; 2]>> {
    let grid = PointGrid::new(points, 2.0);
    let found = AtomicUsize::new(0);
    // Sites in cell order, so that consecutive searches share cached cells.
    let mut edges: Vec<[u32; 2]> = (0..points.len())
        .into_par_iter()
        .map_init(Scratch::default, |s, slot| {
            let mut out = Vec::new();
            if found.load(Relaxed) <= limit && !ctl.is_stopped() {
                candidates_of(slot, &grid, s, &mut out);
                found.fetch_add(out.len(), Relaxed);
            }
            out
        })
        .flatten_iter()
        .collect();
    if found.into_inner() > limit || ctl.is_stopped() {
        return None;
    }
    edges.par_sort_unstable();
    Some(edges)
}

/// The candidates of the site in grid slot `slot` with lexicographically larger sites.
/// Sites are handled by slot throughout (index and coordinates side by side in the grid).
fn candidates_of(slot: usize, grid: &PointGrid, s: &mut Scratch, out: &mut Vec<[u32; 2]>) {
    s.reset();
    let (index, coords) = grid.slots();
    let (p, pp) = (index[slot], coords[slot]);
    let (cx, cy) = grid.cell_of(&pp);
    for ring in 0usize.. {
        // Every cell of ring `r ≥ 1` is at least `(r - 1)` cells from `p`.
        s.activate(ring.saturating_sub(1) as f64 * grid.cell());
        let live = if ring < 2 {
            gather_ring(grid, slot, (cx, cy), ring, &mut s.pending);
            true
        } else {
            !s.dead.full() && gather_live(grid, &pp, (cx, cy), ring, s)
        };
        let exhausted = !live || grid.ring_covers_all((cx, cy), ring);
        // Every site closer than `ring` cells has been gathered, up to the rounding of
        // cell indices (under 10^-11 cells: at most 2^14 cells a side).
        let complete = if exhausted {
            f64::INFINITY
        } else {
            (ring as f64 - 1e-6) * grid.cell()
        };
        // A heap, not a sort: in a dense cluster a ring gathers many more sites than the
        // search visits before every direction is dead.
        while let Some(&Reverse((bits, qs))) = s.pending.peek() {
            let d2 = f64::from_bits(bits);
            if d2 >= complete * complete {
                break;
            }
            s.pending.pop();
            let d = d2.sqrt();
            s.activate(d);
            let pq = coords[qs as usize];
            let (dx, dy) = (pq[0] - pp[0], pq[1] - pp[1]);
            let x = Seen::new(dx, dy, qs);
            let partner = dx > 0.0 || (dx == 0.0 && dy > 0.0);
            if partner && !s.dead.covers(x.pa, x.pa) && open(&pp, &pq, coords, &s.around, &x) {
                out.push(edge_key(p, index[qs as usize]));
            }
            // A site with every direction within `θ` dead serves no later test (module
            // docs, "Sites left out").
            if !s
                .dead
                .covers(x.pa - x.back - 2.0 * EPS, x.pa + x.fwd + 2.0 * EPS)
            {
                s.add(x, d);
            }
            if s.dead.full() {
                return;
            }
        }
        if exhausted {
            break;
        }
    }
}

/// True when `pq` (`q` seen as `x`) has an empty diamond and no site on its open segment
/// among the visited sites `around`, which include every site that could be in either.
fn open(pp: &Point2, pq: &Point2, coords: &[Point2], around: &[Seen], x: &Seen) -> bool {
    let n = around.len();
    let start = around.partition_point(|s| s.pa < x.pa - EPS);
    // `hits`: a visited site in the left, in the right diamond.
    let blocked = |k: usize, hits: &mut (bool, bool)| {
        let h = diamond_hit(pp, pq, &coords[around[k % n].slot as usize]);
        hits.0 |= h.left;
        hits.1 |= h.right;
        h.on_segment || (hits.0 && hits.1)
    };
    let mut hits = (false, false);
    // Counter-clockwise: the sites within `θ` of `q`'s direction (and those within the
    // margin clockwise of it): the only ones that can be in the left diamond. Past the
    // first hit outside the margins around `q`'s direction, the rest are left of `pq`
    // (whose test is skipped: keeping a pair is always safe). Inside the margins the
    // scan goes on: a site on the open segment may sort after one just left of it.
    for k in start..start + n {
        let from = ccw_from(x.pa - EPS, around[k % n].pa);
        if from > x.fwd + 2.0 * EPS {
            break;
        }
        if blocked(k, &mut hits) {
            return false;
        }
        if hits.0 && from > 2.0 * EPS {
            break;
        }
    }
    if !hits.0 {
        return true;
    }
    for k in (start..start + n).rev() {
        if ccw_from(around[k % n].pa, x.pa + EPS) > x.back + 2.0 * EPS {
            break;
        }
        if blocked(k, &mut hits) {
            return false;
        }
    }
    true
}

/// The pseudo-angles `(lo, hi)` of the directions from `p` into the box `[lo, hi]`, which
/// does not contain `p` (`hi` may pass 4).
fn directions_of_box(pp: &Point2, (lo, hi): (Point2, Point2)) -> (f64, f64) {
    let (x0, x1, y0, y1) = (lo[0] - pp[0], hi[0] - pp[0], lo[1] - pp[1], hi[1] - pp[1]);
    let c = [
        pseudo_angle(x0, y0),
        pseudo_angle(x1, y0),
        pseudo_angle(x0, y1),
        pseudo_angle(x1, y1),
    ];
    if x0 > 0.0 && y0 < 0.0 && y1 >= 0.0 {
        // Across the direction 0: from the lower corners to the upper ones, past 4.
        (c[0].min(c[1]), c[2].max(c[3]) + 4.0)
    } else {
        let lo = c.iter().copied().fold(f64::INFINITY, f64::min);
        (lo, c.iter().copied().fold(0.0, f64::max))
    }
}

/// Pushes the sites of the ring-`r` cells (`r ≥ 2`) inside the grid whose directions are
/// not all dead; returns whether there was such a cell.
fn gather_live(
    grid: &PointGrid,
    pp: &Point2,
    (cx, cy): (usize, usize),
    r: usize,
    s: &mut Scratch,
) -> bool {
    let mut live = false;
    grid.for_ring((cx, cy), r, |x, y| {
        // An empty cell matters only until the ring is known to be live.
        let empty = grid.cell_slots(x, y).is_empty();
        if live && empty {
            return;
        }
        let (lo, hi) = directions_of_box(pp, grid.cell_box(x, y));
        if !s.dead.covers(lo - EPS, hi + EPS) {
            live = true;
            if !empty {
                push_cell(grid, pp, x, y, usize::MAX, &mut s.pending);
            }
        }
    });
    live
}

/// Pushes the sites of cell `(x, y)` except `skip`.
fn push_cell(
    grid: &PointGrid,
    pp: &Point2,
    x: usize,
    y: usize,
    skip: usize,
    pending: &mut Pending,
) {
    let coords = grid.slots().1;
    for q in grid.cell_slots(x, y).filter(|&q| q != skip) {
        let a = coords[q];
        let (ex, ey) = (a[0] - pp[0], a[1] - pp[1]);
        pending.push(Reverse(((ex * ex + ey * ey).to_bits(), q as u32)));
    }
}

/// Pushes the sites in ring `r` around cell `(cx, cy)`, except the one in `slot`.
fn gather_ring(grid: &PointGrid, slot: usize, c: (usize, usize), r: usize, pending: &mut Pending) {
    let pp = grid.slots().1[slot];
    grid.for_ring(c, r, |x, y| push_cell(grid, &pp, x, y, slot, pending));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planar::{Distribution, points2d};

    /// The bisection in `distinct_neighbours` finds what a scan from the entry finds, on
    /// sorted lists with runs of one direction, across the wrap at pseudo-angle 4.
    #[test]
    fn distinct_neighbours_match_a_scan() {
        let scan = |around: &[Seen], i: usize| {
            let (n, x, apart) = (around.len(), around[i].pa, 3.0 * EPS);
            let cw = (1..n)
                .map(|k| around[(i + n - k) % n])
                .find(|s| ccw_from(s.pa, x) > apart)?;
            let ccw = (1..n)
                .map(|k| around[(i + k) % n])
                .find(|s| ccw_from(x, s.pa) > apart)?;
            Some((cw.slot, ccw.slot))
        };
        let mut rng = crate::rng::Rng::new(8);
        let mut runs = 0;
        for _ in 0..3000 {
            // A few directions (near 0, near 4, anywhere), each a run of entries at most
            // a margin apart.
            let dirs: Vec<f64> = (0..1 + rng.below(4))
                .map(|_| match rng.below(3) {
                    0 => rng.below(3) as f64 * EPS,
                    1 => 4.0 - (1 + rng.below(3)) as f64 * EPS,
                    _ => rng.unit() * 4.0,
                })
                .collect();
            let mut around: Vec<Seen> = (0..1 + rng.below(12))
                .map(|k| Seen {
                    pa: (dirs[rng.below(dirs.len())] + rng.below(3) as f64 * EPS).min(4.0 - EPS),
                    back: 0.0,
                    fwd: 0.0,
                    slot: k as u32,
                })
                .collect();
            around.sort_by(|a, b| a.pa.total_cmp(&b.pa));
            for i in 0..around.len() {
                let got = distinct_neighbours(&around, i).map(|(a, b)| (a.slot, b.slot));
                assert_eq!(got, scan(&around, i), "{i} in {:?}", around);
                runs += usize::from(got.is_some());
            }
        }
        assert!(runs > 3000, "{runs}");
    }

    #[test]
    fn directions_merge_and_wrap() {
        let mut d = Directions::default();
        d.insert(3.5, 4.25); // wraps: [3.5, 4] and [0, 0.25]
        assert!(d.covers(3.9, 4.1) && d.covers(0.0, 0.25) && !d.covers(0.0, 0.3));
        d.insert(1.0, 2.0);
        d.insert(2.0, 3.0); // touching closed intervals merge
        assert!(d.covers(1.5, 2.5) && !d.full());
        d.insert(0.25, 1.0);
        assert!(!d.full() && !d.covers(3.0, 3.5));
        d.insert(7.0, 7.5); // the same as [3, 3.5]
        assert!(d.full() && d.0.len() == 1);
    }

    /// The widths of `θ` around a direction match the rotations by `atan(13/16)`.
    #[test]
    fn theta_widths_match_the_angle() {
        let theta = (13.0f64 / 16.0).atan();
        for i in 0..720 {
            let a = i as f64 * std::f64::consts::TAU / 720.0 + 1e-3;
            let s = Seen::new(a.cos(), a.sin(), 0);
            let (b, c) = (a - theta, a + theta);
            let want_back = ccw_from(pseudo_angle(b.cos(), b.sin()), s.pa);
            let want_fwd = ccw_from(s.pa, pseudo_angle(c.cos(), c.sin()));
            assert!((s.back - want_back).abs() < 1e-12, "{a}");
            assert!((s.fwd - want_fwd).abs() < 1e-12, "{a}");
        }
        assert!((2.0 * theta.cos() * 1.001 - ACTIVATION).abs() < 1e-12);
    }

    /// The directions into a cell's box contain the direction of every point of it.
    #[test]
    fn box_directions_contain_their_points() {
        let mut rng = crate::rng::Rng::new(5);
        for _ in 0..2000 {
            let (x, y) = ((rng.unit() - 0.5) * 20.0, (rng.unit() - 0.5) * 20.0);
            let (w, h) = (rng.unit(), rng.unit());
            if x <= 0.0 && x + w >= 0.0 && y <= 0.0 && y + h >= 0.0 {
                continue;
            }
            let (lo, hi) = directions_of_box(&[0.0, 0.0], ([x, y], [x + w, y + h]));
            assert!(hi - lo < 2.0);
            for _ in 0..20 {
                let a = pseudo_angle(x + rng.unit() * w, y + rng.unit() * h);
                let a = if a < lo { a + 4.0 } else { a };
                assert!(
                    lo <= a && a <= hi,
                    "{x} {y} {w} {h}: {a} not in [{lo}, {hi}]"
                );
            }
        }
    }

    /// Many sites share a direction from many others: sites on rays from a centre and on
    /// a few long lines (equal pseudo-angles, sites on segments).
    #[test]
    fn search_is_complete_on_rays_and_lines() {
        let mut pts: Vec<Point2> = vec![[0.0, 0.0]];
        for k in 0..12 {
            let (dx, dy) = [(1, 0), (3, 1), (1, 1), (1, 3), (0, 1), (-2, 1)][k % 6];
            let s = if k < 6 { 1.0 } else { -1.0 };
            pts.extend((1..=15).map(|i| [s * (dx * i) as f64, s * (dy * i) as f64]));
        }
        let mut rng = crate::rng::Rng::new(9);
        pts.extend((0..60).map(|i| [(i % 20) as f64 * 2.0 - 20.0, 37.0 + (i / 20) as f64]));
        pts.extend((0..80).map(|_| [rng.unit() * 60.0 - 30.0, rng.unit() * 60.0 - 30.0]));
        pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
        pts.dedup();
        assert_eq!(missing_candidates(&pts), 0);
    }

    /// A site `q` almost behind `x` as seen from `p`: `x` blocks one diamond of `pq`, and
    /// the other is open because `l`, 42° away, is beyond `θ`. The direction of `x` must
    /// stay live (only both neighbours within `θ` kill it).
    #[test]
    fn a_direction_through_a_site_needs_both_neighbours() {
        let a = 42f64.to_radians();
        let pts = [
            [0.0, 0.0],
            [1.0, 0.0],
            [10.0, 1e-10],
            [1.2 * a.cos(), 1.2 * a.sin()],
            [1.0, -0.1],
        ];
        assert!(brute(&pts).contains(&[0, 2]));
        assert_eq!(missing_candidates(&pts), 0);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]
        /// Small integer lattices (collinear and cocircular sites everywhere, many sites
        /// in one direction), sheared and scaled: the search keeps every candidate.
        #[test]
        fn search_is_complete_on_sheared_lattices(
            sites in proptest::collection::hash_set((0i32..9, 0i32..9), 3..60),
            shear in -3i32..=3,
            scale in proptest::prop_oneof![proptest::strategy::Just(1.0f64), 1e-3f64..1e3],
        ) {
            let pts: Vec<Point2> = (sites.iter())
                .map(|&(x, y)| [(x + shear * y) as f64 * scale, y as f64 * scale])
                .collect();
            proptest::prop_assert_eq!(missing_candidates(&pts), 0);
        }
    }

    /// Thin strips and a set hugging the edges of its box: almost every site sees the
    /// edge along some sector, where the kills by the sector's own sites cut the cone.
    #[test]
    fn search_is_complete_where_cones_run_along_edges() {
        let mut rng = crate::rng::Rng::new(11);
        let strip: Vec<Point2> = (0..500)
            .map(|_| [rng.unit() * 1000.0, rng.unit()])
            .collect();
        let slanted: Vec<Point2> = (0..400)
            .map(|_| {
                let t = rng.unit() * 100.0;
                [t, 0.37 * t + rng.unit()]
            })
            .collect();
        let rim: Vec<Point2> = (0..500)
            .map(|i| {
                let t = rng.unit();
                let e = rng.unit() * 1e-3;
                match i % 4 {
                    0 => [t, e],
                    1 => [1.0 - e, t],
                    2 => [t, 1.0 - e],
                    _ => [e, t],
                }
            })
            .collect();
        for (name, pts) in [("strip", strip), ("slanted", slanted), ("rim", rim)] {
            assert_eq!(missing_candidates(&pts), 0, "{name}");
        }
    }

    /// Sites on the rays of a floating-point polar grid tie in pseudo-angle with sites
    /// just off their ray (a site on `pq` sorted after one in its left diamond): no
    /// candidate may pass through a site, and none may be missed.
    #[test]
    fn no_candidate_passes_through_a_site_on_polar_grids() {
        for (rings, rays) in [(5, 20), (10, 40), (6, 30)] {
            let pts: Vec<Point2> = (1..=rings)
                .flat_map(|r| {
                    (0..rays).map(move |k| {
                        let a = std::f64::consts::TAU * k as f64 / rays as f64;
                        [r as f64 * a.cos(), r as f64 * a.sin()]
                    })
                })
                .collect();
            assert_eq!(missing_candidates(&pts), 0, "{rings} x {rays}");
            let through = |e: &&[u32; 2]| {
                let (p, q) = (&pts[e[0] as usize], &pts[e[1] as usize]);
                pts.iter().any(|r| diamond_hit(p, q, r).on_segment)
            };
            assert_eq!(
                search(&pts, usize::MAX, &Control::new())
                    .unwrap()
                    .iter()
                    .filter(through)
                    .count(),
                0,
                "{rings} x {rays}"
            );
        }
    }

    /// The brute-force candidate set: every pair with an empty diamond and no site on it.
    fn brute(points: &[Point2]) -> Vec<[u32; 2]> {
        let n = points.len() as u32;
        let mut out = Vec::new();
        for a in 0..n {
            for b in a + 1..n {
                let (mut l, mut r, mut on) = (false, false, false);
                for c in 0..n {
                    if c != a && c != b {
                        let h = diamond_hit(
                            &points[a as usize],
                            &points[b as usize],
                            &points[c as usize],
                        );
                        l |= h.left;
                        r |= h.right;
                        on |= h.on_segment;
                    }
                }
                if !(on || (l && r)) {
                    out.push([a, b]);
                }
            }
        }
        out
    }

    /// How many brute-force candidates the search misses.
    fn missing_candidates(pts: &[Point2]) -> usize {
        let (got, want) = (
            search(pts, usize::MAX, &Control::new()).unwrap(),
            brute(pts),
        );
        want.iter()
            .filter(|e| got.binary_search(e).is_err())
            .count()
    }

    /// The search's floating-point bounds at the ends of the exact range: tiny and huge
    /// scales, a large offset (few significant bits left for the spread), and ties.
    #[test]
    fn search_is_complete_at_the_ends_of_the_exact_range() {
        let sets = [
            points2d(Distribution::Uniform, 300, 5),
            points2d(Distribution::Grid, 225, 5),
            points2d(Distribution::Regular, 40, 5),
            points2d(Distribution::Clustered, 300, 5),
        ];
        let transforms = [
            (2f64.powi(-120), 0.0),
            (2f64.powi(190), 0.0),
            (1.0, 2f64.powi(24)),
            (2f64.powi(-100), -(2f64.powi(-80))),
        ];
        let mut tested = 0;
        for (i, base) in sets.iter().enumerate() {
            for &(scale, shift) in &transforms {
                let pts: Vec<Point2> = base.iter().map(|p| p.map(|x| x * scale + shift)).collect();
                if check_sites(&pts).is_err() {
                    continue; // a coordinate fell below 2^-142, or two sites merged
                }
                let missing = missing_candidates(&pts);
                assert_eq!(missing, 0, "set {i}, scale {scale:e}, shift {shift:e}");
                tested += 1;
            }
        }
        assert!(
            tested >= 12,
            "only {tested} of 16 transformed sets were in range"
        );
    }

    #[test]
    fn bad_sites_are_named() {
        let err = candidate_edges(&[[1.0, 2.0], [3.0, 4.0], [1.0, 2.0]]).unwrap_err();
        assert_eq!(
            err,
            PlanarError::CoincidentSites {
                sites: [0, 2],
                point: [1.0, 2.0]
            }
        );
        let err = candidate_edges(&[[1.0, 2.0], [1e-300, 4.0]]).unwrap_err();
        assert!(
            matches!(err, PlanarError::CoordinateOutOfRange { site: 1, .. }),
            "{err}"
        );
    }

    #[test]
    fn search_keeps_every_candidate_of_brute_force() {
        for (dist, n) in [
            (Distribution::Uniform, 600),
            (Distribution::Clustered, 500),
            (Distribution::Gaussian, 500),
            (Distribution::Grid, 400),
        ] {
            let pts = points2d(dist, n, 3);
            let got = search(&pts, usize::MAX, &Control::new()).unwrap();
            let want = brute(&pts);
            let missing: Vec<_> = want
                .iter()
                .filter(|e| got.binary_search(e).is_err())
                .collect();
            assert!(missing.is_empty(), "{dist:?}: missing {missing:?}");
            // Extra edges are sound but should be rare.
            assert!(
                got.len() <= want.len() + want.len() / 20,
                "{dist:?}: {} vs {}",
                got.len(),
                want.len()
            );
        }
    }
}
