//! Exact geometry: predicates, intersection tests and convex hulls, and the planar bucket
//! grid the searches share.
//!
//! This is the narrow interface behind which every geometric decision of tetrakit is
//! made (ARCHITECTURE.md, "Invariants"). Nothing here uses a tolerance: floating-point
//! arithmetic appears only as a filter whose error bound is proven, with an exact
//! fallback, or in the bucket grid, which only proposes candidates to exact tests.

mod anchor;
mod coplanar;
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
pub use expansion::{Expansion, det3, edge_edge_side, orient3d_value, parallel, vector};
pub(crate) use grid::Grid2;
pub use hull2::Hull2;
pub use hull3::{Hull3, affine_dimension};
pub use intersect::{
    SegmentMeet, cones_overlap, coplanar_triangles_overlap, point_in_closed_tetrahedron,
    point_in_segment_interior, segment_meets_open_tetrahedron, segment_meets_open_triangle,
    segment_meets_tet_improperly, segment_punctures_triangle, segments_meet, tetrahedra_overlap,
    triangle_meets_tet, triangles_meet_improperly,
};
pub use predicates::{
    ApexPlane, ApexSpheres, Dir, Frame, MAX_MAGNITUDE, MIN_MAGNITUDE, Plane, Point2, Point3,
    bounding_box, collinear3, coordinate_in_range, drop_axis, incircle, insphere, lex_cmp,
    orient2d, orient2d_drop, orient3d, project_to_plane, projection_axis, strictly_between,
};
pub use proximity::{
    DiamondHit, Ratio, RatioError, cmp_length, corner_dot_sign, diamond_hit, in_beta_region,
    in_lune, squared_length,
};
pub use radical::{DoubleDouble, Interval, compare_root_sums};

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
