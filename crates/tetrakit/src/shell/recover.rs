//! Q's facet edges on the current surface: where `Q` touches `P̄` in a facet (Q's facet
//! inside a facet of `P`, or inside a flat facet of the bottom a removal leaves), the
//! triangulation of that facet must have Q's edges, so that Q's facet is a union of its
//! triangles and no tetrahedron is ever built on a triangle reaching into `Q`.
//!
//! Each missing edge `ab` is recovered by 2-2 flips inside the planar facet that holds
//! both ends (Sloan's edge insertion, exact): an edge of the facet's triangulation that
//! `ab` crosses is flipped when its quadrilateral is strictly convex, preferring flips
//! whose new diagonal no longer crosses `ab`. One crossing edge is always flippable, and
//! no vertex lies inside `ab` (a vertex of `P` or `Q` inside an edge of `Q` would not be
//! a corner), so the edge appears; the wall edges of a removal's region are never
//! flipped, and an edge that cannot be recovered refuses the removal (the error is
//! the reason, which the surface reports).

use crate::geom::{Point3, orient2d_drop, orient3d, projection_axis};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

/// Q's edges, by vertex: `edges[v]` are the vertices joined to `v` by an edge of `Q`.
#[derive(Debug, Default)]
pub(super) struct QEdges(HashMap<u32, Vec<u32>>);

impl QEdges {
    /// The edges of the polytope `Q` whose vertices are `inner` (indices into `pts`).
    pub(super) fn new(pts: &[Point3], inner: &[u32]) -> QEdges {
        let coords: Vec<Point3> = inner.iter().map(|&v| pts[v as usize]).collect();
        let hull = crate::geom::Hull3::new(&coords);
        // Every point is a corner of Q, so its edges are the triangle edges between two
        // facets.
        let mut by_vertex: HashMap<u32, Vec<u32>> = HashMap::default();
        let facet: HashMap<(u32, u32), u32> = (hull.triangles.iter().zip(&hull.triangle_facet))
            .flat_map(|(t, &f)| (0..3).map(move |k| ((t[k], t[(k + 1) % 3]), f)))
            .collect();
        for (&(a, b), &f) in &facet {
            if a < b && facet.get(&(b, a)).is_some_and(|&g| g != f) {
                let (a, b) = (inner[a as usize], inner[b as usize]);
                by_vertex.entry(a).or_default().push(b);
                by_vertex.entry(b).or_default().push(a);
            }
        }
        QEdges(by_vertex)
    }

    /// Recovers in `tris` every edge of `Q` whose ends are both corners of `tris` and lie
    /// in the plane of one of its facets; `walls` are never flipped.
    pub(super) fn recover(
        &self,
        pts: &[Point3],
        tris: &mut [[u32; 3]],
        walls: &HashSet<(u32, u32)>,
    ) -> Result<(), &'static str> {
        if self.0.is_empty() {
            return Ok(());
        }
        let corners: HashSet<u32> = tris.iter().flatten().copied().collect();
        let mut wanted: Vec<(u32, u32)> = corners
            .iter()
            .filter_map(|v| self.0.get(v).map(|ws| (v, ws)))
            .flat_map(|(&v, ws)| ws.iter().map(move |&w| (v, w)))
            .filter(|&(v, w)| v < w && corners.contains(&w))
            .collect();
        if wanted.is_empty() {
            return Ok(());
        }
        wanted.sort_unstable();
        let mut have = edges(tris);
        let p = |v: u32| &pts[v as usize];
        for (a, b) in wanted {
            if have.contains(&(a, b)) {
                continue;
            }
            // Only an edge in the plane of a triangle at `a` can be in a facet with `a`.
            let flat = tris.iter().any(|t| {
                t.contains(&a) && {
                    let [x, y, z] = t.map(p);
                    orient3d(x, y, z, p(b)) == 0
                }
            });
            if flat && recover_edge(pts, tris, [a, b], walls)? {
                have = edges(tris);
            }
        }
        Ok(())
    }
}

/// The edges of `tris`, each as `(low, high)`.
fn edges(tris: &[[u32; 3]]) -> HashSet<(u32, u32)> {
    tris.iter()
        .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
        .collect()
}

/// The most flips one edge may take (far beyond what a facet's triangulation needs).
const FLIP_LIMIT: usize = 100_000;

/// Recovers the edge `ab` in the facet of `tris` that holds both ends, if there is one;
/// true when it flipped.
fn recover_edge(
    pts: &[Point3],
    tris: &mut [[u32; 3]],
    [a, b]: [u32; 2],
    walls: &HashSet<(u32, u32)>,
) -> Result<bool, &'static str> {
    let p = |v: u32| &pts[v as usize];
    let has_edge = |tris: &[[u32; 3]]| {
        tris.iter()
            .any(|t| (0..3).any(|k| t[k] == a && (t[(k + 1) % 3] == b || t[(k + 2) % 3] == b)))
    };
    if has_edge(tris) {
        return Ok(false);
    }
    let patch: Vec<usize> = (0..tris.len())
        .filter(|&i| {
            let [x, y, z] = tris[i].map(p);
            orient3d(x, y, z, p(a)) == 0 && orient3d(x, y, z, p(b)) == 0
        })
        .collect();
    let touches = |v: u32| patch.iter().any(|&i| tris[i].contains(&v));
    if !touches(a) || !touches(b) {
        return Ok(false); // not in one facet: the segment is not on the surface
    }
    let [x, y, z] = tris[patch[0]].map(p);
    let axis = projection_axis(x, y, z).ok_or("a degenerate facet triangle")?;
    let side = |u: u32, v: u32, w: u32| orient2d_drop(p(u), p(v), p(w), axis);
    let crosses =
        |c: u32, d: u32| side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
    for _ in 0..FLIP_LIMIT {
        let edge: HashMap<(u32, u32), usize> = patch
            .iter()
            .flat_map(|&i| {
                let t = tris[i];
                (0..3).map(move |k| ((t[k], t[(k + 1) % 3]), i))
            })
            .collect();
        let mut crossing: Vec<(u32, u32, usize, usize)> = edge
            .iter()
            .filter(|&(&(c, d), _)| c < d && !walls.contains(&(c, d)) && !walls.contains(&(d, c)))
            .filter_map(|(&(c, d), &i)| edge.get(&(d, c)).map(|&j| (c, d, i, j)))
            .filter(|&(c, d, _, _)| crosses(c, d))
            .collect();
        crossing.sort_unstable(); // the same flips, whatever the hash order
        let (mut first, mut best) = (None, None);
        for (c, d, i, j) in crossing {
            let (x, y) = (apex(tris[i], c, d), apex(tris[j], d, c));
            // Strictly convex: c and d strictly on either side of the new diagonal xy.
            if side(x, y, c) * side(x, y, d) >= 0 {
                continue;
            }
            first.get_or_insert((i, j, c, d, x, y));
            if !crosses(x, y) {
                best = Some((i, j, c, d, x, y));
                break;
            }
        }
        let Some((i, j, c, d, x, y)) = best.or(first) else {
            return Err("an edge of Q in a facet cannot be recovered");
        };
        // [c, d, x] and [d, c, y] become [c, y, x] and [y, d, x] (counter-clockwise
        // quadrilateral c, y, d, x).
        tris[i] = [c, y, x];
        tris[j] = [y, d, x];
        if has_edge(tris) {
            return Ok(true);
        }
    }
    Err("an edge of Q in a facet took too many flips")
}

/// The corner of triangle `t` other than `c` and `d` (`t` has the directed edge `cd`).
fn apex(t: [u32; 3], c: u32, d: u32) -> u32 {
    t.into_iter().find(|&v| v != c && v != d).unwrap_or(c)
}
