//! Generators of simple polyhedra for chapter 3: stacked polyhedra, bipyramids,
//! (augmented) BP-polyhedra, two- and h-level BP-polyhedra, Schönhardt's polyhedron and
//! the §3.5 counterexample (Figure 3.21).
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

use super::Polyhedron;
use crate::geom::{Point3, orient3d};
use crate::rng::Rng;

/// A polyhedron under construction; faces always outward.
#[derive(Clone)]
struct Builder {
    points: Vec<Point3>,
    faces: Vec<[u32; 3]>,
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
    fn tetrahedron(rng: &mut Rng) -> Builder {
        let mut j = || rng.unit() * 0.1;
        let points = vec![
            [1.0 + j(), 1.0 + j(), 1.0 + j()],
            [1.0 + j(), -1.0 + j(), -1.0 + j()],
            [-1.0 + j(), 1.0 + j(), -1.0 + j()],
            [-1.0 + j(), -1.0 + j(), 1.0 + j()],
        ];
        let faces = vec![[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]];
        Builder::checked(points, faces).expect("a tetrahedron")
    }

    fn checked(points: Vec<Point3>, faces: Vec<[u32; 3]>) -> Option<Builder> {
        Polyhedron::new(points, faces).ok().map(|p| Builder {
            points: p.points,
            faces: p.faces,
        })
    }

    fn finish(self) -> Polyhedron {
        Polyhedron::new(self.points, self.faces).expect("generators keep polyhedra simple")
    }

    /// Stacks a tetrahedron on facet `f`; `None` when no height tried keeps it simple.
    fn stack(&self, f: usize, rng: &mut Rng) -> Option<Builder> {
        let [a, b, c] = self.faces[f];
        let [pa, pb, pc] = [a, b, c].map(|v| self.points[v as usize]);
        let n = cross(&sub(&pb, &pa), &sub(&pc, &pa));
        let size = dot(&n, &n).sqrt().sqrt();
        let n = unit(n);
        let (wa, wb) = (0.2 + 0.6 * rng.unit(), rng.unit());
        let (wa, wb, wc) = (wa / 2.0 + 0.15, (1.0 - wa) * wb / 2.0 + 0.15, 0.0);
        let wc = 1.0 - wa - wb + wc;
        let centre = [0, 1, 2].map(|i| wa * pa[i] + wb * pb[i] + wc * pc[i]);
        let mut h = size * (0.3 + 0.4 * rng.unit());
        for _ in 0..12 {
            let x = self.points.len() as u32;
            let mut next = self.clone();
            next.points.push(axpy(&centre, h, &n));
            next.faces[f] = [a, b, x];
            next.faces.extend([[b, c, x], [c, a, x]]);
            if let Some(ok) = Builder::checked(next.points, next.faces) {
                return Some(ok);
            }
            h *= 0.5;
        }
        None
    }

    /// The two facets on edge `pq`: `(p, q, s)` and `(q, p, t)`, as face indices and apexes.
    fn wings(&self, p: u32, q: u32) -> Option<(usize, u32, usize, u32)> {
        let mut first = None;
        let mut second = None;
        for (i, f) in self.faces.iter().enumerate() {
            for r in 0..3 {
                let (x, y, z) = (f[r], f[(r + 1) % 3], f[(r + 2) % 3]);
                if x == p && y == q {
                    first = Some((i, z));
                }
                if x == q && y == p {
                    second = Some((i, z));
                }
            }
        }
        let ((i, s), (j, t)) = (first?, second?);
        Some((i, s, j, t))
    }

    /// Glues a BP-net with path length `m` (m - 1 new vertices) on edge `pq`.
    fn glue(&self, p: u32, q: u32, m: usize, rng: &mut Rng) -> Option<(Builder, Vec<u32>)> {
        let (fi, s, fj, t) = self.wings(p, q)?;
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
        // Outward normals of the two facets point into the exterior wedge.
        let n1 = unit(cross(&sub(&pq, &pp), &sub(&pt(s), &pp)));
        let n2 = unit(cross(&sub(&pp, &pq), &sub(&pt(t), &pq)));
        let out = [n1[0] + n2[0], n1[1] + n2[1], n1[2] + n2[2]];
        let (phi_t, phi_o) = (angle(&dt), angle(&out));
        let sweep = if phi_o < phi_t {
            phi_t
        } else {
            phi_t - std::f64::consts::TAU
        };
        let mut r = len * (0.12 + 0.08 * rng.unit());
        for _ in 0..12 {
            let mut next = self.clone();
            let mut path = vec![s];
            for j in 1..m {
                let a = sweep * (j as f64 + 0.3 * (rng.unit() - 0.5)) / m as f64;
                let along = 0.5 + 0.2 * (rng.unit() - 0.5);
                let base = axpy(&pp, along * len, &e);
                let dir = [0, 1, 2].map(|i| a.cos() * ds[i] + a.sin() * e2[i]);
                next.points.push(axpy(&base, r, &dir));
                path.push(next.points.len() as u32 - 1);
            }
            path.push(t);
            let mut faces: Vec<[u32; 3]> = next
                .faces
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != fi && i != fj)
                .map(|(_, f)| *f)
                .collect();
            for w in path.windows(2) {
                faces.push([p, w[1], w[0]]);
                faces.push([q, w[0], w[1]]);
            }
            if let Some(ok) = Builder::checked(next.points, faces) {
                return Some((ok, path[1..m].to_vec()));
            }
            r *= 0.5;
        }
        None
    }

    fn edges(&self) -> Vec<[u32; 2]> {
        let mut e: Vec<[u32; 2]> = self
            .faces
            .iter()
            .flat_map(|f| [[f[0], f[1]], [f[1], f[2]], [f[2], f[0]]])
            .filter(|e| e[0] < e[1])
            .collect();
        e.sort_unstable();
        e
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
    stack_more(&mut b, n.max(4) - 4, &mut rng);
    b.finish()
}

fn stack_more(b: &mut Builder, k: usize, rng: &mut Rng) {
    let mut added = 0;
    while added < k {
        let f = rng.below(b.faces.len());
        if let Some(next) = b.stack(f, rng) {
            *b = next;
            added += 1;
        }
    }
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
    /// Vertices of the stacked core (at least 4).
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
/// use tetrakit::polyhedra::{generate, mintetra};
/// let (p, polar) = generate::bp_polyhedron(generate::BpParams::default());
/// let m = mintetra(&p);
/// assert!(m.yes);
/// assert_eq!(m.tets.len(), p.points.len() - 3 + polar);
/// ```
pub fn bp_polyhedron(params: BpParams) -> (Polyhedron, usize) {
    let mut rng = Rng::new(params.seed);
    let mut b = Builder::tetrahedron(&mut rng);
    stack_more(&mut b, params.core.max(4) - 4, &mut rng);
    let mut polar = 0;
    // Edges eligible for the next round: any edge for the first, then edges between a
    // pole and an inner vertex of the previous round's nets.
    let mut eligible: Vec<Vec<[u32; 2]>> = vec![b.edges()];
    for level in 0..params.levels.max(1) {
        let mut next_eligible = Vec::new();
        let mut used = std::collections::HashSet::new();
        let groups = if level == 0 {
            let mut all = eligible[0].clone();
            rng.shuffle(&mut all);
            all.into_iter()
                .take(params.nets * 4)
                .map(|e| vec![e])
                .collect()
        } else {
            std::mem::take(&mut eligible)
        };
        let mut glued = 0;
        for group in groups {
            if glued == params.nets && level == 0 {
                break;
            }
            let mut group = group;
            rng.shuffle(&mut group);
            for [p, q] in group {
                let Some((_, s, _, t)) = b.wings(p, q) else {
                    continue;
                };
                if used.contains(&p)
                    || used.contains(&q)
                    || (!params.hide_all && (used.contains(&s) || used.contains(&t)))
                {
                    continue;
                }
                let m = 3 + rng.below(params.max_m.max(3) - 2);
                if let Some((nb, inner)) = b.glue(p, q, m, &mut rng) {
                    b = nb;
                    used.extend([p, q]);
                    if !params.hide_all {
                        used.extend([s, t]);
                    }
                    used.extend(inner.iter().copied());
                    let around = |v: u32| vec![[p.min(v), p.max(v)], [q.min(v), q.max(v)]];
                    if params.hide_all {
                        next_eligible.extend(inner.iter().map(|&v| around(v)));
                    } else {
                        next_eligible.push(inner.iter().flat_map(|&v| around(v)).collect());
                    }
                    polar += 1;
                    glued += 1;
                    break;
                }
            }
        }
        eligible = next_eligible;
    }
    stack_more(&mut b, params.augment, &mut rng);
    (b.finish(), polar)
}

/// Schönhardt's twisted prism (§2.6, Figure 2.11(a)): six vertices, three reflex edges,
/// no tetrahedralization.
pub fn schonhardt() -> Polyhedron {
    let b = schonhardt_builder();
    b.finish()
}

fn schonhardt_builder() -> Builder {
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
    let mut points = tri(0.0, 0.0); // q1 q2 q3 (bottom)
    points.extend(tri(2.0, 0.5)); // p1 p2 p3 (top), twisted
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
        if let Some(b) = Builder::checked(points.clone(), faces)
            && reflex_edges(&b).len() == 3
        {
            return b;
        }
    }
    unreachable!("one diagonal choice gives Schönhardt's polyhedron")
}

/// Edges whose dihedral angle exceeds π: `(p, q)` with facets `pqs`, `qpt` and `t`
/// strictly outside facet `pqs`.
fn reflex_edges(b: &Builder) -> Vec<[u32; 2]> {
    b.edges()
        .into_iter()
        .filter(|&[p, q]| {
            let (_, s, _, t) = b.wings(p, q).expect("closed surface");
            let pt = |v: u32| &b.points[v as usize];
            orient3d(pt(p), pt(q), pt(s), pt(t)) > 0
        })
        .collect()
}

/// The §3.5 counterexample (Figure 3.21): Schönhardt's polyhedron with a BP-net glued on
/// each reflex edge so that the result is convex. Trimming the three BP-nets gives back
/// Schönhardt's polyhedron, which is not stacked, so MINTETRA answers NO although the
/// polyhedron (being convex) has tetrahedralizations.
pub fn schonhardt_bp() -> Polyhedron {
    let base = schonhardt_builder();
    let mut b = base.clone();
    for [p, q] in reflex_edges(&base) {
        let (fi, s, fj, t) = b.wings(p, q).expect("reflex edge present");
        let pt = |v: u32| b.points[v as usize];
        // Place the path s a1 a2 t on the far side of the quad s p t q, pushed outward
        // until every edge is convex.
        let (ps, pp, pt_, pq) = (pt(s), pt(p), pt(t), pt(q));
        let n = unit(cross(&sub(&pt_, &ps), &sub(&pq, &pp)));
        let centre = [0, 1, 2].map(|i| (ps[i] + pp[i] + pt_[i] + pq[i]) / 4.0);
        let mut found = None;
        for k in 1..40 {
            let h = 0.05 * k as f64;
            let a1 = axpy(&[0, 1, 2].map(|i| (2.0 * ps[i] + centre[i]) / 3.0), h, &n);
            let a2 = axpy(&[0, 1, 2].map(|i| (2.0 * pt_[i] + centre[i]) / 3.0), h, &n);
            let mut next = b.clone();
            let mut add = |x: Point3| {
                next.points.push(x.map(|c| (c * 1024.0).round() / 1024.0));
                next.points.len() as u32 - 1
            };
            let (i1, i2) = (add(a1), add(a2));
            let path = [s, i1, i2, t];
            let mut faces: Vec<[u32; 3]> = next
                .faces
                .iter()
                .enumerate()
                .filter(|&(i, _)| i != fi && i != fj)
                .map(|(_, f)| *f)
                .collect();
            for w in path.windows(2) {
                faces.push([p, w[1], w[0]]);
                faces.push([q, w[0], w[1]]);
            }
            if let Some(ok) = Builder::checked(next.points, faces) {
                let reflex = reflex_edges(&ok);
                if reflex.len() < reflex_edges(&b).len()
                    && reflex.iter().all(|e| !e.contains(&i1) && !e.contains(&i2))
                {
                    found = Some(ok);
                }
            }
            if found.is_some() {
                break;
            }
        }
        b = found.expect("a convexifying placement exists");
    }
    b.finish()
}
