//! Constructions of thesis ch. 2 §2.5: Lemma 2.6's flips ([`hull_gap`]) and the
//! reduction of TRID (does a planar segment set
//! contain a triangulation?) to TETRAD (does a spatial one contain a tetrahedralization?),
//! with its conditions checked exactly on every output.
//!
//! Two constructions: [`trid_to_tetrad`] below (proven), and the thesis's own, with the
//! sphere, the twisted lower copy and regular quasi-prisms, in [`sphere_reduction`]
//! (its conditions checked exactly; its agreement measured, since its proof leans on
//! Lemma 2.7).
//!
//! **The construction** ([`trid_to_tetrad`]). The thesis lifts the points to the upper
//! and lower halves of a large sphere, twists the lower copy, joins every lower pair and
//! every upper–lower pair, and puts an apex `x*` above. This module keeps the thesis's
//! upper half and apex and replaces its lower half by a second apex `y*` below, which
//! needs no twist and no quasi-prism: each point `v = (x, y)` of `E` becomes
//! `u_v = (x, y, 1 − |v − c|² / 4r²)` (a concave paraboloid over the centre `c` of the
//! bounding box, `r` its half-diagonal; `x` and `y` kept bit for bit), `x* = (c, Z)` and
//! `y* = (c, −Z)`; the segments are the lifted `E`, and `x* u_v`, `y* u_v` for every `v`.
//!
//! **Conditions, checked exactly** (else [`ReduceError`]):
//! * (C0) no three points of `E` are collinear (the thesis's nondegenerate case; planar
//!   input in any position is decided directly by [`crate::constrain::contains`]);
//! * (C1) for every triple `a, b, c`: `orient3d(u_a, u_b, u_c, x*)` has the sign of
//!   `orient2d(a, b, c)` and `orient3d(u_a, u_b, u_c, y*)` the opposite one (`Z` is
//!   doubled from 4 until this holds);
//! * (C2) every `u_v` is a vertex of the convex hull of the lifted points, on a facet
//!   whose outward normal points up (the rounding of the lift can break this only for
//!   nearly collinear points, and then the construction refuses).
//!
//! **Why the answers agree.** By (C1) the central projection from `x*` of the lifted
//! points has the orientations of `E`'s points, so both have the same triangulations.
//! If `T` triangulates the points within `E`, the tetrahedra `x* abc` and `y* abc` for
//! `abc ∈ T` ([`Reduction::lift`]) are empty, meet face to face, and fill the hull, whose
//! facets are `x* ab`, `y* ab` over the hull edges `ab` (every such plane has the other
//! points inside it, which is (C1) again). Conversely, in a tetrahedralization within
//! the segments, the link of `x*` (a hull vertex) is a disk whose projection from `x*`
//! covers the projected hull once; a lifted point that were not on it would lie behind
//! one of its triangles, below that triangle's plane, which (C2) forbids; so the link
//! uses every point, its triangles have their edges in `E`, and they triangulate the
//! points ([`Reduction::project`]).

mod hull_gap;
mod outcome;
mod quasi_prism;
mod sphere;

pub use hull_gap::{HullGapError, hull_gap};
pub use outcome::{
    HullGapOutcome, QuasiPrismOutcome, QuasiPrismRoute, ReductionFacts, StuckWitness,
    solve_hull_gap,
};
pub use quasi_prism::{NotQuasiPrism, QuasiPrism, QuasiPrismError, Staircase};
pub use sphere::{SphereReduction, sphere_reduction};

use crate::geom::{Hull3, Point2, Point3, orient2d, orient3d};

/// A TETRAD instance built from a TRID instance.
#[derive(Clone, Debug, PartialEq)]
pub struct Reduction {
    /// The lifted points (point `v` of the input is point `v` here), then `x*`, then `y*`.
    pub points: Vec<Point3>,
    /// The lifted segments, then `x* u_v` and `y* u_v` for every `v`.
    pub segments: Vec<[u32; 2]>,
    /// The apex heights `±Z`.
    pub height: f64,
}

/// Why the construction refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReduceError {
    /// Fewer than three points.
    TooFew,
    /// Three collinear points (C0).
    Collinear([u32; 3]),
    /// No centre strictly inside the hull and off every line through two points was
    /// found (not expected).
    NoCentre,
    /// No apex height up to 2^60 satisfies (C1) (not expected).
    NoHeight,
    /// A lifted point is not a vertex of the upper hull (C2).
    NotConvex(u32),
    /// [`sphere_reduction`]: four of the points are coplanar for every twist tried (S1).
    Coplanar([u32; 4]),
    /// [`sphere_reduction`]: no twist tried makes the prism over this triangle of `E` a
    /// regular quasi-prism (S2), or `None` when not known.
    NoTwist(Option<[u32; 3]>),
    /// [`sphere_reduction`]: this hull edge is not a segment (S4, not expected).
    HullEdgeMissing([u32; 2]),
}

impl std::fmt::Display for ReduceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReduceError::TooFew => write!(f, "fewer than three points"),
            ReduceError::Collinear([a, b, c]) => write!(
                f,
                "points #{a}, #{b} and #{c} are collinear: the reduction needs no three collinear (`contains` decides such planar input directly)"
            ),
            ReduceError::NoCentre => {
                write!(
                    f,
                    "no centre found inside the hull off every line through two points"
                )
            }
            ReduceError::NoHeight => {
                write!(f, "no apex height keeps the orientations (not expected)")
            }
            ReduceError::NotConvex(v) => write!(
                f,
                "point #{v} lifted is not a vertex of the upper hull (points nearly collinear for the rounded lift)"
            ),
            ReduceError::Coplanar([a, b, c, d]) => write!(
                f,
                "points #{a}, #{b}, #{c} and #{d} of the construction are coplanar for every twist tried (upper points are #v, lower ones #(n + v), the apex #2n)"
            ),
            ReduceError::NoTwist(Some([a, b, c])) => write!(
                f,
                "no twist tried makes the prism over triangle (#{a}, #{b}, #{c}) a regular quasi-prism"
            ),
            ReduceError::NoTwist(None) => write!(f, "no twist was tried"),
            ReduceError::HullEdgeMissing([a, b]) => write!(
                f,
                "hull edge (#{a}, #{b}) of the construction is not a segment (not expected)"
            ),
        }
    }
}

impl std::error::Error for ReduceError {}

/// Builds the TETRAD instance of `points` and `segments` (see the module docs) and
/// checks its conditions.
///
/// ```
/// use tetrakit::reduce::trid_to_tetrad;
/// // A square with a point inside and the four spokes: a triangulation.
/// let p = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.5]];
/// let e = [[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [1, 4], [2, 4], [3, 4]];
/// let r = trid_to_tetrad(&p, &e).unwrap();
/// assert_eq!((r.points.len(), r.segments.len()), (7, 18));
/// let t = r.lift(&[[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]);
/// assert!(tetrakit::mesh::certify_hull(&r.points, &t).is_ok());
/// assert_eq!(r.project(&t).unwrap().len(), 4);
/// ```
pub fn trid_to_tetrad(points: &[Point2], segments: &[[u32; 2]]) -> Result<Reduction, ReduceError> {
    let n = points.len();
    if n < 3 {
        return Err(ReduceError::TooFew);
    }
    if let Some(t) = collinear_triple(points) {
        return Err(ReduceError::Collinear(t));
    }
    let c = centre(points).ok_or(ReduceError::NoCentre)?;
    let (lo, hi) = crate::geom::bounding_box(points);
    let r2 = (0..2).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>();
    let lifted: Vec<Point3> = points
        .iter()
        .map(|p| {
            let d2 = (p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2);
            [p[0], p[1], 1.0 - d2 / (4.0 * r2)]
        })
        .collect();
    if let Some(v) = not_upper_hull_vertex(&lifted) {
        return Err(ReduceError::NotConvex(v));
    }
    let mut z = 4.0;
    while !orientations_kept(points, &lifted, [c[0], c[1], z]) {
        z *= 2.0;
        if z > 2f64.powi(60) {
            return Err(ReduceError::NoHeight);
        }
    }
    let mut pts = lifted;
    pts.push([c[0], c[1], z]);
    pts.push([c[0], c[1], -z]);
    let (top, bottom) = (n as u32, n as u32 + 1);
    let mut segs = segments.to_vec();
    segs.extend((0..n as u32).map(|v| [v, top]));
    segs.extend((0..n as u32).map(|v| [v, bottom]));
    Ok(Reduction {
        points: pts,
        segments: segs,
        height: z,
    })
}

impl Reduction {
    fn apexes(&self) -> (u32, u32) {
        let n = self.points.len() as u32;
        (n - 2, n - 1)
    }

    /// The tetrahedralization within the segments that a triangulation `tris` of the
    /// planar points within `E` gives: `x* abc` and `y* abc` for every triangle,
    /// positively oriented.
    pub fn lift(&self, tris: &[[u32; 3]]) -> Vec<[u32; 4]> {
        let (top, bottom) = self.apexes();
        let p = |v: u32| &self.points[v as usize];
        tris.iter()
            .flat_map(|&[a, b, c]| [[a, b, c, top], [a, b, c, bottom]])
            .map(|t| {
                if orient3d(p(t[0]), p(t[1]), p(t[2]), p(t[3])) > 0 {
                    t
                } else {
                    [t[0], t[2], t[1], t[3]]
                }
            })
            .collect()
    }

    /// The triangulation of the planar points that a tetrahedralization within the
    /// segments gives: the link of `x*` (`None` if no tetrahedron has `x*`).
    pub fn project(&self, tets: &[[u32; 4]]) -> Option<Vec<[u32; 3]>> {
        link(self.apexes().0, tets)
    }
}

/// The triangles opposite `apex` in the tetrahedra that have it (`None` if none has).
fn link(apex: u32, tets: &[[u32; 4]]) -> Option<Vec<[u32; 3]>> {
    let link: Vec<[u32; 3]> = tets
        .iter()
        .filter(|t| t.contains(&apex))
        .map(|t| {
            let mut f = [0u32; 3];
            for (k, &v) in t.iter().filter(|&&v| v != apex).enumerate() {
                f[k] = v;
            }
            f
        })
        .collect();
    (!link.is_empty()).then_some(link)
}

/// A point strictly inside the convex hull of `points` and on no line through two of
/// them (checked exactly): the first of [`centres`].
fn centre(points: &[Point2]) -> Option<Point2> {
    centres(points).next()
}

/// Points strictly inside the convex hull of `points` and on no line through two of them
/// (checked exactly): the centroid of all of them, then of triangles `0 i j`.
fn centres(points: &[Point2]) -> impl Iterator<Item = Point2> + '_ {
    let ring = crate::geom::Hull2::new(points).vertices;
    let inside = move |c: &Point2| {
        let k = ring.len();
        k >= 3
            && (0..k).all(|i| {
                orient2d(
                    &points[ring[i] as usize],
                    &points[ring[(i + 1) % k] as usize],
                    c,
                ) > 0
            })
    };
    let off_lines = |c: &Point2| {
        (0..points.len())
            .all(|a| (a + 1..points.len()).all(|b| orient2d(&points[a], &points[b], c) != 0))
    };
    let mean = move |idx: &[usize]| -> Point2 {
        let k = idx.len() as f64;
        [0, 1].map(|d| idx.iter().map(|&i| points[i][d]).sum::<f64>() / k)
    };
    let n = points.len();
    std::iter::once(mean(&(0..n).collect::<Vec<_>>()))
        .chain(
            (1..n)
                .flat_map(move |i| (i + 1..n).map(move |j| (i, j)))
                .map(move |(i, j)| mean(&[0, i, j])),
        )
        .filter(move |c| inside(c) && off_lines(c))
}

/// Three collinear points, if any (`O(n³)`).
fn collinear_triple(points: &[Point2]) -> Option<[u32; 3]> {
    let n = points.len() as u32;
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                let p = |v: u32| &points[v as usize];
                if orient2d(p(a), p(b), p(c)) == 0 {
                    return Some([a, b, c]);
                }
            }
        }
    }
    None
}

/// (C1) for the apex `top` and its mirror `(c, −z)`.
fn orientations_kept(points: &[Point2], lifted: &[Point3], top: Point3) -> bool {
    let bottom = [top[0], top[1], -top[2]];
    let n = points.len();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                let s = orient2d(&points[a], &points[b], &points[c]);
                let (la, lb, lc) = (&lifted[a], &lifted[b], &lifted[c]);
                let (up, down) = (orient3d(la, lb, lc, &top), orient3d(la, lb, lc, &bottom));
                if up != s || down != -s {
                    return false;
                }
            }
        }
    }
    true
}

/// (C2): the first lifted point that is not a vertex of the hull (three facets at least)
/// on a facet with an upward outward normal.
fn not_upper_hull_vertex(lifted: &[Point3]) -> Option<u32> {
    let hull = Hull3::new(lifted);
    if hull.dimension < 3 {
        // The lifted points lie in one plane (three points, or points on a circle up to
        // the lift's rounding): (C2) asks no lifted point below a triangle of others,
        // which holds exactly when the planar points are in convex position.
        let flat: Vec<Point2> = lifted.iter().map(|p| [p[0], p[1]]).collect();
        let corners = crate::geom::Hull2::new(&flat).vertices;
        return (0..lifted.len() as u32).find(|v| !corners.contains(v));
    }
    // Facet planes are oriented with the hull on their non-positive side: a facet faces
    // up when the point straight above one of its corners is on the positive side.
    let upward = |f: u32| {
        let [p, q, r] = hull.facet_planes[f as usize].map(|v| &lifted[v as usize]);
        orient3d(p, q, r, &[p[0], p[1], p[2] + 1.0]) > 0
    };
    (0..lifted.len()).find_map(|v| {
        let fs = hull.facets_of(v);
        let ok = fs.len() >= 3 && fs.iter().any(|&f| upward(f));
        (!ok).then_some(v as u32)
    })
}
