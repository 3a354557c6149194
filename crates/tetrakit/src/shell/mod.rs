//! Steiner-free tetrahedralization of the region between two nested convex polytopes
//! (thesis ch. 4): `P − int(Q)` for convex `Q ⊆ P`, with no point added and no vertex
//! moved.
//!
//! Both methods repeatedly remove outer vertices from the current hull
//! `P̄ = CH(remaining outer vertices ∪ V(Q))` until `P̄ = Q`; each removed piece is
//! star-shaped from its tip and coned from it (Lemma 4.1), see [`surface`](self) for the
//! exact construction of a piece's bottom.
//! - [`Method::Cap`]: Bern's cap removal (§4.1): one vertex at a time, always one of
//!   minimum degree among the outer vertices still on `P̄`. `Θ(n log n)` tetrahedra in
//!   the worst case (`n(2 + 6H_n)`), met by the Bern disks of
//!   [`generate::bern_disk`]: 9.25 per vertex at n = 3002, above 9n − 6.
//! - [`Method::Bigcap`]: bigcaps (§4.2): from each tip, in the same order, a set of
//!   outer vertices removed at once, grown greedily (neighbours in increasing number,
//!   kept while the piece stays star-shaped from the tip and passes every check, at most
//!   32), without BIGCAP-REMOVE's rounds (those are [`Method::Thesis`]): on a
//!   Bern disk no two neighbouring ring vertices form a piece star-shaped from either
//!   (the surface's plan refuses "a bottom triangle is behind the tip"), although both
//!   are visible past `Q` with their facets, so the thesis's `U_v` does not give a
//!   star-shaped bigcap there (Lemma 4.1 assumes it does), and bigcaps equal caps.
//! - [`Method::Thesis`]: Lemma 4.1 checked first, exactly, at every tip ([`lemma41`]).
//!   The lemma is false as stated: on 260 of 300 random small shells some tip's bigcap
//!   is simple and not star-shaped from it, and [`lemma41::counterexample`] has 10
//!   points. Where it fails the answer is the witness. Where it holds, BIGCAP-REMOVE's
//!   Steps 1–7 run on the evolving hull (`Q_a`, `P_a`, `V_a^P`, the chains `C_a`,
//!   `U_v^S` exact past `Q`, Step 3a's fewest tips by exact search within a budget,
//!   Step 6's chains of `P_b` chord by chord), and an S-bigcap the surface refuses (not star-shaped from
//!   its tip: Lemma 4.1 failing later in the run) is **repaired**, grown from its tip
//!   within `U_v^S` while accepted ([`ThesisSteps`]). Run without the lemma's check on
//!   158 small random shells (test `thesis_steps_on_small_random_shells`): 632 S-bigcaps
//!   whole and 89 repaired in 264 rounds, Step 3a decided by its search in all of them,
//!   every shell finished by the removal, largest weight of §4.4 4 (Theorem 4.2's 8
//!   holds there), at most 2.48 tetrahedra per vertex; on 200 others, worst 1.419 × the
//!   exact optimum (1.296 after the flips).
//!
//! **Flips** ([`improve`]): after the removals, exact 3-2 flips, and above 3 tetrahedra
//! per vertex Lawson's flips towards the constrained Delaunay tetrahedralization, kept
//! when they end lower ([`crate::flip`]). They keep both surfaces and add no vertex; on
//! Bern disks they reach TetGen's count (3.0 per vertex), on random spheres the 3-2
//! flips remove about 6 %. This, not the removal, is what keeps every output we have
//! found within 9n − 6. When the asked method still ends above it, or with the flips
//! above [`REMOVAL_BUDGET`] per vertex (a Delaunay shortcut can, below), [`shell`] runs
//! the other and keeps the smaller mesh, and says in `within_bound` how it ended.
//!
//! **Delaunay** ([`Finish::Delaunay`]): with flips, a removal by caps or bigcaps that
//! passes [`REMOVAL_BUDGET`] tetrahedra per vertex (Bern disks: 7.9 per vertex at
//! n = 1502, 10.1 at 15,002; the other families stay below 3.7) is abandoned, and the
//! shell is the exact Delaunay tetrahedralization of its vertices
//! ([`crate::geom::Delaunay3`]) outside `Q`, when `Q` is a union of its tetrahedra
//! (checked exactly and combinatorially, see `delaunay`), then 3-2 flips. That is the
//! count the Lawson flips reach from the removal, at a fraction of the cost (Bern disk of
//! 6002 vertices: 0.50 s → 0.21 s). Otherwise the removal runs to its end as before. On
//! Bern disks the removal passes its budget only near its end, so once it passes
//! [`DELAUNAY_START`] tetrahedra per vertex the Delaunay tetrahedralization is started
//! on a spare core beside it, and stopped when the removal ends within its budget
//! (6002 vertices: 0.21 s → 0.16 s); the mesh does not depend on which ends first.
//!
//! **Weights** ([`Ledger`], §4.4): every interior edge a removal adds is charged to one
//! vertex as Lemmas 4.10–4.12 charge it, and Theorem 4.2's claim (every weight at most 8)
//! is checked on the run. The sum is the removal's interior edges exactly. On Bern disks
//! the claim fails for both removals here (largest weight 13 at n = 1502, 16 at 6002);
//! taking tips next to the part of `Q` already exposed first, as Steps 1–3 order them,
//! changes nothing there (the same meshes). Bigcaps can weigh more than caps (18 against
//! 4 on random spheres, n = 10^4): a big bottom charges its boundary.
//!
//! **Optimum** ([`optimum`]): for small shells the exact solver's minimum over every
//! tetrahedralization (polygon facets triangulated freely), [`crate::exact::Domain::Shell`].
//!
//! Degenerate inputs: a facet of `P̄` that lies inside `P` (made by earlier pieces, in a
//! plane through several vertices) must be met face to face, so a tip that is not an ear
//! of such a facet's triangulation is refused and retried later, and when every tip is
//! refused a tip and one neighbour are removed together. When that fails too (coaxial
//! prisms, boxes in boxes: earlier pieces triangulated a plane through the last tips so
//! that no cone completes it), the removal stops and the shell is built again by
//! **placing** ([`crate::geom::placing`]): `Q`'s boundary, then the removed vertices in
//! the reverse of their removal with the vertices left before them or after them (both
//! are placed; the fewer tetrahedra are kept: on coaxial prisms, n = 10^4, the 28 left
//! make 2.9 tetrahedra per vertex placed last, 4.8 placed first), each coned to the
//! triangles of the current hull it strictly sees. Placing refuses nothing, in any order
//! and on any input (its docs give the argument), so no valid shell fails, at any size;
//! and placing in the reverse of a removal's order fills that removal's caps again (a
//! bigcap becomes one cap per vertex), so the count stays near the removal's. The
//! outcome says which ended it ([`Finish`]). The exact solver is used for `--optimum`
//! only.
//!
//! **Contact.** Where `Q` touches `P̄` in a facet (Q's facet inside a facet of `P`, or in
//! the plane of a removal's flat bottom), the surface's triangulation of that facet gets
//! Q's edges (a facet of `P` holding vertices of `Q` is triangulated with them as
//! constraints; a flat bottom gets them by exact 2-2 flips, [`recover`](self)), so that
//! Q's facet is a union of surface triangles and no piece is built on a triangle
//! reaching into `Q`. On 999 boxes with integer corners in `[0, 4]³` (every contact with
//! a box: floor, corner, edge, shared facets), each in two orders, both methods: 1,750 of
//! the 3,996 runs failed before, none now (test `boxes_touching_a_box_anywhere`).
//!
//! **Input.** `P` and `Q` are the exact convex hulls of two point sets ([`Shell::new`]).
//! Their vertices are the extreme points; other points (inside a hull, or on it but not
//! a corner) are not vertices, and are listed in [`Shell::outer_ignored`] and
//! [`Shell::inner_ignored`]. `Q ⊆ P` is checked exactly; `Q` may touch `P` (shared
//! vertices, edges or facets, a vertex of `Q` on a facet of `P`). A vertex of both is one
//! point. `Q` must be full-dimensional.
//!
//! **Facets.** A facet of `P` or `Q` with more than three vertices is a convex polygon;
//! its triangulation is whatever the removals leave (each removal retriangulates the part
//! of the surface it replaces), and the certificate
//! ([`certify_shell`](crate::mesh::certify_shell)) accepts any triangulation of the
//! facets by their vertices.
//!
//! ```
//! use tetrakit::control::Control;
//! use tetrakit::shell::{Method, Shell, tetrahedralize};
//! let cube: Vec<[f64; 3]> =
//!     (0..8).map(|i| [(i & 1) as f64 * 4.0, ((i >> 1) & 1) as f64 * 4.0, (i >> 2) as f64 * 4.0]).collect();
//! let inner: Vec<[f64; 3]> = cube.iter().map(|p| p.map(|x| 1.0 + x / 2.0)).collect();
//! let shell = Shell::new(&cube, &inner).unwrap();
//! let mesh = tetrahedralize(&shell, Method::Cap, &Control::new()).unwrap();
//! assert!(tetrakit::mesh::certify_shell(&shell.points, &mesh.tets, &shell.inner).is_ok());
//! assert!(mesh.tets.len() <= 9 * 16 - 6);
//! ```

mod blocker;
mod delaunay;
pub mod generate;
mod hidden;
mod improve;
mod ledger;
pub mod lemma41;
mod optimum;
mod outcome;
mod recover;
mod removal;
mod surface;

use crate::bug::Bug;
use crate::control::{Control, Stopped};
use crate::geom::{Hull3, Point3, point_key};
pub use improve::{Improvement, improve};
pub use ledger::Ledger;
pub use optimum::optimum;
pub use outcome::{
    AssumptionWitness, DELAUNAY_START, FileVertex, FlipCounts, Optimum, REMOVAL_BUDGET,
    ShellOptions, ShellOutcome, Weights, shell,
};
pub use removal::ThesisSteps;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use serde::Serialize;
use std::fmt;
use surface::Surface;

/// The region between two nested convex polytopes, as vertices.
#[derive(Clone, Debug)]
pub struct Shell {
    /// The vertices: the outer ones first (in input order), then the inner ones that are
    /// not also outer vertices.
    pub points: Vec<Point3>,
    /// The vertices of `P`: indices into `points`.
    pub outer: Vec<u32>,
    /// The vertices of `Q`: indices into `points` (a vertex of both is an outer index).
    pub inner: Vec<u32>,
    /// For each outer vertex, its index in the outer input.
    pub outer_source: Vec<u32>,
    /// For each inner vertex, its index in the inner input.
    pub inner_source: Vec<u32>,
    /// Outer input points that are not vertices of `P` (inside it, on it but not a
    /// corner, or repeated).
    pub outer_ignored: Vec<u32>,
    /// Inner input points that are not vertices of `Q`.
    pub inner_ignored: Vec<u32>,
    /// Inner vertices (not outer ones) on the boundary of `P`: on an edge or inside a
    /// facet of the outer hull.
    pub touching: Vec<u32>,
    /// `P` as the hull of `points`.
    hull: Hull3,
    /// The edges of `Q`, which the surface keeps on `P`'s facets and recovers in flat
    /// bottoms.
    q_edges: recover::QEdges,
    /// `Q` as the hull of the inner input points (numbered as in the inner input).
    inner_hull: Hull3,
}

/// Why a shell cannot be built or tetrahedralized.
#[derive(Clone, Debug, PartialEq)]
pub enum ShellError {
    /// The outer points span less than 3 dimensions.
    OuterFlat {
        /// Their affine dimension.
        dimension: usize,
    },
    /// The inner points span less than 3 dimensions.
    InnerFlat {
        /// Their affine dimension.
        dimension: usize,
    },
    /// A vertex of `Q` lies outside `P`.
    InnerOutside {
        /// Its index in the inner input.
        index: u32,
        /// The point.
        point: Point3,
    },
    /// `optimum` was asked of a shell larger than the exact solver takes.
    TooLargeForOptimum {
        /// The shell's vertices.
        n: usize,
    },
    /// The control stopped the run.
    Stopped(Stopped),
    /// `optimum`'s exact solver could not run.
    Exact(crate::exact::ExactError),
    /// The mesh failed its certificate (a bug): the verifier's problem.
    Uncertified(crate::mesh::Problem),
    /// A check the construction guarantees failed (a bug).
    Internal(Bug),
}

impl fmt::Display for ShellError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShellError::OuterFlat { dimension } => write!(
                f,
                "the outer points span {dimension} dimension(s), not 3: their hull has no volume"
            ),
            ShellError::InnerFlat { dimension } => write!(
                f,
                "the inner points span {dimension} dimension(s), not 3: a flat inner hull is not a hole"
            ),
            ShellError::InnerOutside { index, point } => write!(
                f,
                "inner point {index} ({} {} {}) lies outside the outer hull",
                point[0], point[1], point[2]
            ),
            ShellError::TooLargeForOptimum { n } => write!(
                f,
                "the exact minimum takes shells of at most {} vertices; this one has {n}",
                crate::exact::MAX_VERTICES
            ),
            ShellError::Stopped(s) => s.fmt(f),
            ShellError::Exact(e) => e.fmt(f),
            ShellError::Uncertified(p) => write!(
                f,
                "internal error, please report the input: the shell mesh fails its certificate: {p}"
            ),
            ShellError::Internal(bug) => bug.fmt(f),
        }
    }
}

impl std::error::Error for ShellError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ShellError::Stopped(s) => Some(s),
            ShellError::Exact(e) => Some(e),
            ShellError::Uncertified(p) => Some(p),
            ShellError::Internal(bug) => Some(bug),
            _ => None,
        }
    }
}

impl From<Stopped> for ShellError {
    fn from(s: Stopped) -> Self {
        ShellError::Stopped(s)
    }
}

/// The extreme points of `pts` (in input order, repeats dropped), the others, and their
/// hull; or the hull's dimension when it is flat.
fn extreme_points(pts: &[Point3]) -> Result<(Vec<u32>, Vec<u32>, Hull3), usize> {
    let hull = Hull3::new(pts);
    if hull.dimension < 3 {
        return Err(hull.dimension);
    }
    let mut seen = HashSet::default();
    let (mut vertices, mut others) = (Vec::new(), Vec::new());
    for (i, p) in pts.iter().enumerate() {
        // A point inside an edge lies on two facets, inside a facet on one.
        let corner = is_corner(&hull, i) && seen.insert(point_key(p));
        if corner {
            vertices.push(i as u32)
        } else {
            others.push(i as u32)
        }
    }
    Ok((vertices, others, hull))
}

/// The outer input points split by the hull of both inputs.
struct Corners {
    /// The vertices of `P`, in input order (repeats dropped).
    vertices: Vec<u32>,
    /// The other outer points.
    others: Vec<u32>,
    /// Each vertex's number by place.
    index: HashMap<[u64; 3], u32>,
}

/// The vertices of `P` from `union`, the hull of `both` (the `n_outer` outer input
/// points, then the inner ones). `Q ⊆ P` exactly when every corner of the union is a
/// point of `P` (a corner that is not lies outside `P`): `None` when one is not, or the
/// union is flat (then `P` is).
fn outer_corners(both: &[Point3], n_outer: usize, union: &Hull3) -> Option<Corners> {
    if union.dimension < 3 {
        return None;
    }
    let mut index: HashMap<[u64; 3], u32> = HashMap::default();
    let (mut vertices, mut others) = (Vec::new(), Vec::new());
    for (i, p) in both[..n_outer].iter().enumerate() {
        let next = vertices.len() as u32;
        if is_corner(union, i) && *index.entry(point_key(p)).or_insert(next) == next {
            vertices.push(i as u32);
        } else {
            others.push(i as u32);
        }
    }
    let stray = (n_outer..both.len())
        .any(|i| is_corner(union, i) && !index.contains_key(&point_key(&both[i])));
    (!stray).then_some(Corners {
        vertices,
        others,
        index,
    })
}

/// `union`, the hull of `both`, on the shell's vertices `points`: vertex `k` is
/// `both[source[k]]`, and `index` numbers every vertex by place (a repeated point is
/// named as its vertex). A point inside an edge or a facet of `P` (no vertex) may be a
/// corner of the union's triangles: then the hull of the vertices alone is built.
fn on_vertices(
    union: Hull3,
    (both, source): (&[Point3], &[u32]),
    index: &HashMap<[u64; 3], u32>,
    points: &[Point3],
) -> Hull3 {
    let mut number = vec![u32::MAX; both.len()];
    for (k, &i) in source.iter().enumerate() {
        number[i as usize] = k as u32;
    }
    let named = |i: u32| match number[i as usize] {
        u32::MAX => index.get(&point_key(&both[i as usize])).copied(),
        k => Some(k),
    };
    (union.renumbered(source, named)).unwrap_or_else(|| Hull3::new(points))
}

/// Why `CH(inner) ⊆ CH(outer)` fails, once [`outer_corners`] has found that it does:
/// `P` flat, else `Q` flat, else the first inner vertex (in input order) that is a corner
/// of the union and no vertex of `P`.
fn refusal(outer: &[Point3], inner: &[Point3]) -> ShellError {
    let outer_v = match extreme_points(outer) {
        Ok((v, _, _)) => v,
        Err(dimension) => return ShellError::OuterFlat { dimension },
    };
    let inner_v = match extreme_points(inner) {
        Ok((v, _, _)) => v,
        Err(dimension) => return ShellError::InnerFlat { dimension },
    };
    let at_p: HashSet<[u64; 3]> = outer_v
        .iter()
        .map(|&i| point_key(&outer[i as usize]))
        .collect();
    let mut pts: Vec<Point3> = outer_v.iter().map(|&i| outer[i as usize]).collect();
    pts.extend(inner_v.iter().map(|&i| inner[i as usize]));
    let union = Hull3::new(&pts);
    let k0 = outer_v.len();
    (inner_v.iter().enumerate())
        .find(|&(k, &i)| {
            is_corner(&union, k0 + k) && !at_p.contains(&point_key(&inner[i as usize]))
        })
        .map_or(
            ShellError::Internal(Bug::new("an inner point outside the outer hull")),
            |(_, &i)| ShellError::InnerOutside {
                index: i,
                point: inner[i as usize],
            },
        )
}

/// Q's edges from `hull`, the hull of the inner input points `inner`, whose corners are
/// `corners` (first copies), each named by its input index.
fn q_edges(inner: &[Point3], hull: &Hull3, corners: &[u32]) -> recover::QEdges {
    let mut named = vec![None; inner.len()];
    for &i in corners {
        named[i as usize] = Some(i);
    }
    // A repeat of a corner is named as the corner.
    let repeats: Vec<usize> = (0..inner.len())
        .filter(|&i| named[i].is_none() && is_corner(hull, i))
        .collect();
    if !repeats.is_empty() {
        let by_place: HashMap<[u64; 3], u32> = (corners.iter())
            .map(|&i| (point_key(&inner[i as usize]), i))
            .collect();
        for i in repeats {
            named[i] = by_place.get(&point_key(&inner[i])).copied();
        }
    }
    recover::QEdges::from_hull(hull, |i| named[i as usize])
}

/// Sorts pairs, each compared as one integer: the same order as by fields, several
/// times faster.
fn sort_pairs(pairs: &mut [(u32, u32)]) {
    pairs.sort_unstable_by_key(|&(a, b)| (a as u64) << 32 | b as u64);
}

/// The entries of `sorted` (sorted by key) whose key is `k`: the lookups of the sorted
/// edge lists that replace hash maps on the removal's hot path.
fn with_key<K: Ord + Copy, V>(sorted: &[(K, V)], k: K) -> &[(K, V)] {
    let from = sorted.partition_point(|x| x.0 < k);
    let to = from + sorted[from..].partition_point(|x| x.0 <= k);
    &sorted[from..to]
}

/// Point `i` is a corner of the 3-polytope `hull` (on three of its facets or more).
fn is_corner(hull: &Hull3, i: usize) -> bool {
    hull.facets_of(i).len() >= 3
}

impl Shell {
    /// The shell between `CH(outer)` and `CH(inner)`: checks exactly that both are
    /// full-dimensional and that `CH(inner) ⊆ CH(outer)`.
    ///
    /// ```
    /// use tetrakit::shell::{Shell, ShellError};
    /// let tet = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0]];
    /// let small = [[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 2.0]];
    /// assert_eq!(Shell::new(&tet, &small).unwrap().points.len(), 8);
    /// let out = [[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [3.0, 3.0, 3.0]];
    /// assert!(matches!(Shell::new(&tet, &out), Err(ShellError::InnerOutside { index: 3, .. })));
    /// ```
    pub fn new(outer: &[Point3], inner: &[Point3]) -> Result<Shell, ShellError> {
        // The hull of both inputs at once, beside Q's (and Q's edges, by input index):
        // when Q ⊆ P it is P's hull (P's own hull is built only to say what is wrong).
        let both: Vec<Point3> = outer.iter().chain(inner).copied().collect();
        let ((union, corners), inner_e) = rayon::join(
            || {
                let union = Hull3::new(&both);
                let corners = outer_corners(&both, outer.len(), &union);
                (union, corners)
            },
            || {
                let (v, others, hull) = extreme_points(inner)?;
                let edges = q_edges(inner, &hull, &v);
                Ok((v, others, hull, edges))
            },
        );
        let Some(Corners {
            vertices: outer_v,
            others: outer_ignored,
            mut index,
        }) = corners
        else {
            return Err(refusal(outer, inner));
        };
        let (inner_v, inner_ignored, inner_hull, q_edges) =
            inner_e.map_err(|dimension| ShellError::InnerFlat { dimension })?;
        let mut points: Vec<Point3> = outer_v.iter().map(|&i| outer[i as usize]).collect();
        // Each vertex's point in `both`, whose facets on the union it takes.
        let mut source: Vec<u32> = outer_v.clone();
        let mut inner_idx = Vec::with_capacity(inner_v.len());
        index.reserve(inner_v.len());
        let mut shell_index = vec![u32::MAX; inner.len()];
        for &i in &inner_v {
            let p = inner[i as usize];
            let k = *index.entry(point_key(&p)).or_insert_with(|| {
                points.push(p);
                source.push((outer.len() + i as usize) as u32);
                points.len() as u32 - 1
            });
            inner_idx.push(k);
            shell_index[i as usize] = k;
        }
        let q_edges = q_edges.renamed(|i| shell_index[i as usize]);
        let hull = on_vertices(union, (&both, &source), &index, &points);
        let n_outer = outer_v.len() as u32;
        let touching = (n_outer..points.len() as u32)
            .filter(|&c| hull.on_boundary(c as usize))
            .collect();
        Ok(Shell {
            points,
            outer: (0..n_outer).collect(),
            inner: inner_idx,
            outer_source: outer_v,
            inner_source: inner_v,
            outer_ignored,
            inner_ignored,
            touching,
            hull,
            q_edges,
            inner_hull,
        })
    }

    /// Vertex `k` of [`Shell::points`] as its input file names it: an outer vertex by
    /// its index among the outer points, an inner one by its index among the inner.
    pub fn file_vertex(&self, k: u32) -> outcome::FileVertex {
        match self.inner.iter().position(|&q| q == k) {
            Some(i) if k as usize >= self.outer.len() => outcome::FileVertex {
                polytope: "inner",
                index: self.inner_source[i],
            },
            _ => outcome::FileVertex {
                polytope: "outer",
                index: self.outer_source[k as usize],
            },
        }
    }

    /// `n = |V(P) ∪ V(Q)|`, the `n` of the thesis's bound `9n − 6`.
    pub fn n(&self) -> usize {
        self.points.len()
    }
}

/// How to remove the outer vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Bern's cap removal, minimum degree first (§4.1).
    Cap,
    /// Greedy bigcaps (§4.2–4.3): from each tip, in Bern's order, the largest set of
    /// neighbouring outer vertices whose piece stays star-shaped from the tip.
    Bigcap,
    /// BIGCAP-REMOVE: its assumption first, Lemma 4.1 checked exactly at every tip of
    /// `P` ([`lemma41`]), where it fails the answer is that witness, not a mesh; where
    /// it holds (or `Q` touches `P`, where it is not examined) the removal follows
    /// Steps 1 to 7 ([`ThesisSteps`]: S-bigcaps over the chains of `P_a`, Step 3a by
    /// exact search within a budget, Step 6's chains of `P_b` chord by chord), then
    /// Bern's order for what they leave.
    Thesis,
}

impl Method {
    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Cap => "cap",
            Method::Bigcap => "bigcap",
            Method::Thesis => "thesis",
        }
    }
}

/// A tetrahedralization of a shell.
#[derive(Clone, Debug)]
pub struct ShellMesh {
    /// Positively oriented tetrahedra on [`Shell::points`].
    pub tets: Vec<[u32; 4]>,
    /// How many pieces were removed (caps or bigcaps), or vertices placed.
    pub pieces: usize,
    /// How the mesh was made.
    pub finished_by: Finish,
    /// The weights of §4.4 on the removal's edges ([`Ledger`]); `None` when placed.
    pub ledger: Option<Ledger>,
    /// What BIGCAP-REMOVE's steps did ([`Method::Thesis`]).
    pub thesis: Option<ThesisSteps>,
}

/// How [`tetrahedralize`] made its mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Finish {
    /// The removal took every outer vertex.
    Removal,
    /// The removal left vertices no piece removes; the mesh is a placing
    /// triangulation in the reverse of the removal's order.
    Placing,
    /// The removal passed its budget of tetrahedra; the mesh is the Delaunay
    /// tetrahedralization of the vertices outside `Q` ([`delaunay`](self)).
    Delaunay,
}

impl ShellMesh {
    /// The edges of the tetrahedra that are not on the boundary surfaces (`e_i` of
    /// Lemma 4.9: `t = e_i + n − 6` when `P` and `Q` are simplicial and do not touch).
    pub fn interior_edges(&self) -> usize {
        // The boundary's edges are among the tetrahedra's: the interior ones are the rest.
        let boundary = crate::mesh::boundary_faces(&self.tets);
        let sides = boundary
            .iter()
            .flat_map(|f| [[f[0], f[1]], [f[1], f[2]], [f[0], f[2]]]);
        crate::mesh::edges_of(&self.tets).len() - crate::mesh::distinct_edges(sides).len()
    }
}

/// Tetrahedralizes the shell by `method`. The result is not yet certified: pass it to
/// [`certify_shell`](crate::mesh::certify_shell) (the CLI always does).
///
/// Where the removal leaves vertices no piece removes (see the module docs), the shell is
/// tetrahedralized again from scratch by [`placing`](crate::geom::placing): `Q`'s
/// boundary, then the removed vertices in the reverse of their removal, the vertices left
/// before or after them (the fewer tetrahedra kept), each coned to what it sees. Placing
/// never refuses a vertex, in any order, so no valid shell fails; and placing in the
/// reverse of a removal's order fills that removal's caps again (a bigcap becomes one cap
/// per vertex), so the count stays near the removal's.
pub fn tetrahedralize(
    shell: &Shell,
    method: Method,
    ctl: &Control,
) -> Result<ShellMesh, ShellError> {
    let (mut mesh, pending) = tetrahedralize_within(shell, (method, &mut |_| true), ctl)?
        .ok_or_else(|| ShellError::Internal(Bug::new("a removal without a budget passed it")))?;
    mesh.ledger = pending.map(|p| p.ledger(shell));
    Ok(mesh)
}

/// [`tetrahedralize`], abandoned (`None`) as soon as `go_on`, told the number of
/// tetrahedra made after each piece of the removal, answers `false`. A mesh the removal
/// finished comes without its ledger, and with what the ledger needs ([`Pending`]): the
/// caller draws it up beside the flips.
pub(super) fn tetrahedralize_within(
    shell: &Shell,
    (method, go_on): (Method, &mut dyn FnMut(usize) -> bool),
    ctl: &Control,
) -> Result<Option<(ShellMesh, Option<Pending>)>, ShellError> {
    let removable: Vec<u32> = {
        let inner: HashSet<u32> = shell.inner.iter().copied().collect();
        shell
            .outer
            .iter()
            .copied()
            .filter(|v| !inner.contains(v))
            .collect()
    };
    let surface = Surface::new(shell);
    let mut thesis = None;
    let order: Vec<Vec<u32>> = match surface {
        Ok(mut surface) => {
            let run = (method, go_on);
            let Some(r) = removal::run(&mut surface, &removable, &shell.inner, run, ctl)? else {
                return Ok(None);
            };
            if r.left.is_empty() && surface.hidden.count() == 0 {
                let mesh = ShellMesh {
                    ledger: None,
                    pieces: r.records.len(),
                    tets: r.tets.clone(),
                    finished_by: Finish::Removal,
                    thesis: r.thesis,
                };
                let pending = Pending {
                    tets: r.tets,
                    records: r.records,
                    last: surface.triangles(),
                };
                return Ok(Some((mesh, Some(pending))));
            }
            thesis = r.thesis;
            placing_orders(r.left, r.order)
        }
        Err(_) => vec![removable],
    };
    ctl.check()?;
    let placed = order.iter().filter_map(|o| {
        let tets = crate::geom::placing(&shell.points, &shell.inner, o)?;
        Some((tets, o.len()))
    });
    let (tets, pieces) = placed.min_by_key(|(tets, _)| tets.len()).ok_or_else(|| {
        ShellError::Internal(Bug::new("the inner polytope, checked solid, has a hull"))
    })?;
    let mesh = ShellMesh {
        tets,
        pieces,
        finished_by: Finish::Placing,
        ledger: None,
        thesis,
    };
    Ok(Some((mesh, None)))
}

/// What the weights of §4.4 need from a removal that took every outer vertex: its
/// tetrahedra, its pieces, and the surface it ended with (`∂Q`).
pub(super) struct Pending {
    tets: Vec<[u32; 4]>,
    records: Vec<ledger::Record>,
    last: Vec<[u32; 3]>,
}

impl Pending {
    /// The ledger of the removal.
    pub(super) fn ledger(self, shell: &Shell) -> Ledger {
        let mut on_p = vec![false; shell.points.len()];
        for &v in shell.outer.iter().chain(&shell.touching) {
            on_p[v as usize] = true;
        }
        ledger::ledger(ledger::Removal {
            tets: &self.tets,
            records: &self.records,
            outer: &shell.hull,
            last: &self.last,
            on_surface: on_p,
        })
    }
}

/// The orders to place in after a removal that left `left` and removed `order`: the
/// removed vertices in reverse, with the left ones first (as if removed last) or last.
fn placing_orders(left: Vec<u32>, order: Vec<u32>) -> Vec<Vec<u32>> {
    let back: Vec<u32> = order.into_iter().rev().collect();
    let first: Vec<u32> = left.iter().chain(&back).copied().collect();
    match left.is_empty() {
        true => vec![first],
        false => vec![first, back.into_iter().chain(left).collect()],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::orient3d;

    /// The points of a box with the given corners' coordinates, as its 8 corners, or
    /// as a `3 × 3 × 3` grid (points inside its edges and facets: no vertices).
    fn cuboid([x, y, z]: [[f64; 2]; 3], grid: bool) -> Vec<Point3> {
        let steps: &[f64] = if grid { &[0.0, 0.5, 1.0] } else { &[0.0, 1.0] };
        let at = |[a, b]: [f64; 2], t: f64| a + t * (b - a);
        let mut pts = Vec::new();
        for &i in steps {
            for &j in steps {
                for &k in steps {
                    pts.push([at(x, i), at(y, j), at(z, k)]);
                }
            }
        }
        pts
    }

    /// [`Shell::new`] against the hulls of `P` and `Q` built apart, with `Q ⊆ P` and
    /// the contact decided by every facet plane of `P` (exact).
    fn agrees_with_separate_hulls(outer: &[Point3], inner: &[Point3]) {
        let (hp, hq) = (Hull3::new(outer), Hull3::new(inner));
        let got = Shell::new(outer, inner);
        if hp.dimension < 3 || hq.dimension < 3 {
            let flat = match hp.dimension < 3 {
                true => ShellError::OuterFlat {
                    dimension: hp.dimension,
                },
                false => ShellError::InnerFlat {
                    dimension: hq.dimension,
                },
            };
            return assert_eq!(got.err(), Some(flat), "{outer:?} {inner:?}");
        }
        let p = |k: u32| &outer[k as usize];
        let side = |x: &Point3| {
            (hp.facet_planes.iter())
                .map(|f| orient3d(p(f[0]), p(f[1]), p(f[2]), x))
                .max()
        };
        let corners = |pts: &[Point3], h: &Hull3| {
            let mut seen = HashSet::default();
            (0..pts.len() as u32)
                .filter(|&i| is_corner(h, i as usize) && seen.insert(point_key(&pts[i as usize])))
                .collect::<Vec<u32>>()
        };
        if inner.iter().any(|x| side(x) == Some(1)) {
            let Err(ShellError::InnerOutside { index, point }) = got else {
                panic!("{outer:?} {inner:?}: {got:?}");
            };
            assert_eq!(point, inner[index as usize]);
            assert!(side(&point) == Some(1) && is_corner(&hq, index as usize));
            return;
        }
        let s = got.expect("nested");
        assert_eq!(s.outer_source, corners(outer, &hp));
        assert_eq!(s.inner_source, corners(inner, &hq));
        let n_outer = s.outer.len() as u32;
        let on_p = |k: u32| side(&s.points[k as usize]) == Some(0);
        let touching: Vec<u32> = (n_outer..s.points.len() as u32)
            .filter(|&k| on_p(k))
            .collect();
        assert_eq!(s.touching, touching);
        for k in 0..s.points.len() as u32 {
            assert_eq!(s.hull.on_boundary(k as usize), on_p(k), "point {k}");
        }
        for t in &s.hull.triangles {
            let [a, b, c] = t.map(|k| &s.points[k as usize]);
            assert!(s.points.iter().all(|x| orient3d(a, b, c, x) <= 0));
        }
    }

    /// Boxes with integer corners in `[0, 4]³` (every contact with the cube) and in
    /// `[-1, 5]³` (most of them not inside it), in `P = [0, 4]³` given as its corners,
    /// as a grid (points inside its edges and facets), or with each point twice; flat
    /// inputs; lattice spheres with `Q = P/2`.
    #[test]
    fn shells_agree_with_separate_hulls() {
        let big = [[0.0, 4.0]; 3];
        let outers = [
            cuboid(big, false),
            cuboid(big, true),
            cuboid(big, false).repeat(2),
        ];
        let spans = |lo: i32, hi: i32| -> Vec<[f64; 2]> {
            (lo..hi)
                .flat_map(|a| (a + 1..=hi).map(move |b| [a as f64, b as f64]))
                .collect()
        };
        let (inside, across) = (spans(0, 4), spans(-1, 5));
        let mut boxes: Vec<[[f64; 2]; 3]> = Vec::new();
        for (i, &x) in across.iter().enumerate() {
            for (j, &y) in across.iter().enumerate() {
                for (k, &z) in across.iter().enumerate() {
                    let nested = [x, y, z].iter().all(|s| inside.contains(s));
                    if nested || (i + 3 * j + 5 * k) % 11 == 0 {
                        boxes.push([x, y, z]);
                    }
                }
            }
        }
        for (b, &corners) in boxes.iter().enumerate() {
            let outer = &outers[b % outers.len()];
            agrees_with_separate_hulls(outer, &cuboid(corners, b % 2 == 0));
        }
        let floor: Vec<Point3> = cuboid(big, true)
            .into_iter()
            .filter(|p| p[2] == 0.0)
            .collect();
        agrees_with_separate_hulls(&floor, &cuboid([[1.0, 2.0]; 3], false));
        agrees_with_separate_hulls(&outers[0], &floor);
        for r2 in [3, 9, 11, 17, 25, 27, 50] {
            let outer = crate::generate::cospherical_points(r2);
            let half: Vec<Point3> = outer.iter().map(|p| p.map(|x| x / 2.0)).collect();
            agrees_with_separate_hulls(&outer, &half);
            agrees_with_separate_hulls(&half, &outer);
        }
    }
}
