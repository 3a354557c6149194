//! The flip graph of a point set's tetrahedralizations (thesis ch. 6, "Flip graph
//! connectivity"): every tetrahedralization that uses every point, enumerated exactly,
//! and the flips between them.
//!
//! The thesis closes with two open questions: is the flip graph of a point set in general
//! position in `R³` connected, and is there a tetrahedralization with no flip at all? It
//! cites de Loera et al.: in convex position (no three points collinear) every
//! tetrahedralization of `n` points has at least `n − 4` flip neighbours. [`flip_graph`]
//! answers both for one small point set, exactly:
//!
//! * The tetrahedralizations are **enumerated, not walked to**: a search over the empty
//!   tetrahedra that closes open faces (`enumerate`), so a component that flips from the
//!   first cannot reach is still found. Two candidates are compatible when they meet in a
//!   common face; the test is exact and general (a circuit of at most five points between
//!   them, `candidates::compatible`), so coplanar, cospherical and collinear points need
//!   no special case. Each tetrahedralization is found once (module docs of `enumerate`).
//! * The **flips** are those that keep every point: 2-3 and 3-2, and for four coplanar
//!   points 2-2 on the hull and 4-4 inside (`graph`). Every flip from a tetrahedralization
//!   found must land on one found; one that does not is reported as an error
//!   ([`FlipError::FlipOutside`]), never counted: it would mean the enumeration missed one.
//! * **Certified**: every tetrahedralization enumerated passes [`mesh::verify`] against
//!   the hull (every point a vertex, every interior face shared by two tetrahedra on
//!   opposite sides, the boundary the hull's).
//!
//! The answer to "is the flip graph connected?" is the verdict: YES, or NO with one
//! tetrahedralization from each of two components; UNDECIDED when the `limit` or the time
//! limit cut the work short (the count found is a lower bound, and nothing about the
//! graph is claimed).
//!
//! ```
//! use tetrakit::control::{Control, Verdict};
//! use tetrakit::flipgraph::{FlipOptions, flip_graph};
//! // The unit cube: 74 tetrahedralizations, one component (de Loera et al.).
//! let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64]).collect();
//! let g = flip_graph(&cube, &FlipOptions::default(), &Control::new()).unwrap();
//! assert_eq!((g.tetrahedralizations, g.verdict), (74, Verdict::Yes));
//! assert_eq!(g.graph.as_ref().unwrap().components, 1);
//! ```

mod candidates;
mod enumerate;
mod graph;

pub use candidates::MAX_CANDIDATES;
pub use enumerate::Cut;
pub use graph::FlipKind;

use crate::control::{Control, Verdict};
use crate::geom::{Hull3, Point3, SetDefect, solid_set};
use crate::mesh;
use graph::Halt;
use rayon::prelude::*;
use serde::Serialize;
use std::fmt;

/// What [`flip_graph`] is asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FlipOptions {
    /// Stop after this many tetrahedralizations (the answer is then UNDECIDED).
    pub limit: usize,
    /// Compute the diameter of a connected graph of at most this many tetrahedralizations
    /// (a breadth-first search from each).
    pub diameter_up_to: usize,
}

impl Default for FlipOptions {
    fn default() -> Self {
        FlipOptions {
            limit: 1_000_000,
            diameter_up_to: 5000,
        }
    }
}

/// Why [`flip_graph`] could not run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FlipError {
    /// Too few points, two equal, or all coplanar.
    Set(SetDefect),
    /// More empty tetrahedra than [`MAX_CANDIDATES`].
    TooManyCandidates(usize),
    /// No anchor point could be placed (not expected).
    NoAnchor,
    /// A flip from tetrahedralization `from` led to one the enumeration did not list (a
    /// bug if it ever happens; reported rather than miscounted).
    FlipOutside {
        /// The tetrahedralization flipped.
        from: usize,
    },
    /// A tetrahedralization enumerated failed the verifier (a bug if it ever happens).
    Uncertified {
        /// The tetrahedralization.
        index: usize,
        /// What the verifier found.
        problem: mesh::Problem,
    },
}

impl fmt::Display for FlipError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FlipError::Set(e) => e.fmt(f),
            FlipError::TooManyCandidates(k) => write!(
                f,
                "{k} empty tetrahedra, more than the {MAX_CANDIDATES} the enumeration takes: use fewer points"
            ),
            FlipError::NoAnchor => write!(f, "could not place an anchor point in general position"),
            FlipError::FlipOutside { from } => write!(
                f,
                "internal error: a flip from tetrahedralization {from} leads to one the enumeration did not find"
            ),
            FlipError::Uncertified { index, problem } => write!(
                f,
                "internal error: tetrahedralization {index} fails the verifier: {problem}"
            ),
        }
    }
}

impl std::error::Error for FlipError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            FlipError::Set(e) => Some(e),
            FlipError::Uncertified { problem, .. } => Some(problem),
            _ => None,
        }
    }
}

/// How many flips of each kind the graph has (each edge once).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct FlipCounts {
    /// Every flip.
    pub total: usize,
    /// 2-3 (and 3-2) flips.
    pub two_three: usize,
    /// 2-2 flips on the hull.
    pub two_two: usize,
    /// 4-4 flips inside.
    pub four_four: usize,
}

/// What the flip graph of a complete enumeration looks like.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct GraphFacts {
    /// Its edges by kind.
    pub flips: FlipCounts,
    /// Connected components.
    pub components: usize,
    /// Their sizes, largest first.
    pub component_sizes: Vec<usize>,
    /// The fewest flip neighbours of a tetrahedralization.
    pub min_flips: usize,
    /// The most.
    pub max_flips: usize,
    /// The tetrahedralizations with no flip (a lone tetrahedralization is one).
    pub isolated: Vec<Vec<[u32; 4]>>,
    /// The longest shortest flip path, when connected and at most
    /// [`FlipOptions::diameter_up_to`] tetrahedralizations.
    pub diameter: Option<usize>,
}

/// Why the flip graph is not connected: one tetrahedralization from each of two
/// components.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Disconnected {
    /// Always `"disconnected"`.
    pub kind: &'static str,
    /// A tetrahedralization in the first component.
    pub first: Vec<[u32; 4]>,
    /// One in another component.
    pub second: Vec<[u32; 4]>,
    /// The sizes of their components.
    pub sizes: [usize; 2],
}

/// The flip graph of a point set's tetrahedralizations ([`flip_graph`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct FlipGraph {
    /// YES: connected; NO: not, with [`FlipGraph::witness`]; UNDECIDED: the enumeration
    /// was cut ([`FlipGraph::cut`]).
    pub verdict: Verdict,
    /// Points.
    pub points: usize,
    /// Empty tetrahedra (the candidates).
    pub candidates: usize,
    /// Tetrahedralizations that use every point (found so far, when cut).
    pub tetrahedralizations: usize,
    /// Whether the flip graph is connected (`None` when the enumeration was cut).
    pub connected: Option<bool>,
    /// Why the enumeration ended early, if it did.
    pub cut: Option<Cut>,
    /// Search states the enumeration visited.
    pub states: u64,
    /// The fewest tetrahedra in a tetrahedralization found.
    pub min_tetrahedra: usize,
    /// The most.
    pub max_tetrahedra: usize,
    /// Every tetrahedralization found passed [`mesh::verify`].
    pub certified: bool,
    /// The graph, when the enumeration is complete.
    #[serde(skip_serializing_if = "Option::is_none", flatten)]
    pub graph: Option<GraphFacts>,
    /// Two tetrahedralizations no flips join (a NO).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<Disconnected>,
    /// Every tetrahedralization found, in the order found.
    #[serde(skip)]
    all: Enumeration,
    /// Each one's flip neighbours (its place, kind), ascending; empty when cut.
    #[serde(skip)]
    pub neighbours: Vec<Vec<(u32, FlipKind)>>,
}

impl FlipGraph {
    /// The `i`-th tetrahedralization found (`i < tetrahedralizations`), positively
    /// oriented.
    pub fn tetrahedralization(&self, i: usize) -> Vec<[u32; 4]> {
        self.all.get(i)
    }

    /// The same outcome with every vertex index plus `base` (a file's numbering);
    /// tetrahedralizations keep their 0-based places.
    pub fn shifted(mut self, base: u32) -> FlipGraph {
        let shift = |t: &mut Vec<[u32; 4]>| t.iter_mut().for_each(|q| *q = q.map(|v| v + base));
        shift(&mut self.all.tets);
        if let Some(g) = &mut self.graph {
            g.isolated.iter_mut().for_each(shift);
        }
        if let Some(w) = &mut self.witness {
            shift(&mut w.first);
            shift(&mut w.second);
        }
        self
    }
}

/// Every tetrahedralization of a point set that uses every point, enumerated exactly and
/// certified ([`tetrahedralizations`]): the first step of [`flip_graph`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Enumeration {
    /// Why the enumeration ended before the last tetrahedralization (`None`: all found).
    pub cut: Option<Cut>,
    /// Search states visited.
    pub states: u64,
    /// The empty tetrahedra, positively oriented.
    tets: Vec<[u32; 4]>,
    found: enumerate::Family,
}

impl Enumeration {
    /// How many were found.
    pub fn len(&self) -> usize {
        self.found.len()
    }

    /// Whether none was found (never, for a set that passes [`solid_set`]).
    pub fn is_empty(&self) -> bool {
        self.found.len() == 0
    }

    /// The `i`-th tetrahedralization found (`i < len()`), positively oriented.
    pub fn get(&self, i: usize) -> Vec<[u32; 4]> {
        let ids = self.found.get(i);
        ids.iter().map(|&t| self.tets[t as usize]).collect()
    }
}

/// Every tetrahedralization of `points` that uses every point, at most `limit` of them,
/// each found once (see the module docs) and passed through [`mesh::verify`].
///
/// ```
/// use tetrakit::control::Control;
/// let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64]).collect();
/// let all = tetrakit::flipgraph::tetrahedralizations(&cube, 1000, &Control::new()).unwrap();
/// assert_eq!((all.len(), all.cut), (74, None));
/// ```
pub fn tetrahedralizations(
    points: &[Point3],
    limit: usize,
    ctl: &Control,
) -> Result<Enumeration, FlipError> {
    Ok(enumerated(points, limit, ctl)?.0)
}

/// Each tetrahedralization of `points` that uses every point, handed to `each` (its
/// tetrahedra, positively oriented) as the enumeration finds it, until `each` returns
/// `false` (then [`Cut::Done`]) or `limit` were found; nothing is kept, so a count takes
/// no memory. Why it ended early, if it did, and how many were handed.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::flipgraph::{Cut, for_each_tetrahedralization};
/// let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64]).collect();
/// let all = for_each_tetrahedralization(&cube, usize::MAX, &Control::new(), |_| true).unwrap();
/// assert_eq!(all, (None, 74));
/// let five = for_each_tetrahedralization(&cube, usize::MAX, &Control::new(), |t| t.len() != 5);
/// assert_eq!(five.unwrap().0, Some(Cut::Done)); // stopped at the first of five tetrahedra
/// ```
pub fn for_each_tetrahedralization(
    points: &[Point3],
    limit: usize,
    ctl: &Control,
    each: impl FnMut(Vec<[u32; 4]>) -> bool,
) -> Result<(Option<Cut>, usize), FlipError> {
    streamed(points, limit, ctl, each).map(|(cut, count, _)| (cut, count))
}

/// [`for_each_tetrahedralization`], with the number of candidates.
fn streamed(
    points: &[Point3],
    limit: usize,
    ctl: &Control,
    mut each: impl FnMut(Vec<[u32; 4]>) -> bool,
) -> Result<(Option<Cut>, usize, usize), FlipError> {
    let (c, start) = prepared(points, ctl)?;
    let tets: Vec<[u32; 4]> = c.tets.iter().map(|&t| oriented(points, t)).collect();
    let mut count = 0;
    let mut visit = |ids: &[u16]| {
        count += 1;
        each(ids.iter().map(|&t| tets[t as usize]).collect())
    };
    let (cut, _) = enumerate::visit(&c, &start, limit.max(1), ctl, &mut visit);
    Ok((cut, count, tets.len()))
}

/// The number of tetrahedralizations of a point set that use every point
/// ([`count`]): `tetrakit flips --count-only --json` without the timing.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Count {
    /// `yes` when every tetrahedralization was counted, `undecided` when the limit or
    /// the time limit cut the enumeration (there are at least that many).
    pub verdict: Verdict,
    /// Points.
    pub points: usize,
    /// Empty tetrahedra the enumeration chose from.
    pub candidates: usize,
    /// Tetrahedralizations counted, each certified.
    pub tetrahedralizations: usize,
    /// Why the enumeration ended early, if it did.
    pub cut: Option<Cut>,
    /// Every one counted passed [`mesh::verify`] against the hull.
    pub certified: bool,
}

/// Counts the tetrahedralizations of `points` that use every point, as [`flip_graph`]
/// enumerates them (up to `limit`), without keeping any: each is checked by
/// [`mesh::verify`] against the hull as it is found and dropped, so the count of
/// millions takes the memory of one. TOPCOM's `points2nallfinetriangs` counts the same
/// (fine triangulations).
///
/// ```
/// use tetrakit::control::{Control, Verdict};
/// use tetrakit::flipgraph::count;
/// let cube: Vec<[f64; 3]> = (0..8).map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64]).collect();
/// let c = count(&cube, usize::MAX, &Control::new()).unwrap();
/// assert_eq!((c.verdict, c.tetrahedralizations, c.certified), (Verdict::Yes, 74, true));
/// let c = count(&cube, 10, &Control::new()).unwrap();
/// assert_eq!((c.verdict, c.tetrahedralizations), (Verdict::Undecided, 10));
/// ```
pub fn count(points: &[Point3], limit: usize, ctl: &Control) -> Result<Count, FlipError> {
    let hull = Hull3::new(points);
    let mut failed = None;
    let (cut, n, candidates) = streamed(points, limit, ctl, |t| {
        match mesh::verify(points, &t, Some(&hull)).problems.first() {
            None => true,
            Some(p) => {
                failed = Some(p.clone());
                false
            }
        }
    })?;
    if let Some(problem) = failed {
        return Err(FlipError::Uncertified {
            index: n - 1,
            problem,
        });
    }
    Ok(Count {
        verdict: match cut {
            None => Verdict::Yes,
            Some(_) => Verdict::Undecided,
        },
        points: points.len(),
        candidates,
        tetrahedralizations: n,
        cut,
        certified: true,
    })
}

/// The candidates of `points` and those that hold the anchor (where every search starts).
fn prepared(
    points: &[Point3],
    ctl: &Control,
) -> Result<(candidates::Candidates, Vec<u16>), FlipError> {
    solid_set(points).map_err(FlipError::Set)?;
    ctl.stage("empty tetrahedra");
    let c = candidates::candidates(points)?;
    let triangles: Vec<[u32; 3]> = c.faces.iter().map(|f| f.v).collect();
    let start: Vec<u16> = crate::geom::anchor(points, &c.tets, &triangles)
        .ok_or(FlipError::NoAnchor)?
        .into_iter()
        .map(|t| t as u16)
        .collect();
    ctl.stage("tetrahedralizations");
    Ok((c, start))
}

/// [`tetrahedralizations`], and the candidates the flips are computed on.
fn enumerated(
    points: &[Point3],
    limit: usize,
    ctl: &Control,
) -> Result<(Enumeration, candidates::Candidates), FlipError> {
    let (c, start) = prepared(points, ctl)?;
    let found = enumerate::enumerate(&c, &start, limit.max(1), ctl);
    let tets: Vec<[u32; 4]> = c.tets.iter().map(|&t| oriented(points, t)).collect();
    certify(points, &tets, &found.all)?;
    let e = Enumeration {
        cut: found.cut,
        states: found.states,
        tets,
        found: found.all,
    };
    Ok((e, c))
}

/// Every tetrahedralization of `points` that uses every point, and the graph of the flips
/// between them (see the module docs).
pub fn flip_graph(
    points: &[Point3],
    opts: &FlipOptions,
    ctl: &Control,
) -> Result<FlipGraph, FlipError> {
    let (e, c) = enumerated(points, opts.limit, ctl)?;
    let sizes = (0..e.len()).map(|i| e.found.get(i).len());
    let mut g = FlipGraph {
        verdict: Verdict::Undecided,
        points: points.len(),
        candidates: c.tets.len(),
        tetrahedralizations: e.len(),
        connected: None,
        cut: e.cut,
        states: e.states,
        min_tetrahedra: sizes.clone().min().unwrap_or(0),
        max_tetrahedra: sizes.max().unwrap_or(0),
        certified: true,
        graph: None,
        witness: None,
        all: e,
        neighbours: Vec::new(),
    };
    if g.cut.is_some() {
        return Ok(g);
    }
    ctl.stage("flips");
    let built = graph::adjacency(points, &c, &g.all.found, ctl)
        .and_then(|adj| Ok((facts(&adj, &g, opts, ctl)?, adj)));
    let (facts, adj) = match built {
        Ok(done) => done,
        Err(Halt::Stopped) => {
            g.cut = Some(Cut::TimeLimit);
            return Ok(g);
        }
        Err(Halt::Outside { from }) => return Err(FlipError::FlipOutside { from }),
    };
    g.neighbours = adj;
    g.connected = Some(facts.components == 1);
    g.verdict = Verdict::from(facts.components == 1);
    if facts.components > 1 {
        let (labels, sizes) = graph::components(&g.neighbours);
        let other = labels.iter().position(|&l| l != 0).expect("two components");
        g.witness = Some(Disconnected {
            kind: "disconnected",
            first: g.tetrahedralization(0),
            second: g.tetrahedralization(other),
            sizes: [sizes[0], sizes[labels[other] as usize]],
        });
    }
    g.graph = Some(facts);
    Ok(g)
}

/// `t`'s corners in positive orientation.
fn oriented(points: &[Point3], mut t: [u32; 4]) -> [u32; 4] {
    let [a, b, c, d] = t.map(|v| &points[v as usize]);
    if crate::geom::orient3d(a, b, c, d) < 0 {
        t.swap(2, 3);
    }
    t
}

/// Every tetrahedralization found through [`mesh::verify`] against the hull.
fn certify(points: &[Point3], tets: &[[u32; 4]], all: &enumerate::Family) -> Result<(), FlipError> {
    let hull = Hull3::new(points);
    (0..all.len()).into_par_iter().try_for_each(|index| {
        let t: Vec<[u32; 4]> = all.get(index).iter().map(|&x| tets[x as usize]).collect();
        match mesh::verify(points, &t, Some(&hull)).problems.first() {
            None => Ok(()),
            Some(p) => Err(FlipError::Uncertified {
                index,
                problem: p.clone(),
            }),
        }
    })
}

fn facts(
    adj: &graph::Adjacency,
    g: &FlipGraph,
    opts: &FlipOptions,
    ctl: &Control,
) -> Result<GraphFacts, Halt> {
    let mut flips = FlipCounts::default();
    for (i, ns) in adj.iter().enumerate() {
        for &(j, kind) in ns {
            if (j as usize) > i {
                flips.total += 1;
                match kind {
                    FlipKind::TwoThree => flips.two_three += 1,
                    FlipKind::TwoTwo => flips.two_two += 1,
                    FlipKind::FourFour => flips.four_four += 1,
                }
            }
        }
    }
    let (_, mut component_sizes) = graph::components(adj);
    component_sizes.sort_unstable_by(|a, b| b.cmp(a));
    let components = component_sizes.len();
    let diameter = if components == 1 && adj.len() <= opts.diameter_up_to {
        Some(graph::diameter(adj, ctl)?)
    } else {
        None
    };
    Ok(GraphFacts {
        flips,
        components,
        component_sizes,
        min_flips: adj.iter().map(Vec::len).min().unwrap_or(0),
        max_flips: adj.iter().map(Vec::len).max().unwrap_or(0),
        isolated: (0..adj.len())
            .filter(|&i| adj[i].is_empty())
            .map(|i| g.tetrahedralization(i))
            .collect(),
        diameter,
    })
}
