//! The improvement pass after the removals: exact flips inside the shell that keep both
//! surfaces' triangles and add no vertex ([`crate::flip`]).
//!
//! 3-2 flips while any applies (each removes a tetrahedron). When the removals left more
//! than [`DELAUNAY_ABOVE`]` · n` tetrahedra, also, on a copy and on another thread,
//! Lawson's flips towards the constrained Delaunay tetrahedralization followed by 3-2
//! flips, kept when they end with fewer tetrahedra. The removals are near 2.4 tetrahedra
//! per vertex on ordinary shells, where Delaunay flips add tetrahedra (TetGen's
//! constrained Delaunay meshes of nested spheres have about 3.3 per vertex); far above
//! that, as on Bern disks ([`super::generate::bern_disk`], where removals make
//! `Θ(n log n)`), they bring the count down to the constrained Delaunay one (3.0 per
//! vertex there). The result is never worse than the removals' and is certified like any
//! other.

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
    if before <= DELAUNAY_ABOVE * points.len() {
        let three_two = flip::reduce(points, &mut mesh.tets, ctl)?;
        return Ok(Improvement {
            before,
            three_two,
            delaunay: None,
        });
    }
    // Both routes at once, from the same removal: 3-2 flips alone, and Lawson's flips
    // then 3-2 flips.
    let mut lawson = mesh.tets.clone();
    let (alone, flipped) = rayon::join(
        || flip::reduce(points, &mut mesh.tets, ctl),
        || -> Result<_, crate::control::Stopped> {
            let flips = flip::delaunay(points, &mut lawson, ctl)?;
            Ok((flips, flip::reduce(points, &mut lawson, ctl)?))
        },
    );
    let (mut three_two, mut delaunay) = (alone?, None);
    let (flips, more) = flipped?;
    if lawson.len() < mesh.tets.len() {
        mesh.tets = lawson;
        // The count went from `before` through the Delaunay flips' net change, then
        // the 3-2 flips.
        three_two = more;
        delaunay = Some(flips);
    }
    Ok(Improvement {
        before,
        three_two,
        delaunay,
    })
}
