//! The weighting of thesis §4.4 kept as a ledger over a removal: every interior edge the
//! removal adds is charged to one vertex, as Lemmas 4.10–4.12 charge it, and Theorem
//! 4.2's claim (every weight at most 8, hence at most `8n` interior edges and `9n − 6`
//! tetrahedra by Lemma 4.9) is checked on the run instead of assumed.
//!
//! A piece with tip `x` adds two kinds of edges: `xu` for the vertices `u` of its bottom
//! not joined to `x` before, and the bottom's own edges. The charges, piece by piece in
//! the order of removal:
//! - an edge `xu`: `+1` to `u` (Lemma 4.11: `w(v) ← w(v) + 1` for `v ∈ V_x − {x}`);
//! - the bottom's new edges, when the piece is a cap of degree at most 5 with no vertex of
//!   `Q` under it (Step 1): all to the tip, at most 2 (Lemma 4.10);
//! - otherwise (Lemma 4.8's count, at most `|V(P_x)| + 3|V(Q_x)| − 3` for a bottom with
//!   boundary `P_x` and inner vertices `Q_x` of `Q`): up to `+3` to each vertex of `Q`
//!   inside the bottom, then `+1` to each boundary vertex but three (the lemma lets any
//!   three be skipped; the ledger skips the three heaviest).
//!
//! Only edges on neither `∂P` (two ends on one facet of `P`) nor `∂Q` (an edge of the
//! surface the removal ends with) are charged, each once, so the weights sum to the
//! mesh's interior edges exactly (the diagonals the thesis also counts, on polygon
//! facets, are boundary edges here; tested on every shell of `tests/shell.rs`).
//!
//! What the ledger measures is the removal that ran ([`Method::Cap`](super::Method::Cap)
//! or the greedy bigcaps), not BIGCAP-REMOVE's steps 2–6, which are not built: so where
//! the theorem's claim fails the ledger says so with the heaviest vertex (Bern disks,
//! where minimum-degree caps are `Θ(n log n)`, and twisted prisms at n = 10^5).

use crate::geom::Hull3;
use rustc_hash::FxHashSet as HashSet;
use std::ops::Range;

/// One piece a removal took: its tip, the vertices it removed, its bottom (every
/// triangle it left on the surface) and the range of its tetrahedra in the removal's.
pub(super) struct Record {
    pub tip: u32,
    pub removed: usize,
    pub bottom: Vec<[u32; 3]>,
    pub tets: Range<usize>,
}

/// Theorem 4.2's weights on a removal's mesh, in the shell's numbering.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ledger {
    /// The weight of each vertex of [`Shell::points`](super::Shell::points).
    pub weights: Vec<usize>,
}

impl Ledger {
    /// The largest weight and the first vertex that has it.
    pub fn heaviest(&self) -> (usize, u32) {
        let (v, w) = self
            .weights
            .iter()
            .enumerate()
            .rev()
            .max_by_key(|&(_, w)| w)
            .unwrap_or((0, &0));
        (*w, v as u32)
    }

    /// `histogram[w]`: how many vertices have weight `w`.
    pub fn histogram(&self) -> Vec<usize> {
        let mut h = vec![0; self.heaviest().0 + 1];
        for &w in &self.weights {
            h[w] += 1;
        }
        h
    }

    /// The edges charged: the sum of the weights.
    pub fn edges(&self) -> usize {
        self.weights.iter().sum()
    }
}

/// What the ledger is given: the removal that took every outer vertex.
pub(super) struct Removal<'r> {
    /// Its tetrahedra.
    pub tets: &'r [[u32; 4]],
    /// Its pieces, in order.
    pub records: &'r [Record],
    /// `P`, to tell its edges.
    pub outer: &'r Hull3,
    /// The surface it ended with: `∂Q`.
    pub last: &'r [[u32; 3]],
    /// The vertices on `∂P` at the start.
    pub on_surface: Vec<bool>,
}

/// The ledger of a finished removal.
pub(super) fn ledger(r: Removal) -> Ledger {
    let on_q: HashSet<(u32, u32)> = r
        .last
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .map(|(a, b)| (a.min(b), a.max(b)))
        .collect();
    // `ab` is on ∂P when both ends are on one facet of `P` (the facet lists are exact).
    let on_p = |a: u32, b: u32| {
        r.outer
            .common_facet(a as usize, b as usize, b as usize)
            .is_some()
    };
    // Each edge is decided once: charged the first time it is met, unless it is on `∂P`
    // or `∂Q`.
    let mut met: HashSet<(u32, u32)> = HashSet::default();
    let mut take = |a: u32, b: u32| {
        let e = (a.min(b), a.max(b));
        met.insert(e) && !on_q.contains(&e) && !on_p(a, b)
    };
    let (tets, mut on_surface) = (r.tets, r.on_surface);
    let mut w = vec![0; on_surface.len()];
    for r in r.records {
        let x = r.tip;
        for t in &tets[r.tets.clone()] {
            for &u in t.iter().filter(|&&u| u != x) {
                if take(x, u) {
                    w[u as usize] += 1;
                }
            }
        }
        let mut k = 0; // the bottom's new edges
        for t in &r.bottom {
            k += (0..3).filter(|&i| take(t[i], t[(i + 1) % 3])).count();
        }
        let mut corners: Vec<u32> = r.bottom.iter().flatten().copied().collect();
        corners.sort_unstable();
        corners.dedup();
        let (ring, inner): (Vec<u32>, Vec<u32>) =
            corners.iter().partition(|&&v| on_surface[v as usize]);
        charge_bottom(&mut w, k, r, ring, inner);
        for v in corners {
            on_surface[v as usize] = true;
        }
    }
    Ledger { weights: w }
}

/// Charges the `k` new edges of the bottom of piece `r`, whose boundary is `ring` and
/// whose vertices of `Q` inside are `inner`: to the tip for a small cap (Lemma 4.10),
/// else up to 3 to each inner vertex and 1 to each boundary vertex but the three
/// heaviest (Lemmas 4.8 and 4.11).
fn charge_bottom(w: &mut [usize], mut k: usize, r: &Record, mut ring: Vec<u32>, inner: Vec<u32>) {
    if r.removed == 1 && inner.is_empty() && ring.len() <= 5 {
        w[r.tip as usize] += k;
        return;
    }
    for q in inner {
        let c = k.min(3);
        w[q as usize] += c;
        k -= c;
    }
    ring.sort_by_key(|&v| (w[v as usize], v));
    let keep = ring.len().saturating_sub(3);
    for &v in &ring[..keep] {
        let c = k.min(1);
        w[v as usize] += c;
        k -= c;
    }
    // Lemma 4.8 says nothing is left; if something were, the tip takes it and the sum
    // stays exact.
    w[r.tip as usize] += k;
}
