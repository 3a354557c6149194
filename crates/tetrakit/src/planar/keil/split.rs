//! The best triangulations with and without `xy`, found by splitting along the polygon
//! `L = q' x p_n … p_1 r_1 … r_n y s'` (thesis Lemma 5.6).
//!
//! Every site of Keil's set is a vertex of `L`. When no segment between sites crosses a
//! side of `L` ([`edge_blocker`], checked for every side, not assumed from
//! Lemma 5.5(i)), every triangulation of the sites is the sides of `L` and of the hull,
//! a triangulation of `L`, and one of each *pocket* (the regions between the hull and
//! `L`), chosen independently. So the best triangulation containing `xy` is the best of
//! `L` containing `xy` plus the best of each pocket, and likewise without `xy`: three
//! exact polygon dynamic programs ([`polygon_dp`]) instead of an MWT of `2n + 4` sites in
//! nearly convex position, whose candidate triangles grow as `n³`. Both answers are
//! certified as triangulations of the whole set.

use crate::control::Control;
use crate::geom::{Hull2, Point2};
use crate::planar::PlanarError;
use crate::planar::edge_key as key;
use crate::planar::forced::{blocked_pairs, edge_blocker};
use crate::planar::mwt::{certified_triangles, polygon_dp, walk_area_sign};
use rayon::prelude::*;

/// The best triangulations with and without `xy`, as sorted edge lists.
pub(super) struct Optima {
    pub with_xy: Vec<[u32; 2]>,
    pub without_xy: Vec<[u32; 2]>,
}

/// Splits along `cycle` (every site once). `Ok(None)` when the split does not apply: a
/// side of the cycle is crossed or holds a site, or the hull has collinear sites on its
/// boundary, or the cycle is not counter-clockwise or clockwise.
pub(super) fn split_along(
    points: &[Point2],
    cycle: &[u32],
    xy: [u32; 2],
    ctl: &Control,
) -> Result<Option<Optima>, PlanarError> {
    let mut cycle = cycle.to_vec();
    match walk_area_sign(points, &cycle) {
        1 => {}
        -1 => cycle.reverse(),
        _ => return Ok(None),
    }
    let m = cycle.len();
    let sides: Vec<[u32; 2]> = (0..m).map(|i| [cycle[i], cycle[(i + 1) % m]]).collect();
    if !sides
        .par_iter()
        .all(|s| edge_blocker(points, s[0], s[1]).is_none())
    {
        return Ok(None);
    }
    let hull = Hull2::new(points);
    if hull.on_boundary.iter().filter(|&&b| b).count() != hull.vertices.len() {
        return Ok(None);
    }
    let Some(pockets) = pockets(points, &cycle, &hull) else {
        return Ok(None);
    };
    let blocked = blocked_pairs(points);
    let usable = |e: [u32; 2]| !blocked.contains(&e);
    let mut common: Vec<[u32; 2]> = sides.iter().map(|s| key(s[0], s[1])).collect();
    for pocket in &pockets {
        let inner = polygon_dp(points, pocket, &[], &usable, ctl);
        ctl.check()?;
        let inner =
            inner.ok_or_else(|| PlanarError::internal("a pocket of L has a triangulation", []))?;
        common.extend(inner.edges);
        common.push(key(pocket[0], pocket[1]));
    }
    let xy = key(xy[0], xy[1]);
    let with = polygon_dp(points, &cycle, &[xy], &usable, ctl);
    let without = polygon_dp(points, &cycle, &[], &|e| e != xy && usable(e), ctl);
    ctl.check()?;
    let complete = |inner: Option<Vec<[u32; 2]>>| -> Result<Vec<[u32; 2]>, PlanarError> {
        let mut edges = common.clone();
        edges.extend(inner.ok_or_else(|| PlanarError::internal("L has a triangulation", []))?);
        edges.sort_unstable();
        edges.dedup();
        certified_triangles(points, &hull, &edges)?;
        Ok(edges)
    };
    let with_xy = complete(with.map(|s| s.edges))?;
    let without_xy = complete(without.map(|s| s.edges))?;
    if with_xy.binary_search(&xy).is_err() || without_xy.binary_search(&xy).is_ok() {
        return Err(PlanarError::internal(
            "the split keeps the constraint on xy",
            [],
        ));
    }
    Ok(Some(Optima {
        with_xy,
        without_xy,
    }))
}

/// The regions between the hull and the counter-clockwise `cycle`, each as a
/// counter-clockwise walk starting with its hull edge. `None` when one is not
/// counter-clockwise (the cycle does not meet the hull vertices in hull order).
fn pockets(points: &[Point2], cycle: &[u32], hull: &Hull2) -> Option<Vec<Vec<u32>>> {
    let m = cycle.len();
    let mut pos = vec![usize::MAX; points.len()];
    for (i, &v) in cycle.iter().enumerate() {
        pos[v as usize] = i;
    }
    let h = hull.vertices.len();
    let mut out = Vec::new();
    for i in 0..h {
        let (u, v) = (hull.vertices[i], hull.vertices[(i + 1) % h]);
        let (a, b) = (pos[u as usize], pos[v as usize]);
        if (a + 1) % m == b {
            continue;
        }
        // u, v, then the cycle's path from v back to u.
        let len = (b + m - a) % m;
        let mut pocket = vec![u, v];
        pocket.extend((1..len).map(|t| cycle[(b + m - t) % m]));
        if walk_area_sign(points, &pocket) <= 0 {
            return None;
        }
        out.push(pocket);
    }
    Some(out)
}
