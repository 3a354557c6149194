//! Exact intersection tests between segments, triangles and tetrahedra, built only from
//! the orientation predicates of [`super::predicates`]. No general-position assumption:
//! every collinear and coplanar case is classified.

use super::expansion;
use super::predicates::{
    Point2, Point3, collinear3, drop_axis, orient2d, orient3d, projection_axis, strictly_between,
};

/// How the relative interiors of two segments meet (they are not allowed to in a
/// tetrahedralization).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SegmentMeet {
    /// The interiors meet in exactly one point.
    Cross,
    /// The segments are collinear and share a piece of positive length.
    Overlap,
    /// An endpoint of one segment lies in the interior of the other.
    Touch,
}

/// Classifies how segments `ab` and `cd` meet beyond shared endpoints; `None` when they
/// are disjoint or meet only at a common endpoint.
///
/// ```
/// use tetrakit::geom::{segments_meet, SegmentMeet};
/// let (a, b) = ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0]);
/// assert_eq!(segments_meet(&a, &b, &[1.0, -1.0, 0.0], &[1.0, 1.0, 0.0]), Some(SegmentMeet::Cross));
/// assert_eq!(segments_meet(&a, &b, &[1.0, 0.0, 0.0], &[3.0, 0.0, 0.0]), Some(SegmentMeet::Overlap));
/// assert_eq!(segments_meet(&a, &b, &[1.0, 1.0, 1.0], &[1.0, 1.0, 5.0]), None);
/// ```
pub fn segments_meet(a: &Point3, b: &Point3, c: &Point3, d: &Point3) -> Option<SegmentMeet> {
    if orient3d(a, b, c, d) != 0 {
        return None;
    }
    let ab_c = collinear3(a, b, c);
    let ab_d = collinear3(a, b, d);
    if ab_c && ab_d {
        return collinear_meet(a, b, c, d);
    }
    // Coplanar, not all collinear: project to a plane where the configuration is faithful.
    let axis = if !ab_c {
        projection_axis(a, b, c)
    } else {
        projection_axis(a, b, d)
    }?;
    let (a2, b2, c2, d2) = (
        drop_axis(a, axis),
        drop_axis(b, axis),
        drop_axis(c, axis),
        drop_axis(d, axis),
    );
    let o1 = orient2d(&a2, &b2, &c2);
    let o2 = orient2d(&a2, &b2, &d2);
    let o3 = orient2d(&c2, &d2, &a2);
    let o4 = orient2d(&c2, &d2, &b2);
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return Some(SegmentMeet::Cross);
    }
    let touch = (o1 == 0 && strictly_between(a, c, b))
        || (o2 == 0 && strictly_between(a, d, b))
        || (o3 == 0 && strictly_between(c, a, d))
        || (o4 == 0 && strictly_between(c, b, d));
    touch.then_some(SegmentMeet::Touch)
}

/// Four collinear points: do segments `ab` and `cd` overlap, touch or not meet?
fn collinear_meet(a: &Point3, b: &Point3, c: &Point3, d: &Point3) -> Option<SegmentMeet> {
    // Coordinate along which the line is not constant orders the points exactly.
    let k = (0..3).find(|&k| a[k] != b[k]).unwrap_or(0);
    let (lo1, hi1) = (a[k].min(b[k]), a[k].max(b[k]));
    let (lo2, hi2) = (c[k].min(d[k]), c[k].max(d[k]));
    let lo = lo1.max(lo2);
    let hi = hi1.min(hi2);
    if lo < hi {
        Some(SegmentMeet::Overlap)
    } else {
        None
    }
}

/// True when point `p` lies in the relative interior of segment `ab`.
pub fn point_in_segment_interior(p: &Point3, a: &Point3, b: &Point3) -> bool {
    collinear3(a, p, b) && strictly_between(a, p, b)
}

/// True when the coplanar segment `pq` and the open triangle `abc` are weakly separated by
/// a line through a triangle edge or through `pq` (separating-axis test, exact).
fn coplanar_separated(p: &Point3, q: &Point3, a: &Point3, b: &Point3, c: &Point3) -> bool {
    let Some(axis) = projection_axis(a, b, c) else {
        return true;
    };
    let [p2, q2, a2, b2, c2] = [p, q, a, b, c].map(|x| drop_axis(x, axis));
    let s = orient2d(&a2, &b2, &c2);
    let edges = [(a2, b2), (b2, c2), (c2, a2)];
    if edges
        .iter()
        .any(|(u, w)| orient2d(u, w, &p2) * s <= 0 && orient2d(u, w, &q2) * s <= 0)
    {
        return true;
    }
    let o = [a2, b2, c2].map(|x| orient2d(&p2, &q2, &x));
    o.iter().all(|&x| x >= 0) || o.iter().all(|&x| x <= 0)
}

/// True when the line `pq` passes through the open triangle `abc` (non-coplanar case).
fn line_through_open_triangle(p: &Point3, q: &Point3, a: &Point3, b: &Point3, c: &Point3) -> bool {
    let s1 = orient3d(p, q, a, b);
    let s2 = orient3d(p, q, b, c);
    let s3 = orient3d(p, q, c, a);
    s1 != 0 && s1 == s2 && s2 == s3
}

/// True when the point `p` on the plane of `abc` lies in the open triangle `abc`.
fn coplanar_point_in_open_triangle(p: &Point3, a: &Point3, b: &Point3, c: &Point3) -> bool {
    let Some(axis) = projection_axis(a, b, c) else {
        return false;
    };
    let [p2, a2, b2, c2] = [p, a, b, c].map(|x| drop_axis(x, axis));
    let s = orient2d(&a2, &b2, &c2);
    orient2d(&a2, &b2, &p2) == s && orient2d(&b2, &c2, &p2) == s && orient2d(&c2, &a2, &p2) == s
}

/// Definition 2.2's *puncture*: the relative interiors of segment `pq` and triangle `abc`
/// intersect (any configuration, coplanar included).
pub fn segment_punctures_triangle(
    p: &Point3,
    q: &Point3,
    a: &Point3,
    b: &Point3,
    c: &Point3,
) -> bool {
    let op = orient3d(a, b, c, p);
    let oq = orient3d(a, b, c, q);
    match (op, oq) {
        (0, 0) => !coplanar_separated(p, q, a, b, c),
        _ if op * oq < 0 => line_through_open_triangle(p, q, a, b, c),
        _ => false,
    }
}

/// True when the *closed* segment `pq` meets the open triangle `abc` (the segment may end
/// inside the triangle). Used for Definition 2.1's L-emptiness of faces.
pub fn segment_meets_open_triangle(
    p: &Point3,
    q: &Point3,
    a: &Point3,
    b: &Point3,
    c: &Point3,
) -> bool {
    let op = orient3d(a, b, c, p);
    let oq = orient3d(a, b, c, q);
    match (op, oq) {
        (0, 0) => !coplanar_separated(p, q, a, b, c),
        (0, _) => coplanar_point_in_open_triangle(p, a, b, c),
        (_, 0) => coplanar_point_in_open_triangle(q, a, b, c),
        _ if op * oq < 0 => line_through_open_triangle(p, q, a, b, c),
        _ => false,
    }
}

/// True when the closed segment `pq` meets the closed triangle `abc` (`p = q` is a
/// point; a collinear `abc` is the segment it spans). Every contact counts: an end on
/// the triangle, the segment along an edge, a segment in the triangle's plane touching a
/// corner.
///
/// In the plane of the triangle the two are disjoint exactly when a line strictly
/// separates them, and such a line can be taken along an edge of the triangle or along
/// the segment (the edges of their Minkowski difference); across it, the line `pq`
/// passes through the closed triangle when the three signs `orient3d(p, q, x, y)` over
/// its edges `xy` are not of both strict signs.
///
/// ```
/// use tetrakit::geom::segment_meets_closed_triangle;
/// let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
/// let meets = |p, q| segment_meets_closed_triangle(&p, &q, &t[0], &t[1], &t[2]);
/// assert!(meets([1.0, 1.0, -1.0], [1.0, 1.0, 1.0]), "through the edge x + y = 2");
/// assert!(!meets([1.5, 1.5, -1.0], [1.5, 1.5, 1.0]));
/// assert!(meets([2.0, 0.0, 0.0], [3.0, 0.0, 0.0]), "a corner, in the plane");
/// assert!(!meets([2.0, 0.5, 0.0], [3.0, 0.0, 0.0]));
/// let (o, x) = ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0]);
/// let flat = |p, q| segment_meets_closed_triangle(&p, &q, &o, &x, &[1.0, 0.0, 0.0]);
/// assert!(flat([1.5, -1.0, 0.0], [1.5, 1.0, 0.0]), "across a collinear triangle");
/// assert!(!flat([2.5, -1.0, 0.0], [2.5, 1.0, 0.0]));
/// ```
pub fn segment_meets_closed_triangle(
    p: &Point3,
    q: &Point3,
    a: &Point3,
    b: &Point3,
    c: &Point3,
) -> bool {
    let (op, oq) = (orient3d(a, b, c, p), orient3d(a, b, c, q));
    if op * oq > 0 {
        return false;
    }
    let Some(axis) = projection_axis(a, b, c) else {
        // A collinear triangle is the union of its sides.
        let sides = [(a, b), (b, c), (c, a)];
        return (sides.iter()).any(|(x, y)| closed_segments_meet(p, q, x, y));
    };
    let [p2, q2, a2, b2, c2] = [p, q, a, b, c].map(|x| drop_axis(x, axis));
    let s = orient2d(&a2, &b2, &c2);
    let in_closed = |x: &Point2| {
        orient2d(&a2, &b2, x) * s >= 0
            && orient2d(&b2, &c2, x) * s >= 0
            && orient2d(&c2, &a2, x) * s >= 0
    };
    match (op, oq) {
        (0, 0) => {
            let edges = [(a2, b2), (b2, c2), (c2, a2)];
            let beyond_an_edge = edges
                .iter()
                .any(|(u, w)| orient2d(u, w, &p2) * s < 0 && orient2d(u, w, &q2) * s < 0);
            let o = [a2, b2, c2].map(|x| orient2d(&p2, &q2, &x));
            let beyond_the_segment = o.iter().all(|&x| x > 0) || o.iter().all(|&x| x < 0);
            !beyond_an_edge && !beyond_the_segment
        }
        (0, _) => in_closed(&p2),
        (_, 0) => in_closed(&q2),
        _ => {
            let e = [
                orient3d(p, q, a, b),
                orient3d(p, q, b, c),
                orient3d(p, q, c, a),
            ];
            e.iter().all(|&k| k >= 0) || e.iter().all(|&k| k <= 0)
        }
    }
}

/// True when the closed segments `pq` and `ab` share a point (either may be a point).
fn closed_segments_meet(p: &Point3, q: &Point3, a: &Point3, b: &Point3) -> bool {
    let on =
        |x: &Point3, u: &Point3, w: &Point3| x == u || x == w || point_in_segment_interior(x, u, w);
    on(p, a, b)
        || on(q, a, b)
        || on(a, p, q)
        || on(b, p, q)
        || segments_meet(p, q, a, b) == Some(SegmentMeet::Cross)
}

/// True when the closed segment `pq` meets the interior of the tetrahedron `t`
/// (any orientation of `t`; a degenerate `t` has an empty interior).
///
/// The segment enters the open tetrahedron iff an endpoint is inside, or it crosses a
/// face's relative interior towards the inside, or it passes through the relative
/// interiors of two opposite edges.
pub fn segment_meets_open_tetrahedron(p: &Point3, q: &Point3, t: &[Point3; 4]) -> bool {
    let s = orient3d(&t[0], &t[1], &t[2], &t[3]);
    if s == 0 {
        return false;
    }
    // Faces oriented so that the inside is positive.
    let faces = [(1, 2, 3, 0), (0, 3, 2, 1), (0, 1, 3, 2), (0, 2, 1, 3)];
    let side =
        |x: &Point3, f: (usize, usize, usize, usize)| -(s * orient3d(&t[f.0], &t[f.1], &t[f.2], x));
    let inside = |x: &Point3| faces.iter().all(|&f| side(x, f) > 0);
    if inside(p) || inside(q) {
        return true;
    }
    for &f in &faces {
        let (a, b, c) = (&t[f.0], &t[f.1], &t[f.2]);
        let (sp, sq) = (side(p, f), side(q, f));
        let crosses = (sp * sq < 0 && line_through_open_triangle(p, q, a, b, c))
            || (sp == 0 && sq > 0 && coplanar_point_in_open_triangle(p, a, b, c))
            || (sq == 0 && sp > 0 && coplanar_point_in_open_triangle(q, a, b, c));
        if crosses {
            return true;
        }
    }
    let opposite = [((0, 1), (2, 3)), ((0, 2), (1, 3)), ((0, 3), (1, 2))];
    opposite.iter().any(|&((i, j), (k, l))| {
        segment_touches_interior(p, q, &t[i], &t[j]) && segment_touches_interior(p, q, &t[k], &t[l])
    })
}

/// True when the closed segment `pq` meets the relative interior of segment `ab`.
fn segment_touches_interior(p: &Point3, q: &Point3, a: &Point3, b: &Point3) -> bool {
    point_in_segment_interior(p, a, b)
        || point_in_segment_interior(q, a, b)
        || segments_meet(p, q, a, b) == Some(SegmentMeet::Cross)
}

/// True when the point `x` lies in the closed tetrahedron `t` but is none of its corners.
pub fn point_in_closed_tetrahedron(x: &Point3, t: &[Point3; 4]) -> bool {
    let s = orient3d(&t[0], &t[1], &t[2], &t[3]);
    if s == 0 || t.contains(x) {
        return false;
    }
    let faces = [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)];
    faces
        .iter()
        .all(|&(a, b, c)| s * orient3d(&t[a], &t[b], &t[c], x) <= 0)
}

/// True when two coplanar triangles have intersecting (2D) interiors. The caller
/// guarantees the six points are coplanar.
pub fn coplanar_triangles_overlap(t: &[Point3; 3], u: &[Point3; 3]) -> bool {
    let Some(axis) = projection_axis(&t[0], &t[1], &t[2]) else {
        return false;
    };
    let t2 = t.map(|x| drop_axis(&x, axis));
    let u2 = u.map(|x| drop_axis(&x, axis));
    let separated_by = |a: &[[f64; 2]; 3], b: &[[f64; 2]; 3]| {
        let s = orient2d(&a[0], &a[1], &a[2]);
        (0..3).any(|i| {
            let (p, q) = (&a[i], &a[(i + 1) % 3]);
            b.iter().all(|x| orient2d(p, q, x) * s <= 0)
        })
    };
    !(separated_by(&t2, &u2) || separated_by(&u2, &t2))
}

/// True when the open cones with common apex `v` spanned by the directions of `a` and of
/// `b` (three points each, not coplanar with `v`) have intersecting interiors.
///
/// Two convex cones with a common apex are disjoint exactly when a plane through the apex
/// separates them; by the separating-axis theorem it can be taken through `v` and two
/// generators (a face plane of either cone, or one generator of each), so every test is an
/// [`orient3d`] of input points.
///
/// ```
/// use tetrakit::geom::cones_overlap;
/// let v = [0.0, 0.0, 0.0];
/// let a = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let b = [[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0]];
/// assert!(cones_overlap(&v, &a, &b));
/// let c = [[-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]];
/// assert!(!cones_overlap(&v, &a, &c));
/// ```
pub fn cones_overlap(v: &Point3, a: &[Point3; 3], b: &[Point3; 3]) -> bool {
    // Does the plane through v, x, y put a and b on opposite closed sides? Stops at the
    // first generator that rules it out.
    // The plane's own generators lie on it: no need for the (slow) exact zero.
    let side = |x: &Point3, y: &Point3, p: &Point3| {
        if p == x || p == y {
            0
        } else {
            orient3d(v, x, y, p)
        }
    };
    let separates = |x: &Point3, y: &Point3| {
        // A degenerate plane (v, x, y collinear, e.g. a generator shared by both cones)
        // separates nothing.
        if collinear3(v, x, y) {
            return false;
        }
        let mut side_a = 0i8;
        for p in a {
            match (side_a, side(x, y, p)) {
                (_, 0) => {}
                (0, s) => side_a = s,
                (s, t) if s != t => return false,
                _ => {}
            }
        }
        b.iter().all(|p| {
            let s = side(x, y, p);
            s == 0 || side_a == 0 || s == -side_a
        }) && (side_a != 0 || {
            // a lies in the plane: b must lie on one closed side.
            let sb: Vec<i8> = b.iter().map(|p| side(x, y, p)).collect();
            sb.iter().all(|&s| s >= 0) || sb.iter().all(|&s| s <= 0)
        })
    };
    let pairs = [(0, 1), (1, 2), (2, 0)];
    if pairs
        .iter()
        .any(|&(i, j)| separates(&a[i], &a[j]) || separates(&b[i], &b[j]))
    {
        return false;
    }
    !(0..3).any(|i| (0..3).any(|j| separates(&a[i], &b[j])))
}

/// True when two triangles meet anywhere other than in the vertices they share (given by
/// index equality in `ti`, `ui`) and the edge between two shared vertices.
pub fn triangles_meet_improperly(
    t: &[Point3; 3],
    ti: [u32; 3],
    u: &[Point3; 3],
    ui: [u32; 3],
) -> bool {
    // Quick exit: the vertices of one triangle not shared with the other all strictly on
    // one side of the other's plane, so the two meet at most in their shared vertices.
    let off_plane = |a: &[Point3; 3], b: &[Point3; 3], bi: [u32; 3], ai: [u32; 3]| {
        let mut side = 0i8;
        for k in 0..3 {
            if ai.contains(&bi[k]) {
                continue;
            }
            let s = orient3d(&a[0], &a[1], &a[2], &b[k]);
            if s == 0 || (side != 0 && s != side) {
                return false;
            }
            side = s;
        }
        true
    };
    if off_plane(t, u, ui, ti) || off_plane(u, t, ti, ui) {
        return false;
    }
    let edges = [(0, 1), (1, 2), (2, 0)];
    let shared = |x: u32| ui.contains(&x);
    for (i, j) in edges {
        // A closed edge of one entering the open other triangle.
        if segment_meets_open_triangle(&t[i], &t[j], &u[0], &u[1], &u[2])
            || segment_meets_open_triangle(&u[i], &u[j], &t[0], &t[1], &t[2])
        {
            return true;
        }
        for (k, l) in edges {
            let same_edge = shared(ti[i])
                && shared(ti[j])
                && [ui[k], ui[l]].contains(&ti[i])
                && [ui[k], ui[l]].contains(&ti[j]);
            if same_edge {
                continue;
            }
            if segments_meet(&t[i], &t[j], &u[k], &u[l]).is_some() {
                return true;
            }
        }
    }
    // A vertex of one on the other that is not a shared vertex.
    (0..3).any(|i| !shared(ti[i]) && u.contains(&t[i]))
        || (0..3).any(|k| !ti.contains(&ui[k]) && t.contains(&u[k]))
}

/// True when the open interiors of two tetrahedra intersect (a degenerate tetrahedron has
/// an empty interior).
///
/// Two convex polytopes have disjoint interiors exactly when a plane puts them on opposite
/// closed sides; by the separating-axis theorem in 3D such a plane can be taken parallel to
/// a face of either or to an edge of each. Face planes are [`orient3d`] tests; the
/// edge-edge planes use exact floating-point expansions (the crate's `geom::expansion`).
///
/// ```
/// use tetrakit::geom::tetrahedra_overlap;
/// let t = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0]];
/// let shifted = t.map(|p| [p[0] + 0.5, p[1] + 0.5, p[2] + 0.5]);
/// let far = t.map(|p| [p[0] + 5.0, p[1], p[2]]);
/// assert!(tetrahedra_overlap(&t, &shifted));
/// assert!(!tetrahedra_overlap(&t, &far));
/// ```
pub fn tetrahedra_overlap(t: &[Point3; 4], u: &[Point3; 4]) -> bool {
    if orient3d(&t[0], &t[1], &t[2], &t[3]) == 0 || orient3d(&u[0], &u[1], &u[2], &u[3]) == 0 {
        return false;
    }
    let separates = |side: &dyn Fn(&Point3) -> i8| {
        let st: Vec<i8> = t.iter().map(side).collect();
        let su: Vec<i8> = u.iter().map(side).collect();
        (st.iter().all(|&s| s <= 0) && su.iter().all(|&s| s >= 0))
            || (st.iter().all(|&s| s >= 0) && su.iter().all(|&s| s <= 0))
    };
    let faces = [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)];
    for w in [t, u] {
        for &(i, j, k) in &faces {
            if separates(&|x: &Point3| orient3d(&w[i], &w[j], &w[k], x)) {
                return false;
            }
        }
    }
    let edges = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    for &(i, j) in &edges {
        for &(k, l) in &edges {
            if expansion::parallel(&t[i], &t[j], &u[k], &u[l]) {
                continue;
            }
            let side = |x: &Point3| expansion::edge_edge_side(&t[i], &t[j], &u[k], &u[l], x);
            if separates(&side) {
                return false;
            }
        }
    }
    true
}

/// True when triangle `tri` (vertex indices `ti`) meets the closed tetrahedron `t`
/// (indices `tt`) anywhere other than in the simplex spanned by their shared vertices.
pub fn triangle_meets_tet(tri: &[Point3; 3], ti: [u32; 3], t: &[Point3; 4], tt: &[u32; 4]) -> bool {
    let s = orient3d(&t[0], &t[1], &t[2], &t[3]);
    let faces = [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)];
    // Quick exit: a face plane with every vertex of tri strictly outside or a corner of
    // that face.
    let separated = faces.iter().any(|&(i, j, k)| {
        (0..3).all(|m| {
            let v = ti[m];
            v == tt[i] || v == tt[j] || v == tt[k] || s * orient3d(&t[i], &t[j], &t[k], &tri[m]) > 0
        })
    });
    if separated {
        return false;
    }
    for &(i, j, k) in &faces {
        if triangles_meet_improperly(&[t[i], t[j], t[k]], [tt[i], tt[j], tt[k]], tri, ti) {
            return true;
        }
    }
    (0..3).any(|m| !tt.contains(&ti[m]) && point_in_closed_tetrahedron(&tri[m], t))
}

/// True when segment `pq` (vertex indices `s`) meets the closed tetrahedron `t`
/// (indices `tt`) anywhere other than in their shared vertices, and is not one of its
/// edges: the test a tetrahedron must pass to sit in a tetrahedralization that has `pq`
/// as an edge.
///
/// ```
/// use tetrakit::geom::segment_meets_tet_improperly;
/// let t = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0]];
/// let (tt, far) = ([0, 1, 2, 3], [9.0, 9.0, 9.0]);
/// // An edge of the tetrahedron, and a segment that leaves a corner outwards: fine.
/// assert!(!segment_meets_tet_improperly(&t[0], &t[1], [0, 1], &t, &tt));
/// assert!(!segment_meets_tet_improperly(&t[0], &[-1.0, -1.0, -1.0], [0, 4], &t, &tt));
/// // Through the tetrahedron, or across one of its edges: improper.
/// assert!(segment_meets_tet_improperly(&t[0], &far, [0, 4], &t, &tt));
/// assert!(segment_meets_tet_improperly(&[2.0, -1.0, 2.0], &[2.0, 1.0, -2.0], [4, 5], &t, &tt));
/// ```
pub fn segment_meets_tet_improperly(
    p: &Point3,
    q: &Point3,
    s: [u32; 2],
    t: &[Point3; 4],
    tt: &[u32; 4],
) -> bool {
    if tt.contains(&s[0]) && tt.contains(&s[1]) {
        return false;
    }
    if segment_meets_open_tetrahedron(p, q, t) {
        return true;
    }
    let faces = [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)];
    if faces
        .iter()
        .any(|&(i, j, k)| segment_meets_open_triangle(p, q, &t[i], &t[j], &t[k]))
    {
        return true;
    }
    let edges = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    edges
        .iter()
        .any(|&(i, j)| segments_meet(p, q, &t[i], &t[j]).is_some())
}

#[cfg(test)]
mod tests {
    /// `segment_punctures_triangle` on a worked example.
    #[test]
    fn segment_punctures_triangle_example() {
        use crate::geom::segment_punctures_triangle;
        let (a, b, c) = ([0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]);
        assert!(segment_punctures_triangle(
            &[1.0, 1.0, -1.0],
            &[1.0, 1.0, 1.0],
            &a,
            &b,
            &c
        ));
        assert!(!segment_punctures_triangle(
            &[1.0, 1.0, 0.0],
            &[1.0, 1.0, 1.0],
            &a,
            &b,
            &c
        ));
    }

    use super::*;

    const O: Point3 = [0.0, 0.0, 0.0];

    #[test]
    fn segment_meet_degenerate_cases() {
        let b = [2.0, 0.0, 0.0];
        // shared endpoint only
        assert_eq!(segments_meet(&O, &b, &b, &[3.0, 1.0, 0.0]), None);
        // collinear, sharing only an endpoint
        assert_eq!(segments_meet(&O, &b, &b, &[3.0, 0.0, 0.0]), None);
        // T-junction: endpoint in the interior
        assert_eq!(
            segments_meet(&O, &b, &[1.0, 0.0, 0.0], &[1.0, 5.0, 0.0]),
            Some(SegmentMeet::Touch)
        );
        // collinear containment
        assert_eq!(
            segments_meet(&O, &b, &[0.5, 0.0, 0.0], &[1.0, 0.0, 0.0]),
            Some(SegmentMeet::Overlap)
        );
        // coplanar disjoint
        assert_eq!(
            segments_meet(&O, &b, &[0.0, 1.0, 0.0], &[2.0, 1.0, 0.0]),
            None
        );
        // crossing in a vertical plane (projection axis matters)
        assert_eq!(
            segments_meet(&O, &[0.0, 0.0, 2.0], &[0.0, -1.0, 1.0], &[0.0, 1.0, 1.0]),
            Some(SegmentMeet::Cross)
        );
        // skew
        assert_eq!(
            segments_meet(&O, &b, &[1.0, -1.0, 1.0], &[1.0, 1.0, 1.0]),
            None
        );
    }

    #[test]
    fn puncture_coplanar_and_boundary_cases() {
        let (a, b, c) = (O, [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]);
        // coplanar segment through the interior
        assert!(segment_punctures_triangle(
            &[-1.0, 1.0, 0.0],
            &[5.0, 1.0, 0.0],
            &a,
            &b,
            &c
        ));
        // coplanar segment along an edge
        assert!(!segment_punctures_triangle(
            &[-1.0, 0.0, 0.0],
            &[5.0, 0.0, 0.0],
            &a,
            &b,
            &c
        ));
        // crossing exactly through an edge
        assert!(!segment_punctures_triangle(
            &[2.0, 0.0, -1.0],
            &[2.0, 0.0, 1.0],
            &a,
            &b,
            &c
        ));
        // through a vertex
        assert!(!segment_punctures_triangle(
            &[0.0, 0.0, -1.0],
            &[0.0, 0.0, 1.0],
            &a,
            &b,
            &c
        ));
        // closed segment ending in the open triangle
        assert!(segment_meets_open_triangle(
            &[1.0, 1.0, 0.0],
            &[1.0, 1.0, 3.0],
            &a,
            &b,
            &c
        ));
        // a segment from a vertex into the triangle (coplanar)
        assert!(segment_punctures_triangle(&a, &[1.0, 1.0, 0.0], &a, &b, &c));
    }

    #[test]
    fn open_tetrahedron_cases() {
        let t = [O, [4.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 4.0]];
        // through two opposite edges (midpoints of edge 01 and edge 23)
        assert!(segment_meets_open_tetrahedron(
            &[2.0, 0.0, 0.0],
            &[0.0, 2.0, 2.0],
            &t
        ));
        // along a face
        assert!(!segment_meets_open_tetrahedron(
            &[1.0, 0.0, 0.0],
            &[0.0, 1.0, 0.0],
            &t
        ));
        // from a vertex through the interior
        assert!(segment_meets_open_tetrahedron(&O, &[3.0, 3.0, 3.0], &t));
        // ending on a face from outside
        assert!(!segment_meets_open_tetrahedron(
            &[1.0, 1.0, -1.0],
            &[1.0, 1.0, 0.0],
            &t
        ));
        // crossing a face into the interior and ending inside
        assert!(segment_meets_open_tetrahedron(
            &[1.0, 1.0, -1.0],
            &[1.0, 1.0, 0.5],
            &t
        ));
        assert!(point_in_closed_tetrahedron(&[1.0, 1.0, 0.0], &t));
        assert!(!point_in_closed_tetrahedron(&O, &t));
    }

    #[test]
    fn coplanar_triangle_overlap() {
        let t = [O, [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
        assert!(coplanar_triangles_overlap(
            &t,
            &[[1.0, 1.0, 0.0], [0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]
        ));
        // sharing an edge, opposite sides
        assert!(!coplanar_triangles_overlap(
            &t,
            &[[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [2.0, 2.0, 0.0]]
        ));
    }
}

#[cfg(test)]
mod shared_vertex_tests {
    use super::*;

    #[test]
    fn triangles_sharing_vertices_meet_properly_or_not() {
        let (a, b) = ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0]);
        let t = [a, b, [1.0, 2.0, 0.0]];
        // A hinge: shared edge, other vertex off the plane.
        assert!(!triangles_meet_improperly(
            &t,
            [0, 1, 2],
            &[a, b, [1.0, 1.0, 1.0]],
            [0, 1, 3]
        ));
        // Folded flat onto t: shared edge, overlapping interiors.
        assert!(triangles_meet_improperly(
            &t,
            [0, 1, 2],
            &[a, b, [1.0, 1.0, 0.0]],
            [0, 1, 3]
        ));
        // Flat, on the other side of the shared edge: proper.
        assert!(!triangles_meet_improperly(
            &t,
            [0, 1, 2],
            &[a, b, [1.0, -1.0, 0.0]],
            [0, 1, 3]
        ));
        // Shared vertex a, the other triangle pierces t.
        let u = [a, [1.0, 0.5, -1.0], [1.0, 0.5, 1.0]];
        assert!(triangles_meet_improperly(&t, [0, 1, 2], &u, [0, 4, 5]));
        // Shared vertex a, u entirely above t's plane except at a: proper.
        let w = [a, [1.0, 0.5, 1.0], [0.0, 1.0, 1.0]];
        assert!(!triangles_meet_improperly(&t, [0, 1, 2], &w, [0, 4, 5]));
    }
}
