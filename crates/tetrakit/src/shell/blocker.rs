//! The inner polytope `Q` as what blocks sight in chapter 4's visibility (§4.3: `u` is
//! visible to `v` when the segment `uv` misses `Q`, a facet when the cone from `v` over
//! it does): does the convex hull of a few points meet the closed `Q`?
//!
//! Exact and complete, in time linear in `Q`'s size. Two closed convex polytopes `A`
//! (here `conv(s)`) and `B` (`Q`) meet exactly when one of these holds:
//! 1. a vertex of `A` lies in `B`, or a vertex of `B` in `A`;
//! 2. an edge of `A` meets a closed boundary triangle of `B`;
//! 3. an edge of `B` meets a closed 2-face of `A`.
//!
//! Why: if they meet, `A ∩ B` is a polytope with a vertex `x`. `x` lies in the relative
//! interiors of a face `F` of `A` and a face `G` of `B` whose affine hulls meet in `x`
//! alone, so `dim F + dim G ≤ 3`: `F` or `G` is a vertex, or one is an edge and the other
//! at most 2-dimensional. A vertex of `B` in `A` with `B ⊄ A` has an edge of `B` leaving
//! `A` through a 2-face of `A` (or, when `A` is flat, lying on `A` itself; when `A` is a
//! segment or a point, the vertex is on an edge or a vertex of `A`, which meets a closed
//! triangle of `B` at `x`), so one vertex of each (`B ⊆ A` or `A ⊆ B`) is enough for 1.
//! The edges and 2-faces of `A` are covered by the segments and triangles of every pair
//! and triple of `s` (each lies in `A`, and every face of `A` is a union of them).
//!
//! Every test is [`segment_meets_closed_triangle`] or an `orient3d` sign; boxes
//! (coordinates compared exactly) only pass over pieces of `Q` that cannot take part.

use crate::geom::{
    Hull3, Point3, bounding_box, collinear3, orient3d, segment_meets_closed_triangle,
};
use rustc_hash::FxHashSet as HashSet;

/// An axis-parallel box, its least and greatest corners.
type Box3 = (Point3, Point3);

/// The closed boxes share a point.
fn overlap(a: &Box3, b: &Box3) -> bool {
    (0..3).all(|k| a.0[k] <= b.1[k] && b.0[k] <= a.1[k])
}

/// A closed convex polytope (`Q`, full-dimensional) that blocks sight.
pub(super) struct Blocker {
    /// Its number of vertices.
    size: usize,
    frame: Box3,
    /// A vertex, for `Q ⊆ conv(s)`.
    vertex: Point3,
    /// The facet planes, each by three points, oriented outwards (`orient3d <= 0` inside).
    planes: Vec<[Point3; 3]>,
    /// The edges of the boundary's triangles, each once, with their boxes.
    edges: Vec<([Point3; 2], Box3)>,
    /// The boundary's triangles, with their boxes.
    triangles: Vec<([Point3; 3], Box3)>,
}

impl Blocker {
    /// `points` must span three dimensions.
    pub(super) fn new(points: &[Point3]) -> Blocker {
        let hull = Hull3::facets_only(points);
        let planes = (hull.facet_planes.iter())
            .map(|f| f.map(|i| points[i as usize]))
            .collect();
        let mut seen = HashSet::default();
        let mut edges = Vec::new();
        for t in &hull.triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                if seen.insert((a.min(b), a.max(b))) {
                    let e = [points[a as usize], points[b as usize]];
                    edges.push((e, bounding_box(&e)));
                }
            }
        }
        let triangles = (hull.triangles.iter())
            .map(|t| {
                let t = t.map(|i| points[i as usize]);
                (t, bounding_box(&t))
            })
            .collect();
        Blocker {
            size: points.len(),
            frame: bounding_box(points),
            vertex: points[hull.triangles[0][0] as usize],
            planes,
            edges,
            triangles,
        }
    }

    /// Its number of points (what one test of [`Blocker::misses`] costs grows with).
    pub(super) fn len(&self) -> usize {
        self.size
    }

    /// `conv(s)` misses the closed polytope (`s` not empty).
    pub(super) fn misses(&self, s: &[Point3]) -> bool {
        self.apart(s)
            || !(self.contains(&s[0])
                || pairs(s.len()).any(|(i, j)| self.crossed(&s[i], &s[j]))
                || self.inside(s)
                || triples(s.len()).any(|(i, j, k)| self.pierces(&s[i], &s[j], &s[k])))
    }

    /// The boxes of `s` and of the polytope are apart: `conv(s)` misses it.
    pub(super) fn apart(&self, s: &[Point3]) -> bool {
        !overlap(&bounding_box(s), &self.frame)
    }

    /// `x` lies in the closed polytope.
    pub(super) fn contains(&self, x: &Point3) -> bool {
        self.planes
            .iter()
            .all(|[a, b, c]| orient3d(a, b, c, x) <= 0)
    }

    /// A vertex of the polytope lies in `conv(s)`, which spans three dimensions.
    pub(super) fn inside(&self, s: &[Point3]) -> bool {
        contains(s, &self.vertex)
    }

    /// The closed segment `pq` meets a closed boundary triangle.
    pub(super) fn crossed(&self, p: &Point3, q: &Point3) -> bool {
        let query = bounding_box(&[*p, *q]);
        (self.triangles.iter()).any(|(t, b)| {
            overlap(b, &query) && segment_meets_closed_triangle(p, q, &t[0], &t[1], &t[2])
        })
    }

    /// An edge of the polytope meets the closed triangle `abc` (false when `abc` is
    /// collinear: its segments are [`Blocker::crossed`]'s).
    pub(super) fn pierces(&self, a: &Point3, b: &Point3, c: &Point3) -> bool {
        if collinear3(a, b, c) {
            return false;
        }
        let query = bounding_box(&[*a, *b, *c]);
        (self.edges.iter())
            .any(|([p, q], e)| overlap(e, &query) && segment_meets_closed_triangle(p, q, a, b, c))
    }
}

/// `x` lies in `conv(s)` where `s` spans three dimensions: on the inner closed side of
/// every plane through three points of `s` that has `s` on one side. False when `s` is
/// flatter (then rules 2 and 3 of the module docs decide).
fn contains(s: &[Point3], x: &Point3) -> bool {
    let mut solid = false;
    for (i, j, k) in triples(s.len()) {
        let (a, b, c) = (&s[i], &s[j], &s[k]);
        let (mut lo, mut hi) = (0, 0);
        for p in s {
            let o = orient3d(a, b, c, p);
            (lo, hi) = (lo.min(o), hi.max(o));
        }
        if lo < 0 && hi > 0 {
            continue;
        }
        solid |= lo < 0 || hi > 0;
        let o = orient3d(a, b, c, x);
        if (hi > 0 && o < 0) || (lo < 0 && o > 0) {
            return false;
        }
    }
    solid
}

fn pairs(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..n).flat_map(move |i| (i + 1..n).map(move |j| (i, j)))
}

fn triples(n: usize) -> impl Iterator<Item = (usize, usize, usize)> {
    pairs(n).flat_map(move |(i, j)| (j + 1..n).map(move |k| (i, j, k)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::{det3, vector};
    use crate::rng::Rng;

    /// The separating axis theorem, exact and slow: `conv(s)` and the closed polytope
    /// are disjoint exactly when a facet plane of either, or a plane spanned by an edge
    /// direction of each, separates them strictly (every pair and triple of `s` stands in
    /// for its edges and facets, every pair of the polytope's points for its edges).
    fn separated(q: &[Point3], s: &[Point3]) -> bool {
        let apart = |value: &dyn Fn(&Point3) -> crate::geom::Expansion| {
            let vals = |pts: &[Point3]| pts.iter().map(value).collect::<Vec<_>>();
            let (vs, vq) = (vals(s), vals(q));
            let below = |x: &[crate::geom::Expansion], y: &[crate::geom::Expansion]| {
                x.iter().all(|a| y.iter().all(|b| a.sub(b).sign() < 0))
            };
            below(&vs, &vq) || below(&vq, &vs)
        };
        let mut dirs: Vec<[Point3; 2]> = Vec::new();
        let mut normals: Vec<[Point3; 3]> = Vec::new();
        for (i, j) in pairs(s.len()) {
            dirs.push([s[i], s[j]]);
        }
        for (i, j, k) in triples(s.len()) {
            normals.push([s[i], s[j], s[k]]);
        }
        let mut q_dirs = Vec::new();
        for (i, j) in pairs(q.len()) {
            q_dirs.push([q[i], q[j]]);
        }
        for (i, j, k) in triples(q.len()) {
            normals.push([q[i], q[j], q[k]]);
        }
        for [a, b, c] in &normals {
            if !collinear3(a, b, c) {
                let (u, w) = (vector(a, b), vector(a, c));
                if apart(&|x| det3(&u, &w, &vector(a, x))) {
                    return true;
                }
            }
        }
        // Parallel directions give the zero axis, on which nothing is apart.
        dirs.iter().any(|[a0, a1]| {
            q_dirs.iter().any(|[g0, g1]| {
                let (u, w) = (vector(a0, a1), vector(g0, g1));
                apart(&|x| det3(&u, &w, &vector(a0, x)))
            })
        })
    }

    /// `misses` answers as the separating axis theorem on random and grid polytopes
    /// against points, segments, triangles, tetrahedra and five-point sets, touching
    /// included, and small polytopes inside them.
    #[test]
    fn misses_is_the_separating_axis_theorem() {
        let mut rng = Rng::new(14);
        let (mut met, mut missed) = (0, 0);
        for case in 0..6000 {
            let pick = |rng: &mut Rng| -> Point3 {
                match case % 3 {
                    0 => [0; 3].map(|_| rng.below(4) as f64),
                    1 => [0; 3].map(|_| rng.below(7) as f64 * 0.5),
                    _ => [0; 3].map(|_| rng.unit() * 3.0),
                }
            };
            // Every fourth polytope shrunk about the middle, to fall inside `conv(s)`.
            let shrink = |p: Point3| match case % 4 {
                0 => p.map(|x| 1.25 + x / 4.0),
                _ => p,
            };
            let q: Vec<Point3> = (0..4 + case % 4).map(|_| shrink(pick(&mut rng))).collect();
            if Hull3::new(&q).dimension < 3 {
                continue;
            }
            let b = Blocker::new(&q);
            let s: Vec<Point3> = (0..1 + case % 5).map(|_| pick(&mut rng)).collect();
            let want = separated(&q, &s);
            assert_eq!(b.misses(&s), want, "case {case}: {q:?} {s:?}");
            if want {
                missed += 1;
            } else {
                met += 1;
            }
        }
        assert!(met > 1000 && missed > 1000, "{met} met, {missed} missed");
    }

    #[test]
    fn a_tetrahedron_sees_past_a_small_far_blocker() {
        let q = Blocker::new(&[
            [10.0, 10.0, 10.0],
            [11.0, 10.0, 10.0],
            [10.0, 11.0, 10.0],
            [10.0, 10.0, 11.0],
        ]);
        let tet = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        assert!(q.misses(&tet));
        assert!(
            !q.misses(&[[0.0, 0.0, 0.0], [20.0, 20.0, 20.0]]),
            "a segment through it"
        );
        // Touching is not missing: the segment ends on the blocker's corner.
        assert!(!q.misses(&[[0.0, 0.0, 0.0], [10.0, 10.0, 10.0]]));
        assert!(
            !q.misses(&[[11.0, 9.0, 10.5], [9.0, 11.0, 10.5]]),
            "crosses a facet"
        );
        // A large tetrahedron around it: no edge or face meets it, a vertex is inside.
        let big = [
            [0.0, 0.0, 0.0],
            [40.0, 0.0, 0.0],
            [0.0, 40.0, 0.0],
            [0.0, 0.0, 40.0],
        ];
        assert!(!q.misses(&big));
        // A segment beside the edge x + y = 1 of the unit corner.
        let corner = Blocker::new(&[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ]);
        assert!(corner.misses(&[[0.6, 0.6, -1.0], [0.6, 0.6, 1.0]]));
        assert!(
            !corner.misses(&[[0.5, 0.5, -1.0], [0.5, 0.5, 1.0]]),
            "touches the edge"
        );
    }
}
