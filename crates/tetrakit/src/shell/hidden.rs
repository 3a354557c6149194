//! The inner vertices not yet on the current surface, in a static tree of boxes that a
//! removal queries by the region its new vertices can come from.
//!
//! Why a query needs no memory of the surface: removing outer vertices `U` with ring `L`
//! leaves the new hull `H' ⊇ Q`, and its bottom is the disk of `∂CH(L ∪ C)` on the tip's
//! side for any set `C` of inner vertices that holds the bottom's and lies in `H'`
//! ([`super::surface`]). Every inner vertex lies in `H'`, so `C` may hold more than it
//! needs: any region that contains the bottom's inner vertices will do. A query keeps
//! the hidden vertices in the closed box of `U ∪ L`, on the inner side of every plane it
//! is given (the facets of `CH(U ∪ L)`, which holds the removed region), and not
//! strictly inside `CH(L)` (such a point is strictly inside `CH(L ∪ C)`, no vertex of it
//! and on no face).
//! Whole boxes of the tree are passed over when [`Plane::box_side`] certifies them
//! outside, so the work is the boxes along the region's boundary and what it holds, not
//! what a removal's triangles cover: on the bent arcs of BENCHMARKS.md every surface
//! triangle spans the shell, and filing vertices under triangles moved each of them
//! again at every removal (`n²/16` moves), for about two vertices a cap on the bottom.

use crate::geom::{Plane, Point3};
use std::sync::Arc;

/// Points in a leaf of the tree.
const LEAF: usize = 8;

/// A box of the tree over `order[start..end]` and its two halves (`None` for a leaf).
struct Node {
    lo: Point3,
    hi: Point3,
    start: u32,
    end: u32,
    halves: Option<[u32; 2]>,
}

/// The inner vertices, each box the exact bounding box of its vertices.
struct Tree {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

impl Tree {
    fn new(pts: &[Point3], vertices: &[u32]) -> Tree {
        let mut t = Tree {
            nodes: Vec::new(),
            order: vertices.to_vec(),
        };
        if !t.order.is_empty() {
            t.split(pts, 0, t.order.len());
        }
        t
    }

    /// Adds the node over `order[start..end]` and its subtree; returns its index.
    fn split(&mut self, pts: &[Point3], start: usize, end: usize) -> u32 {
        let (lo, hi) = crate::geom::bounding_box(
            &self.order[start..end]
                .iter()
                .map(|&v| pts[v as usize])
                .collect::<Vec<_>>(),
        );
        let id = self.nodes.len() as u32;
        self.nodes.push(Node {
            lo,
            hi,
            start: start as u32,
            end: end as u32,
            halves: None,
        });
        if end - start > LEAF {
            // Halve along the longest side, at the median.
            let axis = (0..3)
                .max_by(|&a, &b| (hi[a] - lo[a]).total_cmp(&(hi[b] - lo[b])))
                .unwrap_or(0);
            let mid = (start + end) / 2;
            self.order[start..end].select_nth_unstable_by(mid - start, |&a, &b| {
                pts[a as usize][axis].total_cmp(&pts[b as usize][axis])
            });
            let left = self.split(pts, start, mid);
            let right = self.split(pts, mid, end);
            self.nodes[id as usize].halves = Some([left, right]);
        }
        id
    }
}

/// What a removal's new vertices can come from (module docs).
pub(super) struct Region<'r> {
    /// The closed box of the removed vertices and their ring.
    pub(super) lo: Point3,
    pub(super) hi: Point3,
    /// Planes the region is on the inner (non-positive) side of.
    pub(super) within: &'r [Plane],
    /// The facets of `CH(ring)` (outward): a point strictly inside all of them is left
    /// out. Empty when the ring is flat.
    pub(super) ring: &'r [Plane],
}

/// The planes of a region that still decide inside a box, as ranges of a query's arena
/// of plane indices: `within` those not certified to hold the whole box on their inner
/// side; `ring` those of `CH(ring)` not certified to have it strictly inside, or `None`
/// once one has the whole box strictly beyond it (every point passes the ring's test).
#[derive(Clone, Copy)]
struct Active {
    within: (u32, u32),
    ring: Option<(u32, u32)>,
}

impl Region<'_> {
    /// Every plane, its indices written to `arena`.
    fn all(&self, arena: &mut Vec<u32>) -> Active {
        let within = push(arena, 0..self.within.len());
        let ring = (!self.ring.is_empty()).then(|| push(arena, 0..self.ring.len()));
        Active { within, ring }
    }

    fn holds(&self, x: &Point3, active: Active, arena: &[u32]) -> bool {
        let planes = |(s, e): (u32, u32)| arena[s as usize..e as usize].iter().map(|&k| k as usize);
        (0..3).all(|k| self.lo[k] <= x[k] && x[k] <= self.hi[k])
            && planes(active.within).all(|k| self.within[k].side(x) <= 0)
            && active
                .ring
                .is_none_or(|r| planes(r).any(|k| self.ring[k].side(x) >= 0))
    }

    /// The planes that still decide inside the box `[lo, hi]` (appended to `arena`), or
    /// `None` when no point of it can be in the region (certified by
    /// [`Plane::box_side`]).
    fn narrow(
        &self,
        lo: &Point3,
        hi: &Point3,
        active: Active,
        (arena, pruner): (&mut Vec<u32>, &mut usize),
    ) -> Option<Active> {
        if (0..3).any(|k| hi[k] < self.lo[k] || self.hi[k] < lo[k]) {
            return None;
        }
        // The plane that last passed a box over often passes its neighbour too.
        if self
            .within
            .get(*pruner)
            .is_some_and(|h| h.box_side(lo, hi) == 1)
        {
            return None;
        }
        let start = arena.len() as u32;
        for i in active.within.0..active.within.1 {
            let k = arena[i as usize];
            match self.within[k as usize].box_side(lo, hi) {
                1 => {
                    arena.truncate(start as usize);
                    *pruner = k as usize;
                    return None;
                }
                -1 => {}
                _ => arena.push(k),
            }
        }
        let within = (start, arena.len() as u32);
        let Some((s, e)) = active.ring else {
            return Some(Active { within, ring: None });
        };
        let ring_start = arena.len() as u32;
        for i in s..e {
            let k = arena[i as usize];
            match self.ring[k as usize].box_side(lo, hi) {
                1 => {
                    arena.truncate(ring_start as usize);
                    return Some(Active { within, ring: None });
                }
                -1 => {}
                _ => arena.push(k),
            }
        }
        if arena.len() as u32 == ring_start {
            // Strictly inside `CH(ring)`.
            arena.truncate(start as usize);
            return None;
        }
        Some(Active {
            within,
            ring: Some((ring_start, arena.len() as u32)),
        })
    }
}

/// Appends `indices` to `arena`; returns their range.
fn push(arena: &mut Vec<u32>, indices: std::ops::Range<usize>) -> (u32, u32) {
    let start = arena.len() as u32;
    arena.extend(indices.map(|k| k as u32));
    (start, arena.len() as u32)
}

/// Hidden inner vertices, found by region.
#[derive(Clone)]
pub(super) struct Hidden {
    hidden: Vec<bool>,
    /// Hidden vertices per node of the tree.
    live: Vec<u32>,
    /// Each inner vertex's place in the tree's order.
    place: Vec<u32>,
    tree: Arc<Tree>,
    count: usize,
}

impl Hidden {
    /// `hidden` (indices into `pts`) are hidden.
    pub(super) fn new(pts: &[Point3], hidden: &[u32]) -> Hidden {
        let tree = Tree::new(pts, hidden);
        let mut place = vec![u32::MAX; pts.len()];
        for (k, &v) in tree.order.iter().enumerate() {
            place[v as usize] = k as u32;
        }
        let mut h = vec![false; pts.len()];
        for &v in hidden {
            h[v as usize] = true;
        }
        Hidden {
            live: tree.nodes.iter().map(|n| n.end - n.start).collect(),
            hidden: h,
            place,
            tree: Arc::new(tree),
            count: hidden.len(),
        }
    }

    /// True while `v` is a hidden inner vertex.
    pub(super) fn is_hidden(&self, v: u32) -> bool {
        self.hidden.get(v as usize).copied().unwrap_or(false)
    }

    /// `v` is on the surface now.
    pub(super) fn expose(&mut self, v: u32) {
        if !self.is_hidden(v) {
            return;
        }
        self.hidden[v as usize] = false;
        self.count -= 1;
        let place = self.place[v as usize];
        let mut node = 0;
        loop {
            self.live[node] -= 1;
            let Some([left, right]) = self.tree.nodes[node].halves else {
                break;
            };
            let in_left = place < self.tree.nodes[left as usize].end;
            node = if in_left { left } else { right } as usize;
        }
    }

    /// The hidden vertices in `region`, at most `limit` of them (`None`: more).
    pub(super) fn within(&self, pts: &[Point3], region: &Region, limit: usize) -> Option<Vec<u32>> {
        let mut out = Vec::new();
        let (mut arena, mut pruner) = (Vec::new(), usize::MAX);
        let mut stack = vec![(0usize, region.all(&mut arena))];
        while let Some((i, active)) = stack.pop() {
            let Some(node) = self.tree.nodes.get(i) else {
                continue;
            };
            if self.live[i] == 0 {
                continue;
            }
            let narrowed = region.narrow(&node.lo, &node.hi, active, (&mut arena, &mut pruner));
            let Some(active) = narrowed else {
                continue;
            };
            match node.halves {
                Some([l, r]) => stack.extend([(r as usize, active), (l as usize, active)]),
                None => {
                    let vs = &self.tree.order[node.start as usize..node.end as usize];
                    for &v in vs {
                        let x = &pts[v as usize];
                        if self.hidden[v as usize] && region.holds(x, active, &arena) {
                            if out.len() == limit {
                                return None;
                            }
                            out.push(v);
                        }
                    }
                }
            }
        }
        out.sort_unstable();
        Some(out)
    }

    /// How many inner vertices are still hidden.
    pub(super) fn count(&self) -> usize {
        self.count
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::orient3d;

    /// A query returns exactly the hidden points of its region, as testing every point
    /// finds them, and `None` exactly when they outnumber the limit: points on a small
    /// integer grid (duplicates, many on the planes and box sides) and random floats,
    /// some exposed, against random boxes and planes.
    #[test]
    fn a_query_finds_the_hidden_points_of_its_region() {
        let mut rng = crate::rng::Rng::new(5);
        for case in 0..400 {
            let grid = case % 2 == 0;
            let mut point = || -> Point3 {
                if grid {
                    [0; 3].map(|_| rng.below(7) as f64)
                } else {
                    [0; 3].map(|_| rng.unit() * 6.0)
                }
            };
            let pts: Vec<Point3> = (0..300).map(|_| point()).collect();
            let inner: Vec<u32> = (0..300).filter(|v| v % 5 != 0).collect();
            let (x, y) = (point(), point());
            let lo: Point3 = std::array::from_fn(|k| x[k].min(y[k]) - 1.0);
            let hi: Point3 = std::array::from_fn(|k| x[k].max(y[k]) + 1.0);
            let triples: Vec<[Point3; 3]> = (0..6).map(|_| [point(), point(), point()]).collect();
            let planes: Vec<Plane> = triples
                .iter()
                .map(|[a, b, c]| Plane::new(a, b, c))
                .collect();
            let (within, ring) = planes.split_at(case % 4);
            let mut hidden = Hidden::new(&pts, &inner);
            for &v in inner.iter().filter(|&&v| v % 7 == 0) {
                hidden.expose(v);
            }
            let region = Region {
                lo,
                hi,
                within,
                ring,
            };
            let side = |k: usize, x: &Point3| {
                let [a, b, c] = &triples[k];
                orient3d(a, b, c, x)
            };
            let (nw, nr) = (within.len(), ring.len());
            let expected: Vec<u32> = inner
                .iter()
                .copied()
                .filter(|&v| v % 7 != 0)
                .filter(|&v| {
                    let x = &pts[v as usize];
                    (0..3).all(|k| lo[k] <= x[k] && x[k] <= hi[k])
                        && (0..nw).all(|k| side(k, x) <= 0)
                        && (nr == 0 || (nw..nw + nr).any(|k| side(k, x) >= 0))
                })
                .collect();
            assert_eq!(
                hidden.within(&pts, &region, usize::MAX),
                Some(expected.clone()),
                "case {case}"
            );
            let limit = expected.len().saturating_sub(case % 3);
            let got = hidden.within(&pts, &region, limit);
            assert_eq!(got.is_none(), expected.len() > limit, "case {case}");
        }
    }
}
