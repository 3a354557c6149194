//! Quasi-prisms and Algorithm QUASI-PRISM-TETRAHEDRALIZATION (thesis §2.5, Lemma 2.7):
//! the region between two isomorphic triangulated surfaces `S₁` (upper) and `S₂`
//! (lower), joined by the *vertical* edges `v ψ(v)`, cut into tetrahedra that keep every
//! edge of `S₁`, `S₂` and the vertical ones. The same problem as splitting a layer of
//! prisms (a boundary-layer mesh, an extrusion) into tetrahedra that meet face to face.
//!
//! **The quasi-prism.** Each triangle `abc` of `S₁` spans a *prism* with `ψ(a)ψ(b)ψ(c)`;
//! its three sides are the quadrilaterals `a b ψ(b) ψ(a)`. A side on the boundary of
//! `S₁` is split by its *convex diagonal*, the one that is an edge of the convex hull of
//! all the points, as the thesis defines it; a planar side may take either diagonal.
//! [`QuasiPrism::new`] checks the combinatorics (`S₁` a disk, so the whole boundary is a
//! sphere), and the surface is checked exactly to be a simple polyhedron.
//!
//! **Regular** ([`QuasiPrism::check_regular`]): for every triangle `abc` the hulls of two
//! of its sides meet only in their common vertical edge. Two convex sets sharing a
//! segment `e` meet beyond it exactly when they do near the midpoint of `e`, where each
//! is a wedge around `e`'s line; so the test compares the wedges spanned by the sides'
//! far vertices around the vertical line, with [`orient3d`] signs only (exact, and with
//! planar sides, whose wedge is a ray).
//!
//! **Staircases.** Orient every edge `uv` of `S₁` by the diagonal its side gets (`u → v`
//! for `u ψ(v)`). A prism whose three edges are oriented without a cycle, from `s` via
//! `m` to `t`, is cut into `s m t ψ(t)`, `s m ψ(m) ψ(t)` and `s ψ(s) ψ(m) ψ(t)`;
//! neighbouring prisms share the diagonal of their common side, so the pieces meet face
//! to face. The thesis's algorithm orients the edges by one vertex order (the order in
//! which it removes vertices). **Departure:** that order must also give every boundary
//! side its convex diagonal, which no order can do when the convex diagonals turn one
//! way around the boundary, as they do on every twisted quasi-prism (the thesis's
//! construction twists its lower copy): the algorithm as written then puts a reflex
//! diagonal on the boundary. Here the boundary diagonals are fixed first; a vertex order
//! (a topological sort of the fixed directions) is tried, and when none exists, an
//! orientation with no cyclic triangle is found by SAT (two clauses per triangle; the
//! fixed directions are unit clauses). That orientation exists more often than an order
//! does: a fan around an interior vertex, its spokes pointing out, accepts any boundary.
//! When no such orientation exists either, [`QuasiPrismError::NoStaircase`] says so: no
//! tetrahedralization keeps every prism to three tetrahedra, and the exact solver
//! (`exact::solve` with the quasi-prism's edges required) decides whether any other does.
//!
//! Every result is certified: the tetrahedra tile the surface exactly
//! ([`certify_polyhedron`]) and every edge of the quasi-prism is one of theirs.

use crate::control::{Control, Stopped};
use crate::geom::{Hull3, Point3, collinear3, orient3d};
use crate::mesh::{Polyhedron, Problem, SurfaceError, certify_polyhedron, edges_of};
use rustsat::instances::{BasicVarManager, ManageVars};
use rustsat::solvers::{Solve, SolverResult};
use rustsat::types::{Clause, Lit, TernaryVal};
use std::collections::{HashMap, HashSet};

/// A quasi-prism: `points[..n]` are `S₁`'s vertices, `points[n..]` their images
/// (`ψ(v) = v + n`), and `triangles` are `S₁`'s (on `0..n`).
#[derive(Clone, Debug, PartialEq)]
pub struct QuasiPrism {
    /// The upper vertices, then the lower ones in the same order.
    pub points: Vec<Point3>,
    /// The triangles of `S₁`.
    pub triangles: Vec<[u32; 3]>,
}

/// Why a quasi-prism was refused or could not be cut into staircases. Vertices are named
/// `#v` (0-based; the CLI renumbers).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum QuasiPrismError {
    /// The input is not a quasi-prism (sizes, indices, `S₁` not a disk).
    Input(NotQuasiPrism),
    /// A boundary side is not planar and neither diagonal is a hull edge.
    NoConvexDiagonal([u32; 2]),
    /// Not regular: two sides of the prism over `triangle` meet beyond their vertical
    /// edge at vertex `at` (or the wedge there is degenerate).
    Irregular {
        /// The triangle of `S₁`.
        triangle: [u32; 3],
        /// The vertex whose vertical edge the two sides share.
        at: u32,
        /// What goes wrong there.
        reason: &'static str,
    },
    /// The boundary (S₁, S₂ and the boundary sides) is not a simple polyhedron.
    Surface(SurfaceError),
    /// No orientation of the sides' diagonals leaves every prism without a cycle.
    NoStaircase,
    /// The run-control stopped the work.
    Stopped(Stopped),
    /// The tetrahedra failed the certificate (a bug, or a regular quasi-prism on which
    /// Lemma 2.7 fails): the verifier's problem.
    Uncertified(Problem),
    /// The tetrahedra miss this edge of [`QuasiPrism::edges`] (a bug, or a regular
    /// quasi-prism on which Lemma 2.7 fails).
    MissingEdge([u32; 2]),
    /// The exact solver could not take the boundary (too large).
    Exact(crate::exact::ExactError),
}

impl std::fmt::Display for QuasiPrismError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            QuasiPrismError::Input(s) => write!(f, "not a quasi-prism: {s}"),
            QuasiPrismError::MissingEdge([a, b]) => write!(
                f,
                "internal error, please report the input: edge (#{a}, #{b}) of the quasi-prism is not an edge of the tetrahedra"
            ),
            QuasiPrismError::NoConvexDiagonal([a, b]) => write!(
                f,
                "the boundary side over edge (#{a}, #{b}) is not planar and neither of its diagonals is a convex hull edge"
            ),
            QuasiPrismError::Irregular {
                triangle: [a, b, c],
                at,
                reason,
            } => write!(
                f,
                "not regular: in the prism over triangle (#{a}, #{b}, #{c}), the two sides at the vertical edge of #{at} {reason}"
            ),
            QuasiPrismError::Surface(e) => {
                write!(f, "the boundary is not a simple polyhedron: {e}")
            }
            QuasiPrismError::NoStaircase => write!(
                f,
                "no choice of the sides' diagonals leaves every prism without a cycle (the convex diagonals force one)"
            ),
            QuasiPrismError::Stopped(_) => write!(f, "stopped before a staircase was found"),
            QuasiPrismError::Uncertified(p) => write!(
                f,
                "internal error, please report the input: the tetrahedra fail their certificate: {p}"
            ),
            QuasiPrismError::Exact(e) => write!(f, "no staircase, and the exact solver: {e}"),
        }
    }
}

impl std::error::Error for QuasiPrismError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            QuasiPrismError::Input(e) => Some(e),
            QuasiPrismError::Surface(e) => Some(e),
            QuasiPrismError::Stopped(s) => Some(s),
            QuasiPrismError::Uncertified(p) => Some(p),
            QuasiPrismError::Exact(e) => Some(e),
            _ => None,
        }
    }
}

/// Why the input of [`QuasiPrism::new`] is not a quasi-prism. Vertices are named `#v`
/// (0-based), triangles by their position.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotQuasiPrism {
    /// Not as many lower vertices as upper ones (`ψ` must be a bijection).
    Sizes {
        /// Upper vertices.
        upper: usize,
        /// Lower vertices.
        lower: usize,
    },
    /// No triangles.
    NoTriangles,
    /// A triangle names a vertex that is not an upper vertex.
    NotUpper {
        /// The triangle.
        triangle: usize,
        /// The vertex.
        vertex: u32,
    },
    /// A triangle repeats a vertex.
    RepeatedVertex(usize),
    /// A triangle is given twice (this is its second position).
    RepeatedTriangle(usize),
    /// An upper vertex is on no triangle.
    Unused(u32),
    /// An edge is on more than two triangles.
    NonManifoldEdge([u32; 2]),
    /// `S₁` cannot be oriented.
    NotOrientable,
    /// The triangles of `S₁` do not form a disk.
    NotDisk,
}

impl std::fmt::Display for NotQuasiPrism {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            NotQuasiPrism::Sizes { upper, lower } => write!(
                f,
                "{upper} upper vertices but {lower} lower ones: ψ must be a bijection"
            ),
            NotQuasiPrism::NoTriangles => f.write_str("no triangles"),
            NotQuasiPrism::NotUpper { triangle, vertex } => {
                write!(f, "triangle {triangle} uses #{vertex}, not an upper vertex")
            }
            NotQuasiPrism::RepeatedVertex(k) => write!(f, "triangle {k} repeats a vertex"),
            NotQuasiPrism::RepeatedTriangle(k) => write!(f, "triangle {k} is given twice"),
            NotQuasiPrism::Unused(v) => write!(f, "vertex #{v} is on no triangle"),
            NotQuasiPrism::NonManifoldEdge([a, b]) => {
                write!(f, "edge (#{a}, #{b}) is on more than two triangles")
            }
            NotQuasiPrism::NotOrientable => f.write_str("S₁ is not orientable"),
            NotQuasiPrism::NotDisk => f.write_str("the triangles of S₁ do not form a disk"),
        }
    }
}

impl std::error::Error for NotQuasiPrism {}

/// A tetrahedralization of a quasi-prism by staircases.
#[derive(Clone, Debug)]
pub struct Staircase {
    /// The tetrahedra, positively oriented, three per triangle of `S₁`.
    pub tets: Vec<[u32; 4]>,
    /// The boundary surface, with the diagonals the tetrahedra chose on planar sides.
    pub surface: Polyhedron,
    /// Whether one vertex order gave the orientation (the thesis's algorithm), rather
    /// than the SAT search.
    pub by_order: bool,
}

/// How the diagonal of the side over an edge is chosen.
type Orientation = HashMap<[u32; 2], bool>; // sorted edge -> lo → hi

impl QuasiPrism {
    /// Checks the combinatorics: `upper` and `lower` of the same length, every triangle
    /// three distinct upper vertices, no triangle twice, every edge in one or two
    /// triangles, every vertex on a triangle, and `V − E + F = 1` with one boundary
    /// cycle (a disk).
    ///
    /// ```
    /// use tetrakit::reduce::QuasiPrism;
    /// let up = vec![[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
    /// let down = up.iter().map(|p| [p[0], p[1], 0.0]).collect();
    /// let q = QuasiPrism::new(up, down, vec![[0, 1, 2]]).unwrap();
    /// assert_eq!(q.points.len(), 6);
    /// ```
    pub fn new(
        upper: Vec<Point3>,
        lower: Vec<Point3>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<QuasiPrism, QuasiPrismError> {
        let bad = |e: NotQuasiPrism| Err(QuasiPrismError::Input(e));
        let n = upper.len();
        if lower.len() != n {
            let (upper, lower) = (n, lower.len());
            return bad(NotQuasiPrism::Sizes { upper, lower });
        }
        if triangles.is_empty() {
            return bad(NotQuasiPrism::NoTriangles);
        }
        let mut seen = HashSet::new();
        let mut used = vec![false; n];
        for (k, t) in triangles.iter().enumerate() {
            if let Some(&vertex) = t.iter().find(|&&v| v as usize >= n) {
                return bad(NotQuasiPrism::NotUpper {
                    triangle: k,
                    vertex,
                });
            }
            if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
                return bad(NotQuasiPrism::RepeatedVertex(k));
            }
            let mut s = *t;
            s.sort_unstable();
            if !seen.insert(s) {
                return bad(NotQuasiPrism::RepeatedTriangle(k));
            }
            t.iter().for_each(|&v| used[v as usize] = true);
        }
        if let Some(v) = used.iter().position(|&u| !u) {
            return bad(NotQuasiPrism::Unused(v as u32));
        }
        let counts = edge_counts(&triangles);
        if let Some((e, _)) = counts.iter().find(|&(_, &c)| c > 2) {
            return bad(NotQuasiPrism::NonManifoldEdge(*e));
        }
        let q = QuasiPrism {
            points: [upper, lower].concat(),
            triangles: orient_consistently(triangles)
                .ok_or(QuasiPrismError::Input(NotQuasiPrism::NotOrientable))?,
        };
        let chi = n as i64 - counts.len() as i64 + q.triangles.len() as i64;
        let boundary = q.boundary_edges();
        if chi != 1 || cycles(&boundary) != 1 {
            return bad(NotQuasiPrism::NotDisk);
        }
        Ok(q)
    }

    /// The number of upper vertices `n` (`ψ(v) = v + n`).
    pub fn n(&self) -> usize {
        self.points.len() / 2
    }

    /// The edges of the quasi-prism's graph other than the boundary diagonals: those
    /// of `S₁` and `S₂` and the vertical ones, each `[lo, hi]`, sorted.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        let n = self.n() as u32;
        let mut out: Vec<[u32; 2]> = self.edge_counts().into_keys().collect();
        out.extend(out.clone().iter().map(|&[a, b]| [a + n, b + n]));
        out.extend((0..n).map(|v| [v, v + n]));
        out.sort_unstable();
        out
    }

    /// Checks that the quasi-prism is regular (see the module docs).
    ///
    /// ```
    /// use tetrakit::reduce::QuasiPrism;
    /// // A straight prism is regular; Schönhardt's twist makes one irregular.
    /// assert!(QuasiPrism::lens(6, 4, 0.0, 1).check_regular().is_ok());
    /// ```
    pub fn check_regular(&self) -> Result<(), QuasiPrismError> {
        for t in &self.triangles {
            for i in 0..3 {
                let (v, x, y) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
                if let Err(reason) = self.sides_apart(v, x, y) {
                    return Err(QuasiPrismError::Irregular {
                        triangle: *t,
                        at: v,
                        reason,
                    });
                }
            }
        }
        Ok(())
    }

    /// Algorithm QUASI-PRISM-TETRAHEDRALIZATION with the departure of the module docs:
    /// regularity checked, boundary diagonals fixed, then a vertex order or SAT, three
    /// tetrahedra per prism, certified.
    ///
    /// ```
    /// use tetrakit::reduce::QuasiPrism;
    /// let q = QuasiPrism::lens(8, 6, 3.0, 2);
    /// let s = q.tetrahedralize(&tetrakit::control::Control::new()).unwrap();
    /// assert_eq!(s.tets.len(), 3 * q.triangles.len());
    /// assert!(!s.by_order); // the twist turns the convex diagonals one way round
    /// ```
    pub fn tetrahedralize(&self, ctl: &Control) -> Result<Staircase, QuasiPrismError> {
        self.check_regular()?;
        let fixed = self.fixed_directions()?;
        let (orientation, by_order) = match self.by_order(&fixed) {
            Some(o) => (o, true),
            None => (self.by_sat(&fixed, ctl)?, false),
        };
        if ctl.is_stopped() {
            return Err(QuasiPrismError::Stopped(Stopped));
        }
        let surface = Polyhedron::new(self.points.clone(), self.surface(&orientation))
            .map_err(QuasiPrismError::Surface)?;
        let tets = self.staircases(&orientation);
        self.certify(&surface, &tets)?;
        Ok(Staircase {
            tets,
            surface,
            by_order,
        })
    }

    /// The boundary surface with the convex diagonals (planar sides split from their
    /// lower-numbered corner): the polyhedron the exact solver decides when no staircase
    /// exists, with [`QuasiPrism::edges`] required.
    pub fn boundary(&self) -> Result<Polyhedron, QuasiPrismError> {
        let fixed = self.fixed_directions()?;
        Polyhedron::new(self.points.clone(), self.surface(&fixed)).map_err(QuasiPrismError::Surface)
    }

    /// The boundary surface for `orientation`, used as the polyhedron to tetrahedralize
    /// (its faces in any orientation; [`Polyhedron::new`] orients them).
    fn surface(&self, orientation: &Orientation) -> Vec<[u32; 3]> {
        let n = self.n() as u32;
        let mut faces = self.triangles.clone();
        faces.extend(
            self.triangles
                .iter()
                .map(|t| [t[0] + n, t[2] + n, t[1] + n]),
        );
        for [a, b] in self.boundary_edges() {
            let (u, v) = directed(orientation, a, b);
            faces.extend([[u, v, v + n], [u, v + n, u + n]]);
        }
        faces
    }

    fn staircases(&self, orientation: &Orientation) -> Vec<[u32; 4]> {
        let n = self.n() as u32;
        let mut tets = Vec::with_capacity(3 * self.triangles.len());
        for t in &self.triangles {
            let [s, m, e] = ordered(orientation, t);
            for tet in [
                [s, m, e, e + n],
                [s, m, m + n, e + n],
                [s, s + n, m + n, e + n],
            ] {
                tets.push(self.positive(tet));
            }
        }
        tets
    }

    fn positive(&self, t: [u32; 4]) -> [u32; 4] {
        let p = |v: u32| &self.points[v as usize];
        if orient3d(p(t[0]), p(t[1]), p(t[2]), p(t[3])) < 0 {
            [t[0], t[2], t[1], t[3]]
        } else {
            t
        }
    }

    /// Certifies that `tets` tetrahedralize `surface` (this quasi-prism's boundary) and
    /// have every edge of [`QuasiPrism::edges`].
    pub fn certify(&self, surface: &Polyhedron, tets: &[[u32; 4]]) -> Result<(), QuasiPrismError> {
        certify_polyhedron(surface, tets).map_err(QuasiPrismError::Uncertified)?;
        let have: HashSet<[u32; 2]> = edges_of(tets).into_iter().collect();
        match self.edges().into_iter().find(|e| !have.contains(e)) {
            Some(e) => Err(QuasiPrismError::MissingEdge(e)),
            None => Ok(()),
        }
    }

    /// The directions the boundary sides' convex diagonals fix (planar sides are free).
    fn fixed_directions(&self) -> Result<Orientation, QuasiPrismError> {
        let n = self.n() as u32;
        let hull = Hull3::new(&self.points);
        let on_hull: HashSet<[u32; 2]> = hull
            .polytope_edges(&self.points)
            .iter()
            .flat_map(|g| g.windows(2).map(|w| sorted(w[0], w[1])))
            .collect();
        let p = |v: u32| &self.points[v as usize];
        let mut fixed = Orientation::new();
        for [a, b] in self.boundary_edges() {
            if orient3d(p(a), p(b), p(b + n), p(a + n)) == 0 {
                continue;
            }
            let key = sorted(a, b);
            match (
                on_hull.contains(&sorted(a, b + n)),
                on_hull.contains(&sorted(b, a + n)),
            ) {
                (true, false) => fixed.insert(key, key[0] == a),
                (false, true) => fixed.insert(key, key[0] == b),
                _ => return Err(QuasiPrismError::NoConvexDiagonal(key)),
            };
        }
        Ok(fixed)
    }

    /// The thesis's route: one vertex order (a topological sort of the fixed
    /// directions, ties by index) orients every edge.
    fn by_order(&self, fixed: &Orientation) -> Option<Orientation> {
        let n = self.n();
        let mut indegree = vec![0usize; n];
        let mut out: Vec<Vec<u32>> = vec![Vec::new(); n];
        for (&[a, b], &forward) in fixed {
            let (u, v) = if forward { (a, b) } else { (b, a) };
            out[u as usize].push(v);
            indegree[v as usize] += 1;
        }
        let mut ready: std::collections::BinaryHeap<std::cmp::Reverse<u32>> = (0..n as u32)
            .filter(|&v| indegree[v as usize] == 0)
            .map(std::cmp::Reverse)
            .collect();
        let mut rank = vec![usize::MAX; n];
        let mut next = 0;
        while let Some(std::cmp::Reverse(u)) = ready.pop() {
            rank[u as usize] = next;
            next += 1;
            for &v in &out[u as usize] {
                indegree[v as usize] -= 1;
                if indegree[v as usize] == 0 {
                    ready.push(std::cmp::Reverse(v));
                }
            }
        }
        (next == n).then(|| {
            self.edge_counts()
                .into_keys()
                .map(|[a, b]| ([a, b], rank[a as usize] < rank[b as usize]))
                .collect()
        })
    }

    /// An orientation extending `fixed` with no cyclic triangle, by SAT: for each
    /// triangle `a < b < c` with edge variables `ab`, `bc`, `ac` (true: low to high), the
    /// cycles are `ab ∧ bc ∧ ¬ac` and `¬ab ∧ ¬bc ∧ ac`.
    fn by_sat(&self, fixed: &Orientation, ctl: &Control) -> Result<Orientation, QuasiPrismError> {
        let edges: Vec<[u32; 2]> = self.edge_counts().into_keys().collect();
        let mut vars = BasicVarManager::default();
        let lits: HashMap<[u32; 2], Lit> = edges.iter().map(|&e| (e, vars.new_lit())).collect();
        let mut solver = crate::control::sat_solver(ctl);
        let mut add = |c: &[Lit]| {
            solver
                .add_clause(c.iter().copied().collect::<Clause>())
                .expect("batsat accepts clauses");
        };
        for (e, &forward) in fixed {
            add(&[if forward { lits[e] } else { !lits[e] }]);
        }
        for t in &self.triangles {
            let mut s = *t;
            s.sort_unstable();
            let [a, b, c] = s;
            let (ab, bc, ac) = (lits[&[a, b]], lits[&[b, c]], lits[&[a, c]]);
            add(&[!ab, !bc, ac]);
            add(&[ab, bc, !ac]);
        }
        match solver.solve().expect("batsat") {
            SolverResult::Sat => {}
            SolverResult::Unsat => return Err(QuasiPrismError::NoStaircase),
            SolverResult::Interrupted => return Err(QuasiPrismError::Stopped(Stopped)),
        }
        let value = |e: &[u32; 2]| solver.lit_val(lits[e]).expect("sat") == TernaryVal::True;
        Ok(edges.iter().map(|e| (*e, value(e))).collect())
    }

    /// Whether the hulls of the sides over `vx` and `vy` meet only in `v ψ(v)`: their
    /// wedges around that line, spanned by `x, ψ(x)` and by `y, ψ(y)`, share no ray.
    fn sides_apart(&self, v: u32, x: u32, y: u32) -> Result<(), &'static str> {
        let n = self.n() as u32;
        let p = |u: u32| &self.points[u as usize];
        let (l0, l1) = (p(v), p(v + n));
        if l0 == l1 {
            return Err("are degenerate: the vertical edge has length 0");
        }
        let g = [p(x), p(x + n), p(y), p(y + n)];
        if g.iter().any(|q| collinear3(l0, l1, q)) {
            return Err("are degenerate: a vertex lies on the vertical line");
        }
        let s = |a: &Point3, b: &Point3| orient3d(l0, l1, a, b);
        // Two rays in one plane through the line: the same ray iff a third point off
        // that plane sees them on the same side.
        let same_ray = |a: &Point3, b: &Point3| -> Option<bool> {
            g.iter().find(|r| s(a, r) != 0).map(|r| s(a, r) == s(b, r))
        };
        let wa = Wedge::new(g[0], g[1], s(g[0], g[1]), same_ray(g[0], g[1]))?;
        let wb = Wedge::new(g[2], g[3], s(g[2], g[3]), same_ray(g[2], g[3]))?;
        let inside = |q: &Point3, w: &Wedge| -> Result<bool, &'static str> {
            Ok(match *w {
                Wedge::Proper(a, b, sigma) => s(a, q) * sigma >= 0 && s(q, b) * sigma >= 0,
                Wedge::Ray(a) => {
                    s(a, q) == 0 && same_ray(a, q).ok_or("are coplanar with the vertical line")?
                }
            })
        };
        for (q, w) in [(g[0], &wb), (g[1], &wb), (g[2], &wa), (g[3], &wa)] {
            if inside(q, w)? {
                return Err("meet beyond it");
            }
        }
        Ok(())
    }

    fn edge_counts(&self) -> HashMap<[u32; 2], usize> {
        edge_counts(&self.triangles)
    }

    /// The edges of `S₁` on one triangle only, as `[a, b]` in their triangle's order.
    fn boundary_edges(&self) -> Vec<[u32; 2]> {
        let counts = self.edge_counts();
        let mut out: Vec<[u32; 2]> = self
            .triangles
            .iter()
            .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
            .filter(|&[a, b]| counts[&sorted(a, b)] == 1)
            .collect();
        out.sort_unstable();
        out
    }

    /// A quasi-prism for tests and benchmarks: `ring` points on the unit circle and
    /// `inner` random points inside, Delaunay-triangulated, lifted to the cap
    /// `z = 1 − r²/10` (`S₁`) and, turned by `twist` degrees about the axis, to
    /// `z = −1 + r²/10` (`S₂`). All points are in convex position; the boundary sides are
    /// on the hull. A twist of 0 gives planar sides.
    pub fn lens(ring: usize, inner: usize, twist: f64, seed: u64) -> QuasiPrism {
        let flat = lens_points(ring.max(3), inner, seed);
        let triangles = crate::planar::delaunay(&flat)
            .expect("distinct finite points")
            .triangles;
        let (c, s) = (twist.to_radians().cos(), twist.to_radians().sin());
        let cap = |x: f64, y: f64, top: bool| {
            let h = 1.0 - (x * x + y * y) / 10.0;
            [x, y, if top { h } else { -h }]
        };
        let upper = flat.iter().map(|&[x, y]| cap(x, y, true)).collect();
        let lower = flat
            .iter()
            .map(|&[x, y]| cap(c * x - s * y, s * x + c * y, false))
            .collect();
        QuasiPrism::new(upper, lower, triangles).expect("a triangulated disk")
    }
}

/// A wedge around the vertical line: spanned by two rays (`sigma` the sign from the
/// first to the second), or a single ray (a planar side).
enum Wedge<'a> {
    Proper(&'a Point3, &'a Point3, i8),
    Ray(&'a Point3),
}

impl<'a> Wedge<'a> {
    fn new(
        a: &'a Point3,
        b: &'a Point3,
        sigma: i8,
        same: Option<bool>,
    ) -> Result<Wedge<'a>, &'static str> {
        match (sigma, same) {
            (0, Some(true)) => Ok(Wedge::Ray(a)),
            (0, Some(false)) => Err("are degenerate: a side folds over its vertical edge"),
            (0, None) => Err("are coplanar with the vertical line"),
            _ => Ok(Wedge::Proper(a, b, sigma)),
        }
    }
}

/// The triangles turned (by a walk across shared edges) so that every shared edge is
/// used once each way; `None` when that fails (a Möbius strip) or an edge is shared by
/// more than two.
fn orient_consistently(mut tris: Vec<[u32; 3]>) -> Option<Vec<[u32; 3]>> {
    let mut by_edge: HashMap<[u32; 2], Vec<usize>> = HashMap::new();
    for (k, t) in tris.iter().enumerate() {
        for i in 0..3 {
            by_edge
                .entry(sorted(t[i], t[(i + 1) % 3]))
                .or_default()
                .push(k);
        }
    }
    let has = |t: &[u32; 3], a: u32, b: u32| (0..3).any(|i| t[i] == a && t[(i + 1) % 3] == b);
    let mut done = vec![false; tris.len()];
    for start in 0..tris.len() {
        if done[start] {
            continue;
        }
        done[start] = true;
        let mut stack = vec![start];
        while let Some(k) = stack.pop() {
            let t = tris[k];
            for i in 0..3 {
                let (a, b) = (t[i], t[(i + 1) % 3]);
                for &j in &by_edge[&sorted(a, b)] {
                    if j == k {
                        continue;
                    }
                    if !done[j] {
                        if has(&tris[j], a, b) {
                            tris[j].swap(1, 2);
                        }
                        done[j] = true;
                        stack.push(j);
                    } else if has(&tris[j], a, b) {
                        return None;
                    }
                }
            }
        }
    }
    Some(tris)
}

fn edge_counts(tris: &[[u32; 3]]) -> HashMap<[u32; 2], usize> {
    let mut counts = HashMap::new();
    for t in tris {
        for i in 0..3 {
            *counts.entry(sorted(t[i], t[(i + 1) % 3])).or_insert(0) += 1;
        }
    }
    counts
}

fn sorted(a: u32, b: u32) -> [u32; 2] {
    [a.min(b), a.max(b)]
}

/// `(u, v)` with `u → v` under `orientation` (an edge it does not hold goes low to high).
fn directed(orientation: &Orientation, a: u32, b: u32) -> (u32, u32) {
    let [lo, hi] = sorted(a, b);
    if orientation.get(&[lo, hi]).copied().unwrap_or(true) {
        (lo, hi)
    } else {
        (hi, lo)
    }
}

/// The triangle's vertices as source, middle, sink of its (acyclic) orientation.
fn ordered(orientation: &Orientation, t: &[u32; 3]) -> [u32; 3] {
    let mut indegree = [0; 3];
    for i in 0..3 {
        for j in 0..3 {
            if i != j && directed(orientation, t[i], t[j]) == (t[i], t[j]) {
                indegree[j] += 1;
            }
        }
    }
    let mut out = *t;
    out.sort_by_key(|v| indegree[t.iter().position(|u| u == v).expect("own vertex")]);
    out
}

/// The number of cycles the boundary edges form (each vertex on at most two of them in
/// a disk; a vertex on more is reported as more than one cycle).
fn cycles(edges: &[[u32; 2]]) -> usize {
    let mut next: HashMap<u32, Vec<u32>> = HashMap::new();
    for &[a, b] in edges {
        next.entry(a).or_default().push(b);
    }
    if next.values().any(|v| v.len() != 1) {
        return usize::MAX;
    }
    let mut seen = HashSet::new();
    let mut count = 0;
    for &[start, _] in edges {
        if seen.contains(&start) {
            continue;
        }
        count += 1;
        let mut v = start;
        while seen.insert(v) {
            v = next[&v][0];
        }
    }
    count
}

fn lens_points(ring: usize, inner: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = crate::rng::Rng::new(seed);
    let mut pts: Vec<[f64; 2]> = (0..ring)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / ring as f64;
            [a.cos(), a.sin()]
        })
        .collect();
    while pts.len() < ring + inner {
        let (x, y) = (2.0 * rng.unit() - 1.0, 2.0 * rng.unit() - 1.0);
        if x * x + y * y < 0.64 {
            pts.push([x, y]);
        }
    }
    pts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fan_accepts_a_cyclic_boundary() {
        // One interior vertex: the twisted ring's diagonals all turn one way, no vertex
        // order gives them, spokes pointing out do.
        let q = QuasiPrism::lens(5, 1, 4.0, 3);
        let s = q.tetrahedralize(&Control::new()).unwrap();
        assert!(!s.by_order);
        assert_eq!(s.tets.len(), 15);
    }

    #[test]
    fn straight_prisms_take_the_thesis_order() {
        let q = QuasiPrism::lens(7, 5, 0.0, 4);
        let s = q.tetrahedralize(&Control::new()).unwrap();
        assert!(s.by_order);
    }

    #[test]
    fn a_single_twisted_prism_has_no_staircase() {
        // One triangle: its three sides are all on the boundary and turn one way.
        let q = QuasiPrism::lens(3, 0, 20.0, 1);
        assert_eq!(
            q.tetrahedralize(&Control::new()).unwrap_err(),
            QuasiPrismError::NoStaircase
        );
    }

    /// Sides whose hulls overlap in their interiors (an independent exact test) are
    /// never found apart; straight prisms' sides always are.
    #[test]
    fn the_wedge_test_agrees_with_tetrahedra_overlap() {
        let (mut apart, mut overlapping) = (0, 0);
        for seed in 0..60 {
            let twist = [0.0, 8.0, 25.0, 45.0, -30.0][seed % 5];
            let q = QuasiPrism::lens(3 + seed % 4, seed % 3, twist, seed as u64);
            let n = q.n() as u32;
            let side = |a: u32, b: u32| [a, b, b + n, a + n].map(|v| q.points[v as usize]);
            for t in &q.triangles {
                for i in 0..3 {
                    let (v, x, y) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
                    let ok = q.sides_apart(v, x, y).is_ok();
                    if crate::geom::tetrahedra_overlap(&side(v, x), &side(v, y)) {
                        assert!(!ok, "seed {seed}: overlapping sides found apart");
                        overlapping += 1;
                    }
                    if twist == 0.0 {
                        assert!(ok, "seed {seed}: a straight prism's sides");
                    }
                    apart += usize::from(ok);
                }
            }
        }
        assert!(
            apart > 100 && overlapping > 10,
            "{apart} apart, {overlapping} overlapping"
        );
    }

    #[test]
    fn bad_combinatorics_are_refused() {
        let up = vec![
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [0.0, 1.0, 1.0],
            [1.0, 1.0, 1.0],
        ];
        let down: Vec<Point3> = up.iter().map(|p| [p[0], p[1], 0.0]).collect();
        let e = |t: Vec<[u32; 3]>, d: Vec<Point3>| QuasiPrism::new(up.clone(), d, t).unwrap_err();
        assert!(e(vec![[0, 1, 2]], down.clone()).to_string().contains("#3"));
        assert!(
            e(vec![[0, 1, 2], [1, 3, 2]], down[..3].to_vec())
                .to_string()
                .contains("bijection")
        );
        assert!(e(vec![[0, 1, 4]], down.clone()).to_string().contains("#4"));
        assert!(
            e(vec![[0, 1, 2], [2, 1, 0], [1, 3, 2]], down.clone())
                .to_string()
                .contains("twice")
        );
    }
}
