//! β-skeletons (thesis §5.1–5.2; Kirkpatrick and Radke), exact for every rational β.
//!
//! `pq` is an edge of the β-skeleton when no other site lies strictly inside the
//! β-region of `pq` ([`in_beta_region`] for the circle-based skeleton, the thesis's
//! definition; [`in_lune`] for the lune-based one).
//!
//! **β ≥ 1 via Delaunay, and why it is complete.** For β > 1 the region contains the
//! closed diametral disk of `pq` minus `p` and `q` (every point `r` there has
//! `∠prq ≥ π/2 > arcsin(1/β)`, and the lune contains the diametral disk). So a skeleton
//! edge has a circle through `p` and `q` with no site inside or on it, and `pq` is an
//! edge of the Delaunay subdivision, hence of *every* Delaunay triangulation, whatever
//! the cocircularities. For β = 1 (the Gabriel graph) the open diametral disk is empty
//! but sites may lie on its circle; that circle is then the circumcircle of a Delaunay
//! cell, and `pq` is a chord of it. A chord that is not a side has cell vertices on
//! both arcs; those on the shorter arc see it at more than π/2, so it is an edge only
//! when both arcs are equal: `p` and `q` are antipodal on the cell's circle. Those
//! diameters are added when the cell has four or more vertices.
//!
//! **The local test.** For a Delaunay edge `pq` with apices `r` (left) and `s`, the
//! circle-based region left of `pq` is `{t : ∠ptq > α}`. If `∠prq ≤ α` it lies inside
//! the open circumdisk of `pqr`, which is empty; so the left side holds a site in the
//! region iff `r` itself is in it. On the hull side there is no site at all. Hence one
//! exact test per apex decides the edge: `O(n)` tests after the `O(n log n)`
//! triangulation. The lune is not covered by the circumdisks in this way, so for the
//! lune-based skeleton (β > 1) each Delaunay edge that survives its apices is checked
//! against the sites in a bounding box of its lune (a grid query).
//!
//! **β < 1.** The region shrinks to a lens inside the diametral disk and the skeleton
//! is no longer planar (it tends to the complete graph as β → 0). Each site searches the
//! sites around it, nearest rings of grid cells first, until every direction further
//! out is blocked by a site already seen ([`lens`]); every decision is an exact
//! region test. On uniform sites at β = 0.9 that is about 60 pairs per site.

mod lens;

use super::delaunay::{Delaunay, EdgeView, delaunay, delaunay_edges_where};
use super::grid::PointGrid;
use super::{PlanarError, find};
use crate::control::Control;
use crate::geom::{Point2, Ratio, corner_dot_sign, in_beta_region, in_lune, orient2d};
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::HashSet;

/// Which β-region defines the skeleton.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Region {
    /// Union (β ≥ 1) or intersection (β < 1) of the two disks through `p` and `q`: the
    /// thesis's definition.
    Circle,
    /// Intersection of the two disks centred on the line `pq` (β ≥ 1).
    Lune,
}

/// A β-skeleton and how it was found.
#[derive(Clone, Debug)]
pub struct Skeleton {
    /// Edges `[p, q]` with `p < q`, sorted.
    pub edges: Vec<[u32; 2]>,
    /// False when the control stopped the search first (β < 1 only): `edges` are then
    /// the skeleton's edges found from the sites searched by then, each decided exactly,
    /// a subset of the skeleton.
    pub complete: bool,
    /// Number of candidate pairs tested.
    pub candidates: usize,
    /// Diameters of cocircular Delaunay cells added for β = 1.
    pub cell_diameters: usize,
}

/// The β-skeleton of distinct points (exact; an error names coinciding sites or a
/// coordinate outside the exact range). For β < 1 the search around each site may take
/// minutes for small β: it reports `(sites searched, sites)` to `ctl` now and then and,
/// once `ctl` is stopped, searches no further site and answers with the edges found so
/// far ([`Skeleton::complete`] false); for β ≥ 1 (a Delaunay triangulation and one test
/// per edge) it reports nothing and always completes.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::planar::{Region, beta_skeleton};
/// // A unit square: for β = 1 both diagonals are Gabriel edges (cocircular).
/// let pts = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let ctl = Control::new();
/// let one = "1".parse().unwrap();
/// assert_eq!(beta_skeleton(&pts, one, Region::Circle, &ctl).unwrap().edges.len(), 6);
/// let b = "1.1".parse().unwrap();
/// assert_eq!(beta_skeleton(&pts, b, Region::Circle, &ctl).unwrap().edges.len(), 4);
/// ```
///
/// Progress for β < 1:
///
/// ```
/// use std::sync::Arc;
/// use std::sync::atomic::{AtomicU64, Ordering};
/// use tetrakit::control::{Control, Progress};
/// use tetrakit::planar::{Region, beta_skeleton};
/// let pts: Vec<[f64; 2]> = (0..3000).map(|i| [(i % 60) as f64, (i / 60) as f64]).collect();
/// let last = Arc::new(AtomicU64::new(0));
/// let seen = Arc::clone(&last);
/// let ctl = Control::new().with_progress(move |p| {
///     if let Progress::Items { done, total } = p {
///         assert!(done <= total);
///         seen.fetch_max(done, Ordering::Relaxed);
///     }
/// });
/// let sk = beta_skeleton(&pts, "0.5".parse().unwrap(), Region::Circle, &ctl).unwrap();
/// assert!(!sk.edges.is_empty());
/// assert!(last.load(Ordering::Relaxed) > 0);
/// ```
pub fn beta_skeleton(
    points: &[Point2],
    beta: Ratio,
    region: Region,
    ctl: &Control,
) -> Result<Skeleton, PlanarError> {
    super::check_coordinates(points)?;
    if points.len() < 2 {
        return Ok(Skeleton {
            edges: Vec::new(),
            complete: true,
            candidates: 0,
            cell_diameters: 0,
        });
    }
    if beta.cmp_one() == Ordering::Less {
        super::check_sites(points)?;
        return lens::lens_skeleton(points, beta, ctl);
    }
    let lune = region == Region::Lune && beta.cmp_one() == Ordering::Greater;
    let grid = lune.then(|| PointGrid::new(points, 2.0));
    let keep = |e: &EdgeView| {
        let apex_in = |r: Option<(u32, Point2)>| {
            r.is_some_and(|(_, r)| {
                if lune {
                    in_lune(&e.p.1, &e.q.1, &r, beta)
                } else {
                    in_beta_region(&e.p.1, &e.q.1, &r, beta)
                }
            })
        };
        !apex_in(e.left)
            && !apex_in(e.right)
            && grid
                .as_ref()
                .is_none_or(|g| !lune_occupied(points, g, e.p.0, e.q.0, beta))
    };
    if beta.cmp_one() == Ordering::Greater {
        let (edges, candidates) = delaunay_edges_where(points, keep)?;
        return Ok(Skeleton {
            edges,
            complete: true,
            candidates,
            cell_diameters: 0,
        });
    }
    // β = 1: the Gabriel graph, plus the diameters of cocircular Delaunay cells.
    let dt = delaunay(points)?;
    let mut edges: Vec<[u32; 2]> = dt
        .edges
        .par_iter()
        .filter(|e| {
            let site = |i: u32| (i, points[i as usize]);
            keep(&EdgeView {
                p: site(e.p),
                q: site(e.q),
                left: e.left.map(site),
                right: e.right.map(site),
            })
        })
        .map(|e| [e.p.min(e.q), e.p.max(e.q)])
        .collect();
    let extra = cocircular_diameters(points, &dt);
    let cell_diameters = extra.len();
    edges.extend(extra);
    edges.par_sort_unstable();
    edges.dedup();
    Ok(Skeleton {
        edges,
        complete: true,
        candidates: dt.edges.len() + cell_diameters,
        cell_diameters,
    })
}

/// Bounding box of the disk around the midpoint of `pq` of radius `factor·|pq|`, widened
/// by a margin far above the rounding error. With coordinates in the exact range
/// ([`beta_skeleton`] checks them), nothing underflows or overflows: the midpoint is off
/// by at most one rounding of each coordinate (`u·|m|`), `|pq|` by a few roundings
/// relative (`4u`), and `factor` (a square root, for lunes) by one more. The margin is
/// `10^-9` relative plus `10^-9·(|m_x| + |m_y|)`, more than `10^6` times that; the grid
/// query widens the box by a further cell. So every site in the disk is tested exactly.
pub(super) fn disk_box(a: &Point2, b: &Point2, factor: f64) -> (Point2, Point2) {
    let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    let len = (b[0] - a[0]).hypot(b[1] - a[1]);
    let r = factor * len * (1.0 + 1e-9) + 1e-9 * (m[0].abs() + m[1].abs());
    ([m[0] - r, m[1] - r], [m[0] + r, m[1] + r])
}

/// True when some site other than `a`, `b` lies strictly inside the lune of `ab`
/// (β > 1). The lune lies in the disk around the midpoint of radius `√(2β−1)/2·|ab|`
/// (its farthest points from the midpoint are its two tips).
fn lune_occupied(points: &[Point2], grid: &PointGrid, a: u32, b: u32, beta: Ratio) -> bool {
    let (pa, pb) = (&points[a as usize], &points[b as usize]);
    let (lo, hi) = disk_box(pa, pb, (2.0 * beta.to_f64() - 1.0).sqrt() * 0.5);
    grid.any_in_box(lo, hi, |r| {
        r != a && r != b && in_lune(pa, pb, &points[r as usize], beta)
    })
}

/// Antipodal vertex pairs of the cocircular Delaunay cells with four or more vertices
/// (the extra Gabriel edges of β = 1), excluding pairs that are already Delaunay edges.
fn cocircular_diameters(points: &[Point2], dt: &Delaunay) -> Vec<[u32; 2]> {
    let p = |i: u32| &points[i as usize];
    let mut parent: Vec<u32> = (0..dt.triangles.len() as u32).collect();
    let mut merged = false;
    for e in &dt.edges {
        if let (Some(l), Some(r), Some(fl), Some(fr)) = (e.left, e.right, e.left_face, e.right_face)
            && crate::geom::incircle(p(e.p), p(e.q), p(l), p(r)) == 0
        {
            let (a, b) = (find(&mut parent, fl), find(&mut parent, fr));
            parent[a as usize] = b;
            merged = true;
        }
    }
    if !merged {
        return Vec::new();
    }
    let mut cells: std::collections::HashMap<u32, Vec<u32>> = Default::default();
    for (t, tri) in dt.triangles.iter().enumerate() {
        let root = find(&mut parent, t as u32);
        cells.entry(root).or_default().extend_from_slice(tri);
    }
    let existing: HashSet<[u32; 2]> = dt
        .edges
        .iter()
        .map(|e| [e.p.min(e.q), e.p.max(e.q)])
        .collect();
    let mut out = Vec::new();
    for mut cell in cells.into_values() {
        cell.sort_unstable();
        cell.dedup();
        if cell.len() < 4 {
            continue;
        }
        for pair in antipodal_pairs(points, cell) {
            if !existing.contains(&pair) {
                out.push(pair);
            }
        }
    }
    out
}

/// Antipodal pairs among cocircular points in convex position: `O(k log k)`.
fn antipodal_pairs(points: &[Point2], mut cell: Vec<u32>) -> Vec<[u32; 2]> {
    let p = |i: u32| &points[i as usize];
    let v0 = *cell
        .iter()
        .min_by(|a, b| p(**a).partial_cmp(p(**b)).unwrap())
        .unwrap();
    cell.retain(|&v| v != v0);
    // Convex position: the others sorted counter-clockwise as seen from v0.
    cell.sort_by(|&a, &b| match orient2d(p(v0), p(a), p(b)) {
        1 => Ordering::Less,
        -1 => Ordering::Greater,
        _ => Ordering::Equal,
    });
    cell.insert(0, v0);
    let k = cell.len();
    let dot_sign = |a: u32, b: u32, c: u32| corner_dot_sign(p(a), p(b), p(c));
    // sign of (arc from i to j, counter-clockwise) − π.
    let arc = |i: usize, j: usize| -> i8 {
        let next = (j + 1) % k;
        if next != i {
            -dot_sign(cell[i], cell[j], cell[next])
        } else {
            dot_sign(cell[i], cell[j], cell[(i + 1) % k])
        }
    };
    let mut out = Vec::new();
    for i in 0..k {
        // arc(i, i + t) increases with t; find the first t with sign ≥ 0.
        let (mut lo, mut hi) = (1usize, k - 1);
        while lo < hi {
            let mid = (lo + hi) / 2;
            if arc(i, (i + mid) % k) >= 0 {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        let j = (i + lo) % k;
        if arc(i, j) == 0 {
            let (a, b) = (cell[i], cell[j]);
            if a < b {
                out.push([a, b]);
            }
        }
    }
    out
}
