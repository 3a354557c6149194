//! Tetrahedralizations of a convex polytope whose dual graph has a Hamiltonian path
//! (thesis ch. 6, "Hamiltonian tetrahedralizations", the question of Arkin et al., the thesis's reference 5):
//! the tetrahedra in an order where each shares a triangle with the next, as streaming
//! and rendering pipelines want them.
//!
//! **Method: a cone with a path.** Pick an apex `v` and triangulate every facet of the
//! hull not containing `v` (all the points on it; [`triangulate_coplanar`]); the
//! tetrahedra joining `v` to those triangles tile the polytope, and two of them share a
//! triangle exactly when their base triangles share an edge. So a Hamiltonian path in the
//! dual graph of the base — a triangulated disk, the surface minus `v`'s star — orders
//! the cone. The path is searched depth-first (`search`) within a budget, then decided
//! by SAT (`exact::path`: a path, or a proof that this cone has none, counted
//! in `cones_refuted`), apex after apex, those whose cone has the fewest tetrahedra
//! first. Cones can fail: a vertex with three neighbours of degree 3 has a base whose
//! dual has three leaves (on a Kleetope every original vertex does). Chin, Ding and
//! Wang report a convex polyhedron of 92 vertices on which pulling gives no such path,
//! and Escalona, Fabila-Monroy and Urrutia a set of 84 points with no Hamiltonian
//! tetrahedralization whose tetrahedra all share a vertex.
//!
//! An apex is *eligible* when every point on a facet at `v` also lies on a facet away
//! from `v`: a point inside a facet at `v`, or on an edge through `v`, would be left out
//! of every cone tetrahedron. When every point is a vertex of the hull, every vertex is
//! eligible (the facets round a vertex `q` near `v` cannot all contain the edge `qv`).
//!
//! **Then every tetrahedralization.** When every cone is refuted (or none is eligible)
//! and the set is small ([`PathOptions::enumerate_up_to`], 12 points), every
//! tetrahedralization that uses every point is enumerated
//! ([`crate::flipgraph::tetrahedralizations`], exact, each once) and each one's dual
//! graph searched *completely* (`search::exact_path`: the same depth-first search
//! without a budget, from a leaf or from every node; its pruning never drops a path).
//! The first with a path is a YES (`found_by: "enumeration"`); none, with the
//! enumeration complete, is a NO: no tetrahedralization of these points has a
//! Hamiltonian dual path. That NO would answer the open question for that set; its
//! witness is the count, which TOPCOM's `points2nallfinetriangs` checks, and each
//! tetrahedralization can be listed again by `tetrakit flips --output`. Up to
//! [`PathOptions::sat_up_to`] points (30) the question goes to SAT over every
//! tetrahedralization at once ([`crate::exact::hamiltonian_tetrahedralization`]: the
//! exact solver's formula with path clauses and lazy cuts; `found_by: "sat"`, or a NO
//! when it is unsatisfiable).
//!
//! **Certified**: the tetrahedra pass [`mesh::certify_hull`] (every point a vertex, the
//! hull covered once, face to face) and [`mesh::verify_dual_path`] (each shares a
//! triangle with the next). When every cone is refuted, or none is eligible, and the set
//! is too large for both exact routes (or the enumeration's limit or the time limit
//! cuts it), the answer is UNDECIDED: whether every convex polytope has such a
//! tetrahedralization is the open question.
//!
//! ```
//! use tetrakit::control::{Control, Verdict};
//! use tetrakit::dualpath::{PathOptions, hamiltonian};
//! let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64]).collect();
//! let o = hamiltonian(&cube, &PathOptions::default(), &Control::new()).unwrap();
//! assert_eq!((o.verdict, o.tets.len()), (Verdict::Yes, 6));
//! ```

mod search;

use crate::bug::Bug;
use crate::control::{Control, Verdict};
use crate::exact::PathFound;
use crate::exact::path::graph_path;
use crate::flipgraph::FlipError;
use crate::geom::{Hull3, Point3, SetDefect, orient3d, solid_set, triangulate_coplanar};
use crate::mesh;
use serde::Serialize;
use std::collections::HashMap;
use std::fmt;

/// What [`hamiltonian`] is asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PathOptions {
    /// Depth-first search steps per apex; past them the apex's cone is decided by SAT
    /// (exact: a path, or a proof that its cone has none).
    pub budget: u64,
    /// Try the cones first (off: the enumeration alone, for experiments and tests).
    pub cones: bool,
    /// When no cone gives a path, a set of at most this many points has every
    /// tetrahedralization enumerated and each one's dual graph searched completely.
    pub enumerate_up_to: usize,
    /// The enumeration gives up (UNDECIDED) past this many tetrahedralizations.
    pub enumerate_limit: usize,
    /// When neither the cones nor the enumeration decided, a set of at most this many
    /// points is decided by SAT over every tetrahedralization at once
    /// ([`crate::exact::hamiltonian_tetrahedralization`]).
    pub sat_up_to: usize,
}

/// [`PathOptions::sat_up_to`]'s default.
pub const SAT_UP_TO: usize = 30;

impl Default for PathOptions {
    fn default() -> Self {
        PathOptions {
            budget: 200_000,
            cones: true,
            enumerate_up_to: 12,
            enumerate_limit: 2_000_000,
            sat_up_to: SAT_UP_TO,
        }
    }
}

/// Why [`hamiltonian`] could not run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PathError {
    /// Too few points, two equal, or all coplanar.
    Set(SetDefect),
    /// A point inside the hull: the input is not a convex polytope's boundary points.
    Inside {
        /// The point.
        index: u32,
    },
    /// The enumeration of every tetrahedralization failed (a bug if it ever happens).
    Enumeration(FlipError),
    /// The SAT solver over every tetrahedralization could not run.
    Exact(crate::exact::ExactError),
    /// The tetrahedra failed the verifier (a bug if it ever happens): its problem.
    Uncertified(mesh::Problem),
    /// Two consecutive tetrahedra of the path share no triangle (a bug if it ever
    /// happens; `at` names the first).
    Internal(Bug),
}

impl fmt::Display for PathError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PathError::Set(e) => e.fmt(f),
            PathError::Inside { index } => write!(
                f,
                "point #{index} lies inside the hull: a convex polytope's points are on its boundary"
            ),
            PathError::Uncertified(p) => write!(
                f,
                "internal error, please report the input: the cone fails its certificate: {p}"
            ),
            PathError::Internal(bug) => bug.fmt(f),
            PathError::Enumeration(e) => e.fmt(f),
            PathError::Exact(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for PathError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PathError::Set(e) => Some(e),
            PathError::Uncertified(p) => Some(p),
            PathError::Internal(bug) => Some(bug),
            PathError::Enumeration(e) => Some(e),
            PathError::Exact(e) => Some(e),
            PathError::Inside { .. } => None,
        }
    }
}

/// A tetrahedralization with a Hamiltonian dual path ([`hamiltonian`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct HamiltonianOutcome {
    /// YES with the tetrahedra in path order; NO with its [`NoPath`] witness;
    /// UNDECIDED when every cone is refuted (or none is eligible) and the set is too
    /// large for the exact routes, or a limit cut them.
    pub verdict: Verdict,
    /// Points (all vertices of the tetrahedralization).
    pub vertices: usize,
    /// Tetrahedra of the one found (0 when none).
    pub tetrahedra: usize,
    /// The fewest tetrahedra of a cone from an eligible apex, path or not: what an
    /// ordinary cone costs (`null` when no apex is eligible).
    pub ordinary_tetrahedra: Option<usize>,
    /// The apex of the cone found.
    pub apex: Option<u32>,
    /// Eligible apexes (see the module docs).
    pub apexes: usize,
    /// Apexes tried.
    pub apexes_tried: usize,
    /// Search steps over all apexes.
    pub steps: u64,
    /// Cuts the SAT searches added: the cones' (past [`PathOptions::budget`]) and, when
    /// it ran, the search over every tetrahedralization's.
    pub cuts: u64,
    /// Apexes whose cone has no Hamiltonian dual path, proven by SAT.
    pub cones_refuted: usize,
    /// The tetrahedra passed [`mesh::certify_hull`] and [`mesh::verify_dual_path`].
    pub certified: bool,
    /// How the tetrahedralization was found: `"cone"`, `"enumeration"` or `"sat"`
    /// (`None` when none was).
    pub found_by: Option<&'static str>,
    /// When every tetrahedralization was enumerated: how many, and whether all were.
    pub enumerated: Option<Enumerated>,
    /// A NO: every tetrahedralization enumerated, none with a Hamiltonian dual path.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<NoPath>,
    /// The tetrahedra in path order (each shares a triangle with the next), positively
    /// oriented.
    pub tets: Vec<[u32; 4]>,
}

/// The enumeration's count ([`HamiltonianOutcome::enumerated`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Enumerated {
    /// Tetrahedralizations that use every point, found.
    pub tetrahedralizations: usize,
    /// Whether that is all of them (else the limit or the time limit cut it).
    pub complete: bool,
}

/// Why no tetrahedralization of these points has a Hamiltonian dual path: all of them were
/// enumerated (the count is TOPCOM's `points2nallfinetriangs`, which checks it) and each
/// one's dual graph was searched completely.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct NoPath {
    /// `"no_hamiltonian_tetrahedralization"`.
    pub kind: &'static str,
    /// The tetrahedralizations, all of them, when they were enumerated (`None` for a NO
    /// by SAT).
    pub tetrahedralizations: Option<usize>,
    /// A sentence for a person.
    pub detail: String,
}

impl HamiltonianOutcome {
    /// The same outcome with every vertex index plus `base` (a file's numbering).
    pub fn shifted(mut self, base: u32) -> HamiltonianOutcome {
        self.apex = self.apex.map(|v| v + base);
        self.tets.iter_mut().for_each(|t| *t = t.map(|v| v + base));
        self
    }
}

/// A tetrahedralization of the convex polytope with boundary points `points` (every
/// point a vertex) with its tetrahedra in an order where each shares a triangle with the
/// next (see the module docs): by the cones, then, for at most
/// [`PathOptions::enumerate_up_to`] points, by enumerating every tetrahedralization (a
/// YES the cones missed, or a NO).
pub fn hamiltonian(
    points: &[Point3],
    opts: &PathOptions,
    ctl: &Control,
) -> Result<HamiltonianOutcome, PathError> {
    solid_set(points).map_err(PathError::Set)?;
    let hull = Hull3::new(points);
    if let Some(i) = (0..points.len()).find(|&i| !hull.on_boundary(i)) {
        return Err(PathError::Inside { index: i as u32 });
    }
    let facets = facet_triangles(points, &hull);
    let mut apexes: Vec<(usize, u32)> = (0..points.len() as u32)
        .filter(|&v| eligible(&hull, v, points.len()))
        .map(|v| (base(&hull, &facets, v).len(), v))
        .collect();
    apexes.sort_unstable();
    let mut o = HamiltonianOutcome {
        verdict: Verdict::Undecided,
        vertices: points.len(),
        tetrahedra: 0,
        ordinary_tetrahedra: apexes.first().map(|&(k, _)| k),
        apex: None,
        apexes: apexes.len(),
        apexes_tried: 0,
        steps: 0,
        cuts: 0,
        cones_refuted: 0,
        certified: false,
        found_by: None,
        enumerated: None,
        witness: None,
        tets: Vec::new(),
    };
    if opts.cones {
        by_cones(points, &hull, &facets, &apexes, opts, ctl, &mut o)?;
    }
    let open = |o: &HamiltonianOutcome| o.verdict == Verdict::Undecided && !ctl.is_stopped();
    if open(&o) && points.len() <= opts.enumerate_up_to {
        by_enumeration(points, opts, ctl, &mut o)?;
    }
    if open(&o) && o.enumerated.is_none() && points.len() <= opts.sat_up_to {
        by_sat(points, ctl, &mut o)?;
    }
    Ok(o)
}

/// The cones from `apexes` in turn: each base's dual graph searched depth-first within
/// the budget, then decided by SAT ([`sat::graph_path`]); the first path is the YES.
fn by_cones(
    points: &[Point3],
    hull: &Hull3,
    facets: &[Vec<[u32; 3]>],
    apexes: &[(usize, u32)],
    opts: &PathOptions,
    ctl: &Control,
    o: &mut HamiltonianOutcome,
) -> Result<(), PathError> {
    for &(_, v) in apexes {
        if ctl.is_stopped() {
            break;
        }
        o.apexes_tried += 1;
        let tris = base(hull, facets, v);
        let adj = dual(&tris);
        let order = match search::hamiltonian_path(&adj, opts.budget, ctl, &mut o.steps) {
            Some(order) => order,
            None => match graph_path(&adj, ctl, &mut o.cuts) {
                PathFound::Path(order) => order,
                PathFound::None => {
                    o.cones_refuted += 1;
                    continue;
                }
                PathFound::Stopped => break,
            },
        };
        let tets: Vec<[u32; 4]> = order
            .iter()
            .map(|&i| cone(points, v, tris[i as usize]))
            .collect();
        accept(points, tets, "cone", o)?;
        o.apex = Some(v);
        break;
    }
    Ok(())
}

/// The YES of `tets` in path order, found by `how`, once certified.
fn accept(
    points: &[Point3],
    tets: Vec<[u32; 4]>,
    how: &'static str,
    o: &mut HamiltonianOutcome,
) -> Result<(), PathError> {
    mesh::certify_hull(points, &tets).map_err(PathError::Uncertified)?;
    mesh::verify_dual_path(&tets).map_err(|i| {
        let check = "consecutive tetrahedra of the path share a triangle";
        PathError::Internal(Bug::at(check, [i as u32, i as u32 + 1]))
    })?;
    o.verdict = Verdict::Yes;
    o.tetrahedra = tets.len();
    o.certified = true;
    o.found_by = Some(how);
    o.tets = tets;
    Ok(())
}

/// Every tetrahedralization, each one's dual graph searched completely as it is found:
/// the first with a path is a YES (the enumeration stops there); none, when all were
/// enumerated, is a NO.
fn by_enumeration(
    points: &[Point3],
    opts: &PathOptions,
    ctl: &Control,
    o: &mut HamiltonianOutcome,
) -> Result<(), PathError> {
    let mut found: Option<Vec<[u32; 4]>> = None;
    let mut each =
        |tets: Vec<[u32; 4]>| match search::exact_path(&tet_dual(&tets), ctl, &mut o.steps) {
            Some(Some(order)) => {
                found = Some(order.iter().map(|&k| tets[k as usize]).collect());
                false
            }
            _ => true, // no path (or stopped: the enumeration sees the stop too)
        };
    let limit = opts.enumerate_limit;
    let (cut, count) =
        match crate::flipgraph::for_each_tetrahedralization(points, limit, ctl, &mut each) {
            Ok(ended) => ended,
            Err(FlipError::TooManyCandidates(_)) => return Ok(()),
            Err(e) => return Err(PathError::Enumeration(e)),
        };
    o.enumerated = Some(Enumerated {
        tetrahedralizations: count,
        complete: cut.is_none(),
    });
    if let Some(tets) = found {
        return accept(points, tets, "enumeration", o);
    }
    if cut.is_none() && !ctl.is_stopped() {
        o.verdict = Verdict::No;
        o.witness = Some(NoPath {
            kind: "no_hamiltonian_tetrahedralization",
            tetrahedralizations: Some(count),
            detail: format!(
                "none of the {count} tetrahedralizations that use every point has a Hamiltonian dual path (each dual graph searched completely)"
            ),
        });
    }
    Ok(())
}

/// SAT over every tetrahedralization at once: a path is the YES; unsatisfiable clauses,
/// the NO.
fn by_sat(points: &[Point3], ctl: &Control, o: &mut HamiltonianOutcome) -> Result<(), PathError> {
    let found = crate::exact::hamiltonian_tetrahedralization(points, ctl, &mut o.cuts)
        .map_err(PathError::Exact)?;
    match found {
        PathFound::Path(tets) => accept(points, tets, "sat", o),
        PathFound::None => {
            o.verdict = Verdict::No;
            o.witness = Some(NoPath {
                kind: "no_hamiltonian_tetrahedralization",
                tetrahedralizations: None,
                detail: format!(
                    "no tetrahedralization that uses every point has a Hamiltonian dual path: the SAT formula over every tetrahedralization, with its path clauses and {} cuts, is unsatisfiable",
                    o.cuts
                ),
            });
            Ok(())
        }
        PathFound::Stopped => Ok(()),
    }
}

/// The dual graph of a tetrahedralization: tetrahedra joined when they share a triangle.
fn tet_dual(tets: &[[u32; 4]]) -> Vec<Vec<u32>> {
    let mut faces: Vec<([u32; 3], u32)> = (tets.iter().enumerate())
        .flat_map(|(k, t)| {
            [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
                .map(|f| (mesh::sorted_face(f.map(|i| t[i])), k as u32))
        })
        .collect();
    faces.sort_unstable();
    let mut adj = vec![Vec::new(); tets.len()];
    for w in faces.windows(2) {
        if w[0].0 == w[1].0 {
            adj[w[0].1 as usize].push(w[1].1);
            adj[w[1].1 as usize].push(w[0].1);
        }
    }
    adj
}

/// Each facet's triangles (every point on it used).
fn facet_triangles(points: &[Point3], hull: &Hull3) -> Vec<Vec<[u32; 3]>> {
    let mut members = vec![Vec::new(); hull.facet_count()];
    for i in 0..points.len() {
        for &f in hull.facets_of(i) {
            members[f as usize].push(i as u32);
        }
    }
    members
        .iter()
        .map(|on| triangulate_coplanar(points, on, None))
        .collect()
}

/// Every point on a facet at `v` is `v` or lies on a facet away from `v`.
fn eligible(hull: &Hull3, v: u32, n: usize) -> bool {
    let at_v = hull.facets_of(v as usize);
    (0..n).filter(|&q| q != v as usize).all(|q| {
        let fq = hull.facets_of(q);
        !fq.iter().any(|f| at_v.contains(f)) || fq.iter().any(|f| !at_v.contains(f))
    })
}

/// The triangles of the facets away from `v`: the cone's bases.
fn base(hull: &Hull3, facets: &[Vec<[u32; 3]>], v: u32) -> Vec<[u32; 3]> {
    let at_v = hull.facets_of(v as usize);
    (0..facets.len() as u32)
        .filter(|f| !at_v.contains(f))
        .flat_map(|f| facets[f as usize].iter().copied())
        .collect()
}

/// Triangles sharing an edge.
fn dual(tris: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let mut by_edge: HashMap<[u32; 2], Vec<u32>> = HashMap::new();
    for (i, t) in tris.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            by_edge
                .entry([a.min(b), a.max(b)])
                .or_default()
                .push(i as u32);
        }
    }
    let mut adj = vec![Vec::new(); tris.len()];
    for ts in by_edge.values() {
        if let [a, b] = ts[..] {
            adj[a as usize].push(b);
            adj[b as usize].push(a);
        }
    }
    // In a fixed order, so that the search (and the answer) is the same on every run.
    adj.iter_mut().for_each(|a| a.sort_unstable());
    adj
}

/// The tetrahedron `v` + `t`, positively oriented.
fn cone(points: &[Point3], v: u32, [a, b, c]: [u32; 3]) -> [u32; 4] {
    let p = |x: u32| &points[x as usize];
    if orient3d(p(a), p(b), p(c), p(v)) > 0 {
        [a, b, c, v]
    } else {
        [a, c, b, v]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::{Distribution3, points3d};

    /// On the bases of every cone of small random polytopes, SAT and the complete
    /// depth-first search agree, paths and none alike (some cones have none).
    #[test]
    fn sat_and_the_complete_search_agree_on_cones() {
        let (ctl, mut steps, mut cuts) = (Control::new(), 0, 0);
        let mut counts = [0; 2];
        for seed in 0..90u64 {
            let dist = [
                Distribution3::Convex,
                Distribution3::LatticeHull,
                Distribution3::Cylinder,
            ][seed as usize % 3];
            let pts = points3d(dist, 6 + seed as usize % 19, seed);
            let hull = Hull3::new(&pts);
            let facets = facet_triangles(&pts, &hull);
            for v in (0..pts.len() as u32).filter(|&v| eligible(&hull, v, pts.len())) {
                let adj = dual(&base(&hull, &facets, v));
                let complete = search::exact_path(&adj, &ctl, &mut steps).expect("no limit");
                match graph_path(&adj, &ctl, &mut cuts) {
                    PathFound::Path(p) => {
                        assert!(complete.is_some(), "{adj:?}");
                        assert!(crate::exact::path::tests::is_path(&adj, &p), "{adj:?}");
                    }
                    PathFound::None => assert!(complete.is_none(), "{adj:?}"),
                    PathFound::Stopped => panic!("no limit"),
                }
                counts[usize::from(complete.is_some())] += 1;
            }
        }
        assert!(counts[0] > 50 && counts[1] > 500, "{counts:?}");
    }

    /// Every cut SAT adds over tetrahedralizations holds for every tetrahedralization
    /// with a Hamiltonian dual path (one path each, from the complete search): if it
    /// holds all of the cut's tetrahedra, its path crosses one of the cut's faces. On
    /// small random sets, every tetrahedralization enumerated.
    #[test]
    fn every_cut_keeps_every_hamiltonian_tetrahedralization() {
        let (ctl, mut steps, mut cuts, mut checked) = (Control::new(), 0, 0, 0);
        for seed in 0..40u64 {
            let dist = [Distribution3::Convex, Distribution3::LatticeHull][seed as usize % 2];
            let pts = points3d(dist, 7 + seed as usize % 3, seed);
            crate::exact::path::tests::take_cuts();
            let found = crate::exact::hamiltonian_tetrahedralization(&pts, &ctl, &mut cuts);
            assert!(matches!(found, Ok(PathFound::Path(_))));
            let filed = crate::exact::path::tests::take_cuts();
            let mut each = |tets: Vec<[u32; 4]>| {
                let Some(Some(order)) = search::exact_path(&tet_dual(&tets), &ctl, &mut steps)
                else {
                    return true;
                };
                let sorted = |t: [u32; 4]| {
                    let mut s = t;
                    s.sort_unstable();
                    s
                };
                let held: std::collections::HashSet<[u32; 4]> =
                    tets.iter().map(|&t| sorted(t)).collect();
                let crossed: std::collections::HashSet<[u32; 3]> = (order.windows(2))
                    .map(|w| {
                        let (a, b) = (tets[w[0] as usize], tets[w[1] as usize]);
                        let f: Vec<u32> = a.into_iter().filter(|v| b.contains(v)).collect();
                        mesh::sorted_face([f[0], f[1], f[2]])
                    })
                    .collect();
                for (s, faces) in &filed {
                    if s.iter().all(|t| held.contains(t)) {
                        assert!(faces.iter().any(|f| crossed.contains(f)), "{pts:?}");
                        checked += 1;
                    }
                }
                true
            };
            crate::flipgraph::for_each_tetrahedralization(&pts, usize::MAX, &ctl, &mut each)
                .unwrap();
        }
        assert!(checked > 200, "{checked} cuts checked");
    }
}
