//! Point sets in space for the flip graph and its experiments (`tetrakit generate
//! points3d`): uniform, on an integer lattice, a perturbed grid, cospherical, in convex
//! position.

use crate::geom::{Hull3, Point3};
use crate::rng::Rng;

/// A distribution of points in space.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Distribution3 {
    /// Uniform in the unit cube (53-bit coordinates: general position in practice).
    Uniform,
    /// Distinct integer points in a small cube (`[0, g)³`, `g³ ≥ 2n`): coplanar,
    /// collinear and cospherical subsets everywhere.
    Lattice,
    /// A cubic grid of spacing 1024 (the first `n` of its points), each coordinate moved
    /// by a random integer in `[-32, 32]`: near-degenerate, exact.
    PerturbedGrid,
    /// Integer points on the smallest sphere `x² + y² + z² = r²` about the origin that
    /// has `n` of them, `n` chosen at random (cospherical, many coplanar).
    Cospherical,
    /// Random points near the unit sphere, each a vertex of their hull.
    Convex,
    /// Two aligned rings of integer points on a cylinder of radius 2^20 (a prism: two
    /// polygon facets and rectangles), `n` odd: one more on the top ring.
    Cylinder,
    /// The vertices of the hull of the lattice points in a spherical shell
    /// `r² ≤ x² + y² + z² < (r + 1)²` (`n` of them at random, `r` the smallest with
    /// enough): a convex polytope with many coplanar facets, every point a vertex.
    LatticeHull,
}

/// `n` distinct points of `dist` (at least 4, so that a tetrahedralization can exist).
///
/// ```
/// use tetrakit::generate::{Distribution3, points3d};
/// let p = points3d(Distribution3::Cospherical, 10, 1);
/// let r2 = p[0].iter().map(|x| x * x).sum::<f64>();
/// assert!(p.len() == 10 && p.iter().all(|q| q.iter().map(|x| x * x).sum::<f64>() == r2));
/// ```
pub fn points3d(dist: Distribution3, n: usize, seed: u64) -> Vec<Point3> {
    let n = n.max(4);
    let mut rng = Rng::new(seed);
    match dist {
        Distribution3::Uniform => super::random_points(n, seed, None),
        Distribution3::Lattice => {
            let g = (1..).find(|g| g * g * g >= 2 * n).unwrap_or(2) as u32;
            super::random_points(n, seed, Some(g.max(3)))
        }
        Distribution3::PerturbedGrid => {
            let k = (1..).find(|k| k * k * k >= n).unwrap_or(1);
            (0..n)
                .map(|i| {
                    let cell = [i % k, i / k % k, i / (k * k)];
                    cell.map(|c| (c * 1024) as f64 + rng.below(65) as f64 - 32.0)
                })
                .collect()
        }
        Distribution3::Cospherical => {
            let mut sphere = (1..)
                .map(super::cospherical_points)
                .find(|s| s.len() >= n)
                .unwrap_or_default();
            rng.shuffle(&mut sphere);
            sphere.truncate(n);
            sphere
        }
        Distribution3::Cylinder => {
            let (bottom, top) = (n / 2, n - n / 2);
            let turn = rng.unit();
            let ring = |k: usize, z: f64| {
                (0..k).map(move |i| {
                    let a = std::f64::consts::TAU * (i as f64 + turn) / k as f64;
                    [
                        (a.cos() * 1048576.0).round(),
                        (a.sin() * 1048576.0).round(),
                        z,
                    ]
                })
            };
            ring(bottom, 0.0).chain(ring(top, 1048576.0)).collect()
        }
        Distribution3::LatticeHull => {
            let mut r = 2i64;
            loop {
                let shell: Vec<Point3> = (r * r..(r + 1) * (r + 1))
                    .flat_map(super::cospherical_points)
                    .collect();
                let hull = Hull3::new(&shell);
                let mut corners: Vec<Point3> = (0..shell.len())
                    .filter(|&i| hull.facets_of(i).len() >= 3)
                    .map(|i| shell[i])
                    .collect();
                if corners.len() >= n {
                    rng.shuffle(&mut corners);
                    corners.truncate(n);
                    if crate::geom::affine_dimension(&corners) == 3 {
                        return corners;
                    }
                }
                r += 1;
            }
        }
        Distribution3::Convex => {
            let mut pts = Vec::with_capacity(n);
            while pts.len() < n {
                let (u, v) = (rng.unit() * 2.0 - 1.0, rng.unit() * std::f64::consts::TAU);
                let r = (1.0 - u * u).sqrt();
                pts.push([r * v.cos(), r * v.sin(), u]);
                let hull = Hull3::new(&pts);
                if pts.len() >= 4 && (0..pts.len()).any(|i| !hull.on_boundary(i)) {
                    pts.pop();
                }
            }
            pts
        }
    }
}
