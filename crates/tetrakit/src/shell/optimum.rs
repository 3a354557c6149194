//! The fewest tetrahedra of a small shell, from the exact solver ([`crate::exact`] with
//! [`Domain::Shell`]): how far the removals and flips are from the optimum.

use super::Shell;
use crate::control::Control;
use crate::exact::{Domain, ExactError, Options, Outcome, Stats, minimal_tetrahedralization};

/// The minimum number of tetrahedra over all tetrahedralizations of `shell` (polygon
/// facets of `P` and `Q` triangulated in any way), and one that attains it;
/// [`Outcome::Undecided`] when `ctl` stops first; an error above
/// [`crate::exact::MAX_VERTICES`] vertices.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::Outcome;
/// use tetrakit::shell::{Method, Shell, optimum, tetrahedralize};
/// // A cube in a cube.
/// let cube = |s: f64| (0..8).map(|i| [0, 1, 2].map(|k| if (i >> k) & 1 == 1 { s } else { -s })).collect::<Vec<[f64; 3]>>();
/// let shell = Shell::new(&cube(2.0), &cube(1.0)).unwrap();
/// let ctl = Control::new();
/// let mesh = tetrahedralize(&shell, Method::Cap, &ctl).unwrap();
/// let (best, _) = optimum(&shell, &ctl).unwrap();
/// let Outcome::Optimal { tets, .. } = best else { panic!() };
/// assert!(tets.len() <= mesh.tets.len());
/// ```
pub fn optimum(shell: &Shell, ctl: &Control) -> Result<(Outcome, Stats), ExactError> {
    let domain = Domain::Shell {
        points: &shell.points,
        inner: &shell.inner,
        outer_faces: None,
    };
    minimal_tetrahedralization(domain, &Options::default(), ctl)
}
