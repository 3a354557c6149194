//! Hard instance families for the exact solvers of thesis ch. 2 §2.5–2.6 and ch. 3:
//! polyhedra whose Steiner-free tetrahedralizations are rare or absent.
//!
//! * [`schonhardt_tower`]: Schönhardt's twisted prism stacked `layers` high, each layer
//!   turned further (§2.6, Figure 2.11(a); one layer is Schönhardt's polyhedron);
//! * [`chazelle`]: Chazelle's polyhedron, a box with `k` grooves cut into its top and
//!   `k` across its bottom, their floors on a hyperbolic paraboloid so that they pass
//!   close to each other (Chazelle 1984: `Ω(k²)` convex pieces);
//! * [`perturbed`]: random points on a sphere, their convex hull's surface, some
//!   vertices pushed inward along their radius (the surface kept, checked simple).
//!
//! Every result is checked exactly by [`Polyhedron::new`].

use super::Polyhedron;
use crate::geom::{Hull3, Point2, Point3, orient2d};
use crate::params::GenerateError;
use crate::rng::Rng;

/// Schönhardt's prism stacked: `layers + 1` equilateral triangles of circumradius 1 at
/// heights `0, 2, 4, …`, triangle `l` turned by `l · twist` degrees; each side
/// quadrilateral split by the diagonal from its lower-left to its upper-right corner
/// (reflex for a positive twist). Refused when the faces cross (a twist of 60° or more)
/// or the twist is not in (−120°, 120°).
///
/// ```
/// use tetrakit::polyhedra::generate::reflex_edges;
/// use tetrakit::polyhedra::hard::schonhardt_tower;
/// let t = schonhardt_tower(3, 30.0).unwrap();
/// assert_eq!((t.points.len(), reflex_edges(&t).len()), (12, 9));
/// ```
pub fn schonhardt_tower(layers: usize, twist: f64) -> Result<Polyhedron, GenerateError> {
    if twist.is_nan() || twist.abs() >= 120.0 {
        let expected = "an angle in (-120°, 120°) (the prism's sides cross at 120°)";
        return Err(GenerateError::range("twist", twist, expected));
    }
    if !(1..=10_000).contains(&layers) {
        return Err(GenerateError::range(
            "layers",
            layers,
            "between 1 and 10000",
        ));
    }
    let step = twist.to_radians();
    let mut points = Vec::with_capacity(3 * (layers + 1));
    for l in 0..=layers {
        for i in 0..3 {
            let a = std::f64::consts::TAU * i as f64 / 3.0 + l as f64 * step;
            points.push([a.cos(), a.sin(), 2.0 * l as f64]);
        }
    }
    let top = 3 * layers as u32;
    let mut faces = vec![[0, 2, 1], [top, top + 1, top + 2]];
    for l in 0..layers as u32 {
        let (b, u) = (3 * l, 3 * l + 3);
        for i in 0..3 {
            let j = (i + 1) % 3;
            faces.extend([[b + i, b + j, u + j], [b + i, u + j, u + i]]);
        }
    }
    Polyhedron::new(points, faces).map_err(not_simple)
}

/// Chazelle's polyhedron with `k` grooves on each side (`12k + 8` vertices): the box
/// `[0, L]² × [−H, H]` (`L = k + 1`), the top grooves along x at `y = 1, …, k` with
/// floors `z = s(x − c)(y − c) + δ`, the bottom grooves along y at `x = 1, …, k` with
/// floors `z = s(x − c)(y − c) − δ` (`c = L/2`, `s = 0.1`, `δ = 0.05`): the floors of
/// crossing grooves pass `2δ` apart. The side faces are polygons with a zig-zag edge,
/// triangulated by ear clipping (exact [`orient2d`]).
///
/// ```
/// use tetrakit::polyhedra::hard::chazelle;
/// let p = chazelle(2).unwrap();
/// assert_eq!(p.points.len(), 32);
/// ```
pub fn chazelle(k: usize) -> Result<Polyhedron, GenerateError> {
    if !(1..=1000).contains(&k) {
        return Err(GenerateError::range("grooves", k, "between 1 and 1000"));
    }
    let l = (k + 1) as f64;
    let (c, s, delta, w) = (l / 2.0, 0.1, 0.05, 0.25);
    let h = 1.0 + s * c * c;
    let floor = |x: f64, y: f64, sign: f64| s * (x - c) * (y - c) + sign * delta;
    // The profile across the grooves: (offset, is the floor) from 0 to L.
    let mut profile = vec![(0.0, false)];
    for i in 1..=k {
        let g = i as f64;
        profile.extend([(g - w, false), (g, true), (g + w, false)]);
    }
    profile.push((l, false));
    let m = profile.len() as u32;
    let mut points = Vec::new();
    // Top chains at x = 0 and x = L (indices e·m + j), then bottom chains at y = 0 and
    // y = L (2m + e·m + j).
    for x in [0.0, l] {
        for &(y, is_floor) in &profile {
            points.push([x, y, if is_floor { floor(x, y, 1.0) } else { h }]);
        }
    }
    for y in [0.0, l] {
        for &(x, is_floor) in &profile {
            points.push([x, y, if is_floor { floor(x, y, -1.0) } else { -h }]);
        }
    }
    let (t0, t1, b0, b1) = (0, m, 2 * m, 3 * m);
    let mut faces = Vec::new();
    for j in 0..m - 1 {
        faces.extend([
            [t0 + j, t1 + j, t1 + j + 1],
            [t0 + j, t1 + j + 1, t0 + j + 1],
        ]);
        faces.extend([
            [b0 + j, b1 + j, b1 + j + 1],
            [b0 + j, b1 + j + 1, b0 + j + 1],
        ]);
    }
    let chain = |start: u32| (start..start + m).collect::<Vec<u32>>();
    let last = m - 1;
    let sides = [
        (chain(t0), [b1, b0], 0), // x = 0: top chain, then (0, L, −H), (0, 0, −H)
        (chain(t1), [b1 + last, b0 + last], 0),
        (chain(b0), [t1, t0], 1), // y = 0: bottom chain, then (L, 0, H), (0, 0, H)
        (chain(b1), [t1 + last, t0 + last], 1),
    ];
    for (mut polygon, close, axis) in sides {
        polygon.extend(close);
        faces.extend(ear_clip(&points, &polygon, axis)?);
    }
    Polyhedron::new(points, faces).map_err(not_simple)
}

/// `n` random points on the unit sphere, the triangles of their convex hull, and each
/// vertex with probability one half pushed to radius `1 − dent · u` (`u` uniform in
/// `[0, 1)`). Draws again (up to 100 times) while the surface is not simple or has a
/// coplanar hull facet. `dent` in `[0, 1)`.
///
/// ```
/// use tetrakit::polyhedra::generate::reflex_edges;
/// use tetrakit::polyhedra::hard::perturbed;
/// let p = perturbed(20, 0.5, 1).unwrap();
/// assert_eq!(p.points.len(), 20);
/// assert!(!reflex_edges(&p).is_empty());
/// ```
pub fn perturbed(n: usize, dent: f64, seed: u64) -> Result<Polyhedron, GenerateError> {
    if !(4..=100_000).contains(&n) {
        return Err(GenerateError::range("n", n, "between 4 and 100000"));
    }
    if !(0.0..1.0).contains(&dent) {
        return Err(GenerateError::range("dent", dent, "in [0, 1)"));
    }
    let mut rng = Rng::new(seed);
    for _ in 0..100 {
        let sphere: Vec<Point3> = (0..n).map(|_| on_sphere(&mut rng)).collect();
        let hull = Hull3::new(&sphere);
        if hull.dimension < 3 || hull.triangles.len() != 2 * n - 4 {
            continue;
        }
        let points = sphere
            .iter()
            .map(|p| {
                let r = if rng.below(2) == 0 {
                    1.0 - dent * rng.unit()
                } else {
                    1.0
                };
                p.map(|x| x * r)
            })
            .collect();
        if let Ok(p) = Polyhedron::new(points, hull.triangles.clone()) {
            return Ok(p);
        }
    }
    Err(GenerateError::Unbuildable(
        "no simple polyhedron in 100 draws of these points with this dent",
    ))
}

/// The surface built is not a simple polyhedron.
fn not_simple(_: crate::mesh::SurfaceError) -> GenerateError {
    GenerateError::Unbuildable("the surface built is not a simple polyhedron")
}

fn on_sphere(rng: &mut Rng) -> Point3 {
    loop {
        let p = [0, 1, 2].map(|_| 2.0 * rng.unit() - 1.0);
        let r2: f64 = p.iter().map(|x| x * x).sum();
        if (0.01..=1.0).contains(&r2) {
            return p.map(|x| x / r2.sqrt());
        }
    }
}

/// Triangles of a simple polygon lying in a plane `coordinate[axis] = const`, by ear
/// clipping: an ear is a convex corner whose triangle holds no other corner (closed).
fn ear_clip(
    points: &[Point3],
    polygon: &[u32],
    axis: usize,
) -> Result<Vec<[u32; 3]>, GenerateError> {
    let flat = |v: u32| -> Point2 {
        let p = points[v as usize];
        if axis == 0 {
            [p[1], p[2]]
        } else {
            [p[0], p[2]]
        }
    };
    let mut poly = polygon.to_vec();
    // Counter-clockwise: the corner at the lowest-leftmost point is convex.
    let lowest = (0..poly.len())
        .min_by(|&i, &j| {
            // `+ 0.0`: -0 and 0 tie, so that `x` decides between them.
            let (a, b) = (
                flat(poly[i]).map(|x| x + 0.0),
                flat(poly[j]).map(|x| x + 0.0),
            );
            a[1].total_cmp(&b[1]).then(a[0].total_cmp(&b[0]))
        })
        .expect("a polygon");
    let k = poly.len();
    let (p, q, r) = (
        poly[(lowest + k - 1) % k],
        poly[lowest],
        poly[(lowest + 1) % k],
    );
    if orient2d(&flat(p), &flat(q), &flat(r)) < 0 {
        poly.reverse();
    }
    let mut out = Vec::new();
    while poly.len() > 3 {
        let k = poly.len();
        let ear = (0..k).find(|&i| {
            let (a, b, c) = (poly[(i + k - 1) % k], poly[i], poly[(i + 1) % k]);
            let (fa, fb, fc) = (flat(a), flat(b), flat(c));
            orient2d(&fa, &fb, &fc) > 0
                && poly
                    .iter()
                    .filter(|&&v| v != a && v != b && v != c)
                    .all(|&v| {
                        let fv = flat(v);
                        !(orient2d(&fa, &fb, &fv) >= 0
                            && orient2d(&fb, &fc, &fv) >= 0
                            && orient2d(&fc, &fa, &fv) >= 0)
                    })
        });
        let Some(i) = ear else {
            return Err(GenerateError::Unbuildable(
                "a side polygon has no ear (not simple)",
            ));
        };
        out.push([poly[(i + k - 1) % k], poly[i], poly[(i + 1) % k]]);
        poly.remove(i);
    }
    out.push([poly[0], poly[1], poly[2]]);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::polyhedra::generate::reflex_edges;

    #[test]
    fn one_layer_is_the_twisted_prism() {
        let a = schonhardt_tower(1, 30.0).unwrap();
        let b = crate::polyhedra::generate::twisted_prism(30.0).unwrap();
        assert_eq!((a.points, a.faces), (b.points, b.faces));
        assert!(schonhardt_tower(2, 70.0).is_err());
        assert!(schonhardt_tower(0, 10.0).is_err());
    }

    #[test]
    fn chazelle_has_its_grooves() {
        for k in 1..=4 {
            let p = chazelle(k).unwrap();
            assert_eq!(p.points.len(), 12 * k + 8);
            // Each groove's floor is a reflex edge.
            assert!(reflex_edges(&p).len() >= 2 * k, "k = {k}");
        }
    }

    #[test]
    fn perturbed_polyhedra_are_simple_and_dented() {
        for seed in 0..10 {
            let p = perturbed(16, 0.6, seed).unwrap();
            assert_eq!(p.faces.len(), 2 * 16 - 4);
        }
        assert_eq!(reflex_edges(&perturbed(30, 0.0, 1).unwrap()).len(), 0);
        assert!(perturbed(3, 0.5, 1).is_err());
    }
}
