//! Helpers shared by the 3D links and the planar case: faces of a rotation system,
//! connectivity, the hull-edge chain check, and the local search for a checkable witness.

use super::graph::Graph;
use super::witness::{Witness, WitnessKind};
use crate::geom::{Point3, SegmentMeet, point_in_segment_interior, segments_meet};

/// The faces of a rotation system: `rot[x]` lists the neighbours of `x` counter-clockwise
/// (the adjacency must be symmetric). Each face is the cycle of vertices to the left of its
/// directed edges, so bounded faces of an embedded graph come out counter-clockwise.
pub(super) fn trace_faces(rot: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let k = rot.len();
    let mut start = vec![0usize; k + 1];
    for i in 0..k {
        start[i + 1] = start[i] + rot[i].len();
    }
    // by_nbr[start[y]..start[y + 1]]: (x, position of x in rot[y]), sorted by x, so the
    // reverse of a dart is found by binary search (high-degree vertices stay cheap).
    let mut by_nbr: Vec<(u32, u32)> = Vec::with_capacity(start[k]);
    for r in rot {
        let from = by_nbr.len();
        by_nbr.extend(r.iter().enumerate().map(|(p, &x)| (x, p as u32)));
        by_nbr[from..].sort_unstable();
    }
    let position = |y: usize, x: usize| {
        let row = &by_nbr[start[y]..start[y + 1]];
        row.binary_search_by_key(&(x as u32), |e| e.0)
            .map_or(0, |i| row[i].1 as usize)
    };
    let mut seen = vec![false; start[k]];
    let mut faces = Vec::new();
    for a in 0..k {
        for pos in 0..rot[a].len() {
            if seen[start[a] + pos] {
                continue;
            }
            let mut cycle = Vec::new();
            let (mut x, mut px) = (a, pos);
            while !seen[start[x] + px] {
                seen[start[x] + px] = true;
                cycle.push(x as u32);
                let y = rot[x][px] as usize;
                let back = position(y, x);
                (x, px) = (y, (back + rot[y].len() - 1) % rot[y].len());
            }
            faces.push(cycle);
        }
    }
    faces
}

/// True when the graph on `0..k` whose neighbours are `nbrs(x)` is connected.
pub(super) fn connected<'a>(k: usize, nbrs: impl Fn(usize) -> &'a [u32]) -> bool {
    if k == 0 {
        return true;
    }
    let mut seen = vec![false; k];
    let mut stack = vec![0usize];
    seen[0] = true;
    let mut count = 1;
    while let Some(x) = stack.pop() {
        for &y in nbrs(x) {
            if !seen[y as usize] {
                seen[y as usize] = true;
                count += 1;
                stack.push(y as usize);
            }
        }
    }
    count == k
}

/// Consecutive points along each hull edge (each chain sorted along its edge) must be
/// joined by a segment (Step 1 of TETRAHEDRALIZATION-DETECTION).
pub(super) fn check_chains(
    chains: impl IntoIterator<Item = Vec<u32>>,
    g: &Graph,
) -> Result<(), Witness> {
    for chain in chains {
        for w in chain.windows(2) {
            if !g.has_edge(w[0], w[1]) {
                return Err(Witness::new(
                    WitnessKind::MissingHullEdge,
                    vec![w[0], w[1]],
                    vec![[w[0], w[1]]],
                    format!(
                        "points #{} and #{} are consecutive along an edge of the convex hull but not joined by a segment",
                        w[0], w[1]
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// Looks for two segments that cross or overlap, or a vertex inside a segment, among the
/// segments within two steps of the given vertices: a witness anyone can check, to report
/// instead of a failed link. Gives up (`None`) when the neighbourhood is large.
pub(super) fn local_crossing(points: &[Point3], g: &Graph, around: &[u32]) -> Option<Witness> {
    const LIMIT: usize = 3000;
    let mut segs: Vec<(u32, u32)> = Vec::new();
    for &v in around {
        for &w in g.nbrs(v) {
            segs.push((v.min(w), v.max(w)));
            for &x in g.nbrs(w) {
                segs.push((w.min(x), w.max(x)));
            }
            if segs.len() > 4 * LIMIT {
                return None;
            }
        }
    }
    segs.sort_unstable();
    segs.dedup();
    if segs.len() > LIMIT {
        return None;
    }
    let p = |i: u32| &points[i as usize];
    let mut verts: Vec<u32> = segs.iter().flat_map(|&(a, b)| [a, b]).collect();
    verts.sort_unstable();
    verts.dedup();
    for &(a, b) in &segs {
        if let Some(&x) = verts
            .iter()
            .find(|&&x| point_in_segment_interior(p(x), p(a), p(b)))
        {
            return Some(Witness::new(
                WitnessKind::VertexOnSegment,
                vec![x, a, b],
                vec![[a, b]],
                format!("vertex #{x} lies inside segment (#{a}, #{b})"),
            ));
        }
    }
    for (i, &(a, b)) in segs.iter().enumerate() {
        for &(c, d) in &segs[i + 1..] {
            let how = match segments_meet(p(a), p(b), p(c), p(d)) {
                Some(SegmentMeet::Cross) => "cross",
                Some(SegmentMeet::Overlap) => "overlap",
                _ => continue,
            };
            return Some(Witness::new(
                WitnessKind::CrossingSegments,
                vec![a, b, c, d],
                vec![[a, b], [c, d]],
                format!("segments (#{a}, #{b}) and (#{c}, #{d}) {how}"),
            ));
        }
    }
    None
}
