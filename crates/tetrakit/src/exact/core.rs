//! Where a NO happens (thesis ch. 6: how hard is it to decide whether a convex
//! polyhedron with a triangulated surface can be tetrahedralized?). The formula of the
//! module docs covers every facet with a candidate tetrahedron on its inner side, allows
//! at most one chosen tetrahedron on each side of a triangle, and pairs every inner face
//! of a chosen one with a chosen one across it. Guard each facet's covering clause and
//! each inner face's pairing clauses by a literal of their own, and a NO is an
//! unsatisfiable set of guards: [`face_core`] shrinks it to a *minimal* set (without any
//! one of them the clauses are satisfiable), from the solver's core and then by
//! deletion. Its vertices are where the NO happens: a few facets that no candidates
//! cover without overlapping, or the pairings around a twisted prism, or a cell that
//! runs round the whole polyhedron. Minimal is not minimum: another, smaller core may
//! exist.

use super::encode::Domain;
use super::{Edges, ExactError, Formula, check_size, polyhedron_pairs, restricted};
use crate::control::Control;
use crate::mesh::Polyhedron;
use rustsat::solvers::{Solve, SolveIncremental, SolverResult};
use rustsat::types::Lit;

/// A minimal set of facets to cover and inner faces to pair that no candidate
/// tetrahedra satisfy together ([`face_core`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FaceCore {
    /// The facets whose covering the refutation needs, each with its vertices in
    /// increasing order, sorted.
    pub facets: Vec<[u32; 3]>,
    /// The inner faces whose pairing it needs, likewise.
    pub faces: Vec<[u32; 3]>,
    /// Their vertices, sorted.
    pub vertices: Vec<u32>,
    /// SAT calls made.
    pub calls: usize,
}

/// A minimal set of `p`'s facets to cover and candidate faces to pair that no set of
/// candidate tetrahedra satisfies; `None` when a tetrahedralization exists, when no
/// candidate tetrahedron exists (the witness is then `no_candidate`), or when `ctl`
/// stopped first.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::face_core;
/// use tetrakit::polyhedra::generate::{ConvexShape, convex_triangulated};
/// // A prism over a square, its facets triangulated at random: no tetrahedralization.
/// let p = convex_triangulated(ConvexShape::Prism, 4, 0, 5).unwrap();
/// let core = face_core(&p, &Control::new()).unwrap().expect("a NO");
/// assert!(!core.facets.is_empty() && core.vertices.len() <= p.points.len());
/// ```
pub fn face_core(p: &Polyhedron, ctl: &Control) -> Result<Option<FaceCore>, ExactError> {
    let domain = Domain::Polyhedron(p);
    check_size(domain, Edges::default())?;
    let Ok(pairs) = polyhedron_pairs(domain, Edges::default(), ctl) else {
        return Ok(None);
    };
    let edges = restricted(Edges::default(), pairs.as_deref());
    let mut guards = Vec::new();
    let Some(f) = Formula::guarded(domain, edges, ctl, Some(&mut guards))? else {
        return Ok(None);
    };
    if f.cand.tets.is_empty() {
        return Ok(None);
    }
    let mut solver = crate::control::sat_solver(ctl);
    solver.add_cnf(f.cnf).expect("batsat accepts clauses");
    let mut calls = 0;
    // The guards an unsatisfiable call needed (from the solver's core), `Some(None)`
    // when satisfiable, `None` when stopped.
    let mut needed = |assumed: &[Lit]| -> Option<Option<Vec<Lit>>> {
        calls += 1;
        match solver.solve_assumps(assumed).expect("batsat") {
            SolverResult::Unsat => {
                let core = solver.core().expect("a core after UNSAT");
                Some(Some(
                    assumed
                        .iter()
                        .copied()
                        .filter(|l| core.contains(&!*l))
                        .collect(),
                ))
            }
            SolverResult::Sat => Some(None),
            SolverResult::Interrupted => None,
        }
    };
    let all: Vec<Lit> = guards.iter().map(|g| g.1).collect();
    let Some(Some(mut keep)) = needed(&all) else {
        return Ok(None);
    };
    let mut i = 0;
    while i < keep.len() {
        let without: Vec<Lit> = (keep.iter().enumerate())
            .filter(|&(k, _)| k != i)
            .map(|(_, &l)| l)
            .collect();
        match needed(&without) {
            Some(Some(smaller)) => keep = smaller,
            Some(None) => i += 1,
            None => return Ok(None),
        }
    }
    let facets_of_p: std::collections::HashSet<[u32; 3]> = p
        .faces
        .iter()
        .map(|&f| crate::mesh::sorted_face(f))
        .collect();
    let (mut facets, mut faces) = (Vec::new(), Vec::new());
    for (f, _) in guards.iter().filter(|g| keep.contains(&g.1)) {
        match facets_of_p.contains(f) {
            true => facets.push(*f),
            false => faces.push(*f),
        }
    }
    facets.sort_unstable();
    faces.sort_unstable();
    let mut vertices: Vec<u32> = facets.iter().chain(&faces).flatten().copied().collect();
    vertices.sort_unstable();
    vertices.dedup();
    Ok(Some(FaceCore {
        facets,
        faces,
        vertices,
        calls,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{WitnessKind, tetrahedralize};
    use crate::polyhedra::generate::{ConvexShape, convex_triangulated};
    use varisat::ExtendFormula;

    /// The guarded formula of `p` with the guards of `on` set and every other guard
    /// unset, decided by varisat (another solver than the one [`face_core`] uses).
    fn satisfiable_with(p: &Polyhedron, on: &[[u32; 3]]) -> bool {
        let domain = Domain::Polyhedron(p);
        let pairs = polyhedron_pairs(domain, Edges::default(), &Control::new()).unwrap();
        let edges = restricted(Edges::default(), pairs.as_deref());
        let mut guards = Vec::new();
        let f = Formula::guarded(domain, edges, &Control::new(), Some(&mut guards))
            .unwrap()
            .unwrap();
        let lit = |l: Lit| varisat::Lit::from_dimacs(l.to_ipasir() as isize);
        let mut v = varisat::CnfFormula::new();
        for clause in f.cnf.iter() {
            v.add_clause(&clause.iter().map(|&l| lit(l)).collect::<Vec<_>>());
        }
        for (face, g) in &guards {
            v.add_clause(&[if on.contains(face) { lit(*g) } else { !lit(*g) }]);
        }
        let mut solver = varisat::Solver::new();
        solver.add_formula(&v);
        solver.solve().unwrap()
    }

    /// On random triangulated prisms and cubes, every core is unsatisfiable and each of
    /// its facets and faces is needed (without it, satisfiable), by varisat; and a
    /// polyhedron with no core has a tetrahedralization or a short witness.
    #[test]
    fn cores_are_unsatisfiable_and_minimal() {
        let (mut cores, mut yes) = (0, 0);
        for seed in 0..120 {
            let shape = [ConvexShape::Prism, ConvexShape::Cube][seed as usize % 2];
            let p = convex_triangulated(shape, 4 + (seed as usize % 9), 0, seed).unwrap();
            let Some(core) = face_core(&p, &Control::new()).unwrap() else {
                let o = tetrahedralize(Domain::Polyhedron(&p), Default::default(), &Control::new());
                let kind = o.unwrap().witness.map(|w| w.kind);
                assert_ne!(kind, Some(WitnessKind::Unsatisfiable), "seed {seed}");
                yes += usize::from(kind.is_none());
                continue;
            };
            cores += 1;
            let all: Vec<[u32; 3]> = core.facets.iter().chain(&core.faces).copied().collect();
            assert!(!satisfiable_with(&p, &all), "seed {seed}");
            for k in 0..all.len() {
                let mut fewer = all.clone();
                fewer.remove(k);
                assert!(
                    satisfiable_with(&p, &fewer),
                    "seed {seed}: {:?} not needed",
                    all[k]
                );
            }
        }
        assert!(cores > 10 && yes > 10, "{cores} cores, {yes} without");
    }
}
