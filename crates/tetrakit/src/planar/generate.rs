//! Planar point sets for tests and benchmarks (`tetrakit generate points2d`).

use crate::geom::{Hull2, Point2};
use crate::rng::Rng;
use std::collections::HashSet;

/// A distribution of planar points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Distribution {
    /// Uniform in the unit square.
    Uniform,
    /// Standard normal in each coordinate.
    Gaussian,
    /// Gaussian clusters (about √n clusters of spread 0.01) in the unit square.
    Clustered,
    /// In strictly convex position (random angles on a circle, kept if extreme).
    Convex,
    /// The vertices of a regular n-gon (cocircular up to rounding: near-ties).
    Regular,
    /// An integer grid, row by row (exact ties everywhere).
    Grid,
}

fn normal(rng: &mut Rng) -> f64 {
    // Box–Muller; 1 - unit() is in (0, 1].
    let (u, v) = (1.0 - rng.unit(), rng.unit());
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// `n` distinct points of the distribution (fewer only for `Convex` when `n` is huge).
///
/// ```
/// use tetrakit::planar::{Distribution, points2d};
/// let pts = points2d(Distribution::Grid, 10, 1);
/// assert_eq!(pts.len(), 10);
/// assert_eq!(pts[5], [1.0, 1.0]); // a 4-wide grid
/// ```
pub fn points2d(dist: Distribution, n: usize, seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    if dist == Distribution::Convex {
        return convex(&mut rng, n);
    }
    let mut seen = HashSet::new();
    let mut out = Vec::with_capacity(n);
    let side = (n as f64).sqrt().ceil() as usize;
    let centers: Vec<Point2> = (0..side.max(1)).map(|_| [rng.unit(), rng.unit()]).collect();
    let mut i = 0usize;
    while out.len() < n {
        let p = match dist {
            Distribution::Uniform => [rng.unit(), rng.unit()],
            Distribution::Gaussian => [normal(&mut rng), normal(&mut rng)],
            Distribution::Clustered => {
                let c = centers[rng.below(centers.len())];
                [
                    c[0] + 0.01 * normal(&mut rng),
                    c[1] + 0.01 * normal(&mut rng),
                ]
            }
            Distribution::Convex => unreachable!("drawn by convex()"),
            Distribution::Regular => {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                [a.cos(), a.sin()]
            }
            Distribution::Grid => [(i % side) as f64, (i / side) as f64],
        };
        i += 1;
        if seen.insert((p[0].to_bits(), p[1].to_bits())) {
            out.push(p);
        }
    }
    out
}

/// Up to `n` points in strictly convex position: random angles on the unit circle, of
/// which the hull vertices are kept (rounding puts a few inside), drawn in rounds with
/// a margin until `n` are kept, then the first `n` (a subset of points in convex
/// position is in convex position). One hull per round, so `O(n log n)`.
fn convex(rng: &mut Rng, n: usize) -> Vec<Point2> {
    let mut out: Vec<Point2> = Vec::with_capacity(n);
    let mut seen = HashSet::new();
    let mut drawn = 0;
    while out.len() < n && drawn <= 20 * n {
        let want = n - out.len();
        for _ in 0..want + want / 8 + 16 {
            let a = std::f64::consts::TAU * rng.unit();
            let p = [a.cos(), a.sin()];
            if seen.insert((p[0].to_bits(), p[1].to_bits())) {
                out.push(p);
            }
        }
        drawn += want + want / 8 + 16;
        let mut keep = vec![false; out.len()];
        for &v in &Hull2::new(&out).vertices {
            keep[v as usize] = true;
        }
        let mut k = 0;
        out.retain(|_| {
            k += 1;
            keep[k - 1]
        });
    }
    out.truncate(n);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_distribution_gives_n_distinct_points() {
        use Distribution::*;
        for dist in [Uniform, Gaussian, Clustered, Convex, Regular, Grid] {
            for n in [0, 1, 5, 3000] {
                let pts = points2d(dist, n, 7);
                assert_eq!(pts.len(), n, "{dist:?}");
                let distinct: HashSet<_> = pts.iter().map(|p| p.map(f64::to_bits)).collect();
                assert_eq!(distinct.len(), n, "{dist:?}");
            }
        }
    }

    #[test]
    fn convex_points_are_all_hull_vertices() {
        for (n, seed) in [(3, 1), (50, 2), (20_000, 3)] {
            let pts = points2d(Distribution::Convex, n, seed);
            let hull = Hull2::new(&pts);
            assert_eq!(hull.vertices.len(), n);
            assert!(hull.on_boundary.iter().all(|&b| b));
        }
    }
}
