//! Generators of simple polyhedra for chapter 3: stacked polyhedra, bipyramids,
//! (augmented) BP-polyhedra, two- and h-level BP-polyhedra, Schönhardt's polyhedron and
//! the §3.5 counterexample (Figure 3.21); and, for chapter 6, convex polyhedra with
//! triangulated facets ([`convex_triangulated`]).
//!
//! Coordinates are `f64` and every result is checked exactly by [`Polyhedron::new`]: a
//! construction step whose floating-point placement came out invalid is retried closer to
//! its base, so the output is always a simple polyhedron.
//!
//! The two moves, each the inverse of a MINTETRA trim:
//! * **stack** a tetrahedron on a facet `abc`: a new vertex just outside its centre;
//! * **glue a BP-net** on an edge `pq` with facets `pqs`, `qpt`: a path
//!   `s v1 … v(m-1) t` around `pq`'s midpoint, in the exterior wedge, every `v_j` joined
//!   to `p` and `q`. Trimming it restores `pq`, which becomes the polar edge.

pub use super::triangulated::{ConvexShape, convex_triangulated};
use super::{Polyhedron, SurfaceGraph};
use crate::geom::{Point3, orient3d};
use crate::mesh::grid::TriangleGrid;
use crate::mesh::rotated_face;
use crate::rng::Rng;
use std::collections::{HashMap, HashSet};

/// A polyhedron under construction: faces (always outward) as a directed-edge map, a
/// grid over them for the local exact checks, and the faces in creation order so that
/// stacking subdivides evenly.
struct Builder {
    points: Vec<Point3>,
    next: HashMap<(u32, u32), u32>,
    grid: TriangleGrid,
    /// Faces ever added (dead ones are dropped when drawn).
    pool: Vec<[u32; 3]>,
    /// For a face, the fourth vertex of the tetrahedron it bounds, when known.
    opposite: HashMap<[u32; 3], u32>,
}

fn sub(a: &Point3, b: &Point3) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn unit(a: [f64; 3]) -> [f64; 3] {
    let l = dot(&a, &a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}
fn axpy(p: &Point3, s: f64, d: &[f64; 3]) -> Point3 {
    [p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]]
}

impl Builder {
    /// A builder from a valid polyhedron, with grid cells of side `cell`.
    fn from_polyhedron(p: &Polyhedron, cell: f64) -> Builder {
        let mut b = Builder {
            points: p.points.clone(),
            next: HashMap::new(),
            grid: TriangleGrid::with_cell(&p.points, cell),
            pool: Vec::new(),
            opposite: HashMap::new(),
        };
        p.faces.iter().for_each(|&f| b.add_face(f, None));
        b
    }

    fn tetrahedron(rng: &mut Rng) -> Builder {
        let mut j = || rng.unit() * 0.1;
        let points = vec![
            [1.0 + j(), 1.0 + j(), 1.0 + j()],
            [1.0 + j(), -1.0 + j(), -1.0 + j()],
            [-1.0 + j(), 1.0 + j(), -1.0 + j()],
            [-1.0 + j(), -1.0 + j(), 1.0 + j()],
        ];
        let faces = vec![[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]];
        let p = Polyhedron::new(points, faces).expect("a tetrahedron");
        let mut b = Builder::from_polyhedron(&p, 3.0);
        for f in &p.faces {
            let o = (0..4).find(|v| !f.contains(v)).expect("four vertices");
            b.opposite.insert(rotated_face(*f), o);
        }
        b
    }

    /// A Boerdijk–Coxeter helix of `n >= 4` vertices: tetrahedra `v_i … v_(i+3)` glued
    /// face to face along a helix, a stacked polyhedron with fat tetrahedra and vertex
    /// degree at most 6, so it grows to any size without crowding (a random tree of
    /// tetrahedra packs its surface ever more densely).
    fn helix(n: usize, rng: &mut Rng) -> Builder {
        let theta = (-2.0f64 / 3.0).acos();
        let (r, h) = (3.0 * 3f64.sqrt() / 10.0, 1.0 / 10f64.sqrt());
        let mut j = || (rng.unit() - 0.5) * 0.02;
        let points: Vec<Point3> = (0..n)
            .map(|i| {
                let a = theta * i as f64;
                [r * a.cos() + j(), r * a.sin() + j(), h * i as f64 + j()]
            })
            .collect();
        let n = n as u32;
        let mut faces = vec![[0, 1, 2], [n - 3, n - 2, n - 1]];
        for i in 0..n - 3 {
            faces.push([i, i + 1, i + 3]);
            faces.push([i, i + 2, i + 3]);
        }
        let p = Polyhedron::new(points, faces).expect("a tetrahelix is a simple polyhedron");
        let mut b = Builder::from_polyhedron(&p, 1.5);
        for f in &p.faces {
            let (lo, hi) = (
                f.iter().min().copied().unwrap_or(0),
                f.iter().max().copied().unwrap_or(0),
            );
            // The tetrahedron behind a face spans four consecutive indices.
            let first = if hi - lo == 3 {
                lo
            } else if lo == 0 {
                0
            } else {
                hi - 3
            };
            let o = (first..first + 4)
                .find(|v| !f.contains(v))
                .expect("four consecutive");
            b.opposite.insert(rotated_face(*f), o);
        }
        b
    }

    fn faces(&self) -> Vec<[u32; 3]> {
        let mut f: Vec<[u32; 3]> = self
            .next
            .iter()
            .filter(|&(&(a, b), &c)| a < b && a < c)
            .map(|(&(a, b), &c)| [a, b, c])
            .collect();
        f.sort_unstable();
        f
    }

    fn has_face(&self, f: &[u32; 3]) -> bool {
        self.next.get(&(f[0], f[1])) == Some(&f[2])
    }

    fn add_face(&mut self, f: [u32; 3], opposite: Option<u32>) {
        for r in 0..3 {
            self.next.insert((f[r], f[(r + 1) % 3]), f[(r + 2) % 3]);
        }
        self.grid.insert(&self.points, f);
        self.pool.push(f);
        if let Some(o) = opposite {
            self.opposite.insert(rotated_face(f), o);
        }
    }

    fn remove_face(&mut self, f: [u32; 3]) {
        for r in 0..3 {
            self.next.remove(&(f[r], f[(r + 1) % 3]));
        }
    }

    fn finish(self) -> Polyhedron {
        let faces = self.faces();
        Polyhedron::new(self.points, faces).expect("generators keep polyhedra simple")
    }

    /// True when the tetrahedron meets no current face but `replaced` except in shared
    /// vertices and edges (exact).
    fn free(&self, tet: [u32; 4], replaced: &[[u32; 3]]) -> bool {
        let replaced: Vec<[u32; 3]> = replaced.iter().map(|&g| rotated_face(g)).collect();
        !self.grid.blocks_tet(&self.points, &tet, |f| {
            self.has_face(f) && !replaced.contains(&rotated_face(*f))
        })
    }

    /// Stacks a tetrahedron on face `f`: the mirror image of the tetrahedron behind `f`
    /// when there is room (keeps shapes fat), else a lower apex over a random interior
    /// point; false when nothing tried fits.
    fn stack(&mut self, f: [u32; 3], rng: &mut Rng) -> bool {
        let [a, b, c] = f;
        let [pa, pb, pc] = f.map(|v| self.points[v as usize]);
        let n = cross(&sub(&pb, &pa), &sub(&pc, &pa));
        let size = dot(&n, &n).sqrt().sqrt();
        let n = unit(n);
        let mut tries: Vec<Point3> = Vec::new();
        if let Some(&o) = self.opposite.get(&rotated_face(f)) {
            let po = self.points[o as usize];
            let d = dot(&sub(&po, &pa), &n);
            let mut j = || (rng.unit() - 0.5) * 0.1 * size;
            let m = axpy(&po, -2.0 * d, &n);
            tries.push([m[0] + j(), m[1] + j(), m[2] + j()]);
        }
        let wa = 0.25 + 0.5 * rng.unit();
        let wb = (1.0 - wa) * (0.25 + 0.5 * rng.unit());
        let wc = 1.0 - wa - wb;
        let centre = [0, 1, 2].map(|i| wa * pa[i] + wb * pb[i] + wc * pc[i]);
        let mut h = size * (0.2 + 0.3 * rng.unit());
        for _ in 0..6 {
            tries.push(axpy(&centre, h, &n));
            h *= 0.5;
        }
        let x = self.points.len() as u32;
        for apex in tries {
            self.points.push(apex);
            let outside = orient3d(&pa, &pb, &pc, &apex) > 0;
            if outside && self.free([a, b, c, x], &[f]) {
                self.remove_face(f);
                self.add_face([a, b, x], Some(c));
                self.add_face([b, c, x], Some(a));
                self.add_face([c, a, x], Some(b));
                return true;
            }
            self.points.pop();
        }
        false
    }

    /// The apexes `s`, `t` of the faces `(p, q, s)` and `(q, p, t)`.
    fn wings(&self, p: u32, q: u32) -> Option<(u32, u32)> {
        Some((*self.next.get(&(p, q))?, *self.next.get(&(q, p))?))
    }

    /// Glues a BP-net with path length `m` (m - 1 new vertices) on edge `pq`; returns the
    /// new vertices.
    fn glue(&mut self, p: u32, q: u32, m: usize, rng: &mut Rng) -> Option<Vec<u32>> {
        let (s, t) = self.wings(p, q)?;
        let pt = |v: u32| self.points[v as usize];
        let (pp, pq) = (pt(p), pt(q));
        let len = dot(&sub(&pq, &pp), &sub(&pq, &pp)).sqrt();
        let e = unit(sub(&pq, &pp));
        let perp = |x: Point3| {
            let d = sub(&x, &pp);
            let a = dot(&d, &e);
            unit([d[0] - a * e[0], d[1] - a * e[1], d[2] - a * e[2]])
        };
        let (ds, dt) = (perp(pt(s)), perp(pt(t)));
        let e2 = cross(&e, &ds);
        let angle = |d: &[f64; 3]| {
            let a = dot(d, &e2).atan2(dot(d, &ds));
            if a < 0.0 {
                a + std::f64::consts::TAU
            } else {
                a
            }
        };
        // Outward normals of the two faces point into the exterior wedge.
        let n1 = unit(cross(&sub(&pq, &pp), &sub(&pt(s), &pp)));
        let n2 = unit(cross(&sub(&pp, &pq), &sub(&pt(t), &pq)));
        let out = [n1[0] + n2[0], n1[1] + n2[1], n1[2] + n2[2]];
        let (phi_t, phi_o) = (angle(&dt), angle(&out));
        let sweep = if phi_o < phi_t {
            phi_t
        } else {
            phi_t - std::f64::consts::TAU
        };
        let mut r = len * (0.1 + 0.08 * rng.unit());
        let first = self.points.len() as u32;
        let replaced = [[p, q, s], [q, p, t]];
        for _ in 0..10 {
            let mut path = vec![s];
            for j in 1..m {
                let a = sweep * (j as f64 + 0.3 * (rng.unit() - 0.5)) / m as f64;
                let along = 0.5 + 0.2 * (rng.unit() - 0.5);
                let base = axpy(&pp, along * len, &e);
                let dir = [0, 1, 2].map(|i| a.cos() * ds[i] + a.sin() * e2[i]);
                self.points.push(axpy(&base, r, &dir));
                path.push(self.points.len() as u32 - 1);
            }
            path.push(t);
            let pts = &self.points;
            let sign = |w: &[u32]| {
                orient3d(
                    &pts[p as usize],
                    &pts[q as usize],
                    &pts[w[0] as usize],
                    &pts[w[1] as usize],
                )
            };
            let s0 = sign(&path[0..2]);
            let ok = s0 != 0
                && path.windows(2).all(|w| sign(w) == s0)
                && path
                    .windows(2)
                    .all(|w| self.free([p, q, w[0], w[1]], &replaced));
            if ok {
                replaced.iter().for_each(|&f| self.remove_face(f));
                for w in path.windows(2) {
                    self.add_face([p, w[1], w[0]], Some(q));
                    self.add_face([q, w[0], w[1]], Some(p));
                }
                return Some((first..first + m as u32 - 1).collect());
            }
            self.points.truncate(first as usize);
            r *= 0.5;
        }
        None
    }

    fn edges(&self) -> Vec<[u32; 2]> {
        let mut e: Vec<[u32; 2]> = self
            .next
            .keys()
            .filter(|(a, b)| a < b)
            .map(|&(a, b)| [a, b])
            .collect();
        e.sort_unstable();
        e
    }

    /// Stacks `k` tetrahedra on faces drawn at random (fewer if the surface is too
    /// crowded to take them).
    fn stack_more(&mut self, k: usize, rng: &mut Rng) {
        let (mut added, mut misses) = (0, 0);
        while added < k && !self.pool.is_empty() && misses < 20 * (k + 10) {
            let i = rng.below(self.pool.len());
            let f = self.pool[i];
            if !self.has_face(&f) {
                self.pool.swap_remove(i);
                continue;
            }
            if self.stack(f, rng) {
                added += 1;
            } else {
                misses += 1;
            }
        }
    }
}

/// A stacked polyhedron with `n >= 4` vertices (the empty diagonal set tetrahedralizes it).
///
/// ```
/// let p = tetrakit::polyhedra::generate::stacked(10, 1);
/// assert_eq!(p.points.len(), 10);
/// assert_eq!(p.faces.len(), 16);
/// ```
pub fn stacked(n: usize, seed: u64) -> Polyhedron {
    let mut rng = Rng::new(seed);
    let mut b = Builder::tetrahedron(&mut rng);
    b.stack_more(n.max(4) - 4, &mut rng);
    b.finish()
}

/// A bipyramid `B(p v0 … v(m-1) v0 q)` over a convex `m`-gon, `m >= 3`.
pub fn bipyramid(m: usize, seed: u64) -> Polyhedron {
    let mut rng = Rng::new(seed);
    let m = m.max(3);
    let mut points: Vec<Point3> = (0..m)
        .map(|i| {
            let a = std::f64::consts::TAU * (i as f64 + 0.2 * rng.unit()) / m as f64;
            [a.cos(), a.sin(), 0.05 * (rng.unit() - 0.5)]
        })
        .collect();
    points.push([0.05 * rng.unit(), 0.05 * rng.unit(), 1.0]);
    points.push([0.05 * rng.unit(), 0.05 * rng.unit(), -1.0]);
    let (p, q) = (m as u32, m as u32 + 1);
    let faces = (0..m as u32)
        .flat_map(|i| {
            let j = (i + 1) % m as u32;
            [[p, i, j], [q, j, i]]
        })
        .collect();
    Polyhedron::new(points, faces).expect("a convex bipyramid")
}

/// Parameters of the BP-polyhedron generators.
#[derive(Clone, Copy, Debug)]
pub struct BpParams {
    /// Vertices of the stacked core, a Boerdijk–Coxeter helix (at least 4).
    pub core: usize,
    /// BP-nets glued per level.
    pub nets: usize,
    /// Levels (1: BP-polyhedron; 2: two-level; h: h-level).
    pub levels: usize,
    /// Path length m of each BP-net is drawn from `3..=max_m`.
    pub max_m: usize,
    /// Tetrahedra stacked on the result (the "augmented" of Corollary 3.6).
    pub augment: usize,
    /// From the second level on, glue a net on an edge at *every* inner vertex of the
    /// previous level's nets (so none of them shows before the outer ones are trimmed),
    /// instead of one per net (Theorem 3.6's special case).
    pub hide_all: bool,
    /// The seed.
    pub seed: u64,
}

impl Default for BpParams {
    fn default() -> Self {
        BpParams {
            core: 6,
            nets: 2,
            levels: 1,
            max_m: 4,
            augment: 2,
            hide_all: false,
            seed: 1,
        }
    }
}

/// An augmented h-level BP-polyhedron: a stacked core, `levels` rounds of BP-nets (each
/// round's nets glued on edges of the previous round's nets, one per net, which is
/// Theorem 3.6's special case for two levels), then `augment` stacked tetrahedra.
/// Returns the polyhedron and the number of polar edges, so that MINTETRA's count is
/// `n - 3 + polar` (Theorem 3.5, Corollaries 3.6–3.7).
///
/// ```
/// use tetrakit::polyhedra::{Checks, generate, mintetra};
/// let (p, polar) = generate::bp_polyhedron(generate::BpParams::default());
/// let m = mintetra(&p, Checks::Shelling);
/// assert!(m.yes);
/// assert_eq!(m.tets.len(), p.points.len() - 3 + polar);
/// ```
pub fn bp_polyhedron(params: BpParams) -> (Polyhedron, usize) {
    let mut rng = Rng::new(params.seed);
    let core = params.core.max(4);
    let mut b = Builder::helix(core, &mut rng);
    let mut polar = 0;
    // Edges eligible for the next round, in groups of which at most one is used: any
    // edge for the first round, then edges between a pole and an inner vertex of the
    // previous round's nets.
    let mut groups: Vec<Vec<[u32; 2]>> = {
        let mut all = b.edges();
        rng.shuffle(&mut all);
        all.into_iter().map(|e| vec![e]).collect()
    };
    for level in 0..params.levels.max(1) {
        let mut next_groups = Vec::new();
        let mut used = HashSet::new();
        let mut glued = 0;
        for mut group in std::mem::take(&mut groups) {
            if level == 0 && glued == params.nets {
                break;
            }
            rng.shuffle(&mut group);
            for [p, q] in group {
                let Some((s, t)) = b.wings(p, q) else {
                    continue;
                };
                let busy = |x: &u32| used.contains(x);
                if busy(&p) || busy(&q) || (!params.hide_all && (busy(&s) || busy(&t))) {
                    continue;
                }
                let m = 3 + rng.below(params.max_m.max(3) - 2);
                if let Some(inner) = b.glue(p, q, m, &mut rng) {
                    used.extend([p, q]);
                    if !params.hide_all {
                        used.extend([s, t]);
                    }
                    used.extend(inner.iter().copied());
                    let around = |v: u32| vec![[p.min(v), p.max(v)], [q.min(v), q.max(v)]];
                    if params.hide_all {
                        next_groups.extend(inner.iter().map(|&v| around(v)));
                    } else {
                        next_groups.push(inner.iter().flat_map(|&v| around(v)).collect());
                    }
                    polar += 1;
                    glued += 1;
                    break;
                }
            }
        }
        groups = next_groups;
    }
    b.stack_more(params.augment, &mut rng);
    (b.finish(), polar)
}

/// Schönhardt's twisted prism (§2.6, Figure 2.11(a)): six vertices, three reflex edges,
/// no tetrahedralization.
pub fn schonhardt() -> Polyhedron {
    let tri = |z: f64, twist: f64| -> Vec<Point3> {
        (0..3)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / 3.0 + twist;
                [
                    (8.0 * a.cos()).round() / 8.0,
                    (8.0 * a.sin()).round() / 8.0,
                    z,
                ]
            })
            .collect()
    };
    let mut points = tri(0.0, 0.0); // bottom
    points.extend(tri(2.0, 0.5)); // top, twisted
    for diag in [true, false] {
        let mut faces = vec![[0, 2, 1], [3, 4, 5]];
        for i in 0..3u32 {
            let j = (i + 1) % 3;
            let (qi, qj, pi, pj) = (i, j, i + 3, j + 3);
            if diag {
                faces.extend([[qi, qj, pi], [pi, qj, pj]]);
            } else {
                faces.extend([[qi, qj, pj], [qi, pj, pi]]);
            }
        }
        if let Ok(p) = Polyhedron::new(points.clone(), faces)
            && reflex_edges(&p).len() == 3
        {
            return p;
        }
    }
    unreachable!("one diagonal choice gives Schönhardt's polyhedron")
}

/// A triangular prism whose top is twisted by `degrees` about the axis, each side
/// quadrilateral split by the diagonal from its bottom-left to its top-right corner. A
/// positive twist makes the three diagonals reflex: Schönhardt's polyhedron, with no
/// tetrahedralization. A negative twist makes it convex (tetrahedralizable). Twists of
/// 120° or more (either way) are refused, and so is any prism whose faces cross (a
/// positive twist of 60° or more: the dented sides pass through each other).
///
/// ```
/// use tetrakit::polyhedra::generate::{reflex_edges, twisted_prism};
/// assert_eq!(reflex_edges(&twisted_prism(30.0).unwrap()).len(), 3);
/// assert!(reflex_edges(&twisted_prism(-30.0).unwrap()).is_empty());
/// assert!(twisted_prism(130.0).is_err());
/// ```
pub fn twisted_prism(degrees: f64) -> Result<Polyhedron, crate::params::GenerateError> {
    super::hard::schonhardt_tower(1, degrees)
}

/// Edges whose dihedral angle exceeds π: `pq` with faces `pqs`, `qpt` and `t` strictly
/// outside face `pqs`.
pub fn reflex_edges(p: &Polyhedron) -> Vec<[u32; 2]> {
    let g = SurfaceGraph::new(p);
    let pt = |v: u32| &p.points[v as usize];
    p.edges()
        .into_iter()
        .filter(|&[a, b]| {
            let [s, t] = g.tri(a, b).expect("closed surface");
            orient3d(pt(a), pt(b), pt(s), pt(t)) > 0
        })
        .collect()
}

/// The §3.5 counterexample (Figure 3.21): Schönhardt's polyhedron with a BP-net glued on
/// each reflex edge so that the result is convex. Trimming the three BP-nets gives back
/// Schönhardt's polyhedron, which is not stacked, so MINTETRA answers NO although the
/// polyhedron (being convex) has tetrahedralizations.
///
/// ```
/// use tetrakit::polyhedra::generate::{reflex_edges, schonhardt_bp};
/// let p = schonhardt_bp();
/// assert_eq!(p.points.len(), 12);
/// assert!(reflex_edges(&p).is_empty());
/// ```
pub fn schonhardt_bp() -> Polyhedron {
    let mut cur = schonhardt();
    for [p, q] in reflex_edges(&cur) {
        let g = SurfaceGraph::new(&cur);
        // tri(pq) = [s, t] with faces (p, q, s) and (q, p, t).
        let [s, t] = g.tri(p, q).expect("reflex edge present");
        let pt = |v: u32| cur.points[v as usize];
        let (ps, pp, ptt, pq) = (pt(s), pt(p), pt(t), pt(q));
        let n = unit(cross(&sub(&ptt, &ps), &sub(&pq, &pp)));
        let centre = [0, 1, 2].map(|i| (ps[i] + pp[i] + ptt[i] + pq[i]) / 4.0);
        let before = reflex_edges(&cur).len();
        let mut found = None;
        for k in 1..80 {
            for sign in [1.0, -1.0] {
                let h = sign * 0.05 * k as f64;
                let mid =
                    |a: &Point3| axpy(&[0, 1, 2].map(|i| (2.0 * a[i] + centre[i]) / 3.0), h, &n);
                let mut points = cur.points.clone();
                let i1 = points.len() as u32;
                points.push(mid(&ps).map(|c| (c * 1024.0).round() / 1024.0));
                points.push(mid(&ptt).map(|c| (c * 1024.0).round() / 1024.0));
                let path = [s, i1, i1 + 1, t];
                let mut faces: Vec<[u32; 3]> = cur
                    .faces
                    .iter()
                    .filter(|f| !(f.contains(&p) && f.contains(&q)))
                    .copied()
                    .collect();
                for w in path.windows(2) {
                    faces.push([p, w[1], w[0]]);
                    faces.push([q, w[0], w[1]]);
                }
                if let Ok(next) = Polyhedron::new(points, faces) {
                    let reflex = reflex_edges(&next);
                    if reflex.len() < before
                        && reflex
                            .iter()
                            .all(|e| !e.contains(&i1) && !e.contains(&(i1 + 1)))
                    {
                        found = Some(next);
                        break;
                    }
                }
            }
            if found.is_some() {
                break;
            }
        }
        cur = found.expect("a convexifying placement exists");
    }
    cur
}
