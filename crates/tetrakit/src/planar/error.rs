//! Why a planar computation gave no answer.

use crate::bug::Bug;
use crate::control::Stopped;
use crate::geom::{Point2, Ratio};
use std::fmt;

/// The bytes, in GiB, for messages.
fn gib(bytes: usize) -> usize {
    bytes >> 30
}

/// An error of a planar computation: bad input or parameters (with the sites or values
/// involved), a refusal before an allocation past the memory limit, a stop, or an
/// internal inconsistency (a bug, please report it).
#[derive(Clone, Debug, PartialEq)]
pub enum PlanarError {
    /// A coordinate is not finite or outside the exactly supported magnitude range
    /// ([`coordinate_in_range`](crate::geom::coordinate_in_range)).
    CoordinateOutOfRange {
        /// The site (0-based).
        site: u32,
        /// Its coordinates.
        point: Point2,
    },
    /// Two sites coincide.
    CoincidentSites {
        /// The two sites, the lower index first.
        sites: [u32; 2],
        /// Where.
        point: Point2,
    },
    /// A constraint edge does not join two distinct sites of the set.
    BadConstraint {
        /// The edge as given.
        edge: [u32; 2],
        /// Number of sites.
        sites: usize,
    },
    /// A forced edge passes through a site or is also forbidden.
    ForcedEdgeBlocked {
        /// The edge.
        edge: [u32; 2],
    },
    /// More candidate edges than the memory limit allows (sites in or near convex
    /// position keep most pairs).
    TooManyCandidates {
        /// Number of sites.
        sites: usize,
        /// The most candidates allowed.
        limit: usize,
        /// The memory limit in bytes.
        memory: usize,
    },
    /// A polygon dynamic program would need more memory than allowed.
    DynamicProgramTooLarge {
        /// Vertices of its walk.
        vertices: usize,
        /// Whether the walk is the hull of sites all in convex position (otherwise a face
        /// left by the LMT-skeleton).
        convex_position: bool,
        /// Bytes it would need.
        bytes: usize,
        /// Bytes allowed.
        memory: usize,
    },
    /// The β-skeleton for β < 1 would have more edges than fit in memory.
    TooManyEdges {
        /// Number of sites.
        sites: usize,
        /// The most edges allowed.
        limit: usize,
        /// β.
        beta: Ratio,
    },
    /// β is outside the interval where the construction of §5.2 applies.
    BetaOutsideKeilInterval {
        /// β.
        beta: Ratio,
    },
    /// β is so close to the interval's upper end that the construction's gap δ is
    /// below double precision's reach.
    BetaTooCloseToUpperEnd {
        /// β.
        beta: Ratio,
        /// The gap δ.
        delta: f64,
    },
    /// Too many sites per arc asked of the Keil construction.
    KeilTooLarge {
        /// Sites per arc asked.
        n: usize,
        /// The most allowed.
        limit: usize,
        /// Lemma 5.8's bound on `n`.
        lemma_bound: f64,
    },
    /// The Keil set is too large for the best triangulation without `xy`, which is
    /// computed over all segments.
    KeilConstrainedTooLarge {
        /// Number of sites.
        sites: usize,
        /// The most allowed.
        limit: usize,
    },
    /// The control was stopped first.
    Stopped(Stopped),
    /// An internal consistency check failed: a bug.
    Internal(Bug),
}

impl PlanarError {
    /// An internal inconsistency (a bug): `check` failed at the sites `at`.
    pub(crate) fn internal(check: &'static str, at: impl IntoIterator<Item = u32>) -> Self {
        PlanarError::Internal(Bug::at(check, at))
    }
}

impl From<Stopped> for PlanarError {
    fn from(s: Stopped) -> Self {
        PlanarError::Stopped(s)
    }
}

impl fmt::Display for PlanarError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use PlanarError::*;
        match self {
            CoordinateOutOfRange { site, point } => write!(
                f,
                "site {site} ({point:?}) has a coordinate that is not finite or outside the exactly supported magnitude range [2^-142, 2^201]"
            ),
            CoincidentSites { sites, point } => {
                write!(
                    f,
                    "sites {} and {} coincide at {point:?}",
                    sites[0], sites[1]
                )
            }
            BadConstraint { edge, sites } => write!(
                f,
                "constraint edge {}-{} does not join two distinct sites of {sites}",
                edge[0], edge[1]
            ),
            ForcedEdgeBlocked { edge } => write!(
                f,
                "forced edge {}-{} passes through a site or is forbidden",
                edge[0], edge[1]
            ),
            TooManyCandidates {
                sites,
                limit,
                memory,
            } => write!(
                f,
                "{sites} sites have more than {limit} candidate edges (sites in or near convex \
                 position keep most pairs): the LMT-skeleton would need more than {} GB",
                gib(*memory)
            ),
            DynamicProgramTooLarge {
                vertices,
                convex_position,
                bytes,
                memory,
            } => {
                if *convex_position {
                    write!(f, "{vertices} sites in convex position")?;
                } else {
                    f.write_str("a face left by the LMT-skeleton")?;
                }
                write!(
                    f,
                    ": the exact dynamic program over its {vertices} vertices needs about {} GB \
                     and m³/6 steps (at most {} GB allowed)",
                    gib(*bytes),
                    gib(*memory)
                )
            }
            TooManyEdges { sites, limit, beta } => write!(
                f,
                "the β-skeleton of these {sites} sites has more than {limit} edges (β = {beta} is \
                 small for their density): the list would not fit in memory"
            ),
            BetaOutsideKeilInterval { beta } => write!(
                f,
                "β = {beta} is outside [2/√3, √(2√3+45)/6) ≈ [1.154701, 1.160274): the construction of §5.2 does not apply"
            ),
            BetaTooCloseToUpperEnd { beta, delta } => write!(
                f,
                "β = {beta} is so close to the upper end that δ = {delta:.3e} is below double precision's reach"
            ),
            KeilTooLarge {
                n,
                limit,
                lemma_bound,
            } => write!(
                f,
                "n = {n} is above the limit of {limit} sites per arc (Lemma 5.8 asks n > {lemma_bound:.1}); ask for fewer sites"
            ),
            KeilConstrainedTooLarge { sites, limit } => write!(
                f,
                "{sites} sites and xy is in the MWT: the best triangulation without xy is computed over all segments, limited to {limit} sites; ask for fewer sites"
            ),
            Stopped(s) => s.fmt(f),
            Internal(bug) => bug.fmt(f),
        }
    }
}

impl std::error::Error for PlanarError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PlanarError::Stopped(s) => Some(s),
            PlanarError::Internal(bug) => Some(bug),
            _ => None,
        }
    }
}
