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

/// What [`smallest_core`] found: the core with the fewest vertices, or that every core
/// has more than it searched.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SmallestCore {
    /// A core with the fewest vertices (a minimal one, its vertices exactly the
    /// smallest set whose facets and faces are unsatisfiable), or `None` when every set
    /// of at most `searched` vertices is satisfiable.
    pub core: Option<FaceCore>,
    /// Every vertex set of at most this many vertices was tried.
    pub searched: usize,
    /// Vertex sets decided by the solver (sets whose facets and faces were those of a
    /// set already decided are not asked again).
    pub sets: usize,
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
    let Some(mut g) = Guarded::new(p, ctl)? else {
        return Ok(None);
    };
    let all: Vec<Lit> = g.guards.iter().map(|g| g.1).collect();
    let Some(Some(keep)) = g.needed(&all) else {
        return Ok(None);
    };
    Ok(g.shrink(keep).map(|keep| g.core(p, &keep)))
}

/// The core of `p`'s refutation with the fewest vertices, searched exhaustively over
/// the vertex sets of at most `most` vertices that hold a facet, smallest first: the
/// first set whose facets and faces (those with every vertex in the set) are
/// unsatisfiable has the fewest vertices any core can have. `None` as for
/// [`face_core`]. Each set is one SAT call under assumptions; there are up to
/// `facets × C(n − 3, most − 3)` of them.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::{face_core, smallest_core};
/// use tetrakit::polyhedra::generate::{ConvexShape, convex_triangulated};
/// let p = convex_triangulated(ConvexShape::Prism, 4, 0, 5).unwrap();
/// let s = smallest_core(&p, 8, &Control::new()).unwrap().expect("a NO");
/// let least = s.core.expect("a core of at most 8 vertices").vertices.len();
/// assert!(least <= face_core(&p, &Control::new()).unwrap().unwrap().vertices.len());
/// ```
pub fn smallest_core(
    p: &Polyhedron,
    most: usize,
    ctl: &Control,
) -> Result<Option<SmallestCore>, ExactError> {
    let Some(mut g) = Guarded::new(p, ctl)? else {
        return Ok(None);
    };
    let all: Vec<Lit> = g.guards.iter().map(|g| g.1).collect();
    if !matches!(g.needed(&all), Some(Some(_))) {
        return Ok(None);
    }
    let n = p.points.len() as u32;
    let mut facets: Vec<[u32; 3]> = p
        .faces
        .iter()
        .map(|&f| crate::mesh::sorted_face(f))
        .collect();
    facets.sort_unstable();
    let mut seen = std::collections::HashSet::new();
    let mut sets = 0;
    for k in 3..=most.min(n as usize) {
        for f in &facets {
            let rest: Vec<u32> = (0..n).filter(|v| !f.contains(v)).collect();
            for extra in Combinations::new(rest.len(), k - 3) {
                if ctl.is_stopped() {
                    return Ok(None);
                }
                let mut set: Vec<u32> = extra.iter().map(|&i| rest[i]).chain(*f).collect();
                set.sort_unstable();
                let inside: Vec<Lit> = (g.guards.iter())
                    .filter(|(t, _)| t.iter().all(|v| set.binary_search(v).is_ok()))
                    .map(|g| g.1)
                    .collect();
                if !seen.insert(inside.clone()) {
                    continue;
                }
                sets += 1;
                match g.needed(&inside) {
                    None => return Ok(None),
                    Some(None) => {}
                    Some(Some(keep)) => {
                        let core = g.shrink(keep).map(|keep| g.core(p, &keep));
                        let Some(core) = core else { return Ok(None) };
                        return Ok(Some(SmallestCore {
                            core: Some(core),
                            searched: k,
                            sets,
                        }));
                    }
                }
            }
        }
    }
    Ok(Some(SmallestCore {
        core: None,
        searched: most.min(n as usize),
        sets,
    }))
}

/// The `k`-subsets of `0..n`, as increasing index lists, in lexicographic order.
struct Combinations {
    n: usize,
    next: Option<Vec<usize>>,
}

impl Combinations {
    fn new(n: usize, k: usize) -> Self {
        Combinations {
            n,
            next: (k <= n).then(|| (0..k).collect()),
        }
    }
}

impl Iterator for Combinations {
    type Item = Vec<usize>;

    fn next(&mut self) -> Option<Vec<usize>> {
        let current = self.next.take()?;
        let (n, k) = (self.n, current.len());
        let mut c = current.clone();
        // The last place that can still grow, grown, and everything after it reset.
        if let Some(i) = (0..k).rev().find(|&i| c[i] < n - k + i) {
            c[i] += 1;
            for j in i + 1..k {
                c[j] = c[j - 1] + 1;
            }
            self.next = Some(c);
        }
        Some(current)
    }
}

/// The guarded formula of a polyhedron on an incremental solver: each facet's covering
/// and each inner face's pairing under a guard literal of its own.
struct Guarded {
    solver: crate::control::SatSolver,
    guards: Vec<([u32; 3], Lit)>,
    calls: usize,
}

impl Guarded {
    /// `None` when a tetrahedralization's short witness or its absence of candidates
    /// decides first, or `ctl` stopped.
    fn new(p: &Polyhedron, ctl: &Control) -> Result<Option<Guarded>, ExactError> {
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
        Ok(Some(Guarded {
            solver,
            guards,
            calls: 0,
        }))
    }

    /// The guards an unsatisfiable call under `assumed` needed (from the solver's
    /// core), `Some(None)` when satisfiable, `None` when stopped.
    fn needed(&mut self, assumed: &[Lit]) -> Option<Option<Vec<Lit>>> {
        self.calls += 1;
        match self.solver.solve_assumps(assumed).expect("batsat") {
            SolverResult::Unsat => {
                let core = self.solver.core().expect("a core after UNSAT");
                let kept = assumed.iter().copied().filter(|l| core.contains(&!*l));
                Some(Some(kept.collect()))
            }
            SolverResult::Sat => Some(None),
            SolverResult::Interrupted => None,
        }
    }

    /// `keep` (unsatisfiable) shrunk by deletion to a minimal set; `None` when stopped.
    fn shrink(&mut self, mut keep: Vec<Lit>) -> Option<Vec<Lit>> {
        let mut i = 0;
        while i < keep.len() {
            let without: Vec<Lit> = (keep.iter().enumerate())
                .filter(|&(k, _)| k != i)
                .map(|(_, &l)| l)
                .collect();
            match self.needed(&without)? {
                Some(smaller) => keep = smaller,
                None => i += 1,
            }
        }
        Some(keep)
    }

    /// The facets and faces of the guards `keep`, and their vertices.
    fn core(&self, p: &Polyhedron, keep: &[Lit]) -> FaceCore {
        let facets_of_p: std::collections::HashSet<[u32; 3]> = (p.faces.iter())
            .map(|&f| crate::mesh::sorted_face(f))
            .collect();
        let (mut facets, mut faces) = (Vec::new(), Vec::new());
        for (f, _) in self.guards.iter().filter(|g| keep.contains(&g.1)) {
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
        FaceCore {
            facets,
            faces,
            vertices,
            calls: self.calls,
        }
    }
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

    /// Every guarded facet and face of `p`.
    fn guard_faces(p: &Polyhedron) -> Vec<[u32; 3]> {
        let domain = Domain::Polyhedron(p);
        let pairs = polyhedron_pairs(domain, Edges::default(), &Control::new()).unwrap();
        let edges = restricted(Edges::default(), pairs.as_deref());
        let mut guards = Vec::new();
        Formula::guarded(domain, edges, &Control::new(), Some(&mut guards)).unwrap();
        guards.into_iter().map(|g| g.0).collect()
    }

    /// On random triangulated cubes and square prisms (8 vertices) with a SAT NO, the
    /// smallest core is unsatisfiable and minimal by varisat, and every vertex set with
    /// fewer vertices is satisfiable (its facets and faces, by varisat, all 2^8 sets).
    #[test]
    fn the_smallest_core_has_the_fewest_vertices() {
        let mut found = std::collections::BTreeMap::new();
        for seed in 0..60 {
            let shape = [ConvexShape::Prism, ConvexShape::Cube][seed as usize % 2];
            let p = convex_triangulated(shape, 4, 0, seed).unwrap();
            let Some(s) = smallest_core(&p, 8, &Control::new()).unwrap() else {
                continue;
            };
            let core = s.core.expect("a NO of 8 vertices has a core of at most 8");
            let k = core.vertices.len();
            assert_eq!(k, s.searched, "seed {seed}");
            let all: Vec<[u32; 3]> = core.facets.iter().chain(&core.faces).copied().collect();
            assert!(!satisfiable_with(&p, &all), "seed {seed}");
            for i in 0..all.len() {
                let mut fewer = all.clone();
                fewer.remove(i);
                assert!(satisfiable_with(&p, &fewer), "seed {seed}: not minimal");
            }
            let faces = guard_faces(&p);
            for set in 0u32..1 << p.points.len() {
                if (set.count_ones() as usize) < k {
                    let inside: Vec<[u32; 3]> = (faces.iter())
                        .filter(|t| t.iter().all(|&v| set >> v & 1 == 1))
                        .copied()
                        .collect();
                    assert!(satisfiable_with(&p, &inside), "seed {seed}: set {set:b}");
                }
            }
            *found.entry(k).or_insert(0) += 1;
        }
        assert!(found.values().sum::<usize>() >= 10, "{found:?}");
    }

    /// A NO that no set of six vertices refutes: a hexagonal prism, its facets
    /// triangulated (`generate convex-triangulated --shape prism --n 6 --seed 64`),
    /// whose smallest core has 7 vertices. Checked by varisat: the core is
    /// unsatisfiable, and the facets and faces of every set of at most 6 of the 12
    /// vertices are satisfiable.
    #[test]
    fn a_no_that_six_vertices_do_not_refute() {
        let p = convex_triangulated(ConvexShape::Prism, 6, 0, 64).unwrap();
        let s = smallest_core(&p, 12, &Control::new())
            .unwrap()
            .expect("a NO");
        let core = s.core.expect("a core");
        assert_eq!(core.vertices.len(), 7);
        let all: Vec<[u32; 3]> = core.facets.iter().chain(&core.faces).copied().collect();
        assert!(!satisfiable_with(&p, &all));
        let faces = guard_faces(&p);
        let mut sets = 0;
        for set in 0u32..1 << 12 {
            let inside: Vec<[u32; 3]> = (faces.iter())
                .filter(|t| t.iter().all(|&v| set >> v & 1 == 1))
                .copied()
                .collect();
            let facet = p.faces.iter().any(|f| f.iter().all(|&v| set >> v & 1 == 1));
            if set.count_ones() <= 6 && facet {
                assert!(satisfiable_with(&p, &inside), "set {set:b}");
                sets += 1;
            }
        }
        assert!(sets > 1000, "{sets} sets");
    }

    /// The k-subsets come each once, in order.
    #[test]
    fn combinations_are_the_binomials() {
        for n in 0..8 {
            for k in 0..=n + 1 {
                let all: Vec<Vec<usize>> = Combinations::new(n, k).collect();
                let mut sorted = all.clone();
                sorted.sort();
                sorted.dedup();
                assert_eq!(all, sorted);
                let binomial = (0..k).fold(1usize, |b, i| b * (n - i) / (i + 1));
                assert_eq!(all.len(), if k > n { 0 } else { binomial }, "C({n}, {k})");
                assert!(all.iter().all(|c| c.len() == k && c.iter().all(|&i| i < n)));
            }
        }
    }
}
