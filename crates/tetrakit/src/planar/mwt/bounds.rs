//! Certified bounds on the minimum weight without solving, for a caller who cannot wait
//! for the exact solver (`tetrakit mwt --time-limit`). Every triangulation contains a
//! spanning tree, so the minimum spanning tree's weight is a lower bound; every
//! triangulation's weight is an upper bound, and the Delaunay triangulation's is close
//! to the optimum on most sets. Both take `O(n log n)`: some minimum spanning tree lies
//! in the Delaunay triangulation (with ties too), and Kruskal's order compares lengths
//! exactly.

use super::{certified_triangles, collinear, weight_of};
use crate::geom::{Hull2, Interval, Point2, cmp_length};
use crate::planar::{PlanarError, delaunay, edge_key, find};
use rayon::prelude::*;

/// Bounds on the weight of a minimum weight triangulation, with the triangulation that
/// gives the upper one.
#[derive(Clone, Debug)]
pub struct MwtBounds {
    /// The minimum spanning tree's weight: `lower.lo` is at most the minimum weight.
    pub lower: Interval,
    /// The Delaunay triangulation's weight: `upper.hi` is at least the minimum weight.
    pub upper: Interval,
    /// The Delaunay triangulation's edges, sorted (certified a triangulation).
    pub edges: Vec<[u32; 2]>,
    /// Its triangles, counter-clockwise.
    pub triangles: Vec<[u32; 3]>,
}

/// Certified bounds on the minimum weight of a triangulation of distinct sites (an
/// error names any two that coincide, or a coordinate outside the exact range).
///
/// ```
/// use tetrakit::planar::{mwt, mwt_bounds};
/// let pts = [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.5]];
/// let b = mwt_bounds(&pts).unwrap();
/// let w = mwt(&pts).unwrap().weight;
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
            upper: m.weight,
            edges: m.edges,
            triangles: Vec::new(),
        });
    }
    let dt = delaunay(points)?;
    let mut edges: Vec<[u32; 2]> = dt.edges.iter().map(|e| edge_key(e.p, e.q)).collect();
    edges.par_sort_unstable();
    let triangles = certified_triangles(points, &hull, &edges)?;
    let tree = spanning_tree(points, &edges);
    Ok(MwtBounds {
        lower: weight_of(points, &tree),
        upper: weight_of(points, &edges),
        edges,
        triangles,
    })
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
                let w = mwt(&pts).unwrap().weight;
                assert!(b.lower.lo <= w.hi && w.lo <= b.upper.hi, "{dist:?} {seed}");
                assert_eq!(b.edges.len(), mwt(&pts).unwrap().edges.len());
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
