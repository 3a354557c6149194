//! Planar input: is a set of segments exactly a triangulation of its endpoints
//! (Theorems 2.4–2.5)? Exact and degenerate-tolerant.
//!
//! The segments around each vertex are sorted by angle (exact), the faces of the resulting
//! rotation system are traced, and the answer is YES when the graph is connected, consecutive
//! hull points are joined, every bounded face is a counter-clockwise triangle, there is one
//! outer face, and Euler's formula holds (so Theorem 2.4's count |E| = 3|V| − |V(CH)| − 3
//! holds); the triangles are then certified by [`crate::mesh::verify_triangulation`].

use super::Cells;
use super::graph::Graph;
use super::rotation::{check_chains, local_crossing, trace_faces};
use super::witness::{Witness, WitnessKind};
use crate::geom::{Hull2, Point2, Point3, orient2d, project_to_plane};
use crate::mesh::verify_triangulation;
use crate::numbering::ids;

pub(super) fn detect(points: &[Point3], g: &Graph) -> (usize, Result<Cells, Witness>) {
    let Some(p) = project_to_plane(points) else {
        return (
            points.len(),
            Err(Witness::new(
                WitnessKind::Degenerate,
                vec![],
                vec![],
                "points are collinear",
            )),
        );
    };
    let hull = Hull2::new(&p);
    let hv = hull.on_boundary.iter().filter(|&&b| b).count();
    (hv, detect2(points, &p, g, &hull))
}

fn detect2(points: &[Point3], p: &[Point2], g: &Graph, hull: &Hull2) -> Result<Cells, Witness> {
    super::connectivity(g)?;
    check_chains(hull.boundary_chains(p), g)?;
    let n = p.len();
    let mut rot: Vec<Vec<u32>> = Vec::with_capacity(n);
    for v in 0..n as u32 {
        rot.push(sort_around(p, v, g.nbrs(v))?);
    }
    let (mut tris, mut outer) = (Vec::new(), Vec::new());
    for cycle in trace_faces(&rot) {
        let q = |i: usize| &p[cycle[i] as usize];
        if cycle.len() == 3 && orient2d(q(0), q(1), q(2)) > 0 {
            tris.push([cycle[0], cycle[1], cycle[2]]);
        } else {
            outer.push(cycle);
        }
    }
    let faces = tris.len() + outer.len();
    let euler = n as i64 - g.edge_count() as i64 + faces as i64;
    if outer.len() != 1 || euler != 2 {
        let face = outer
            .iter()
            .find(|c| c.len() != 3)
            .or(outer.first())
            .cloned()
            .unwrap_or_default();
        if let Some(w) = local_crossing(points, g, &face) {
            return Err(w);
        }
        return Err(Witness::new(
            WitnessKind::BadLink,
            face.clone(),
            vec![],
            format!(
                "the segments bound {} faces that are not counter-clockwise triangles (one is {}) and V-E+F = {euler}; a triangulation has exactly one outer face and V-E+F = 2",
                outer.len(),
                ids(&face)
            ),
        ));
    }
    let report = verify_triangulation(p, &tris);
    if let Some(pb) = report.problems.first() {
        let vs: Vec<u32> = pb.vertices.clone();
        if let Some(w) = local_crossing(points, g, &vs) {
            return Err(w);
        }
        return Err(Witness::new(
            WitnessKind::Inconsistent,
            vs,
            vec![],
            pb.detail.clone(),
        ));
    }
    Ok(Cells::Triangles(tris))
}

/// Neighbours of `v` sorted counter-clockwise, starting from the first one.
fn sort_around(p: &[Point2], v: u32, nbrs: &[u32]) -> Result<Vec<u32>, Witness> {
    let pv = &p[v as usize];
    let Some(&b0) = nbrs.first() else {
        return Ok(vec![]);
    };
    let pb0 = &p[b0 as usize];
    let same_ray = |x: &Point2, y: &Point2| {
        (0..2).all(|k| {
            (x[k] - pv[k]).signum() == (y[k] - pv[k]).signum() || (x[k] == pv[k] && y[k] == pv[k])
        })
    };
    let half = |b: u32| -> u8 {
        let pb = &p[b as usize];
        match orient2d(pv, pb0, pb) {
            1 => 1,
            -1 => 3,
            _ if same_ray(pb0, pb) => 0,
            _ => 2,
        }
    };
    let mut keyed: Vec<(u8, u32)> = nbrs.iter().map(|&b| (half(b), b)).collect();
    keyed.sort_by(|x, y| {
        x.0.cmp(&y.0).then_with(|| {
            if x.0 % 2 == 0 {
                return std::cmp::Ordering::Equal;
            }
            0.cmp(&orient2d(pv, &p[x.1 as usize], &p[y.1 as usize]))
        })
    });
    for w in keyed.windows(2) {
        let (a, b) = (w[0].1, w[1].1);
        if w[0].0 == w[1].0 && orient2d(pv, &p[a as usize], &p[b as usize]) == 0 {
            return Err(Witness::overlap_on_ray(v, a, b));
        }
    }
    Ok(keyed.into_iter().map(|(_, b)| b).collect())
}
