//! Instance generators: Kuhn grids, random (non-Delaunay) tetrahedralizations, the
//! skew-lines worst case of the thesis, cospherical lattice points, and corruptions of
//! valid instances. Everything is built with exact predicates and is reproducible from a
//! seed.

mod insert;
mod points;

pub use insert::tetrahedralize_points;
pub use points::{Distribution3, points3d};

use crate::geom::{Point3, orient3d, point_in_segment_interior, segments_meet};
use crate::mesh::Tetrahedralization;
use crate::rng::Rng;
use std::collections::HashMap;

/// The Kuhn (Freudenthal) tetrahedralization of a `k × k × k` grid of unit cubes:
/// `(k+1)^3` points, `6k^3` tetrahedra, full of coplanar and cospherical points.
///
/// ```
/// let t = tetrakit::generate::kuhn(2);
/// assert_eq!((t.points.len(), t.tets.len()), (27, 48));
/// assert!(t.verify_convex().is_valid());
/// ```
pub fn kuhn(k: usize) -> Tetrahedralization {
    let s = k + 1;
    let id = |i: usize, j: usize, l: usize| (i * s * s + j * s + l) as u32;
    let mut points = Vec::with_capacity(s * s * s);
    for i in 0..s {
        for j in 0..s {
            for l in 0..s {
                points.push([i as f64, j as f64, l as f64]);
            }
        }
    }
    let perms = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let mut tets = Vec::with_capacity(6 * k * k * k);
    for i in 0..k {
        for j in 0..k {
            for l in 0..k {
                for p in &perms {
                    let mut c = [i, j, l];
                    let mut t = [id(c[0], c[1], c[2]); 4];
                    for (step, &axis) in p.iter().enumerate() {
                        c[axis] += 1;
                        t[step + 1] = id(c[0], c[1], c[2]);
                    }
                    tets.push(t);
                }
            }
        }
    }
    let mut t = Tetrahedralization { points, tets };
    t.orient_positively();
    t
}

/// `n` random points in the unit cube with 53-bit coordinates, or, with `grid = Some(g)`,
/// distinct integer points in `[0, g)^3` (many coplanar and collinear subsets).
///
/// ```
/// let p = tetrakit::generate::random_points(10, 3, Some(4));
/// assert_eq!(p.len(), 10);
/// assert!(p.iter().flatten().all(|&x| x == x.floor() && (0.0..4.0).contains(&x)));
/// ```
pub fn random_points(n: usize, seed: u64, grid: Option<u32>) -> Vec<Point3> {
    let mut rng = Rng::new(seed);
    match grid {
        None => (0..n)
            .map(|_| [rng.unit(), rng.unit(), rng.unit()])
            .collect(),
        Some(g) => {
            let g = g.max(2) as usize;
            let n = n.min(g * g * g);
            let mut seen = std::collections::HashSet::new();
            let mut pts = Vec::with_capacity(n);
            while pts.len() < n {
                let p = [rng.below(g), rng.below(g), rng.below(g)];
                if seen.insert(p) {
                    pts.push(p.map(|x| x as f64));
                }
            }
            pts
        }
    }
}

/// All integer points on the sphere `x² + y² + z² = r2` (cospherical, and many coplanar).
///
/// ```
/// let p = tetrakit::generate::cospherical_points(25);
/// assert!(p.iter().all(|q| q[0] * q[0] + q[1] * q[1] + q[2] * q[2] == 25.0));
/// assert_eq!(p.len(), 30);
/// ```
pub fn cospherical_points(r2: i64) -> Vec<Point3> {
    let r = (r2 as f64).sqrt() as i64 + 1;
    let mut pts = Vec::new();
    for x in -r..=r {
        for y in -r..=r {
            for z in -r..=r {
                if x * x + y * y + z * z == r2 {
                    pts.push([x as f64, y as f64, z as f64]);
                }
            }
        }
    }
    pts
}

/// A random valid tetrahedralization of `n` random points (see [`random_points`]) that is in
/// general not Delaunay: points inserted in random order (stellar splits inside, placing
/// outside) followed by `flips` random 2-3/3-2 flips.
///
/// ```
/// let t = tetrakit::generate::random_tetrahedralization(30, 40, 7, None);
/// assert!(t.verify_convex().is_valid());
/// ```
pub fn random_tetrahedralization(
    n: usize,
    flips: usize,
    seed: u64,
    grid: Option<u32>,
) -> Tetrahedralization {
    let points = random_points(n, seed, grid);
    let mut t = tetrahedralize_points(points, seed);
    random_flips(&mut t, flips, seed ^ 0x5eed);
    t
}

/// Performs up to `flips` random exact 2-3 and 3-2 flips; returns how many were done.
///
/// ```
/// let mut t = tetrakit::generate::tetrahedralize_points(tetrakit::generate::random_points(40, 1, None), 1);
/// let done = tetrakit::generate::random_flips(&mut t, 50, 2);
/// assert!(done > 0 && t.verify_convex().is_valid());
/// ```
pub fn random_flips(t: &mut Tetrahedralization, flips: usize, seed: u64) -> usize {
    let mut rng = Rng::new(seed);
    let mut done = 0;
    let mut attempts = 0;
    while done < flips && attempts < 20 * flips + 20 && !t.tets.is_empty() {
        attempts += 1;
        let ti = rng.below(t.tets.len());
        let ok = if rng.below(2) == 0 {
            flip23(t, ti, rng.below(4))
        } else {
            flip32(t, ti, rng.below(6))
        };
        done += usize::from(ok);
    }
    done
}

fn pos(t: &Tetrahedralization, tet: [u32; 4]) -> [u32; 4] {
    let p = |i: u32| &t.points[i as usize];
    if orient3d(p(tet[0]), p(tet[1]), p(tet[2]), p(tet[3])) < 0 {
        [tet[0], tet[1], tet[3], tet[2]]
    } else {
        tet
    }
}

/// True when the line `de` passes through the open triangle `abc`.
fn pierces(t: &Tetrahedralization, d: u32, e: u32, [a, b, c]: [u32; 3]) -> bool {
    let p = |i: u32| &t.points[i as usize];
    let s = [
        orient3d(p(d), p(e), p(a), p(b)),
        orient3d(p(d), p(e), p(b), p(c)),
        orient3d(p(d), p(e), p(c), p(a)),
    ];
    s[0] != 0 && s[0] == s[1] && s[1] == s[2]
}

/// 2-3 flip across face `f` of tetrahedron `ti`, when the two apexes see through it.
fn flip23(t: &mut Tetrahedralization, ti: usize, f: usize) -> bool {
    let tet = t.tets[ti];
    let d = tet[f];
    let face: Vec<u32> = tet.iter().copied().filter(|&x| x != d).collect();
    let Some(tj) =
        (0..t.tets.len()).find(|&j| j != ti && face.iter().all(|x| t.tets[j].contains(x)))
    else {
        return false;
    };
    let e = *t.tets[tj].iter().find(|x| !face.contains(x)).unwrap();
    let (a, b, c) = (face[0], face[1], face[2]);
    if !pierces(t, d, e, [a, b, c]) {
        return false;
    }
    let new = [
        pos(t, [a, b, d, e]),
        pos(t, [b, c, d, e]),
        pos(t, [c, a, d, e]),
    ];
    t.tets[ti] = new[0];
    t.tets[tj] = new[1];
    t.tets.push(new[2]);
    true
}

/// 3-2 flip removing edge `k` of tetrahedron `ti` when exactly three tetrahedra surround it.
fn flip32(t: &mut Tetrahedralization, ti: usize, k: usize) -> bool {
    let (i, j) = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)][k];
    let (d, e) = (t.tets[ti][i], t.tets[ti][j]);
    let around: Vec<usize> = (0..t.tets.len())
        .filter(|&x| t.tets[x].contains(&d) && t.tets[x].contains(&e))
        .collect();
    if around.len() != 3 {
        return false;
    }
    let mut ring: Vec<u32> = around
        .iter()
        .flat_map(|&x| t.tets[x])
        .filter(|&x| x != d && x != e)
        .collect();
    ring.sort_unstable();
    ring.dedup();
    if ring.len() != 3 || !pierces(t, d, e, [ring[0], ring[1], ring[2]]) {
        return false;
    }
    // The segment de itself must cross the ring triangle, not just its line.
    let (a, b, c) = (ring[0], ring[1], ring[2]);
    let p = |i: u32| &t.points[i as usize];
    if orient3d(p(a), p(b), p(c), p(d)) * orient3d(p(a), p(b), p(c), p(e)) >= 0 {
        return false;
    }
    let new = [pos(t, [a, b, c, d]), pos(t, [a, b, c, e])];
    let mut idx = around.clone();
    idx.sort_unstable();
    t.tets.swap_remove(idx[2]);
    t.tets[idx[0]] = new[0];
    t.tets[idx[1]] = new[1];
    true
}

/// The skew-lines tetrahedralization: `n/2` points on each of two skew lines and all
/// `(n/2 − 1)^2` tetrahedra `a_i a_{i+1} b_j b_{j+1}`, so Θ(n²) tetrahedra and segments —
/// the worst case for the number of segments. Every point lies on a hull edge.
///
/// ```
/// let t = tetrakit::generate::skew_lines(10);
/// assert_eq!(t.tets.len(), 16);
/// assert!(t.verify_convex().is_valid());
/// ```
pub fn skew_lines(n: usize) -> Tetrahedralization {
    let k = (n / 2).max(2);
    let mut points: Vec<Point3> = (0..k).map(|i| [i as f64, 0.0, 0.0]).collect();
    points.extend((0..k).map(|j| [0.0, j as f64, 1.0]));
    let mut tets = Vec::new();
    for i in 0..k - 1 {
        for j in 0..k - 1 {
            tets.push([i as u32, i as u32 + 1, (k + j) as u32, (k + j + 1) as u32]);
        }
    }
    let mut t = Tetrahedralization { points, tets };
    t.orient_positively();
    t
}

/// A way to break a valid instance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Corruption {
    /// Remove one segment.
    DropEdge,
    /// Add a segment that crosses a segment or passes through a point.
    AddCrossing,
    /// Add a segment that overlaps a collinear segment.
    AddOverlap,
}

/// Applies `c` to an edge set; `None` when no such change exists (for instance no segment
/// can cross another when the points are in general position). The result is never the edge
/// set of a tetrahedralization: a dropped edge leaves a face or hull edge unjoined, and an
/// added segment crosses, overlaps or passes through something.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::detect::{Options, detect};
/// use tetrakit::generate::{Corruption, corrupt_edges, kuhn};
/// let t = kuhn(2);
/// let e = corrupt_edges(&t.points, &t.edges(), Corruption::AddCrossing, 1).unwrap();
/// assert!(!detect(&t.points, &e, &Options::default(), &Control::new()).unwrap().is_yes());
/// ```
pub fn corrupt_edges(
    points: &[Point3],
    edges: &[[u32; 2]],
    c: Corruption,
    seed: u64,
) -> Option<Vec<[u32; 2]>> {
    let mut rng = Rng::new(seed);
    let mut out = edges.to_vec();
    if c == Corruption::DropEdge {
        if out.is_empty() {
            return None;
        }
        out.remove(rng.below(out.len()));
        return Some(out);
    }
    let mut adj: HashMap<u32, Vec<u32>> = HashMap::new();
    for &[a, b] in edges {
        adj.entry(a).or_default().push(b);
        adj.entry(b).or_default().push(a);
    }
    let p = |i: u32| &points[i as usize];
    let mut starts: Vec<u32> = (0..points.len() as u32).collect();
    rng.shuffle(&mut starts);
    for &a in starts.iter().take(64) {
        // Candidates: vertices two or three steps away; only segments near them can be hit.
        let mut cands: Vec<u32> = Vec::new();
        for &x in adj.get(&a).into_iter().flatten() {
            for &y in adj.get(&x).into_iter().flatten() {
                cands.push(y);
                cands.extend(adj.get(&y).into_iter().flatten().copied());
            }
        }
        cands.sort_unstable();
        cands.dedup();
        let near: Vec<[u32; 2]> = cands
            .iter()
            .flat_map(|&x| adj[&x].iter().map(move |&y| [x, y]))
            .collect();
        for &b in &cands {
            if b == a || adj[&a].contains(&b) {
                continue;
            }
            let meets = |&[x, y]: &[u32; 2]| segments_meet(p(a), p(b), p(x), p(y));
            let hit = match c {
                Corruption::AddOverlap => near
                    .iter()
                    .any(|e| meets(e) == Some(crate::geom::SegmentMeet::Overlap)),
                _ => {
                    cands
                        .iter()
                        .any(|&x| point_in_segment_interior(p(x), p(a), p(b)))
                        || near.iter().any(|e| meets(e).is_some())
                }
            };
            if hit {
                out.push([a.min(b), a.max(b)]);
                return Some(out);
            }
        }
    }
    None
}

/// Two Kuhn-subdivided unit cubes, the second moved by `shift`, sharing the points they
/// have in common: `[1, 1, 0]` makes them touch along an edge (a non-manifold domain),
/// `[1, 1, 1]` at a corner, `[0.5, 0.5, 0]` overlap.
///
/// ```
/// let t = tetrakit::generate::two_cubes([1.0, 1.0, 0.0]);
/// assert_eq!((t.points.len(), t.tets.len()), (14, 12));
/// ```
pub fn two_cubes(shift: [f64; 3]) -> Tetrahedralization {
    let a = kuhn(1);
    let mut points = a.points.clone();
    let mut tets = a.tets.clone();
    let index: Vec<u32> = (a.points.iter())
        .map(|p| {
            let q = [p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]];
            match points.iter().position(|r| *r == q) {
                Some(i) => i as u32,
                None => {
                    points.push(q);
                    points.len() as u32 - 1
                }
            }
        })
        .collect();
    tets.extend(a.tets.iter().map(|t| t.map(|v| index[v as usize])));
    Tetrahedralization { points, tets }
}

/// Adds a tetrahedron overlapping two neighbours (the union of two adjacent tetrahedra
/// `abcd`, `abce` contains the new `abde` when `de` crosses `abc`); when no pair of
/// neighbours allows it (grids: `de` meets `abc` only on its boundary), a second copy of
/// one tetrahedron, with its vertices rotated. `None` only for an empty mesh.
///
/// ```
/// let t = tetrakit::generate::random_tetrahedralization(50, 50, 1, None);
/// let bad = tetrakit::generate::add_overlapping_tet(&t, 1).unwrap();
/// assert!(!bad.verify_convex().is_valid());
/// ```
pub fn add_overlapping_tet(t: &Tetrahedralization, seed: u64) -> Option<Tetrahedralization> {
    let mut rng = Rng::new(seed);
    let mut faces: HashMap<[u32; 3], Vec<usize>> = HashMap::new();
    for (i, tet) in t.tets.iter().enumerate() {
        for skip in 0..4 {
            let mut f: Vec<u32> = (0..4).filter(|&j| j != skip).map(|j| tet[j]).collect();
            f.sort_unstable();
            faces.entry([f[0], f[1], f[2]]).or_default().push(i);
        }
    }
    let mut shared: Vec<([u32; 3], usize, usize)> = faces
        .into_iter()
        .filter(|(_, v)| v.len() == 2)
        .map(|(f, v)| (f, v[0], v[1]))
        .collect();
    shared.sort_unstable();
    rng.shuffle(&mut shared);
    for (f, i, j) in shared {
        let d = *t.tets[i].iter().find(|x| !f.contains(x)).unwrap();
        let e = *t.tets[j].iter().find(|x| !f.contains(x)).unwrap();
        if pierces(t, d, e, f) {
            let mut out = t.clone();
            out.tets.push(pos(t, [f[0], f[1], d, e]));
            return Some(out);
        }
    }
    if t.tets.is_empty() {
        return None;
    }
    let mut out = t.clone();
    let [a, b, c, d] = t.tets[rng.below(t.tets.len())];
    out.tets.push([b, c, a, d]);
    Some(out)
}

/// A partition of `tets` into `k` slabs along x, as a domain decomposition makes them:
/// the tetrahedra ordered by their lowest corner's x (ties by index) and cut into `k`
/// runs of equal size; the piece of each tetrahedron.
///
/// ```
/// let t = tetrakit::generate::kuhn(2);
/// let pieces = tetrakit::generate::slabs(&t.points, &t.tets, 4);
/// assert_eq!((pieces.len(), pieces.iter().max()), (48, Some(&3)));
/// ```
pub fn slabs(points: &[Point3], tets: &[[u32; 4]], k: usize) -> Vec<u32> {
    let low = |t: &[u32; 4]| {
        t.iter()
            .map(|&v| points[v as usize][0])
            .fold(f64::INFINITY, f64::min)
    };
    let mut order: Vec<usize> = (0..tets.len()).collect();
    order.sort_by(|&a, &b| low(&tets[a]).total_cmp(&low(&tets[b])).then(a.cmp(&b)));
    let mut piece = vec![0u32; tets.len()];
    let k = k.clamp(1, tets.len().max(1));
    for (rank, &t) in order.iter().enumerate() {
        piece[t] = (rank * k / tets.len()) as u32;
    }
    piece
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `--seed` reproduces an instance: no hash-map order leaks into the output.
    #[test]
    fn same_seed_same_tetrahedralization() {
        for seed in 0..4 {
            let a = random_tetrahedralization(150, 300, seed, None);
            for _ in 0..3 {
                assert_eq!(random_tetrahedralization(150, 300, seed, None).tets, a.tets);
            }
        }
    }
}
