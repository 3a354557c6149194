//! Whether a tetrahedron's interior meets a convex polytope's interior, exactly: two
//! convex polytopes have disjoint interiors if and only if some plane has one on each
//! closed side, and then one such plane is parallel to a facet of one of them or to an
//! edge of each (the separating axis theorem). Each axis is tried by comparing the two
//! extreme projections with exact determinants.

use crate::geom::{Hull3, Point3, det3, orient3d, vector};

/// A convex polytope `Q` prepared for [`Convex::meets_interior`].
pub(crate) struct Convex {
    points: Vec<Point3>,
    hull: Hull3,
    edges: Vec<[u32; 2]>,
}

impl Convex {
    /// `Q` as the hull of `points` (full-dimensional).
    pub(crate) fn new(points: Vec<Point3>) -> Convex {
        let hull = Hull3::new(&points);
        let mut edges: Vec<[u32; 2]> = hull
            .triangles
            .iter()
            .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
            .map(|[a, b]| [a.min(b), a.max(b)])
            .collect();
        edges.sort_unstable();
        edges.dedup();
        Convex {
            points,
            hull,
            edges,
        }
    }

    /// The facet of `Q` holding the three points, if any (then the triangle lies on `∂Q`).
    pub(crate) fn common_facet(&self, a: usize, b: usize, c: usize) -> Option<u32> {
        self.hull.common_facet(a, b, c)
    }

    /// True when two vertices of `Q` share no facet: the segment between them crosses
    /// the interior of `Q`.
    pub(crate) fn chord(&self, a: usize, b: usize) -> bool {
        let fb = self.hull.facets_of(b);
        !self.hull.facets_of(a).iter().any(|f| fb.contains(f))
    }

    /// True when the interior of tetrahedron `t` meets the interior of `Q`.
    pub(crate) fn meets_interior(&self, t: &[Point3; 4]) -> bool {
        let q = &self.points;
        // A facet plane of Q with the tetrahedron on its outer closed side.
        for f in &self.hull.facet_planes {
            let [a, b, c] = f.map(|v| &q[v as usize]);
            if t.iter().all(|x| orient3d(a, b, c, x) >= 0) {
                return false;
            }
        }
        // A face plane of the tetrahedron with Q on its outer closed side.
        for k in 0..4 {
            let [a, b, c] = [(k + 1) % 4, (k + 2) % 4, (k + 3) % 4].map(|i| &t[i]);
            let s = orient3d(a, b, c, &t[k]);
            if q.iter().all(|x| s * orient3d(a, b, c, x) <= 0) {
                return false;
            }
        }
        // An edge of each.
        for (i, j) in [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)] {
            let u = vector(&t[i], &t[j]);
            for e in &self.edges {
                let v = vector(&q[e[0] as usize], &q[e[1] as usize]);
                if separates(&u, &v, t, q) {
                    return false;
                }
            }
        }
        true
    }
}

/// Whether the axis `u × v` separates the two point sets (projections not overlapping
/// in an open interval). A zero axis (parallel edges) separates nothing.
fn separates(
    u: &[crate::geom::Expansion; 3],
    v: &[crate::geom::Expansion; 3],
    a: &[Point3],
    b: &[Point3],
) -> bool {
    // The sign of (u × v) · (x − y): in floating point when the value clears an error
    // bound, exactly otherwise. The rounded value (the estimates of u and v, the cross
    // product, x − y and the dot product, each step off by at most 2⁻⁵³ of its size) is
    // within about 10 · 2⁻⁵³ of the permanent Σ |n_i| |w_i| of the true one, far inside
    // the 10⁻¹² of it used: a filter, never the decision near zero.
    let (uf, vf) = (
        [0, 1, 2].map(|i| u[i].estimate()),
        [0, 1, 2].map(|i| v[i].estimate()),
    );
    let n = [
        uf[1] * vf[2] - uf[2] * vf[1],
        uf[2] * vf[0] - uf[0] * vf[2],
        uf[0] * vf[1] - uf[1] * vf[0],
    ];
    let na = [
        (uf[1] * vf[2]).abs() + (uf[2] * vf[1]).abs(),
        (uf[2] * vf[0]).abs() + (uf[0] * vf[2]).abs(),
        (uf[0] * vf[1]).abs() + (uf[1] * vf[0]).abs(),
    ];
    let cmp = |x: &Point3, y: &Point3| {
        let w = [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
        let d = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
        let bound = (na[0] * w[0].abs() + na[1] * w[1].abs() + na[2] * w[2].abs()) * 1e-12;
        if d > bound {
            1
        } else if d < -bound {
            -1
        } else {
            det3(u, v, &vector(y, x)).sign()
        }
    };
    let extreme = |s: &[Point3], want: i8| -> Point3 {
        let mut best = s[0];
        for x in &s[1..] {
            if cmp(x, &best) == want {
                best = *x;
            }
        }
        best
    };
    let (a_hi, a_lo, b_hi, b_lo) = (extreme(a, 1), extreme(a, -1), extreme(b, 1), extreme(b, -1));
    if cmp(&a_hi, &a_lo) == 0 && cmp(&b_hi, &b_lo) == 0 {
        // Both flat along the axis: it is zero (parallel edges) or they are coplanar.
        return cmp(&a_hi, &b_hi) != 0;
    }
    cmp(&a_hi, &b_lo) <= 0 || cmp(&b_hi, &a_lo) <= 0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(lo: f64, side: f64) -> Vec<Point3> {
        (0..8)
            .map(|i| [0, 1, 2].map(|k| lo + if (i >> k) & 1 == 1 { side } else { 0.0 }))
            .collect()
    }

    #[test]
    fn tetrahedra_against_a_cube() {
        let q = Convex::new(cube(0.0, 1.0));
        // Far away, touching a facet, touching an edge only, and crossing it.
        let far = [
            [3.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [3.0, 1.0, 0.0],
            [3.0, 0.0, 1.0],
        ];
        let on_facet = [
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [1.0, 0.0, 1.0],
            [2.0, 0.0, 0.0],
        ];
        let on_edge = [
            [1.0, 1.0, 0.0],
            [1.0, 1.0, 1.0],
            [2.0, 2.0, 0.0],
            [1.5, 2.5, 0.5],
        ];
        let crossing = [
            [0.5, 0.5, 0.5],
            [3.0, 0.0, 0.0],
            [3.0, 1.0, 0.0],
            [3.0, 0.0, 1.0],
        ];
        // Beside the cube's vertical edge at (1, 1), across the plane x + y = 2: only an
        // axis from an edge of each (vertical, and along (−1, 1, 0)) separates them.
        let skew = [
            [1.2, 1.2, -1.0],
            [1.2, 1.2, 3.0],
            [3.0, -1.0, 1.0],
            [-1.0, 3.0, 1.0],
        ];
        assert!(!q.meets_interior(&far));
        assert!(!q.meets_interior(&on_facet));
        assert!(!q.meets_interior(&on_edge));
        assert!(q.meets_interior(&crossing));
        assert!(!q.meets_interior(&skew));
        let mut through = skew;
        through[2] = [2.6, -1.4, 1.0]; // x + y = 1.2 there: into the cube
        assert!(q.meets_interior(&through));
        let inside = [
            [0.1, 0.1, 0.1],
            [0.9, 0.1, 0.1],
            [0.1, 0.9, 0.1],
            [0.1, 0.1, 0.9],
        ];
        assert!(q.meets_interior(&inside));
    }
}
