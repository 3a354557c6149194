//! Plane graphs in rotation form: neighbours sorted counter-clockwise (exactly), face
//! walks, and wedge tests. Shared by the exact face stage and the output assembly.

use crate::geom::{Expansion, Point2, orient2d};
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

/// Compressed rows of `(neighbour, edge id)` per vertex, in edge order.
pub fn csr(n: usize, edges: &[[u32; 2]]) -> (Vec<u32>, Vec<(u32, u32)>) {
    let entries = edges.iter().enumerate().flat_map(|(id, e)| {
        let id = id as u32;
        [(e[0] as usize, (e[1], id)), (e[1] as usize, (e[0], id))]
    });
    crate::rows::buckets(n, entries)
}

/// Neighbour lists sorted counter-clockwise.
pub struct Rotation {
    /// Compressed rows.
    pub start: Vec<u32>,
    /// Neighbours.
    pub nbr: Vec<u32>,
}

impl Rotation {
    /// The rotation system of an edge list.
    pub fn new(points: &[Point2], edges: &[[u32; 2]]) -> Rotation {
        let n = points.len();
        let (start, adj) = csr(n, edges);
        let mut nbr: Vec<u32> = adj.into_iter().map(|(b, _)| b).collect();
        for v in 0..n {
            nbr[start[v] as usize..start[v + 1] as usize]
                .sort_by(|&a, &b| angle_cmp(points, v as u32, a, b));
        }
        Rotation { start, nbr }
    }

    /// Neighbours of `v`, counter-clockwise.
    pub fn around(&self, v: u32) -> &[u32] {
        &self.nbr[self.start[v as usize] as usize..self.start[v as usize + 1] as usize]
    }

    /// Half-edge id of `v → around(v)[i]`.
    pub fn half(&self, v: u32, i: usize) -> usize {
        self.start[v as usize] as usize + i
    }

    /// The half-edge after `u → v` along the face on its left.
    pub fn next(&self, u: u32, v: u32) -> (u32, u32) {
        let ring = self.around(v);
        let i = ring
            .iter()
            .position(|&x| x == u)
            .expect("reverse half-edge exists");
        (v, ring[(i + ring.len() - 1) % ring.len()])
    }

    /// Every face walk: the vertex sequence and, per half-edge, its walk id.
    pub fn walks(&self) -> (Vec<Vec<u32>>, Vec<u32>) {
        let mut walk_of = vec![u32::MAX; self.nbr.len()];
        let mut walks = Vec::new();
        for v in 0..self.start.len() as u32 - 1 {
            for (i, &w) in self.around(v).iter().enumerate() {
                if walk_of[self.half(v, i)] != u32::MAX {
                    continue;
                }
                let id = walks.len() as u32;
                let mut seq = Vec::new();
                let (mut a, mut b) = (v, w);
                loop {
                    let pos = self
                        .around(a)
                        .iter()
                        .position(|&x| x == b)
                        .expect("half-edge");
                    let h = self.half(a, pos);
                    if walk_of[h] != u32::MAX {
                        break;
                    }
                    walk_of[h] = id;
                    seq.push(a);
                    (a, b) = self.next(a, b);
                }
                walks.push(seq);
            }
        }
        (walks, walk_of)
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
