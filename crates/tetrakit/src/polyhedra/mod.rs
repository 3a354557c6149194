//! Chapter 3: minimal tetrahedralizations of polyhedra.
//!
//! * [`Polyhedron`]: a simple polyhedron, validated exactly (closed, edge-manifold,
//!   orientable, genus 0, not self-intersecting) and oriented outward.
//! * [`SurfaceGraph`]: the graph G(P) of §3.2 (degrees, adjacency, tri(ab)).
//! * [`bp_nets`], [`is_proper`], [`are_disjoint`]: BP-nets of §3.3.1 (Theorem 3.4).
//! * [`mintetra`]: Algorithm MINTETRA of §3.4 for augmented and multi-level BP-polyhedra.
//! * [`certify`]: the independent check of a tetrahedralization of a polyhedron.
//! * [`generate`]: stacked polyhedra, bipyramids, BP-polyhedra, Schönhardt.

mod bpnet;
pub mod generate;
mod graph;
mod mintetra;

pub use crate::mesh::{Polyhedron, SurfaceError};
pub use bpnet::{BpNet, are_disjoint, bp_nets, is_proper, proper_nets_disjoint, strip_stacked};
pub use graph::SurfaceGraph;
pub use mintetra::{Checks, Mintetra, mintetra, mintetra_with};

use crate::mesh::verify;

/// Certifies that `tets` tetrahedralize `poly`: [`mesh::verify`](crate::mesh::verify)
/// (orientation, face pairing, no overlap) and the boundary triangles are exactly the
/// polyhedron's facets with their outward orientation. Returns the first problem found.
///
/// ```
/// use tetrakit::polyhedra::{certify, generate, mintetra};
/// let p = generate::stacked(8, 3);
/// let m = mintetra(&p);
/// assert_eq!(certify(&p, &m.tets), Ok(()));
/// assert!(certify(&p, &m.tets[1..]).is_err());
/// ```
pub fn certify(poly: &Polyhedron, tets: &[[u32; 4]]) -> Result<(), String> {
    let report = verify(&poly.points, tets, None);
    if let Some(p) = report.problems.first() {
        return Err(format!("{:?}: {}", p.kind, p.detail));
    }
    // Boundary faces, outward: a tet (a,b,c,d) positively oriented has outward faces
    // (b,d,c), (a,c,d), (a,d,b), (a,b,c) under the orientation convention of mesh.
    let mut faces: Vec<([u32; 3], [u32; 3])> = tets
        .iter()
        .flat_map(|&[a, b, c, d]| [[a, c, b], [a, b, d], [a, d, c], [b, c, d]])
        .map(|f| (crate::mesh::sorted_face(f), crate::mesh::rotated_face(f)))
        .collect();
    faces.sort_unstable();
    let mut boundary = Vec::new();
    let mut i = 0;
    while i < faces.len() {
        let mut j = i + 1;
        while j < faces.len() && faces[j].0 == faces[i].0 {
            j += 1;
        }
        if j - i == 1 {
            boundary.push(faces[i].1);
        }
        i = j;
    }
    let mut want: Vec<[u32; 3]> = poly
        .faces
        .iter()
        .map(|&f| crate::mesh::rotated_face(f))
        .collect();
    boundary.sort_unstable();
    want.sort_unstable();
    if boundary != want {
        let missing = want.iter().find(|f| boundary.binary_search(f).is_err());
        let extra = boundary.iter().find(|f| want.binary_search(f).is_err());
        return Err(format!(
            "the boundary of the tetrahedra is not the polyhedron's surface (facet {missing:?} not covered, boundary triangle {extra:?} not a facet)"
        ));
    }
    Ok(())
}
