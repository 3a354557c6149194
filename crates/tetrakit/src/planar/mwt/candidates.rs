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
//! beyond the radius already searched. The bounds carry a 0.1% margin, far above the
//! rounding of the float distances and angles, and only ever skip edges that the exact
//! test would exclude.

use crate::geom::{Point2, diamond_hit};
use crate::planar::grid::PointGrid;
use rayon::prelude::*;

const SECTORS: usize = 64;
const WIDTH: f64 = std::f64::consts::TAU / SECTORS as f64;
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
    /// `kill[i]`: the distance factor for a site `i` sectors away (i = 2..=5).
    kill: [f64; 6],
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
        Sectors { bounds, kill }
    }

    fn of(&self, dx: f64, dy: f64) -> usize {
        let a = pseudo_angle(dx, dy);
        self.bounds.partition_point(|&b| b <= a).saturating_sub(1)
    }
}

/// Per-thread scratch space.
#[derive(Default)]
struct Scratch {
    by_sector: Vec<Vec<u32>>,
    nearest: Vec<f64>,
    pending: Vec<(f64, u32)>,
}

/// All candidate edges `[p, q]` (`p < q`), sorted.
pub fn candidate_edges(points: &[Point2]) -> Vec<[u32; 2]> {
    let grid = PointGrid::new(points, 2.0);
    let sectors = Sectors::new();
    let mut edges: Vec<[u32; 2]> = (0..points.len() as u32)
        .into_par_iter()
        .map_init(Scratch::default, |s, p| {
            let mut out = Vec::new();
            candidates_of(p, points, &grid, &sectors, s, &mut out);
            out
        })
        .flatten_iter()
        .collect();
    edges.par_sort_unstable();
    edges
}

fn dead_radius(s: &Scratch, sec: &Sectors, k: usize) -> f64 {
    let side = |sign: isize| {
        (2..=5)
            .map(|i| {
                let j = (k as isize + sign * i as isize).rem_euclid(SECTORS as isize) as usize;
                s.nearest[j] * sec.kill[i]
            })
            .fold(f64::INFINITY, f64::min)
    };
    side(1).max(side(-1))
}

fn candidates_of(
    p: u32,
    points: &[Point2],
    grid: &PointGrid,
    sec: &Sectors,
    s: &mut Scratch,
    out: &mut Vec<[u32; 2]>,
) {
    s.by_sector.resize_with(SECTORS, Vec::new);
    s.by_sector.iter_mut().for_each(Vec::clear);
    s.nearest.clear();
    s.nearest.resize(SECTORS, f64::INFINITY);
    s.pending.clear();
    let pp = points[p as usize];
    let (cx, cy) = grid.cell_of(&pp);
    let (nx, ny) = grid.dims();
    let mut ring = 0usize;
    loop {
        gather_ring(grid, points, p, cx, cy, ring, &mut s.pending);
        let exhausted = ring >= cx && ring >= cy && cx + ring >= nx - 1 && cy + ring >= ny - 1;
        let complete = if exhausted {
            f64::INFINITY
        } else {
            ring as f64 * grid.cell()
        };
        s.pending.sort_unstable_by(|a, b| b.0.total_cmp(&a.0));
        while let Some(&(d2, q)) = s.pending.last() {
            if d2 >= complete * complete {
                break;
            }
            s.pending.pop();
            let pq = points[q as usize];
            let (dx, dy) = (pq[0] - pp[0], pq[1] - pp[1]);
            let k = sec.of(dx, dy);
            let d = d2.sqrt();
            if q > p && d <= dead_radius(s, sec, k) && diamonds_open(p, q, points, s, k) {
                out.push([p, q]);
            }
            s.by_sector[k].push(q);
            s.nearest[k] = s.nearest[k].min(d);
        }
        if exhausted {
            return;
        }
        let dead = (0..SECTORS)
            .map(|k| dead_radius(s, sec, k))
            .fold(0.0, f64::max);
        if dead < complete {
            return;
        }
        ring += 1;
    }
}

/// Pushes `(squared distance, index)` of the sites in ring `r` around cell `(cx, cy)`.
fn gather_ring(
    grid: &PointGrid,
    points: &[Point2],
    p: u32,
    cx: usize,
    cy: usize,
    r: usize,
    pending: &mut Vec<(f64, u32)>,
) {
    let (nx, ny) = grid.dims();
    let pp = points[p as usize];
    let mut push = |items: &[u32]| {
        for &q in items {
            if q != p {
                let a = points[q as usize];
                let (dx, dy) = (a[0] - pp[0], a[1] - pp[1]);
                pending.push((dx * dx + dy * dy, q));
            }
        }
    };
    let x0 = cx.saturating_sub(r);
    let x1 = (cx + r).min(nx - 1);
    for y in cy.saturating_sub(r)..=(cy + r).min(ny - 1) {
        if y + r == cy || y == cy + r {
            push(grid.row(y, x0, x1));
        } else {
            if cx >= r {
                push(grid.row(y, cx - r, cx - r));
            }
            if cx + r < nx && r > 0 {
                push(grid.row(y, cx + r, cx + r));
            }
        }
    }
}

/// True when `pq` has an empty diamond and no site on its open segment, among the
/// visited sites (which include every site that could be in either).
fn diamonds_open(p: u32, q: u32, points: &[Point2], s: &Scratch, k: usize) -> bool {
    let (a, b) = (&points[p as usize], &points[q as usize]);
    let (mut left, mut right) = (false, false);
    for off in 0..=2 * REACH {
        let j = (k + SECTORS + off - REACH) % SECTORS;
        for &r in &s.by_sector[j] {
            let h = diamond_hit(a, b, &points[r as usize]);
            left |= h.left;
            right |= h.right;
            if h.on_segment || (left && right) {
                return false;
            }
        }
    }
    true
}
