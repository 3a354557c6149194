//! The exact stage on a face whose holes enclose no area (isolated sites, trees of
//! edges): dynamic programming over the regions that cutting out triangles leaves (the
//! scheme of Grantson, Borgelt and Levcopoulos, "Minimum weight triangulation by cutting
//! out triangles", 2005).
//!
//! A *region* is bounded by a run of the face's walk, occurrences `i..=j`, followed by a
//! path through sites, back to occurrence `i` (or by a cycle of sites alone). Every
//! triangulation of a region has one triangle on its *base*, the edge from the last
//! vertex `u` back to the first `v`. Its apex is
//! - another vertex of the region's boundary: the triangle cuts the region in two
//!   regions of the same form (the part before the apex, the part after it), or
//! - a site inside the region: the rest is one region, the path extended by that site.
//!
//! So the lightest triangulation of a region is the best apex plus the lightest
//! triangulations of what is left, and memoising regions makes the search polynomial
//! when the paths stay short: a face with `k` isolated sites costs about what the
//! polygon DP does, plus `O(d²)` regions per site of degree `d`, instead of the
//! `d₁·d₂·…·d_k` polygon DPs of branching over the edges that join each site.
//!
//! The sites of a tree hole are sites like the others and its edges are *fixed*: usable
//! between their ends, of no weight (they are in the triangulation already), and never
//! crossed (alive edges cross no certain edge). Each ends up a side of the triangles on
//! it: a segment between vertices of a triangulated region that crosses no side and
//! passes through no vertex is a side. A hole that encloses area is not for this DP,
//! which would have to triangulate its inside; the face search splices it in first.
//!
//! **Why each cut is a triangle of the region, empty.** Diagonals between occurrences
//! come from the polygon DP's rows (usable, inside the walk's wedges at both ends, across
//! no cut); segments from a site to an occurrence are checked the same way. A usable
//! segment crosses no walk edge (alive edges cross no certain edge) and passes through no
//! site. A cut triangle `u v a` must moreover have `a` strictly left of `u → v`, leave
//! each of its corners on the region's boundary inside the region's wedge there, cross
//! no path edge of the region, and hold no site strictly inside. Then no boundary vertex
//! lies inside it (a boundary run entering it would cross a side or leave a corner's
//! wedge), so it lies in the region, and every site of the region ends up a vertex. On a
//! region bounded by walk edges and one diagonal, a triangle on two more diagonals needs
//! only its orientation and emptiness: its sides leave their ends inside the walk's
//! wedges and cannot cross the diagonal they share an end with. Likewise, a side ending
//! at an occurrence strictly inside the run leaves it inside the region (the walk's
//! wedge is the region's there), so only path crossings decide whether it stays inside.

use super::polygon::{Rows, Solution, clear_of, cmp_edge_sets, crosses, upper_index};
use super::walks::in_wedge;
use crate::control::Control;
use crate::geom::{DoubleDouble, Point2, orient2d};
use crate::planar::edge_key as key;
use rustc_hash::FxBuildHasher;
use std::cell::RefCell;
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};

/// The lightest triangulation of the face bounded by the counter-clockwise `walk` with
/// the `sites` of its flat holes inside (their edges `fixed`), whose new edges satisfy
/// `usable` and cross no edge of `cuts`: the new edges and their weight; `None` when
/// there is none, or once `ctl` is stopped (looked at region by region).
pub(super) fn walk_with_sites(
    points: &[Point2],
    walk: &[u32],
    sites: &[u32],
    fixed: &HashSet<[u32; 2]>,
    cuts: &[[u32; 2]],
    usable: &(dyn Fn([u32; 2]) -> bool + Sync),
    ctl: &Control,
) -> Option<Solution> {
    let m = walk.len();
    if m < 3 {
        return None;
    }
    let dp = Dp::new(points, walk, sites, fixed, cuts, usable);
    let root = Region {
        chain: Some((0, m as u32 - 1)),
        path: Vec::new(),
    };
    dp.solve(root, ctl)
}

/// A region: walk occurrences `i..=j` (if any), then the sites `path` (indices into the
/// face's sites), counter-clockwise, closed back to the first vertex.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
struct Region {
    chain: Option<(u32, u32)>,
    path: Vec<u32>,
}

impl Region {
    fn chain_len(&self) -> usize {
        self.chain.map_or(0, |(i, j)| (j - i + 1) as usize)
    }

    fn len(&self) -> usize {
        self.chain_len() + self.path.len()
    }

    /// The boundary from position 0 through `t`, closed by the segment back.
    fn prefix(&self, t: usize) -> Region {
        let c = self.chain_len();
        match self.chain {
            Some((i, _)) if t < c => Region {
                chain: Some((i, i + t as u32)),
                path: Vec::new(),
            },
            chain => Region {
                chain,
                path: self.path[..=t - c].to_vec(),
            },
        }
    }

    /// The boundary from position `t` to the end, closed by the base's last vertex.
    fn suffix(&self, t: usize) -> Region {
        let c = self.chain_len();
        match self.chain {
            Some((i, j)) if t < c => Region {
                chain: Some((i + t as u32, j)),
                path: self.path.clone(),
            },
            _ => Region {
                chain: None,
                path: self.path[t - c..].to_vec(),
            },
        }
    }
}

/// The apex of the triangle on a region's base: a boundary position, or a free site.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Apex {
    Corner(usize),
    Site(u32),
}

/// The lightest triangulation of a region: the weight of its edges strictly inside it
/// and of its base if that is a new edge, and the apex on its base (`None`: the region
/// has no triangulation).
#[derive(Clone, Copy)]
struct Best {
    w: DoubleDouble,
    apex: Option<Apex>,
}

/// A [`Best`] in 24 bytes for the dense table: the apex as one code (a corner's
/// position, a site's index with the top bit set, or a sentinel).
#[derive(Clone, Copy)]
struct Packed {
    w: DoubleDouble,
    code: u32,
}

impl Packed {
    const UNSOLVED: Packed = Packed {
        w: DoubleDouble::ZERO,
        code: u32::MAX,
    };
    const NONE: u32 = u32::MAX - 1;
    const SITE: u32 = 1 << 31;

    fn pack(b: Best) -> Packed {
        let code = match b.apex {
            None => Packed::NONE,
            Some(Apex::Corner(t)) => t as u32,
            Some(Apex::Site(q)) => Packed::SITE | q,
        };
        Packed { w: b.w, code }
    }

    fn unpack(self) -> Option<Best> {
        let apex = match self.code {
            u32::MAX => return None,
            Packed::NONE => None,
            c if c & Packed::SITE != 0 => Some(Apex::Site(c & !Packed::SITE)),
            c => Some(Apex::Corner(c as usize)),
        };
        Some(Best { w: self.w, apex })
    }
}

struct Dp<'a> {
    points: &'a [Point2],
    walk: &'a [u32],
    sites: &'a [u32],
    /// Valid diagonals between walk occurrences.
    rows: Rows,
    /// Per site, bit `o`: the segment to walk occurrence `o` is usable, inside the walk's
    /// wedge there, and across no cut.
    to_walk: Vec<Vec<u64>>,
    /// Per pair of sites (row-major): the segment between them is usable and across no
    /// cut, or a fixed edge.
    between: Vec<bool>,
    /// Edges between sites already in the triangulation (hole edges): not counted.
    fixed: &'a HashSet<[u32; 2]>,
    /// A bound on the number of lengths in any sum compared.
    terms: usize,
    /// Solved regions: bounded by a run of the walk and one diagonal (by the run's ends,
    /// in an upper triangle), and the others.
    chains: RefCell<Vec<Packed>>,
    others: RefCell<HashMap<Region, Best, FxBuildHasher>>,
}

fn bit(row: &[u64], o: usize) -> bool {
    row[o / 64] >> (o % 64) & 1 == 1
}

impl<'a> Dp<'a> {
    fn new(
        points: &'a [Point2],
        walk: &'a [u32],
        sites: &'a [u32],
        fixed: &'a HashSet<[u32; 2]>,
        cuts: &[[u32; 2]],
        usable: &(dyn Fn([u32; 2]) -> bool + Sync),
    ) -> Dp<'a> {
        let m = walk.len();
        let ok = |e: [u32; 2]| usable(e) && clear_of(points, cuts, &e);
        let to_walk = (sites.iter())
            .map(|&q| {
                let mut row = vec![0u64; m.div_ceil(64)];
                for o in 0..m {
                    let (prev, next) = (walk[(o + m - 1) % m], walk[(o + 1) % m]);
                    if ok(key(walk[o], q)) && in_wedge(points, walk[o], next, prev, q) {
                        row[o / 64] |= 1 << (o % 64);
                    }
                }
                row
            })
            .collect();
        let between = (sites.iter())
            .flat_map(|&a| sites.iter().map(move |&b| (a, b)))
            .map(|(a, b)| a != b && (fixed.contains(&key(a, b)) || ok(key(a, b))))
            .collect();
        Dp {
            points,
            walk,
            sites,
            rows: Rows::new(points, walk, cuts, usable),
            to_walk,
            between,
            fixed,
            terms: 3 * (m + sites.len()) + 3,
            chains: RefCell::new(vec![Packed::UNSOLVED; m * (m - 1) / 2]),
            others: Default::default(),
        }
    }

    /// Where the region bounded by the walk's run `i..=j` and a diagonal is kept.
    fn chain_slot(&self, r: &Region) -> Option<usize> {
        let (i, j) = r.chain.filter(|_| r.path.is_empty())?;
        let (i, j, m) = (i as usize, j as usize, self.walk.len());
        Some(upper_index(m, i, j))
    }

    fn get(&self, r: &Region) -> Option<Best> {
        match self.chain_slot(r) {
            Some(k) => self.chains.borrow()[k].unpack(),
            None => self.others.borrow().get(r).copied(),
        }
    }

    fn set(&self, r: Region, best: Best) {
        match self.chain_slot(&r) {
            Some(k) => self.chains.borrow_mut()[k] = Packed::pack(best),
            None => {
                self.others.borrow_mut().insert(r, best);
            }
        }
    }

    /// The site at boundary position `t` of `r`.
    fn vertex(&self, r: &Region, t: usize) -> u32 {
        match r.chain {
            Some((i, _)) if t < r.chain_len() => self.walk[i as usize + t],
            _ => self.sites[r.path[t - r.chain_len()] as usize],
        }
    }

    fn joined(&self, a: u32, b: u32) -> bool {
        self.between[a as usize * self.sites.len() + b as usize]
    }

    /// The site of the apex `a` of a triangle on the base of `r`.
    fn apex_site(&self, r: &Region, a: Apex) -> u32 {
        match a {
            Apex::Corner(t) => self.vertex(r, t),
            Apex::Site(q) => self.sites[q as usize],
        }
    }

    /// What cutting the triangle with apex `a` leaves of `r`: regions of at least three
    /// vertices.
    fn pieces(&self, r: &Region, a: Apex) -> [Option<Region>; 2] {
        let n = r.len();
        match a {
            Apex::Corner(t) => [
                (t >= 2).then(|| r.prefix(t)),
                (n - t >= 3).then(|| r.suffix(t)),
            ],
            Apex::Site(q) => {
                let mut rest = r.clone();
                rest.path.push(q);
                [Some(rest), None]
            }
        }
    }

    /// The sides `v–a` and `a–u` of the triangle with apex `a` on the base `u → v` of
    /// `r`, each unless it is on the boundary of `r` (the new edges).
    fn sides(&self, r: &Region, a: Apex) -> [Option<[u32; 2]>; 2] {
        let n = r.len();
        let (u, v, c) = (
            self.vertex(r, n - 1),
            self.vertex(r, 0),
            self.apex_site(r, a),
        );
        let (first, last) = match a {
            Apex::Corner(t) => (t == 1, t == n - 2),
            Apex::Site(_) => (false, false),
        };
        [(!first).then(|| key(v, c)), (!last).then(|| key(c, u))]
    }

    /// The sides that are not fixed edges (those are in the triangulation already).
    fn new_edges(&self, sides: [Option<[u32; 2]>; 2]) -> impl Iterator<Item = [u32; 2]> + '_ {
        sides
            .into_iter()
            .flatten()
            .filter(|e| !self.fixed.contains(e))
    }

    /// True when no site other than those on the boundary of `r` and `c` lies strictly
    /// inside the triangle `u v c`.
    fn empty(&self, r: &Region, u: u32, v: u32, c: u32) -> bool {
        let p = |x: u32| &self.points[x as usize];
        let (pu, pv, pc) = (p(u), p(v), p(c));
        let lo = [pu[0].min(pv[0]).min(pc[0]), pu[1].min(pv[1]).min(pc[1])];
        let hi = [pu[0].max(pv[0]).max(pc[0]), pu[1].max(pv[1]).max(pc[1])];
        !self.sites.iter().enumerate().any(|(q, &s)| {
            let ps = p(s);
            s != c
                && (lo[0]..=hi[0]).contains(&ps[0])
                && (lo[1]..=hi[1]).contains(&ps[1])
                && !r.path.contains(&(q as u32))
                && orient2d(pu, pv, ps) > 0
                && orient2d(pv, pc, ps) > 0
                && orient2d(pc, pu, ps) > 0
        })
    }

    /// The full test of a triangle on the base of `r` whose sides are usable (see the
    /// module documentation): orientation, wedges at its corners on the boundary, no
    /// path edge crossed, nothing inside.
    fn fits(&self, r: &Region, a: Apex) -> bool {
        let n = r.len();
        let at = |t: usize| self.vertex(r, t % n);
        let (u, v, c) = (at(n - 1), at(0), self.apex_site(r, a));
        let p = |x: u32| &self.points[x as usize];
        if orient2d(p(u), p(v), p(c)) <= 0 {
            return false;
        }
        let [vc, cu] = self.sides(r, a);
        let c0 = r.chain_len();
        // The wedge at boundary position `t` holds the direction to `d`. An occurrence
        // inside the run has the walk's wedge, which the rows checked already.
        let wedge = |t: usize, d: u32| in_wedge(self.points, at(t), at(t + 1), at(t + n - 1), d);
        let corners_ok = match a {
            Apex::Corner(t) if t + 1 < c0 => true,
            Apex::Corner(t) => {
                (vc.is_none() || (wedge(0, c) && wedge(t, v)))
                    && (cu.is_none() || (wedge(n - 1, c) && wedge(t, u)))
            }
            Apex::Site(_) => wedge(0, c) && wedge(n - 1, c),
        };
        if !corners_ok {
            return false;
        }
        // Path edges: consecutive boundary positions with a site of the path at one end,
        // from the run's last occurrence on (not over the whole run: this is per option).
        let first = if r.chain.is_some() { c0 - 1 } else { 0 };
        let sides = [vc, cu];
        let crossing = (first..n)
            .map(|t| [at(t), at(t + 1)])
            .any(|e| sides.iter().flatten().any(|s| crosses(self.points, &e, s)));
        !crossing && self.empty(r, u, v, c)
    }

    /// The apexes of the triangles the base of `r` can have.
    fn options(&self, r: &Region) -> Vec<Apex> {
        let n = r.len();
        let mut out = Vec::new();
        let free = (0..self.sites.len() as u32).filter(|q| !r.path.contains(q));
        match r.chain {
            Some((i, j)) if r.path.is_empty() => {
                let (i, j) = (i as usize, j as usize);
                let (wi, wj) = (self.walk[i], self.walk[j]);
                let p = |x: u32| &self.points[x as usize];
                self.rows.common(i, j, |k| {
                    let wk = self.walk[k];
                    if orient2d(p(wi), p(wk), p(wj)) > 0 && self.empty(r, wj, wi, wk) {
                        out.push(Apex::Corner(k - i));
                    }
                });
                for q in free {
                    let row = &self.to_walk[q as usize];
                    if bit(row, i) && bit(row, j) && self.fits(r, Apex::Site(q)) {
                        out.push(Apex::Site(q));
                    }
                }
            }
            Some((i, j)) => {
                let (i, j) = (i as usize, j as usize);
                let last = *r.path.last().expect("a path");
                let c = r.chain_len();
                // Occurrences joined to both ends of the base: the next one (a walk
                // edge) or a diagonal from `i`, and a segment to `last` (or the path's
                // first edge, at `j`).
                let to_last = &self.to_walk[last as usize];
                let from_i = self.rows.row(i);
                for w in (i + 1) / 64..=j / 64 {
                    let mut x = to_last[w] & from_i[w];
                    while x != 0 {
                        let k = w * 64 + x.trailing_zeros() as usize;
                        x &= x - 1;
                        if k > i + 1 && k <= j {
                            out.push(Apex::Corner(k - i));
                        }
                    }
                }
                // (With a run of one occurrence there is none: position 1 is the path's.)
                let ends = [i + 1, j].into_iter().filter(|&k| k > i && k <= j);
                for k in ends {
                    let side_u = (k == j && r.path.len() == 1) || bit(to_last, k);
                    let side_v = k == i + 1 || self.rows.ok(i, k);
                    if side_u && side_v && !out.contains(&Apex::Corner(k - i)) {
                        out.push(Apex::Corner(k - i));
                    }
                }
                for s in 0..r.path.len() - 1 {
                    let q = r.path[s];
                    if bit(&self.to_walk[q as usize], i)
                        && (s + 2 == r.path.len() || self.joined(q, last))
                    {
                        out.push(Apex::Corner(c + s));
                    }
                }
                for q in free {
                    if bit(&self.to_walk[q as usize], i) && self.joined(q, last) {
                        out.push(Apex::Site(q));
                    }
                }
                out.retain(|&a| self.fits(r, a));
            }
            None => {
                let (first, last) = (r.path[0], r.path[n - 1]);
                for t in 1..n - 1 {
                    let q = r.path[t];
                    if (t == 1 || self.joined(first, q)) && (t == n - 2 || self.joined(q, last)) {
                        out.push(Apex::Corner(t));
                    }
                }
                for q in free {
                    if self.joined(first, q) && self.joined(q, last) {
                        out.push(Apex::Site(q));
                    }
                }
                out.retain(|&a| self.fits(r, a));
            }
        }
        out
    }

    /// Solves `root` and every region it needs, children before parents (an explicit
    /// stack: regions nest as deep as the walk is long).
    fn solve(&self, root: Region, ctl: &Control) -> Option<Solution> {
        // A region comes back with its options once the regions they leave are solved.
        let mut stack: Vec<(Region, Option<Vec<Apex>>)> = vec![(root.clone(), None)];
        while let Some((r, options)) = stack.pop() {
            if ctl.is_stopped() {
                return None;
            }
            if self.get(&r).is_some() {
                continue;
            }
            let options = match options {
                Some(o) => o,
                None => {
                    let o = self.options(&r);
                    let missing: Vec<Region> = (o.iter())
                        .flat_map(|&a| self.pieces(&r, a))
                        .flatten()
                        .filter(|p| self.get(p).is_none())
                        .collect();
                    if !missing.is_empty() {
                        stack.push((r, Some(o)));
                        stack.extend(missing.into_iter().map(|p| (p, None)));
                        continue;
                    }
                    o
                }
            };
            let best = self.best(&r, &options);
            self.set(r, best);
        }
        let top = self.get(&root).expect("solved");
        top.apex?;
        let mut edges = Vec::new();
        self.collect(&root, &mut edges);
        Some(Solution {
            edges,
            weight: top.w.interval(self.terms),
        })
    }

    /// The lightest of `options` for `r`, its pieces solved.
    fn best(&self, r: &Region, options: &[Apex]) -> Best {
        let mut best = Best {
            w: DoubleDouble::ZERO,
            apex: None,
        };
        let p = |x: u32| &self.points[x as usize];
        for &a in options {
            let (pieces, sides) = (self.pieces(r, a), self.sides(r, a));
            // The pieces' weights include their bases: the sides, but the second side
            // of a site apex. A piece without a triangulation rules the option out.
            let mut weights = (pieces.iter().flatten())
                .map(|piece| self.get(piece).filter(|b| b.apex.is_some()).map(|b| b.w));
            let Some(mut w) = weights.try_fold(DoubleDouble::ZERO, |acc, w| Some(acc.plus(w?)))
            else {
                continue;
            };
            if let (Apex::Site(_), [_, Some(e)]) = (a, sides)
                && !self.fixed.contains(&e)
            {
                w = w.plus(DoubleDouble::length(p(e[0]), p(e[1])));
            }
            let better = match best.apex {
                None => true,
                Some(cur) => match w.certain_cmp(best.w, self.terms) {
                    Some(o) => o == Ordering::Less,
                    None => {
                        let (mine, theirs) = (self.edges_with(r, a), self.edges_with(r, cur));
                        cmp_edge_sets(self.points, &mine, &theirs) == Ordering::Less
                    }
                },
            };
            if better {
                best = Best { w, apex: Some(a) };
            }
        }
        best.w = best.w.plus(self.base_length(r));
        best
    }

    /// The length of the base of `r` if it is a new edge (`r` is not the whole face and
    /// its base is not a fixed edge); a region's weight includes it.
    fn base_length(&self, r: &Region) -> DoubleDouble {
        let n = r.len();
        let (u, v) = (self.vertex(r, n - 1), self.vertex(r, 0));
        let whole = r.path.is_empty() && r.chain == Some((0, self.walk.len() as u32 - 1));
        if whole || self.fixed.contains(&key(u, v)) {
            return DoubleDouble::ZERO;
        }
        DoubleDouble::length(&self.points[u as usize], &self.points[v as usize])
    }

    /// The new edges of `r`'s triangulation with apex `a` on its base, pieces solved.
    fn edges_with(&self, r: &Region, a: Apex) -> Vec<[u32; 2]> {
        let mut out: Vec<[u32; 2]> = self.new_edges(self.sides(r, a)).collect();
        let pieces = self.pieces(r, a);
        for piece in pieces.iter().flatten() {
            self.collect(piece, &mut out);
        }
        out
    }

    /// Appends the new edges of the lightest triangulation of the solved region `r`.
    fn collect(&self, r: &Region, out: &mut Vec<[u32; 2]>) {
        let mut stack = vec![r.clone()];
        while let Some(r) = stack.pop() {
            let Some(a) = self.get(&r).and_then(|b| b.apex) else {
                continue;
            };
            out.extend(self.new_edges(self.sides(&r, a)));
            stack.extend(self.pieces(&r, a).into_iter().flatten());
        }
    }
}
