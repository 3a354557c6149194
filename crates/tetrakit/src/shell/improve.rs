//! The improvement pass after the removals: exact flips inside the shell that keep both
//! surfaces' triangles and add no vertex ([`crate::flip`]).
//!
//! First 3-2 flips while any applies (each removes a tetrahedron). Then, when more than
//! [`DELAUNAY_ABOVE`]` · n` tetrahedra are left, Lawson's flips towards the constrained
//! Delaunay tetrahedralization followed by 3-2 flips again, kept only if they end with
//! fewer tetrahedra. The removals are near 2.4 tetrahedra per vertex on ordinary shells,
//! where Delaunay flips add tetrahedra (TetGen's constrained Delaunay meshes of nested
//! spheres have about 3.3 per vertex); far above that, as on Bern disks
//! ([`super::generate::bern_disk`], where removals make `Θ(n log n)`), they bring the
//! count down to the constrained Delaunay one (3.0 per vertex there). The result is never
//! worse than the removals' and is certified like any other.

use super::{ShellError, ShellMesh};
use crate::control::Control;
use crate::flip;
use crate::geom::Point3;

/// Tetrahedra per vertex above which the Delaunay flips are tried.
pub const DELAUNAY_ABOVE: usize = 3;

/// What [`improve`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Improvement {
    /// Tetrahedra before the pass.
    pub before: usize,
    /// 3-2 flips kept.
    pub three_two: usize,
    /// The Delaunay flips, when tried and kept.
    pub delaunay: Option<flip::Flips>,
}

/// Improves `mesh` of the shell on `points` in place (see the module docs).
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::shell::{Method, Shell, improve, tetrahedralize};
/// use tetrakit::shell::generate::bern_disk;
/// let (outer, inner) = bern_disk(200, 50, 1).unwrap();
/// let shell = Shell::new(&outer, &inner).unwrap();
/// let ctl = Control::new();
/// let mut mesh = tetrahedralize(&shell, Method::Cap, &ctl).unwrap();
/// let done = improve(&shell.points, &mut mesh, &ctl).unwrap();
/// assert!(mesh.tets.len() < done.before);
/// assert!(tetrakit::mesh::certify_shell(&shell.points, &mesh.tets, &shell.inner).is_ok());
/// ```
pub fn improve(
    points: &[Point3],
    mesh: &mut ShellMesh,
    ctl: &Control,
) -> Result<Improvement, ShellError> {
    let before = mesh.tets.len();
    let mut three_two = flip::reduce(points, &mut mesh.tets, ctl)?;
    let mut delaunay = None;
    if mesh.tets.len() > DELAUNAY_ABOVE * points.len() {
        let mut tets = mesh.tets.clone();
        let flips = flip::delaunay(points, &mut tets, ctl)?;
        let more = flip::reduce(points, &mut tets, ctl)?;
        if tets.len() < mesh.tets.len() {
            mesh.tets = tets;
            // The count went from `before` down through the first 3-2 flips, then the
            // Delaunay flips' net change, then the second 3-2 flips.
            three_two += more;
            delaunay = Some(flips);
        }
    }
    Ok(Improvement {
        before,
        three_two,
        delaunay,
    })
}
