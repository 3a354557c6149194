//! Algorithm MINTETRA (thesis §3.4, Theorems 3.7–3.8), for augmented and multi-level
//! BP-polyhedra.
//!
//! The polyhedron is trimmed until nothing is left:
//! * a vertex `u` of degree 3 is a stacked tetrahedron `u u1 u2 u3` (Step 2.1);
//! * two adjacent vertices `u, w` of degree 4 are the middle of a BP-net
//!   `B(p u' u w u'' q)` (Theorem 3.4, Step 2.3(a)); the three tetrahedra
//!   `pqu'u, pquw, pqwu''` are removed and the polar edge `pq` added. The rest of a longer
//!   BP-net becomes stacked and goes by the first rule.
//!
//! Departures from the thesis, and why:
//! * **Exact containment.** The thesis assumes the trimmed pieces lie in the polyhedron
//!   (properness). Here every tetrahedron is checked exactly against the *current* surface
//!   before it is removed: it must lie on the inner side of the facets it replaces and no
//!   other facet may meet it except in shared vertices and edges (hash-grid filter, then
//!   exact triangle tests). A piece that fails waits; it is retried after other trims,
//!   because removing material elsewhere can unblock it. So a YES is a shelling: every
//!   tetrahedron lay inside what was left, which is a tetrahedralization by induction, and
//!   the caller still certifies it with [`mesh::verify`](crate::mesh::verify).
//! * **Work queues instead of the vertex scan.** Degree-3 vertices go first, then
//!   degree-4 ones; a trim re-queues only the vertices whose degree changed. Each trim
//!   costs O(degree) plus the grid query, so the whole run is O(n) on inputs whose facets
//!   are of comparable size (the thesis's bound is O(n²)).
//! * **Levels.** A BP-net of the internal polyhedron P_(h-1) shows only once an outer
//!   net has been trimmed, through one of its edges being that net's polar edge (§3.3.3).
//!   So a BP trim's level is one more than the highest level among the polar edges that
//!   are edges of the trimmed piece (0 for an edge of the input). `levels` is the highest
//!   level: 1 for a BP-polyhedron (Theorem 3.5), 2 for a two-level one (Theorem 3.6), h
//!   for the conjecture's h-level ones (§3.5).

use super::{Minimality, Polyhedron, SurfaceGraph};
use crate::geom::{Point3, orient3d, tetrahedra_overlap};
use crate::mesh::grid::TriangleGrid;
use crate::mesh::rotated_face;
use std::collections::{HashMap, VecDeque};

/// What MINTETRA found.
#[derive(Clone, Debug)]
pub struct Mintetra {
    /// True when the whole polyhedron was trimmed away.
    pub yes: bool,
    /// The tetrahedra removed, positively oriented, in removal order.
    pub tets: Vec<[u32; 4]>,
    /// The polar edges added (the diagonals of the tetrahedralization).
    pub polar_edges: Vec<[u32; 2]>,
    /// The highest BP level (0: stacked polyhedron).
    pub levels: u32,
    /// For every level `h >= 1`, how many BP trims it had.
    pub trims_per_level: Vec<usize>,
    /// On NO: the facets of what is left.
    pub remaining: Vec<[u32; 3]>,
    /// On NO: why nothing more could be trimmed.
    pub reason: String,
}

/// How much geometry MINTETRA checks while trimming.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Checks {
    /// Every removed tetrahedron is checked exactly against the current surface: a YES is
    /// a shelling, and a NO means that no trim order the algorithm tries works.
    Shelling,
    /// Orientation checks only; the grid is not even built. Much faster, but a YES must
    /// be certified ([`certify_polyhedron`](crate::mesh::certify_polyhedron)): if it fails, or on NO, run
    /// [`Checks::Shelling`]. The CLI does exactly this; the certificate is run on every
    /// answer anyway, so the per-trim checks are redundant whenever it passes.
    OrientationOnly,
}

/// What MINTETRA's answer proves about minimality: [`Minimality::Proven`] when Theorem
/// 3.5 / Corollary 3.6 apply (at most one level and disjoint proper BP-nets), else
/// [`Minimality::Conjectured`] (§3.5; the exact solver can confirm it).
pub fn minimality(p: &Polyhedron, m: &Mintetra) -> Minimality {
    if m.levels <= 1 && super::proper_nets_disjoint(p) {
        Minimality::Proven
    } else {
        Minimality::Conjectured
    }
}

/// Seconds spent by [`mintetra_certified`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Seconds {
    /// Trimming (both runs when the fast one did not do).
    pub trimming: f64,
    /// Certificates.
    pub certificate: f64,
}

/// MINTETRA, fast and certified: the orientation-only run ([`Checks::OrientationOnly`]),
/// whose YES is kept once [`certify_polyhedron`](crate::mesh::certify_polyhedron)
/// passes; on NO, or if the certificate fails, the shelling run decides, and its YES is
/// certified too (an `Err` would be a bug in MINTETRA, with the certificate's problem).
///
/// ```
/// use tetrakit::polyhedra::{Polyhedron, mintetra_certified};
/// let pts = vec![[1.0, 0.0, 0.0], [-0.5, 0.9, 0.0], [-0.5, -0.9, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
/// let faces = vec![[0, 1, 3], [1, 2, 3], [2, 0, 3], [1, 0, 4], [2, 1, 4], [0, 2, 4]];
/// let (m, _) = mintetra_certified(&Polyhedron::new(pts, faces).unwrap()).unwrap();
/// assert_eq!((m.yes, m.tets.len()), (true, 2));
/// ```
pub fn mintetra_certified(p: &Polyhedron) -> Result<(Mintetra, Seconds), crate::mesh::Problem> {
    let mut s = Seconds::default();
    let timed = |f: &mut dyn FnMut() -> Mintetra, acc: &mut f64| {
        let t = std::time::Instant::now();
        let m = f();
        *acc += t.elapsed().as_secs_f64();
        m
    };
    let certify = |m: &Mintetra, acc: &mut f64| {
        let t = std::time::Instant::now();
        let ok = crate::mesh::certify_polyhedron(p, &m.tets);
        *acc += t.elapsed().as_secs_f64();
        ok
    };
    let m = timed(
        &mut || mintetra(p, Checks::OrientationOnly),
        &mut s.trimming,
    );
    if m.yes && certify(&m, &mut s.certificate).is_ok() {
        return Ok((m, s));
    }
    let m = timed(&mut || mintetra(p, Checks::Shelling), &mut s.trimming);
    if m.yes {
        certify(&m, &mut s.certificate)?;
    }
    Ok((m, s))
}

/// Runs MINTETRA on a validated polyhedron, with the given [`Checks`].
///
/// ```
/// use tetrakit::polyhedra::{Checks, Polyhedron, mintetra};
/// // A triangular bipyramid: poles 3 and 4, equator 0 1 2.
/// let pts = vec![[1.0, 0.0, 0.0], [-0.5, 0.9, 0.0], [-0.5, -0.9, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]];
/// let faces = vec![[0, 1, 3], [1, 2, 3], [2, 0, 3], [1, 0, 4], [2, 1, 4], [0, 2, 4]];
/// let p = Polyhedron::new(pts, faces).unwrap();
/// let m = mintetra(&p, Checks::Shelling);
/// assert!(m.yes);
/// assert_eq!(m.tets.len(), 2); // two stacked tetrahedra, n - 3
/// ```
pub fn mintetra(p: &Polyhedron, checks: Checks) -> Mintetra {
    let mut t = Trimmer::new(p, checks == Checks::Shelling);
    t.run();
    t.finish()
}

struct Trimmer<'a> {
    points: &'a [Point3],
    g: SurfaceGraph,
    grid: Option<TriangleGrid>,
    deg3: VecDeque<u32>,
    deg4: VecDeque<u32>,
    blocked: Vec<u32>,
    polar_level: HashMap<[u32; 2], u32>,
    tets: Vec<[u32; 4]>,
    polar: Vec<[u32; 2]>,
    per_level: Vec<usize>,
}

impl<'a> Trimmer<'a> {
    fn new(p: &'a Polyhedron, careful: bool) -> Self {
        // Only the careful mode queries the grid.
        let grid = careful.then(|| TriangleGrid::of_faces(&p.points, &p.faces));
        let g = SurfaceGraph::new(p);
        let n = p.points.len();
        let mut t = Trimmer {
            points: &p.points,
            g,
            grid,
            deg3: VecDeque::new(),
            deg4: VecDeque::new(),
            blocked: Vec::new(),
            polar_level: HashMap::new(),
            tets: Vec::with_capacity(n),
            polar: Vec::new(),
            per_level: Vec::new(),
        };
        (0..n as u32).for_each(|v| t.enqueue(v));
        t
    }

    fn enqueue(&mut self, v: u32) {
        match self.g.degree(v) {
            3 => self.deg3.push_back(v),
            4 => self.deg4.push_back(v),
            _ => {}
        }
    }

    fn run(&mut self) {
        loop {
            let progressed_before = self.tets.len();
            while self.g.alive() > 0 {
                let Some(u) = self.deg3.pop_front().or_else(|| self.deg4.pop_front()) else {
                    break;
                };
                let trimmed = match self.g.degree(u) {
                    3 => self.trim_stacked(u),
                    4 => self.trim_bp(u),
                    _ => continue,
                };
                if !trimmed && self.g.is_alive(u) {
                    self.blocked.push(u);
                }
            }
            if self.g.alive() == 0
                || self.blocked.is_empty()
                || self.tets.len() == progressed_before
            {
                return;
            }
            for u in std::mem::take(&mut self.blocked) {
                self.enqueue(u);
            }
        }
    }

    fn p(&self, v: u32) -> &Point3 {
        &self.points[v as usize]
    }

    /// Step 2.1: a degree-3 vertex.
    fn trim_stacked(&mut self, u: u32) -> bool {
        let r = self.g.ring(u).to_vec();
        // Inner side of the facet (u, r0, r1) is negative.
        if orient3d(self.p(u), self.p(r[0]), self.p(r[1]), self.p(r[2])) >= 0 {
            return false;
        }
        let tet = [u, r[0], r[1], r[2]];
        if self.g.alive() == 4 {
            self.push_tet(tet);
            self.g.clear();
            return true;
        }
        let removed = [[u, r[0], r[1]], [u, r[1], r[2]], [u, r[2], r[0]]];
        if !self.fits(&tet, &removed) {
            return false;
        }
        self.push_tet(tet);
        self.g.kill(u);
        for &x in &r {
            self.g.unlink(x, u);
        }
        self.index([r[0], r[1], r[2]]);
        r.iter().for_each(|&x| self.enqueue(x));
        true
    }

    /// Step 2.3(a): a degree-4 vertex with a degree-4 neighbour.
    fn trim_bp(&mut self, u: u32) -> bool {
        let ring = self.g.ring(u).to_vec();
        for &w in &ring {
            if self.g.degree(w) == 4 && self.try_bp(u, w) {
                return true;
            }
        }
        false
    }

    fn try_bp(&mut self, u: u32, w: u32) -> bool {
        // ring(u) = [w, a, b, c]: facets (u,w,a), (u,a,b), (u,b,c), (u,c,w).
        let ru = self.g.ring_from(u, w).expect("w adjacent to u");
        let (a, b, c) = (ru[1], ru[2], ru[3]);
        // ring(w) = [u, c, d, a]: facets (w,u,c), (w,c,d), (w,d,a), (w,a,u).
        let Some(rw) = self.g.ring_from(w, u) else {
            return false;
        };
        if rw[1] != c || rw[3] != a {
            return false;
        }
        let d = rw[2];
        let closed = b == d; // a bipyramid over the triangle u w b
        if closed && self.g.alive() != 5 {
            return false;
        }
        if !closed && self.g.adjacent(a, c) {
            return false; // pq already an edge: trimming would pinch the surface
        }
        let pieces = [[a, c, b, u], [a, c, u, w], [a, c, w, d]];
        // Each piece lies on the inner side of a facet it replaces.
        let inner = [(u, a, b, c), (u, w, a, c), (w, c, d, a)];
        if inner
            .iter()
            .any(|&(x, y, z, o)| orient3d(self.p(x), self.p(y), self.p(z), self.p(o)) >= 0)
        {
            return false;
        }
        let removed = [
            [u, w, a],
            [u, a, b],
            [u, b, c],
            [u, c, w],
            [w, c, d],
            [w, d, a],
        ];
        if !closed && !pieces.iter().all(|t| self.fits(t, &removed)) {
            return false;
        }
        let geo = |t: &[u32; 4]| t.map(|v| *self.p(v));
        for (i, j) in [(0, 1), (1, 2), (0, 2)] {
            if tetrahedra_overlap(&geo(&pieces[i]), &geo(&pieces[j])) {
                return false;
            }
        }
        let edge = |x: u32, y: u32| [x.min(y), x.max(y)];
        let piece = [(u, w), (u, a), (u, b), (u, c), (w, c), (w, d), (w, a)];
        let lvl = 1 + piece
            .iter()
            .map(|&(x, y)| self.polar_level.get(&edge(x, y)).copied().unwrap_or(0))
            .max()
            .unwrap_or(0);
        if self.per_level.len() < lvl as usize {
            self.per_level.resize(lvl as usize, 0);
        }
        self.per_level[lvl as usize - 1] += 1;
        pieces.iter().for_each(|&t| self.push_tet(t));
        if closed {
            self.g.clear();
            return true;
        }
        self.polar.push(edge(a, c));
        self.polar_level.insert(edge(a, c), lvl);
        self.g.kill(u);
        self.g.kill(w);
        self.g.contract(a, u, w, c);
        self.g.contract(c, w, u, a);
        self.g.unlink(b, u);
        self.g.unlink(d, w);
        self.index([a, b, c]);
        self.index([c, d, a]);
        [a, b, c, d].iter().for_each(|&x| self.enqueue(x));
        true
    }

    /// Adds a new surface face to the grid (only the careful mode queries it).
    fn index(&mut self, f: [u32; 3]) {
        if let Some(grid) = &mut self.grid {
            grid.insert(self.points, f);
        }
    }

    fn push_tet(&mut self, t: [u32; 4]) {
        let [a, b, c, d] = t.map(|v| self.p(v));
        self.tets.push(if orient3d(a, b, c, d) > 0 {
            t
        } else {
            [t[0], t[2], t[1], t[3]]
        });
    }

    /// True when the tetrahedron meets no current facet other than `removed` except in
    /// shared vertices and edges.
    fn fits<const N: usize>(&self, tet: &[u32; 4], removed: &[[u32; 3]; N]) -> bool {
        let Some(grid) = &self.grid else {
            return true;
        };
        // Dead faces stay in the grid: the ring look-up drops them before any geometry.
        let removed = removed.map(rotated_face);
        !grid.blocks_tet(self.points, tet, |f| {
            self.g.has_facet(f[0], f[1], f[2]) && !removed.contains(&rotated_face(*f))
        })
    }

    fn finish(self) -> Mintetra {
        let yes = self.g.alive() == 0;
        let remaining = if yes { Vec::new() } else { self.g.facets() };
        let reason = if yes {
            String::new()
        } else {
            let low: Vec<u32> = (0..self.g.len() as u32)
                .filter(|&v| self.g.is_alive(v) && self.g.degree(v) <= 4)
                .collect();
            if low.is_empty() {
                format!(
                    "{} vertices are left and every one has degree 5 or more: no stacked tetrahedron or BP-net remains",
                    self.g.alive()
                )
            } else {
                format!(
                    "{} vertices are left; the {} of degree 3 or 4 start no stacked tetrahedron or BP-net that lies inside what is left",
                    self.g.alive(),
                    low.len()
                )
            }
        };
        Mintetra {
            yes,
            tets: self.tets,
            polar_edges: self.polar,
            levels: self.per_level.len() as u32,
            trims_per_level: self.per_level,
            remaining,
            reason,
        }
    }
}
