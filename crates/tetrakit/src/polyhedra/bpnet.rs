//! BP-nets (thesis §3.2.1, §3.3.1): finding them (Theorem 3.4), and deciding exactly
//! whether they are proper and pairwise disjoint.

use super::{Polyhedron, SurfaceGraph};
use crate::geom::{Point3, orient3d, tetrahedra_overlap};
use crate::mesh::grid::{Aabb, TriangleGrid, aabb, boxes_meet};
use crate::mesh::sorted_face;

/// A BP-net `B(p v0 v1 … vm q)`: poles `p`, `q` and a path `v0 … vm` (m ≥ 3) whose every
/// vertex is adjacent to both poles and whose inner vertices have degree 4. A bipyramid
/// (a closed path) has `path[0] == path[m]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BpNet {
    /// Pole p.
    pub p: u32,
    /// Pole q.
    pub q: u32,
    /// The path v0 … vm.
    pub path: Vec<u32>,
}

impl BpNet {
    /// The tetrahedra `p q v_j v_{j+1}` of the tetrahedralized BP-net.
    pub fn tetrahedra(&self) -> Vec<[u32; 4]> {
        self.path
            .windows(2)
            .map(|w| [self.p, self.q, w[0], w[1]])
            .collect()
    }
}

/// All maximal BP-nets on the surface: maximal paths of two or more degree-4 vertices
/// with the same two common neighbours (Theorem 3.4), each reported once.
///
/// ```
/// use tetrakit::polyhedra::{Polyhedron, SurfaceGraph, bp_nets};
/// let p = tetrakit::polyhedra::generate::bipyramid(5, 1);
/// let nets = bp_nets(&SurfaceGraph::new(&p));
/// assert_eq!(nets.len(), 1); // the closed bipyramid around its axis
/// assert_eq!(nets[0].path.first(), nets[0].path.last());
/// ```
pub fn bp_nets(g: &SurfaceGraph) -> Vec<BpNet> {
    let mut out: Vec<BpNet> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for v in 0..g.len() as u32 {
        if g.degree(v) != 4 {
            continue;
        }
        let r = g.ring(v);
        for (p, q) in [(r[1], r[3]), (r[0], r[2])] {
            let key = (v, p.min(q), p.max(q));
            if seen.contains(&key) {
                continue;
            }
            let inner = |x: u32| {
                g.degree(x) == 4 && {
                    let rx = g.ring(x);
                    rx.contains(&p) && rx.contains(&q)
                }
            };
            // Walk both ways from v along neighbours that are not the poles; the second
            // walk collects its half backwards.
            let mut path = vec![v];
            let mut left = Vec::new();
            let mut closed = false;
            for dir in 0..2 {
                let mut prev = v;
                let mut cur = other_neighbours(g, v, p, q)[dir];
                loop {
                    if cur == v {
                        closed = true;
                        break;
                    }
                    if dir == 0 {
                        path.push(cur);
                    } else {
                        left.push(cur);
                    }
                    if !inner(cur) {
                        break;
                    }
                    let next = other_neighbours(g, cur, p, q);
                    let nxt = if next[0] == prev { next[1] } else { next[0] };
                    prev = cur;
                    cur = nxt;
                }
                if closed {
                    path.push(v);
                    break;
                }
            }
            left.reverse();
            left.extend(path);
            let path = left;
            let interior = path.len().saturating_sub(2);
            for &x in &path[1..path.len() - 1] {
                seen.insert((x, p.min(q), p.max(q)));
            }
            if closed || interior >= 2 {
                out.push(BpNet {
                    p: p.min(q),
                    q: p.max(q),
                    path,
                });
            }
        }
    }
    out
}

/// The two neighbours of degree-4 vertex `x` other than `p` and `q`.
fn other_neighbours(g: &SurfaceGraph, x: u32, p: u32, q: u32) -> [u32; 2] {
    let o: Vec<u32> = g
        .ring(x)
        .iter()
        .copied()
        .filter(|&y| y != p && y != q)
        .collect();
    [o[0], *o.get(1).unwrap_or(&o[0])]
}

/// Properness (§3.3.1): `pq` is an edge or a diagonal, and every `p q v_j v_{j+1}` is a
/// tetrahedron inside the polyhedron whose surface is `g` (on the vertices of `poly`). Decided exactly: each tetrahedron is non-degenerate,
/// lies on the inner side of its two surface facets, and meets no facet except in shared
/// vertices and edges; then `pq`, an edge of all of them, lies inside too.
pub fn is_proper(poly: &Polyhedron, g: &SurfaceGraph, net: &BpNet) -> bool {
    proper_on(poly, g, &surface_grid(poly, g), net)
}

fn surface_grid(poly: &Polyhedron, g: &SurfaceGraph) -> TriangleGrid {
    TriangleGrid::of_faces(&poly.points, &g.facets())
}

fn proper_on(poly: &Polyhedron, g: &SurfaceGraph, grid: &TriangleGrid, net: &BpNet) -> bool {
    let pt = |v: u32| &poly.points[v as usize];
    net.path.windows(2).all(|w| {
        let (x, y) = (w[0], w[1]);
        // The facet (p, x, y) or (p, y, x) is on the surface; its inner side holds q.
        let facet = if g.has_facet(net.p, x, y) {
            (net.p, x, y)
        } else {
            (net.p, y, x)
        };
        if orient3d(pt(facet.0), pt(facet.1), pt(facet.2), pt(net.q)) >= 0 {
            return false;
        }
        // Only this tetrahedron's own two facets are exempt: the net's other facets must
        // not cut into it either (a folded net is not proper).
        let own = [[net.p, x, y], [net.q, x, y]].map(sorted_face);
        !grid.blocks_tet(&poly.points, &[net.p, net.q, x, y], |f| {
            !own.contains(&sorted_face(*f))
        })
    })
}

/// Disjointness (§3.3.1): the interiors of the two tetrahedralized BP-nets do not meet.
pub fn are_disjoint(points: &[Point3], a: &BpNet, b: &BpNet) -> bool {
    let geo = |t: [u32; 4]| t.map(|v| points[v as usize]);
    a.tetrahedra().iter().all(|&s| {
        b.tetrahedra()
            .iter()
            .all(|&t| !tetrahedra_overlap(&geo(s), &geo(t)))
    })
}

/// G(P') of Corollary 3.6: the surface after removing degree-3 vertices recursively (a
/// purely combinatorial step; each removal replaces three facets by one).
pub fn strip_stacked(poly: &Polyhedron) -> SurfaceGraph {
    let mut g = SurfaceGraph::new(poly);
    let mut stack: Vec<u32> = (0..g.len() as u32).filter(|&v| g.degree(v) == 3).collect();
    while let Some(u) = stack.pop() {
        if g.degree(u) != 3 || g.alive() <= 4 {
            continue;
        }
        let r = g.ring(u).to_vec();
        g.kill(u);
        for &x in &r {
            g.unlink(x, u);
            if g.degree(x) == 3 {
                stack.push(x);
            }
        }
    }
    g
}

/// The hypothesis of Theorem 3.5 and Corollary 3.6 on `poly`: after stripping stacked
/// tetrahedra, every proper BP-net is disjoint from every other. (Without it the polar
/// edges still give *a* minimum in all cases tested, but not always the only one: an
/// octahedron has three proper bipyramids, one per axis, and three minimum
/// tetrahedralizations.)
pub fn proper_nets_disjoint(poly: &Polyhedron) -> bool {
    let g = strip_stacked(poly);
    let grid = surface_grid(poly, &g);
    let proper: Vec<BpNet> = bp_nets(&g)
        .into_iter()
        .filter(|b| proper_on(poly, &g, &grid, b))
        .collect();
    // Only nets whose bounding boxes meet can overlap: sweep along the longest axis.
    let boxes: Vec<Aabb> = proper
        .iter()
        .map(|b| {
            let pts: Vec<&Point3> = b
                .path
                .iter()
                .chain([&b.p, &b.q])
                .map(|&v| &poly.points[v as usize])
                .collect();
            aabb(&pts)
        })
        .collect();
    let (lo, hi) = crate::geom::bounding_box(&poly.points);
    let axis = (0..3)
        .max_by(|&i, &j| (hi[i] - lo[i]).total_cmp(&(hi[j] - lo[j])))
        .unwrap_or(0);
    let mut order: Vec<usize> = (0..proper.len()).collect();
    order.sort_by(|&i, &j| boxes[i].0[axis].total_cmp(&boxes[j].0[axis]));
    order.iter().enumerate().all(|(k, &i)| {
        order[k + 1..]
            .iter()
            .take_while(|&&j| boxes[j].0[axis] <= boxes[i].1[axis])
            .all(|&j| {
                !boxes_meet(&boxes[i], &boxes[j])
                    || are_disjoint(&poly.points, &proper[i], &proper[j])
            })
    })
}
