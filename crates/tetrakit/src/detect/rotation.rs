//! Combinatorial helpers shared by the 3D links and the planar case: faces of a rotation
//! system, connectivity, and the hull-edge chain check.

use super::graph::Graph;
use super::witness::{Witness, WitnessKind};

/// The faces of a rotation system: `rot[x]` lists the neighbours of `x` counter-clockwise
/// (the adjacency must be symmetric). Each face is the cycle of vertices to the left of its
/// directed edges, so bounded faces of an embedded graph come out counter-clockwise.
pub(super) fn trace_faces(rot: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let k = rot.len();
    let mut start = vec![0usize; k + 1];
    for i in 0..k {
        start[i + 1] = start[i] + rot[i].len();
    }
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
                let back = rot[y].iter().position(|&z| z as usize == x).unwrap_or(0);
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
