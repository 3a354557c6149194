//! The LMT-skeleton (Dickerson and Montague; Belleville et al.), in the form of
//! Beirouti and Snoeyink with certain edges found by crossings.
//!
//! Each candidate edge is *alive*, *certain* (in every MWT) or *impossible* (in none).
//! Soundness rests on two facts about every MWT `M` (all of whose edges are candidates):
//! 1. `M` is locally minimal: an interior edge `pq` of `M` bounds triangles `pqr`, `pqs`
//!    of `M` whose edges are in `M`, hence alive, and if `prqs` is strictly convex then
//!    `|pq| ≤ |rs|`. An alive edge without such a pair of alive triangles is impossible.
//!    The triangles considered are those whose three edges are alive and which hold no
//!    candidate neighbour of `p` or `q` (a cheap test in the angular order around `p` and
//!    `q`; Haas 2018 walks the same order). A triangle with another site inside can only
//!    add certificates, which may keep alive an edge a strict emptiness test would drop,
//!    never drop an edge of `M`. On uniform sets the skeleton is the same as with exact
//!    emptiness tests.
//! 2. `M` is a maximal plane graph: an alive edge crossed by no alive edge crosses no
//!    edge of `M`, so it is in `M`, and is certain. Hull edges are certain.
//!
//! Each edge keeps the certificate it was last found alive with (the four other edges
//! of its two triangles), and is examined again only when one of those dies. Statuses
//! only ever move from alive to impossible or certain, so the examinations run in
//! parallel rounds: a stale "alive" read only makes a test more lenient, and the edge is
//! examined again in the next round.

use crate::control::Control;
use crate::geom::{Hull2, Point2, cmp_length, orient2d};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering::Relaxed};

/// Edge status codes.
pub const ALIVE: u8 = 0;
/// In every MWT.
pub const CERTAIN: u8 = 1;
/// In no MWT.
pub const IMPOSSIBLE: u8 = 2;

/// The candidate graph with edge statuses.
pub struct Skeleton {
    /// Candidate edges `[p, q]`, `p < q`.
    pub edges: Vec<[u32; 2]>,
    /// Status of each edge.
    pub status: Vec<u8>,
    /// Adjacency in compressed rows: `(neighbour, edge)` counter-clockwise around each
    /// site, from the direction of the positive x-axis.
    pub start: Vec<u32>,
    /// See `start`.
    pub adj: Vec<(u32, u32)>,
    /// For edge `[p, q]`: where `q` is in the row of `p`, and `p` in the row of `q`.
    pub pos: Vec<[u32; 2]>,
    /// Edges no triangulation considered may use: a flip to one of them is not
    /// available, so it does not refute local minimality.
    pub forbidden: std::collections::HashSet<[u32; 2]>,
}

impl Skeleton {
    /// The edges with status `status`, in order.
    pub fn with_status(&self, status: u8) -> Vec<[u32; 2]> {
        let pairs = self.edges.iter().zip(&self.status);
        pairs
            .filter(|(_, s)| **s == status)
            .map(|(e, _)| *e)
            .collect()
    }

    /// Neighbours of `v` with edge ids.
    pub fn around(&self, v: u32) -> &[(u32, u32)] {
        &self.adj[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }
}

/// For each edge `[p, q]`, where `q` is in the row of `p` and `p` in the row of `q`
/// (edges in parallel, each row scanned for the edge).
fn positions(start: &[u32], adj: &[(u32, u32)], edges: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let find = |v: u32, e: u32| {
        let row = start[v as usize]..start[v as usize + 1];
        row.into_iter()
            .find(|&i| adj[i as usize].1 == e)
            .expect("every edge in its rows")
    };
    (edges.par_iter().enumerate())
        .map(|(e, &[p, q])| [find(p, e as u32), find(q, e as u32)])
        .collect()
}

/// A site `v` with two candidate neighbours `a`, `b` in one direction, if any: then one
/// of `va`, `vb` passes through a site, which the candidate filter excludes and the
/// angular sweeps assume (rows in parallel; adjacent entries of a sorted row).
fn overlapping(points: &[Point2], start: &[u32], adj: &[(u32, u32)]) -> Option<[u32; 3]> {
    (0..start.len() as u32 - 1)
        .into_par_iter()
        .find_map_any(|v| {
            let row = &adj[start[v as usize] as usize..start[v as usize + 1] as usize];
            (row.windows(2))
                .find(|w| super::walks::angle_cmp(points, v, w[0].0, w[1].0).is_eq())
                .map(|w| [v, w[0].0, w[1].0])
        })
}

/// Hull edges (consecutive boundary sites, collinear ones included), as `[p, q]`, `p < q`.
pub(super) fn hull_edges(points: &[Point2], hull: &Hull2) -> Vec<[u32; 2]> {
    hull.boundary_chains(points)
        .iter()
        .flat_map(|c| {
            c.windows(2)
                .map(|w| [w[0].min(w[1]), w[0].max(w[1])])
                .collect::<Vec<_>>()
        })
        .collect()
}

/// The entries of the row of `v` after entry `i` (an index into `adj`), once round,
/// counter-clockwise or clockwise.
fn row_after(sk: &Skeleton, v: u32, i: u32, ccw: bool) -> impl Iterator<Item = (u32, u32)> + '_ {
    let (first, len) = (
        sk.start[v as usize],
        sk.start[v as usize + 1] - sk.start[v as usize],
    );
    let at = i - first;
    (1..len).map(move |k| {
        let j = if ccw { at + k } else { at + len - k };
        sk.adj[(first + if j >= len { j - len } else { j }) as usize]
    })
}

/// A triangle on an edge `pq`: its apex and the edges `p–apex`, `q–apex`.
type Apex = (u32, [u32; 2]);

/// The triangles left of `p → q` whose three edges are alive, except those with a
/// neighbour of `p` or `q` (alive or not) strictly inside: such a triangle is not empty,
/// so it is no face of a triangulation. `ip` is where `q` is in the row of `p`, `iq`
/// where `p` is in the row of `q`.
///
/// The neighbours of `p` left of `p → q` are the row of `p` counter-clockwise after `q`
/// (by angle `α` at `p` from `q`); those of `q` are the row of `q` clockwise before `p`
/// (by angle `γ` at `q` from `p`). A site `s` is inside triangle `pqr` exactly when
/// `α(s) < α(r)` and `γ(s) < γ(r)`, so a sweep in `α` keeping the least `γ`, and one in
/// `γ` keeping the least `α`, find the apexes with a neighbour inside (checked exactly).
fn left_triangles(
    points: &[Point2],
    sk: &Skeleton,
    status: &[AtomicU8],
    (p, ip): (u32, u32),
    (q, iq): (u32, u32),
    near: &mut Swept,
    mut found: impl FnMut(Apex) -> bool,
) -> bool {
    near.clear();
    let pt = |v: u32| &points[v as usize];
    let (pp, pq) = (pt(p), pt(q));
    let left = |v: u32| orient2d(pp, pq, pt(v)) > 0;
    // Neighbours of q by γ, each flagged when one swept before (smaller γ) has a smaller
    // α: it is inside. One orientation against the least α so far decides both that and
    // whether the neighbour is the new least.
    let mut least: Option<u32> = None;
    for (u, f) in row_after(sk, q, iq, false) {
        if !left(u) {
            break;
        }
        let o = least.map_or(1, |m| orient2d(pp, pt(u), pt(m)));
        near.push((u, f, o < 0));
        if o > 0 {
            least = Some(u);
        }
    }
    let near = near.index();
    // Neighbours of p by α, against the least γ so far.
    let alive = |f: u32| status[f as usize].load(Relaxed) != IMPOSSIBLE;
    let mut least: Option<u32> = None;
    for (t, g) in row_after(sk, p, ip, true) {
        if !left(t) {
            break;
        }
        let o = least.map_or(-1, |m| orient2d(pq, pt(t), pt(m)));
        if o <= 0
            && let Some((_, f, hidden)) = near.find(t)
            && !hidden
            && alive(f)
            && alive(g)
            && found((t, [g, f]))
        {
            return true;
        }
        if o < 0 {
            least = Some(t);
        }
    }
    false
}

/// Per-thread buffers: the triangles left of an edge, and a sweep's neighbours.
type Buffers = (Vec<Apex>, Swept);

/// The neighbours of `q` a sweep of [`left_triangles`] has seen: site, edge to it, and
/// whether one seen before lies inside its triangle. Looked up by site through
/// [`Swept::index`] once complete; past 16 (rows of anisotropic sets run to hundreds)
/// through an open-addressing table, not a scan.
#[derive(Default)]
struct Swept {
    list: Vec<(u32, u32, bool)>,
    /// Positions in `list` by hashed site (`u32::MAX`: empty).
    table: Vec<u32>,
}

/// A complete [`Swept`], looked up by site.
struct Lookup<'a> {
    list: &'a [(u32, u32, bool)],
    /// The table, for a long list.
    table: Option<&'a [u32]>,
}

/// Lists up to this long are scanned.
const SCAN: usize = 16;

fn slot(v: u32, size: usize) -> usize {
    ((v as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 32) as usize & (size - 1)
}

impl Swept {
    fn clear(&mut self) {
        self.list.clear();
    }

    fn push(&mut self, x: (u32, u32, bool)) {
        self.list.push(x);
    }

    /// The list, indexed by site (the only way to look it up, so no stale table is read).
    fn index(&mut self) -> Lookup<'_> {
        if self.list.len() <= SCAN {
            return Lookup {
                list: &self.list,
                table: None,
            };
        }
        let size = (2 * self.list.len()).next_power_of_two();
        self.table.clear();
        self.table.resize(size, u32::MAX);
        for (k, e) in self.list.iter().enumerate() {
            let mut h = slot(e.0, size);
            while self.table[h] != u32::MAX {
                h = (h + 1) & (size - 1);
            }
            self.table[h] = k as u32;
        }
        Lookup {
            list: &self.list,
            table: Some(&self.table),
        }
    }
}

impl Lookup<'_> {
    fn find(&self, v: u32) -> Option<(u32, u32, bool)> {
        let Some(table) = self.table else {
            return self.list.iter().find(|b| b.0 == v).copied();
        };
        let mut h = slot(v, table.len());
        loop {
            let k = table[h];
            if k == u32::MAX {
                return None;
            }
            if self.list[k as usize].0 == v {
                return Some(self.list[k as usize]);
            }
            h = (h + 1) & (table.len() - 1);
        }
    }
}

/// A pair of alive triangles on `e` that makes it locally minimal, as the four other
/// edges (left pair, right pair), if there is one.
fn certificate(
    points: &[Point2],
    sk: &Skeleton,
    status: &[AtomicU8],
    e: u32,
    (left, near): &mut Buffers,
) -> Option<[u32; 4]> {
    let [p, q] = sk.edges[e as usize];
    let [ip, iq] = sk.pos[e as usize];
    left.clear();
    left_triangles(points, sk, status, (p, ip), (q, iq), near, |t| {
        left.push(t);
        false
    });
    if left.is_empty() {
        return None;
    }
    let pt = |i: u32| &points[i as usize];
    let (pp, pq) = (pt(p), pt(q));
    // Each triangle on the right against those on the left, as it is found.
    let mut cert = None;
    left_triangles(points, sk, status, (q, iq), (p, ip), near, |(s, [d, c])| {
        cert = left.iter().find_map(|&(r, [a, b])| {
            let convex = orient2d(pt(r), pt(s), pp) * orient2d(pt(r), pt(s), pq) < 0;
            let flip_shorter = convex && cmp_length(pp, pq, pt(r), pt(s)).is_gt();
            let flip_allowed =
                sk.forbidden.is_empty() || !sk.forbidden.contains(&[r.min(s), r.max(s)]);
            (!flip_shorter || !flip_allowed).then_some([a, b, c, d])
        });
        cert.is_some()
    });
    cert
}

/// Edges per task in a round: a task owns the certificates of one block of edge ids.
const BLOCK: usize = 4096;

/// Runs the LMT rounds from `queue` (sorted) to a fixpoint, or until `ctl` is stopped
/// (every status set by then is sound; more edges stay alive).
fn eliminate(
    points: &[Point2],
    sk: &Skeleton,
    status: &[AtomicU8],
    mut queue: Vec<u32>,
    ctl: &Control,
) {
    let m = sk.edges.len();
    let queued: Vec<AtomicBool> = (0..m).map(|_| AtomicBool::new(false)).collect();
    // Zeroed, so its pages are untouched until written. Every alive edge is examined in
    // the first round and holds a certificate from then on: only alive edges' entries
    // are read.
    let mut certs = vec![[0u32; 4]; m];
    while !queue.is_empty() && !ctl.is_stopped() {
        let dead: Vec<u32> = (certs.par_chunks_mut(BLOCK).enumerate())
            .map_init(Buffers::default, |bufs, (b, block)| {
                let ids = (b * BLOCK) as u32..(b * BLOCK + block.len()) as u32;
                let lo = queue.partition_point(|e| *e < ids.start);
                let hi = queue.partition_point(|e| *e < ids.end);
                let mut dead = Vec::new();
                for &e in &queue[lo..hi] {
                    if ctl.is_stopped() {
                        break;
                    }
                    queued[e as usize].store(false, Relaxed);
                    if status[e as usize].load(Relaxed) != ALIVE {
                        continue;
                    }
                    match certificate(points, sk, status, e, bufs) {
                        Some(c) => block[(e - ids.start) as usize] = c,
                        None => {
                            status[e as usize].store(IMPOSSIBLE, Relaxed);
                            dead.push(e);
                        }
                    }
                }
                dead
            })
            .flatten_iter()
            .collect();
        // Examine again the alive edges whose certificate used a dead edge. While many
        // edges die, every alive edge checks its certificate; later, only the edges
        // around the dead ones (they share an endpoint with them) are checked.
        let requeue = |f: u32| {
            status[f as usize].load(Relaxed) == ALIVE
                && (certs[f as usize].iter())
                    .any(|&c| status[c as usize].load(Relaxed) == IMPOSSIBLE)
                && !queued[f as usize].swap(true, Relaxed)
        };
        queue = if dead.len() * FULL_SCAN_RATIO > m {
            (0..m as u32)
                .into_par_iter()
                .filter(|&f| requeue(f))
                .collect()
        } else {
            let mut around: Vec<u32> = (dead.par_iter())
                .map(|&e| {
                    let [p, q] = sk.edges[e as usize];
                    (sk.around(p).iter().chain(sk.around(q)))
                        .map(|&(_, f)| f)
                        .filter(|&f| requeue(f))
                        .collect::<Vec<u32>>()
                })
                .flatten_iter()
                .collect();
            around.par_sort_unstable();
            around
        };
    }
}

/// A round in which more than one edge in this many died checks every certificate
/// for dead edges (a pass in edge order, at 10^6 sites 35–120 ms) rather than the edges
/// around each dead one (46 random reads per dead edge; ten times slower in the first
/// rounds, faster once few edges die).
const FULL_SCAN_RATIO: usize = 256;

/// Alive edges crossed by no other alive (or certain) edge.
fn crossed_by_none(points: &[Point2], sk: &Skeleton) -> Vec<usize> {
    let kept: Vec<u32> = (0..sk.edges.len() as u32)
        .filter(|&e| sk.status[e as usize] != IMPOSSIBLE)
        .collect();
    let grid = super::edge_grid::EdgeGrid::new(points, &sk.edges, &kept);
    kept.par_iter()
        .filter(|&&e| sk.status[e as usize] == ALIVE && !grid.crossed(points, &sk.edges, e))
        .map(|&e| e as usize)
        .collect()
}

/// Statistics of an LMT run.
#[derive(Clone, Copy, Debug, Default)]
pub struct LmtStats {
    /// Certain edges at the end.
    pub certain: usize,
    /// Edges still undecided.
    pub undecided: usize,
    /// The rounds reached their fixpoint (not stopped by the control first).
    pub complete: bool,
}

/// Computes the LMT-skeleton of `candidates` (sorted `[p, q]`, `p < q`, containing every
/// MWT edge), with `forced` edges taken as certain (their crossers impossible).
/// `Err([v, a, b])` when candidates `va` and `vb` share a direction (one of them passes
/// through a site): the sweeps' premise, so nothing is decided.
pub fn lmt_skeleton(
    points: &[Point2],
    hull: &Hull2,
    candidates: Vec<[u32; 2]>,
    forced: &[[u32; 2]],
    forbidden: &[[u32; 2]],
    ctl: &Control,
) -> Result<(Skeleton, LmtStats), [u32; 3]> {
    let (start, adj) = super::walks::ccw_rows(points, &candidates);
    if let Some(v_a_b) = overlapping(points, &start, &adj) {
        return Err(v_a_b);
    }
    let pos = positions(&start, &adj, &candidates);
    let mut sk = Skeleton {
        status: vec![ALIVE; candidates.len()],
        edges: candidates,
        start,
        adj,
        pos,
        forbidden: forbidden.iter().copied().collect(),
    };
    let find = |sk: &Skeleton, e: &[u32; 2]| sk.edges.binary_search(e).ok();
    for e in hull_edges(points, hull).iter().chain(forced) {
        if let Some(id) = find(&sk, e) {
            sk.status[id] = CERTAIN;
        }
    }
    if !forced.is_empty() {
        for (id, e) in sk.edges.iter().enumerate() {
            let pt = |i: u32| &points[i as usize];
            for f in forced {
                if e != f && super::cross(pt(e[0]), pt(e[1]), pt(f[0]), pt(f[1])) {
                    sk.status[id] = IMPOSSIBLE;
                }
            }
        }
    }
    let status: Vec<AtomicU8> = sk.status.iter().map(|&s| AtomicU8::new(s)).collect();
    let queue: Vec<u32> = (0..sk.edges.len() as u32)
        .filter(|&e| sk.status[e as usize] == ALIVE)
        .collect();
    eliminate(points, &sk, &status, queue, ctl);
    sk.status = status.into_iter().map(|s| s.into_inner()).collect();
    // An alive edge that no alive edge crosses is in every MWT (fact 2). Promotion
    // changes no LMT test, so one pass suffices; stopped, it is skipped (it only adds
    // certain edges, and early on it would test nearly every candidate).
    let complete = !ctl.is_stopped();
    if complete {
        for e in crossed_by_none(points, &sk) {
            sk.status[e] = CERTAIN;
        }
    }
    let certain = sk.status.iter().filter(|&&s| s == CERTAIN).count();
    let undecided = sk.status.iter().filter(|&&s| s == ALIVE).count();
    let stats = LmtStats {
        certain,
        undecided,
        complete,
    };
    Ok((sk, stats))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planar::{Distribution, points2d};

    /// A stop flag never set.
    fn go() -> Control {
        Control::new()
    }

    /// The triangles left of `p → q` by definition: common neighbours with both edges
    /// alive, and no neighbour of `p` or `q` strictly inside.
    fn brute_left(points: &[Point2], sk: &Skeleton, alive: &[bool], p: u32, q: u32) -> Vec<u32> {
        let pt = |v: u32| &points[v as usize];
        let edge = |a: u32, b: u32| sk.around(a).iter().find(|x| x.0 == b).map(|x| x.1);
        let inside = |s: u32, r: u32| {
            orient2d(pt(p), pt(q), pt(s)) > 0
                && orient2d(pt(q), pt(r), pt(s)) > 0
                && orient2d(pt(r), pt(p), pt(s)) > 0
        };
        let mut out: Vec<u32> = (sk.around(p).iter())
            .filter(|&&(r, g)| {
                let f = edge(q, r);
                orient2d(pt(p), pt(q), pt(r)) > 0
                    && f.is_some_and(|f| alive[f as usize] && alive[g as usize])
                    && !(sk.around(p).iter().chain(sk.around(q))).any(|&(s, _)| inside(s, r))
            })
            .map(|&(r, _)| r)
            .collect();
        out.sort_unstable();
        out
    }

    /// The candidate graph of `pts`, every edge alive.
    fn all_alive(pts: &[Point2]) -> Skeleton {
        let cands = super::super::candidates::search(pts, usize::MAX, &go()).unwrap();
        let (start, adj) = super::super::walks::ccw_rows(pts, &cands);
        let pos = positions(&start, &adj, &cands);
        Skeleton {
            status: vec![ALIVE; cands.len()],
            edges: cands,
            start,
            adj,
            pos,
            forbidden: Default::default(),
        }
    }

    /// The rounds that examine only the edges whose certificate lost an edge reach the
    /// same fixpoint as plain rounds over every alive edge.
    #[test]
    fn incremental_rounds_reach_the_plain_fixpoint() {
        for (dist, n, seed) in [
            (Distribution::Uniform, 4000, 1),
            (Distribution::Clustered, 4000, 2),
            (Distribution::Grid, 900, 3),
        ] {
            let pts = points2d(dist, n, seed);
            let mut plain = all_alive(&pts);
            for e in hull_edges(&pts, &Hull2::new(&pts)) {
                if let Ok(id) = plain.edges.binary_search(&e) {
                    plain.status[id] = CERTAIN;
                }
            }
            let status: Vec<AtomicU8> = plain.status.iter().map(|&s| AtomicU8::new(s)).collect();
            let mut bufs = Buffers::default();
            loop {
                let dead: Vec<u32> = (0..plain.edges.len() as u32)
                    .filter(|&e| status[e as usize].load(Relaxed) == ALIVE)
                    .filter(|&e| certificate(&pts, &plain, &status, e, &mut bufs).is_none())
                    .collect();
                if dead.is_empty() {
                    break;
                }
                for e in dead {
                    status[e as usize].store(IMPOSSIBLE, Relaxed);
                }
            }
            let (sk, _) = lmt_skeleton(
                &pts,
                &Hull2::new(&pts),
                plain.edges.clone(),
                &[],
                &[],
                &go(),
            )
            .unwrap();
            let kept = |s: &[u8]| -> Vec<bool> { s.iter().map(|&s| s != IMPOSSIBLE).collect() };
            let plain_status: Vec<u8> = status.iter().map(|s| s.load(Relaxed)).collect();
            assert_eq!(kept(&sk.status), kept(&plain_status), "{dist:?}");
        }
    }

    /// With every segment a candidate (as for constrained optima), the elimination still
    /// fixes most of the MWT. It once was skipped past a work budget (`Σ deg²`), and dense
    /// rows of collinear sites went whole to the exact stage, as one face.
    #[test]
    fn the_elimination_runs_with_every_segment_a_candidate() {
        let pts = points2d(Distribution::Uniform, 600, 5);
        let n = pts.len() as u32;
        let all: Vec<[u32; 2]> = (0..n)
            .flat_map(|a| (a + 1..n).map(move |b| [a, b]))
            .collect();
        let (_, stats) = lmt_skeleton(&pts, &Hull2::new(&pts), all, &[], &[], &go()).unwrap();
        assert!(stats.certain > 2 * pts.len(), "{} certain", stats.certain);
    }

    #[test]
    fn left_triangles_match_their_definition() {
        for (dist, n, seed) in [
            (Distribution::Uniform, 120, 1),
            (Distribution::Grid, 100, 2),
            (Distribution::Clustered, 120, 3),
            (Distribution::Regular, 30, 4),
        ] {
            let pts = points2d(dist, n, seed);
            let sk = all_alive(&pts);
            let mut rng = crate::rng::Rng::new(seed);
            let alive: Vec<bool> = (0..sk.edges.len()).map(|_| rng.unit() < 0.8).collect();
            let status: Vec<AtomicU8> = (alive.iter())
                .map(|&a| AtomicU8::new(if a { ALIVE } else { IMPOSSIBLE }))
                .collect();
            let mut near = Swept::default();
            for (e, &[p, q]) in sk.edges.iter().enumerate() {
                let [ip, iq] = sk.pos[e];
                for ((a, ia), (b, ib)) in [((p, ip), (q, iq)), ((q, iq), (p, ip))] {
                    let mut got = Vec::new();
                    left_triangles(&pts, &sk, &status, (a, ia), (b, ib), &mut near, |t| {
                        got.push(t.0);
                        false
                    });
                    got.sort_unstable();
                    assert_eq!(
                        got,
                        brute_left(&pts, &sk, &alive, a, b),
                        "{dist:?} {a}->{b}"
                    );
                }
            }
        }
    }
}
