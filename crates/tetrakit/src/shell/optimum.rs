//! The fewest tetrahedra of a small shell, from the exact solver ([`crate::exact`] with
//! [`Domain::Shell`]): how far the removals and flips are from the optimum.

use super::{Shell, ShellMesh};
use crate::control::Control;
use crate::exact::{Domain, ExactError, Options, Outcome, Stats, minimal_tetrahedralization};

/// The minimum number of tetrahedra over the tetrahedralizations of `shell` with the same
/// boundary triangles as `mesh`, and one that attains it. When `P` and `Q` are simplicial
/// that is every tetrahedralization of the shell; a polygon facet is kept triangulated as
/// in `mesh`, so the answer is then the minimum for that triangulation of the facets.
/// [`Outcome::Undecided`] when `ctl` stops first; an error above
/// [`crate::exact::MAX_VERTICES`] vertices.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::Outcome;
/// use tetrakit::shell::{Method, Shell, optimum, tetrahedralize};
/// // A cube in a cube: the fewest tetrahedra with the removal's triangles of the squares.
/// let cube = |s: f64| (0..8).map(|i| [0, 1, 2].map(|k| if (i >> k) & 1 == 1 { s } else { -s })).collect::<Vec<[f64; 3]>>();
/// let shell = Shell::new(&cube(2.0), &cube(1.0)).unwrap();
/// let ctl = Control::new();
/// let mesh = tetrahedralize(&shell, Method::Cap, &ctl).unwrap();
/// let (best, _) = optimum(&shell, &mesh, &ctl).unwrap();
/// let Outcome::Optimal { tets, .. } = best else { panic!() };
/// assert!(tets.len() <= mesh.tets.len());
/// ```
pub fn optimum(
    shell: &Shell,
    mesh: &ShellMesh,
    ctl: &Control,
) -> Result<(Outcome, Stats), ExactError> {
    let faces = crate::mesh::boundary_faces(&mesh.tets);
    let domain = Domain::Shell {
        points: &shell.points,
        faces: &faces,
    };
    minimal_tetrahedralization(domain, &Options::default(), ctl)
}
