//! Nested convex shapes for tests and benchmarks (`tetrakit generate nested`).

use super::{Shell, ShellError};
use crate::geom::Point3;
use crate::params::GenerateError;
use crate::rng::Rng;
use std::f64::consts::TAU;

/// A convex shape given by points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Shape {
    /// Random points on a sphere (in convex position up to rounding; any that are not are
    /// reported by `tetrakit shell`).
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
pub(crate) fn min_points(shape: Shape) -> usize {
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
pub fn nested(p: &NestedParams) -> Result<(Vec<Point3>, Vec<Point3>, f64), GenerateError> {
    let sizes = [
        (p.outer, p.n_outer, "n_outer"),
        (p.inner, p.n_inner, "n_inner"),
    ];
    for (shape, n, which) in sizes {
        if n < min_points(shape) {
            let expected = format!("at least {} points ({shape:?})", min_points(shape));
            return Err(GenerateError::range(which, n, expected));
        }
    }
    if !(p.gap > 0.0 && p.gap < 1.0) {
        return Err(GenerateError::range("gap", p.gap, "in (0, 1)"));
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
    Err(GenerateError::Unbuildable(
        "the inner shape does not fit inside the outer hull",
    ))
}

/// Heights of the Bern disk: the outer rings at `±RING_HEIGHT`, the inner apexes at
/// `±APEX_HEIGHT` (the rings more than twice as high, so a ring vertex sees the whole
/// upper cone of the inner polytope).
const RING_HEIGHT: f64 = 0.05;
const APEX_HEIGHT: f64 = 0.02;

/// A shell on which Bern's minimum-degree cap removal makes `Θ(n log n)` tetrahedra:
/// the outer polytope an antiprism over two regular `ring`-gons at heights `±0.05`
/// (heights jittered by 10⁻³ of themselves, so no four ring vertices are coplanar), of
/// radius `1 / cos(1.5π / ring)`; the inner one a flat bicone, `ridge` points on the unit
/// circle at height 0 and two apexes at `±0.02`.
///
/// The ring's chords clear the unit circle, but once a ring vertex is removed its
/// neighbours' chord does not: the ridge shows through between them. Every ridge vertex
/// is then joined to the nearest ring vertices left, and the apexes stay hidden until the
/// last ring vertex on their side goes, so each removal hands its stretch of ridge to
/// its neighbours. A ridge vertex changes hands about `log₂ ring` times, each time at
/// the cost of new triangles, whatever the order of removal (a merge tree over the
/// ring); TetGen's constrained Delaunay tetrahedralization of the same surfaces has
/// about 3 tetrahedra per vertex. Returns `(outer, inner)`; refuses fewer than 3 ring or
/// ridge points.
///
/// ```
/// use tetrakit::shell::generate::bern_disk;
/// let (outer, inner) = bern_disk(40, 10, 1).unwrap();
/// assert_eq!((outer.len(), inner.len()), (20, 42));
/// ```
pub fn bern_disk(
    ridge: usize,
    ring: usize,
    seed: u64,
) -> Result<(Vec<Point3>, Vec<Point3>), GenerateError> {
    if ridge < 3 {
        return Err(GenerateError::range("ridge", ridge, "at least 3"));
    }
    if ring < 3 {
        return Err(GenerateError::range("ring", ring, "at least 3"));
    }
    let mut rng = Rng::new(seed);
    let radius = 1.0 / (1.5 * std::f64::consts::PI / ring as f64).cos();
    let mut outer = Vec::with_capacity(2 * ring);
    for side in [1.0, -1.0] {
        let shift = if side > 0.0 { 0.5 } else { 0.0 };
        for j in 0..ring {
            let t = TAU * (j as f64 + shift) / ring as f64;
            let z = side * RING_HEIGHT * (1.0 + 1e-3 * rng.unit());
            outer.push([radius * t.cos(), radius * t.sin(), z]);
        }
    }
    let mut inner: Vec<Point3> = (0..ridge)
        .map(|j| {
            let t = TAU * j as f64 / ridge as f64;
            [t.cos(), t.sin(), 0.0]
        })
        .collect();
    inner.push([0.0, 0.0, APEX_HEIGHT]);
    inner.push([0.0, 0.0, -APEX_HEIGHT]);
    Ok((outer, inner))
}

/// How the inner polytope of [`contact`] touches the outer one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Contact {
    /// At one shared vertex.
    Vertex,
    /// Along one shared edge.
    Edge,
    /// Along one shared facet.
    Facet,
    /// A vertex of `Q` inside a facet of `P` (the cube `[−1, 1]³`, its top facet).
    FacetPoint,
}

/// A shell whose inner polytope touches the outer one as `kind` says, and nowhere else:
/// `P` is the hull of `n_outer` random points on the unit sphere (the cube `[−1, 1]³` for
/// [`Contact::FacetPoint`]), and `Q` the hull of the shared part (a vertex, the two ends
/// of an edge, or a facet's corners of `P`; the point `(0.25, 0.5, 1)` on the cube's top)
/// with `n_inner` points strictly inside `P` (outer points pulled halfway to the centroid
/// of `P`'s vertices). Returns `(outer, inner)`.
///
/// ```
/// use tetrakit::shell::{Shell, generate::{Contact, contact}};
/// let (outer, inner) = contact(Contact::FacetPoint, 8, 6, 1).unwrap();
/// let shell = Shell::new(&outer, &inner).unwrap();
/// assert_eq!(shell.touching.len(), 1);
/// ```
pub fn contact(
    kind: Contact,
    n_outer: usize,
    n_inner: usize,
    seed: u64,
) -> Result<(Vec<Point3>, Vec<Point3>), GenerateError> {
    if n_outer < 4 {
        return Err(GenerateError::range("n_outer", n_outer, "at least 4"));
    }
    if n_inner < 4 {
        return Err(GenerateError::range("n_inner", n_inner, "at least 4"));
    }
    let mut rng = Rng::new(seed);
    let outer: Vec<Point3> = match kind {
        Contact::FacetPoint => shape_points(Shape::Cube, 8, 3f64.sqrt(), &mut rng),
        _ => (0..n_outer).map(|_| on_sphere(&mut rng)).collect(),
    };
    let hull = crate::geom::Hull3::new(&outer);
    if hull.dimension < 3 {
        return Err(GenerateError::Unbuildable("the outer points are flat"));
    }
    let corners: Vec<usize> = (0..outer.len()).filter(|&v| hull.on_boundary(v)).collect();
    let k = corners.len() as f64;
    let centre: Point3 = [0, 1, 2].map(|d| corners.iter().map(|&v| outer[v][d]).sum::<f64>() / k);
    let f = hull.facet_planes[0];
    let mut inner: Vec<Point3> = match kind {
        Contact::Vertex => vec![outer[f[0] as usize]],
        Contact::Edge => vec![outer[f[0] as usize], outer[f[1] as usize]],
        Contact::Facet => f.iter().map(|&v| outer[v as usize]).collect(),
        Contact::FacetPoint => vec![[0.25, 0.5, 1.0]],
    };
    while inner.len() < n_inner {
        let p = outer[corners[rng.below(corners.len())]];
        let q = on_sphere(&mut rng).map(|x| 0.2 * x);
        inner.push([0, 1, 2].map(|d| centre[d] + 0.5 * (p[d] - centre[d]) + q[d] * 0.1));
    }
    Ok((outer, inner))
}
