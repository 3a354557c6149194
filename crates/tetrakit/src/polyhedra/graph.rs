//! The graph G(P) of a polyhedron's surface (thesis §3.2): degrees, adjacency, tri(ab),
//! and the rotation around every vertex, kept up to date while MINTETRA trims.

use super::Polyhedron;

/// The surface as a rotation system: for every vertex its neighbours in order, so that
/// `(v, ring[i], ring[i + 1])` are its facets, outward oriented. Removed vertices have an
/// empty ring.
///
/// ```
/// use tetrakit::polyhedra::{Polyhedron, SurfaceGraph};
/// let pts = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let tet = Polyhedron::new(pts, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]).unwrap();
/// let g = SurfaceGraph::new(&tet);
/// assert_eq!(g.degree(0), 3);
/// let mut t = g.tri(0, 1).unwrap();
/// t.sort();
/// assert_eq!(t, [2, 3]);
/// ```
#[derive(Clone, Debug)]
pub struct SurfaceGraph {
    rings: Vec<Vec<u32>>,
    alive: usize,
}

impl SurfaceGraph {
    /// The graph of a (validated) polyhedron.
    pub fn new(p: &Polyhedron) -> Self {
        let n = p.points.len();
        let (start, star) = crate::mesh::surface::vertex_stars(&p.faces, n);
        let rings = (0..n)
            .map(|v| {
                let s = &star[start[v]..start[v + 1]];
                let mut ring = Vec::with_capacity(s.len());
                let mut cur = s[0].0;
                for _ in 0..s.len() {
                    ring.push(cur);
                    cur = s.iter().find(|x| x.0 == cur).map_or(cur, |x| x.1);
                }
                ring
            })
            .collect();
        SurfaceGraph { rings, alive: n }
    }

    /// Number of vertex slots (removed ones included).
    pub fn len(&self) -> usize {
        self.rings.len()
    }

    /// True when no vertex slot exists.
    pub fn is_empty(&self) -> bool {
        self.rings.is_empty()
    }

    /// Number of vertices not yet removed.
    pub fn alive(&self) -> usize {
        self.alive
    }

    /// True when `v` has not been removed.
    pub fn is_alive(&self, v: u32) -> bool {
        !self.rings[v as usize].is_empty()
    }

    /// deg(v).
    pub fn degree(&self, v: u32) -> usize {
        self.rings[v as usize].len()
    }

    /// adj(v) in rotation order.
    pub fn ring(&self, v: u32) -> &[u32] {
        &self.rings[v as usize]
    }

    /// True when `ab` is an edge.
    pub fn adjacent(&self, a: u32, b: u32) -> bool {
        self.rings[a as usize].contains(&b)
    }

    /// tri(ab): the third vertices `[c, d]` of the facets `(a, b, c)` and `(b, a, d)`.
    pub fn tri(&self, a: u32, b: u32) -> Option<[u32; 2]> {
        let r = &self.rings[a as usize];
        let i = r.iter().position(|&x| x == b)?;
        let k = r.len();
        Some([r[(i + 1) % k], r[(i + k - 1) % k]])
    }

    /// True when `(a, b, c)` is a facet with this orientation.
    pub fn has_facet(&self, a: u32, b: u32, c: u32) -> bool {
        let r = &self.rings[a as usize];
        r.iter()
            .position(|&x| x == b)
            .is_some_and(|i| r[(i + 1) % r.len()] == c)
    }

    /// The current facets (each once, outward oriented).
    pub fn facets(&self) -> Vec<[u32; 3]> {
        let mut out = Vec::new();
        for (v, r) in self.rings.iter().enumerate() {
            let v = v as u32;
            for i in 0..r.len() {
                let (a, b) = (r[i], r[(i + 1) % r.len()]);
                if v < a && v < b {
                    out.push([v, a, b]);
                }
            }
        }
        out
    }

    /// Checks the degree theorems of §3.2 on this graph and returns what fails, each
    /// with the vertices involved (empty for the graph of any simple polyhedron):
    /// Theorem 3.1 (no two adjacent degree-3 vertices when n > 4), Theorem 3.2 (a
    /// degree-3 vertex has at most one neighbour of degree < 5 when n > 5) and the count
    /// part of Theorem 3.3 (a degree-4 vertex has at most two neighbours of degree < 5
    /// when n > 6). Theorem 3.3 also claims those two are never adjacent; that is false
    /// (an octahedron with a tetrahedron stacked on a face), so it is not checked.
    ///
    /// ```
    /// use tetrakit::polyhedra::{generate, SurfaceGraph};
    /// let g = SurfaceGraph::new(&generate::stacked(12, 5));
    /// assert!(g.degree_theorem_violations().is_empty());
    /// ```
    pub fn degree_theorem_violations(&self) -> Vec<(&'static str, Vec<u32>)> {
        let n = self.alive;
        let mut out = Vec::new();
        for v in 0..self.len() as u32 {
            let adj = self.ring(v);
            let low: Vec<u32> = adj
                .iter()
                .copied()
                .filter(|&w| self.degree(w) < 5)
                .collect();
            match self.degree(v) {
                3 if n > 4 => {
                    if let Some(&w) = adj.iter().find(|&&w| self.degree(w) == 3) {
                        out.push(("Theorem 3.1", vec![v, w]));
                    }
                    if n > 5 && low.len() > 1 {
                        out.push(("Theorem 3.2", [vec![v], low].concat()));
                    }
                }
                4 if n > 6 && low.len() > 2 => out.push(("Theorem 3.3", [vec![v], low].concat())),
                _ => {}
            }
        }
        out
    }

    /// The ring of `v` rotated to start at `first`.
    pub(crate) fn ring_from(&self, v: u32, first: u32) -> Option<Vec<u32>> {
        let r = &self.rings[v as usize];
        let i = r.iter().position(|&x| x == first)?;
        Some(r[i..].iter().chain(&r[..i]).copied().collect())
    }

    /// Removes `v` (its neighbours' rings are updated by the caller's operations).
    pub(crate) fn kill(&mut self, v: u32) {
        self.rings[v as usize].clear();
        self.alive -= 1;
    }

    /// Deletes `x` from the ring of `v`.
    pub(crate) fn unlink(&mut self, v: u32, x: u32) {
        self.rings[v as usize].retain(|&y| y != x);
    }

    /// In the ring of `v`, replaces the consecutive pair `{x, y}` (in either order) by `z`.
    pub(crate) fn contract(&mut self, v: u32, x: u32, y: u32, z: u32) {
        let r = &mut self.rings[v as usize];
        let k = r.len();
        let i = r.iter().position(|&a| a == x).expect("x in ring");
        let j = r.iter().position(|&a| a == y).expect("y in ring");
        let first = if (i + 1) % k == j { i } else { j };
        r[first] = z;
        let second = (first + 1) % k;
        r.remove(second);
    }

    /// Empties the graph (the last tetrahedron was removed).
    pub(crate) fn clear(&mut self) {
        self.rings.iter_mut().for_each(Vec::clear);
        self.alive = 0;
    }
}
