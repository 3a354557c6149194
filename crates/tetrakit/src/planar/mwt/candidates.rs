//! Candidate edges of a minimum weight triangulation: the diamond test.
//!
//! Drysdale, McElfresh and Snoeyink (2001) proved that an edge `pq` of an MWT has at
//! least one of its two *diamonds* (the isosceles triangles on `pq` with base angle
//! π/4.6) empty. We use the slightly smaller diamonds of base angle `atan(13/16)`
//! ([`diamond_hit`]), which are exact rational regions inside the true ones, so
//! excluding an edge is always justified. An edge with a site on its open segment is
//! excluded too (it is no triangulation edge).
//!
//! **Search.** For each site `p`, sites are visited in order of distance (grid rings).
//! Every site in a diamond of `pq` is closer to `p` than `q`, so the diamonds of `pq`
//! are tested against the sites already visited, restricted to the 15 angular sectors
//! (of 64) around `q`'s direction that a diamond can reach. A visited site `r` at
//! distance `ρ` and angle `ψ ∈ (0, θ)` counter-clockwise from the direction of `q` is
//! in the left diamond of `pq` once `|pq| > ρ(cos ψ + sin ψ cot θ)`; so the nearest
//! visited site in sectors `k+2..=k+5` (offsets in `(s, 6s)`, `s = 5.625°`) kills the
//! left diamonds of every farther `q` in sector `k` beyond a computed radius, and
//! sectors `k-5..=k-2` the right ones. The search stops when every sector is dead
//! beyond the radius already searched.
//!
//! **Sites near an edge of the set.** Looking along the edge, one side of a sector has
//! no sites, so its neighbouring sectors never kill that side's diamonds and the cone
//! would be walked to the bounding box (`O(n)` visits for such a site). The sector's own
//! sites kill them instead: a visited site `r` of sector `k` at distance `ρ` is at
//! `ψ ∈ (0, one sector]` from every farther `q` of the sector clockwise of it, so it
//! lies in their left diamonds once `|pq| > ρ(cos s + sin s cot θ)` (`s` one sector, with
//! the 0.1% margin), and in the right diamonds of those counter-clockwise of it. When
//! one side is dead by the neighbours, the live part of the sector beyond a radius is the
//! sliver past the last (or first) such `r`, with a `10^-9` pseudo-angle margin; its
//! reach to the bounding box ends the walk.
//!
//! **Why the floating-point search is exact.** Every exclusion is decided one of three
//! ways: by exact hits ([`diamond_hit`] on two sites, one per diamond, or one on the
//! segment), by `|pq|` above the dead radius of `q`'s sector, or by the search stopping
//! before `q` is reached. Only the last two use floating-point distances and angles, and
//! they hold with margins far above their rounding error:
//! - [`mwt`](super::mwt) admits only coordinates in the exact range (zero or magnitude
//!   in `[2^-142, 2^201]`), so a non-zero coordinate difference is at least `2^-194` and
//!   a squared distance at most `2^405`: nothing underflows or overflows, and each
//!   distance, pseudo-angle, sector boundary and cell coordinate carries a relative error
//!   below `2^-45` (a handful of roundings; cell coordinates are below `2^14`, so a cell
//!   index is off by at most one near a cell boundary, which moves a ring radius by
//!   under `2^-37` cells).
//! - The margins: 0.1% on the kill factors; a site rounded into the next sector shifts
//!   `ψ` by under `2^-40` of a sector and stays in `(0, θ)` (offsets 2..=5 span
//!   `(s, 6s)`, `6s = 33.75° < θ = 39.09°`); diamonds reach 7 sectors while `θ` needs
//!   6.95 (a 0.28° margin); 1% on the bounding-box reach; two cells on each side of a
//!   cone's range in a ring (a ray crosses at most three cells of a ring); `10^-9` on the
//!   inner ring radius; `10^-9` in pseudo-angle against errors below `2^-45` for the
//!   in-sector kills, and `10^-6` when a sliver's corners are collected.
//! - Keeping a pair the exact test would exclude is always safe (the LMT-skeleton and
//!   the exact stage optimise over the candidates, a superset of the MWT's edges), so the
//!   order in which sites are visited, by rounded distance, only affects speed: the
//!   kill radii come from sites actually visited, whatever the order.

use crate::geom::{Point2, diamond_hit};
use crate::planar::grid::PointGrid;
use crate::planar::{PlanarError, check_sites};
use rayon::prelude::*;

const SECTORS: usize = 64;
const WIDTH: f64 = std::f64::consts::TAU / SECTORS as f64;
/// Steps per unit of pseudo-angle in the sector lookup table.
const LUT_SCALE: usize = 256;
/// Diamonds reach at most `θ = atan(13/16) < 7 sectors` from `q`'s direction.
const REACH: usize = 7;

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

struct Sectors {
    bounds: [f64; SECTORS],
    /// `first[i]`: the sector holding pseudo-angle `i / LUT_SCALE` (a sector spans more
    /// than one such step, so at most one boundary lies in each).
    first: Vec<u8>,
    /// Unit vectors of the sector boundaries `0..=SECTORS`.
    rays: [(f64, f64); SECTORS + 1],
    /// `kill[i]`: the distance factor for a site `i` sectors away (i = 2..=5).
    kill: [f64; 6],
    /// The distance factor for a site in the same sector (`ψ` up to one sector).
    kill_in: f64,
}

impl Sectors {
    fn new() -> Sectors {
        let mut bounds = [0.0; SECTORS];
        for (k, b) in bounds.iter_mut().enumerate() {
            let a = k as f64 * WIDTH;
            *b = if k == 0 {
                0.0
            } else {
                pseudo_angle(a.cos(), a.sin())
            };
        }
        let mut kill = [f64::INFINITY; 6];
        for (i, f) in kill.iter_mut().enumerate().skip(2) {
            let psi = (i + 1) as f64 * WIDTH;
            *f = (psi.cos() + psi.sin() * 16.0 / 13.0) * 1.001;
        }
        let kill_in = (WIDTH.cos() + WIDTH.sin() * 16.0 / 13.0) * 1.001;
        let rays = std::array::from_fn(|k| {
            let a = k as f64 * WIDTH;
            (a.cos(), a.sin())
        });
        let first = (0..4 * LUT_SCALE)
            .map(|i| (bounds.partition_point(|&b| b <= i as f64 / LUT_SCALE as f64) - 1) as u8)
            .collect();
        Sectors {
            bounds,
            first,
            rays,
            kill,
            kill_in,
        }
    }

    /// Pseudo-angle where sector `k` ends (4 for the last).
    fn end(&self, k: usize) -> f64 {
        if k + 1 < SECTORS {
            self.bounds[k + 1]
        } else {
            4.0
        }
    }

    fn of(&self, dx: f64, dy: f64) -> usize {
        self.of_pseudo(pseudo_angle(dx, dy))
    }

    fn of_pseudo(&self, a: f64) -> usize {
        // Equal to `bounds.partition_point(|&b| b <= a) - 1`: the step's sector, then at
        // most one boundary up.
        let i = ((a * LUT_SCALE as f64) as usize).min(4 * LUT_SCALE - 1);
        let k = self.first[i] as usize;
        if k + 1 < SECTORS && self.bounds[k + 1] <= a {
            k + 1
        } else {
            k
        }
    }
}

/// Per-thread scratch space.
#[derive(Default)]
struct Scratch {
    by_sector: Vec<Vec<u32>>,
    /// Per sector, in visiting order: (distance, smallest and largest pseudo-angle of
    /// the sector's sites visited so far).
    span: Vec<Vec<(f64, f64, f64)>>,
    nearest: Vec<f64>,
    pending: Vec<(f64, u32)>,
    visited: Vec<bool>,
}

/// All candidate edges `[p, q]` (`p < q`) of distinct sites, sorted: the pairs with an
/// empty diamond and no site on the open segment (a few more may be kept, never fewer).
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
    Ok(search(points))
}

/// [`candidate_edges`] for checked sites.
pub(super) fn search(points: &[Point2]) -> Vec<[u32; 2]> {
    let grid = PointGrid::new(points, 2.0);
    let sectors = Sectors::new();
    // Sites in cell order, so that consecutive searches share cached cells.
    let mut edges: Vec<[u32; 2]> = (0..points.len())
        .into_par_iter()
        .map_init(Scratch::default, |s, slot| {
            let mut out = Vec::new();
            candidates_of(slot, &grid, &sectors, s, &mut out);
            out
        })
        .flatten_iter()
        .collect();
    edges.par_sort_unstable();
    edges
}

/// Margin in pseudo-angle for kills by a site of the same sector (pseudo-angles carry
/// relative errors below `2^-45`).
const ANGLE_MARGIN: f64 = 1e-9;

/// A part of a sector, as a pseudo-angle interval, where diamonds may still be open
/// beyond some distance, with the distance beyond which its side is dead anyway.
type Wedge = Option<(f64, f64, f64)>;

/// The distances beyond which every site of sector `k` has a visited site of the
/// neighbouring sectors in its left (counter-clockwise) and in its right diamond.
fn side_radii(s: &Scratch, sec: &Sectors, k: usize) -> (f64, f64) {
    let side = |sign: isize| {
        (2..=5)
            .map(|i| {
                let j = (k as isize + sign * i as isize).rem_euclid(SECTORS as isize) as usize;
                s.nearest[j] * sec.kill[i]
            })
            .fold(f64::INFINITY, f64::min)
    };
    (side(1), side(-1))
}

/// The smallest and largest pseudo-angle among the sites of sector `k` visited at a
/// distance `ρ` with `ρ · kill_in < t`. Such a site `r` is in the left diamond of every
/// `pq` with `q` in the sector, farther than `t` and clockwise of `r` (`ψ ∈ (0, one
/// sector]`, so `|pq| > ρ(cos ψ + sin ψ cot θ)`), and in the right diamond of those
/// counter-clockwise of it.
fn span_below(s: &Scratch, sec: &Sectors, k: usize, t: f64) -> Option<(f64, f64)> {
    let h = &s.span[k];
    let i = h.partition_point(|e| e.0 * sec.kill_in < t);
    (i > 0).then(|| (h[i - 1].1, h[i - 1].2))
}

/// True when both diamonds of `pq` hold a visited site, for `q` at distance `d` and
/// pseudo-angle `a` in sector `k`.
fn killed(s: &Scratch, sec: &Sectors, k: usize, d: f64, a: f64) -> bool {
    let (lr, rr) = side_radii(s, sec, k);
    let (left, right) = (d > lr, d > rr);
    if left == right {
        // Both killed, or neither: the sector's own sites kill both sides only for a
        // site between two of them, which the exact test then rejects as fast.
        return left;
    }
    let Some((lo, hi)) = span_below(s, sec, k, d) else {
        return false;
    };
    (left || a < hi - ANGLE_MARGIN) && (right || a > lo + ANGLE_MARGIN)
}

/// The parts of sector `k` where a site farther than `t` may have an open diamond. When
/// the neighbouring sectors kill one side's diamonds (a site near an edge of the set,
/// looking along it), the other side's stay open only counter-clockwise of the sector's
/// last killer (left) or clockwise of its first (right), see [`span_below`]: that cuts
/// the cone along the edge to a sliver that soon leaves the bounding box. With both sides
/// open the whole sector is kept (cutting it there costs more than it saves).
fn live_wedges(s: &Scratch, sec: &Sectors, k: usize, t: f64) -> [Wedge; 2] {
    let (lr, rr) = side_radii(s, sec, k);
    let (start, end) = (sec.bounds[k], sec.end(k));
    match (lr >= t, rr >= t) {
        (false, false) => [None, None],
        (true, true) => [Some((start, end, lr.max(rr))), None],
        (left, _) => {
            let span = span_below(s, sec, k, t);
            let (mut a0, mut a1) = (start, end);
            if left {
                a0 = span.map_or(start, |(_, hi)| (hi - ANGLE_MARGIN).max(start));
            } else {
                a1 = span.map_or(end, |(lo, _)| (lo + ANGLE_MARGIN).min(end));
            }
            // A wide part is not worth its own rays and reach: keep the sector.
            if a1 - a0 > 0.25 * (end - start) {
                (a0, a1) = (start, end);
            }
            [Some((a0, a1, if left { lr } else { rr })), None]
        }
    }
}

/// A direction whose pseudo-angle is `a` (not normalised).
fn direction(a: f64) -> (f64, f64) {
    let q = a.floor().clamp(0.0, 3.0);
    let f = a - q;
    match q as u8 {
        0 => (1.0 - f, f),
        1 => (-f, 1.0 - f),
        2 => (f - 1.0, -f),
        _ => (f, f - 1.0),
    }
}

/// The candidates `[p, q]`, `p < q`, of the site in grid slot `slot`. Sites are handled
/// by slot throughout (index and coordinates side by side in the grid).
fn candidates_of(
    slot: usize,
    grid: &PointGrid,
    sec: &Sectors,
    s: &mut Scratch,
    out: &mut Vec<[u32; 2]>,
) {
    s.by_sector.resize_with(SECTORS, Vec::new);
    s.by_sector.iter_mut().for_each(Vec::clear);
    s.span.resize_with(SECTORS, Vec::new);
    s.span.iter_mut().for_each(Vec::clear);
    s.nearest.clear();
    s.nearest.resize(SECTORS, f64::INFINITY);
    s.pending.clear();
    let (index, coords) = grid.slots();
    let (p, pp) = (index[slot], coords[slot]);
    let (cx, cy) = grid.cell_of(&pp);
    let (nx, ny) = grid.dims();
    let mut ring = 0usize;
    let mut live = [[None; 2]; SECTORS];
    let reach = sector_reach(&pp, grid.bounds(), sec);
    loop {
        if ring < 2 {
            gather_ring(grid, slot, cx, cy, ring, &mut s.pending);
        } else {
            gather_live_cones(grid, slot, (cx, cy), ring, sec, &live, s);
        }
        let exhausted = ring >= cx && ring >= cy && cx + ring >= nx - 1 && cy + ring >= ny - 1;
        let complete = if exhausted {
            f64::INFINITY
        } else {
            ring as f64 * grid.cell()
        };
        s.pending.sort_unstable_by(|a, b| b.0.total_cmp(&a.0));
        while let Some(&(d2, qs)) = s.pending.last() {
            if d2 >= complete * complete {
                break;
            }
            s.pending.pop();
            let (q, pq) = (index[qs as usize], coords[qs as usize]);
            let a = pseudo_angle(pq[0] - pp[0], pq[1] - pp[1]);
            let k = sec.of_pseudo(a);
            let d = d2.sqrt();
            if q > p && !killed(s, sec, k, d, a) && diamonds_open(&pp, &pq, coords, s, k) {
                out.push([p, q]);
            }
            s.by_sector[k].push(qs);
            s.nearest[k] = s.nearest[k].min(d);
            let (lo, hi) = s.span[k]
                .last()
                .map_or((a, a), |e| (e.1.min(a), e.2.max(a)));
            s.span[k].push((d, lo, hi));
        }
        if exhausted {
            return;
        }
        // What stays live beyond the next ring's inner radius, cut to the bounding box.
        let inner = complete * (1.0 - 1e-9);
        let mut farthest = 0.0f64;
        for (k, wedges) in live.iter_mut().enumerate() {
            *wedges = live_wedges(s, sec, k, inner);
            for w in wedges.iter_mut() {
                let Some((a0, a1, radius)) = *w else { continue };
                // The sector's own reach first: most wedges die there, without the
                // wedge's (dearer) reach.
                let mut until = radius.min(reach[k]);
                if until >= inner && (a0 > sec.bounds[k] || a1 < sec.end(k)) {
                    until = until.min(wedge_reach(&pp, grid.bounds(), a0, a1));
                }
                farthest = farthest.max(until);
                if until < inner {
                    *w = None;
                }
            }
        }
        if farthest < complete {
            return;
        }
        ring += 1;
    }
}

/// Distance from `p` along the unit direction `(c, s)` to the bounding box's boundary.
fn box_exit(p: &Point2, (lo, hi): (Point2, Point2), (c, s): (f64, f64)) -> f64 {
    let t = |d: f64, l: f64, h: f64, x: f64| {
        if d > 1e-12 {
            (h - x) / d
        } else if d < -1e-12 {
            (l - x) / d
        } else {
            f64::INFINITY
        }
    };
    t(c, lo[0], hi[0], p[0])
        .min(t(s, lo[1], hi[1], p[1]))
        .max(0.0)
}

fn corners((lo, hi): (Point2, Point2)) -> [Point2; 4] {
    [
        [lo[0], lo[1]],
        [lo[0], hi[1]],
        [hi[0], lo[1]],
        [hi[0], hi[1]],
    ]
}

/// For each sector, a distance beyond which its cone holds no site: the farthest vertex
/// of (bounding box ∩ cone), i.e. the exits of its two rays and the box corners in it
/// (corners of the neighbouring sectors too, against rounding), with a 1% margin.
fn sector_reach(p: &Point2, bbox: (Point2, Point2), sec: &Sectors) -> [f64; SECTORS] {
    let rays: Vec<f64> = sec.rays.iter().map(|&r| box_exit(p, bbox, r)).collect();
    let mut reach = [0.0; SECTORS];
    for k in 0..SECTORS {
        reach[k] = rays[k].max(rays[k + 1]);
    }
    for c in corners(bbox) {
        let (dx, dy) = (c[0] - p[0], c[1] - p[1]);
        let k = sec.of(dx, dy);
        let d = dx.hypot(dy);
        for j in [k + SECTORS - 1, k, k + 1] {
            let r = &mut reach[j % SECTORS];
            *r = r.max(d);
        }
    }
    reach.map(|r| r * 1.01 + 1e-300)
}

/// [`sector_reach`] for the wedge of pseudo-angles `[a0, a1]` inside one sector: the
/// exits of its two rays and the corners within `10^-6` of it, with a 1% margin.
fn wedge_reach(p: &Point2, bbox: (Point2, Point2), a0: f64, a1: f64) -> f64 {
    let unit = |a: f64| {
        let (x, y) = direction(a);
        let l = (x * x + y * y).sqrt();
        (x / l, y / l)
    };
    let mut reach = box_exit(p, bbox, unit(a0)).max(box_exit(p, bbox, unit(a1)));
    for c in corners(bbox) {
        let (dx, dy) = (c[0] - p[0], c[1] - p[1]);
        if (a0 - 1e-6..=a1 + 1e-6).contains(&pseudo_angle(dx, dy)) {
            reach = reach.max((dx * dx + dy * dy).sqrt());
        }
    }
    reach * 1.01 + 1e-300
}

/// Perimeter position (counter-clockwise from the east side) of the ring-`r` cell at
/// offset `(dx, dy)` from the centre cell (`max(|dx|, |dy|) = r`, `r ≥ 1`).
fn ring_index(dx: isize, dy: isize, r: isize) -> isize {
    if dx == r && dy > -r {
        dy + r - 1
    } else if dy == r {
        2 * r + (r - 1 - dx)
    } else if dx == -r {
        4 * r + (r - 1 - dy)
    } else {
        6 * r + (dx + r - 1)
    }
}

/// Inverse of [`ring_index`].
fn ring_cell(i: isize, r: isize) -> (isize, isize) {
    let i = i.rem_euclid(8 * r);
    match i / (2 * r) {
        0 => (r, i - r + 1),
        1 => (r - 1 - (i - 2 * r), r),
        2 => (-r, r - 1 - (i - 4 * r)),
        _ => (i - 6 * r - r + 1, -r),
    }
}

/// Perimeter position of the ring-`r` cell where the ray from `p` in direction `d`
/// leaves the ring's outer square.
fn ray_ring_index(
    grid: &PointGrid,
    p: &Point2,
    cx: usize,
    cy: usize,
    d: (f64, f64),
    r: usize,
) -> isize {
    let cell = grid.cell();
    let (lo, _) = grid.cell_box(cx, cy);
    let o = [p[0] - (lo[0] + 0.5 * cell), p[1] - (lo[1] + 0.5 * cell)];
    let h = (r as f64 + 0.5) * cell;
    let exit = |dir: f64, off: f64| {
        if dir > 1e-12 {
            (h - off) / dir
        } else if dir < -1e-12 {
            (-h - off) / dir
        } else {
            f64::INFINITY
        }
    };
    let t = exit(d.0, o[0]).min(exit(d.1, o[1])) * (1.0 - 1e-9);
    let (px, py) = (o[0] + t * d.0, o[1] + t * d.1);
    let ri = r as isize;
    let mut dx = ((px / cell) + 0.5).floor() as isize;
    let mut dy = ((py / cell) + 0.5).floor() as isize;
    if dx.abs() < ri && dy.abs() < ri {
        if px.abs() >= py.abs() {
            dx = if px >= 0.0 { ri } else { -ri };
        } else {
            dy = if py >= 0.0 { ri } else { -ri };
        }
    }
    ring_index(dx.clamp(-ri, ri), dy.clamp(-ri, ri), ri)
}

/// Pushes the sites of the ring-`r` cells met by the cones of the sectors still live
/// beyond the ring's inner radius (each cone's perimeter range widened by two cells
/// against rounding and the offset of `p` in its cell).
fn gather_live_cones(
    grid: &PointGrid,
    slot: usize,
    (cx, cy): (usize, usize),
    r: usize,
    sec: &Sectors,
    live: &[[Wedge; 2]; SECTORS],
    s: &mut Scratch,
) {
    let pp = grid.slots().1[slot];
    let ri = r as isize;
    let (nx, ny) = grid.dims();
    s.visited.clear();
    s.visited.resize(8 * r, false);
    // Each boundary ray is shared by two sectors: locate it once.
    let mut at = [isize::MIN; SECTORS + 1];
    let mut ray = |j: usize| {
        if at[j] == isize::MIN {
            at[j] = ray_ring_index(grid, &pp, cx, cy, sec.rays[j], r);
        }
        at[j]
    };
    for (k, &(a0, a1, _)) in live
        .iter()
        .enumerate()
        .flat_map(|(k, w)| w.iter().flatten().map(move |w| (k, w)))
    {
        // Sector boundaries are cached; a sliver's own edge is located afresh.
        let i0 = if a0 == sec.bounds[k] {
            ray(k)
        } else {
            ray_ring_index(grid, &pp, cx, cy, direction(a0), r)
        } - 2;
        let i1 = if a1 == sec.end(k) {
            ray(k + 1)
        } else {
            ray_ring_index(grid, &pp, cx, cy, direction(a1), r)
        } + 2;
        let len = ((i1 - i0).rem_euclid(8 * ri) + 1).min(8 * ri);
        for i in i0..i0 + len {
            let visit = i.rem_euclid(8 * ri) as usize;
            if std::mem::replace(&mut s.visited[visit], true) {
                continue;
            }
            let (dx, dy) = ring_cell(i, ri);
            let (x, y) = (cx as isize + dx, cy as isize + dy);
            if x >= 0 && y >= 0 && x < nx as isize && y < ny as isize {
                push_cell(
                    grid,
                    &pp,
                    x as usize,
                    y as usize,
                    usize::MAX,
                    &mut s.pending,
                );
            }
        }
    }
}

/// Pushes `(squared distance from pp, slot)` for the sites of cell `(x, y)` except `skip`.
fn push_cell(
    grid: &PointGrid,
    pp: &Point2,
    x: usize,
    y: usize,
    skip: usize,
    pending: &mut Vec<(f64, u32)>,
) {
    let coords = grid.slots().1;
    for q in grid.cell_slots(x, y).filter(|&q| q != skip) {
        let a = coords[q];
        let (ex, ey) = (a[0] - pp[0], a[1] - pp[1]);
        pending.push((ex * ex + ey * ey, q as u32));
    }
}

/// Pushes `(squared distance, slot)` of the sites in ring `r` around cell `(cx, cy)`.
fn gather_ring(
    grid: &PointGrid,
    slot: usize,
    cx: usize,
    cy: usize,
    r: usize,
    pending: &mut Vec<(f64, u32)>,
) {
    let (nx, ny) = grid.dims();
    let pp = grid.slots().1[slot];
    let mut cell = |x: usize, y: usize| push_cell(grid, &pp, x, y, slot, pending);
    let x0 = cx.saturating_sub(r);
    let x1 = (cx + r).min(nx - 1);
    for y in cy.saturating_sub(r)..=(cy + r).min(ny - 1) {
        if y + r == cy || y == cy + r {
            (x0..=x1).for_each(|x| cell(x, y));
        } else {
            if cx >= r {
                cell(cx - r, y);
            }
            if cx + r < nx && r > 0 {
                cell(cx + r, y);
            }
        }
    }
}

/// True when `pq` has an empty diamond and no site on its open segment, among the
/// visited sites (slots in `s.by_sector`, which include every site that could be in
/// either).
fn diamonds_open(a: &Point2, b: &Point2, coords: &[Point2], s: &Scratch, k: usize) -> bool {
    let (mut left, mut right) = (false, false);
    // Nearest directions first: sites close to the line pq are the likeliest blockers.
    for t in 0..=2 * REACH {
        let off = if t % 2 == 0 {
            REACH + t / 2
        } else {
            REACH - t.div_ceil(2)
        };
        let j = (k + SECTORS + off - REACH) % SECTORS;
        for &r in &s.by_sector[j] {
            let h = diamond_hit(a, b, &coords[r as usize]);
            left |= h.left;
            right |= h.right;
            if h.on_segment || (left && right) {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planar::{Distribution, points2d};

    #[test]
    fn sector_lookup_table_agrees_with_binary_search() {
        let sec = Sectors::new();
        let slow = |a: f64| sec.bounds.partition_point(|&b| b <= a) - 1;
        let mut probes: Vec<f64> = (0..40_000).map(|i| i as f64 * 1e-4).collect();
        for &b in &sec.bounds {
            probes.extend([b, b.next_up(), b.next_down().max(0.0)]);
        }
        probes.extend((1..4 * LUT_SCALE).map(|i| i as f64 / LUT_SCALE as f64));
        probes.push(4f64.next_down());
        for a in probes {
            assert_eq!(sec.of_pseudo(a), slow(a), "pseudo-angle {a}");
        }
    }

    #[test]
    fn directions_invert_pseudo_angles() {
        for i in 0..4000 {
            let a = i as f64 / 1000.0;
            let (x, y) = direction(a);
            assert!((pseudo_angle(x, y) - a).abs() < 1e-12, "{a}");
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

    #[test]
    fn ring_positions_round_trip() {
        for r in 1..7isize {
            for i in 0..8 * r {
                let (dx, dy) = ring_cell(i, r);
                assert_eq!(dx.abs().max(dy.abs()), r);
                assert_eq!(ring_index(dx, dy, r), i);
            }
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
        let (got, want) = (search(pts), brute(pts));
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
        assert!(err.0.contains("sites 0 and 2 coincide"), "{err}");
        let err = candidate_edges(&[[1.0, 2.0], [1e-300, 4.0]]).unwrap_err();
        assert!(err.0.contains("site 1"), "{err}");
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
            let got = search(&pts);
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
