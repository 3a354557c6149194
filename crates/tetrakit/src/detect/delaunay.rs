//! A fast proposal for the common case: segments that are the edges of a Delaunay
//! tetrahedralization. It is not a decision: [`detect`](super::detect) certifies what it
//! proposes with [`crate::mesh::verify`] plus `edges(T) = L`, and runs the thesis's
//! algorithm (§2.4) whenever the proposal is absent or fails, so every NO still comes from
//! the thesis's checks with their witnesses. The proposal only has to be *right often* and
//! *cheap*: each tetrahedron is derived once, from its lowest face, instead of from the
//! links of all four of its vertices.
//!
//! The rule. For a segment `ab`, let `C_ab = N(a) ∩ N(b)` be the common neighbours. For a
//! triangle `abc` with `c ∈ C_ab`, the spheres through `a, b, c` form a pencil, ordered by
//! how far their centre lies towards the `+` side of the plane `abc`; a point `p` on the
//! `+` side is strictly inside exactly the spheres beyond its own `t_p`, a point on the `−`
//! side inside exactly those before it. `abc` is a Delaunay face when some sphere of the
//! pencil has no point of `C_ab` inside, i.e. when the `−` point latest in the pencil is
//! not inside the sphere of the earliest `+` point `d₊`; the tetrahedron on the `+` side is
//! then `abcd₊` (and symmetrically on the `−` side).
//!
//! Why `C_ab` is enough when `L` is the Delaunay edge set of points in general position: the
//! centres of the empty spheres through `a` and `b` form the Voronoi polygon dual to `ab`,
//! cut out of the bisector plane by the half-planes `|z − a| ≤ |z − p|` of the points `p`
//! of the ring of `ab` alone (one per edge of the polygon), and the ring lies in `C_ab`.
//! The centres of the spheres through `a, b, c` are a line in that plane; it meets the
//! polygon exactly when `abc` is a Delaunay face, and the endpoints of the intersection
//! are the circumcentres of the two tetrahedra on `abc`. Every other point of `C_ab` only
//! adds a half-plane that already contains the polygon, so the answer is the same.
//!
//! Emission. The tetrahedron `{a, b, c, d}` with `a < b < c < d` is emitted from the pair
//! `ab` and the face `abc`, when `d` is the apex found on its side: once per tetrahedron.
//! Ties and planes (a point of `C_ab` on the plane `abc`, or on a sphere of the pencil
//! already taken) mean the input is not in general position: the proposal is withdrawn and
//! the thesis's algorithm, which assumes nothing, decides. So does a pair with more than
//! [`MAX_COMMON`] common neighbours, which bounds the proposal's work by `O(|L|)` tests
//! per vertex pair. All tests are exact.

use super::graph::Graph;
use crate::geom::{Dir, Frame, Point3};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// The Delaunay tetrahedra of the graph `g` (positively oriented, each once), or `None`
/// when the rule above meets a tie or a plane and withdraws.
pub(super) fn propose(points: &[Point3], g: &Graph) -> Option<Vec<[u32; 4]>> {
    let withdrawn = AtomicBool::new(false);
    let pieces: Vec<Vec<[u32; 4]>> = (0..g.len() as u32)
        .into_par_iter()
        .with_min_len(64)
        .fold(
            || (Vec::new(), Scratch::default()),
            |(mut tets, mut scratch), a| {
                if !withdrawn.load(Ordering::Relaxed)
                    && tets_at(points, g, a, &mut scratch, &mut tets).is_none()
                {
                    withdrawn.store(true, Ordering::Relaxed);
                }
                (tets, scratch)
            },
        )
        .map(|(tets, _)| tets)
        .collect();
    if withdrawn.into_inner() {
        return None;
    }
    Some(pieces.concat())
}

/// The most common neighbours a pair may have before the proposal withdraws. The work at
/// a pair is quadratic in their number (about 6 on Delaunay meshes of random points); on
/// families with huge rings, such as the thesis's skew lines (`n/2` around an edge), the
/// links route is the output-sensitive one, so the proposal steps aside at once.
const MAX_COMMON: usize = 64;

/// Reused per-thread buffers.
#[derive(Default)]
struct Scratch {
    dirs: Vec<Dir>,
    common: Vec<u32>,
}

thread_local! {
    /// Per vertex, its index in the neighbour list of the vertex being processed (or
    /// `u32::MAX`): common neighbours by one lookup each instead of a list intersection.
    static POSITION: std::cell::RefCell<Vec<u32>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Appends the tetrahedra whose lowest vertex is `a`; `None` on a tie or a plane.
fn tets_at(
    points: &[Point3],
    g: &Graph,
    a: u32,
    s: &mut Scratch,
    out: &mut Vec<[u32; 4]>,
) -> Option<()> {
    let nb = g.nbrs(a);
    let first = nb.partition_point(|&x| x < a);
    if nb.len() - first < 3 {
        return Some(());
    }
    POSITION.with(|pos| {
        let mut pos = pos.borrow_mut();
        pos.resize(g.len(), u32::MAX);
        for (i, &x) in nb.iter().enumerate() {
            pos[x as usize] = i as u32;
        }
        let found = tets_from(points, g, (a, nb, first), &pos, s, out);
        for &x in nb {
            pos[x as usize] = u32::MAX;
        }
        found
    })
}

/// [`tets_at`] with the positions of `a`'s neighbours `nb` marked in `pos` (`nb[first..]`
/// are the ones above `a`).
fn tets_from(
    points: &[Point3],
    g: &Graph,
    (a, nb, first): (u32, &[u32], usize),
    pos: &[u32],
    s: &mut Scratch,
    out: &mut Vec<[u32; 4]>,
) -> Option<()> {
    let frame = Frame::new(&points[a as usize]);
    s.dirs.clear();
    s.dirs
        .extend(nb.iter().map(|&x| frame.dir(&points[x as usize])));
    for (bi, &b) in nb.iter().enumerate().skip(first) {
        // C_ab as indices into `nb`, increasing (both lists are sorted). Branch-free:
        // whether a neighbour of `b` is common is a coin toss for the predictor.
        let nbrs_b = g.nbrs(b);
        s.common.resize(nbrs_b.len() + 1, 0);
        let mut len = 0;
        for &y in nbrs_b {
            let i = pos[y as usize];
            s.common[len] = i;
            len += usize::from(i != u32::MAX);
        }
        s.common.truncate(len);
        if s.common.len() > MAX_COMMON {
            return None;
        }
        let above_b = s.common.partition_point(|&j| nb[j as usize] < b);
        if s.common.len() - above_b < 2 {
            continue;
        }
        let face = Face {
            pts: points,
            nb,
            dirs: &s.dirs,
            frame: &frame,
            common: &s.common,
            b: bi,
        };
        for k in above_b..s.common.len() - 1 {
            let ci = s.common[k] as usize;
            let [plus, minus] = face.apexes(ci)?;
            let c = nb[ci];
            // `nb` is sorted, so a larger index is a larger vertex.
            if let Some(d) = plus.filter(|&d| d > ci) {
                out.push([a, b, c, nb[d]]);
            }
            if let Some(d) = minus.filter(|&d| d > ci) {
                out.push([a, c, b, nb[d]]);
            }
        }
    }
    Some(())
}

/// The pencil of spheres through `a`, `b = nb[b]` and a third common neighbour, with the
/// common neighbours `common` (indices into `nb`) as the points that may lie inside.
struct Face<'a> {
    pts: &'a [Point3],
    nb: &'a [u32],
    dirs: &'a [Dir],
    frame: &'a Frame,
    common: &'a [u32],
    b: usize,
}

impl Face<'_> {
    fn p(&self, i: usize) -> &Point3 {
        &self.pts[self.nb[i] as usize]
    }

    /// The apexes (indices into `nb`) of the Delaunay tetrahedra on the `+` and `−` sides
    /// of `abc`, `c = nb[c]` (none on a side without points, none at all when `abc` is not
    /// a Delaunay face); `None` on a tie or a point in the plane.
    fn apexes(&self, c: usize) -> Option<[Option<usize>; 2]> {
        let b = self.b;
        let (pb, pc) = (self.p(b), self.p(c));
        let plane = self.frame.plane(&self.dirs[b], &self.dirs[c]);
        let spheres = self.frame.spheres(&self.dirs[b], &self.dirs[c]);
        // +1 when nb[p] is strictly inside the sphere through a, b, c and nb[q], for
        // `abcq` positively oriented.
        let inside = |q: usize, p: usize| {
            let d = self.dirs;
            self.frame
                .insphere(&spheres, pb, pc, self.p(q), self.p(p), &d[q], &d[p])
        };
        // best[0]: earliest `+` point; best[1]: latest `−` point.
        let mut best: [Option<usize>; 2] = [None, None];
        for &p in self.common {
            let p = p as usize;
            if p == c {
                continue;
            }
            let side = self.frame.side(&plane, pb, pc, self.p(p), &self.dirs[p]);
            let slot = match side {
                1 => &mut best[0],
                -1 => &mut best[1],
                _ => return None,
            };
            match *slot {
                None => *slot = Some(p),
                // `p` strictly inside the sphere of `abcq` (same side) comes earlier.
                Some(q) => match inside(q, p) * side {
                    1 => *slot = Some(p),
                    0 => return None,
                    _ => {}
                },
            }
        }
        if let [Some(up), Some(down)] = best {
            match inside(up, down) {
                1 => return Some([None, None]),
                0 => return None,
                _ => {}
            }
        }
        Some(best)
    }
}
