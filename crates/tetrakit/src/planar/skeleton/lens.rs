//! The β-skeleton for β < 1 (thesis ch. 5, §5.1's circle-based region, which for β < 1
//! is a lens and the same as the lune-based one): a search around each site whose cost
//! follows the skeleton's size, not the `n²/2` pairs.
//!
//! **The cone of a site.** Let `φ = arcsin β`. The region of `pq` is
//! `{r : ∠prq > π − φ}`, a lens inside the diametral disk, so a site `r` in it is
//! strictly closer to `p` than `q` is. Seen from `p`, the sites `q` whose lens holds `r`
//! form an open cone: `∠prq > π − φ` iff the angle between `r − p` and `q − r` is less
//! than `φ`, so `q` must lie in the cone with apex `r`, axis `r − p` and half-angle `φ`.
//!
//! **Dead directions.** Take `q` at distance `ρ > d = |pr|` from `p`, in a direction at
//! angle `δ` from `r`'s. In the triangle `prq` the exterior angle at `r` is `δ + γ`,
//! where `γ`, the angle at `q`, is acute (it faces the shorter side `pr`) and has
//! `sin γ = d sin δ / |rq| ≤ d / (ρ − d)`. So when `δ ≤ δ₀ < φ` and
//! `ρ ≥ d (1 + 1 / sin(φ − δ₀))`, `q` is in the cone: every direction within `δ₀` of
//! `r`'s is *dead* beyond that distance, and no site there is a neighbour of `p`.
//!
//! **The search.** The circle of directions around `p` is cut into sectors. Each site
//! `r` the search gathers (ring by ring of grid cells, nearest rings first) lowers the
//! activation distance of every sector it covers, computed from the sector's farthest
//! direction from `r`'s; a sector that points out of the sites' bounding box is dead
//! beyond the box. Once every sector is dead within the radius the rings have
//! completed, no site further out can be a neighbour and the search of `p` stops.
//!
//! **Exact decisions.** Floating point only proposes: the sector bounds carry margins
//! (a millionth of the cone angle and a billionth of the distance), so stopping never
//! drops a neighbour. A gathered site `q` is decided only once every site closer to `p`
//! has been gathered: it is rejected when the site that killed its sector is in its lens
//! ([`in_beta_region`], exact), and otherwise tested exactly against every gathered site
//! that may be closer, lies within `φ` of its direction, and may be in the lens by a
//! floating-point angle test (each filter with a margin). Gathered sites are kept by
//! sector, so this reads only the sectors that meet the window of directions. Each pair
//! is decided from its lesser index.

use super::Skeleton;
use crate::control::Control;
use crate::geom::{Point2, Ratio, in_beta_region};
use crate::planar::PlanarError;
use crate::planar::grid::PointGrid;
use rayon::prelude::*;
use std::f64::consts::{FRAC_PI_2, TAU};
use std::sync::atomic::{AtomicUsize, Ordering as AtomicOrdering};

/// The most edges the skeleton may have: 16 GB of `[u32; 2]`. Past that (small β on
/// dense sets: the skeleton tends to the complete graph) the search stops with an error.
const MAX_EDGES: usize = 2 << 30;

/// The β-skeleton for `0 < β < 1` of checked, distinct sites, reporting
/// `(sites searched, sites)` to `ctl` every [`REPORT_EVERY`] sites; once `ctl` is
/// stopped no further site is searched (incomplete, the edges found kept).
pub(super) fn lens_skeleton(
    points: &[Point2],
    beta: Ratio,
    ctl: &Control,
) -> Result<Skeleton, PlanarError> {
    at_most(points, beta, MAX_EDGES, ctl)
}

/// Sites searched between two progress reports.
const REPORT_EVERY: usize = 1024;

/// [`lens_skeleton`], refused once it has more than `limit` edges.
fn at_most(
    points: &[Point2],
    beta: Ratio,
    limit: usize,
    ctl: &Control,
) -> Result<Skeleton, PlanarError> {
    let grid = PointGrid::new(points, 2.0);
    let cones = Cones::new(beta, crate::geom::bounding_box(points));
    let (edges, decided, done) = (
        AtomicUsize::new(0),
        AtomicUsize::new(0),
        AtomicUsize::new(0),
    );
    let found: Vec<Vec<[u32; 2]>> = (0..points.len())
        .into_par_iter()
        .map_init(
            || Search::new(cones.sectors),
            |s, slot| {
                if edges.load(AtomicOrdering::Relaxed) > limit || ctl.is_stopped() {
                    return Vec::new();
                }
                let out = s.neighbours(&grid, &cones, beta, slot);
                edges.fetch_add(out.len(), AtomicOrdering::Relaxed);
                decided.fetch_add(s.decided, AtomicOrdering::Relaxed);
                let d = done.fetch_add(1, AtomicOrdering::Relaxed) + 1;
                if d % REPORT_EVERY == 0 {
                    ctl.items(d as u64, points.len() as u64);
                }
                out
            },
        )
        .collect();
    if edges.into_inner() > limit {
        return Err(PlanarError::TooManyEdges {
            sites: points.len(),
            limit,
            beta,
        });
    }
    let mut edges: Vec<[u32; 2]> = found.into_iter().flatten().collect();
    edges.par_sort_unstable();
    Ok(Skeleton {
        edges,
        complete: done.into_inner() == points.len(),
        candidates: decided.into_inner(),
        cell_diameters: 0,
    })
}

/// The sector geometry shared by every site's search.
struct Cones {
    /// The cone's half-angle `arcsin β`, lowered by a margin.
    phi: f64,
    /// `cos(arcsin β) = √(1 − β²)`, the lens's bound on `−cos ∠prq`.
    cos_phi: f64,
    /// Number of sectors and their width.
    sectors: usize,
    width: f64,
    /// The unit direction of each sector boundary (`sectors + 1` of them).
    bounds: Vec<[f64; 2]>,
    /// The sites' bounding box, and its diagonal.
    lo: Point2,
    hi: Point2,
    diagonal: f64,
    /// `1 + 1/sin x` rounded up, on a grid of `x` over `[0, π/2]`.
    factor: Vec<f64>,
}

/// Steps of the grid of [`Cones::factor`].
const FACTOR_STEPS: usize = 4096;

/// Margin on angles (radians) against the rounding of `atan2` and `asin`.
const ANGLE_SLACK: f64 = 1e-9;

impl Cones {
    fn new(beta: Ratio, (lo, hi): (Point2, Point2)) -> Cones {
        let phi = beta.to_f64().asin() * (1.0 - 1e-6) - ANGLE_SLACK;
        // About 8 sectors per cone width (at least 32), so that a site covers most of its
        // cone.
        let sectors = ((8.0 * TAU / (2.0 * phi.max(1e-9))).ceil() as usize).clamp(32, 4096);
        let width = TAU / sectors as f64;
        let bounds = (0..=sectors)
            .map(|s| {
                let a = s as f64 * width;
                [a.cos(), a.sin()]
            })
            .collect();
        // sin is increasing on [0, π/2]: at the grid point below x it bounds sin x
        // from below (a millionth of a millionth covers the rounding of sin).
        let factor = (0..=FACTOR_STEPS)
            .map(|i| {
                let s = (i as f64 * FRAC_PI_2 / FACTOR_STEPS as f64).sin() * (1.0 - 1e-12);
                (1.0 + 1.0 / s) * (1.0 + 1e-9)
            })
            .collect();
        let b = beta.to_f64();
        Cones {
            phi,
            cos_phi: (1.0 - b * b).sqrt(),
            sectors,
            width,
            bounds,
            lo,
            hi,
            diagonal: (hi[0] - lo[0]).hypot(hi[1] - lo[1]),
            factor,
        }
    }

    /// At least `1 + 1/sin x`, for `0 < x < π/2` (infinite near 0).
    fn activation_factor(&self, x: f64) -> f64 {
        let i = (x * (FACTOR_STEPS as f64 / FRAC_PI_2)) as usize;
        self.factor[i.min(FACTOR_STEPS)]
    }

    /// The sector of direction `a` (radians in `[0, 2π)`).
    fn sector(&self, a: f64) -> usize {
        ((a / self.width) as usize).min(self.sectors - 1)
    }

    /// The sectors that meet the directions within `window` of `a`, and one more on
    /// each side; every sector when that wraps around.
    fn around(&self, a: f64, window: f64) -> impl Iterator<Item = usize> + '_ {
        let n = self.sectors;
        let first = self.sector((a - window).rem_euclid(TAU));
        let last = self.sector((a + window).rem_euclid(TAU));
        let span = (last + n - first) % n + 3;
        let (start, count) = if 2.0 * window + 2.0 * self.width >= TAU || span >= n {
            (0, n)
        } else {
            (first + n - 1, span)
        };
        (start..start + count).map(move |s| s % n)
    }

    /// False only when `r` is certainly outside the lens of `pq`, that is when
    /// `cos ∠prq ≥ −cos φ` by a margin (10^-9 of `|rp||rq|`) far above the rounding of
    /// the dot product: coordinates in the exact range neither overflow nor underflow
    /// here.
    fn may_be_in_lens(&self, p: &Point2, q: &Point2, r: &Point2) -> bool {
        let (ax, ay) = (p[0] - r[0], p[1] - r[1]);
        let (bx, by) = (q[0] - r[0], q[1] - r[1]);
        let norms = ((ax * ax + ay * ay) * (bx * bx + by * by)).sqrt();
        ax * bx + ay * by < (1e-9 - self.cos_phi) * norms
    }

    /// Distance from `p` along direction `d` to where it leaves the bounding box.
    fn exit(&self, p: &Point2, d: [f64; 2]) -> f64 {
        let along = |k: usize| {
            if d[k] > 0.0 {
                (self.hi[k] - p[k]) / d[k]
            } else if d[k] < 0.0 {
                (self.lo[k] - p[k]) / d[k]
            } else {
                f64::INFINITY
            }
        };
        along(0).min(along(1))
    }

    /// Per sector, a distance from `p` beyond which none of its directions (widened by
    /// the slack) meets the bounding box. The exit distance along a direction is largest
    /// at the ends of the range of directions that leave through one side of the box, so
    /// it is the greatest of the exits at the sector's bounds and the distances of box
    /// corners in (or within a millionth of a radian of) the sector. Between a bound and
    /// the slack beyond it no corner lies, and the exit there changes by at most the
    /// diagonal times the slack.
    fn box_exits(&self, p: &Point2, out: &mut [f64]) {
        for (s, o) in out.iter_mut().enumerate() {
            *o = self
                .exit(p, self.bounds[s])
                .max(self.exit(p, self.bounds[s + 1]));
        }
        for c in [
            [self.lo[0], self.lo[1]],
            [self.hi[0], self.lo[1]],
            [self.hi[0], self.hi[1]],
            [self.lo[0], self.hi[1]],
        ] {
            let (dx, dy) = (c[0] - p[0], c[1] - p[1]);
            let a = angle(dx, dy);
            let d = dx.hypot(dy);
            for b in [a - 1e-6, a + 1e-6] {
                let s = self.sector(b.rem_euclid(TAU));
                out[s] = out[s].max(d);
            }
        }
        for o in out.iter_mut() {
            *o = (*o + self.diagonal * 1e-8) * (1.0 + 1e-9);
        }
    }
}

/// The direction of `(dx, dy)` in `[0, 2π)`.
fn angle(dx: f64, dy: f64) -> f64 {
    let a = dy.atan2(dx);
    if a < 0.0 { a + TAU } else { a }
}

/// The angle between directions `a` and `b` of `[0, 2π)`, in `[0, π]`.
fn separation(a: f64, b: f64) -> f64 {
    let d = (a - b).abs();
    d.min(TAU - d)
}

/// A site gathered by the search of `p`.
#[derive(Clone, Copy)]
struct Near {
    dist: f64,
    angle: f64,
    slot: u32,
}

/// One site's search state, reused from site to site.
struct Search {
    /// Per sector: the distance beyond which it is dead, and the site that kills it
    /// there (`u32::MAX` for the bounding box).
    dead: Vec<f64>,
    killer: Vec<u32>,
    gathered: Vec<Near>,
    /// Per sector, the positions in `gathered` of the sites in it, and the sectors that
    /// hold any (so that clearing costs what gathering did).
    by_sector: Vec<Vec<u32>>,
    filled: Vec<u32>,
    /// Gathered sites of greater index, not decided yet.
    pending: Vec<Near>,
    /// Pairs decided by the last search.
    decided: usize,
}

impl Search {
    fn new(sectors: usize) -> Search {
        Search {
            dead: vec![f64::INFINITY; sectors],
            killer: vec![u32::MAX; sectors],
            gathered: Vec::new(),
            by_sector: vec![Vec::new(); sectors],
            filled: Vec::new(),
            pending: Vec::new(),
            decided: 0,
        }
    }

    /// The skeleton edges `[p, q]` of the site in grid slot `slot` with `p < q`.
    fn neighbours(
        &mut self,
        grid: &PointGrid,
        cones: &Cones,
        beta: Ratio,
        slot: usize,
    ) -> Vec<[u32; 2]> {
        let (index, coords) = grid.slots();
        let p = Site {
            at: coords[slot],
            index: index[slot],
        };
        cones.box_exits(&p.at, &mut self.dead);
        self.killer.fill(u32::MAX);
        self.gathered.clear();
        for s in self.filled.drain(..) {
            self.by_sector[s as usize].clear();
        }
        self.pending.clear();
        self.decided = 0;
        let mut out = Vec::new();
        let c = grid.cell_of(&p.at);
        for ring in 0usize.. {
            grid.for_ring(c, ring, |x, y| {
                for t in grid.cell_slots(x, y) {
                    if t != slot {
                        self.gather(cones, &p, coords, index[t], t);
                    }
                }
            });
            let exhausted = grid.ring_covers_all(c, ring);
            // Every site closer to `p` than `complete` has been gathered, up to the
            // rounding of cell indices (under 10^-11 cells).
            let complete = if exhausted {
                f64::INFINITY
            } else {
                (ring as f64 - 1e-6) * grid.cell()
            };
            self.decide(cones, beta, coords, index, &p, complete, &mut out);
            let reach = self.dead.iter().fold(0.0f64, |a, &b| a.max(b));
            if exhausted || reach <= complete * (1.0 - 1e-6) {
                return out;
            }
        }
        unreachable!("the rings reach the whole grid")
    }

    /// Records site `t` (of index `ti`) and the sectors its cone kills.
    fn gather(&mut self, cones: &Cones, p: &Site, coords: &[Point2], ti: u32, t: usize) {
        let r = coords[t];
        let (dx, dy) = (r[0] - p.at[0], r[1] - p.at[1]);
        let near = Near {
            dist: (dx * dx + dy * dy).sqrt(),
            angle: angle(dx, dy),
            slot: t as u32,
        };
        let n = cones.sectors;
        let home = cones.sector(near.angle);
        if self.by_sector[home].is_empty() {
            self.filled.push(home as u32);
        }
        self.by_sector[home].push(self.gathered.len() as u32);
        self.gathered.push(near);
        if ti > p.index {
            self.pending.push(near);
        }
        // Sectors `home + k`, bounds unwrapped around `near.angle`.
        let reach = ((cones.phi / cones.width) as usize + 1).min(n / 2);
        let mut s = (home + n - reach) % n;
        for k in 0..=2 * reach {
            let a0 = (home + k) as f64 * cones.width - reach as f64 * cones.width - ANGLE_SLACK;
            let a1 = a0 + cones.width + 2.0 * ANGLE_SLACK;
            let far = (near.angle - a0).max(a1 - near.angle);
            if far < cones.phi {
                let at = near.dist * cones.activation_factor(cones.phi - far);
                if at < self.dead[s] {
                    self.dead[s] = at;
                    self.killer[s] = t as u32;
                }
            }
            s = if s + 1 == n { 0 } else { s + 1 };
        }
    }

    /// Decides the pending sites closer than `complete` (every site closer to `p` than
    /// they are has been gathered).
    #[allow(clippy::too_many_arguments)]
    fn decide(
        &mut self,
        cones: &Cones,
        beta: Ratio,
        coords: &[Point2],
        index: &[u32],
        p: &Site,
        complete: f64,
        out: &mut Vec<[u32; 2]>,
    ) {
        let limit = complete * (1.0 - 1e-9);
        let window = cones.phi / (1.0 - 1e-6) + 1e-6;
        let mut i = 0;
        while i < self.pending.len() {
            let q = self.pending[i];
            if q.dist >= limit {
                i += 1;
                continue;
            }
            self.pending.swap_remove(i);
            self.decided += 1;
            let at = coords[q.slot as usize];
            let killed = |k: u32| in_beta_region(&p.at, &at, &coords[k as usize], beta);
            let s = cones.sector(q.angle);
            if self.killer[s] != u32::MAX && self.dead[s] <= q.dist && killed(self.killer[s]) {
                continue;
            }
            // A site in the lens is closer than `q`, and seen from `p` within `φ` of it:
            // in the sectors that meet that window (one more each side for rounding).
            let within = q.dist * (1.0 + 1e-8);
            let hit = cones.around(q.angle, window).any(|s| {
                self.by_sector[s].iter().any(|&g| {
                    let r = &self.gathered[g as usize];
                    r.slot != q.slot
                        && r.dist <= within
                        && separation(r.angle, q.angle) < window
                        && cones.may_be_in_lens(&p.at, &at, &coords[r.slot as usize])
                        && killed(r.slot)
                })
            });
            if !hit {
                out.push([p.index, index[q.slot as usize]]);
            }
        }
    }
}

/// The site whose neighbours a search finds.
struct Site {
    at: Point2,
    index: u32,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    /// The reference: every pair against the sites in the bounding box of its lens.
    fn all_pairs(points: &[Point2], beta: Ratio) -> Vec<[u32; 2]> {
        let grid = PointGrid::new(points, 2.0);
        let n = points.len() as u32;
        let mut out = Vec::new();
        for a in 0..n {
            for b in a + 1..n {
                let (pa, pb) = (&points[a as usize], &points[b as usize]);
                let (lo, hi) = super::super::disk_box(pa, pb, 0.5);
                let hit = grid.any_in_box(lo, hi, |r| {
                    r != a && r != b && in_beta_region(pa, pb, &points[r as usize], beta)
                });
                if !hit {
                    out.push([a, b]);
                }
            }
        }
        out
    }

    fn distinct(mut v: Vec<Point2>) -> Vec<Point2> {
        let mut seen = std::collections::HashSet::new();
        v.retain(|p| seen.insert((p[0].to_bits(), p[1].to_bits())));
        v
    }

    /// Random, lattice, polar, clustered, collinear, rotated, far-from-origin and
    /// box-boundary sets.
    fn family(rng: &mut Rng, kind: usize, n: usize) -> Vec<Point2> {
        let pts = (0..n).map(|i| {
            let (u, v) = (rng.unit(), rng.unit());
            match kind {
                0 => [u, v],
                1 => [rng.below(12) as f64, rng.below(9) as f64],
                2 => {
                    let a = TAU * rng.below(24) as f64 / 24.0;
                    let r = 1.0 + rng.below(8) as f64;
                    [r * a.cos(), r * a.sin()]
                }
                3 => {
                    let c = (i % 4) as f64 * 100.0;
                    [c + 0.01 * u, c * 0.5 + 0.01 * v]
                }
                4 => [rng.below(200) as f64, if i % 9 == 0 { u } else { 0.0 }],
                5 => {
                    let (x, y) = (rng.below(20) as f64, rng.below(20) as f64);
                    let a = 0.3f64;
                    [x * a.cos() - y * a.sin(), x * a.sin() + y * a.cos()]
                }
                6 => [1e6 + u * 1e-3, -3e5 + v * 1e-3],
                // On the box's sides and at its corners: neighbours in corner directions.
                _ => match i % 6 {
                    0 => [(i / 6 % 2) as f64, (i / 12 % 2) as f64],
                    1 => [u, 0.0],
                    2 => [0.0, v],
                    3 => [1.0, v],
                    4 => [u, 1.0],
                    _ => [0.5 + 0.1 * u, 0.5 + 0.1 * v],
                },
            }
        });
        distinct(pts.collect())
    }

    #[test]
    fn lens_search_matches_every_pair() {
        let mut rng = Rng::new(5);
        let betas = [
            "0.000000000000001",
            "0.01",
            "0.05",
            "0.3",
            "0.6",
            "0.9",
            "0.99",
            "0.999999",
        ];
        let mut edges = 0;
        for round in 0..128 {
            let kind = round % 8;
            let n = 50 + rng.below(if round % 3 == 0 { 1200 } else { 300 });
            let pts = family(&mut rng, kind, n);
            let b = betas[(round / 8) % betas.len()];
            let beta: Ratio = b.parse().unwrap();
            let got = lens_skeleton(&pts, beta, &Control::new()).unwrap();
            let want = all_pairs(&pts, beta);
            assert_eq!(
                got.edges,
                want,
                "β = {b}, family {kind}, {} sites",
                pts.len()
            );
            edges += want.len();
        }
        assert!(edges > 50_000, "{edges}");
    }

    /// Past its limit the search stops with an error instead of growing the list.
    #[test]
    fn too_many_edges_are_refused() {
        let mut rng = Rng::new(7);
        let pts: Vec<Point2> = (0..2000).map(|_| [rng.unit(), rng.unit()]).collect();
        let beta: Ratio = "0.2".parse().unwrap();
        let all = lens_skeleton(&pts, beta, &Control::new())
            .unwrap()
            .edges
            .len();
        assert!(at_most(&pts, beta, all, &Control::new()).is_ok());
        let err = at_most(&pts, beta, all / 2, &Control::new()).unwrap_err();
        assert!(
            matches!(err, PlanarError::TooManyEdges { sites: 2000, limit, .. } if limit == all / 2),
            "{err}"
        );
    }

    /// Stopped after its first progress report, the search keeps the edges found from
    /// the sites searched (a subset of the skeleton, marked incomplete); stopped before,
    /// it has none.
    #[test]
    fn a_stopped_search_keeps_the_edges_found() {
        let mut rng = Rng::new(8);
        let pts: Vec<Point2> = (0..20_000).map(|_| [rng.unit(), rng.unit()]).collect();
        let beta: Ratio = "0.9".parse().unwrap();
        let all = lens_skeleton(&pts, beta, &Control::new()).unwrap();
        assert!(all.complete);
        let parent = Control::new();
        let p = parent.clone();
        let part = lens_skeleton(&pts, beta, &parent.child().with_progress(move |_| p.stop()));
        let part = part.unwrap();
        assert!(!part.complete && !part.edges.is_empty());
        assert!(part.edges.len() < all.edges.len());
        assert!(
            part.edges
                .iter()
                .all(|e| all.edges.binary_search(e).is_ok())
        );
        let stopped = Control::new();
        stopped.stop();
        let none = lens_skeleton(&pts, beta, &stopped).unwrap();
        assert!(!none.complete && none.edges.is_empty());
    }

    /// On uniform sites the search decides a bounded number of pairs per site (about 59
    /// here; every pair would be 10,000): it stops once every direction is blocked.
    #[test]
    fn lens_search_decides_few_pairs_per_site() {
        let mut rng = Rng::new(6);
        let pts: Vec<Point2> = (0..20_000).map(|_| [rng.unit(), rng.unit()]).collect();
        let sk = lens_skeleton(&pts, "0.9".parse().unwrap(), &Control::new()).unwrap();
        assert!(sk.candidates < 100 * pts.len(), "{}", sk.candidates);
        assert!(sk.edges.len() > 2 * pts.len());
    }
}
