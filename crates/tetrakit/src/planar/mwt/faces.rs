//! The exact stage: the faces of the certain edges that still hold undecided edges are
//! triangulated optimally.
//!
//! A face is given by its boundary walk (counter-clockwise, face on the left, vertices
//! possibly repeated where certain edges dangle into it) and its holes (clockwise walks
//! of certain-edge components, or isolated sites). Without holes, dynamic programming
//! over the walk's occurrences ([`polygon_dp`], `O(m³)`) finds the optimum among the
//! alive edges that leave and enter each occurrence inside its wedge. Holes that enclose
//! no area (isolated sites, trees of edges) all go at once to the region DP of
//! [`super::sites`], which cuts triangles off the face and memoises what is left.
//! Holes that enclose area are first spliced into the outer walk by a branch and bound
//! over the ways they meet the rest of the face, in one of two exhaustive forms:
//! - **ears**: every triangulation has a triangle on the face side of each walk edge
//!   `ab` of a hole; when no site of that hole could be its apex, the apex is on another
//!   walk (the outer one or another hole), and the branches are those apexes. The walks
//!   are spliced along the triangle's two new sides.
//! - **joins**, for holes whose own sites could be an apex: every triangulation is
//!   connected, so the hole is joined by an edge to the outer walk or to another hole
//!   (not necessarily the outer walk: a site can be ringed by other holes); the walks
//!   are spliced along it (it is walked twice).
//!
//! Each level removes one hole, so the minimum over the branches is exact. The hole and
//! edge with the fewest branches are taken, and a branch whose new edges already
//! outweigh the best solution found is dropped. Branches run in parallel; ties between
//! leaves go to the lesser sorted edge list, so the answer is the same on any number of
//! threads. A small hole inside a large convex face has few ears (triangles on a short
//! edge that hold no other site) but many joins: a 100-gon with three triangles of sites
//! inside takes 0.4 s by ears, 645 s by joins. Joins alone, every hole included, are the
//! slow exact reference of the tests.
//!
//! Costs are compared as certified intervals, with the exact comparison of sums of
//! square roots when two intervals overlap (ties on grids, regular polygons).

use super::polygon::{Solution, clear_of, cmp_edge_sets, polygon_dp};
use super::sites::walk_with_sites;
use super::walks::{in_wedge, walk_area_sign};
use crate::control::Control;
use crate::geom::{Interval, Point2, orient2d};
use crate::planar::edge_key as key;
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::HashSet;
use std::sync::Mutex;

/// A face to triangulate.
pub struct Face {
    /// Outer walk, counter-clockwise.
    pub outer: Vec<u32>,
    /// Hole walks (face on their left) and isolated sites (walks of length one).
    pub holes: Vec<Vec<u32>>,
}

impl Face {
    /// The number of edges every triangulation of the face adds inside it. A simple
    /// polygon of `m` corners takes `m - 3` diagonals; each hole whose walk has `k ≥ 2`
    /// occurrences adds `k + 3` (cut the face open along a bridge to it: `k + 2` more
    /// corners, and the bridge counted twice), an isolated site adds 3 (the three edges
    /// of the triangle it splits). Walks that visit a site twice count each visit, so
    /// the same holds for them after cutting along the doubled edges.
    pub fn interior_edges(&self) -> usize {
        let holes: usize = (self.holes.iter())
            .map(|h| if h.len() < 2 { 3 } else { h.len() + 3 })
            .sum();
        self.outer.len() + holes - 3
    }
}

/// Solves a face exactly. `chords` are the alive edges usable inside it. `None` when
/// the face has no triangulation with them.
///
/// Exponential in the number of holes that enclose area in the worst case (one branch
/// per ear or joining edge, and hole), and in the length of the paths through hole
/// sites the region DP meets; the faces the LMT-skeleton leaves on random sets have at
/// most one hole.
/// `None` also once `ctl` is stopped (looked at in every branch and in each DP).
pub fn solve(
    points: &[Point2],
    face: &Face,
    chords: &HashSet<[u32; 2]>,
    ctl: &Control,
) -> Option<Solution> {
    solve_by(points, face, chords, true, ctl)
}

/// [`solve`]; when `fast` is false every hole branches by joins, even isolated sites
/// (the slow exact reference the tests hold ears and the region DP to).
fn solve_by(
    points: &[Point2],
    face: &Face,
    chords: &HashSet<[u32; 2]>,
    fast: bool,
    ctl: &Control,
) -> Option<Solution> {
    let search = Search {
        points,
        best: Mutex::new(None),
        fast,
        ctl,
    };
    search.branch(
        face.outer.clone(),
        face.holes.clone(),
        Vec::new(),
        Interval::ZERO,
        chords,
    );
    search.best.into_inner().unwrap_or_else(|e| e.into_inner())
}

/// Branch and bound over the ways holes meet the rest of the face. The branches of a
/// level run in parallel; the answer does not depend on their timing. It is the least
/// of the leaves' solutions (each leaf's DP is deterministic) by weight and then by
/// sorted edge list ([`Search::offer`]), and a branch is dropped only when it is
/// certainly heavier than a solution found, so that least solution is never dropped.
struct Search<'a> {
    points: &'a [Point2],
    /// The least complete solution so far (cut edges included, sorted).
    best: Mutex<Option<Solution>>,
    /// Whether holes with edges branch by ears and isolated sites go to the region DP
    /// (otherwise everything branches by joins).
    fast: bool,
    /// Stops the search (every branch returns at once).
    ctl: &'a Control,
}

impl Search<'_> {
    /// Splices the hole with the fewest steps (ears or joins, see the module
    /// documentation) into another walk, one branch per step, until only holes the
    /// region DP takes are left (none, in the reference). Each level removes one hole,
    /// so every triangulation is reached. `spent` is the length of `cuts`; a branch
    /// already heavier than the best solution is dropped.
    fn branch(
        &self,
        outer: Vec<u32>,
        holes: Vec<Vec<u32>>,
        cuts: Vec<[u32; 2]>,
        spent: Interval,
        chords: &HashSet<[u32; 2]>,
    ) {
        if self.heavier(spent) || self.ctl.is_stopped() {
            return;
        }
        // Holes that enclose nothing (sites, trees of edges) all at once in the region
        // DP; the others are spliced into the outer walk first.
        let flat = |h: &Vec<u32>| self.fast && walk_area_sign(self.points, h) == 0;
        if holes.iter().all(flat) {
            let usable = |e| free(chords, &cuts, e);
            let sol = if holes.is_empty() {
                polygon_dp(self.points, &outer, &cuts, &usable, self.ctl)
            } else {
                let mut sites: Vec<u32> = holes.concat();
                sites.sort_unstable();
                sites.dedup();
                let fixed: HashSet<[u32; 2]> = (holes.iter())
                    .flat_map(|h| (0..h.len()).map(|i| key(h[i], h[(i + 1) % h.len()])))
                    .filter(|e| e[0] != e[1])
                    .collect();
                walk_with_sites(
                    self.points,
                    &outer,
                    &sites,
                    &fixed,
                    &cuts,
                    &usable,
                    self.ctl,
                )
            };
            if let Some(sol) = sol {
                let mut edges = sol.edges;
                edges.extend_from_slice(&cuts);
                self.offer(Solution {
                    edges,
                    weight: sol.weight.plus(spent),
                });
            }
            return;
        }
        let view = View {
            outer: &outer,
            holes: &holes,
            cuts: &cuts,
            chords,
        };
        let (hi, options) = (0..holes.len())
            .filter(|&i| !flat(&holes[i]))
            .map(|i| (i, self.steps(&view, i)))
            .min_by_key(|(_, o)| o.len())
            .expect("holes");
        // Light steps first (a float order, only a heuristic: every step is tried; each
        // thread takes its share in this order): a light solution early prunes more.
        // Each step's cost is computed once.
        let points = self.points;
        let len = |a: u32, b: u32| {
            let (a, b) = (&points[a as usize], &points[b as usize]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        };
        let cost = |s: &Step| s.new_edges().iter().map(|e| len(e[0], e[1])).sum::<f64>();
        let mut order: Vec<(f64, Step)> = options.into_iter().map(|s| (cost(&s), s)).collect();
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
        order.into_par_iter().for_each(|(_, step)| {
            let mut rest = holes.clone();
            let hole = rest.remove(hi);
            let walk = |target: &[u32]| match step {
                Step::Join(j) => splice(points, target, &hole, j.to, j.from),
                Step::Ear { at, occ, .. } => Some(splice_ear(target, &hole, at, occ)),
            };
            let outer2 = match step.target() {
                None => walk(&outer),
                Some(t) => {
                    let t = t - usize::from(t > hi);
                    walk(&rest[t]).map(|merged| {
                        rest[t] = merged;
                        outer.clone()
                    })
                }
            };
            let Some(outer2) = outer2 else {
                return;
            };
            let (mut cuts2, mut spent2) = (cuts.clone(), spent);
            for e in step.new_edges() {
                cuts2.push(e);
                spent2 = spent2.plus(Interval::length(
                    &points[e[0] as usize],
                    &points[e[1] as usize],
                ));
            }
            self.branch(outer2, rest, cuts2, spent2, chords);
        });
    }

    /// The ways to connect hole `i` to the rest of the face, one of which every
    /// triangulation takes: the triangles on one side of one of its walk edges (the edge
    /// with the fewest), or, when no edge qualifies (an isolated site, or a walk that may
    /// hold a triangle's apex itself), the edges joining it to another walk.
    fn steps(&self, f: &View, i: usize) -> Vec<Step> {
        let ears = self.fast.then(|| {
            (0..f.holes[i].len())
                .filter_map(|at| self.ears(f, i, at))
                .min_by_key(|o| o.len())
        });
        ears.flatten()
            .unwrap_or_else(|| (self.joins(f, i).into_iter()).map(Step::Join).collect())
    }

    /// The triangles on the face side of the edge from entry `at` of hole `i` to the
    /// next (every triangulation has one), each with its apex on another walk; `None`
    /// for an isolated site, or when a site of the hole itself could be the apex.
    fn ears(&self, f: &View, i: usize, at: usize) -> Option<Vec<Step>> {
        let (outer, holes) = (f.outer, f.holes);
        let hole = &holes[i];
        let k = hole.len();
        if k < 2 {
            return None;
        }
        let pt = |v: u32| &self.points[v as usize];
        let (a, b) = (hole[at], hole[(at + 1) % k]);
        let all = || {
            std::iter::once(outer)
                .chain(holes.iter().map(|h| &h[..]))
                .flatten()
        };
        let empty = |c: u32| {
            let (pa, pb, pc) = (pt(a), pt(b), pt(c));
            !all().any(|&s| {
                orient2d(pa, pb, pt(s)) > 0
                    && orient2d(pb, pc, pt(s)) > 0
                    && orient2d(pc, pa, pt(s)) > 0
            })
        };
        let left = |c: u32| orient2d(pt(a), pt(b), pt(c)) > 0 && empty(c);
        // A site of the hole itself could be the apex: no step splices a hole into
        // itself, so this edge would not branch exhaustively.
        if hole.iter().any(|&c| c != a && c != b && left(c)) {
            return None;
        }
        let usable = |e: [u32; 2]| f.usable(self.points, e);
        let targets = other_walks(outer, holes, i);
        let mut out = Vec::new();
        for (target, walk) in targets {
            let m = walk.len();
            for (j, &c) in walk.iter().enumerate() {
                let inside = |d: u32| {
                    m == 1 || in_wedge(self.points, c, walk[(j + 1) % m], walk[(j + m - 1) % m], d)
                };
                // No wedge test at `a` or `b`: a walk edge there inside the triangle's
                // corner would end inside it or cross `bc` or `ac`, which cross no walk
                // edge. At `c` the test picks the occurrence the triangle is at.
                if inside(a) && inside(b) && usable(key(a, c)) && usable(key(b, c)) && left(c) {
                    out.push(Step::Ear {
                        at,
                        occ: j,
                        apex: c,
                        a,
                        b,
                        target,
                    });
                }
            }
        }
        Some(out)
    }

    /// The usable edges from hole `i` to the outer walk (`target` `None`) or to another
    /// hole, crossing no cut.
    fn joins(&self, f: &View, i: usize) -> Vec<Join> {
        let (outer, holes) = (f.outer, f.holes);
        let mut out = Vec::new();
        let targets = other_walks(outer, holes, i);
        let sites = dedup(&holes[i]);
        for (target, walk) in targets {
            let ends = dedup(walk);
            for &from in &sites {
                for &to in &ends {
                    let e = key(from, to);
                    if f.usable(self.points, e) {
                        out.push(Join { from, to, target });
                    }
                }
            }
        }
        out
    }

    /// True when `w` is certainly heavier than the best solution so far.
    fn heavier(&self, w: Interval) -> bool {
        let best = self.best.lock().unwrap_or_else(|e| e.into_inner());
        (best.as_ref()).is_some_and(|b| w.certain_cmp(b.weight) == Some(Ordering::Greater))
    }

    /// Keeps `sol` if it is less than the best so far: lighter (exactly), or as light
    /// with a lexicographically smaller sorted edge list.
    fn offer(&self, mut sol: Solution) {
        sol.edges.sort_unstable();
        let mut best = self.best.lock().unwrap_or_else(|e| e.into_inner());
        let less = match best.as_ref() {
            None => true,
            Some(b) => match sol.weight.certain_cmp(b.weight) {
                Some(o) => o == Ordering::Less,
                None => cmp_edge_sets(self.points, &sol.edges, &b.edges)
                    .then_with(|| sol.edges.cmp(&b.edges))
                    .is_lt(),
            },
        };
        if less {
            *best = Some(sol);
        }
    }
}

/// A state of the search: the outer walk, the holes left, the edges chosen so far
/// (`cuts`) and the face's alive edges (`chords`; those not in `cuts` are free).
struct View<'v> {
    outer: &'v [u32],
    holes: &'v [Vec<u32>],
    cuts: &'v [[u32; 2]],
    chords: &'v HashSet<[u32; 2]>,
}

impl View<'_> {
    /// A free alive edge across no chosen one.
    fn usable(&self, points: &[Point2], e: [u32; 2]) -> bool {
        free(self.chords, self.cuts, e) && clear_of(points, self.cuts, &e)
    }
}

/// An alive edge of the face not chosen yet (`cuts`, a few edges, are the chosen ones).
fn free(chords: &HashSet<[u32; 2]>, cuts: &[[u32; 2]], e: [u32; 2]) -> bool {
    chords.contains(&e) && !cuts.contains(&e)
}

/// The walks other than hole `i`: the outer one (`None`) and the other holes.
fn other_walks<'w>(
    outer: &'w [u32],
    holes: &'w [Vec<u32>],
    i: usize,
) -> impl Iterator<Item = (Option<usize>, &'w [u32])> {
    let rest = (0..holes.len()).filter(move |&t| t != i);
    std::iter::once((None, outer)).chain(rest.map(|t| (Some(t), &holes[t][..])))
}

/// A way to connect a hole to another walk (the outer one when `target` is `None`).
#[derive(Clone, Copy)]
enum Step {
    /// One edge.
    Join(Join),
    /// The triangle on the hole's walk edge `a → b` (from entry `at`) with apex `apex`,
    /// entry `occ` of the target walk.
    Ear {
        at: usize,
        occ: usize,
        apex: u32,
        a: u32,
        b: u32,
        target: Option<usize>,
    },
}

impl Step {
    fn target(&self) -> Option<usize> {
        match *self {
            Step::Join(j) => j.target,
            Step::Ear { target, .. } => target,
        }
    }

    /// The edges the step adds to the triangulation.
    fn new_edges(&self) -> Vec<[u32; 2]> {
        match *self {
            Step::Join(j) => vec![key(j.from, j.to)],
            Step::Ear { apex, a, b, .. } => vec![key(a, apex), key(b, apex)],
        }
    }
}

/// An edge from a hole site `from` to a site `to` of the outer walk (`target` `None`)
/// or of another hole.
#[derive(Clone, Copy)]
struct Join {
    from: u32,
    to: u32,
    target: Option<usize>,
}

/// The distinct sites of a walk.
fn dedup(walk: &[u32]) -> Vec<u32> {
    let mut v = walk.to_vec();
    v.sort_unstable();
    v.dedup();
    v
}

/// The walk `target` (the outer walk or a hole) with `hole` spliced in along the edge
/// `w–h` (`w` on `target`, `h` on `hole`): the edge is walked once each way, at the
/// occurrences of `w` and `h` whose wedges hold it. `None` if the edge leaves no
/// occurrence inside its wedge.
fn splice(points: &[Point2], target: &[u32], hole: &[u32], w: u32, h: u32) -> Option<Vec<u32>> {
    // The occurrence of `v` in `walk` whose wedge (face side) holds the direction to `d`.
    let at = |walk: &[u32], v: u32, d: u32| -> Option<usize> {
        let k = walk.len();
        if k == 1 {
            return Some(0);
        }
        (0..k).find(|&i| {
            walk[i] == v && in_wedge(points, v, walk[(i + 1) % k], walk[(i + k - 1) % k], d)
        })
    };
    let (i, j) = (at(target, w, h)?, at(hole, h, w)?);
    let k = hole.len();
    let mut out: Vec<u32> = target[..=i].to_vec();
    out.extend((0..k).map(|t| hole[(j + t) % k]));
    if k > 1 {
        out.push(h);
    }
    if target.len() > 1 {
        out.push(w);
    }
    out.extend_from_slice(&target[i + 1..]);
    Some(out)
}

/// The walk `target` with `hole` spliced in by the triangle on the hole's edge `a → b`
/// (from entry `at`) whose apex `c` is entry `occ` of `target`: the walk arrives at `c`,
/// goes to `b`, round the hole to `a`, and back to `c` (the triangle is left of `a → b`,
/// so the rest of the face is left of `c → b` and `a → c`).
fn splice_ear(target: &[u32], hole: &[u32], at: usize, occ: usize) -> Vec<u32> {
    let k = hole.len();
    let round = (1..=k).map(|t| hole[(at + t) % k]);
    if target.len() == 1 {
        return std::iter::once(target[0]).chain(round).collect();
    }
    let mut out = target[..=occ].to_vec();
    out.extend(round);
    out.extend_from_slice(&target[occ..]);
    out
}

#[cfg(test)]
mod tests {
    use super::super::polygon::crosses;
    use super::*;
    use crate::geom::Hull2;
    use crate::rng::Rng;

    /// How the first interior sites of a test face are joined into one hole.
    #[derive(Clone, Copy, PartialEq)]
    enum Shape {
        /// Every interior site is an isolated hole.
        Sites,
        /// The first two joined by an edge (a hole walked both ways).
        Pair,
        /// The first three joined by a path (a walk that repeats its middle site).
        Path,
        /// The first three as a triangle with nothing inside.
        Triangle,
    }

    /// The walk and edges of the hole `shape` makes of `inner` (clockwise, the face on
    /// its left), if no site blocks its edges and nothing lies inside it.
    fn hole_of(
        pts: &[Point2],
        inner: &[u32],
        shape: Shape,
        blocked: &HashSet<[u32; 2]>,
    ) -> Option<(Vec<u32>, Vec<[u32; 2]>)> {
        let need = match shape {
            Shape::Sites => return None,
            Shape::Pair => 2,
            Shape::Path | Shape::Triangle => 3,
        };
        let v = inner.get(..need)?;
        let (walk, edges) = match shape {
            Shape::Pair => (vec![v[0], v[1]], vec![key(v[0], v[1])]),
            Shape::Path => (
                vec![v[0], v[1], v[2], v[1]],
                vec![key(v[0], v[1]), key(v[1], v[2])],
            ),
            _ => {
                let p = |i: usize| &pts[v[i] as usize];
                let o = orient2d(p(0), p(1), p(2));
                let inside = |s: &Point2| (0..3).all(|i| orient2d(p(i), p((i + 1) % 3), s) == o);
                if o == 0 || pts.iter().any(inside) {
                    return None;
                }
                let walk = if o > 0 {
                    vec![v[0], v[2], v[1]]
                } else {
                    v.to_vec()
                };
                let edges = vec![key(v[0], v[1]), key(v[1], v[2]), key(v[0], v[2])];
                (walk, edges)
            }
        };
        let overlap = shape == Shape::Path
            && orient2d(
                &pts[v[0] as usize],
                &pts[v[1] as usize],
                &pts[v[2] as usize],
            ) == 0;
        (!overlap && edges.iter().all(|e| !blocked.contains(e))).then_some((walk, edges))
    }

    /// Every segment between sites that is not fixed, through no site (`blocked`) and
    /// across no fixed edge; `None` when the fixed edges themselves cross or are blocked.
    fn free_segments(
        pts: &[Point2],
        fixed: &[[u32; 2]],
        blocked: &HashSet<[u32; 2]>,
    ) -> Option<HashSet<[u32; 2]>> {
        let crossing = |e: &[u32; 2]| fixed.iter().any(|f| crosses(pts, f, e));
        if fixed.iter().any(|e| crossing(e) || blocked.contains(e)) {
            return None;
        }
        let n = pts.len() as u32;
        let free = (0..n)
            .flat_map(|a| (a + 1..n).map(move |b| [a, b]))
            .filter(|e| !fixed.contains(e) && !blocked.contains(e) && !crossing(e));
        Some(free.collect())
    }

    /// The face of a convex polygon whose interior sites are holes: isolated sites, and
    /// the first two or three joined by `shape` when no site blocks it. Every other
    /// segment through no site and across no fixed edge is usable. Returns the optimum
    /// of the face stage and the fixed edges.
    fn solve_face(pts: &[Point2], shape: Shape) -> Option<[Vec<[u32; 2]>; 2]> {
        let hull = Hull2::new(pts);
        if hull.vertices.len() < 3
            || hull.on_boundary.iter().filter(|&&b| b).count() != hull.vertices.len()
        {
            return None;
        }
        let h = hull.vertices.len();
        let mut fixed: Vec<[u32; 2]> = (0..h)
            .map(|i| key(hull.vertices[i], hull.vertices[(i + 1) % h]))
            .collect();
        let n = pts.len() as u32;
        let inner: Vec<u32> = (0..n).filter(|&v| !hull.on_boundary[v as usize]).collect();
        let blocked = crate::planar::forced::blocked_pairs(pts);
        let mut holes: Vec<Vec<u32>> = inner.iter().map(|&v| vec![v]).collect();
        if let Some((walk, edges)) = hole_of(pts, &inner, shape, &blocked) {
            holes.retain(|h| !walk.contains(&h[0]));
            holes.push(walk);
            fixed.extend(edges);
        }
        let chords = free_segments(pts, &fixed, &blocked)?;
        let face = Face {
            outer: hull.vertices.clone(),
            holes,
        };
        let sol = solve(pts, &face, &chords, &Control::new()).expect("a triangulation exists");
        assert_eq!(sol.edges.len(), face.interior_edges(), "{:?}", face.holes);
        let mut edges = sol.edges;
        edges.extend(&fixed);
        edges.sort_unstable();
        Some([edges, fixed])
    }

    /// The lightest triangulation containing `fixed`, by exhaustive search.
    fn lightest(pts: &[Point2], fixed: &[[u32; 2]]) -> Vec<[u32; 2]> {
        let all = crate::planar::triangulations(pts);
        let with = all
            .into_iter()
            .filter(|t| fixed.iter().all(|f| t.contains(f)));
        with.reduce(|best, t| {
            if cmp_edge_sets(pts, &t, &best) == Ordering::Less {
                t
            } else {
                best
            }
        })
        .expect("a triangulation with the fixed edges")
    }

    /// `m` sites at integer coordinates near a circle of `radius`, counter-clockwise,
    /// each turned by up to 0.3 of the step between them.
    fn jittered_polygon(rng: &mut Rng, m: usize, radius: f64) -> Vec<Point2> {
        (0..m)
            .map(|i| {
                let a = std::f64::consts::TAU * (i as f64 + 0.3 * rng.unit()) / m as f64;
                [(radius * a.cos()).round(), (radius * a.sin()).round()]
            })
            .collect()
    }

    /// Faces with up to four holes (isolated sites, edges, paths and triangles) against
    /// exhaustive search, including sites that an optimum joins only to other holes (a
    /// ring around a centre site).
    #[test]
    fn faces_with_holes_match_exhaustive_search() {
        let mut rng = Rng::new(21);
        let mut cases: Vec<Vec<Point2>> = Vec::new();
        for _ in 0..240 {
            let m = 4 + rng.below(4);
            let mut pts = jittered_polygon(&mut rng, m, 8.0);
            for _ in 0..1 + rng.below(4) {
                pts.push([rng.below(7) as f64 - 3.0, rng.below(7) as f64 - 3.0]);
            }
            cases.push(pts);
        }
        // A centre joined to a ring of three: no edge from the centre leaves the ring.
        let ring = vec![
            [10.0, 0.0],
            [0.0, 10.0],
            [-10.0, 0.0],
            [0.0, -10.0],
            [0.0, 0.0],
            [1.0, 0.0],
            [-1.0, 1.0],
            [-1.0, -1.0],
        ];
        cases.push(ring.clone());
        cases.push(ring);
        // The same with the centre's segments to three hull sites blocked by the ring:
        // its one edge to the hull crosses the ring.
        let blocked = vec![
            [10.0, 0.0],
            [-5.0, 10.0],
            [-5.0, -10.0],
            [-9.0, 0.0],
            [0.0, 0.0],
            [2.0, 0.0],
            [-1.0, 2.0],
            [-1.0, -2.0],
        ];
        cases.extend([blocked.clone(), blocked.clone(), blocked]);
        let (mut with_two_holes, mut with_a_walk, mut with_three) = (0, 0, 0);
        for (i, mut pts) in cases.into_iter().enumerate() {
            pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
            pts.dedup();
            let shape = [Shape::Sites, Shape::Pair, Shape::Path, Shape::Triangle][i % 4];
            let Some([edges, fixed]) = solve_face(&pts, shape) else {
                continue;
            };
            let best = lightest(&pts, &fixed);
            assert_eq!(
                cmp_edge_sets(&pts, &edges, &best),
                Ordering::Equal,
                "{pts:?} fixed {fixed:?} got {edges:?} best {best:?}"
            );
            let hull = Hull2::new(&pts).vertices.len();
            let mut distinct = edges.clone();
            distinct.dedup();
            assert_eq!(distinct.len(), edges.len(), "{pts:?}");
            assert_eq!(edges.len(), 3 * pts.len() - 3 - hull, "{pts:?}");
            let inner = pts.len() - hull;
            with_two_holes += usize::from(inner >= 3 || (inner == 2 && fixed.len() == hull));
            with_a_walk += usize::from(inner >= 3 && fixed.len() > hull);
            with_three += usize::from(fixed.len() >= hull + 2);
        }
        assert!(with_two_holes > 80 && with_a_walk > 40 && with_three > 20);
    }

    /// Ears and the region DP against joins (all exact) on faces too large for
    /// exhaustive search: convex polygons with small triangles and segments of sites
    /// inside, the shape on which joins alone take exponential time.
    #[test]
    fn ears_and_region_dp_match_join_branching() {
        let mut rng = Rng::new(8);
        let mut checked = 0;
        for case in 0..40 {
            let m = 6 + rng.below(4);
            let mut pts = jittered_polygon(&mut rng, m, 20.0);
            let clusters = 2 + usize::from(case % 4 == 0);
            for c in 0..clusters {
                let (x, y) = (rng.below(17) as f64 - 8.0, rng.below(17) as f64 - 8.0);
                pts.extend([[x, y], [x + 2.0, y]]);
                if (case + c) % 3 != 0 {
                    pts.push([x + 1.0, y + 2.0]);
                }
            }
            let sizes: Vec<usize> = (0..clusters)
                .map(|c| if (case + c) % 3 != 0 { 3 } else { 2 })
                .collect();
            // In odd cases a site hangs from hull site 0 by a fixed edge, so the outer
            // walk visits site 0 twice (an apex there has two occurrences to choose from).
            let dangling = (case % 2 == 1).then(|| {
                pts.push([15.0, 1.0]);
                pts.len() as u32 - 1
            });
            let mut sorted = pts.clone();
            sorted.sort_by(|a, b| a.partial_cmp(b).unwrap());
            sorted.dedup();
            let hull = Hull2::new(&pts);
            if sorted.len() != pts.len()
                || hull.on_boundary.iter().filter(|&&b| b).count() != hull.vertices.len()
                || hull.vertices.len() != m
            {
                continue;
            }
            let blocked = crate::planar::forced::blocked_pairs(&pts);
            let h = hull.vertices.len();
            let mut fixed: Vec<[u32; 2]> = (0..h)
                .map(|i| key(hull.vertices[i], hull.vertices[(i + 1) % h]))
                .collect();
            let mut holes = Vec::new();
            let mut first = m as u32;
            for &size in &sizes {
                let sites: Vec<u32> = (first..first + size as u32).collect();
                first += size as u32;
                let shape = if size == 3 {
                    Shape::Triangle
                } else {
                    Shape::Pair
                };
                let Some((walk, edges)) = hole_of(&pts, &sites, shape, &blocked) else {
                    holes.extend(sites.iter().map(|&v| vec![v]));
                    continue;
                };
                holes.push(walk);
                fixed.extend(edges);
            }
            let mut outer = hull.vertices.clone();
            if let Some(d) = dangling {
                fixed.push(key(0, d));
                let Some(walk) = splice(&pts, &outer, &[d], 0, d) else {
                    continue;
                };
                outer = walk;
            }
            let Some(chords) = free_segments(&pts, &fixed, &blocked) else {
                continue;
            };
            let face = Face { outer, holes };
            let by_ears =
                solve_by(&pts, &face, &chords, true, &Control::new()).expect("a triangulation");
            let by_joins =
                solve_by(&pts, &face, &chords, false, &Control::new()).expect("a triangulation");
            assert_eq!(
                cmp_edge_sets(&pts, &by_ears.edges, &by_joins.edges),
                Ordering::Equal,
                "{pts:?}"
            );
            assert_eq!(by_ears.edges.len() + fixed.len(), 3 * pts.len() - 3 - h);
            checked += 1;
        }
        assert!(checked > 30, "{checked}");
    }

    /// The region DP against joins on star-shaped (non-convex) faces with two to four
    /// isolated sites, and in some a segment, a path or a triangle of sites, inside, and
    /// in half of them a site hanging from the boundary by a fixed edge (the outer walk
    /// visits its end twice): every segment between sites through no site and across no
    /// side or fixed edge is usable (the DP's wedge tests keep out those outside the
    /// face).
    #[test]
    fn region_dp_matches_join_branching_in_star_polygons() {
        let mut rng = Rng::new(77);
        let (mut checked, mut with_a_walk, mut hanging) = (0, 0, 0);
        for case in 0..60 {
            let m = 7 + rng.below(6);
            let mut pts: Vec<Point2> = (0..m)
                .map(|i| {
                    let a = std::f64::consts::TAU * (i as f64 + 0.4 * rng.unit()) / m as f64;
                    let r = if i % 2 == 0 {
                        30.0
                    } else {
                        12.0 + 14.0 * rng.unit()
                    };
                    [(r * a.cos()).round(), (r * a.sin()).round()]
                })
                .collect();
            let p = |pts: &[Point2], i: usize| pts[i % m];
            let inside = |pts: &[Point2], s: &Point2| {
                (0..m).any(|i| {
                    let (a, b) = (p(pts, i), p(pts, i + 1));
                    orient2d(&[0.0, 0.0], &a, s) > 0
                        && orient2d(&a, &b, s) > 0
                        && orient2d(&b, &[0.0, 0.0], s) > 0
                })
            };
            let k = 2 + rng.below(3);
            while pts.len() < m + k {
                let s = [rng.below(41) as f64 - 20.0, rng.below(41) as f64 - 20.0];
                if inside(&pts, &s) && !pts.contains(&s) {
                    pts.push(s);
                }
            }
            // In half the cases a site hangs from site 0 by a fixed edge.
            let hang = [(pts[0][0] * 0.7).round(), (pts[0][1] * 0.7).round()];
            let dangling =
                (case % 2 == 1 && inside(&pts, &hang) && !pts.contains(&hang)).then(|| {
                    pts.push(hang);
                    pts.len() as u32 - 1
                });
            let blocked = crate::planar::forced::blocked_pairs(&pts);
            let mut fixed: Vec<[u32; 2]> = (0..m)
                .map(|i| key(i as u32, ((i + 1) % m) as u32))
                .collect();
            fixed.extend(dangling.map(|d| key(0, d)));
            let inner: Vec<u32> = (m as u32..pts.len() as u32)
                .filter(|&v| Some(v) != dangling)
                .collect();
            let mut holes: Vec<Vec<u32>> = inner.iter().map(|&v| vec![v]).collect();
            let shape = [Shape::Sites, Shape::Pair, Shape::Path, Shape::Triangle][case % 4];
            if let Some((walk, edges)) = hole_of(&pts, &inner, shape, &blocked) {
                holes.retain(|h| !walk.contains(&h[0]));
                holes.push(walk);
                fixed.extend(edges);
            }
            let Some(chords) = free_segments(&pts, &fixed, &blocked) else {
                continue;
            };
            let mut outer: Vec<u32> = (0..m as u32).collect();
            if let Some(d) = dangling {
                let Some(walk) = splice(&pts, &outer, &[d], 0, d) else {
                    continue;
                };
                outer = walk;
            }
            let k = pts.len() - m;
            let face = Face { outer, holes };
            let fast =
                solve_by(&pts, &face, &chords, true, &Control::new()).expect("a triangulation");
            let reference =
                solve_by(&pts, &face, &chords, false, &Control::new()).expect("a triangulation");
            assert_eq!(
                cmp_edge_sets(&pts, &fast.edges, &reference.edges),
                Ordering::Equal,
                "{pts:?}"
            );
            // Euler: a triangulated polygon with `k` sites inside has `m - 3 + 3k`
            // diagonals.
            assert_eq!(fast.edges.len() + fixed.len() - m, m - 3 + 3 * k, "{pts:?}");
            checked += 1;
            with_a_walk += usize::from(fixed.len() > m + usize::from(dangling.is_some()));
            hanging += usize::from(dangling.is_some());
        }
        assert!(
            checked > 50 && with_a_walk > 20 && hanging > 15,
            "{checked} {with_a_walk} {hanging}"
        );
    }

    /// A face whose region DP reaches a run of one walk occurrence followed by a path:
    /// the occurrence after it on the walk is no corner of that region. Taking it for
    /// one put the path's first site at the apex without testing the side from there to
    /// the path's end, and a side through site 7 (on the segment 6–10) made a lighter
    /// "triangulation" in which site 7 hung on its hole edge alone.
    #[test]
    fn a_run_of_one_occurrence_has_no_next_corner() {
        let pts: Vec<Point2> = vec![
            [20.0, 1.0],
            [7.0, 19.0],
            [-14.0, 14.0],
            [-20.0, -4.0],
            [-6.0, -19.0],
            [12.0, -16.0],
            [-5.0, 2.0],
            [-3.0, 2.0],
            [4.0, 0.0],
            [6.0, 0.0],
            [5.0, 2.0],
            [15.0, 1.0],
        ];
        // The hexagon 0..6 with site 11 dangling from 0, the pair 6–7 and the sites 8, 9
        // and 10 inside.
        let mut fixed: Vec<[u32; 2]> = (0..6).map(|i| key(i, (i + 1) % 6)).collect();
        fixed.extend([[0, 11], [6, 7]]);
        let blocked = crate::planar::forced::blocked_pairs(&pts);
        let chords = free_segments(&pts, &fixed, &blocked).expect("fixed edges apart");
        let face = Face {
            outer: vec![3, 4, 5, 0, 11, 0, 1, 2],
            holes: vec![vec![6, 7], vec![8], vec![9], vec![10]],
        };
        let fast = solve_by(&pts, &face, &chords, true, &Control::new()).expect("a triangulation");
        let joins =
            solve_by(&pts, &face, &chords, false, &Control::new()).expect("a triangulation");
        assert_eq!(fast.edges.len() + fixed.len(), 3 * pts.len() - 3 - 6);
        assert!(fast.edges.iter().all(|e| chords.contains(e)));
        let cmp = cmp_edge_sets(&pts, &fast.edges, &joins.edges);
        assert_eq!(cmp, Ordering::Equal);
    }

    /// The ring between two concentric squares: each of its four isosceles trapezoids
    /// takes either of two diagonals of the same length, so the face has 16 optima of
    /// the same exact weight. The branches run in parallel, yet the answer is the same
    /// on any number of threads.
    #[test]
    fn ties_give_the_same_answer_on_any_number_of_threads() {
        let pts: Vec<Point2> = vec![
            [-4.0, -4.0],
            [4.0, -4.0],
            [4.0, 4.0],
            [-4.0, 4.0],
            [-1.0, -1.0],
            [-1.0, 1.0],
            [1.0, 1.0],
            [1.0, -1.0],
        ];
        let ring = |v: &[u32]| -> Vec<[u32; 2]> {
            (0..v.len())
                .map(|i| key(v[i], v[(i + 1) % v.len()]))
                .collect()
        };
        let (outer, hole): (Vec<u32>, Vec<u32>) = ((0..4).collect(), (4..8).collect());
        let fixed: Vec<[u32; 2]> = ring(&outer).into_iter().chain(ring(&hole)).collect();
        let blocked = crate::planar::forced::blocked_pairs(&pts);
        let mut chords = free_segments(&pts, &fixed, &blocked).expect("fixed edges apart");
        chords.retain(|e| e[0] < 4); // not inside the hole
        let face = Face {
            outer,
            holes: vec![hole],
        };
        let on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads);
            let sol = pool
                .build()
                .unwrap()
                .install(|| solve(&pts, &face, &chords, &Control::new()));
            let mut edges = sol.expect("a triangulation").edges;
            edges.sort_unstable();
            edges
        };
        let one = on(1);
        assert_eq!(one, on(2));
        assert_eq!(one, on(4));
        let joins =
            solve_by(&pts, &face, &chords, false, &Control::new()).expect("a triangulation");
        assert_eq!(cmp_edge_sets(&pts, &one, &joins.edges), Ordering::Equal);
        // Four corner edges and one diagonal per trapezoid.
        assert_eq!(one.len(), 8);
        // The tie-break itself: the mirror image (x -> -x) is another optimum, and
        // offers in either order keep the lesser edge list.
        let mirror = |v: u32| [1, 0, 3, 2, 7, 6, 5, 4][v as usize];
        let mut other: Vec<[u32; 2]> = (one.iter())
            .map(|e| key(mirror(e[0]), mirror(e[1])))
            .collect();
        other.sort_unstable();
        assert_ne!(other, one);
        let least = one.clone().min(other.clone());
        for offers in [[&one, &other], [&other, &one]] {
            let search = Search {
                points: &pts,
                best: Mutex::new(None),
                fast: true,
                ctl: &Control::new(),
            };
            for edges in offers {
                let weight = super::super::weight_of(&pts, edges);
                search.offer(Solution {
                    edges: edges.clone(),
                    weight,
                });
            }
            let best = search.best.into_inner().unwrap().expect("offered");
            assert_eq!(best.edges, least);
        }
    }
}
