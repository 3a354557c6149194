//! Certificates that tetrahedra tetrahedralize a given domain: the convex hull of a point
//! set (every point a vertex) or a polyhedron (boundary exactly its facets). Both rest on
//! [`verify`]; every tetrahedralization a solver returns passes one of them.

use super::report::{Problem, ProblemKind};
use super::{Polyhedron, rotated_face, sorted_face, verify};
use crate::geom::{Hull3, Point3};
use crate::numbering::ids;

/// Certifies that `tets` tetrahedralize the convex hull of `points` with every point a
/// vertex ([`verify`] with the hull). Returns the first problem found.
///
/// ```
/// use tetrakit::mesh::certify_hull;
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// assert_eq!(certify_hull(&pts, &[[0, 1, 2, 3]]), Ok(()));
/// assert!(certify_hull(&pts, &[[0, 2, 1, 3]]).is_err()); // inverted
/// ```
pub fn certify_hull(points: &[Point3], tets: &[[u32; 4]]) -> Result<(), Problem> {
    let hull = Hull3::new(points);
    first_problem(verify(points, tets, Some(&hull)).problems)
}

/// Certifies that `tets` tetrahedralize `poly`: [`verify`] (orientation, face pairing,
/// no overlap) and the boundary triangles are exactly the polyhedron's facets with their
/// outward orientation. Returns the first problem found.
///
/// ```
/// use tetrakit::mesh::certify_polyhedron;
/// use tetrakit::polyhedra::{generate, mintetra};
/// let p = generate::stacked(8, 3);
/// let m = mintetra(&p);
/// assert_eq!(certify_polyhedron(&p, &m.tets), Ok(()));
/// assert!(certify_polyhedron(&p, &m.tets[1..]).is_err());
/// ```
pub fn certify_polyhedron(poly: &Polyhedron, tets: &[[u32; 4]]) -> Result<(), Problem> {
    first_problem(verify(&poly.points, tets, None).problems)?;
    let boundary = boundary_faces(tets);
    let mut want: Vec<[u32; 3]> = poly.faces.iter().map(|&f| rotated_face(f)).collect();
    want.sort_unstable();
    if boundary == want {
        return Ok(());
    }
    let missing = want.iter().find(|f| boundary.binary_search(f).is_err());
    let extra = boundary.iter().find(|f| want.binary_search(f).is_err());
    let name = |f: Option<&[u32; 3]>| f.map_or("none".to_string(), |f| ids(f));
    Err(Problem::new(
        ProblemKind::BoundaryNotSurface,
        Vec::new(),
        missing
            .into_iter()
            .chain(extra)
            .flatten()
            .copied()
            .collect(),
        format!(
            "the boundary of the tetrahedra is not the polyhedron's surface (facet {} not covered, boundary triangle {} not a facet)",
            name(missing),
            name(extra)
        ),
    ))
}

fn first_problem(problems: Vec<Problem>) -> Result<(), Problem> {
    match problems.into_iter().next() {
        None => Ok(()),
        Some(p) => Err(p),
    }
}

/// The faces of exactly one tetrahedron, outward and rotated to their smallest vertex,
/// sorted. A positively oriented tet (a,b,c,d) has outward faces (a,c,b), (a,b,d),
/// (a,d,c), (b,c,d).
fn boundary_faces(tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
    let mut faces: Vec<([u32; 3], [u32; 3])> = tets
        .iter()
        .flat_map(|&[a, b, c, d]| [[a, c, b], [a, b, d], [a, d, c], [b, c, d]])
        .map(|f| (sorted_face(f), rotated_face(f)))
        .collect();
    faces.sort_unstable();
    let mut boundary = Vec::new();
    for run in faces.chunk_by(|x, y| x.0 == y.0) {
        if run.len() == 1 {
            boundary.push(run[0].1);
        }
    }
    boundary.sort_unstable();
    boundary
}
