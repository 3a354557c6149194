//! Niches (thesis §2.6, Definition 2.4, Theorem 2.10): Schönhardt's polyhedron without
//! its top face, the gadget of the CT reduction. A point sees the base `a₁b₁c₁` when
//! every segment from it to the base enters the polyhedron's interior and meets none of
//! the niche's faces; the points that see the whole base are its *view*. Theorem 2.10:
//! a segment set holding a niche whose view has none of its vertices cannot be
//! tetrahedralized.
//!
//! The view is decided exactly, one point at a time: `p` sees the whole base exactly when
//! `p` is strictly on the niche's side of the base plane and the tetrahedron `p a₁b₁c₁`
//! (the union of the segments from `p` to the base) meets no side face of the niche
//! other than along the base's edges.

use crate::geom::{Point3, orient3d, triangle_meets_tet};
use std::collections::HashSet;

/// A niche: top `a, b, c`, base `a₁, b₁, c₁`, faces `a₁b₁c₁`, `a a₁ b₁`, `b b₁ c₁`,
/// `c c₁ a₁`, `a b b₁`, `b c c₁`, `c a a₁`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Niche {
    /// `a, b, c`.
    pub top: [u32; 3],
    /// `a₁, b₁, c₁`.
    pub base: [u32; 3],
}

impl Niche {
    /// The six side faces (the base excluded).
    pub fn sides(&self) -> [[u32; 3]; 6] {
        let ([a, b, c], [a1, b1, c1]) = (self.top, self.base);
        [
            [a, a1, b1],
            [b, b1, c1],
            [c, c1, a1],
            [a, b, b1],
            [b, c, c1],
            [c, a, a1],
        ]
    }

    /// The twelve edges of the seven faces.
    pub fn edges(&self) -> [[u32; 2]; 12] {
        let ([a, b, c], [a1, b1, c1]) = (self.top, self.base);
        [
            [a1, b1],
            [b1, c1],
            [c1, a1],
            [a, b],
            [b, c],
            [c, a],
            [a, a1],
            [b, b1],
            [c, c1],
            [a, b1],
            [b, c1],
            [c, a1],
        ]
    }

    /// True when `p` (point `v`) sees the whole base (see the module docs).
    ///
    /// ```
    /// use tetrakit::constrain::find_niches;
    /// use tetrakit::polyhedra::generate::twisted_prism;
    /// // Schönhardt's polyhedron: bottom 0 1 2 at z = 0, top 3 4 5 at z = 2.
    /// let s = twisted_prism(30.0).unwrap();
    /// let niches = find_niches(&s.points, &s.edges());
    /// let niche = niches.iter().find(|n| n.base.iter().all(|&v| v < 3)).unwrap();
    /// let mut pts = s.points.clone();
    /// pts.push([0.0, 0.0, 0.05]); // just above the base's centre
    /// pts.push([3.0, 0.0, 1.0]); // beside the prism
    /// assert!(niche.sees_base(&pts, 6));
    /// assert!(!niche.sees_base(&pts, 7) && !niche.sees_base(&pts, 3));
    /// ```
    pub fn sees_base(&self, points: &[Point3], v: u32) -> bool {
        let all: Vec<u32> = self.top.iter().chain(&self.base).copied().collect();
        if all.contains(&v) {
            return false;
        }
        let p = |x: u32| points[x as usize];
        let [a1, b1, c1] = self.base;
        let side = orient3d(&p(a1), &p(b1), &p(c1), &p(self.top[0]));
        if side == 0 || orient3d(&p(a1), &p(b1), &p(c1), &p(v)) != side {
            return false;
        }
        let tet = [v, a1, b1, c1];
        let geo = tet.map(p);
        !self
            .sides()
            .iter()
            .any(|f| triangle_meets_tet(&f.map(p), *f, &geo, &tet))
    }

    /// A vertex of `points` in the view, if any.
    pub fn vertex_in_view(&self, points: &[Point3]) -> Option<u32> {
        (0..points.len() as u32).find(|&v| self.sees_base(points, v))
    }
}

/// The niches whose twelve edges are all among `segments` and whose closure (with the
/// top face) is Schönhardt's polyhedron: three reflex side diagonals `a b₁`, `b c₁`,
/// `c a₁`. By brute force over pairs of segment triangles (small inputs).
///
/// ```
/// use tetrakit::constrain::find_niches;
/// use tetrakit::polyhedra::generate::twisted_prism;
/// let s = twisted_prism(30.0).unwrap();
/// let mut segs: Vec<[u32; 2]> = s.edges();
/// let found = find_niches(&s.points, &segs);
/// assert!(!found.is_empty());
/// segs.retain(|e| *e != [0, 1]);
/// assert!(find_niches(&s.points, &segs).is_empty());
/// ```
pub fn find_niches(points: &[Point3], segments: &[[u32; 2]]) -> Vec<Niche> {
    let have: HashSet<[u32; 2]> = segments
        .iter()
        .map(|&[a, b]| [a.min(b), a.max(b)])
        .collect();
    let has = |a: u32, b: u32| have.contains(&[a.min(b), a.max(b)]);
    let n = points.len() as u32;
    let mut triangles = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                if has(a, b) && has(b, c) && has(a, c) {
                    triangles.push([a, b, c]);
                }
            }
        }
    }
    let mut out = Vec::new();
    for base in &triangles {
        for top in &triangles {
            if top.iter().any(|v| base.contains(v)) {
                continue;
            }
            for niche in labellings(*top, *base) {
                if niche.edges().iter().all(|&[x, y]| has(x, y)) && schonhardt(points, &niche) {
                    out.push(niche);
                }
            }
        }
    }
    out
}

/// The ways to match a top triangle to a base one: both orientations of the top, every
/// order of the base.
fn labellings(top: [u32; 3], base: [u32; 3]) -> Vec<Niche> {
    let mut out = Vec::new();
    for t in [top, [top[0], top[2], top[1]]] {
        for r in 0..3 {
            for flip in [false, true] {
                let mut b = [base[r], base[(r + 1) % 3], base[(r + 2) % 3]];
                if flip {
                    b.swap(1, 2);
                }
                out.push(Niche { top: t, base: b });
            }
        }
    }
    out
}

/// True when the niche with its top face is Schönhardt's polyhedron: the top on one side
/// of the base, and each side quadrilateral `a a₁ b₁ b` dented along its diagonal `a b₁`
/// (its fourth corner `b` on the other side of the plane `a a₁ b₁` from the base's third
/// corner `c₁`; convex, it would be on the same side).
fn schonhardt(points: &[Point3], n: &Niche) -> bool {
    let p = |x: u32| &points[x as usize];
    let ([a, b, c], [a1, b1, c1]) = (n.top, n.base);
    let up = orient3d(p(a1), p(b1), p(c1), p(a));
    if up == 0
        || orient3d(p(a1), p(b1), p(c1), p(b)) != up
        || orient3d(p(a1), p(b1), p(c1), p(c)) != up
    {
        return false;
    }
    [(a, a1, b1, b, c1), (b, b1, c1, c, a1), (c, c1, a1, a, b1)]
        .iter()
        .all(|&(x, y, z, w, o)| {
            let s = orient3d(p(x), p(y), p(z), p(w));
            s != 0 && s == -orient3d(p(x), p(y), p(z), p(o))
        })
}
