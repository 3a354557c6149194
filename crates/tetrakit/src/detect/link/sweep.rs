//! The sphere sweep of thesis §2.4.2 (CHECK-CLOSED-TRIANGULATION, UPDATE-STATUS,
//! DELETE-SEGMENT), exact and without the general-position assumption: which segments of
//! `L_v` survive the puncture rule of [`link`](super::link), with `O(|L_v| log |L_v|)`
//! exact predicates. It replaces the `O(|L_v|·(|N(v)| + |L_v|))` sign table on large links
//! (the skew-lines family, where `|N(v)|` and `|L_v|` grow with `n`).
//!
//! Seen from `v`, every segment `ab` of `L_v` is an arc of a great circle shorter than a
//! half circle. Every test below is an `orient3d` with apex `v` on input points and two
//! auxiliary points — nothing is projected, no intersection point is constructed:
//!
//! - **Poles and seam.** A north pole `Y` and a seam point `R` (floating-point points
//!   near `v`, tried in a fixed pseudo-random sequence) are accepted only when exact tests
//!   show that no neighbour lies on the plane `vYR` (so none is on the polar axis or on the
//!   seam meridian or its opposite) and no segment lies in a plane through the axis
//!   (`orient3d(v, Y, a, b) ≠ 0`, so no arc is part of a meridian or passes through a
//!   pole). A segment whose plane contains every axis has `v` inside it: a witness.
//! - **Longitudes.** `orient3d(v, Y, R, a) > 0` puts `a` in the open half `(0, π)` of
//!   longitudes, `< 0` in `(π, 2π)`; within a half, `b` is east of `a` when
//!   `orient3d(v, Y, a, b) > 0`. Points on one meridian are swept south to north (a
//!   slightly tilted meridian): `a` is north of `b` when `orient3d(v, b, a, R)` has the
//!   sign of the side of that meridian on which `R` lies (west for the first half).
//! - **Arcs.** Each arc runs from its west end to its east end
//!   (`orient3d(v, Y, west, east) > 0`); a point `c` is north of it when
//!   `orient3d(v, west, east, c) > 0`; two arcs leaving `c` eastwards are ordered by
//!   `orient3d(v, c, x, y)`. Arcs are monotone in longitude and two of them cross at most
//!   once, so the status (the arcs met by the sweeping meridian, south to north) behaves
//!   as in a plane sweep.
//!
//! **Deletions.** Every pair of arcs that becomes adjacent in the status (by an insertion,
//! the end of an arc, or a deletion) is tested; two arcs that cross are two segments of
//! which one punctures the other's triangle with `v` (one exact `orient3d(a, b, c, d)`
//! says which, or that they meet: a witness), and the punctured one is deleted
//! (DELETE-SEGMENT). An event point `c` found exactly on an arc of the status punctures it
//! with `vc`; of two arcs leaving `c` in one direction the longer is punctured by the
//! shorter one's end. Every deletion removes a punctured segment, so link edges survive;
//! and since adjacent arcs are always tested, two adjacent arcs of the status never cross
//! and the status order stays exact. At the end no two kept arcs cross and no point lies
//! on a kept arc: the kept segments are a plane graph on the sphere containing the link,
//! hence equal to it (for the edge set of a tetrahedralization; otherwise the face checks
//! that follow reject it, and a YES is verified independently anyway).
//!
//! **The seam** (the thesis's second pass). The sweep starts at longitude 0 with an empty
//! status. An arc whose west end lies in `(π, 2π)` and east end in `(0, π)` crosses the
//! seam: it is still in the status when the first lap ends, in its exact position. A
//! second lap over the points of `(0, π)` takes the arcs out at their east ends and
//! inserts the kept arcs of those points again, so every pair of arcs that cross, on
//! either side of the seam, is adjacent at some moment of one of the two laps (arcs are
//! shorter than a half turn, so a seam-crossing arc ends before longitude π).
//!
//! The status is a sorted vector: `O(log s)` exact comparisons per search, while the
//! insertions and removals shift machine words (`O(s)` each, for a status of `s` arcs).

use super::{LocalView, crossing};
use crate::detect::{Witness, WitnessKind};
use crate::geom::{Dir, Point3, collinear3};
use crate::rng::Rng;
use std::cmp::Ordering;

/// Attempts at a pole and seam before giving up (a random choice fails with probability
/// zero; the attempts only guard against adversarial input).
const POLE_ATTEMPTS: u64 = 8;

/// Runs the sweep on the segments `edges` of `L_v` (local indices, all kept on entry) and
/// clears `keep` for the punctured ones. `Ok(false)`: no valid pole was found and `keep`
/// is untouched (the caller uses the sign table instead).
pub(super) fn puncture_free_by_sweep(
    lv: &LocalView,
    edges: &[(u32, u32)],
    keep: &mut [bool],
    buffers: &mut Buffers,
) -> Result<bool, Witness> {
    let mut sweep = Sweep {
        lv,
        keep,
        b: buffers,
    };
    if !sweep.prepare(edges)? {
        return Ok(false);
    }
    let order = std::mem::take(&mut sweep.b.order);
    for &c in &order {
        sweep.event(c)?;
    }
    let first_half = order.partition_point(|&c| sweep.b.half[c as usize] == 0);
    for &c in &order[..first_half] {
        sweep.event(c)?;
    }
    sweep.b.order = order;
    Ok(true)
}

/// Scratch space of the sweep, reused from one vertex to the next.
#[derive(Default)]
pub(super) struct Buffers {
    /// The neighbours of `v`, then the pole `Y` and the seam point `R`.
    p: Vec<Point3>,
    d: Vec<Dir>,
    /// West and east end of each arc (local indices).
    west: Vec<u32>,
    east: Vec<u32>,
    /// Per neighbour: 0 for longitudes in `(0, π)`, 1 for `(π, 2π)`.
    half: Vec<u8>,
    /// The arcs leaving each neighbour eastwards, south to north (CSR rows).
    start: Vec<u32>,
    fill: Vec<u32>,
    leaving: Vec<u32>,
    /// Arcs met by the sweeping meridian, south to north.
    status: Vec<u32>,
    /// The neighbours in sweep order, and their rounded longitudes.
    order: Vec<u32>,
    rough: Vec<f64>,
}

struct Sweep<'a, 'k> {
    lv: &'a LocalView<'a>,
    keep: &'k mut [bool],
    b: &'k mut Buffers,
}

impl Sweep<'_, '_> {
    /// Poles, arcs, rows of leaving arcs and the event order; `false` when no pole fits.
    fn prepare(&mut self, edges: &[(u32, u32)]) -> Result<bool, Witness> {
        let k = self.lv.p.len();
        self.b.p.clear();
        self.b.p.extend_from_slice(self.lv.p);
        self.b.d.clear();
        self.b.d.extend_from_slice(self.lv.d);
        if !self.choose_poles(edges)? {
            return Ok(false);
        }
        self.leaving_rows(k);
        self.event_order(k);
        self.b.status.clear();
        Ok(true)
    }

    /// Exact `orient3d(v, a, b, c)` on local indices (neighbours, then `Y`, then `R`).
    #[inline]
    fn o(&self, a: usize, b: usize, c: usize) -> i8 {
        let (p, d) = (&self.b.p, &self.b.d);
        self.lv.frame.sign(&p[a], &p[b], &p[c], &d[a], &d[b], &d[c])
    }

    /// Picks `Y` and `R` (appended to `p`, `d`) so that no neighbour is on the plane
    /// `vYR` and no segment is in a plane through the axis `vY`; records each neighbour's
    /// half and each arc's west and east end on the way.
    fn choose_poles(&mut self, edges: &[(u32, u32)]) -> Result<bool, Witness> {
        let lv = self.lv;
        let k = lv.p.len();
        let scale =
            lv.d.iter()
                .flat_map(|x| x.d)
                .fold(0.0f64, |m, x| m.max(x.abs()));
        let scale = if scale > 0.0 && scale.is_finite() {
            scale
        } else {
            1.0
        };
        let mut rng = Rng::new(u64::from(lv.v));
        'attempt: for _ in 0..POLE_ATTEMPTS {
            let mut point = || -> Point3 {
                std::array::from_fn(|i| lv.pv[i] + scale * (2.0 * rng.unit() - 1.0))
            };
            let (y, r) = (point(), point());
            self.b.p.truncate(k);
            self.b.d.truncate(k);
            self.b.p.extend([y, r]);
            self.b.d.extend([lv.frame.dir(&y), lv.frame.dir(&r)]);
            self.b.half.clear();
            for a in 0..k {
                match self.o(k, k + 1, a) {
                    0 => continue 'attempt,
                    s => self.b.half.push(u8::from(s < 0)),
                }
            }
            self.b.west.clear();
            self.b.east.clear();
            for &(a, b) in edges {
                let (w, e) = match self.o(k, a as usize, b as usize) {
                    1 => (a, b),
                    -1 => (b, a),
                    _ if collinear3(lv.pv, &lv.p[a as usize], &lv.p[b as usize]) => {
                        // Not on one ray (checked before), so v lies inside segment ab.
                        let (ga, gb) = (lv.g(a), lv.g(b));
                        return Err(Witness::new(
                            WitnessKind::VertexOnSegment,
                            vec![lv.v, ga, gb],
                            vec![[ga, gb]],
                            format!("vertex #{} lies inside segment (#{ga}, #{gb})", lv.v),
                        ));
                    }
                    _ => continue 'attempt,
                };
                self.b.west.push(w);
                self.b.east.push(e);
            }
            return Ok(true);
        }
        Ok(false)
    }

    /// The arcs leaving each point eastwards, sorted south to north; of arcs leaving in
    /// one direction only the shortest is kept (its east end punctures the others).
    fn leaving_rows(&mut self, k: usize) {
        let b = &mut *self.b;
        b.start.clear();
        b.start.resize(k + 1, 0);
        for &w in &b.west {
            b.start[w as usize + 1] += 1;
        }
        for i in 0..k {
            b.start[i + 1] += b.start[i];
        }
        b.fill.clear();
        b.fill.extend_from_slice(&b.start[..k]);
        b.leaving.clear();
        b.leaving.resize(b.west.len(), 0);
        for (x, &w) in b.west.iter().enumerate() {
            b.leaving[b.fill[w as usize] as usize] = x as u32;
            b.fill[w as usize] += 1;
        }
        let mut leaving = std::mem::take(&mut self.b.leaving);
        for c in 0..k {
            let row = &mut leaving[self.b.start[c] as usize..self.b.start[c + 1] as usize];
            if row.len() > 1 {
                row.sort_unstable_by(|&x, &y| self.direction_cmp(c, x, y));
                self.shortest_per_direction(c, row);
            }
        }
        self.b.leaving = leaving;
    }

    /// Of arcs leaving `c` in one direction (adjacent in the sorted `row`), keeps the one
    /// with the westmost east end: that end punctures the others.
    fn shortest_per_direction(&mut self, c: usize, row: &[u32]) {
        let y = self.lv.p.len();
        let mut i = 0;
        while i < row.len() {
            let mut j = i + 1;
            let mut best = row[i];
            while j < row.len() && self.direction_cmp(c, row[i], row[j]).is_eq() {
                let (eb, ej) = (self.b.east[best as usize], self.b.east[row[j] as usize]);
                let dead = if self.o(y, eb as usize, ej as usize) > 0 {
                    row[j]
                } else {
                    std::mem::replace(&mut best, row[j])
                };
                self.keep[dead as usize] = false;
                j += 1;
            }
            i = j;
        }
    }

    /// South-to-north order of two arcs leaving `c` eastwards.
    fn direction_cmp(&self, c: usize, x: u32, y: u32) -> Ordering {
        let (ex, ey) = (self.b.east[x as usize], self.b.east[y as usize]);
        self.o(c, ex as usize, ey as usize).cmp(&0).reverse()
    }

    /// The neighbours in sweep order: by half, then west to east, then south to north.
    /// A floating-point longitude proposes the order and the exact comparison certifies
    /// each consecutive pair (one test per neighbour); any doubt sorts exactly.
    fn event_order(&mut self, k: usize) {
        let mut order = std::mem::take(&mut self.b.order);
        let mut longitude = std::mem::take(&mut self.b.rough);
        self.rough_longitudes(k, &mut longitude);
        order.clear();
        order.extend(0..k as u32);
        order.sort_unstable_by(|&a, &b| longitude[a as usize].total_cmp(&longitude[b as usize]));
        let cmp = |a: &u32, b: &u32| self.event_cmp(k, *a as usize, *b as usize);
        if order
            .windows(2)
            .any(|w| cmp(&w[0], &w[1]) != Ordering::Less)
        {
            order.sort_by(cmp);
        }
        self.b.order = order;
        self.b.rough = longitude;
    }

    /// The exact sweep order of two neighbours.
    fn event_cmp(&self, k: usize, a: usize, b: usize) -> Ordering {
        let (y, r, half) = (k, k + 1, &self.b.half);
        half[a].cmp(&half[b]).then_with(|| match self.o(y, a, b) {
            1 => Ordering::Less,
            -1 => Ordering::Greater,
            // One meridian: R is west of it in the first half, east in the second.
            _ => {
                let north = self.o(b, a, r) * if half[a] == 0 { 1 } else { -1 };
                north.cmp(&0)
            }
        })
    }

    /// A monotone stand-in for each neighbour's longitude, in `[0, 4)`, rounded (a guess
    /// for the order; never trusted).
    fn rough_longitudes(&self, k: usize, out: &mut Vec<f64>) {
        let (yd, rd) = (self.b.d[k].d, self.b.d[k + 1].d);
        let dot = |a: &Point3, b: &Point3| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let t = dot(&rd, &yd) / dot(&yd, &yd);
        let u: Point3 = std::array::from_fn(|i| rd[i] - t * yd[i]);
        let w = [
            yd[1] * u[2] - yd[2] * u[1],
            yd[2] * u[0] - yd[0] * u[2],
            yd[0] * u[1] - yd[1] * u[0],
        ];
        out.clear();
        out.extend(self.b.d[..k].iter().map(|d| {
            let (x, y) = (dot(&d.d, &u), dot(&d.d, &w));
            let s = x.abs() + y.abs();
            let (x, y) = if s > 0.0 { (x / s, y / s) } else { (1.0, 0.0) };
            match (y >= 0.0, x >= 0.0) {
                (true, true) => y,
                (true, false) => 1.0 - x,
                (false, false) => 2.0 - y,
                (false, true) => 3.0 + x,
            }
        }));
    }

    /// Sign of "`c` is north of arc `x`" at `c`'s meridian (0: on it, or an end of it).
    fn north_of(&self, c: u32, x: u32) -> i8 {
        let (w, e) = (self.b.west[x as usize], self.b.east[x as usize]);
        if w == c || e == c {
            return 0;
        }
        self.o(w as usize, e as usize, c as usize)
    }

    /// UPDATE-STATUS at point `c`.
    fn event(&mut self, c: u32) -> Result<(), Witness> {
        let pos = self.b.status.partition_point(|&x| self.north_of(c, x) > 0);
        let mut end = pos;
        while end < self.b.status.len() && self.north_of(c, self.b.status[end]) == 0 {
            let x = self.b.status[end] as usize;
            if self.b.east[x] != c {
                // c lies inside the arc: vc punctures the segment's triangle with v.
                self.keep[x] = false;
            }
            end += 1;
        }
        let b = &mut *self.b;
        b.status.drain(pos..end);
        let row = &b.leaving[b.start[c as usize] as usize..b.start[c as usize + 1] as usize];
        let before = b.status.len();
        let keep = &*self.keep;
        b.status
            .splice(pos..pos, row.iter().copied().filter(|&x| keep[x as usize]));
        if self.b.status.len() == before {
            self.settle(pos)?;
            return Ok(());
        }
        let low = self.settle(pos)?;
        let mut top = low;
        while top < self.b.status.len() && self.b.west[self.b.status[top] as usize] == c {
            top += 1;
        }
        if top > low {
            self.settle(top)?;
        }
        Ok(())
    }

    /// Tests the adjacent arcs at positions `i − 1` and `i`, deleting punctured ones until
    /// the pair there does not cross (HANDLE-ABOVE/BELOW-SEGMENTS); returns the final `i`.
    fn settle(&mut self, mut i: usize) -> Result<usize, Witness> {
        while i > 0 && i < self.b.status.len() {
            let (lo, hi) = (self.b.status[i - 1], self.b.status[i]);
            let Some(dead) = self.punctured(lo, hi)? else {
                break;
            };
            self.keep[dead as usize] = false;
            if dead == lo {
                self.b.status.remove(i - 1);
                i -= 1;
            } else {
                self.b.status.remove(i);
            }
        }
        Ok(i)
    }

    /// DELETE-SEGMENT: when arcs `x` and `y` cross, the one whose segment is punctured by
    /// the other; segments that meet are a witness.
    fn punctured(&self, x: u32, y: u32) -> Result<Option<u32>, Witness> {
        let (a, b) = (self.b.west[x as usize], self.b.east[x as usize]);
        let (c, d) = (self.b.west[y as usize], self.b.east[y as usize]);
        if a == c || a == d || b == c || b == d {
            return Ok(None);
        }
        let (ua, ub, uc, ud) = (a as usize, b as usize, c as usize, d as usize);
        let (sc, sd) = (self.o(ua, ub, uc), self.o(ua, ub, ud));
        if sc * sd >= 0 {
            return Ok(None);
        }
        let (sa, sb) = (self.o(uc, ud, ua), self.o(uc, ud, ub));
        // Opposite signs: the great circles meet at ±X and the arcs at different points.
        if sa * sb >= 0 || sd != sa {
            return Ok(None);
        }
        Ok(match crossing(self.lv, (a, b), (c, d), sa, sc)? {
            Some(true) => Some(x),
            Some(false) => Some(y),
            None => None,
        })
    }
}
