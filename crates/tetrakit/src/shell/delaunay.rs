//! The shell from the Delaunay tetrahedralization of its vertices, when `Q` is a union
//! of its tetrahedra: where the removals make `Θ(n log n)` tetrahedra (Bern disks,
//! [`super::generate::bern_disk`]) and the flips would bring them down to the
//! constrained Delaunay count, that count is reached directly ([`Delaunay3`]).
//!
//! The test is exact and combinatorial. `D`, the union of the tetrahedra with four
//! vertices of `Q`, lies in `Q` (convex). When `D` is not empty and every face between
//! a tetrahedron of `D` and one outside it lies in a facet of `Q` (its vertices share a
//! facet of `Q`'s hull), `∂D ⊆ ∂Q` (the hull faces of `D` lie on `∂P ∩ Q ⊆ ∂Q`), so `D`
//! is open and closed in `int Q`, hence `D = Q`, and the other tetrahedra tile
//! `P − int Q`. Otherwise some Delaunay tetrahedron crosses a facet of `Q` and the answer
//! is `None`: the removal decides.

use super::Shell;
use crate::control::{Control, Stopped};
use crate::geom::{Delaunay3, DelaunayError};

/// The Delaunay tetrahedra of the shell's vertices outside `Q`, when `Q` is a union of
/// Delaunay tetrahedra (see the module docs); `None` otherwise.
pub(super) fn delaunay_shell(s: &Shell, ctl: &Control) -> Result<Option<Vec<[u32; 4]>>, Stopped> {
    let d = match Delaunay3::within(&s.points, ctl) {
        Ok(d) => d,
        Err(DelaunayError::Stopped) => return Err(Stopped),
        Err(_) => return Ok(None),
    };
    Ok(union_outside(s, d))
}

/// The tetrahedra of `d` outside `Q`, when those inside make `Q` (the module docs' test).
fn union_outside(s: &Shell, d: Delaunay3) -> Option<Vec<[u32; 4]>> {
    // Each vertex of Q by its index among the inner input points.
    let mut source = vec![u32::MAX; s.points.len()];
    for (&k, &i) in s.inner.iter().zip(&s.inner_source) {
        source[k as usize] = i;
    }
    let in_q: Vec<bool> = (d.tets.iter())
        .map(|t| t.iter().all(|&v| source[v as usize] != u32::MAX))
        .collect();
    if !in_q.contains(&true) {
        return None;
    }
    for (t, c) in d.tets.iter().enumerate().filter(|&(t, _)| !in_q[t]) {
        for (k, &n) in d.neighbours[t].iter().enumerate() {
            if n == u32::MAX || !in_q[n as usize] {
                continue;
            }
            let f: Vec<usize> = (0..4)
                .filter(|&i| i != k)
                .map(|i| source[c[i] as usize] as usize)
                .collect();
            s.inner_hull.common_facet(f[0], f[1], f[2])?;
        }
    }
    let outside = d.tets.into_iter().zip(in_q).filter(|&(_, q)| !q);
    Some(outside.map(|(t, _)| t).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point3;
    use crate::mesh::certify_shell;
    use crate::rng::Rng;

    /// A random pair: points near two spheres (the inner one off-centre, sometimes close
    /// to the outer), points on a sphere around a needle, or integer points in a box and a box inside it (coplanar facets,
    /// contact with the outer facets, corners shared).
    fn pair(rng: &mut Rng, round: usize) -> (Vec<Point3>, Vec<Point3>) {
        let mut on_sphere = |r: f64, c: f64, n: usize| -> Vec<Point3> {
            (0..n)
                .map(|_| {
                    let v: Point3 = [0, 1, 2].map(|_| rng.unit() * 2.0 - 1.0);
                    let l = v.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-9);
                    [c + r * v[0] / l, r * v[1] / l, r * v[2] / l]
                })
                .collect()
        };
        if round.is_multiple_of(3) {
            let gap = [0.3, 0.6, 0.9][round / 3 % 3];
            let outer = on_sphere(1.0, 0.0, 8 + round % 13);
            let inner = on_sphere(0.5 * gap, 0.45 * (1.0 - gap), 4 + round % 7);
            return (outer, inner);
        }
        if round % 3 == 1 {
            // A needle along a diameter: Delaunay edges between outer points cross it.
            let outer = on_sphere(1.0, 0.0, 8 + round % 13);
            let inner = on_sphere(0.05, 0.0, 4 + round % 7)
                .into_iter()
                .map(|p| [p[0] * 16.0, p[1], p[2]])
                .collect();
            return (outer, inner);
        }
        let grid = |rng: &mut Rng, lo: usize, side: usize, n: usize| -> Vec<Point3> {
            (0..n)
                .map(|_| [0, 1, 2].map(|_| (lo + rng.below(side + 1)) as f64))
                .collect()
        };
        let outer = grid(rng, 0, 4, 6 + round % 20);
        let inner = grid(rng, 1 + round % 2, 1 + round % 3, 4 + round % 9);
        (outer, inner)
    }

    /// The exact test of the module docs says yes exactly when the independent
    /// certificate accepts the tetrahedra outside `Q`, on shells of both kinds.
    #[test]
    fn the_facet_test_agrees_with_the_certificate() {
        let mut rng = Rng::new(45);
        let (mut yes, mut no) = (0, 0);
        for round in 0..1200 {
            let (outer, inner) = pair(&mut rng, round);
            let Ok(s) = Shell::new(&outer, &inner) else {
                continue;
            };
            let Ok(d) = Delaunay3::new(&s.points) else {
                continue;
            };
            let inside = |t: &[u32; 4]| t.iter().all(|v| s.inner.contains(v));
            let kept: Vec<[u32; 4]> = d.tets.into_iter().filter(|t| !inside(t)).collect();
            let certified = certify_shell(&s.points, &kept, &s.inner).is_ok();
            let found = delaunay_shell(&s, &Control::new()).unwrap();
            assert_eq!(found.is_some(), certified, "round {round}");
            assert!(found.is_none_or(|t| t == kept));
            (yes, no) = (yes + usize::from(certified), no + usize::from(!certified));
        }
        assert!(yes > 150 && no > 150, "{yes} yes, {no} no");
    }
}
