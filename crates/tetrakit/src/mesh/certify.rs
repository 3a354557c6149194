//! Certificates that tetrahedra tetrahedralize a given domain: the convex hull of a point
//! set (every point a vertex), a region given by its boundary (a polyhedron's facets;
//! the outer and reversed inner facets of a shell), or the region between two nested
//! convex polytopes whatever the triangulation of their facets ([`certify_shell`]). All
//! rest on [`verify`]; every tetrahedralization a solver returns passes one of them.

use super::report::{Problem, ProblemKind};
use super::{Polyhedron, rotated_face, sorted_face, verify};
use crate::geom::{Expansion, Hull3, Point3, orient2d_drop, orient3d_value, projection_axis};
use crate::numbering::ids;
use rayon::prelude::*;

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

/// Certifies that `tets` tetrahedralize the closed region `P − int(Q)` between the convex
/// hulls `P = CH(points)` and `Q = CH(points[inner])`, with no Steiner point, however the
/// tetrahedra triangulate the polygon facets of `P` and `Q` (thesis ch. 4; `Q` must be
/// full-dimensional and inside `P`, and may touch it).
///
/// The checks, all exact:
/// 1. [`verify`]: every tetrahedron positively oriented, faces paired on opposite sides,
///    no overlap near any vertex, the boundary a closed embedded surface.
/// 2. Every boundary triangle lies in a facet of `P`, facing out of `P`, or in a facet of
///    `Q`, facing into `Q`.
/// 3. Every vertex of a tetrahedron lies on `∂P` or `∂Q` (no Steiner point).
/// 4. The volumes: `Σ vol(t) = vol(P) − vol(Q)` exactly (sums of exact determinants).
///
/// By 1 and 2 the tetrahedra tile a region whose boundary lies in `∂P ∪ ∂Q`, so a union
/// of the pieces `∂P ∪ ∂Q` cuts space into; the orientations exclude `Q` and the outside,
/// and the volume leaves only `P − int(Q)`.
///
/// ```
/// use tetrakit::mesh::certify_shell;
/// // The unit cube around a small tetrahedron: the tetrahedron itself is not the shell.
/// let mut pts: Vec<[f64; 3]> =
///     (0..8).map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64]).collect();
/// pts.extend([[0.25, 0.25, 0.25], [0.5, 0.25, 0.25], [0.25, 0.5, 0.25], [0.25, 0.25, 0.5]]);
/// assert!(certify_shell(&pts, &[[8, 9, 10, 11]], &[8, 9, 10, 11]).is_err());
/// ```
pub fn certify_shell(points: &[Point3], tets: &[[u32; 4]], inner: &[u32]) -> Result<(), Problem> {
    first_problem(verify(points, tets, None).problems)?;
    let outer_hull = Hull3::new(points);
    let inner_points: Vec<Point3> = inner.iter().map(|&i| points[i as usize]).collect();
    let inner_hull = Hull3::new(&inner_points);
    if outer_hull.dimension < 3 || inner_hull.dimension < 3 {
        return Err(shell_problem(
            Vec::new(),
            "the outer or inner hull is flat".into(),
        ));
    }
    let mut local = vec![u32::MAX; points.len()];
    for (k, &i) in inner.iter().enumerate() {
        local[i as usize] = k as u32;
    }
    let on_inner = |v: u32| {
        let l = local[v as usize];
        l != u32::MAX && inner_hull.on_boundary(l as usize)
    };
    let on_outer = |v: u32| outer_hull.on_boundary(v as usize);
    if let Some(&v) = tets
        .iter()
        .flatten()
        .find(|&&v| !on_outer(v) && !on_inner(v))
    {
        return Err(Problem::new(
            ProblemKind::SteinerPoint,
            Vec::new(),
            vec![v],
            format!("vertex #{v} lies on neither the outer nor the inner surface"),
        ));
    }
    // A triangle in a facet's plane faces the same way as the facet's plane triple when
    // the two have the same orientation seen along an axis the plane is not parallel to.
    let same_way = |pts: &[Point3], plane: [u32; 3], f: [&Point3; 3]| -> bool {
        let q = |k: usize| &pts[plane[k] as usize];
        projection_axis(q(0), q(1), q(2)).is_some_and(|axis| {
            orient2d_drop(q(0), q(1), q(2), axis) == orient2d_drop(f[0], f[1], f[2], axis)
        })
    };
    let outer_side = |f: &[u32; 3]| -> bool {
        let facet = outer_hull.common_facet(f[0] as usize, f[1] as usize, f[2] as usize);
        let tri = f.map(|v| &points[v as usize]);
        facet.is_some_and(|g| same_way(points, outer_hull.facet_planes[g as usize], tri))
    };
    let inner_side = |f: &[u32; 3]| -> bool {
        if !f.iter().all(|&v| on_inner(v)) {
            return false;
        }
        let l = f.map(|v| local[v as usize] as usize);
        let facet = inner_hull.common_facet(l[0], l[1], l[2]);
        // Facing into Q: the reversed triangle faces out of it.
        let reversed = [f[0], f[2], f[1]].map(|v| &points[v as usize]);
        facet
            .is_some_and(|g| same_way(&inner_points, inner_hull.facet_planes[g as usize], reversed))
    };
    let boundary = boundary_faces(tets);
    if let Some(f) = boundary
        .par_iter()
        .find_first(|f| !outer_side(f) && !inner_side(f))
    {
        return Err(shell_problem(
            f.to_vec(),
            format!(
                "boundary triangle {} lies neither in a facet of the outer hull facing out nor in a facet of the inner hull facing in",
                ids(f)
            ),
        ));
    }
    let p = |v: u32| &points[v as usize];
    let tets_volume = exact_sum(
        tets.par_iter()
            .map(|t| orient3d_value(p(t[0]), p(t[1]), p(t[2]), p(t[3]))),
    );
    let expected = hull_volume(points, &outer_hull).sub(&hull_volume(&inner_points, &inner_hull));
    if tets_volume.sub(&expected).sign() != 0 {
        return Err(shell_problem(
            Vec::new(),
            format!(
                "the tetrahedra's volume ({:.6e}) is not the outer hull's minus the inner hull's ({:.6e})",
                tets_volume.estimate() / 6.0,
                expected.estimate() / 6.0
            ),
        ));
    }
    Ok(())
}

/// The exact sum of expansions, added pairwise in parallel.
fn exact_sum(terms: impl ParallelIterator<Item = Expansion>) -> Expansion {
    terms.reduce(Expansion::default, |a, b| a.add(&b))
}

/// Six times the volume of a hull: the cones from its first point over its outward
/// triangles.
fn hull_volume(pts: &[Point3], h: &Hull3) -> Expansion {
    exact_sum(h.triangles.par_iter().map(|t| {
        let q = |k: usize| &pts[t[k] as usize];
        orient3d_value(q(0), q(2), q(1), &pts[0])
    }))
}

fn shell_problem(vertices: Vec<u32>, detail: String) -> Problem {
    Problem::new(
        ProblemKind::BoundaryNotSurface,
        Vec::new(),
        vertices,
        detail,
    )
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
pub(crate) fn boundary_faces(tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
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
        // The same by the hulls alone, whatever the facets' triangulation.
        let inner: Vec<u32> = (0..block.points.len() as u32)
            .filter(|&v| {
                block.points[v as usize]
                    .iter()
                    .all(|&x| (1.0..=2.0).contains(&x))
            })
            .collect();
        assert_eq!(inner.len(), 8);
        assert_eq!(certify_shell(&block.points, &shell, &inner), Ok(()));
        assert!(certify_shell(&block.points, &block.tets, &inner).is_err());
        assert!(certify_shell(&block.points, &shell[1..], &inner).is_err());
        assert!(
            certify_shell(&block.points, &inner_tets_only(&inner, &block.tets), &inner).is_err()
        );
    }

    fn inner_tets_only(inner: &[u32], tets: &[[u32; 4]]) -> Vec<[u32; 4]> {
        tets.iter()
            .filter(|t| t.iter().all(|v| inner.contains(v)))
            .copied()
            .collect()
    }
}
