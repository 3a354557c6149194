//! Hamiltonian paths by SAT, exact (thesis ch. 6, "Hamiltonian tetrahedralizations"):
//! in a given graph ([`graph_path`], a cone's base once the depth-first budget is
//! spent), and over every tetrahedralization of a point set at once
//! ([`hamiltonian_tetrahedralization`], the exact solver the cones fall back on).
//!
//! **Variables.** One per edge of the graph (the path uses it) and one per node (the
//! path ends there). Over tetrahedralizations, the nodes are the candidate tetrahedra of
//! the module's formula (chosen or not) and the edges its inner triangles: the path
//! crosses a triangle only where both sides' candidates are chosen, and since at most
//! one is chosen on each side, a crossed face of a chosen tetrahedron always joins it
//! to the one tetrahedron across.
//!
//! **Clauses.** Every (chosen) node has exactly two of its edges and its end literal
//! (an inner node two edges, an end one); at most two ends and at least one. A model is
//! then one path and any number of cycles, disjoint, covering every (chosen) node. A
//! path of one node (a graph of one node; four points, whose one tetrahedralization is
//! one tetrahedron) is answered before any clause.
//!
//! **Cuts, added lazily.** For each component `S` of a model other than the whole,
//! some edge leaving `S` is on the path (or, over tetrahedralizations, some member of
//! `S` is not chosen). Every Hamiltonian path satisfies it: a path through a proper
//! subset of the nodes has to leave it; and a proper subset `S` of a tetrahedralization
//! covers less than the hull, so a tetrahedralization holding all of `S` holds more, and
//! its path leaves `S` through a face of exactly one member of `S` (a face two members
//! share has no third tetrahedron on it). The model that gave the cut violates it, so
//! the loop ends: with a model of one component (a Hamiltonian path, returned in order)
//! or with the clauses unsatisfiable (there is none).

use super::{ExactError, Formula};
use crate::control::{Control, SatSolver};
use crate::geom::{Point3, orient3d};
use crate::mesh::sorted_face;
use rustc_hash::FxHashMap as HashMap;
use rustsat::instances::{BasicVarManager, ManageVars};
use rustsat::solvers::{Solve, SolverResult};
use rustsat::types::{Clause, Lit, TernaryVal};

/// What a search for a Hamiltonian path found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PathFound<T> {
    /// A path through every node, in order.
    Path(Vec<T>),
    /// There is none: the clauses and cuts are unsatisfiable.
    None,
    /// The control stopped the solver first.
    Stopped,
}

/// A Hamiltonian path of the undirected graph `adj`, by SAT (see the module docs);
/// `cuts` counts the cuts added.
pub(crate) fn graph_path(adj: &[Vec<u32>], ctl: &Control, cuts: &mut u64) -> PathFound<u32> {
    let n = adj.len();
    if n <= 1 {
        return PathFound::Path((0..n as u32).collect());
    }
    let edges: Vec<[u32; 2]> = (0..n as u32)
        .flat_map(|u| {
            adj[u as usize]
                .iter()
                .filter(move |&&v| u < v)
                .map(move |&v| [u, v])
        })
        .collect();
    let (mut solver, mut vars) = (crate::control::sat_solver(ctl), BasicVarManager::default());
    let edge_lits: Vec<Lit> = edges.iter().map(|_| vars.new_lit()).collect();
    let mut incident: Vec<Vec<Lit>> = vec![Vec::new(); n];
    for (&[u, v], &e) in edges.iter().zip(&edge_lits) {
        incident[u as usize].push(e);
        incident[v as usize].push(e);
    }
    path_clauses(&mut solver, &mut vars, &vec![None; n], &incident);
    lazily(&mut solver, cuts, |solver| {
        let used: Vec<[u32; 2]> = (edges.iter().zip(&edge_lits))
            .filter(|&(_, &e)| is_true(solver, e))
            .map(|(&uv, _)| uv)
            .collect();
        let (label, parts) = components(n, &used);
        if parts == 1 {
            return Model::Path(walk(n, &used));
        }
        let mut cut: Vec<Vec<Lit>> = vec![Vec::new(); parts];
        for (&[u, v], &e) in edges.iter().zip(&edge_lits) {
            let (a, b) = (label[u as usize], label[v as usize]);
            if a != b {
                cut[a as usize].push(e);
                cut[b as usize].push(e);
            }
        }
        Model::Cuts(cut)
    })
}

/// A tetrahedralization of the hull of `points` using every point, with its tetrahedra
/// (positively oriented) in an order where each shares a triangle with the next, by SAT
/// over every tetrahedralization at once (see the module docs); `cuts` counts the cuts
/// added. Not certified here: the caller certifies what it prints
/// ([`crate::dualpath::hamiltonian`] does).
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::{PathFound, hamiltonian_tetrahedralization};
/// let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64]).collect();
/// let mut cuts = 0;
/// let PathFound::Path(tets) = hamiltonian_tetrahedralization(&cube, &Control::new(), &mut cuts).unwrap() else { panic!() };
/// assert!(tetrakit::mesh::certify_hull(&cube, &tets).is_ok());
/// assert!(tets.windows(2).all(|w| w[1].iter().filter(|v| w[0].contains(v)).count() == 3));
/// ```
pub fn hamiltonian_tetrahedralization(
    points: &[Point3],
    ctl: &Control,
    cuts: &mut u64,
) -> Result<PathFound<[u32; 4]>, ExactError> {
    if points.len() == 4 && crate::geom::affine_dimension(points) == 3 {
        // The one tetrahedralization is one tetrahedron: a path of one node, which the
        // degree clauses (two ends, or two edges) do not describe.
        return Ok(PathFound::Path(vec![oriented(points, [0, 1, 2, 3])]));
    }
    let domain = super::Domain::Points(points);
    let Some(f) = Formula::new(domain, super::Edges::default(), ctl)? else {
        return Ok(PathFound::Stopped);
    };
    let (cand, mut solver, mut vars, tet_lits) = f.into_solver(ctl);
    let crossing = crossings(&cand, &tet_lits, &mut solver, &mut vars);
    let incident: Vec<Vec<Lit>> = (cand.tets.iter())
        .map(|&t| {
            let faces = faces(t);
            faces
                .iter()
                .filter_map(|f| crossing.get(f).copied())
                .collect()
        })
        .collect();
    let present: Vec<Option<Lit>> = tet_lits.iter().map(|&x| Some(x)).collect();
    path_clauses(&mut solver, &mut vars, &present, &incident);
    let found = lazily(&mut solver, cuts, |solver| {
        let chosen: Vec<u32> = (0..tet_lits.len() as u32)
            .filter(|&t| is_true(solver, tet_lits[t as usize]))
            .collect();
        read_tetrahedra(solver, &chosen, (&cand.tets, &tet_lits), &crossing)
    });
    Ok(match found {
        PathFound::Path(order) => PathFound::Path(
            order
                .iter()
                .map(|&t| oriented(points, cand.tets[t as usize]))
                .collect(),
        ),
        PathFound::None => PathFound::None,
        PathFound::Stopped => PathFound::Stopped,
    })
}

/// A path variable per inner triangle (in a fixed order, so that every run gives the
/// same answer), implying a chosen candidate on each side.
fn crossings(
    cand: &super::Candidates,
    tet_lits: &[Lit],
    solver: &mut SatSolver,
    vars: &mut BasicVarManager,
) -> HashMap<[u32; 3], Lit> {
    let mut inner: Vec<(&[u32; 3], &super::encode::TriangleUse)> = (cand.triangles.iter())
        .filter(|(_, tri)| !tri.on_hull && !tri.pos.is_empty() && !tri.neg.is_empty())
        .collect();
    inner.sort_unstable_by_key(|&(key, _)| *key);
    let mut crossing = HashMap::default();
    for (key, tri) in inner {
        let y = vars.new_lit();
        for side in [&tri.pos, &tri.neg] {
            let mut c: Vec<Lit> = side.iter().map(|&t| tet_lits[t as usize]).collect();
            c.push(!y);
            add(solver, &c);
        }
        crossing.insert(*key, y);
    }
    crossing
}

/// One model over tetrahedralizations read as a graph on the `chosen` candidates,
/// joined where the path crosses the face two of them share: a path (of candidates),
/// or each component's cut: one of its members is not chosen, or the path crosses a face
/// it shares with a chosen tetrahedron outside it.
fn read_tetrahedra(
    solver: &SatSolver,
    chosen: &[u32],
    (tets, tet_lits): (&[[u32; 4]], &[Lit]),
    crossing: &HashMap<[u32; 3], Lit>,
) -> Model<u32> {
    let mut by_face: HashMap<[u32; 3], Vec<u32>> = HashMap::default();
    for (i, &t) in chosen.iter().enumerate() {
        for f in faces(tets[t as usize]) {
            by_face.entry(f).or_default().push(i as u32);
        }
    }
    let shared = || {
        (by_face.iter()).filter_map(|(f, ts)| match ts[..] {
            [a, b] => Some((crossing[f], [a, b])),
            _ => None,
        })
    };
    let used: Vec<[u32; 2]> = shared()
        .filter(|&(y, _)| is_true(solver, y))
        .map(|(_, ab)| ab)
        .collect();
    let (label, parts) = components(chosen.len(), &used);
    if parts == 1 {
        let order = walk(chosen.len(), &used);
        return Model::Path(order.iter().map(|&i| chosen[i as usize]).collect());
    }
    let mut cut: Vec<Vec<Lit>> = vec![Vec::new(); parts];
    for (i, &t) in chosen.iter().enumerate() {
        cut[label[i] as usize].push(!tet_lits[t as usize]);
    }
    for (y, [a, b]) in shared() {
        let (la, lb) = (label[a as usize], label[b as usize]);
        if la != lb {
            cut[la as usize].push(y);
            cut[lb as usize].push(y);
        }
    }
    #[cfg(test)]
    tests::record(&cut, (tets, tet_lits), crossing);
    Model::Cuts(cut)
}

/// The faces of a tetrahedron, as sorted triples.
fn faces(t: [u32; 4]) -> [[u32; 3]; 4] {
    FACES.map(|f| sorted_face(f.map(|i| t[i])))
}

/// The faces of a tetrahedron `[a, b, c, d]`, by position.
const FACES: [[usize; 3]; 4] = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];

/// `t` positively oriented.
fn oriented(points: &[Point3], t: [u32; 4]) -> [u32; 4] {
    let [a, b, c, d] = t.map(|v| &points[v as usize]);
    if orient3d(a, b, c, d) > 0 {
        t
    } else {
        [t[0], t[2], t[1], t[3]]
    }
}

/// What one model says: a Hamiltonian path (the nodes in order), or the cuts of its
/// components.
enum Model<T> {
    Path(Vec<T>),
    Cuts(Vec<Vec<Lit>>),
}

/// Solves, reads each model with `read`, and adds its cuts until a model is a path or
/// none is left.
fn lazily<T>(
    solver: &mut SatSolver,
    cuts: &mut u64,
    mut read: impl FnMut(&SatSolver) -> Model<T>,
) -> PathFound<T> {
    loop {
        match solver.solve().expect("batsat") {
            SolverResult::Unsat => return PathFound::None,
            SolverResult::Interrupted => return PathFound::Stopped,
            SolverResult::Sat => {}
        }
        match read(solver) {
            Model::Path(order) => return PathFound::Path(order),
            Model::Cuts(cs) => {
                *cuts += cs.len() as u64;
                cs.iter().for_each(|c| add(solver, c));
            }
        }
    }
}

/// The degree and end clauses of the module docs: node `i`, when present (`present[i]`,
/// `None` for always), has exactly two of `incident[i]` and its end literal; one or two
/// ends.
fn path_clauses(
    solver: &mut SatSolver,
    vars: &mut BasicVarManager,
    present: &[Option<Lit>],
    incident: &[Vec<Lit>],
) {
    let ends: Vec<Lit> = present.iter().map(|_| vars.new_lit()).collect();
    for ((&p, lits), &s) in present.iter().zip(incident).zip(&ends) {
        let mut with_end = lits.clone();
        with_end.push(s);
        let guard: Vec<Lit> = p.map(|x| !x).into_iter().collect();
        exactly_two(&with_end, &mut |c| add(solver, &[&guard[..], c].concat()));
        if let Some(x) = p {
            add(solver, &[!s, x]);
        }
    }
    at_most_two(&ends, vars, &mut |c| add(solver, c));
    add(solver, &ends);
}

fn add(solver: &mut SatSolver, lits: &[Lit]) {
    solver
        .add_clause(lits.iter().copied().collect::<Clause>())
        .expect("batsat accepts clauses");
}

fn is_true(solver: &SatSolver, l: Lit) -> bool {
    solver.lit_val(l).expect("sat") == TernaryVal::True
}

/// Each node's component in the graph of `used` edges, and how many there are.
fn components(n: usize, used: &[[u32; 2]]) -> (Vec<u32>, usize) {
    let adj = adjacency(n, used);
    let mut label = vec![u32::MAX; n];
    let mut parts = 0;
    for s in 0..n {
        if label[s] != u32::MAX {
            continue;
        }
        let mut stack = vec![s as u32];
        label[s] = parts;
        while let Some(u) = stack.pop() {
            for &v in &adj[u as usize] {
                if label[v as usize] == u32::MAX {
                    label[v as usize] = parts;
                    stack.push(v);
                }
            }
        }
        parts += 1;
    }
    (label, parts as usize)
}

/// The nodes of the path formed by the `used` edges on `n` nodes, in order.
fn walk(n: usize, used: &[[u32; 2]]) -> Vec<u32> {
    let adj = adjacency(n, used);
    let end = (0..n)
        .find(|&v| adj[v].len() <= 1)
        .expect("a path has an end") as u32;
    let mut order = vec![end];
    let mut prev = u32::MAX;
    while let Some(&next) = adj[*order.last().expect("nonempty") as usize]
        .iter()
        .find(|&&v| v != prev)
    {
        prev = *order.last().expect("nonempty");
        order.push(next);
    }
    order
}

/// Adjacency lists of `edges` on `n` nodes.
fn adjacency(n: usize, edges: &[[u32; 2]]) -> Vec<Vec<u32>> {
    let mut adj = vec![Vec::new(); n];
    for &[u, v] in edges {
        adj[u as usize].push(v);
        adj[v as usize].push(u);
    }
    adj
}

/// Clauses: exactly two of `lits` are true (at most two: no three together; at least
/// two: no all-but-one false).
pub(crate) fn exactly_two(lits: &[Lit], add: &mut impl FnMut(&[Lit])) {
    let k = lits.len();
    for a in 0..k {
        for b in a + 1..k {
            for c in b + 1..k {
                add(&[!lits[a], !lits[b], !lits[c]]);
            }
        }
    }
    for skip in 0..k {
        let rest: Vec<Lit> = (0..k).filter(|&i| i != skip).map(|i| lits[i]).collect();
        add(&rest);
    }
}

/// Clauses: at most two of `lits` are true (a sequential counter: `one[i]`, `two[i]`
/// say that at least one, two of the first `i + 1` are).
pub(crate) fn at_most_two(lits: &[Lit], vars: &mut BasicVarManager, add: &mut impl FnMut(&[Lit])) {
    let (mut one, mut two): (Option<Lit>, Option<Lit>) = (None, None);
    for &x in lits {
        let (o, t) = (vars.new_lit(), vars.new_lit());
        add(&[!x, o]);
        if let Some(p) = one {
            add(&[!p, o]);
            add(&[!x, !p, t]);
        }
        if let Some(q) = two {
            add(&[!q, t]);
            add(&[!x, !q]);
        }
        (one, two) = (Some(o), Some(t));
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::rng::Rng;
    use std::cell::RefCell;

    /// A cut in geometric terms: its tetrahedra `S` (sorted) and the faces that leave it.
    pub(crate) type Cut = (Vec<[u32; 4]>, Vec<[u32; 3]>);

    thread_local! {
        static CUTS: RefCell<Vec<Cut>> = const { RefCell::new(Vec::new()) };
    }

    /// Files the cut clauses of one model (called by `read_tetrahedra`), read back into
    /// the tetrahedra whose literals they negate and the faces whose crossing they ask.
    pub(super) fn record(
        cut: &[Vec<Lit>],
        (tets, tet_lits): (&[[u32; 4]], &[Lit]),
        crossing: &HashMap<[u32; 3], Lit>,
    ) {
        let tet_of: HashMap<Lit, [u32; 4]> = (tet_lits.iter().zip(tets))
            .map(|(&x, &t)| {
                let mut s = t;
                s.sort_unstable();
                (!x, s)
            })
            .collect();
        let face_of: HashMap<Lit, [u32; 3]> = crossing.iter().map(|(&f, &y)| (y, f)).collect();
        CUTS.with(|c| {
            c.borrow_mut().extend(cut.iter().map(|clause| {
                let s = clause.iter().filter_map(|l| tet_of.get(l).copied());
                let f = clause.iter().filter_map(|l| face_of.get(l).copied());
                (s.collect(), f.collect())
            }))
        });
    }

    /// The cuts filed on this thread since the last call.
    pub(crate) fn take_cuts() -> Vec<Cut> {
        CUTS.with(|c| std::mem::take(&mut *c.borrow_mut()))
    }

    /// Is `p` a path through every node of `adj`?
    pub(crate) fn is_path(adj: &[Vec<u32>], p: &[u32]) -> bool {
        let mut seen = vec![false; adj.len()];
        p.len() == adj.len()
            && p.iter()
                .all(|&v| !std::mem::replace(&mut seen[v as usize], true))
            && p.windows(2).all(|w| adj[w[0] as usize].contains(&w[1]))
    }

    /// Every order of the nodes, tried: whether some is a path.
    pub(crate) fn brute_force(adj: &[Vec<u32>]) -> bool {
        fn go(adj: &[Vec<u32>], path: &mut Vec<u32>, used: &mut [bool]) -> bool {
            if path.len() == adj.len() {
                return true;
            }
            for v in 0..adj.len() as u32 {
                let joins = path.last().is_none_or(|&u| adj[u as usize].contains(&v));
                if !used[v as usize] && joins {
                    (used[v as usize], _) = (true, path.push(v));
                    if go(adj, path, used) {
                        return true;
                    }
                    (used[v as usize], _) = (false, path.pop());
                }
            }
            false
        }
        go(adj, &mut Vec::new(), &mut vec![false; adj.len()])
    }

    /// A random graph of 1 to `most` nodes, each of degree at most 4 (a dual graph's).
    pub(crate) fn random_graph(rng: &mut Rng, most: usize) -> Vec<Vec<u32>> {
        let n = 1 + rng.below(most);
        let mut adj = vec![Vec::new(); n];
        for a in 0..n as u32 {
            for b in a + 1..n as u32 {
                let room = adj[a as usize].len() < 4 && adj[b as usize].len() < 4;
                if room && rng.below(3) == 0 {
                    adj[a as usize].push(b);
                    adj[b as usize].push(a);
                }
            }
        }
        adj
    }

    /// SAT agrees with trying every order on 3000 random graphs of at most 9 nodes and
    /// degree at most 4, paths and none alike, and its paths are paths.
    #[test]
    fn sat_agrees_with_every_order() {
        let (mut rng, ctl, mut cuts) = (Rng::new(29), Control::new(), 0);
        let mut counts = [0; 2];
        for _ in 0..3000 {
            let adj = random_graph(&mut rng, 9);
            let exists = brute_force(&adj);
            match graph_path(&adj, &ctl, &mut cuts) {
                PathFound::Path(p) => assert!(exists && is_path(&adj, &p), "{adj:?}: {p:?}"),
                PathFound::None => assert!(!exists, "{adj:?}"),
                PathFound::Stopped => panic!("never stopped"),
            }
            counts[usize::from(exists)] += 1;
        }
        assert!(
            counts[0] > 300 && counts[1] > 300 && cuts > 100,
            "{counts:?} {cuts}"
        );
    }

    /// At most two ends: every choice of three of five literals is refused, and so is
    /// every choice of none.
    #[test]
    fn the_counter_allows_one_or_two_ends() {
        for mask in 0u32..32 {
            let mut vars = BasicVarManager::default();
            let lits: Vec<Lit> = (0..5).map(|_| vars.new_lit()).collect();
            let mut clauses: Vec<Vec<Lit>> = Vec::new();
            at_most_two(&lits, &mut vars, &mut |c| clauses.push(c.to_vec()));
            clauses.push(lits.clone());
            let mut solver = crate::control::sat_solver(&Control::new());
            for c in clauses {
                solver
                    .add_clause(c.into_iter().collect::<Clause>())
                    .unwrap();
            }
            let assumed: Vec<Lit> = (0..5)
                .map(|i| {
                    if mask >> i & 1 == 1 {
                        lits[i]
                    } else {
                        !lits[i]
                    }
                })
                .collect();
            let sat = rustsat::solvers::SolveIncremental::solve_assumps(&mut solver, &assumed)
                .unwrap()
                == SolverResult::Sat;
            assert_eq!(sat, (1..=2).contains(&mask.count_ones()), "{mask:05b}");
        }
    }
}
