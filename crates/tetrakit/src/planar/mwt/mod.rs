//! Exact minimum weight triangulations (thesis §5.1; the pipeline of Beirouti–Snoeyink
//! and Haas): the diamond test ([`candidates`]), the LMT-skeleton ([`lmt`]), and an
//! exact stage on the faces the skeleton leaves ([`faces`]): dynamic programming on
//! simple faces, branching over connecting edges for faces with holes. Sites all on the
//! hull's boundary skip the first two stages: one polygon DP over the hull decides them.
//! The result is verified as a triangulation and its weight is a certified interval;
//! every weight comparison is exact.

mod bounds;
mod candidates;
mod edge_grid;
mod faces;
mod lmt;
mod polygon;
mod sites;
mod walks;

pub use bounds::{LowerBound, MwtBounds, mwt_bounds};
pub use candidates::candidate_edges;
pub use polygon::cmp_edge_sets;
pub(crate) use polygon::polygon_dp;
pub(crate) use walks::walk_area_sign;

use super::{PlanarError, find};
use crate::control::{Control, Stopped};
use crate::geom::{Hull2, Interval, Point2, orient2d};
use crate::mesh::verify_triangulation;
use crate::numbering::Renumbering;
use crate::planar::grid::PointGrid;
use faces::Face;
use lmt::{ALIVE, CERTAIN};
use polygon::Solution;
use rayon::prelude::*;
use std::time::Instant;
use walks::Rotation;

/// True when the open segments `ab` and `cd` cross at one interior point (exact).
pub(crate) fn cross(a: &Point2, b: &Point2, c: &Point2, d: &Point2) -> bool {
    orient2d(a, b, c) * orient2d(a, b, d) < 0 && orient2d(c, d, a) * orient2d(c, d, b) < 0
}

/// Options of [`mwt`].
#[derive(Clone, Debug, Default)]
pub struct MwtOptions {
    /// Edges every triangulation considered must contain (a constrained optimum). The
    /// diamond test does not apply to constrained optima, so all segments are candidates
    /// when this is non-empty (meant for small inputs).
    pub forced: Vec<[u32; 2]>,
    /// Edges no triangulation considered may contain.
    pub forbidden: Vec<[u32; 2]>,
}

/// The stages [`mwt`] reports ([`Progress::Stage`](crate::control::Progress::Stage)) as
/// each one starts.
pub mod mwt_stage {
    /// The candidate filter.
    pub const CANDIDATES: &str = "candidate edges (diamond test)";
    /// The LMT-skeleton.
    pub const SKELETON: &str = "LMT-skeleton";
    /// The exact stage on the faces left.
    pub const FACES: &str = "exact stage on the faces left";
    /// The check that the answer triangulates the hull.
    pub const CERTIFY: &str = "certifying the triangulation";
}

/// Statistics of an MWT computation.
#[derive(Clone, Debug, Default)]
pub struct MwtStats {
    /// Candidate edges after the diamond test (every pair for sites in convex position,
    /// which go straight to one polygon DP).
    pub candidates: usize,
    /// Edges fixed by the LMT-skeleton (hull edges included).
    pub skeleton_edges: usize,
    /// Candidate edges still undecided after the LMT-skeleton.
    pub undecided_edges: usize,
    /// Faces left to the exact stage.
    pub faces_left: usize,
    /// Of those, faces with holes.
    pub faces_with_holes: usize,
    /// Largest face (walk length) left to the exact stage.
    pub largest_face: usize,
    /// Seconds in the candidate filter, the LMT-skeleton and the exact stage.
    pub seconds: [f64; 3],
}

/// A minimum weight triangulation.
#[derive(Clone, Debug, Default)]
pub struct Mwt {
    /// Edges `[p, q]`, `p < q`, sorted.
    pub edges: Vec<[u32; 2]>,
    /// Counter-clockwise triangles (empty when the sites are collinear).
    pub triangles: Vec<[u32; 3]>,
    /// The total length, certified.
    pub weight: Interval,
    /// Edges fixed by the LMT-skeleton (in every MWT), sorted.
    pub skeleton: Vec<[u32; 2]>,
    /// How the answer was found.
    pub stats: MwtStats,
}

/// The exact minimum weight triangulation of distinct sites, with the constraints of
/// `opts` (an error names any two sites that coincide, a coordinate outside the exact
/// range, or a bad constraint). Progress: the [`mwt_stage`]s as each starts. Stopped by
/// `ctl`, it gives up with [`PlanarError::Stopped`]; it looks between sites, between
/// edges and between faces, and a face's DP already under way runs to its end
/// ([`mwt_bounds`] then gives certified bounds).
///
/// ```
/// use tetrakit::control::{Control, Stopped};
/// use tetrakit::planar::{MwtOptions, PlanarError, mwt};
/// let pts = [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.5]];
/// let t = mwt(&pts, &MwtOptions::default(), &Control::new()).unwrap();
/// assert_eq!((t.edges.len(), t.triangles.len()), (8, 4));
/// assert!(t.weight.lo <= t.weight.hi);
/// let stopped = Control::new();
/// stopped.stop();
/// assert_eq!(mwt(&pts, &MwtOptions::default(), &stopped).unwrap_err(), PlanarError::Stopped(Stopped));
/// ```
pub fn mwt(points: &[Point2], opts: &MwtOptions, ctl: &Control) -> Result<Mwt, PlanarError> {
    mwt_reporting(points, opts, ctl, &mut 0.0)
}

/// What [`mwt_or_bounds`] found: the MWT, or certified bounds when stopped first.
#[derive(Clone, Debug)]
pub enum MwtOutcome {
    /// The exact minimum weight triangulation.
    Solved(Mwt),
    /// Stopped by the control: [`mwt_bounds`], its lower bound raised to the solver's
    /// ([`MwtBounds::lower_source`] says which).
    Stopped(MwtBounds),
}

/// [`mwt`] (no constraints), or, once `ctl` is stopped, certified bounds on the minimum
/// weight with a triangulation that meets the upper one. The lower bound is the better
/// of the minimum spanning tree's and the one the solver's state gives when the
/// LMT-skeleton has run: every MWT has the `3n - 3 - h` edges of any triangulation (`h`
/// sites on the hull's boundary), the edges the skeleton fixed, the optimum of every
/// face already solved, and otherwise only undecided edges of the faces left, so it
/// weighs at least those weights plus the shortest undecided edges that make up the
/// count.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::planar::{LowerBound, MwtOutcome, mwt_or_bounds};
/// let pts = [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.5]];
/// assert!(matches!(mwt_or_bounds(&pts, &Control::new()).unwrap(), MwtOutcome::Solved(_)));
/// let stopped = Control::new();
/// stopped.stop();
/// let MwtOutcome::Stopped(b) = mwt_or_bounds(&pts, &stopped).unwrap() else { panic!() };
/// assert!(b.lower.lo <= b.upper.hi && b.lower_source == LowerBound::SpanningTree);
/// ```
pub fn mwt_or_bounds(points: &[Point2], ctl: &Control) -> Result<MwtOutcome, PlanarError> {
    let mut lower = 0.0;
    match mwt_reporting(points, &MwtOptions::default(), ctl, &mut lower) {
        Ok(m) => Ok(MwtOutcome::Solved(m)),
        Err(PlanarError::Stopped(Stopped)) => {
            let mut b = mwt_bounds(points)?;
            if lower > b.lower.lo {
                b.lower = Interval {
                    lo: lower,
                    hi: lower,
                };
                b.lower_source = LowerBound::SolverState;
            }
            Ok(MwtOutcome::Stopped(b))
        }
        Err(e) => Err(e),
    }
}

/// [`mwt`], setting `lower` to a certified lower bound on the minimum weight from the
/// solver's state when it stops (left as it is when there is none).
fn mwt_reporting(
    points: &[Point2],
    opts: &MwtOptions,
    ctl: &Control,
    lower: &mut f64,
) -> Result<Mwt, PlanarError> {
    super::check_sites(points)?;
    let n = points.len() as u32;
    let constraints = opts.forced.iter().chain(&opts.forbidden);
    if let Some(e) = constraints
        .into_iter()
        .find(|e| e[0].max(e[1]) >= n || e[0] == e[1])
    {
        return Err(PlanarError::BadConstraint {
            edge: *e,
            sites: n as usize,
        });
    }
    // Every stage reads sites by index, at random; in grid-cell order, neighbours in the
    // plane are mostly neighbours in memory (at 10^6 sites this halves the time).
    let renumber = Renumbering::from_order(PointGrid::new(points, 2.0).slots().0.to_vec());
    let local = renumber.reorder(points);
    // Edges as sorted `[min, max]` pairs, in either numbering.
    let sorted = |mut v: Vec<[u32; 2]>| -> Vec<[u32; 2]> {
        v.iter_mut().for_each(|e| *e = super::edge_key(e[0], e[1]));
        v.par_sort_unstable();
        v
    };
    let local_opts = MwtOptions {
        forced: sorted(renumber.to_new(&opts.forced)),
        forbidden: sorted(renumber.to_new(&opts.forbidden)),
    };
    let m = solve(&local, &local_opts, &renumber, ctl, lower)?;
    Ok(Mwt {
        edges: sorted(renumber.to_old(&m.edges)),
        triangles: renumber.to_old(&m.triangles),
        weight: m.weight,
        skeleton: sorted(renumber.to_old(&m.skeleton)),
        stats: m.stats,
    })
}

/// [`mwt`] on checked sites; `global` maps site indices to the caller's (messages).
/// Stopped after the LMT-skeleton, it sets `lower` ([`faces_bound`]).
fn solve(
    points: &[Point2],
    opts: &MwtOptions,
    global: &Renumbering,
    ctl: &Control,
    lower: &mut f64,
) -> Result<Mwt, PlanarError> {
    ctl.check()?;
    let hull = Hull2::new(points);
    if hull.vertices.len() < 3 {
        return Ok(collinear(points));
    }
    let constrained = !opts.forced.is_empty() || !opts.forbidden.is_empty();
    if hull.on_boundary.iter().all(|&b| b) && !constrained {
        ctl.stage(mwt_stage::FACES);
        return convex_position(points, &hull, ctl);
    }
    let mut stats = MwtStats::default();
    ctl.stage(mwt_stage::CANDIDATES);
    let t0 = Instant::now();
    let sorted = |v: &[[u32; 2]]| -> Vec<[u32; 2]> {
        let mut v: Vec<[u32; 2]> = v.iter().map(|e| super::edge_key(e[0], e[1])).collect();
        v.sort_unstable();
        v
    };
    let (forced, forbidden) = (sorted(&opts.forced), sorted(&opts.forbidden));
    let n = points.len();
    let cands = if constrained {
        (n * (n - 1) / 2 <= MAX_CANDIDATES).then(|| all_segments(points))
    } else {
        candidates::search(points, MAX_CANDIDATES, ctl)
    };
    ctl.check()?;
    let mut cands = cands.ok_or_else(|| too_many_candidates(n))?;
    cands.retain(|e| forbidden.binary_search(e).is_err());
    for f in &forced {
        if cands.binary_search(f).is_err() {
            return Err(PlanarError::ForcedEdgeBlocked {
                edge: [global.old(f[0]), global.old(f[1])],
            });
        }
    }
    stats.candidates = cands.len();
    stats.seconds[0] = t0.elapsed().as_secs_f64();
    ctl.stage(mwt_stage::SKELETON);
    let t1 = Instant::now();
    let (sk, lstats) = lmt::lmt_skeleton(points, &hull, cands, &forced, &forbidden, ctl).map_err(
        |[v, a, b]| {
            PlanarError::internal(
                "no two candidate edges from one site overlap (at the site and the edges' other ends)",
                [v, a, b].map(|x| global.old(x)),
            )
        },
    )?;
    let (certain, alive) = (sk.with_status(CERTAIN), sk.with_status(ALIVE));
    if ctl.is_stopped() {
        // Faces are worth finding only when the skeleton is complete (before, they are
        // few and huge, and finding them takes as long as the rounds left).
        let faces = lstats
            .complete
            .then(|| undecided_faces(points, &certain, &alive).ok());
        *lower = match faces.flatten() {
            Some(problems) => faces_bound(points, &certain, &problems, &[]),
            None => {
                let h = hull.on_boundary.iter().filter(|&&b| b).count();
                let needed = (3 * n - 3 - h).saturating_sub(certain.len());
                bounds::state_bound(points, &certain, &[(needed, alive)])
            }
        };
        return Err(PlanarError::Stopped(Stopped));
    }
    stats.skeleton_edges = lstats.certain;
    stats.undecided_edges = lstats.undecided;
    stats.seconds[1] = t1.elapsed().as_secs_f64();
    ctl.stage(mwt_stage::FACES);
    let t2 = Instant::now();
    let mut edges = certain.clone();
    if !alive.is_empty() {
        let problems = undecided_faces(points, &certain, &alive)?;
        stats.faces_left = problems.len();
        stats.faces_with_holes = problems.iter().filter(|(f, _)| !f.holes.is_empty()).count();
        stats.largest_face = problems
            .iter()
            .map(|(f, _)| f.outer.len())
            .max()
            .unwrap_or(0);
        for (f, _) in &problems {
            // Splicing a hole into the outer walk walks its joining edge twice.
            let m = f.outer.len() + f.holes.iter().map(|h| h.len() + 2).sum::<usize>();
            dp_fits(m, false)?;
        }
        // Inside the pool even for a single face, which `par_iter` would run on this
        // thread: the DPs' parallel loops are cheap from a worker, and from outside the
        // pool each one waits for a worker to take it (a ring-hole face, whose leaves'
        // DPs ran there one after another, spent half its time so).
        let solved: Vec<Option<Solution>> = rayon::scope(|_| {
            (problems.par_iter())
                .map(|(face, chords)| {
                    let usable = || chords.iter().copied().collect();
                    (!ctl.is_stopped())
                        .then(|| faces::solve(points, face, &usable(), ctl))
                        .flatten()
                })
                .collect()
        });
        if ctl.is_stopped() {
            *lower = faces_bound(points, &certain, &problems, &solved);
            return Err(PlanarError::Stopped(Stopped));
        }
        for s in solved {
            let s = s.ok_or_else(|| {
                PlanarError::internal(
                    "the exact stage finds a triangulation of every face with the allowed edges",
                    [],
                )
            })?;
            edges.extend(s.edges);
        }
    }
    stats.seconds[2] = t2.elapsed().as_secs_f64();
    edges.par_sort_unstable();
    edges.dedup();
    ctl.stage(mwt_stage::CERTIFY);
    let triangles = certified_triangles(points, &hull, &edges)?;
    let weight = weight_of(points, &edges);
    Ok(Mwt {
        edges,
        triangles,
        weight,
        skeleton: certain,
        stats,
    })
}

/// [`bounds::state_bound`] once the faces are known: the certain edges and the solved
/// faces' edges (`solved[i]`, when there) are known, every other face needs its
/// [`Face::interior_edges`] from its chords.
fn faces_bound(
    points: &[Point2],
    certain: &[[u32; 2]],
    problems: &[FaceProblem],
    solved: &[Option<Solution>],
) -> f64 {
    let (mut known, mut left) = (certain.to_vec(), Vec::new());
    for (i, (face, chords)) in problems.iter().enumerate() {
        match solved.get(i).and_then(Option::as_ref) {
            Some(s) => known.extend(&s.edges),
            None => left.push((face.interior_edges(), chords.clone())),
        }
    }
    known.sort_unstable();
    known.dedup();
    bounds::state_bound(points, &known, &left)
}

/// The most memory the solver plans to use: past it an error says so before the
/// allocation (never an abort for want of memory).
const MEMORY_LIMIT: usize = 16 << 30;

/// Bytes per pair of walk occurrences that a face's polygon DP uses (table and rows;
/// 63 MB measured on a convex polygon of 2000 sites).
const DP_BYTES_PER_PAIR: usize = 32;

/// Peak bytes per candidate edge of the whole solver (69 measured on 10^6 uniform sites,
/// 64 on 10^7), and so the most candidates it takes.
const BYTES_PER_CANDIDATE: usize = 64;
const MAX_CANDIDATES: usize = MEMORY_LIMIT / BYTES_PER_CANDIDATE;

/// The error for a set with more than [`MAX_CANDIDATES`] candidate edges.
fn too_many_candidates(n: usize) -> PlanarError {
    PlanarError::TooManyCandidates {
        sites: n,
        limit: MAX_CANDIDATES,
        memory: MEMORY_LIMIT,
    }
}

/// An error when the polygon DP over a walk of `m` occurrences would pass the memory
/// limit; `convex_position` says whether the walk is the hull of sites in convex
/// position (otherwise a face left by the LMT-skeleton).
fn dp_fits(m: usize, convex_position: bool) -> Result<(), PlanarError> {
    let bytes = DP_BYTES_PER_PAIR.saturating_mul(m).saturating_mul(m) / 2;
    if bytes <= MEMORY_LIMIT {
        return Ok(());
    }
    Err(PlanarError::DynamicProgramTooLarge {
        vertices: m,
        convex_position,
        bytes,
        memory: MEMORY_LIMIT,
    })
}

/// Sites all on the hull's boundary: every triangulation is one of the hull polygon (its
/// walk through every boundary site), so one polygon DP over it decides the MWT. Every
/// segment between two sites lies in the polygon, and the DP's wedge test drops those
/// along a side. The diamond test would keep `Θ(n²)` candidates at cubic cost, and the
/// LMT decides nothing here.
fn convex_position(points: &[Point2], hull: &Hull2, ctl: &Control) -> Result<Mwt, PlanarError> {
    let n = points.len();
    let t = Instant::now();
    dp_fits(n, true)?;
    let walk: Vec<u32> = (hull.boundary_chains(points).iter())
        .flat_map(|c| c[..c.len() - 1].iter().copied())
        .collect();
    let dp = polygon_dp(points, &walk, &[], &|_| true, ctl);
    ctl.check()?;
    let dp = dp.ok_or_else(|| PlanarError::internal("a convex polygon has a triangulation", []))?;
    let mut skeleton = lmt::hull_edges(points, hull);
    skeleton.sort_unstable();
    let mut edges: Vec<[u32; 2]> = skeleton.iter().copied().chain(dp.edges).collect();
    edges.par_sort_unstable();
    edges.dedup();
    let stats = MwtStats {
        candidates: n * (n - 1) / 2,
        skeleton_edges: n,
        undecided_edges: n * (n - 1) / 2 - n,
        faces_left: usize::from(n > 3),
        largest_face: if n > 3 { n } else { 0 },
        seconds: [0.0, 0.0, t.elapsed().as_secs_f64()],
        ..MwtStats::default()
    };
    let triangles = certified_triangles(points, hull, &edges)?;
    let weight = weight_of(points, &edges);
    Ok(Mwt {
        edges,
        triangles,
        weight,
        skeleton,
        stats,
    })
}

/// The total length of `edges`, certified. The same edges in the same order give the
/// same interval to the bit: fixed blocks are summed in parallel, then in order.
pub fn weight_of(points: &[Point2], edges: &[[u32; 2]]) -> Interval {
    let length = |e: &[u32; 2]| Interval::length(&points[e[0] as usize], &points[e[1] as usize]);
    let blocks: Vec<Interval> = edges
        .par_chunks(4096)
        .map(|b| b.iter().map(length).fold(Interval::ZERO, Interval::plus))
        .collect();
    blocks.into_iter().fold(Interval::ZERO, Interval::plus)
}

/// The counter-clockwise triangles of `edges` (sorted, distinct), after checking that
/// they triangulate the hull of `points` ([`certify`]).
pub(crate) fn certified_triangles(
    points: &[Point2],
    hull: &Hull2,
    edges: &[[u32; 2]],
) -> Result<Vec<[u32; 3]>, PlanarError> {
    let triangles = triangles_of(points, edges);
    certify(points, hull, edges, &triangles)?;
    Ok(triangles)
}

/// Checks that `triangles`, with edge set `edges`, triangulate the hull of `points`:
/// [`verify_triangulation`] and `3n - 3 - h` edges.
pub(crate) fn certify(
    points: &[Point2],
    hull: &Hull2,
    edges: &[[u32; 2]],
    triangles: &[[u32; 3]],
) -> Result<(), PlanarError> {
    let h = hull.on_boundary.iter().filter(|&&b| b).count();
    if !verify_triangulation(points, triangles).is_valid()
        || edges.len() != 3 * points.len() - 3 - h
    {
        return Err(PlanarError::internal(
            "the edges and triangles found form a triangulation",
            [],
        ));
    }
    Ok(())
}

fn collinear(points: &[Point2]) -> Mwt {
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    order.sort_by(|&a, &b| {
        points[a as usize]
            .partial_cmp(&points[b as usize])
            .expect("finite")
    });
    let mut edges: Vec<[u32; 2]> = order
        .windows(2)
        .map(|w| [w[0].min(w[1]), w[0].max(w[1])])
        .collect();
    edges.sort_unstable();
    let weight = weight_of(points, &edges);
    Mwt {
        skeleton: edges.clone(),
        edges,
        triangles: Vec::new(),
        weight,
        stats: MwtStats::default(),
    }
}

/// Every segment without a site on its open interior (`O(n² log n)`; small inputs).
fn all_segments(points: &[Point2]) -> Vec<[u32; 2]> {
    let blocked = super::forced::blocked_pairs(points);
    let n = points.len() as u32;
    (0..n)
        .flat_map(|a| (a + 1..n).map(move |b| [a, b]))
        .filter(|e| !blocked.contains(e))
        .collect()
}

/// Counter-clockwise triangles of a plane graph whose bounded faces are triangles.
fn triangles_of(points: &[Point2], edges: &[[u32; 2]]) -> Vec<[u32; 3]> {
    Rotation::new(points, edges).triangles(points)
}

/// A face to solve and the alive edges usable inside it, sorted (a list, not a set:
/// a 300 × 300 grid leaves 89,000 faces of two chords, whose sets took 20 MB; the
/// exact stage builds each face's set as it solves it).
type FaceProblem = (Face, Vec<[u32; 2]>);

/// Groups the alive edges by the face of the certain edges they lie in. The faces come
/// in a fixed order (by their first walk or lone site).
fn undecided_faces(
    points: &[Point2],
    certain: &[[u32; 2]],
    alive: &[[u32; 2]],
) -> Result<Vec<FaceProblem>, PlanarError> {
    let rot = Rotation::new(points, certain);
    let (walks, walk_of) = rot.walks();
    // Elements: the walks, then the sites (a site on no certain edge is a face's hole).
    let w = walks.len() as u32;
    let elems = w as usize + points.len();
    let elem = |v: u32, d: u32| rot.face_toward(points, &walk_of, v, d).unwrap_or(w + v);
    let ends: Vec<[u32; 2]> = (alive.par_iter())
        .map(|e| [elem(e[0], e[1]), elem(e[1], e[0])])
        .collect();
    let mut parent: Vec<u32> = (0..elems as u32).collect();
    for &[a, b] in &ends {
        let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
        parent[ra as usize] = ra.min(rb);
        parent[rb as usize] = ra.min(rb);
    }
    let root: Vec<u32> = (0..elems as u32).map(|x| find(&mut parent, x)).collect();
    // Alive edges and member elements, each grouped by root (the least element of a face).
    let mut chords: Vec<(u32, [u32; 2])> = (ends.par_iter().zip(alive))
        .map(|(ab, e)| (root[ab[0] as usize], *e))
        .collect();
    chords.par_sort_unstable();
    let mut with_chords = vec![false; elems];
    for c in &chords {
        with_chords[c.0 as usize] = true;
    }
    let mut members: Vec<(u32, u32)> = (0..elems as u32)
        .map(|x| (root[x as usize], x))
        .filter(|m| with_chords[m.0 as usize])
        .collect();
    members.par_sort_unstable();
    let groups: Vec<_> = chords
        .chunk_by(|a, b| a.0 == b.0)
        .zip(members.chunk_by(|a, b| a.0 == b.0))
        .collect();
    groups
        .into_par_iter()
        .map(|(chords, members)| {
            debug_assert_eq!(
                chords[0].0, members[0].0,
                "the same roots in the same order"
            );
            let face = face_of(points, &walks, w, members.iter().map(|m| m.1))?;
            Ok((face, chords.iter().map(|c| c.1).collect()))
        })
        .collect()
}

/// The face bounded by the walks and lone sites `members` (elements `w + v` are sites).
/// A face's one walk bounds it (alive edges lie in bounded faces); with several, the
/// outer one runs counter-clockwise and the holes clockwise or flat.
fn face_of(
    points: &[Point2],
    walks: &[Vec<u32>],
    w: u32,
    members: impl ExactSizeIterator<Item = u32>,
) -> Result<Face, PlanarError> {
    let alone = members.len() == 1;
    let mut outer = None;
    let mut holes = Vec::new();
    for x in members {
        if x >= w {
            holes.push(vec![x - w]);
        } else if alone || walk_area_sign(points, &walks[x as usize]) > 0 {
            if outer.replace(walks[x as usize].clone()).is_some() {
                return Err(PlanarError::internal("a face has one outer walk", []));
            }
        } else {
            holes.push(walks[x as usize].clone());
        }
    }
    let outer =
        outer.ok_or_else(|| PlanarError::internal("every undecided edge is inside a face", []))?;
    Ok(Face { outer, holes })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planar::{Distribution, points2d};

    /// The weight interval does not depend on how the work was split between threads.
    #[test]
    fn weight_is_the_same_on_any_number_of_threads() {
        let pts = points2d(Distribution::Uniform, 3000, 4);
        let mut rng = crate::rng::Rng::new(4);
        let edges: Vec<[u32; 2]> = (0..200_000)
            .map(|_| [rng.below(3000) as u32, rng.below(3000) as u32])
            .collect();
        let on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads);
            let w = pool.build().unwrap().install(|| weight_of(&pts, &edges));
            [w.lo.to_bits(), w.hi.to_bits()]
        };
        assert_eq!(on(1), on(3));
        assert_eq!(on(1), on(8));
    }

    /// Alive edges are grouped by the face of the certain edges they lie in: two faces
    /// split by a certain edge, one with a triangle and a lone site as holes, the other
    /// with a lone site; the unbounded face and faces without alive edges are not listed.
    #[test]
    fn undecided_edges_are_grouped_by_face() {
        let pts: Vec<Point2> = vec![
            [0.0, 0.0],
            [20.0, 0.0],
            [20.0, 10.0],
            [0.0, 10.0],
            [3.0, 3.0],
            [6.0, 3.0],
            [4.0, 6.0],
            [7.0, 7.0],
            [10.0, 0.0],
            [10.0, 10.0],
            [15.0, 5.0],
        ];
        let mut certain = vec![
            [0, 8],
            [1, 8],
            [1, 2],
            [2, 9],
            [3, 9],
            [0, 3],
            [8, 9],
            [4, 5],
            [5, 6],
            [4, 6],
        ];
        certain.sort_unstable();
        let alive = [[0, 4], [6, 7], [7, 9], [1, 10], [9, 10]];
        let mut faces: Vec<_> = undecided_faces(&pts, &certain, &alive)
            .unwrap()
            .into_iter()
            .map(|(f, chords)| {
                // Walks from their least site, holes and chords sorted.
                let least = |w: &[u32]| {
                    let i = (0..w.len()).min_by_key(|&i| w[i]).unwrap();
                    [&w[i..], &w[..i]].concat()
                };
                let mut holes: Vec<Vec<u32>> = f.holes.iter().map(|h| least(h)).collect();
                holes.sort();
                let mut chords: Vec<[u32; 2]> = chords.into_iter().collect();
                chords.sort_unstable();
                (least(&f.outer), holes, chords)
            })
            .collect();
        faces.sort();
        assert_eq!(
            faces,
            vec![
                (
                    vec![0, 8, 9, 3],
                    vec![vec![4, 6, 5], vec![7]],
                    vec![[0, 4], [6, 7], [7, 9]]
                ),
                (vec![1, 2, 9, 8], vec![vec![10]], vec![[1, 10], [9, 10]]),
            ]
        );
    }

    /// The solver works on sites in grid order; its answer must be in the caller's.
    #[test]
    fn answer_is_in_the_callers_site_order() {
        let pts = points2d(Distribution::Clustered, 400, 9);
        let m = mwt(&pts, &MwtOptions::default(), &Control::new()).unwrap();
        assert!(verify_triangulation(&pts, &m.triangles).is_valid());
        let mut from_triangles: Vec<[u32; 2]> = m
            .triangles
            .iter()
            .flat_map(|t| [0, 1, 2].map(|i| super::super::edge_key(t[i], t[(i + 1) % 3])))
            .collect();
        from_triangles.sort_unstable();
        from_triangles.dedup();
        assert_eq!(from_triangles, m.edges);
        assert!(m.skeleton.iter().all(|e| m.edges.binary_search(e).is_ok()));
        // Constraints named in the caller's indices: an edge forced (given reversed) is
        // in the answer, an interior edge forbidden is not.
        let few = &pts[..40];
        let m = mwt(few, &MwtOptions::default(), &Control::new()).unwrap();
        let sides = |e: &[u32; 2]| {
            let has = |t: &&[u32; 3]| t.contains(&e[0]) && t.contains(&e[1]);
            m.triangles.iter().filter(has).count()
        };
        let interior: Vec<[u32; 2]> = m.edges.iter().copied().filter(|e| sides(e) == 2).collect();
        let (forced, forbidden) = (interior[0], interior[interior.len() / 2]);
        let opts = MwtOptions {
            forced: vec![[forced[1], forced[0]]],
            forbidden: vec![forbidden],
        };
        let c = mwt(few, &opts, &Control::new()).unwrap();
        assert!(verify_triangulation(few, &c.triangles).is_valid());
        assert!(c.edges.contains(&forced) && !c.edges.contains(&forbidden));
        let bad = MwtOptions {
            forced: vec![[3, 3]],
            forbidden: vec![],
        };
        assert_eq!(
            mwt(&pts, &bad, &Control::new()).unwrap_err(),
            PlanarError::BadConstraint {
                edge: [3, 3],
                sites: 400
            }
        );
    }

    /// The stages reach the control's progress callback in order.
    #[test]
    fn stages_are_reported_in_order() {
        use crate::control::Progress;
        use std::sync::{Arc, Mutex};
        let seen = Arc::new(Mutex::new(Vec::new()));
        let log = Arc::clone(&seen);
        let ctl = Control::new().with_progress(move |p| log.lock().unwrap().push(p));
        let pts = points2d(Distribution::Uniform, 300, 8);
        mwt(&pts, &MwtOptions::default(), &ctl).unwrap();
        let want = [
            mwt_stage::CANDIDATES,
            mwt_stage::SKELETON,
            mwt_stage::FACES,
            mwt_stage::CERTIFY,
        ]
        .map(Progress::Stage);
        assert_eq!(*seen.lock().unwrap(), want);
    }

    /// A stopped control ends each stage: the candidate search, the polygon DP (between
    /// spans), the search over a face, and the whole solver; a passed deadline stops it
    /// the same way.
    #[test]
    fn a_stopped_control_ends_every_stage() {
        let stopped = Control::new();
        stopped.stop();
        let go = Control::new();
        let ring = points2d(Distribution::Convex, 60, 2);
        let walk: Vec<u32> = Hull2::new(&ring).vertices.clone();
        assert_eq!(walk.len(), 60);
        assert!(polygon_dp(&ring, &walk, &[], &|_| true, &go).is_some());
        assert!(polygon_dp(&ring, &walk, &[], &|_| true, &stopped).is_none());
        let face = Face {
            outer: walk.clone(),
            holes: Vec::new(),
        };
        let chords: std::collections::HashSet<[u32; 2]> = (0..60u32)
            .flat_map(|a| (a + 1..60).map(move |b| super::super::edge_key(a, b)))
            .collect();
        assert!(faces::solve(&ring, &face, &chords, &go).is_some());
        assert!(faces::solve(&ring, &face, &chords, &stopped).is_none());
        // A face with an isolated site goes to the region DP, which looks as well.
        let mut with_site = ring.clone();
        let c = ring
            .iter()
            .fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
        with_site.push([c[0] / 60.0, c[1] / 60.0]);
        let region = |ctl: &Control| {
            let none = std::collections::HashSet::new();
            sites::walk_with_sites(&with_site, &walk, &[60], &none, &[], &|_| true, ctl)
        };
        assert!(region(&go).is_some());
        assert!(region(&stopped).is_none());
        let pts = points2d(Distribution::Uniform, 500, 5);
        assert!(candidates::search(&pts, usize::MAX, &stopped).is_none());
        let past = Control::new().with_deadline(std::time::Instant::now());
        for set in [&ring, &pts] {
            for ctl in [&stopped, &past] {
                let err = mwt(set, &MwtOptions::default(), ctl).unwrap_err();
                assert_eq!(err, PlanarError::Stopped(Stopped));
            }
        }
    }

    /// Every face the exact stage solves gets `Face::interior_edges` edges from it (faces
    /// with holes of every shape: `faces::tests::solve_face`).
    #[test]
    fn faces_take_the_interior_edge_count() {
        let mut faces = 0;
        for seed in 0..30 {
            let dist = [
                Distribution::Clustered,
                Distribution::Uniform,
                Distribution::Grid,
            ];
            let pts = points2d(dist[seed as usize % 3], 100 + 30 * seed as usize, seed);
            let hull = Hull2::new(&pts);
            let go = Control::new();
            let cands = candidates::search(&pts, usize::MAX, &go).unwrap();
            let (sk, _) = lmt::lmt_skeleton(&pts, &hull, cands, &[], &[], &go).unwrap();
            let (certain, alive) = (sk.with_status(CERTAIN), sk.with_status(ALIVE));
            for (face, chords) in undecided_faces(&pts, &certain, &alive).unwrap() {
                let usable = chords.iter().copied().collect();
                let s = faces::solve(&pts, &face, &usable, &go).unwrap();
                assert_eq!(s.edges.len(), face.interior_edges(), "seed {seed}");
                faces += 1;
            }
        }
        assert!(faces > 1000, "{faces} faces");
    }

    /// Stopped as the LMT-skeleton or the exact stage starts, the solver's lower bound is
    /// at most the minimum weight and at least the spanning tree's, and from the exact
    /// stage on, far above it; stopped by deadlines anywhere, every bound is sound.
    #[test]
    fn the_lower_bound_from_the_solvers_state_is_sound_and_close() {
        use crate::control::Progress;
        let stop_at = |stage: &'static str| {
            let flag = Control::new();
            let ctl = flag.clone();
            ctl.with_progress(move |p| {
                if p == Progress::Stage(stage) {
                    flag.stop();
                }
            })
        };
        let (mut state, mut ratios) = (0, Vec::new());
        for seed in 0..24 {
            let dist = [
                Distribution::Uniform,
                Distribution::Clustered,
                Distribution::Gaussian,
            ];
            let pts = points2d(dist[seed as usize % 3], 60 + 40 * seed as usize, seed);
            let opt = mwt(&pts, &MwtOptions::default(), &Control::new())
                .unwrap()
                .weight;
            let mst = mwt_bounds(&pts).unwrap().lower.lo;
            for stage in [mwt_stage::SKELETON, mwt_stage::FACES] {
                let MwtOutcome::Stopped(b) = mwt_or_bounds(&pts, &stop_at(stage)).unwrap() else {
                    panic!("stopped at {stage}, it solved");
                };
                assert!(
                    b.lower.lo <= opt.hi,
                    "seed {seed} {stage}: {} > {}",
                    b.lower.lo,
                    opt.hi
                );
                assert!(b.lower.lo >= mst && opt.lo <= b.upper.hi);
                if b.lower_source == LowerBound::SolverState {
                    state += 1;
                }
                if stage == mwt_stage::FACES {
                    ratios.push(b.lower.lo / opt.lo);
                }
            }
        }
        assert!(state >= 24, "the solver's bound won only {state} times");
        ratios.sort_by(f64::total_cmp);
        // Measured: 0.75 at worst (clustered sets, whose open faces are long), 0.97 median.
        assert!(
            ratios[0] > 0.7,
            "worst bound {:.3} of the optimum",
            ratios[0]
        );
        assert!(
            ratios[ratios.len() / 2] > 0.95,
            "median bound {:.3}",
            ratios[ratios.len() / 2]
        );
        let pts = points2d(Distribution::Clustered, 20_000, 3);
        let opt = mwt(&pts, &MwtOptions::default(), &Control::new())
            .unwrap()
            .weight;
        for ms in [5, 20, 50, 100, 200, 400, 800] {
            let ctl = Control::new().with_time_limit(std::time::Duration::from_millis(ms));
            if let MwtOutcome::Stopped(b) = mwt_or_bounds(&pts, &ctl).unwrap() {
                assert!(b.lower.lo <= opt.hi && opt.lo <= b.upper.hi, "{ms} ms");
            }
        }
    }

    /// The memory guards refuse before allocating: the candidate search stops past its
    /// limit, the constrained path (every segment a candidate) checks `n²/2`, and the
    /// polygon DP checks `m²`.
    #[test]
    fn memory_guards_refuse_before_allocating() {
        let pts = points2d(Distribution::Uniform, 300, 3);
        let go = Control::new();
        let all = candidates::search(&pts, usize::MAX, &go).unwrap();
        assert!(candidates::search(&pts, all.len(), &go).is_some());
        assert!(candidates::search(&pts, all.len() / 2, &go).is_none());

        let n = 23_200; // n (n - 1) / 2 just over MAX_CANDIDATES
        assert!(n * (n - 1) / 2 > MAX_CANDIDATES && 23_100 * 23_099 / 2 <= MAX_CANDIDATES);
        let pts = points2d(Distribution::Uniform, n, 4);
        let hull = Hull2::new(&pts);
        let opts = MwtOptions {
            forced: vec![[hull.vertices[0], hull.vertices[1]]],
            forbidden: Vec::new(),
        };
        let err = mwt(&pts, &opts, &Control::new()).unwrap_err();
        assert!(
            matches!(err, PlanarError::TooManyCandidates { sites, .. } if sites == n),
            "{err}"
        );

        assert!(dp_fits(32_000, false).is_ok());
        let err = dp_fits(33_000, false).unwrap_err();
        assert!(
            matches!(err, PlanarError::DynamicProgramTooLarge { vertices: 33_000, convex_position: false, memory, .. } if memory == 16 << 30),
            "{err}"
        );
        assert!(err.to_string().contains("16 GB"), "{err}");
    }
}
