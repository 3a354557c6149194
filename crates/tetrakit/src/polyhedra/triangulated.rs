//! Convex polyhedra whose polygon facets are triangulated at random (thesis ch. 6,
//! "Tetrahedralizations of non-strictly convex polyhedra"): the surface is fixed, and
//! whether a tetrahedralization without Steiner points exists is the open question's
//! instance (`tetrakit generate convex-triangulated`, then `tetrakit tetrahedralize`).
//!
//! A convex polytope is built on exact (integer or dyadic) points, optionally with points
//! added strictly inside facets; every facet of its hull ([`Hull3`]'s merged coplanar
//! facets) is triangulated with every point on it, at random: the placing triangulation
//! of its points in lexicographic order, then random flips of strictly convex
//! quadrilaterals. Points on a polytope edge lie on both facets' boundaries, so the
//! facets' triangulations meet edge to edge. Every orientation test is exact.

use super::Polyhedron;
use crate::geom::{Hull3, Point3, orient2d_drop, projection_axis, triangulate_coplanar};
use crate::params::GenerateError;
use crate::rng::Rng;

/// The convex polytope a [`convex_triangulated`] polyhedron is built on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum ConvexShape {
    /// A prism over a convex `n`-gon (integer coordinates): two `n`-gons and `n`
    /// rectangles. `n = 3` with diagonals running round is the classic NO.
    Prism,
    /// The cube `[0, 64]³`: six squares.
    Cube,
    /// The hull of `n` distinct random integer points in a small cube: many coplanar
    /// facets, points on facets and on edges.
    Lattice,
}

/// A convex polyhedron of `shape` (size `n`, see [`ConvexShape`]) with `facet_points`
/// points added strictly inside random facets, every facet triangulated at random.
///
/// ```
/// use tetrakit::polyhedra::generate::{ConvexShape, convex_triangulated};
/// let p = convex_triangulated(ConvexShape::Cube, 0, 3, 1).unwrap();
/// assert_eq!(p.points.len(), 11);
/// assert_eq!(p.faces.len(), 2 * 11 - 4); // a triangulated sphere
/// ```
pub fn convex_triangulated(
    shape: ConvexShape,
    n: usize,
    facet_points: usize,
    seed: u64,
) -> Result<Polyhedron, GenerateError> {
    if facet_points > 10_000 {
        return Err(GenerateError::range(
            "facet_points",
            facet_points,
            "at most 10000",
        ));
    }
    let mut rng = Rng::new(seed);
    let mut points = polytope(shape, n, &mut rng)?;
    for _ in 0..facet_points {
        if !add_facet_point(&mut points, &mut rng) {
            return Err(GenerateError::Unbuildable(
                "no room for another facet point after 100 tries: ask for fewer",
            ));
        }
    }
    let hull = Hull3::new(&points);
    let on_hull: Vec<u32> = (0..points.len() as u32)
        .filter(|&i| hull.on_boundary(i as usize))
        .collect();
    let mut faces = Vec::new();
    for f in 0..hull.facet_count() as u32 {
        let on: Vec<u32> = (on_hull.iter().copied())
            .filter(|&i| hull.facets_of(i as usize).contains(&f))
            .collect();
        let inside = hull.facet_planes[f as usize];
        for t in triangulate_coplanar(&points, &on, Some(&mut rng)) {
            faces.push(outward(&points, t, inside));
        }
    }
    // Keep only the points on the surface, renumbered.
    let mut new = vec![u32::MAX; points.len()];
    let kept: Vec<Point3> = (on_hull.iter().enumerate())
        .map(|(k, &i)| {
            new[i as usize] = k as u32;
            points[i as usize]
        })
        .collect();
    let faces = faces.iter().map(|t| t.map(|v| new[v as usize])).collect();
    Polyhedron::new(kept, faces).map_err(|_| {
        GenerateError::Unbuildable("the polytope's surface is not a simple polyhedron")
    })
}

fn polytope(shape: ConvexShape, n: usize, rng: &mut Rng) -> Result<Vec<Point3>, GenerateError> {
    Ok(match shape {
        ConvexShape::Prism => {
            if !(3..=1000).contains(&n) {
                return Err(GenerateError::range("n", n, "between 3 and 1000"));
            }
            // A convex n-gon with integer corners, rotated at random; the rounding keeps
            // it convex (corners at least 6 units apart on a circle of radius 2^20).
            let turn = rng.unit();
            let ring: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let a = std::f64::consts::TAU * (i as f64 + turn) / n as f64;
                    [(a.cos() * 1048576.0).round(), (a.sin() * 1048576.0).round()]
                })
                .collect();
            let height = 1048576.0;
            (ring.iter().map(|&[x, y]| [x, y, 0.0]))
                .chain(ring.iter().map(|&[x, y]| [x, y, height]))
                .collect()
        }
        ConvexShape::Cube => (0..8)
            .map(|i| {
                [
                    (i & 1) as f64 * 64.0,
                    (i >> 1 & 1) as f64 * 64.0,
                    (i >> 2) as f64 * 64.0,
                ]
            })
            .collect(),
        ConvexShape::Lattice => {
            if !(4..=10_000).contains(&n) {
                return Err(GenerateError::range("n", n, "between 4 and 10000"));
            }
            let g = (2..).find(|g| g * g * g >= 3 * n).unwrap_or(2);
            let mut pts: Vec<Point3> = Vec::with_capacity(n);
            while pts.len() < n {
                let p = [0, 1, 2].map(|_| rng.below(g) as f64 * 16.0);
                if !pts.contains(&p) {
                    pts.push(p);
                }
            }
            if crate::geom::affine_dimension(&pts) < 3 {
                return Err(GenerateError::Unbuildable(
                    "the lattice points are coplanar: try another seed",
                ));
            }
            pts
        }
    })
}

/// A point strictly inside a random facet: `a + s(b − a) + t(c − a)` for three points
/// on it and dyadic `s, t > 0` with `s + t < 1`, exact on integer corners; kept only
/// when it lies on that facet alone and on no other point. False after 100 tries.
fn add_facet_point(points: &mut Vec<Point3>, rng: &mut Rng) -> bool {
    let hull = Hull3::new(points);
    for _ in 0..100 {
        let f = rng.below(hull.facet_count()) as u32;
        let on: Vec<usize> = (0..points.len())
            .filter(|&i| hull.facets_of(i).contains(&f))
            .collect();
        let [a, b, c] = [0, 1, 2].map(|_| points[on[rng.below(on.len())]]);
        let (s, t) = (1 + rng.below(14), 1 + rng.below(14));
        if s + t >= 16 {
            continue;
        }
        let (s, t) = (s as f64 / 16.0, t as f64 / 16.0);
        let p: Point3 = [0, 1, 2].map(|k| a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]));
        if points.contains(&p) {
            continue;
        }
        points.push(p);
        let h = Hull3::new(points);
        if h.facets_of(points.len() - 1) == [f] && h.facet_count() == hull.facet_count() {
            return true;
        }
        points.pop();
    }
    false
}

/// Triangle `t` turned to face away from the polytope (`plane`'s points have every point
/// on their non-positive side).
fn outward(points: &[Point3], t: [u32; 3], plane: [u32; 3]) -> [u32; 3] {
    let p = |v: u32| &points[v as usize];
    let [a, b, c] = plane.map(p);
    let [x, y, z] = t.map(p);
    // Same orientation in the plane as the outward-oriented `plane` triple?
    let axis = projection_axis(a, b, c).expect("a facet plane");
    if orient2d_drop(x, y, z, axis) == orient2d_drop(a, b, c, axis) {
        t
    } else {
        [t[0], t[2], t[1]]
    }
}
