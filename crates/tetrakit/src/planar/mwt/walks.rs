//! Plane graphs in rotation form: neighbours sorted counter-clockwise (exactly), face
//! walks, and wedge tests. Shared by the exact face stage and the output assembly.

use crate::geom::{Expansion, Point2, orient2d};
use rayon::prelude::*;
use std::cmp::Ordering;

/// Exact counter-clockwise order of directions `a - v` and `b - v`, starting from the
/// positive x-axis.
pub fn angle_cmp(points: &[Point2], v: u32, a: u32, b: u32) -> Ordering {
    let (pv, pa, pb) = (
        &points[v as usize],
        &points[a as usize],
        &points[b as usize],
    );
    let half = |p: &Point2| {
        // 0 for angles in [0, π), 1 for [π, 2π); differences' signs are exact.
        if p[1] > pv[1] || (p[1] == pv[1] && p[0] > pv[0]) {
            0
        } else {
            1
        }
    };
    half(pa)
        .cmp(&half(pb))
        .then_with(|| match orient2d(pv, pa, pb) {
            1 => Ordering::Less,
            -1 => Ordering::Greater,
            _ => Ordering::Equal,
        })
}

/// True when direction `d - v` lies strictly inside the counter-clockwise wedge from
/// `a - v` to `b - v` (the full turn minus the ray when `a == b`).
pub fn in_wedge(points: &[Point2], v: u32, a: u32, b: u32, d: u32) -> bool {
    if d == a || d == b {
        return false;
    }
    // Angles measured counter-clockwise from a: compare d with b.
    let rel = |x: u32| -> u8 {
        let (pv, pa, px) = (
            &points[v as usize],
            &points[a as usize],
            &points[x as usize],
        );
        let o = orient2d(pv, pa, px);
        match o {
            1 => 1,
            -1 => 3,
            _ => {
                if crate::geom::corner_dot_sign(pa, px, pv) > 0 {
                    0
                } else {
                    2
                }
            }
        }
    };
    let cd = rel(d);
    let mut cb = rel(b);
    if cb == 0 {
        cb = 4; // b in a's direction: the wedge is the full turn
    }
    if cd == 0 {
        return false;
    }
    match cd.cmp(&cb) {
        Ordering::Less => true,
        Ordering::Greater => false,
        Ordering::Equal => {
            cd % 2 == 1
                && orient2d(
                    &points[v as usize],
                    &points[d as usize],
                    &points[b as usize],
                ) > 0
        }
    }
}

/// Compressed rows of `(neighbour, edge id)` per vertex, in edge order (built in
/// parallel, [`crate::rows::group`]).
pub fn csr(n: usize, edges: &[[u32; 2]]) -> (Vec<u32>, Vec<(u32, u32)>) {
    let (start, adj) = crate::rows::group(n, edges.len(), |id| {
        let ([a, b], id) = (edges[id], id as u32);
        [(a as usize, (b, id)), (b as usize, (a, id))]
    });
    (start.into_iter().map(|s| s as u32).collect(), adj)
}

/// [`csr`] with each row sorted counter-clockwise from the positive x-axis
/// ([`angle_cmp`], exact), rows in parallel.
pub fn ccw_rows(points: &[Point2], edges: &[[u32; 2]]) -> (Vec<u32>, Vec<(u32, u32)>) {
    let (start, mut adj) = csr(points.len(), edges);
    let offsets: Vec<usize> = start.iter().map(|&o| o as usize).collect();
    crate::rows::for_each_row(&mut adj, &offsets, |v, row| {
        row.sort_unstable_by(|a, b| angle_cmp(points, v as u32, a.0, b.0));
    });
    (start, adj)
}

/// Neighbour lists sorted counter-clockwise, with each half-edge's reverse.
pub struct Rotation {
    /// Compressed rows.
    pub start: Vec<u32>,
    /// Neighbours.
    pub nbr: Vec<u32>,
    /// For half-edge `h` (`v → nbr[h]`, `h` in the row of `v`), the half-edge `nbr[h] → v`.
    twin: Vec<u32>,
}

impl Rotation {
    /// The rotation system of an edge list (distinct edges, no loops); rows are sorted
    /// in parallel.
    pub fn new(points: &[Point2], edges: &[[u32; 2]]) -> Rotation {
        let (start, adj) = ccw_rows(points, edges);
        // The two half-edges of each edge.
        let mut halves = vec![[u32::MAX; 2]; edges.len()];
        for (h, &(_, id)) in adj.iter().enumerate() {
            let pair = &mut halves[id as usize];
            pair[usize::from(pair[0] != u32::MAX)] = h as u32;
        }
        let twin = (adj.par_iter().enumerate())
            .map(|(h, &(_, id))| {
                let [a, b] = halves[id as usize];
                if a == h as u32 { b } else { a }
            })
            .collect();
        let nbr = adj.into_iter().map(|(b, _)| b).collect();
        Rotation { start, nbr, twin }
    }

    /// Neighbours of `v`, counter-clockwise.
    pub fn around(&self, v: u32) -> &[u32] {
        &self.nbr[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }

    /// Half-edge id of `v → around(v)[i]`.
    pub fn half(&self, v: u32, i: usize) -> usize {
        self.start[v as usize] as usize + i
    }

    /// The half-edge after `h` along the face on its left: out of `h`'s head, the
    /// neighbour just clockwise of `h`'s tail.
    fn next_half(&self, h: usize) -> usize {
        let t = self.twin[h] as usize;
        let w = self.nbr[h] as usize;
        if t == self.start[w] as usize {
            self.start[w + 1] as usize - 1
        } else {
            t - 1
        }
    }

    /// Every face walk: the vertex sequence and, per half-edge, its walk id.
    pub fn walks(&self) -> (Vec<Vec<u32>>, Vec<u32>) {
        let mut walk_of = vec![u32::MAX; self.nbr.len()];
        let mut walks = Vec::new();
        for v in 0..self.start.len() as u32 - 1 {
            for first in self.start[v as usize] as usize..self.start[v as usize + 1] as usize {
                if walk_of[first] != u32::MAX {
                    continue;
                }
                let id = walks.len() as u32;
                let mut seq = Vec::new();
                let (mut h, mut tail) = (first, v);
                while walk_of[h] == u32::MAX {
                    walk_of[h] = id;
                    seq.push(tail);
                    tail = self.nbr[h];
                    h = self.next_half(h);
                }
                walks.push(seq);
            }
        }
        (walks, walk_of)
    }

    /// The counter-clockwise triangles that are faces (walks of three half-edges), each
    /// from its least vertex, in the order of [`Rotation::walks`]; vertices in parallel.
    pub fn triangles(&self, points: &[Point2]) -> Vec<[u32; 3]> {
        (0..self.start.len() as u32 - 1)
            .into_par_iter()
            .flat_map_iter(|v| {
                let row = self.start[v as usize] as usize..self.start[v as usize + 1] as usize;
                row.filter_map(move |h| {
                    let h2 = self.next_half(h);
                    let h3 = self.next_half(h2);
                    let (a, b) = (self.nbr[h], self.nbr[h2]);
                    let pt = |x: u32| &points[x as usize];
                    (self.next_half(h3) == h && v < a && v < b && orient2d(pt(v), pt(a), pt(b)) > 0)
                        .then_some([v, a, b])
                })
            })
            .collect()
    }

    /// The walk id of the face containing direction `d - v` next to `v` (`None` when
    /// `v` has no neighbours).
    pub fn face_toward(&self, points: &[Point2], walk_of: &[u32], v: u32, d: u32) -> Option<u32> {
        let ring = self.around(v);
        if ring.is_empty() {
            return None;
        }
        // The last neighbour strictly before d counter-clockwise (cyclically).
        let k = ring.partition_point(|&x| angle_cmp(points, v, x, d) == Ordering::Less);
        let i = (k + ring.len() - 1) % ring.len();
        Some(walk_of[self.half(v, i)])
    }
}

/// Exact sign of twice the signed area of a closed walk.
pub fn walk_area_sign(points: &[Point2], walk: &[u32]) -> i8 {
    let mut sum = Expansion::default();
    for (i, &a) in walk.iter().enumerate() {
        let b = walk[(i + 1) % walk.len()];
        let (pa, pb) = (&points[a as usize], &points[b as usize]);
        let t = Expansion::from(pa[0])
            .scale(pb[1])
            .sub(&Expansion::from(pa[1]).scale(pb[0]));
        sum = sum.add(&t);
    }
    sum.sign()
}
