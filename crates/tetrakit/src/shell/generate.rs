//! Nested convex shapes for tests and benchmarks (`tetrakit generate nested`).

use super::{Shell, ShellError};
use crate::geom::Point3;
use crate::rng::Rng;
use std::f64::consts::TAU;

/// A convex shape given by points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Shape {
    /// Random points on a sphere (in convex position up to rounding; any that are not are
    /// reported by [`Shell::new`]).
    Sphere,
    /// A cube: its 8 corners, and the other points on its faces (coplanar facets with
    /// points that are not vertices).
    Cube,
    /// Random points in a ball (a random polytope with few vertices).
    Random,
    /// A prism over a regular polygon of `n / 2` sides (two coplanar polygon facets).
    Cylinder,
}

/// The smallest number of points each shape takes.
pub fn min_points(shape: Shape) -> usize {
    match shape {
        Shape::Sphere | Shape::Random => 4,
        Shape::Cube => 8,
        Shape::Cylinder => 6,
    }
}

fn on_sphere(rng: &mut Rng) -> Point3 {
    loop {
        let p = [0, 1, 2].map(|_| 2.0 * rng.unit() - 1.0);
        let r2: f64 = p.iter().map(|x| x * x).sum();
        if (1e-6..=1.0).contains(&r2) {
            return p.map(|x| x / r2.sqrt());
        }
    }
}

/// `n` points of `shape` with radius `r` about the origin.
pub fn shape_points(shape: Shape, n: usize, r: f64, rng: &mut Rng) -> Vec<Point3> {
    match shape {
        Shape::Sphere => (0..n).map(|_| on_sphere(rng).map(|x| r * x)).collect(),
        Shape::Random => (0..n)
            .map(|_| on_sphere(rng).map(|x| r * x * rng.unit().cbrt()))
            .collect(),
        Shape::Cube => {
            let h = r / 3f64.sqrt();
            let mut pts: Vec<Point3> = (0..8)
                .map(|i| [0, 1, 2].map(|k| if (i >> k) & 1 == 1 { h } else { -h }))
                .collect();
            while pts.len() < n {
                let mut p = [0, 1, 2].map(|_| h * (2.0 * rng.unit() - 1.0));
                let k = rng.below(3);
                p[k] = if rng.below(2) == 0 { h } else { -h };
                pts.push(p);
            }
            pts
        }
        Shape::Cylinder => {
            let k = (n / 2).max(3);
            let (a, h) = (r * 0.8, r * 0.6);
            (0..2 * k)
                .map(|i| {
                    let t = TAU * (i % k) as f64 / k as f64;
                    [a * t.cos(), a * t.sin(), if i < k { -h } else { h }]
                })
                .collect()
        }
    }
}

/// Parameters of [`nested`].
#[derive(Clone, Copy, Debug)]
pub struct NestedParams {
    /// The outer shape.
    pub outer: Shape,
    /// The inner shape.
    pub inner: Shape,
    /// Points of the outer shape.
    pub n_outer: usize,
    /// Points of the inner shape.
    pub n_inner: usize,
    /// The inner shape's radius is `1 − gap` (the outer's is 1), in `(0, 1)`.
    pub gap: f64,
    /// Seed.
    pub seed: u64,
}

/// Two nested point sets: the outer shape of radius 1 about the origin and the inner one
/// of radius `1 − gap` about the centre of the outer points, shrunk by factors of 0.9
/// until its hull fits inside the outer hull (a coarse outer polytope cuts into the
/// sphere of radius `1 − gap`). Returns the points
/// and the inner radius used; refuses too few points or a gap outside `(0, 1)`.
///
/// ```
/// use tetrakit::shell::generate::{NestedParams, Shape, nested};
/// let p = NestedParams { outer: Shape::Sphere, inner: Shape::Cube, n_outer: 40, n_inner: 8, gap: 0.5, seed: 1 };
/// let (outer, inner, radius) = nested(&p).unwrap();
/// assert_eq!((outer.len(), inner.len()), (40, 8));
/// assert!(radius <= 0.5);
/// ```
pub fn nested(p: &NestedParams) -> Result<(Vec<Point3>, Vec<Point3>, f64), String> {
    for (shape, n, which) in [(p.outer, p.n_outer, "outer"), (p.inner, p.n_inner, "inner")] {
        if n < min_points(shape) {
            return Err(format!(
                "{which} {shape:?} needs at least {} points, not {n}",
                min_points(shape)
            ));
        }
    }
    if !(p.gap > 0.0 && p.gap < 1.0) {
        return Err(format!("gap {} is not in (0, 1)", p.gap));
    }
    let mut rng = Rng::new(p.seed);
    let outer = shape_points(p.outer, p.n_outer, 1.0, &mut rng);
    let unit_inner = shape_points(p.inner, p.n_inner, 1.0, &mut rng);
    // The centre of the outer points is inside their hull (a random polytope need not
    // hold the origin); the inner shape shrinks towards it.
    let n = outer.len() as f64;
    let centre: Point3 = [0, 1, 2].map(|k| outer.iter().map(|p| p[k]).sum::<f64>() / n);
    let mut radius = 1.0 - p.gap;
    for _ in 0..200 {
        let inner: Vec<Point3> = unit_inner
            .iter()
            .map(|q| [0, 1, 2].map(|k| centre[k] + q[k] * radius))
            .collect();
        match Shell::new(&outer, &inner) {
            Err(ShellError::InnerOutside { .. }) => radius *= 0.9,
            _ => return Ok((outer, inner, radius)),
        }
    }
    Err("the inner shape does not fit inside the outer hull".into())
}
