//! Exact geometry: predicates, intersection tests and convex hulls, and the planar bucket
//! grid the searches share.
//!
//! This is the narrow interface behind which every geometric decision of tetrakit is
//! made (ARCHITECTURE.md, "Invariants"). Nothing here uses a tolerance: floating-point
//! arithmetic appears only as a filter whose error bound is proven, with an exact
//! fallback, or in the bucket grid, which only proposes candidates to exact tests.

mod anchor;
mod coplanar;
mod delaunay3;
mod expansion;
mod grid;
mod hull2;
mod hull3;
mod intersect;
mod predicates;
mod proximity;
mod radical;

pub(crate) use anchor::anchor;
pub use coplanar::triangulate_coplanar;
pub use delaunay3::{Delaunay3, DelaunayError};
pub use expansion::{Expansion, orient3d_value};
pub(crate) use expansion::{det3, vector};
pub(crate) use grid::Grid2;
pub use hull2::Hull2;
pub use hull3::{Hull3, affine_dimension, placing};
pub use intersect::{
    SegmentMeet, cones_overlap, coplanar_triangles_overlap, point_in_closed_tetrahedron,
    point_in_segment_interior, segment_meets_closed_triangle, segment_meets_tet_improperly,
    segments_meet, tetrahedra_overlap, triangles_meet_improperly,
};
pub(crate) use intersect::{
    segment_meets_open_tetrahedron, segment_meets_open_triangle, segment_punctures_triangle,
    triangle_meets_tet,
};
pub(crate) use predicates::{
    Dir, Plane, drop_axis, lex_cmp, orient2d_drop, project_to_plane, projection_axis,
    strictly_between,
};
pub use predicates::{
    Frame, MAX_MAGNITUDE, MIN_MAGNITUDE, Point2, Point3, bounding_box, collinear3,
    coordinate_in_range, incircle, insphere, orient2d, orient3d,
};
pub use proximity::{Ratio, RatioError, in_beta_region, in_lune};
pub(crate) use proximity::{cmp_length, corner_dot_sign, diamond_hit, squared_length};
pub use radical::Interval;
pub(crate) use radical::{DoubleDouble, compare_root_sums};

/// The exact identity of a point, for hashing: equal keys mean equal coordinates
/// (`-0.0` and `0.0` are one coordinate).
///
/// ```
/// use tetrakit::geom::point_key;
/// assert_eq!(point_key(&[0.0, 1.0, 2.0]), point_key(&[-0.0, 1.0, 2.0]));
/// assert_ne!(point_key(&[0.0, 1.0, 2.0]), point_key(&[0.0, 1.0, 2.5]));
/// ```
pub fn point_key(p: &Point3) -> [u64; 3] {
    p.map(|x| (x + 0.0).to_bits())
}

/// Why a point set has no tetrahedralization that uses every point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetDefect {
    /// Fewer than four points.
    TooFew(usize),
    /// Two points at the same coordinates (no tetrahedralization uses both).
    Duplicate {
        /// The first point.
        first: u32,
        /// The later copy.
        second: u32,
    },
    /// Every point on one plane.
    Flat,
}

impl std::fmt::Display for SetDefect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SetDefect::TooFew(n) => write!(f, "{n} points: a tetrahedralization needs at least 4"),
            SetDefect::Duplicate { first, second } => {
                write!(
                    f,
                    "points #{first} and #{second} coincide: no tetrahedralization uses both"
                )
            }
            SetDefect::Flat => write!(f, "the points are coplanar: there is no tetrahedralization"),
        }
    }
}

impl std::error::Error for SetDefect {}

/// At least four distinct points, not all on one plane: the sets a tetrahedralization
/// can use every point of.
///
/// ```
/// use tetrakit::geom::{SetDefect, solid_set};
/// let flat = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]];
/// assert_eq!(solid_set(&flat), Err(SetDefect::Flat));
/// ```
pub fn solid_set(points: &[Point3]) -> Result<(), SetDefect> {
    if points.len() < 4 {
        return Err(SetDefect::TooFew(points.len()));
    }
    let mut seen = std::collections::HashMap::new();
    for (i, p) in points.iter().enumerate() {
        if let Some(&first) = seen.get(&point_key(p)) {
            return Err(SetDefect::Duplicate {
                first,
                second: i as u32,
            });
        }
        seen.insert(point_key(p), i as u32);
    }
    if affine_dimension(points) < 3 {
        return Err(SetDefect::Flat);
    }
    Ok(())
}
