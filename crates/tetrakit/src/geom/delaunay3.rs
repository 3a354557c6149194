//! The Delaunay tetrahedralization of a point set, exactly: Bowyer–Watson insertion
//! with an infinite vertex, in a biased randomized order (BRIO: random rounds, each
//! sorted along a Morton curve), each point located by a visibility walk.
//!
//! **No general position.** Where five points are cospherical (or four coplanar points
//! on the hull are cocircular) the empty-sphere test is decided by a symbolic
//! perturbation of the lifting in the order of insertion: the `r`-th point inserted is
//! lifted to `|p|² + ε^(N−r)`, so a point inserted later is lifted more. In every test
//! the point being inserted is the newest, so at a tie its own lift, the largest
//! perturbation, decides: raised, it leaves the sphere. A cell is therefore in conflict
//! exactly when the new point is strictly inside its sphere, and the cavities of
//! degenerate insertions are as small as they can be (the integer points on a sphere:
//! 0.07 s at 10^4 points where a perturbation by input index, which lets an old point's
//! lift decide, took 0.34 s with cavities of thousands of cells).
//!
//! The result is the regular triangulation of the perturbed lifted points, one
//! tetrahedralization of the convex hull with every distinct point a vertex (the lifted
//! points are in convex position), Delaunay for the unperturbed points (a tetrahedron's
//! sphere has no point strictly inside). Which one, among several where points are
//! cospherical, depends on the insertion order, which is fixed (a seeded shuffle).
//!
//! A point coplanar with a hull face is in conflict with the infinite cell on that face
//! exactly when it is with the finite one: strictly inside the face's circumcircle, by
//! the same test (the sphere meets the face's plane in that circle). Likewise two cells
//! sharing a face agree on a point in its plane, so a cavity's boundary face is never
//! coplanar with the new point, and every new tetrahedron is positively oriented.
//!
//! Repeated points and flat sets have no such tetrahedralization; they are reported, not
//! dropped ([`DelaunayError`]).

use super::{Point3, insphere, orient3d};
use crate::control::Control;
use crate::rng::Rng;

/// The infinite vertex, and "no tetrahedron" in the neighbour lists.
const INF: u32 = u32::MAX;
const NONE: u32 = u32::MAX;

/// The Delaunay tetrahedralization of a point set ([`Delaunay3::new`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Delaunay3 {
    /// Positively oriented tetrahedra (`orient3d > 0`), on the input's indices.
    pub tets: Vec<[u32; 4]>,
    /// `neighbours[t][k]`: the tetrahedron sharing the face of `tets[t]` opposite its
    /// `k`-th vertex, or `u32::MAX` where that face is on the hull.
    pub neighbours: Vec<[u32; 4]>,
}

/// Why a point set has no Delaunay tetrahedralization with every point a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DelaunayError {
    /// The points span less than three dimensions.
    Flat,
    /// Point `second` repeats point `first`.
    Repeated {
        /// The point inserted first.
        first: u32,
        /// The repeat.
        second: u32,
    },
    /// A point location walked longer than the number of tetrahedra allows, or a
    /// cavity's boundary was not closed (a bug).
    Lost,
    /// The run-control stopped it ([`Delaunay3::within`]).
    Stopped,
}

impl Delaunay3 {
    /// The Delaunay tetrahedralization of `points` (see the module docs for ties).
    ///
    /// ```
    /// use tetrakit::geom::{Delaunay3, DelaunayError};
    /// // The eight corners of a cube are cospherical: six tetrahedra or five, by the
    /// // perturbation; either way a tetrahedralization of the cube.
    /// let cube: Vec<[f64; 3]> =
    ///     (0..8).map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64]).collect();
    /// let d = Delaunay3::new(&cube).unwrap();
    /// assert!(d.tets.len() == 5 || d.tets.len() == 6);
    /// assert!(tetrakit::mesh::certify_hull(&cube, &d.tets).is_ok());
    /// let flat = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]];
    /// assert_eq!(Delaunay3::new(&flat), Err(DelaunayError::Flat));
    /// ```
    pub fn new(points: &[Point3]) -> Result<Delaunay3, DelaunayError> {
        Delaunay3::within(points, &Control::new())
    }

    /// [`Delaunay3::new`] under a run-control: [`DelaunayError::Stopped`] once `ctl` is
    /// stopped (asked before every insertion).
    ///
    /// ```
    /// use tetrakit::control::Control;
    /// use tetrakit::geom::{Delaunay3, DelaunayError};
    /// let pts: Vec<[f64; 3]> = (0..300).map(|i| {
    ///     let t = i as f64;
    ///     [t.sin(), (2.0 * t).cos(), (3.0 * t).sin() * t]
    /// }).collect();
    /// let ctl = Control::new();
    /// assert!(Delaunay3::within(&pts, &ctl).is_ok());
    /// ctl.stop();
    /// assert_eq!(Delaunay3::within(&pts, &ctl), Err(DelaunayError::Stopped));
    /// ```
    pub fn within(points: &[Point3], ctl: &Control) -> Result<Delaunay3, DelaunayError> {
        let order = brio(points);
        let (mut b, simplex) = Builder::start(points)?;
        for &i in &order {
            if ctl.is_stopped() {
                return Err(DelaunayError::Stopped);
            }
            if !simplex.contains(&i) {
                b.insert(i)?;
            }
        }
        Ok(b.finish())
    }
}

/// The insertion order: rounds of doubling size in random order (the last holds half
/// the points), each sorted along a Morton curve (the coordinates only order the
/// points; no decision depends on them).
fn brio(points: &[Point3]) -> Vec<u32> {
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    Rng::new(0x5eed_de1a).shuffle(&mut order);
    let (lo, hi) = super::bounding_box(points);
    let scale: Vec<f64> = (0..3)
        .map(|k| (hi[k] - lo[k]).max(f64::MIN_POSITIVE))
        .collect();
    let key = |i: &u32| {
        let p = &points[*i as usize];
        let q = |k: usize| (((p[k] - lo[k]) / scale[k]) * 2097151.0) as u64;
        morton(q(0), q(1), q(2))
    };
    let mut end = order.len();
    while end > 0 {
        let start = if end > 64 { end / 2 } else { 0 };
        order[start..end].sort_by_cached_key(key);
        end = start;
    }
    order
}

/// The Morton code of three 21-bit coordinates.
fn morton(x: u64, y: u64, z: u64) -> u64 {
    let spread = |mut v: u64| {
        v &= 0x1f_ffff;
        v = (v | v << 32) & 0x1f_0000_0000_ffff;
        v = (v | v << 16) & 0x1f_0000_ff00_00ff;
        v = (v | v << 8) & 0x100f_00f0_0f00_f00f;
        v = (v | v << 4) & 0x10c3_0c30_c30c_30c3;
        (v | v << 2) & 0x1249_2492_4924_9249
    };
    spread(x) | spread(y) << 1 | spread(z) << 2
}

/// The triangulation under construction: tetrahedra (`INF` marks the infinite vertex),
/// their neighbours, the free slots, and the scratch of one insertion.
struct Builder<'p> {
    pts: &'p [Point3],
    cells: Vec<[u32; 4]>,
    nbr: Vec<[u32; 4]>,
    alive: Vec<bool>,
    free: Vec<u32>,
    /// The insertion that last tested each cell, and the test's answer.
    seen: Vec<u32>,
    conflict: Vec<bool>,
    stamp: u32,
    /// Where the next walk starts.
    last: u32,
    rng: Rng,
    stack: Vec<u32>,
    cavity: Vec<u32>,
    boundary: Vec<(u32, usize)>,
    /// Per vertex (the point at infinity last): the insertion that last filed a cone's
    /// face at it, and the first such face still waiting for its second cell.
    at: Vec<(u32, u32)>,
    /// A cone's faces through its apex ([`Builder::glue_cone`]).
    faces: Vec<Face>,
}

/// A face of a cone through its apex, waiting for its second cell: the other end of
/// its edge opposite the apex, its cell and the cell's index of it, and the next face
/// filed at the same vertex.
#[derive(Clone, Copy)]
struct Face {
    other: u32,
    cell: u32,
    k: u8,
    next: u32,
}

impl<'p> Builder<'p> {
    /// The first tetrahedron ([`initial_simplex`](super::hull3::initial_simplex)'s, of
    /// points far apart), with its four infinite neighbours.
    fn start(pts: &'p [Point3]) -> Result<(Self, [u32; 4]), DelaunayError> {
        let ([a, b, c, d], _) = (super::hull3::initial_simplex(pts))
            .filter(|&(_, dimension)| dimension == 3)
            .ok_or(DelaunayError::Flat)?;
        let p = |i: u32| &pts[i as usize];
        let first = match orient3d(p(a), p(b), p(c), p(d)) > 0 {
            true => [a, b, c, d],
            false => [b, a, c, d],
        };
        let mut b = Builder {
            pts,
            cells: Vec::with_capacity(7 * pts.len()),
            nbr: Vec::with_capacity(7 * pts.len()),
            alive: Vec::with_capacity(7 * pts.len()),
            free: Vec::new(),
            seen: Vec::with_capacity(7 * pts.len()),
            conflict: Vec::with_capacity(7 * pts.len()),
            stamp: 0,
            last: 0,
            rng: Rng::new(0x3a1c),
            stack: Vec::new(),
            cavity: Vec::new(),
            boundary: Vec::new(),
            at: vec![(0, NONE); pts.len() + 1],
            faces: Vec::new(),
        };
        // Infinite cell `k` holds the face opposite `first[k]`, across from the finite
        // cell; two infinite cells share the face through `INF` without either's vertex.
        let finite = b.add(first);
        let inf: Vec<u32> = (0..4)
            .map(|k| {
                let mut cell = first;
                cell[k] = INF;
                cell.swap((k + 1) % 4, (k + 2) % 4);
                b.add(cell)
            })
            .collect();
        for k in 0..4 {
            b.nbr[finite as usize][k] = inf[k];
            let cell = b.cells[inf[k] as usize];
            for (i, &v) in cell.iter().enumerate() {
                b.nbr[inf[k] as usize][i] = match first.iter().position(|&x| x == v) {
                    Some(j) => inf[j],
                    None => finite,
                };
            }
        }
        Ok((b, first))
    }

    /// A new cell with no neighbours yet.
    fn add(&mut self, cell: [u32; 4]) -> u32 {
        match self.free.pop() {
            Some(id) => {
                let t = id as usize;
                (self.cells[t], self.nbr[t], self.alive[t]) = (cell, [NONE; 4], true);
                id
            }
            None => {
                self.cells.push(cell);
                self.nbr.push([NONE; 4]);
                self.alive.push(true);
                self.seen.push(0);
                self.conflict.push(false);
                (self.cells.len() - 1) as u32
            }
        }
    }

    /// Inserts point `e`: its cavity (the cells whose sphere it is in), replaced by the
    /// cone from `e` over the cavity's boundary.
    fn insert(&mut self, e: u32) -> Result<(), DelaunayError> {
        let start = self.locate(e)?;
        self.stamp += 1;
        self.cavity.clear();
        self.boundary.clear();
        self.mark(start, true);
        self.stack.push(start);
        while let Some(c) = self.stack.pop() {
            self.cavity.push(c);
            for k in 0..4 {
                let n = self.nbr[c as usize][k];
                let inside = match self.seen[n as usize] == self.stamp {
                    true => self.conflict[n as usize],
                    false => {
                        let inside = self.in_conflict(n, e);
                        self.mark(n, inside);
                        if inside {
                            self.stack.push(n);
                        }
                        inside
                    }
                };
                if !inside {
                    self.boundary.push((c, k));
                }
            }
        }
        self.fill(e)
    }

    fn mark(&mut self, t: u32, inside: bool) {
        self.seen[t as usize] = self.stamp;
        self.conflict[t as usize] = inside;
    }

    /// Replaces the cavity by the cone from `e` over its boundary faces.
    fn fill(&mut self, e: u32) -> Result<(), DelaunayError> {
        for &c in &self.cavity {
            self.alive[c as usize] = false;
        }
        let mut made = Vec::with_capacity(self.boundary.len());
        let boundary = std::mem::take(&mut self.boundary);
        for &(c, k) in &boundary {
            let mut cell = self.cells[c as usize];
            cell[k] = e;
            let outer = self.nbr[c as usize][k];
            let id = self.add(cell);
            self.nbr[id as usize][k] = outer;
            let back = self.nbr[outer as usize].iter().position(|&x| x == c);
            if let Some(j) = back {
                self.nbr[outer as usize][j] = id;
            }
            made.push(id);
        }
        self.boundary = boundary;
        let glued = self.glue_cone(&made, e);
        self.free.extend(self.cavity.iter().copied());
        self.last = made[0];
        match glued {
            true => Ok(()),
            false => Err(DelaunayError::Lost),
        }
    }

    /// Glues the cone's cells to each other across the faces through `e`, each named by
    /// its two other vertices `lo < hi` and filed at `lo` (a list per vertex, stamped by
    /// the insertion: no hashing, nothing to clear). Every such face has two cells in the
    /// cone; false when one is left without its second, which `fill` reports as a bug.
    fn glue_cone(&mut self, made: &[u32], e: u32) -> bool {
        self.faces.clear();
        let mut open = 0usize;
        for &id in made {
            let c = self.cells[id as usize];
            for k in (0..4).filter(|&k| c[k] != e) {
                let mut others = (0..4).filter(|&i| i != k && c[i] != e).map(|i| c[i]);
                let (a, b) = (others.next().unwrap_or(e), others.next().unwrap_or(e));
                let (lo, hi) = (a.min(b), a.max(b));
                if let Some(Face { cell, k: j, .. }) = self.take_face(lo, hi) {
                    self.nbr[id as usize][k] = cell;
                    self.nbr[cell as usize][j as usize] = id;
                    open -= 1;
                } else {
                    let (cell, k, next) = (id, k as u8, NONE);
                    self.file_face(
                        lo,
                        Face {
                            other: hi,
                            cell,
                            k,
                            next,
                        },
                    );
                    open += 1;
                }
            }
        }
        open == 0
    }

    /// Vertex `v`'s place in [`Builder::at`] (the point at infinity last).
    fn slot(&self, v: u32) -> usize {
        if v == INF { self.pts.len() } else { v as usize }
    }

    /// The face filed at `lo` whose other end is `hi`, taken off the list (a list filed
    /// by an earlier insertion is dropped first).
    fn take_face(&mut self, lo: u32, hi: u32) -> Option<Face> {
        let s = self.slot(lo);
        if self.at[s].0 != self.stamp {
            self.at[s] = (self.stamp, NONE);
        }
        let (mut prev, mut f) = (NONE, self.at[s].1);
        while f != NONE && self.faces[f as usize].other != hi {
            (prev, f) = (f, self.faces[f as usize].next);
        }
        let face = *self.faces.get(f as usize)?;
        match prev {
            NONE => self.at[s].1 = face.next,
            p => self.faces[p as usize].next = face.next,
        }
        Some(face)
    }

    /// Files `face` at `lo` (whose list [`Builder::take_face`] has just searched).
    fn file_face(&mut self, lo: u32, mut face: Face) {
        let s = self.slot(lo);
        face.next = self.at[s].1;
        self.at[s].1 = self.faces.len() as u32;
        self.faces.push(face);
    }

    /// A cell in conflict with `e`, by a visibility walk from the last cell made.
    fn locate(&mut self, e: u32) -> Result<u32, DelaunayError> {
        let pe = self.pts[e as usize];
        let mut t = self.last;
        let mut from = NONE;
        for _ in 0..=self.cells.len() + 8 {
            let c = self.cells[t as usize];
            if let Some(k) = c.iter().position(|&v| v == INF) {
                // Outside the hull: this cell is in conflict when `e` is beyond its face
                // (always so when the walk crossed that face).
                if from != NONE || self.sees(&c, k, &pe) > 0 {
                    return Ok(t);
                }
                (from, t) = (t, self.nbr[t as usize][k]);
                continue;
            }
            let r = self.rng.below(4);
            let next = (0..4)
                .map(|i| (r + i) % 4)
                .find(|&k| self.nbr[t as usize][k] != from && self.sees(&c, k, &pe) < 0);
            match next {
                Some(k) => (from, t) = (t, self.nbr[t as usize][k]),
                None => {
                    return match c.iter().find(|&&v| self.pts[v as usize] == pe) {
                        Some(&v) => Err(DelaunayError::Repeated {
                            first: v,
                            second: e,
                        }),
                        None => Ok(t),
                    };
                }
            }
        }
        Err(DelaunayError::Lost)
    }

    /// `orient3d` of cell `c` with its `k`-th vertex replaced by `p`: positive when `p`
    /// is on the same side of the face opposite `k` as that vertex (for the infinite
    /// vertex: beyond the hull face).
    fn sees(&self, c: &[u32; 4], k: usize, p: &Point3) -> i8 {
        let q = |i: usize| match i == k {
            true => p,
            false => &self.pts[c[i] as usize],
        };
        orient3d(q(0), q(1), q(2), q(3))
    }

    /// Is `e` in conflict with cell `t` (strictly inside its sphere, ties perturbed; for
    /// an infinite cell, beyond its face, or on its plane and inside its circle)?
    fn in_conflict(&self, t: u32, e: u32) -> bool {
        let c = self.cells[t as usize];
        let pe = &self.pts[e as usize];
        if let Some(k) = c.iter().position(|&v| v == INF) {
            return match self.sees(&c, k, pe) {
                0 => self.in_sphere(self.nbr[t as usize][k], e),
                s => s > 0,
            };
        }
        self.in_sphere(t, e)
    }

    /// The perturbed in-sphere test of `e` against the finite cell `t`: `e` is the
    /// newest point, so a tie leaves it outside (see the module docs).
    fn in_sphere(&self, t: u32, e: u32) -> bool {
        let c = self.cells[t as usize];
        let p = |i: u32| &self.pts[i as usize];
        insphere(p(c[0]), p(c[1]), p(c[2]), p(c[3]), p(e)) > 0
    }

    /// The finite cells, renumbered, with their neighbours.
    fn finish(self) -> Delaunay3 {
        let mut id = vec![NONE; self.cells.len()];
        let mut tets = Vec::new();
        for (t, c) in self.cells.iter().enumerate() {
            if self.alive[t] && !c.contains(&INF) {
                id[t] = tets.len() as u32;
                tets.push(*c);
            }
        }
        let neighbours = (0..self.cells.len())
            .filter(|&t| id[t] != NONE)
            .map(|t| self.nbr[t].map(|n| id[n as usize]))
            .collect();
        Delaunay3 { tets, neighbours }
    }
}
