//! Planar proximity structures of thesis ch. 5: β-skeletons ([`beta_skeleton`]), exact
//! minimum weight triangulations ([`mwt`]), and the counterexample to Keil's conjecture
//! of §5.2–5.3 ([`keil`]).
//!
//! Every decision is exact: β is a rational ([`Ratio`](crate::geom::Ratio)), regions are
//! tested by polynomial signs ([`crate::geom::in_beta_region`]), and weights are compared
//! with certified intervals and an exact fallback for sums of square roots
//! ([`crate::geom::compare_root_sums`]).

mod delaunay;
mod forced;
mod generate;
mod grid;
mod keil;
mod mwt;
mod skeleton;

pub use delaunay::{Delaunay, DelaunayEdge, delaunay};
pub use forced::{Blocker, blocked_pairs, edge_blocker};
pub use generate::{Distribution, points2d};
pub use keil::{KeilResult, above_cheng_xu, check_random, in_keil_interval, keil, keil_sites};
pub use mwt::{
    Mwt, MwtOptions, MwtStats, candidate_edges, cmp_edge_sets, mwt, mwt_with, weight_of,
};
pub use skeleton::{Region, Skeleton, beta_skeleton};

/// Union-find root with path halving (cells of cocircular Delaunay triangles, faces of
/// the certain edges).
pub(crate) fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        parent[x as usize] = parent[parent[x as usize] as usize];
        x = parent[x as usize];
    }
    x
}

/// The edge `ab` as `[min, max]`.
pub(crate) fn edge_key(a: u32, b: u32) -> [u32; 2] {
    [a.min(b), a.max(b)]
}

/// Compressed rows: `entries` `(bucket, item)` with buckets below `n`, grouped by bucket
/// (a counting sort, stable within a bucket). Returns the row starts (`n + 1` of them)
/// and the items. Used for the point and edge grids, adjacency lists and edge lists.
pub(crate) fn buckets<T: Copy + Default>(
    n: usize,
    entries: impl Iterator<Item = (usize, T)> + Clone,
) -> (Vec<u32>, Vec<T>) {
    let mut start = vec![0u32; n + 1];
    for (b, _) in entries.clone() {
        start[b + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut items = vec![T::default(); start[n] as usize];
    for (b, x) in entries {
        items[fill[b] as usize] = x;
        fill[b] += 1;
    }
    (start, items)
}

/// An error of a planar computation (bad parameters or an internal inconsistency).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlanarError(pub String);

impl PlanarError {
    /// An error with a message.
    pub fn new(message: impl Into<String>) -> Self {
        PlanarError(message.into())
    }
}

impl std::fmt::Display for PlanarError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for PlanarError {}
