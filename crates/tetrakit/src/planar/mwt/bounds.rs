//! Certified bounds on the minimum weight without solving, for a caller who cannot wait
//! for the exact solver (`tetrakit mwt --time-limit`). Every triangulation contains a
//! spanning tree, so the minimum spanning tree's weight is a lower bound; every
//! triangulation's weight is an upper bound. The triangulation offered is the Delaunay
//! one after exact flips that shorten it (Lawson's flips with length as the criterion):
//! close to the optimum on uniform sets, and far closer than Delaunay on sets in or near
//! convex position. Some minimum spanning tree lies in the Delaunay triangulation (ties
//! too), and Kruskal's order compares lengths exactly. The work is a few Delaunay
//! triangulations' worth (3.4 s at 10^6 uniform sites).

use super::{certify, collinear, weight_of};
use crate::geom::{Hull2, Interval, Point2, cmp_length, orient2d};
use crate::planar::{Delaunay, PlanarError, delaunay, edge_key, find};
use rayon::prelude::*;
use std::cmp::Ordering;

/// Bounds on the weight of a minimum weight triangulation, with the triangulation that
/// gives the upper one.
#[derive(Clone, Debug)]
pub struct MwtBounds {
    /// A lower bound: `lower.lo` is at most the minimum weight.
    pub lower: Interval,
    /// Where `lower` comes from.
    pub lower_source: LowerBound,
    /// The weight of a triangulation: `upper.hi` is at least the minimum weight.
    pub upper: Interval,
    /// That triangulation's edges, sorted (certified a triangulation): the Delaunay
    /// triangulation after flips that shorten it.
    pub edges: Vec<[u32; 2]>,
    /// Its triangles, counter-clockwise.
    pub triangles: Vec<[u32; 3]>,
}

/// Where a lower bound of [`MwtBounds`] comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LowerBound {
    /// The weight of a minimum spanning tree.
    SpanningTree,
    /// The solver's state when stopped ([`mwt_or_bounds`](super::mwt_or_bounds)).
    SolverState,
}

impl std::fmt::Display for LowerBound {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            LowerBound::SpanningTree => "minimum spanning tree",
            LowerBound::SolverState => "the solver's state",
        })
    }
}

/// Certified bounds on the minimum weight of a triangulation of distinct sites (an
/// error names any two that coincide, or a coordinate outside the exact range).
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::planar::{MwtOptions, mwt, mwt_bounds};
/// let pts = [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.5]];
/// let b = mwt_bounds(&pts).unwrap();
/// let w = mwt(&pts, &MwtOptions::default(), &Control::new()).unwrap().weight;
/// assert!(b.lower.lo <= w.hi && w.lo <= b.upper.hi);
/// assert_eq!(b.triangles.len(), 4);
/// ```
pub fn mwt_bounds(points: &[Point2]) -> Result<MwtBounds, PlanarError> {
    crate::planar::check_sites(points)?;
    let hull = Hull2::new(points);
    if hull.vertices.len() < 3 {
        // A path: the only triangulation, its own bounds.
        let m = collinear(points);
        return Ok(MwtBounds {
            lower: m.weight,
            lower_source: LowerBound::SpanningTree,
            upper: m.weight,
            edges: m.edges,
            triangles: Vec::new(),
        });
    }
    let dt = delaunay(points)?;
    let dt_edges: Vec<[u32; 2]> = dt.edges.iter().map(|e| edge_key(e.p, e.q)).collect();
    let tree = spanning_tree(points, &dt_edges);
    let triangles = flip_shorter(points, &dt, FLIPS_PER_SITE * points.len());
    let mut edges: Vec<[u32; 2]> = triangles
        .iter()
        .flat_map(|t| [0, 1, 2].map(|k| edge_key(t[k], t[(k + 1) % 3])))
        .collect();
    edges.par_sort_unstable();
    edges.dedup();
    certify(points, &hull, &edges, &triangles)?;
    Ok(MwtBounds {
        lower: weight_of(points, &tree),
        lower_source: LowerBound::SpanningTree,
        upper: weight_of(points, &edges),
        edges,
        triangles,
    })
}

/// A lower bound on the minimum weight from the solver's state: `known`, edges of
/// every MWT or edges whose weight every MWT matches (the optimum of a face solved
/// exactly, in a face of edges in every MWT), and `left`, groups `(k, edges)` from
/// each of which an MWT has exactly `k` edges and nothing else beyond `known` (a face
/// still open, with its interior edge count and its undecided edges). The MWT weighs at
/// least `known` plus the `k` shortest edges of each group. Lengths are the lower ends
/// of their intervals, selected exactly, and the sums are rounded down.
pub(super) fn state_bound(
    points: &[Point2],
    known: &[[u32; 2]],
    left: &[(usize, Vec<[u32; 2]>)],
) -> f64 {
    let group = |(k, edges): &(usize, Vec<[u32; 2]>)| {
        let mut lengths: Vec<f64> = (edges.iter())
            .map(|e| Interval::length(&points[e[0] as usize], &points[e[1] as usize]).lo)
            .collect();
        let k = (*k).min(lengths.len());
        if k < lengths.len() {
            lengths.select_nth_unstable_by(k, f64::total_cmp);
        }
        (lengths[..k].iter()).fold(0.0_f64, |sum, &l| (sum + l).next_down().max(0.0))
    };
    let sums: Vec<f64> = left.par_iter().map(group).collect();
    let rest = (sums.iter()).fold(0.0_f64, |sum, &l| (sum + l).next_down().max(0.0));
    (weight_of(points, known).lo + rest).next_down()
}

/// Flips allowed per site in [`flip_shorter`] (its work stays linear whatever the set).
const FLIPS_PER_SITE: usize = 20;

/// Lawson's flips towards weight: while some edge `ab` of two triangles `abr`, `bas`
/// has `asbr` strictly convex and `|rs| < |ab|` (exactly), it becomes `rs`, at most
/// `budget` times. Each flip lowers the weight, so a triangulation comes out, lighter
/// than the Delaunay one that went in (which is far from optimal on sets in or near
/// convex position: their many cocircular sites leave it long diagonals).
fn flip_shorter(points: &[Point2], dt: &Delaunay, budget: usize) -> Vec<[u32; 3]> {
    let p = |v: u32| &points[v as usize];
    let mut tris = dt.triangles.clone();
    let mut across = neighbours(dt);
    // Edge `k` of triangle `t` runs from `t[k]` to `t[k + 1]`; each interior edge once.
    let mut todo: Vec<(u32, usize)> = (0..tris.len() as u32)
        .flat_map(|t| (0..3).map(move |k| (t, k)))
        .filter(|&(t, k)| across[t as usize][k] != NONE && t < across[t as usize][k])
        .collect();
    let mut flips = 0;
    while let Some((i, k)) = todo.pop() {
        let j = across[i as usize][k];
        if j == NONE {
            continue;
        }
        let [a, b, r] = rotated(tris[i as usize], k);
        let l = slot_of(&across[j as usize], i);
        let s = tris[j as usize][(l + 2) % 3];
        // `r` is left of `a → b` and `s` right of it; the quadrilateral `a s b r` is
        // strictly convex when `a` and `b` are strictly on opposite sides of `rs`.
        let convex = orient2d(p(r), p(s), p(a)) * orient2d(p(r), p(s), p(b)) < 0;
        if !convex || cmp_length(p(r), p(s), p(a), p(b)) != Ordering::Less {
            continue;
        }
        if flips == budget {
            break;
        }
        flips += 1;
        // Outer neighbours: across `b r` and `r a` in `i`, across `a s` and `s b` in `j`.
        let (br, ra) = (
            across[i as usize][(k + 1) % 3],
            across[i as usize][(k + 2) % 3],
        );
        let (as_, sb) = (
            across[j as usize][(l + 1) % 3],
            across[j as usize][(l + 2) % 3],
        );
        tris[i as usize] = [r, a, s];
        across[i as usize] = [ra, as_, j];
        tris[j as usize] = [s, b, r];
        across[j as usize] = [sb, br, i];
        // `b r` now belongs to `j`, `a s` to `i`.
        if br != NONE {
            let m = slot_of(&across[br as usize], i);
            across[br as usize][m] = j;
        }
        if as_ != NONE {
            let m = slot_of(&across[as_ as usize], j);
            across[as_ as usize][m] = i;
        }
        todo.extend([(i, 0), (i, 1), (j, 0), (j, 1)]);
    }
    tris
}

/// No triangle (across a hull edge).
const NONE: u32 = u32::MAX;

/// `t` rotated to start at its corner `k`.
fn rotated(t: [u32; 3], k: usize) -> [u32; 3] {
    [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
}

/// Where `row` holds `t`.
fn slot_of(row: &[u32; 3], t: u32) -> usize {
    row.iter()
        .position(|&x| x == t)
        .expect("neighbours are mutual")
}

/// Per triangle of `dt`, the triangle across each edge (edge `k` from corner `k`).
fn neighbours(dt: &Delaunay) -> Vec<[u32; 3]> {
    let mut across = vec![[NONE; 3]; dt.triangles.len()];
    let edge_of = |t: [u32; 3], a: u32, b: u32| {
        (0..3)
            .find(|&k| t[k] == a && t[(k + 1) % 3] == b)
            .expect("a triangle has its edge")
    };
    for e in &dt.edges {
        if let (Some(l), Some(r)) = (e.left_face, e.right_face) {
            // `p → q` runs counter-clockwise in the left triangle, `q → p` in the right.
            across[l as usize][edge_of(dt.triangles[l as usize], e.p, e.q)] = r;
            across[r as usize][edge_of(dt.triangles[r as usize], e.q, e.p)] = l;
        }
    }
    across
}

/// A minimum spanning tree among `edges` (Kruskal, lengths compared exactly).
fn spanning_tree(points: &[Point2], edges: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let p = |v: u32| &points[v as usize];
    let mut order = edges.to_vec();
    order.par_sort_by(|a, b| cmp_length(p(a[0]), p(a[1]), p(b[0]), p(b[1])));
    let mut parent: Vec<u32> = (0..points.len() as u32).collect();
    order.retain(|e| {
        let (a, b) = (find(&mut parent, e[0]), find(&mut parent, e[1]));
        parent[a as usize] = b;
        a != b
    });
    order
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::Control;
    use crate::planar::MwtOptions;
    use crate::planar::{Distribution, mwt, points2d};

    /// Prim's algorithm on every pair, lengths compared exactly: the reference tree.
    fn prim(points: &[Point2]) -> Vec<[u32; 2]> {
        let n = points.len();
        let p = |v: usize| &points[v];
        // Every site outside the tree links to its nearest site inside (site 0 first).
        let mut link: Vec<Option<usize>> = vec![Some(0); n];
        let mut inside = vec![false; n];
        inside[0] = true;
        let mut tree = Vec::new();
        for _ in 1..n {
            let next = (0..n)
                .filter(|&v| !inside[v])
                .min_by(|&a, &b| {
                    let (la, lb) = (link[a].unwrap(), link[b].unwrap());
                    cmp_length(p(a), p(la), p(b), p(lb))
                })
                .unwrap();
            let u = link[next].unwrap();
            tree.push(edge_key(next as u32, u as u32));
            inside[next] = true;
            for v in 0..n {
                if !inside[v] && cmp_length(p(v), p(next), p(v), p(link[v].unwrap())).is_lt() {
                    link[v] = Some(next);
                }
            }
        }
        tree
    }

    /// On random, grid (ties everywhere), regular and clustered sets: the tree weighs
    /// what Prim's tree on all pairs weighs, and the optimum lies between the bounds.
    #[test]
    fn bounds_enclose_the_optimum_and_the_tree_is_minimum() {
        for (k, dist) in [
            Distribution::Uniform,
            Distribution::Grid,
            Distribution::Regular,
            Distribution::Clustered,
            Distribution::Gaussian,
        ]
        .into_iter()
        .enumerate()
        {
            for seed in 0..6 {
                let pts = points2d(dist, 20 + 37 * seed as usize, seed + 10 * k as u64);
                let b = mwt_bounds(&pts).unwrap();
                let tree = spanning_tree(&pts, &b.edges);
                assert_eq!(tree.len(), pts.len() - 1);
                let want = weight_of(&pts, &prim(&pts));
                assert!(
                    b.lower.lo <= want.hi && want.lo <= b.lower.hi,
                    "{dist:?} {seed}: tree {:?}, Prim {want:?}",
                    b.lower
                );
                let w = mwt(&pts, &MwtOptions::default(), &Control::new())
                    .unwrap()
                    .weight;
                assert!(b.lower.lo <= w.hi && w.lo <= b.upper.hi, "{dist:?} {seed}");
                // The flips only shorten; on cocircular sites they shorten by much.
                let dt = delaunay(&pts).unwrap();
                let dt_edges: Vec<[u32; 2]> = dt.edges.iter().map(|e| edge_key(e.p, e.q)).collect();
                let dt_weight = weight_of(&pts, &dt_edges);
                assert!(b.upper.lo <= dt_weight.hi, "{dist:?} {seed}");
                if dist == Distribution::Regular {
                    assert!(b.upper.hi < dt_weight.lo, "{dist:?} {seed}");
                }
                assert_eq!(
                    b.edges.len(),
                    mwt(&pts, &MwtOptions::default(), &Control::new())
                        .unwrap()
                        .edges
                        .len()
                );
            }
        }
    }

    #[test]
    fn collinear_sites_are_their_own_bounds() {
        let pts = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]];
        let b = mwt_bounds(&pts).unwrap();
        assert_eq!(b.edges, vec![[0, 2], [1, 2]]);
        assert!(b.triangles.is_empty() && b.lower == b.upper);
    }
}
