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
//! the cone. The path is searched depth-first (`search`) within a budget, apex after
//! apex, those whose cone has the fewest tetrahedra first.
//!
//! An apex is *eligible* when every point on a facet at `v` also lies on a facet away
//! from `v`: a point inside a facet at `v`, or on an edge through `v`, would be left out
//! of every cone tetrahedron. When every point is a vertex of the hull, every vertex is
//! eligible (the facets round a vertex `q` near `v` cannot all contain the edge `qv`).
//!
//! **Certified**: the tetrahedra pass [`mesh::certify_hull`] (every point a vertex, the
//! hull covered once, face to face) and [`mesh::verify_dual_path`] (each shares a
//! triangle with the next). When no apex gives a path within the budget, or none is
//! eligible, the answer is UNDECIDED, never NO: the method is a heuristic, and whether
//! every convex polytope has such a tetrahedralization is the open question.
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
use crate::geom::{Hull3, Point3, SetDefect, orient3d, solid_set, triangulate_coplanar};
use crate::mesh;
use serde::Serialize;
use std::collections::HashMap;
use std::fmt;

/// What [`hamiltonian`] is asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PathOptions {
    /// Search steps per apex.
    pub budget: u64,
}

impl Default for PathOptions {
    fn default() -> Self {
        PathOptions { budget: 200_000 }
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
        }
    }
}

impl std::error::Error for PathError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PathError::Set(e) => Some(e),
            PathError::Uncertified(p) => Some(p),
            PathError::Internal(bug) => Some(bug),
            PathError::Inside { .. } => None,
        }
    }
}

/// A tetrahedralization with a Hamiltonian dual path ([`hamiltonian`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct HamiltonianOutcome {
    /// YES with the tetrahedra in path order; UNDECIDED when no apex gave a path within
    /// the budget or the time limit (or none is eligible).
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
    /// The tetrahedra passed [`mesh::certify_hull`] and [`mesh::verify_dual_path`].
    pub certified: bool,
    /// The tetrahedra in path order (each shares a triangle with the next), positively
    /// oriented.
    pub tets: Vec<[u32; 4]>,
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
/// next (see the module docs).
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
        certified: false,
        tets: Vec::new(),
    };
    for &(_, v) in &apexes {
        if ctl.is_stopped() {
            break;
        }
        o.apexes_tried += 1;
        let tris = base(&hull, &facets, v);
        let Some(order) = search::hamiltonian_path(&dual(&tris), opts.budget, ctl, &mut o.steps)
        else {
            continue;
        };
        let tets: Vec<[u32; 4]> = order
            .iter()
            .map(|&i| cone(points, v, tris[i as usize]))
            .collect();
        mesh::certify_hull(points, &tets).map_err(PathError::Uncertified)?;
        mesh::verify_dual_path(&tets).map_err(|i| {
            let check = "consecutive tetrahedra of the path share a triangle";
            PathError::Internal(Bug::at(check, [i as u32, i as u32 + 1]))
        })?;
        o.verdict = Verdict::Yes;
        o.tetrahedra = tets.len();
        o.apex = Some(v);
        o.certified = true;
        o.tets = tets;
        break;
    }
    Ok(o)
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
