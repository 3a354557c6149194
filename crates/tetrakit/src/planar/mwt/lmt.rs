//! The LMT-skeleton (Dickerson and Montague; Belleville et al.), in the form of
//! Beirouti and Snoeyink with certain edges found by crossings.
//!
//! Each candidate edge is *alive*, *certain* (in every MWT) or *impossible* (in none).
//! Soundness rests on two facts about every MWT `M` (all of whose edges are candidates):
//! 1. `M` is locally minimal: an interior edge `pq` of `M` bounds triangles `pqr`, `pqs`
//!    of `M` whose edges are in `M`, hence alive, and if `prqs` is strictly convex then
//!    `|pq| ≤ |rs|`. An alive edge without such a pair of alive triangles is impossible.
//! 2. `M` is a maximal plane graph: an alive edge crossed by no alive edge crosses no
//!    edge of `M`, so it is in `M`, and is certain. Hull edges are certain.
//!
//! Statuses only ever move from alive to impossible or certain, so the per-edge tests
//! run in parallel rounds: a stale "alive" read only makes a test more lenient.

use crate::geom::{Hull2, Point2, cmp_length, orient2d};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering::Relaxed};

/// Edge status codes.
pub const ALIVE: u8 = 0;
/// In every MWT.
pub const CERTAIN: u8 = 1;
/// In no MWT.
pub const IMPOSSIBLE: u8 = 2;

/// An empty candidate triangle seen from one of its edges `[p, q]` (`p < q`).
#[derive(Clone, Copy, Debug, Default)]
pub struct Tri {
    /// The third vertex.
    pub apex: u32,
    /// The edges `p–apex` and `q–apex`.
    pub sides: [u32; 2],
    /// Orientation of `p, q, apex` (+1: the apex is left of `p → q`).
    pub turn: i8,
}

/// The candidate graph with edge statuses.
pub struct Skeleton {
    /// Candidate edges `[p, q]`, `p < q`.
    pub edges: Vec<[u32; 2]>,
    /// Status of each edge.
    pub status: Vec<u8>,
    /// Adjacency in compressed rows: `(neighbour, edge)` sorted by neighbour.
    pub start: Vec<u32>,
    /// See `start`.
    pub adj: Vec<(u32, u32)>,
    /// Empty candidate triangles per edge, in compressed rows.
    pub tri_start: Vec<u32>,
    /// See `tri_start`.
    pub tris: Vec<Tri>,
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

    /// Empty candidate triangles on edge `e`.
    pub fn triangles(&self, e: u32) -> &[Tri] {
        &self.tris[self.tri_start[e as usize] as usize..self.tri_start[e as usize + 1] as usize]
    }

    /// For edge `e = [p, q]`, calls `f(r, edge p–r, edge q–r)` for every common
    /// neighbour `r > q` (so each candidate triangle once, from its two smallest
    /// vertices): a merge of the two sorted neighbour lists.
    fn third_vertices(&self, e: u32, mut f: impl FnMut(u32, u32, u32)) {
        let [p, q] = self.edges[e as usize];
        let (a, b) = (self.around(p), self.around(q));
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                std::cmp::Ordering::Less => i += 1,
                std::cmp::Ordering::Greater => j += 1,
                std::cmp::Ordering::Equal => {
                    if a[i].0 > q {
                        f(a[i].0, a[i].1, b[j].1);
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
    }

    /// Neighbours of `v` with edge ids.
    pub fn around(&self, v: u32) -> &[(u32, u32)] {
        &self.adj[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }
}

/// Adjacency sorted by neighbour (for merging neighbour lists).
fn adjacency(n: usize, edges: &[[u32; 2]]) -> (Vec<u32>, Vec<(u32, u32)>) {
    let (start, mut adj) = super::walks::csr(n, edges);
    for v in 0..n {
        adj[start[v] as usize..start[v + 1] as usize].sort_unstable();
    }
    (start, adj)
}

/// Hull edges (consecutive boundary sites, collinear ones included), as `[p, q]`, `p < q`.
fn hull_edges(points: &[Point2]) -> Vec<[u32; 2]> {
    Hull2::new(points)
        .boundary_chains(points)
        .iter()
        .flat_map(|c| {
            c.windows(2)
                .map(|w| [w[0].min(w[1]), w[0].max(w[1])])
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Every empty triangle whose three edges are candidates, listed on each of its edges.
/// A face of a triangulation is empty, so only these can witness local minimality;
/// emptiness is static and computed once (a grid query per triangle).
fn empty_triangles(points: &[Point2], sk: &Skeleton) -> (Vec<u32>, Vec<Tri>) {
    let grid = crate::planar::grid::PointGrid::new(points, 2.0);
    let pt = |i: u32| &points[i as usize];
    let inc: Vec<(u32, Tri)> = (0..sk.edges.len() as u32)
        .into_par_iter()
        .flat_map_iter(|e| {
            let [p, q] = sk.edges[e as usize];
            let mut out = Vec::new();
            sk.third_vertices(e, |r, epr, eqr| {
                let o = orient2d(pt(p), pt(q), pt(r));
                if o == 0 || !triangle_empty(points, &grid, p, q, r, o) {
                    return;
                }
                // p < q < r: seen from [p, r] the apex q turns -o, from [q, r] the apex
                // p turns o.
                let tri = |apex, sides, turn| Tri { apex, sides, turn };
                out.push((e, tri(r, [epr, eqr], o)));
                out.push((epr, tri(q, [e, eqr], -o)));
                out.push((eqr, tri(p, [e, epr], o)));
            });
            out
        })
        .collect();
    crate::rows::buckets(sk.edges.len(), inc.iter().map(|&(e, t)| (e as usize, t)))
}

/// The number of triangles whose three edges are candidates (empty or not): a merge of
/// two sorted neighbour lists per edge.
fn candidate_triangles(sk: &Skeleton) -> usize {
    (0..sk.edges.len() as u32)
        .into_par_iter()
        .map(|e| {
            let mut count = 0;
            sk.third_vertices(e, |_, _, _| count += 1);
            count
        })
        .sum()
}

/// True when no site lies strictly inside triangle `pqr` (orientation `o`); candidate
/// edges carry no site on their interiors, so the boundary needs no test.
fn triangle_empty(
    points: &[Point2],
    grid: &crate::planar::grid::PointGrid,
    p: u32,
    q: u32,
    r: u32,
    o: i8,
) -> bool {
    let pt = |i: u32| &points[i as usize];
    let (a, b, c) = if o > 0 { (p, q, r) } else { (p, r, q) };
    let lo = [
        pt(a)[0].min(pt(b)[0]).min(pt(c)[0]),
        pt(a)[1].min(pt(b)[1]).min(pt(c)[1]),
    ];
    let hi = [
        pt(a)[0].max(pt(b)[0]).max(pt(c)[0]),
        pt(a)[1].max(pt(b)[1]).max(pt(c)[1]),
    ];
    !grid.any_in_exact_box(lo, hi, |t| {
        t != a && t != b && t != c && {
            let x = pt(t);
            x[0] >= lo[0]
                && x[0] <= hi[0]
                && x[1] >= lo[1]
                && x[1] <= hi[1]
                && orient2d(pt(a), pt(b), x) > 0
                && orient2d(pt(b), pt(c), x) > 0
                && orient2d(pt(c), pt(a), x) > 0
        }
    })
}

/// The alive empty triangles on edge `e`.
fn alive_triangles(sk: &Skeleton, status: &[AtomicU8], e: u32, out: &mut Vec<Tri>) {
    out.clear();
    out.extend(sk.triangles(e).iter().copied().filter(|t| {
        t.sides
            .iter()
            .all(|&f| status[f as usize].load(Relaxed) != IMPOSSIBLE)
    }));
}

/// True when the edge has a locally minimal pair of alive triangles.
fn locally_minimal(
    points: &[Point2],
    sk: &Skeleton,
    status: &[AtomicU8],
    e: u32,
    buf: &mut Vec<Tri>,
) -> bool {
    let [p, q] = sk.edges[e as usize];
    alive_triangles(sk, status, e, buf);
    let pt = |i: u32| &points[i as usize];
    let (pp, pq) = (pt(p), pt(q));
    for left in buf.iter().filter(|t| t.turn > 0) {
        for right in buf.iter().filter(|t| t.turn < 0) {
            let (r, s) = (left.apex, right.apex);
            let (a, b) = (orient2d(pt(r), pt(s), pp), orient2d(pt(r), pt(s), pq));
            let convex = a * b < 0;
            if !convex
                || cmp_length(pp, pq, pt(r), pt(s)) != std::cmp::Ordering::Greater
                || sk.forbidden.contains(&[r.min(s), r.max(s)])
            {
                return true;
            }
        }
    }
    false
}

/// Runs the LMT rounds from `queue` to a fixpoint.
fn eliminate(points: &[Point2], sk: &Skeleton, status: &[AtomicU8], mut queue: Vec<u32>) {
    let queued: Vec<AtomicBool> = (0..sk.edges.len())
        .map(|_| AtomicBool::new(false))
        .collect();
    while !queue.is_empty() {
        let dead: Vec<u32> = queue
            .par_iter()
            .map_init(Vec::new, |buf, &e| {
                queued[e as usize].store(false, Relaxed);
                let ok = status[e as usize].load(Relaxed) != ALIVE
                    || locally_minimal(points, sk, status, e, buf);
                if !ok {
                    status[e as usize].store(IMPOSSIBLE, Relaxed);
                }
                (!ok).then_some(e)
            })
            .flatten_iter()
            .collect();
        queue = dead
            .par_iter()
            .map(|&e| {
                // Every triangle on e, dead or alive: when two edges of a triangle die
                // in one round, the third must still be rechecked.
                sk.triangles(e)
                    .iter()
                    .flat_map(|t| t.sides)
                    .filter(|&f| {
                        status[f as usize].load(Relaxed) == ALIVE
                            && !queued[f as usize].swap(true, Relaxed)
                    })
                    .collect::<Vec<u32>>()
            })
            .flatten_iter()
            .collect();
    }
}

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
}

/// Candidate triangles (about 60 bytes each once listed) allowed beyond `64·n`.
const TRIANGLE_BUDGET: usize = 20_000_000;

/// Computes the LMT-skeleton of `candidates` (sorted `[p, q]`, `p < q`, containing every
/// MWT edge), with `forced` edges taken as certain (their crossers impossible).
pub fn lmt_skeleton(
    points: &[Point2],
    candidates: Vec<[u32; 2]>,
    forced: &[[u32; 2]],
    forbidden: &[[u32; 2]],
) -> (Skeleton, LmtStats) {
    let n = points.len();
    let (start, adj) = adjacency(n, &candidates);
    let mut sk = Skeleton {
        status: vec![ALIVE; candidates.len()],
        edges: candidates,
        start,
        adj,
        tri_start: Vec::new(),
        tris: Vec::new(),
        forbidden: forbidden.iter().copied().collect(),
    };
    // Sites in (near) convex position make Θ(n³) empty triangles and no LMT
    // progress; past the budget the elimination is skipped (every candidate stays
    // alive, which is sound) and the exact stage gets the whole face.
    let eliminating = candidate_triangles(&sk) <= TRIANGLE_BUDGET.max(64 * n);
    if eliminating {
        (sk.tri_start, sk.tris) = empty_triangles(points, &sk);
    } else {
        sk.tri_start = vec![0; sk.edges.len() + 1];
    }
    let find = |sk: &Skeleton, e: &[u32; 2]| sk.edges.binary_search(e).ok();
    for e in hull_edges(points).iter().chain(forced) {
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
    if eliminating {
        eliminate(points, &sk, &status, queue);
    }
    sk.status = status.into_iter().map(|s| s.into_inner()).collect();
    // An alive edge that no alive edge crosses is in every MWT (fact 2). Promotion
    // changes no LMT test, so one pass suffices.
    let promote: Vec<usize> = crossed_by_none(points, &sk);
    for e in promote {
        sk.status[e] = CERTAIN;
    }
    let certain = sk.status.iter().filter(|&&s| s == CERTAIN).count();
    let undecided = sk.status.iter().filter(|&&s| s == ALIVE).count();
    let stats = LmtStats { certain, undecided };
    (sk, stats)
}
