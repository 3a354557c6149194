//! Certificates that tetrahedra tetrahedralize a given domain: the convex hull of a point
//! set (every point a vertex), or a region given by its boundary (a polyhedron's facets;
//! the outer and reversed inner facets of a shell). Both rest on [`verify`]; every
//! tetrahedralization a solver returns passes one of them.

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

/// Certifies that `tets` tetrahedralize `poly`: [`certify_boundary`] with the
/// polyhedron's facets.
///
/// ```
/// use tetrakit::mesh::certify_polyhedron;
/// use tetrakit::polyhedra::{Checks, generate, mintetra};
/// let p = generate::stacked(8, 3);
/// let m = mintetra(&p, Checks::Shelling);
/// assert_eq!(certify_polyhedron(&p, &m.tets), Ok(()));
/// assert!(certify_polyhedron(&p, &m.tets[1..]).is_err());
/// ```
pub fn certify_polyhedron(poly: &Polyhedron, tets: &[[u32; 4]]) -> Result<(), Problem> {
    certify_boundary(&poly.points, tets, &poly.faces)
}

/// Certifies that `tets` tetrahedralize the region whose boundary is exactly `faces`,
/// each oriented outward from the region: [`verify`] (orientation, face pairing, no
/// overlap near any vertex, an embedded boundary, no nested piece) and the boundary
/// triangles of the tetrahedra are exactly `faces` with their orientation. A region with
/// holes is given by all its boundary surfaces: the shell between nested polytopes by
/// the outer facets and the inner ones reversed. Returns the first problem found.
///
/// ```
/// use tetrakit::mesh::certify_boundary;
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
/// assert_eq!(certify_boundary(&pts, &[[0, 1, 2, 3]], &faces), Ok(()));
/// assert!(certify_boundary(&pts, &[[0, 1, 2, 3]], &faces[1..]).is_err());
/// ```
pub fn certify_boundary(
    points: &[Point3],
    tets: &[[u32; 4]],
    faces: &[[u32; 3]],
) -> Result<(), Problem> {
    first_problem(verify(points, tets, None).problems)?;
    let boundary = boundary_faces(tets);
    let mut want: Vec<[u32; 3]> = faces.iter().map(|&f| rotated_face(f)).collect();
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
            "the boundary of the tetrahedra is not the given surface (face {} not covered, boundary triangle {} not a given face)",
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The 3 × 3 × 3 Kuhn block without its middle cube is a tetrahedralization of the
    /// shell between two cubes: its boundary is the outer faces and the middle cube's
    /// faces reversed, and neither surface alone will do.
    #[test]
    fn a_shell_is_certified_by_both_surfaces() {
        let block = crate::generate::kuhn(3);
        let p = |t: &[u32; 4]| t.map(|v| block.points[v as usize]);
        let middle = |t: &[u32; 4]| p(t).iter().flatten().all(|&x| (1.0..=2.0).contains(&x));
        let (inner, shell): (Vec<[u32; 4]>, Vec<[u32; 4]>) =
            block.tets.iter().partition(|t| middle(t));
        assert_eq!((inner.len(), shell.len()), (6, 156));
        let outer = boundary_faces(&block.tets);
        let hole: Vec<[u32; 3]> = boundary_faces(&inner)
            .iter()
            .map(|f| [f[0], f[2], f[1]])
            .collect();
        let both: Vec<[u32; 3]> = outer.iter().chain(&hole).copied().collect();
        assert_eq!(certify_boundary(&block.points, &shell, &both), Ok(()));
        assert!(certify_boundary(&block.points, &shell, &outer).is_err());
        // The hole filled is not the shell.
        assert!(certify_boundary(&block.points, &block.tets, &both).is_err());
    }
}
