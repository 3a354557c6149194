//! The thesis's own construction for Theorem 2.9 (§2.5): TRID to TETRAD through a large
//! sphere, a twisted lower copy and regular quasi-prisms.
//!
//! **The construction** ([`sphere_reduction`]). Let `c` be a centre strictly inside the
//! hull of `E`'s points (the first candidate from which no four lifted points are
//! coplanar: points cocircular about `c`, or symmetric about a line through it, lift to
//! coplanar ones) and `r` the half-diagonal of their bounding box; the sphere has
//! centre `(c, 0)` and radius `R = 100 r`. Each point `v` becomes `u_v = (v, √(R² − |v −
//! c|²))` on the upper half (`v`'s coordinates kept bit for bit) and `l_v`, its image on the
//! lower half after turning `v` about `c` by a small angle `θ` (the twist). The apex `x* =
//! (c, Z)`. The segments are, as in the thesis: `E_U` (the lifted `E`), `E_L` (every pair of
//! lower points), `E_UL` (every upper–lower pair) and `L*` (`x* u_v` for every `v`).
//!
//! **Conditions, checked exactly on every output** (else [`ReduceError`]):
//! * (S0) no three points of `E` collinear;
//! * (S1) no four of the `2n + 1` points coplanar (the thesis's claim for its twist);
//! * (S2) the prism over every triangle whose three edges are in `E` is a regular
//!   quasi-prism ([`QuasiPrism::check_regular`]);
//! * (S3) `x*` sees the upper points as the plane does: `orient3d(u_a, u_b, u_c, x*)` has
//!   the sign of `orient2d(a, b, c)` for every triple (`Z` doubled from `2R` until it
//!   holds), and every `u_v` is a vertex of the upper hull;
//! * (S4) every edge of the hull of all the points is a segment, or the lift of a hull
//!   edge of `E`'s points missing from `E` (then both answers are NO).
//!
//! `θ` starts at 0.01 radians and is halved until (S1) and (S2) hold.
//!
//! **Status of the proof.** The thesis's YES direction rests on Lemma 2.7 (a regular
//! quasi-prism is tetrahedralized by its staircases), and [`QuasiPrism`]'s module docs show
//! that the algorithm as written fails on twisted quasi-prisms, which this construction
//! always makes. So unlike [`trid_to_tetrad`](super::trid_to_tetrad), whose argument is
//! complete, this construction's agreement is measured, not proven: the tests compare the
//! planar and spatial answers on random instances (they have always agreed).

use super::{ReduceError, centres, collinear_triple, not_upper_hull_vertex};
use crate::geom::{Hull3, Point2, Point3, orient2d, orient3d};
use crate::reduce::QuasiPrism;

/// The thesis's TETRAD instance of a TRID instance.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereReduction {
    /// The upper points `u_v` (`v` here is `v` of the input), the lower points `l_v`
    /// (`n + v`), then `x*` (`2n`).
    pub points: Vec<Point3>,
    /// `E_U`, `E_L`, `E_UL`, then `L*`.
    pub segments: Vec<[u32; 2]>,
    /// The sphere's radius `R`.
    pub radius: f64,
    /// The twist `θ` of the lower points, in radians.
    pub twist: f64,
    /// The apex height `Z`.
    pub height: f64,
}

/// Builds the thesis's TETRAD instance of `points` and `segments` (module docs) and
/// checks its conditions.
///
/// ```
/// use tetrakit::reduce::sphere_reduction;
/// let p = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.5]];
/// let e = [[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [1, 4], [2, 4], [3, 4]];
/// let r = sphere_reduction(&p, &e).unwrap();
/// // 5 upper, 5 lower, the apex; E_U, the 10 lower pairs, the 25 upper–lower pairs, L*.
/// assert_eq!((r.points.len(), r.segments.len()), (11, 8 + 10 + 25 + 5));
/// assert!(r.twist > 0.0);
/// ```
pub fn sphere_reduction(
    points: &[Point2],
    segments: &[[u32; 2]],
) -> Result<SphereReduction, ReduceError> {
    let n = points.len();
    if n < 3 {
        return Err(ReduceError::TooFew);
    }
    if let Some(t) = collinear_triple(points) {
        return Err(ReduceError::Collinear(t));
    }
    let (lo, hi) = crate::geom::bounding_box(points);
    let r = ((0..2).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>()).sqrt() / 2.0;
    let radius = 100.0 * r;
    let lift = |c: Point2| -> Vec<Point3> {
        points
            .iter()
            .map(|p| on_sphere(*p, c, radius, 1.0))
            .collect()
    };
    // Points cocircular about the centre, or symmetric about a line through it, lift to
    // coplanar points: try centres until no four upper points are coplanar.
    let mut flat = None;
    let c = centres(points)
        .take(64)
        .find(|&c| {
            flat = coplanar_quadruple(&lift(c));
            flat.is_none()
        })
        .ok_or(flat.map_or(ReduceError::NoCentre, ReduceError::Coplanar))?;
    let upper = lift(c);
    if let Some(v) = not_upper_hull_vertex(&upper) {
        return Err(ReduceError::NotConvex(v));
    }
    let height = apex_height(points, &upper, c, radius)?;
    let triangles = triangles_of(n, segments);
    let mut twist = 0.01;
    let mut last = ReduceError::NoTwist(None);
    for _ in 0..40 {
        let mut pts = upper.clone();
        pts.extend(
            points
                .iter()
                .map(|p| on_sphere(turned(*p, c, twist), c, radius, -1.0)),
        );
        pts.push([c[0], c[1], height]);
        match twisted_ok(&pts, n, &triangles) {
            Ok(()) => {
                let segs = segments_of(n, segments);
                hull_edges_are_segments(&pts, &segs, points, n)?;
                return Ok(SphereReduction {
                    points: pts,
                    segments: segs,
                    radius,
                    twist,
                    height,
                });
            }
            Err(e) => last = e,
        }
        twist /= 2.0;
    }
    Err(last)
}

impl SphereReduction {
    /// The triangulation of the planar points that a tetrahedralization within the
    /// segments gives: the link of `x*` (`None` if no tetrahedron has `x*`).
    pub fn project(&self, tets: &[[u32; 4]]) -> Option<Vec<[u32; 3]>> {
        super::link(self.points.len() as u32 - 1, tets)
    }
}

/// `p` lifted onto the sphere of centre `(c, 0)` and radius `radius`, on the upper
/// (`side = 1`) or lower (`side = −1`) half.
fn on_sphere(p: Point2, c: Point2, radius: f64, side: f64) -> Point3 {
    let d2 = (p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2);
    [p[0], p[1], side * (radius * radius - d2).sqrt()]
}

/// `p` turned about `c` by `angle` radians.
fn turned(p: Point2, c: Point2, angle: f64) -> Point2 {
    let (s, k) = angle.sin_cos();
    let (x, y) = (p[0] - c[0], p[1] - c[1]);
    [c[0] + k * x - s * y, c[1] + s * x + k * y]
}

/// (S3): the least height `2R · 2^k` from which `x*` sees the upper points with the
/// plane's orientations.
fn apex_height(
    points: &[Point2],
    upper: &[Point3],
    c: Point2,
    radius: f64,
) -> Result<f64, ReduceError> {
    let mut z = 2.0 * radius;
    while !seen_as_planar(points, upper, [c[0], c[1], z]) {
        z *= 2.0;
        if z > radius * 2f64.powi(60) {
            return Err(ReduceError::NoHeight);
        }
    }
    Ok(z)
}

fn seen_as_planar(points: &[Point2], upper: &[Point3], apex: Point3) -> bool {
    let n = points.len();
    (0..n).all(|a| {
        (a + 1..n).all(|b| {
            (b + 1..n).all(|c| {
                orient3d(&upper[a], &upper[b], &upper[c], &apex)
                    == orient2d(&points[a], &points[b], &points[c])
            })
        })
    })
}

/// The triangles of `E`: triples whose three sides are segments.
fn triangles_of(n: usize, segments: &[[u32; 2]]) -> Vec<[u32; 3]> {
    let mut adj = vec![vec![false; n]; n];
    for &[a, b] in segments {
        adj[a as usize][b as usize] = true;
        adj[b as usize][a as usize] = true;
    }
    let mut out = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in (b + 1..n).filter(|&c| adj[a][b] && adj[b][c] && adj[a][c]) {
                out.push([a as u32, b as u32, c as u32]);
            }
        }
    }
    out
}

/// (S1) and (S2) for the points with their twisted lower half.
fn twisted_ok(pts: &[Point3], n: usize, triangles: &[[u32; 3]]) -> Result<(), ReduceError> {
    if let Some(q) = coplanar_quadruple(pts) {
        return Err(ReduceError::Coplanar(q));
    }
    for &t in triangles {
        let upper = t.iter().map(|&v| pts[v as usize]).collect();
        let lower = t.iter().map(|&v| pts[n + v as usize]).collect();
        let prism = QuasiPrism::new(upper, lower, vec![[0, 1, 2]])
            .map_err(|_| ReduceError::NoTwist(Some(t)))?;
        prism
            .check_regular()
            .map_err(|_| ReduceError::NoTwist(Some(t)))?;
    }
    Ok(())
}

/// Four coplanar points, if any (`O(N⁴)` orientation tests).
fn coplanar_quadruple(pts: &[Point3]) -> Option<[u32; 4]> {
    let m = pts.len();
    for a in 0..m {
        for b in a + 1..m {
            for c in b + 1..m {
                for d in c + 1..m {
                    if orient3d(&pts[a], &pts[b], &pts[c], &pts[d]) == 0 {
                        return Some([a, b, c, d].map(|v| v as u32));
                    }
                }
            }
        }
    }
    None
}

/// `E_U` (the input's segments), `E_L`, `E_UL` and `L*`.
fn segments_of(n: usize, segments: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let n = n as u32;
    let mut segs = segments.to_vec();
    segs.extend((0..n).flat_map(|a| (a + 1..n).map(move |b| [n + a, n + b])));
    segs.extend((0..n).flat_map(|a| (0..n).map(move |b| [a, n + b])));
    segs.extend((0..n).map(|v| [v, 2 * n]));
    segs
}

/// (S4): every edge of the hull of `pts` is a segment or the lift of a hull edge of the
/// planar points.
fn hull_edges_are_segments(
    pts: &[Point3],
    segs: &[[u32; 2]],
    planar: &[Point2],
    n: usize,
) -> Result<(), ReduceError> {
    let key = |a: u32, b: u32| [a.min(b), a.max(b)];
    let have: std::collections::HashSet<[u32; 2]> = segs.iter().map(|s| key(s[0], s[1])).collect();
    let ring = crate::geom::Hull2::new(planar).vertices;
    let rim: std::collections::HashSet<[u32; 2]> = (0..ring.len())
        .map(|i| key(ring[i], ring[(i + 1) % ring.len()]))
        .collect();
    let hull = Hull3::new(pts);
    for run in hull.polytope_edges(pts) {
        for w in run.windows(2) {
            let e = key(w[0], w[1]);
            let lifted_rim = e[1] < n as u32 && rim.contains(&e);
            if !(have.contains(&e) || lifted_rim) {
                return Err(ReduceError::HullEdgeMissing(e));
            }
        }
    }
    Ok(())
}
