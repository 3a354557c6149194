//! The flips between the tetrahedralizations found, and the graph they make.
//!
//! A flip that keeps every point replaces the tetrahedra of one triangulation of a
//! circuit (a minimal affinely dependent set `Z = Z₊ ∪ Z₋` whose two parts' hulls cross)
//! joined to a common link by the other triangulation joined to the same link. In three
//! dimensions with every point kept, `|Z₊|, |Z₋| ≥ 2`: five points with the segment
//! `de` crossing the triangle `abc` (the 2-3 flip and its inverse 3-2; the link is empty),
//! or four coplanar points whose diagonals `ab`, `de` cross (the link is the apex of the
//! tetrahedra on the quadrilateral: one on the hull, the 2-2 flip; two inside, the 4-4
//! flip). Every flip is seen from a pair of tetrahedra sharing a face `abc` with apexes
//! `d`, `e`: `de` crosses the open triangle (2-3), or the open edge `ab` (2-2 or 4-4).
//! The 3-2 flip is the inverse of a 2-3 flip, so it is the same edge of the graph, found
//! from the other end.

use super::candidates::Candidates;
use super::enumerate::Family;
use crate::control::Control;
use crate::geom::{Point3, orient3d};
use crate::partition::{find, singletons, union};
use rayon::prelude::*;
use rustc_hash::FxHashMap as HashMap;
use serde::Serialize;
use std::collections::VecDeque;

/// Which flip joins two tetrahedralizations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FlipKind {
    /// Two tetrahedra on a face become three around an edge (or back: 3-2).
    TwoThree,
    /// Two tetrahedra on a quadrilateral of the hull swap its diagonal.
    TwoTwo,
    /// Four tetrahedra on an inner quadrilateral swap its diagonal.
    FourFour,
}

/// Why the graph was not built: stopped, or a flip from tetrahedralization `from` led
/// outside the list.
pub(super) enum Halt {
    Stopped,
    Outside { from: usize },
}

/// Per tetrahedralization, its flip neighbours (index, kind), ascending.
pub(super) type Adjacency = Vec<Vec<(u32, FlipKind)>>;

/// The flip neighbours of every tetrahedralization in `all` (complete: a flip leading
/// outside `all` is [`Halt::Outside`]).
pub(super) fn adjacency(
    pts: &[Point3],
    c: &Candidates,
    all: &Family,
    ctl: &Control,
) -> Result<Adjacency, Halt> {
    let index: HashMap<&[u16], u32> = (0..all.len()).map(|i| (all.get(i), i as u32)).collect();
    let out: Vec<Vec<(u32, FlipKind)>> = (0..all.len())
        .into_par_iter()
        .map(|i| {
            let t = all.get(i);
            ctl.check().map_err(|_| Halt::Stopped)?;
            flips(pts, c, t)
                .into_iter()
                .map(|(kind, next)| {
                    let j = index.get(&next[..]).ok_or(Halt::Outside { from: i })?;
                    Ok((*j, kind))
                })
                .collect()
        })
        .collect::<Result<_, Halt>>()?;
    // A 3-2 flip is seen from its 2-3 end only: every edge both ways.
    let mut adj: Adjacency = out.clone();
    for (i, ns) in out.iter().enumerate() {
        for &(j, kind) in ns {
            adj[j as usize].push((i as u32, kind));
        }
    }
    for ns in &mut adj {
        ns.sort_unstable();
        ns.dedup();
    }
    Ok(adj)
}

/// The tetrahedralizations one flip away from `t` (candidate ids, ascending), with
/// repeats (a 4-4 flip is seen from two pairs).
fn flips(pts: &[Point3], c: &Candidates, t: &[u16]) -> Vec<(FlipKind, Vec<u16>)> {
    let mut across: HashMap<u32, [Option<u16>; 2]> = HashMap::default();
    for &x in t {
        for &(f, side) in &c.tet_faces[x as usize] {
            across.entry(f).or_default()[side as usize] = Some(x);
        }
    }
    let other = |f: u32, x: u16| -> Option<u16> {
        let [a, b] = across.get(&f)?;
        if *a == Some(x) { *b } else { *a }
    };
    let mut out = Vec::new();
    for (&f, pair) in &across {
        let [Some(below), Some(above)] = *pair else {
            continue;
        };
        let [a, b, cc] = c.faces[f as usize].v;
        let (d, e) = (apex(c, below, f), apex(c, above, f));
        let p = |v: u32| &pts[v as usize];
        let s =
            [(a, b, cc), (b, cc, a), (cc, a, b)].map(|(x, y, _)| orient3d(p(d), p(e), p(x), p(y)));
        let replace = |old: &[u16], new: &[[u32; 4]]| -> Option<Vec<u16>> {
            let mut next: Vec<u16> = t.iter().copied().filter(|x| !old.contains(x)).collect();
            for q in new {
                let mut key = *q;
                key.sort_unstable();
                next.push(*c.ids.get(&key)?);
            }
            next.sort_unstable();
            Some(next)
        };
        if s[0] != 0 && s[0] == s[1] && s[1] == s[2] {
            let new = [[a, b, d, e], [b, cc, d, e], [cc, a, d, e]];
            out.extend(replace(&[below, above], &new).map(|n| (FlipKind::TwoThree, n)));
            continue;
        }
        // `de` through the open edge opposite the zero's third corner.
        let Some(k) =
            (0..3).find(|&k| s[k] == 0 && s[(k + 1) % 3] == s[(k + 2) % 3] && s[(k + 1) % 3] != 0)
        else {
            continue;
        };
        let ring = [a, b, cc];
        let (x, y, top) = (ring[k], ring[(k + 1) % 3], ring[(k + 2) % 3]);
        let (fd, fe) = (face_of(c, below, [x, y, d]), face_of(c, above, [x, y, e]));
        if c.faces[fd as usize].hull {
            let new = [[d, e, x, top], [d, e, y, top]];
            out.extend(replace(&[below, above], &new).map(|n| (FlipKind::TwoTwo, n)));
            continue;
        }
        let (Some(u), Some(w)) = (other(fd, below), other(fe, above)) else {
            continue;
        };
        let bottom = apex(c, u, fd);
        if apex(c, w, fe) != bottom {
            continue;
        }
        let new = [
            [d, e, x, top],
            [d, e, y, top],
            [d, e, x, bottom],
            [d, e, y, bottom],
        ];
        out.extend(replace(&[below, above, u, w], &new).map(|n| (FlipKind::FourFour, n)));
    }
    out
}

/// The corner of candidate `t` off its face `f`.
fn apex(c: &Candidates, t: u16, f: u32) -> u32 {
    let v = c.faces[f as usize].v;
    *c.tets[t as usize]
        .iter()
        .find(|x| !v.contains(x))
        .expect("a face has three of the four corners")
}

/// The id of the face of candidate `t` with corners `v`.
fn face_of(c: &Candidates, t: u16, mut v: [u32; 3]) -> u32 {
    v.sort_unstable();
    c.tet_faces[t as usize]
        .iter()
        .map(|&(f, _)| f)
        .find(|&f| c.faces[f as usize].v == v)
        .expect("the face is one of the candidate's")
}

/// Component labels (0 for the component of the first tetrahedralization, then in order
/// of first member) and each component's size.
pub(super) fn components(adj: &Adjacency) -> (Vec<u32>, Vec<usize>) {
    let mut parent = singletons(adj.len());
    for (i, ns) in adj.iter().enumerate() {
        for &(j, _) in ns {
            union(&mut parent, i as u32, j);
        }
    }
    let mut label: HashMap<u32, u32> = HashMap::default();
    let mut sizes = Vec::new();
    let labels = (0..adj.len() as u32)
        .map(|i| {
            let root = find(&mut parent, i);
            let l = *label.entry(root).or_insert_with(|| {
                sizes.push(0);
                sizes.len() as u32 - 1
            });
            sizes[l as usize] += 1;
            l
        })
        .collect();
    (labels, sizes)
}

/// The longest shortest flip path of a connected graph (a breadth-first search from every
/// tetrahedralization).
pub(super) fn diameter(adj: &Adjacency, ctl: &Control) -> Result<usize, Halt> {
    (0..adj.len())
        .into_par_iter()
        .map(|s| {
            ctl.check().map_err(|_| Halt::Stopped)?;
            let mut dist = vec![u32::MAX; adj.len()];
            dist[s] = 0;
            let mut queue = VecDeque::from([s as u32]);
            let mut far = 0;
            while let Some(i) = queue.pop_front() {
                far = dist[i as usize];
                for &(j, _) in &adj[i as usize] {
                    if dist[j as usize] == u32::MAX {
                        dist[j as usize] = far + 1;
                        queue.push_back(j);
                    }
                }
            }
            Ok(far as usize)
        })
        .try_reduce(|| 0, |a, b| Ok(a.max(b)))
}
