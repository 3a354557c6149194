//! Deciding whether a set of segments is exactly the edge set of a tetrahedralization
//! (thesis ch. 2 §2.3–2.4, algorithm TETRAHEDRALIZATION-DETECTION; Theorems 2.2, 2.6, 2.7),
//! and, for planar input, of a triangulation (Theorems 2.4–2.5).
//!
//! The steps, for segments `L` on points `V`:
//! 1. the graph `(V, L)` must be connected and use every point;
//! 2. (Step 1) consecutive points along every edge of the convex hull must be joined;
//! 3. (Steps 2–3) for every vertex `v`, in parallel, the puncture-free link of `v` is
//!    computed and checked to be a triangulated disk (hull vertices) or sphere (interior
//!    vertices) — see [`link`](self) for the generalized puncture rule that makes this
//!    exact without the general-position assumption;
//! 4. (Step 4) every tetrahedron must be found from all four of its vertices;
//! 5. the tetrahedra are certified by [`crate::mesh::verify`] and `edges(T) = L` is checked.
//!
//! Before these steps, a cheap proposal is tried ([`Route::Delaunay`]): when `L` is the
//! edge set of a Delaunay tetrahedralization, its tetrahedra are found from the graph once
//! each (see `delaunay.rs`) and certified by step 5 alone (a tetrahedralization passes
//! steps 1–4 anyway). When the proposal is withdrawn or fails step 5, steps 1–5 decide as
//! above; a NO always comes from them.
//!
//! Work is output-sensitive: `L_v` is listed from the adjacency lists of `v`'s neighbours
//! (galloping intersections, never a scan of all of `L`), and the link is freed of
//! punctured segments by the thesis's sphere sweep with `O(|L_v| log |L_v|)` exact
//! predicates. Memory is linear in `|L|` plus the link triangles.
//!
//! A NO always carries a [`Witness`]. Each check above is *complete* (it never rejects the
//! edge set of a tetrahedralization), so a failed check is a correct NO; crossing segments
//! and vertices inside segments are reported as such whenever they are met.

mod coplanar;
mod delaunay;
mod graph;
mod link;
pub mod oracle;
mod rotation;
mod witness;

pub use graph::{Graph, SegmentError};
pub use link::LinkMethod;
pub use witness::{Witness, WitnessKind};

use crate::control::{Control, Stopped, Verdict};
use crate::geom::{Hull3, Point3};
use crate::mesh;
use crate::numbering::{Renumbering, ids};
use link::Ctx;
use rayon::prelude::*;

/// The cells of a YES answer.
#[derive(Clone, Debug, PartialEq)]
pub enum Cells {
    /// Positively oriented tetrahedra (3D input).
    Tetrahedra(Vec<[u32; 4]>),
    /// Counter-clockwise triangles in the plane of the points (planar input).
    Triangles(Vec<[u32; 3]>),
}

/// The answer of [`detect`].
#[derive(Clone, Debug)]
pub struct Detection {
    /// Number of points.
    pub vertices: usize,
    /// Number of segments.
    pub segments: usize,
    /// Points on the boundary of the convex hull.
    pub hull_vertices: usize,
    /// Affine dimension of the points (3 for tetrahedralizations, 2 for triangulations).
    pub dimension: usize,
    /// The cells (YES), why not (NO), or nothing (stopped first).
    pub answer: Answer,
    /// Which procedure gave the answer.
    pub route: Route,
}

/// Which procedure answered. Both end in the same certificate check, so the verdict never
/// depends on it; only the work does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Route {
    /// The Delaunay tetrahedra of the graph, proposed once each and certified by
    /// [`crate::mesh::verify`] plus `edges(T) = L` (YES only).
    Delaunay,
    /// The thesis's per-vertex links (§2.4), every tetrahedron confirmed from its four
    /// vertices, then certified the same way (YES and NO).
    Links,
}

/// What [`detect`] tries. The verdict never depends on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Options {
    /// Try the Delaunay proposal ([`Route::Delaunay`]) before the thesis's algorithm.
    pub delaunay_first: bool,
    /// How the thesis's algorithm computes links.
    pub links: LinkMethod,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            delaunay_first: true,
            links: LinkMethod::Sweep,
        }
    }
}

/// A decision about cells: the cells (YES), a witness (NO), or nothing when the control
/// stopped it first. [`crate::constrain`] answers with the same type over its own kinds
/// of witness.
#[derive(Clone, Debug, PartialEq)]
pub enum Answer<K = WitnessKind> {
    /// The cells (tetrahedra, or triangles for planar input), certified.
    Yes(Cells),
    /// No; the witness says why.
    No(crate::witness::Witness<K>),
    /// The control stopped the work first.
    Undecided,
}

impl<K> Answer<K> {
    /// `yes`, `no` or `undecided`.
    pub fn verdict(&self) -> Verdict {
        match self {
            Answer::Yes(_) => Verdict::Yes,
            Answer::No(_) => Verdict::No,
            Answer::Undecided => Verdict::Undecided,
        }
    }

    /// The cells of a YES.
    pub fn cells(&self) -> Option<&Cells> {
        match self {
            Answer::Yes(c) => Some(c),
            _ => None,
        }
    }

    /// The witness of a NO.
    pub fn witness(&self) -> Option<&crate::witness::Witness<K>> {
        match self {
            Answer::No(w) => Some(w),
            _ => None,
        }
    }

    /// The answer from a route's result: `Ok` cells or `Err` witness.
    fn of(r: Result<Cells, crate::witness::Witness<K>>) -> Self {
        match r {
            Ok(c) => Answer::Yes(c),
            Err(w) => Answer::No(w),
        }
    }
}

impl Detection {
    /// True for a YES.
    pub fn is_yes(&self) -> bool {
        matches!(self.answer, Answer::Yes(_))
    }

    /// `yes`, `no` or `undecided`.
    pub fn verdict(&self) -> Verdict {
        self.answer.verdict()
    }
}

/// Decides whether `segments` is exactly the edge set of a tetrahedralization of `points`
/// (or, when the points are coplanar, of a triangulation). Fails only on malformed
/// segments (index out of range, self-loop, repeated segment); stopped by `ctl`, the
/// answer is [`Answer::Undecided`] with the counts known by then.
/// All [`Options`] give the same verdict; they differ only in work. Progress: the stage
/// `"vertex links"` and its vertices done, when the thesis's per-vertex algorithm runs.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::detect::{Options, WitnessKind, detect};
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let all = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
/// let (opts, ctl) = (Options::default(), Control::new());
/// assert!(detect(&pts, &all, &opts, &ctl).unwrap().is_yes());
/// let no = detect(&pts, &all[..5], &opts, &ctl).unwrap();
/// assert_eq!(no.answer.witness().unwrap().kind, WitnessKind::MissingHullEdge);
/// ```
///
/// The thesis's per-vertex route alone, with the sign-table link method:
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::detect::{LinkMethod, Options, Route, detect};
/// let t = tetrakit::generate::skew_lines(12);
/// let links_only = Options { delaunay_first: false, links: LinkMethod::SignTable };
/// let d = detect(&t.points, &t.edges(), &links_only, &Control::new()).unwrap();
/// assert!(d.is_yes() && d.route == Route::Links);
/// ```
pub fn detect(
    points: &[Point3],
    segments: &[[u32; 2]],
    opts: &Options,
    ctl: &Control,
) -> Result<Detection, SegmentError> {
    let n = points.len();
    if let Some(k) = segments
        .par_iter()
        .position_first(|&[a, b]| a as usize >= n || b as usize >= n || a == b)
    {
        // Name malformed segments in the caller's numbering.
        Graph::new(n, &[segments[k]])?;
    }
    // Work in a space-filling-curve order: neighbours then sit close in memory.
    let renumber = Renumbering::from_order(spatial_order(points));
    let pts = renumber.reorder(points);
    let segs: Vec<[u32; 2]> = segments
        .par_iter()
        .map(|s| s.map(|v| renumber.new_of(v)))
        .collect();
    // Only a repeated segment can be refused here (the others were checked above): name
    // it in the caller's numbering.
    let mut d = detect_ordered(&pts, &segs, opts, ctl).map_err(|e| match e {
        SegmentError::Repeated { ends: [a, b] } => {
            let (a, b) = (renumber.old(a), renumber.old(b));
            SegmentError::Repeated {
                ends: [a.min(b), a.max(b)],
            }
        }
        other => other,
    })?;
    d.answer = match d.answer {
        Answer::Yes(Cells::Tetrahedra(t)) => Answer::Yes(Cells::Tetrahedra(renumber.to_old(&t))),
        Answer::Yes(Cells::Triangles(t)) => Answer::Yes(Cells::Triangles(renumber.to_old(&t))),
        Answer::No(w) => Answer::No(w.mapped(|v| renumber.old(v))),
        Answer::Undecided => Answer::Undecided,
    };
    Ok(d)
}

/// Point indices sorted along a Morton (Z-order) curve of the bounding box (a heuristic
/// for memory locality only; no decision depends on it).
fn spatial_order(points: &[Point3]) -> Vec<u32> {
    let (lo, hi) = crate::geom::bounding_box(points);
    let spread = |k: usize| if hi[k] > lo[k] { hi[k] - lo[k] } else { 1.0 };
    let scale: [f64; 3] = std::array::from_fn(|k| ((1u64 << 21) - 1) as f64 / spread(k));
    fn spread_bits(x: u64) -> u64 {
        let mut x = x & 0x1f_ffff;
        x = (x | (x << 32)) & 0x1f_0000_0000_ffff;
        x = (x | (x << 16)) & 0x1f_0000_ff00_00ff;
        x = (x | (x << 8)) & 0x100f_00f0_0f00_f00f;
        x = (x | (x << 4)) & 0x10c3_0c30_c30c_30c3;
        (x | (x << 2)) & 0x1249_2492_4924_9249
    }
    let mut keyed: Vec<(u64, u32)> = points
        .par_iter()
        .enumerate()
        .map(|(i, p)| {
            let q: [u64; 3] = std::array::from_fn(|k| ((p[k] - lo[k]) * scale[k]) as u64);
            (
                spread_bits(q[0]) | (spread_bits(q[1]) << 1) | (spread_bits(q[2]) << 2),
                i as u32,
            )
        })
        .collect();
    keyed.par_sort_unstable();
    keyed.into_iter().map(|(_, i)| i).collect()
}

fn detect_ordered(
    points: &[Point3],
    segs: &[[u32; 2]],
    opts: &Options,
    ctl: &Control,
) -> Result<Detection, SegmentError> {
    let mut phases = Phases::new();
    let g = Graph::new(points.len(), segs)?;
    phases.mark("graph");
    let hull = Hull3::new(points);
    phases.mark("hull");
    let mut out = Detection {
        vertices: points.len(),
        segments: segs.len(),
        hull_vertices: 0,
        dimension: hull.dimension,
        answer: Answer::Undecided,
        route: Route::Links,
    };
    if hull.dimension == 2 {
        let (hv, result) = coplanar::detect(points, &g);
        out.hull_vertices = hv;
        out.answer = Answer::of(result);
        return Ok(out);
    }
    if hull.dimension < 2 {
        out.hull_vertices = points.len();
        out.answer = Answer::No(Witness::new(
            WitnessKind::Degenerate,
            vec![],
            vec![],
            format!(
                "all {} points lie on one line: they span no triangle or tetrahedron",
                points.len()
            ),
        ));
        return Ok(out);
    }
    out.hull_vertices = (0..points.len()).filter(|&i| hull.on_boundary(i)).count();
    if let Ok((route, result)) = detect3(points, &g, &hull, out.hull_vertices, opts, ctl) {
        (out.route, out.answer) = (route, Answer::of(result));
    }
    Ok(out)
}

/// Prints the time of each phase on stderr when `TETRAKIT_PHASES` is set.
struct Phases(Option<std::time::Instant>);

impl Phases {
    fn new() -> Self {
        Phases(std::env::var_os("TETRAKIT_PHASES").map(|_| std::time::Instant::now()))
    }
    fn mark(&mut self, name: &str) {
        if let Some(t) = self.0 {
            eprintln!("phase {name}: {:.3} s", t.elapsed().as_secs_f64());
            self.0 = Some(std::time::Instant::now());
        }
    }
}

fn detect3(
    points: &[Point3],
    g: &Graph,
    hull: &Hull3,
    hull_vertices: usize,
    opts: &Options,
    ctl: &Control,
) -> Result<(Route, Result<Cells, Witness>), Stopped> {
    let mut phases = Phases::new();
    if opts.delaunay_first {
        let proposed = delaunay::propose(points, g);
        phases.mark("delaunay proposal");
        // Euler's count (Theorem 2.3, condition 3) holds for every tetrahedralization:
        // a proposal that misses it is not worth certifying.
        let euler = (g.edge_count() + 3).checked_sub(points.len() + hull_vertices);
        if let Some(tets) = proposed
            && euler == Some(tets.len())
            && certify(points, g, hull, &tets).is_ok()
        {
            phases.mark("verify");
            return Ok((Route::Delaunay, Ok(Cells::Tetrahedra(tets))));
        }
        phases.mark("verify");
        ctl.check()?;
    }
    Ok((Route::Links, links_route(points, g, hull, opts.links, ctl)?))
}

/// `T` is a tetrahedralization of the hull of the points ([`mesh::verify`]) and
/// `edges(T) = L`.
fn certify(points: &[Point3], g: &Graph, hull: &Hull3, tets: &[[u32; 4]]) -> Result<(), Witness> {
    let report = mesh::verify(points, tets, Some(hull));
    if let Some(p) = report.problems.first() {
        return Err(Witness::new(
            WitnessKind::Inconsistent,
            p.vertices.clone(),
            vec![],
            format!("the tetrahedra found fail verification: {}", p.detail),
        ));
    }
    edges_are_segments(tets, g)
}

/// Steps 1–5: connectivity, hull edges, the thesis's per-vertex links, confirmation,
/// certificate.
fn links_route(
    points: &[Point3],
    g: &Graph,
    hull: &Hull3,
    method: LinkMethod,
    ctl: &Control,
) -> Result<Result<Cells, Witness>, Stopped> {
    let mut phases = Phases::new();
    if let Err(w) =
        connectivity(g).and_then(|_| rotation::check_chains(hull.polytope_edges(points), g))
    {
        return Ok(Err(w));
    }
    ctl.stage("vertex links");
    phases.mark("connectivity and hull edges");
    let counter = std::sync::atomic::AtomicU64::new(0);
    let ctx = Ctx {
        pts: points,
        g,
        hull,
        method,
    };
    let n = points.len();
    // Each rayon piece is a run of consecutive vertices whose link triangles go to one flat
    // buffer (no allocation per vertex); the first best-ranked witness is kept.
    let pieces: Vec<(LinkChunk, Option<(u32, Witness)>)> = (0..n as u32)
        .into_par_iter()
        .with_min_len(16)
        .fold(
            || {
                (
                    LinkChunk {
                        first: u32::MAX,
                        start: vec![0],
                        faces: Vec::new(),
                    },
                    None,
                )
            },
            |(mut chunk, mut worst): (LinkChunk, Option<(u32, Witness)>), v| {
                let done = counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                if done.is_multiple_of(8192) || done == n as u64 {
                    ctl.items(done, n as u64);
                }
                if ctl.is_stopped() {
                    return (chunk, worst);
                }
                if chunk.first == u32::MAX {
                    chunk.first = v;
                }
                let before = chunk.faces.len();
                if let Err(w) = link::link_into(&ctx, v, &mut chunk.faces) {
                    chunk.faces.truncate(before);
                    if worst.as_ref().is_none_or(|(_, b)| w.rank() < b.rank()) {
                        worst = Some((v, w));
                    }
                }
                chunk.start.push(chunk.faces.len() as u32);
                (chunk, worst)
            },
        )
        .collect();
    ctl.check()?;
    let witness = pieces
        .iter()
        .filter_map(|(_, w)| w.as_ref())
        .min_by_key(|(v, w)| (w.rank(), *v))
        .map(|(_, w)| w.clone());
    if let Some(w) = witness {
        return Ok(Err(sharpen(points, g, w)));
    }
    let mut links = Links::new(
        pieces
            .into_iter()
            .map(|(c, _)| c)
            .filter(|c| c.first != u32::MAX)
            .collect(),
    );
    phases.mark("links");
    let tets = match confirm(&mut links) {
        Ok(t) => t,
        Err(w) => return Ok(Err(sharpen(points, g, w))),
    };
    phases.mark("confirm");
    let certified = certify(points, g, hull, &tets);
    phases.mark("verify");
    Ok(certified.map(|_| Cells::Tetrahedra(tets)))
}

/// Replaces a witness that rests on a failed check by two crossing segments or a vertex
/// inside a segment near the vertices it names, when there are any: those a person can
/// check directly.
fn sharpen(points: &[Point3], g: &Graph, w: Witness) -> Witness {
    if w.rank() == 0 {
        return w;
    }
    match rotation::local_crossing(points, g, &w.vertices) {
        Some(mut better) => {
            better.detail =
                format!("{} (found where {}: {})", better.detail, w.kind, w.detail).into();
            better
        }
        None => w,
    }
}

/// `edges(T) = L`: every edge of a tetrahedron is a segment, and every segment is used.
/// In parallel; the witness is the first in tetrahedron (then vertex) order.
fn edges_are_segments(tets: &[[u32; 4]], g: &Graph) -> Result<(), Witness> {
    use std::sync::atomic::{AtomicBool, Ordering::Relaxed};
    let used: Vec<AtomicBool> = (0..2 * g.edge_count())
        .map(|_| AtomicBool::new(false))
        .collect();
    let stray = tets.par_iter().find_map_first(|t| {
        for (i, j) in [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)] {
            let (x, y) = (t[i].min(t[j]), t[i].max(t[j]));
            match g.slot(x, y) {
                Some(slot) => used[slot].store(true, Relaxed),
                None => return Some([x, y]),
            }
        }
        None
    });
    if let Some([x, y]) = stray {
        return Err(Witness::new(
            WitnessKind::Inconsistent,
            vec![x, y],
            vec![],
            format!("a tetrahedron found has edge (#{x}, #{y}), which is not a segment"),
        ));
    }
    let unused = (0..g.len() as u32).into_par_iter().find_map_first(|x| {
        g.slots(x)
            .zip(g.nbrs(x))
            .find(|&(slot, &y)| y > x && !used[slot].load(Relaxed))
            .map(|(_, &y)| [x, y])
    });
    match unused {
        Some([x, y]) => Err(Witness::new(
            WitnessKind::Inconsistent,
            vec![x, y],
            vec![[x, y]],
            format!("segment (#{x}, #{y}) is an edge of no tetrahedron found"),
        )),
        None => Ok(()),
    }
}

/// Step 0: a tetrahedralization's graph is connected and uses every point.
fn connectivity(g: &Graph) -> Result<(), Witness> {
    let comp = g.components();
    let Some(v) = comp.iter().position(|&c| c != 0) else {
        return Ok(());
    };
    let size = comp.iter().filter(|&&c| c == comp[v]).count();
    let detail = if g.nbrs(v as u32).is_empty() {
        format!("point #{v} is on no segment")
    } else {
        format!("the {size} points of the component of vertex #{v} are not connected to vertex #0")
    };
    Err(Witness::new(
        WitnessKind::Disconnected,
        vec![0, v as u32],
        vec![],
        detail,
    ))
}

/// The link triangles of consecutive runs of vertices, one flat buffer per run.
struct LinkChunk {
    first: u32,
    start: Vec<u32>,
    faces: Vec<[u32; 3]>,
}

/// The link triangles of every vertex, in runs.
struct Links {
    chunks: Vec<LinkChunk>,
    /// The run holding each vertex.
    chunk_of: Vec<u32>,
}

impl Links {
    /// The runs, in order of their first vertex, covering `0..n` without gaps.
    fn new(chunks: Vec<LinkChunk>) -> Self {
        let mut chunk_of = Vec::new();
        for (i, c) in chunks.iter().enumerate() {
            chunk_of.resize(chunk_of.len() + c.start.len() - 1, i as u32);
        }
        Links { chunks, chunk_of }
    }

    fn of(&self, v: u32) -> &[[u32; 3]] {
        let c = &self.chunks[self.chunk_of[v as usize] as usize];
        let i = (v - c.first) as usize;
        &c.faces[c.start[i] as usize..c.start[i + 1] as usize]
    }

    /// Every vertex with its link triangles.
    fn iter(&self) -> impl Iterator<Item = (u32, &[[u32; 3]])> {
        self.chunks.iter().flat_map(|c| {
            c.start
                .windows(2)
                .enumerate()
                .map(move |(i, w)| (c.first + i as u32, &c.faces[w[0] as usize..w[1] as usize]))
        })
    }
}

/// Step 4: keep each tetrahedron found from its smallest vertex and confirm it from the
/// other three; every link triangle must be accounted for. Sorts each link in place.
fn confirm(links: &mut Links) -> Result<Vec<[u32; 4]>, Witness> {
    let tets: Vec<[u32; 4]> = links
        .chunks
        .par_iter()
        .flat_map_iter(|c| {
            c.start.windows(2).enumerate().flat_map(move |(i, w)| {
                let v = c.first + i as u32;
                c.faces[w[0] as usize..w[1] as usize]
                    .iter()
                    .filter(move |f| f.iter().all(|&x| x > v))
                    .map(move |f| [v, f[0], f[1], f[2]])
            })
        })
        .collect();
    let total: usize = links.chunks.iter().map(|c| c.faces.len()).sum();
    links.chunks.par_iter_mut().for_each(|c| {
        for w in c.start.windows(2) {
            let fs = &mut c.faces[w[0] as usize..w[1] as usize];
            fs.iter_mut()
                .for_each(|f| *f = crate::mesh::sorted_face(*f));
            fs.sort_unstable();
        }
    });
    let links: &Links = links;
    let found = |u: u32, f: [u32; 3]| {
        links
            .of(u)
            .binary_search(&crate::mesh::sorted_face(f))
            .is_ok()
    };
    let unconfirmed = tets
        .par_iter()
        .find_any(|t| (1..4).any(|i| !found(t[i], opposite(t, i))));
    if let Some(t) = unconfirmed {
        return Err(unconfirmed_witness(*t, &found));
    }
    if total != 4 * tets.len() {
        // Some link triangle's tetrahedron was not found from its smallest vertex.
        for (u, fs) in links.iter() {
            for f in fs {
                let mut t = [u, f[0], f[1], f[2]];
                t.sort_unstable();
                if t[0] != u && !found(t[0], [t[1], t[2], t[3]]) {
                    return Err(unconfirmed_witness(t, &found));
                }
            }
        }
    }
    Ok(tets)
}

/// The face of `t` opposite its `i`-th vertex.
fn opposite(t: &[u32; 4], i: usize) -> [u32; 3] {
    std::array::from_fn(|j| t[if j < i { j } else { j + 1 }])
}

fn unconfirmed_witness(t: [u32; 4], found: &dyn Fn(u32, [u32; 3]) -> bool) -> Witness {
    let from: Vec<u32> = (0..4)
        .filter(|&i| found(t[i], opposite(&t, i)))
        .map(|i| t[i])
        .collect();
    let mut s = t;
    s.sort_unstable();
    Witness::new(
        WitnessKind::UnconfirmedTetrahedron,
        s.to_vec(),
        vec![],
        format!(
            "tetrahedron {} is found from the links of {} of its vertices ({}), not all four",
            ids(&s),
            from.len(),
            ids(&from)
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Progress reaches the control: the stage, then every vertex done.
    #[test]
    fn progress_reports_the_links_stage() {
        use crate::control::Progress;
        use std::sync::{Arc, Mutex};
        let t = crate::generate::kuhn(2);
        let seen = Arc::new(Mutex::new(Vec::new()));
        let log = Arc::clone(&seen);
        let ctl = Control::new().with_progress(move |p| log.lock().unwrap().push(p));
        let links = Options {
            delaunay_first: false,
            ..Options::default()
        };
        assert!(
            detect(&t.points, &t.edges(), &links, &ctl)
                .unwrap()
                .is_yes()
        );
        let seen = seen.lock().unwrap();
        assert_eq!(seen[0], Progress::Stage("vertex links"));
        assert_eq!(
            seen.last(),
            Some(&Progress::Items {
                done: 27,
                total: 27
            })
        );
    }

    /// A repeated segment is named in the caller's numbering.
    #[test]
    fn a_repeated_segment_is_named() {
        let t = crate::generate::kuhn(2);
        let mut e = t.edges();
        e.push([e[5][1], e[5][0]]);
        let err = detect(&t.points, &e, &Options::default(), &Control::new()).unwrap_err();
        let [a, b] = e[5];
        let want = SegmentError::Repeated {
            ends: [a.min(b), a.max(b)],
        };
        assert_eq!(err, want);
    }

    /// A stopped control leaves both routes undecided; a live one answers.
    #[test]
    fn a_stopped_control_ends_detection() {
        let t = crate::generate::kuhn(3);
        let e = t.edges();
        let stopped = Control::new();
        stopped.stop();
        for delaunay_first in [true, false] {
            for links in [LinkMethod::Sweep, LinkMethod::SignTable] {
                let opts = Options {
                    delaunay_first,
                    links,
                };
                assert!(
                    detect(&t.points, &e, &opts, &Control::new())
                        .unwrap()
                        .is_yes()
                );
                let d = detect(&t.points, &e, &opts, &stopped).unwrap();
                assert_eq!(d.answer, Answer::Undecided);
                assert_eq!((d.verdict(), d.vertices), (Verdict::Undecided, 64));
            }
        }
    }

    /// `edges(T) = L` names a tetrahedron edge that is no segment, and a segment that is
    /// no tetrahedron edge.
    #[test]
    fn edges_must_equal_the_segments() {
        let tet = [[0, 1, 2, 3]];
        let six = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
        assert!(edges_are_segments(&tet, &Graph::new(5, &six).unwrap()).is_ok());
        let mut extra = six.to_vec();
        extra.push([2, 4]);
        let w = edges_are_segments(&tet, &Graph::new(5, &extra).unwrap()).unwrap_err();
        assert_eq!(
            (w.kind, w.segments.clone()),
            (WitnessKind::Inconsistent, vec![[2, 4]])
        );
        let w = edges_are_segments(&tet, &Graph::new(5, &six[1..]).unwrap()).unwrap_err();
        assert_eq!(
            (w.kind, w.vertices.clone()),
            (WitnessKind::Inconsistent, vec![0, 1])
        );
    }

    /// Step 4 on synthetic links: a tetrahedron missing from one vertex's link is reported
    /// with the vertices it was found from.
    #[test]
    fn confirmation_names_the_missing_vertex() {
        // Positive tetrahedron (0,1,2,3): link triangles oriented so (v, face) is positive.
        let links = |per: Vec<Vec<[u32; 3]>>| {
            let mut start = vec![0u32];
            let mut faces = Vec::new();
            for fs in per {
                faces.extend(fs);
                start.push(faces.len() as u32);
            }
            Links::new(vec![LinkChunk {
                first: 0,
                start,
                faces,
            }])
        };
        let full = vec![
            vec![[1, 2, 3]],
            vec![[0, 3, 2]],
            vec![[0, 1, 3]],
            vec![[0, 2, 1]],
        ];
        assert_eq!(
            confirm(&mut links(full.clone())).unwrap(),
            vec![[0, 1, 2, 3]]
        );
        let mut missing = full.clone();
        missing[3].clear();
        let w = confirm(&mut links(missing)).unwrap_err();
        assert_eq!(w.kind, WitnessKind::UnconfirmedTetrahedron);
        assert_eq!(w.vertices, vec![0, 1, 2, 3]);
        assert!(w.detail.contains("3 of its vertices"), "{}", w.detail);
        // Found from a vertex other than its smallest only.
        let stray = vec![vec![], vec![[0, 3, 2]], vec![], vec![]];
        let w = confirm(&mut links(stray)).unwrap_err();
        assert_eq!(w.kind, WitnessKind::UnconfirmedTetrahedron);
        assert!(w.detail.contains("1 of its vertices"), "{}", w.detail);
    }

    #[test]
    fn disconnected_and_isolated_points() {
        let mut pts = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let tet = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
        pts.push([0.2, 0.2, 0.2]);
        let w = detect(&pts, &tet, &Options::default(), &Control::new())
            .unwrap()
            .answer
            .witness()
            .cloned()
            .unwrap();
        assert_eq!(w.kind, WitnessKind::Disconnected);
        assert!(w.detail.contains("#4 is on no segment"), "{}", w.detail);
        // Two tetrahedra, far apart, not joined.
        let mut two = pts[..4].to_vec();
        two.extend(pts[..4].iter().map(|p| [p[0] + 5.0, p[1], p[2]]));
        let mut e = tet.to_vec();
        e.extend(tet.iter().map(|&[a, b]| [a + 4, b + 4]));
        let w = detect(&two, &e, &Options::default(), &Control::new())
            .unwrap()
            .answer
            .witness()
            .cloned()
            .unwrap();
        assert_eq!(w.kind, WitnessKind::Disconnected);
    }

    #[test]
    fn collinear_points_are_degenerate() {
        let pts = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]];
        let d = detect(
            &pts,
            &[[0, 1], [1, 2]],
            &Options::default(),
            &Control::new(),
        )
        .unwrap();
        assert_eq!(d.answer.witness().unwrap().kind, WitnessKind::Degenerate);
    }
}
