//! Planar proximity structures of thesis ch. 5: β-skeletons ([`beta_skeleton`]), exact
//! minimum weight triangulations ([`mwt`]), and the counterexample to Keil's conjecture
//! of §5.2–5.3 ([`keil`]).
//!
//! Every decision is exact: β is a rational ([`Ratio`](crate::geom::Ratio)), regions are
//! tested by polynomial signs ([`crate::geom::in_beta_region`]), and weights are compared
//! with certified intervals and an exact fallback for sums of square roots
//! (`geom`'s exact comparison of root sums).
//!
//! [`triangulations`] enumerates every triangulation of a small set: the exhaustive
//! oracle the exact stages are tested against.

mod delaunay;
mod error;
mod forced;
mod generate;
mod grid;
mod keil;
mod mwt;
mod oracle;
mod skeleton;

use crate::geom::Point2;
use rayon::prelude::*;

pub use delaunay::{Delaunay, DelaunayEdge, delaunay};
pub use error::PlanarError;
pub use generate::{Distribution, points2d};
pub use keil::{
    KeilConstruction, KeilOutcome, KeilResult, Violation, above_cheng_xu, check_random, keil,
    keil_sites,
};
pub use mwt::{
    LowerBound, Mwt, MwtBounds, MwtOptions, MwtOutcome, MwtStats, candidate_edges, cmp_edge_sets,
    mwt, mwt_bounds, mwt_or_bounds, mwt_stage, weight_of,
};
pub use oracle::triangulations;
pub use skeleton::{Region, Skeleton, beta_skeleton};

pub(crate) use crate::partition::find;

/// The edge `ab` as `[min, max]`.
pub(crate) fn edge_key(a: u32, b: u32) -> [u32; 2] {
    [a.min(b), a.max(b)]
}

/// Checks that every coordinate is in the exactly supported range
/// ([`coordinate_in_range`](crate::geom::coordinate_in_range)): the predicates are exact
/// there, and the floating-point search bounds of the skeleton and the MWT filter have
/// the error bounds their docs state.
pub(crate) fn check_coordinates(points: &[Point2]) -> Result<(), PlanarError> {
    match points
        .iter()
        .position(|p| !p.iter().all(|&x| crate::geom::coordinate_in_range(x)))
    {
        None => Ok(()),
        Some(i) => Err(PlanarError::CoordinateOutOfRange {
            site: i as u32,
            point: points[i],
        }),
    }
}

/// Checks the coordinates ([`check_coordinates`]) and that no two sites coincide.
pub(crate) fn check_sites(points: &[Point2]) -> Result<(), PlanarError> {
    check_coordinates(points)?;
    match coincident_sites(points) {
        None => Ok(()),
        Some(sites) => Err(PlanarError::CoincidentSites {
            sites,
            point: points[sites[0] as usize],
        }),
    }
}

/// Two sites at the same position, the lower index first, if there are any
/// (`O(n log n)`).
///
/// ```
/// use tetrakit::planar::coincident_sites;
/// assert_eq!(coincident_sites(&[[0.0, 1.0], [2.0, 0.0], [0.0, 1.0]]), Some([0, 2]));
/// assert_eq!(coincident_sites(&[[0.0, 0.0], [-0.0, 1.0]]), None);
/// ```
pub fn coincident_sites(points: &[Point2]) -> Option<[u32; 2]> {
    // `+ 0.0` maps -0 to +0, so the total order agrees with equality of points.
    let key = |i: u32| points[i as usize].map(|x| x + 0.0);
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    order.par_sort_unstable_by(|&a, &b| {
        let (p, q) = (key(a), key(b));
        p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
    });
    (order.windows(2))
        .find(|w| key(w[0]) == key(w[1]))
        .map(|w| [w[0].min(w[1]), w[0].max(w[1])])
}
