//! The certificate check of a tetrahedralization.
//!
//! Conditions checked (all exact):
//! 1. every tetrahedron has four distinct, in-range vertices and is positively oriented,
//!    and no two vertices of tetrahedra are at the same place (points no tetrahedron
//!    uses may be anywhere);
//! 2. every triangle is a face of at most two tetrahedra, and of two only when they lie on
//!    opposite sides of it (oriented-face pairing);
//! 3. the unpaired (boundary) faces form a closed surface: every boundary edge is used as
//!    often in one direction as in the other. An edge used more than once each way is a
//!    *non-manifold edge* of the domain (two boxes meshed conformingly, touching along an
//!    edge), as valid as a non-manifold vertex (boxes touching at a corner); such edges are
//!    counted in [`Report::non_manifold`], and `check --manifold` reports them;
//! 4. with a convex domain: every boundary face lies on a facet of the convex hull of the
//!    points, the boundary faces on one facet do not overlap, and every point is a vertex;
//!    without one: the tetrahedra around each vertex do not overlap, the boundary does not
//!    meet itself, and no piece is nested inside another (see [`embed`]).
//!
//! Why 1–4 certify a tetrahedralization of the hull: for a generic point x inside the hull,
//! the number N(x) of tetrahedra containing x does not change when x crosses a paired face
//! (it leaves one tetrahedron and enters the other) and x cannot cross a boundary face
//! without leaving the hull, so N is a constant d on the hull's interior. Just inside a
//! hull facet, N counts the boundary faces over that spot, so d = 1 exactly when boundary
//! faces on a facet do not overlap. With d = 1 the tetrahedra have disjoint interiors and
//! cover the hull, and pairing excludes hanging vertices.

use super::embed;
use super::report::{Problem, ProblemKind, Report};
use crate::geom::{Hull3, Point3, coplanar_triangles_overlap, orient3d};
use crate::numbering::ids;
use crate::rows::split_at_offsets;
use rayon::prelude::*;

/// Verifies `tets` over `points`. With `hull` given, also certifies that the tetrahedra
/// tetrahedralize the convex hull of *all* points (see the module docs for why the
/// conditions suffice).
///
/// ```
/// use tetrakit::{geom::Hull3, mesh::verify};
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let hull = Hull3::new(&pts);
/// assert!(verify(&pts, &[[0, 1, 2, 3]], Some(&hull)).is_valid());
/// assert!(!verify(&pts, &[[0, 2, 1, 3]], Some(&hull)).is_valid()); // inverted
/// ```
pub fn verify(points: &[Point3], tets: &[[u32; 4]], hull: Option<&Hull3>) -> Report {
    let (mut report, boundary) = verify_faces(points, tets);
    if report
        .problems
        .iter()
        .any(|p| p.kind == ProblemKind::BadIndex)
    {
        return report;
    }
    for p in coincident_vertices(points, tets) {
        report.push(p);
    }
    if let Some(h) = hull {
        for p in check_hull(points, tets, &boundary, h) {
            report.push(p);
        }
    } else if report.is_valid() {
        check_embedding(points, tets, &boundary, &mut report);
    }
    report
}

/// Conditions 1–3 (orientation, face pairing, a closed boundary) and the boundary faces,
/// outward; nothing about the domain. A certificate that pins the covering degree by
/// other means ([`certify_shell`](super::certify_shell)) adds its own checks to these.
/// With a bad index the boundary is empty and the report names the index.
pub(crate) fn verify_faces(points: &[Point3], tets: &[[u32; 4]]) -> (Report, Vec<BoundaryFace>) {
    let mut report = Report::default();
    let (problems, signs) = check_tets(points, tets);
    for p in problems {
        report.push(p);
    }
    if report
        .problems
        .iter()
        .any(|p| p.kind == ProblemKind::BadIndex)
    {
        return (report, Vec::new());
    }
    let (boundary, pairing) = pair_faces(points.len(), tets, &signs, None);
    for p in pairing {
        report.push(p);
    }
    report.boundary_faces = boundary.len();
    let (open, non_manifold) = check_closed(&boundary);
    for p in open {
        report.push(p);
    }
    report.non_manifold = non_manifold;
    (report, boundary)
}

/// Vertices of tetrahedra at the same place, each after the first of its place named
/// with the first, and a tetrahedron using each. (Only a file can make them: every
/// algorithm's points are distinct.)
pub(super) fn coincident_vertices(points: &[Point3], tets: &[[u32; 4]]) -> Vec<Problem> {
    let mut first_tet = vec![u32::MAX; points.len()];
    for (k, t) in tets.iter().enumerate().rev() {
        t.iter().for_each(|&v| first_tet[v as usize] = k as u32);
    }
    let mut used: Vec<(Point3, u32, u32)> = (0..points.len() as u32)
        .filter(|&v| first_tet[v as usize] != u32::MAX)
        .map(|v| (points[v as usize], v, first_tet[v as usize]))
        .collect();
    coincident_runs(&mut used)
}

/// [`coincident_vertices`] of the used vertices `(place, vertex, first tetrahedron)`,
/// each vertex once: sorted by place, then vertex.
pub(crate) fn coincident_runs(used: &mut [(Point3, u32, u32)]) -> Vec<Problem> {
    used.par_sort_unstable_by(|a, b| crate::geom::lex_cmp(&a.0, &b.0).then(a.1.cmp(&b.1)));
    let mut problems = Vec::new();
    let mut run_start = 0;
    for k in 1..used.len() {
        let ((pa, a, ta), (pb, b, tb)) = (used[run_start], used[k]);
        if pa != pb {
            run_start = k;
            continue;
        }
        problems.push(Problem::new(
            ProblemKind::CoincidentVertices,
            vec![ta, tb],
            vec![a, b],
            format!(
                "vertices #{a} (of T{ta}) and #{b} (of T{tb}) are both at {pa:?}: the tetrahedra around them are not joined there (a non-conforming assembly)"
            ),
        ));
    }
    problems
}

/// Without a convex domain: local injectivity at every vertex and an embedded boundary.
fn check_embedding(
    points: &[Point3],
    tets: &[[u32; 4]],
    boundary: &[BoundaryFace],
    report: &mut Report,
) {
    let mut on_boundary = vec![false; points.len()];
    for f in boundary {
        f.v.iter().for_each(|&x| on_boundary[x as usize] = true);
    }
    for p in embed::vertex_overlaps(points, tets, &on_boundary, &|_| true) {
        report.push(p);
    }
    let faces: Vec<([u32; 3], u32)> = boundary.iter().map(|f| (f.v, f.tet)).collect();
    for p in embed::boundary_self_intersections(points, &faces) {
        report.push(p);
    }
    let components = embed::boundary_components(&faces);
    if components.len() > 1 {
        for p in embed::nested_overlaps(points, tets, &components) {
            report.push(p);
        }
    }
}

/// Index, repeated-vertex and orientation problems, and the orientation of every
/// tetrahedron (0 when it is degenerate or malformed), computed once for the face pairing.
/// The orientations are computed first and problems only for the tetrahedra whose sign
/// is not +1, so a valid mesh allocates nothing per tetrahedron beyond its sign.
pub(super) fn check_tets(points: &[Point3], tets: &[[u32; 4]]) -> (Vec<Problem>, Vec<i8>) {
    let n = points.len() as u32;
    let malformed = |t: &[u32; 4]| t.iter().any(|&v| v >= n) || repeats(t);
    let signs: Vec<i8> = tets
        .par_iter()
        .map(|t| {
            if malformed(t) {
                return 0;
            }
            let p = |k: usize| &points[t[k] as usize];
            orient3d(p(0), p(1), p(2), p(3))
        })
        .collect();
    let problems = signs
        .par_iter()
        .zip(tets)
        .enumerate()
        .filter(|(_, (s, _))| **s != 1)
        .map(|(i, (&sign, t))| tet_problem(i as u32, t, sign, n))
        .collect();
    (problems, signs)
}

fn repeats(t: &[u32; 4]) -> bool {
    (0..4).any(|a| (a + 1..4).any(|b| t[a] == t[b]))
}

/// What is wrong with tetrahedron `i` = `t` of orientation `sign` (not +1).
fn tet_problem(i: u32, t: &[u32; 4], sign: i8, n: u32) -> Problem {
    if let Some(&v) = t.iter().find(|&&v| v >= n) {
        let d = format!("tetrahedron T{i} names vertex #{v}, but there are {n} points");
        return Problem::new(ProblemKind::BadIndex, vec![i], vec![v], d);
    }
    if repeats(t) {
        let d = format!("tetrahedron T{i} repeats a vertex: {}", ids(t));
        return Problem::new(ProblemKind::RepeatedVertex, vec![i], t.to_vec(), d);
    }
    let (kind, what) = if sign == 0 {
        (
            ProblemKind::Degenerate,
            "has its four vertices in one plane",
        )
    } else {
        (ProblemKind::Inverted, "is negatively oriented")
    };
    let d = format!("tetrahedron T{i} {} {what}", ids(t));
    Problem::new(kind, vec![i], t.to_vec(), d)
}

/// A boundary face, oriented outward, with its tetrahedron.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BoundaryFace {
    /// The face's vertices, outward (counterclockwise seen from outside).
    pub(crate) v: [u32; 3],
    /// The tetrahedron it is a face of.
    pub(crate) tet: u32,
}

/// Sorts a triangle's vertices, returning them and whether the sort was an odd permutation.
fn sort3(mut f: [u32; 3]) -> ([u32; 3], bool) {
    let mut odd = false;
    for (i, j) in [(0, 1), (1, 2), (0, 1)] {
        if f[i] > f[j] {
            f.swap(i, j);
            odd = !odd;
        }
    }
    (f, odd)
}

/// The outward faces of a tetrahedron taken as positively oriented.
fn outward_faces(t: [u32; 4]) -> [[u32; 3]; 4] {
    let [a, b, c, d] = t;
    [[b, c, d], [a, d, c], [a, b, d], [a, c, b]]
}

/// Pairs the faces of the tetrahedra with orientation `signs` (degenerate ones skipped).
pub(super) fn pair_faces(
    n: usize,
    tets: &[[u32; 4]],
    signs: &[i8],
    wanted: Option<&[bool]>,
) -> (Vec<BoundaryFace>, Vec<Problem>) {
    let (start, mut recs) = bucket_faces(tets, signs, n, wanted);
    // One pair of vectors per run of buckets, not per bucket (a thousand allocations at
    // 10^3 vertices); in order, as the buckets.
    let results: Vec<(Vec<BoundaryFace>, Vec<Problem>)> = split_at_offsets(&mut recs, &start)
        .into_par_iter()
        .enumerate()
        .fold(Default::default, |(mut b, mut p), (a, c)| {
            pair_bucket(a as u32, c, (&mut b, &mut p));
            (b, p)
        })
        .collect();
    let mut boundary = Vec::new();
    let mut problems = Vec::new();
    for (b, p) in results {
        boundary.extend(b);
        problems.extend(p);
    }
    (boundary, problems)
}

/// Every outward face `(a, b, c)` with `a < b, c` as the record `[b, c, tet << 1 | odd]`
/// (`odd`: the sorted order reverses the orientation) in the bucket of `a` (rows
/// `start[a]..start[a + 1]`). With `wanted`, only the faces with a wanted vertex.
fn bucket_faces(
    tets: &[[u32; 4]],
    signs: &[i8],
    n: usize,
    wanted: Option<&[bool]>,
) -> (Vec<usize>, Vec<[u32; 3]>) {
    crate::rows::group(n, tets.len(), |ti| {
        let t = tets[ti];
        // Positively oriented; degenerate and malformed tetrahedra are skipped.
        let t = match signs[ti] {
            1 => t,
            -1 => [t[0], t[1], t[3], t[2]],
            _ => return [(usize::MAX, [0; 3]); 4],
        };
        outward_faces(t).map(|f| {
            if wanted.is_some_and(|w| f.iter().all(|&v| !w[v as usize])) {
                return (usize::MAX, [0; 3]);
            }
            let (s, odd) = sort3(f);
            (s[0] as usize, [s[1], s[2], ((ti as u32) << 1) | odd as u32])
        })
    })
}

/// The faces of bucket `a` (`recs`, as [`bucket_faces`] files them) paired: the unpaired
/// ones pushed on `boundary`, the pairs that are no pair on `problems`.
fn pair_bucket(
    a: u32,
    recs: &mut [[u32; 3]],
    (boundary, problems): (&mut Vec<BoundaryFace>, &mut Vec<Problem>),
) {
    // By the face alone, one integer (the bucket of a vertex of `P` holds most of a
    // shell's faces), then each face's few records by their tetrahedra.
    recs.sort_unstable_by_key(|r| (r[0] as u64) << 32 | r[1] as u64);
    let mut i = 0;
    while i < recs.len() {
        let key = [recs[i][0], recs[i][1]];
        let j = i + recs[i..].iter().take_while(|r| r[..2] == key).count();
        let face = [a, key[0], key[1]];
        recs[i..j].sort_unstable();
        let group = &recs[i..j];
        let tets = || -> Vec<u32> { group.iter().map(|r| r[2] >> 1).collect() };
        match group.len() {
            1 => {
                let odd = group[0][2] & 1 == 1;
                let v = if odd {
                    [face[0], face[2], face[1]]
                } else {
                    face
                };
                boundary.push(BoundaryFace {
                    v,
                    tet: group[0][2] >> 1,
                });
            }
            2 if (group[0][2] ^ group[1][2]) & 1 == 1 => {}
            2 => {
                let tets = tets();
                let detail = format!(
                    "tetrahedra T{} and T{} lie on the same side of their common face {}",
                    tets[0],
                    tets[1],
                    ids(&face)
                );
                problems.push(Problem::new(
                    ProblemKind::SameSide,
                    tets,
                    face.to_vec(),
                    detail,
                ));
            }
            k => {
                let tets = tets();
                let named: Vec<String> = tets.iter().map(|t| format!("T{t}")).collect();
                let detail = format!(
                    "triangle {} is a face of {k} tetrahedra: {}",
                    ids(&face),
                    named.join(", ")
                );
                let kind = ProblemKind::FaceSharedByMore;
                problems.push(Problem::new(kind, tets, face.to_vec(), detail));
            }
        }
        i = j;
    }
}

/// The boundary edges used unequally in the two directions (the boundary is not closed
/// there) and those used equally but more than once each way (non-manifold edges).
///
/// One sort of the edges by their unordered ends, each record marked with its direction
/// (`a < b` or not) and its tetrahedron; a group of equal ends counts both directions.
/// Problems are listed by directed edge, as `(a, b)` ascending.
pub(super) fn check_closed(boundary: &[BoundaryFace]) -> (Vec<Problem>, Vec<Problem>) {
    let mut edges: Vec<(u32, u32, bool, u32)> = boundary
        .par_iter()
        .flat_map_iter(|f| {
            (0..3).map(move |i| {
                let (a, b) = (f.v[i], f.v[(i + 1) % 3]);
                (a.min(b), a.max(b), a > b, f.tet)
            })
        })
        .collect();
    // By the edge alone, one integer, then each edge's few records in full: the same
    // order as one sort of the tuples (here 6000 tuples took 240 µs, 6000 integers 80).
    edges.par_sort_unstable_by_key(|e| (e.0 as u64) << 32 | e.1 as u64);
    let (mut open, mut non_manifold) = (Vec::new(), Vec::new());
    for group in edges.chunk_by_mut(|x, y| (x.0, x.1) == (y.0, y.1)) {
        group.sort_unstable();
        let (lo, hi) = (group[0].0, group[0].1);
        let up = group.partition_point(|e| !e.2);
        let (fw, bw) = (up, group.len() - up);
        if fw != bw {
            let sides = [(lo, hi, fw, bw, 0), (hi, lo, bw, fw, up)];
            for (a, b, fw, bw, first) in sides.into_iter().filter(|s| s.2 > 0) {
                open.push(Problem::new(
                    ProblemKind::OpenBoundary,
                    vec![group[first].3],
                    vec![a, b],
                    format!("boundary edge (#{a}, #{b}) is used {fw} times in one direction and {bw} in the other; the boundary is not a closed surface"),
                ));
            }
        } else if fw > 1 {
            non_manifold.push(Problem::new(
                ProblemKind::NonManifoldEdge,
                vec![group[0].3],
                vec![lo, hi],
                format!("boundary edge (#{lo}, #{hi}) is used by {} boundary faces ({fw} each way): the domain is not a manifold there", 2 * fw),
            ));
        }
    }
    open.sort_by_key(|p| (p.vertices[0], p.vertices[1]));
    (open, non_manifold)
}

pub(super) fn check_hull(
    points: &[Point3],
    tets: &[[u32; 4]],
    boundary: &[BoundaryFace],
    hull: &Hull3,
) -> Vec<Problem> {
    let mut used = vec![false; points.len()];
    for t in tets {
        for &v in t {
            used[v as usize] = true;
        }
    }
    let mut problems: Vec<Problem> = (0..points.len() as u32)
        .filter(|&v| !used[v as usize])
        .map(unused_vertex)
        .collect();
    let unused = !problems.is_empty();
    problems.extend(hull_faces(points, boundary, hull, unused));
    problems
}

/// Point `v` is a vertex of no tetrahedron.
pub(crate) fn unused_vertex(v: u32) -> Problem {
    let d = format!("point #{v} is not a vertex of any tetrahedron");
    Problem::new(ProblemKind::UnusedVertex, vec![], vec![v], d)
}

/// The boundary faces not on the hull, and, when all are and nothing else is wrong
/// (`wrong` false), those overlapping the first one on its facet.
pub(crate) fn hull_faces(
    points: &[Point3],
    boundary: &[BoundaryFace],
    hull: &Hull3,
    wrong: bool,
) -> Vec<Problem> {
    let mut problems = Vec::new();
    let facets: Vec<Option<u32>> = boundary
        .iter()
        .map(|f| hull.common_facet(f.v[0] as usize, f.v[1] as usize, f.v[2] as usize))
        .collect();
    for (f, facet) in boundary.iter().zip(&facets) {
        if facet.is_none() {
            problems.push(Problem::new(
                ProblemKind::BoundaryNotOnHull,
                vec![f.tet],
                f.v.to_vec(),
                format!("face {} of tetrahedron T{} has no neighbour across it but is not on the convex hull", ids(&f.v), f.tet),
            ));
        }
    }
    if wrong || !problems.is_empty() || boundary.is_empty() {
        return problems;
    }
    // Covering degree: boundary faces over one facet must not overlap the first one.
    let f0 = &boundary[0];
    let tri = |f: &BoundaryFace| f.v.map(|i| points[i as usize]);
    for (g, facet) in boundary.iter().zip(&facets).skip(1) {
        if *facet == facets[0] && coplanar_triangles_overlap(&tri(f0), &tri(g)) {
            problems.push(Problem::new(
                ProblemKind::Overlap,
                vec![f0.tet, g.tet],
                f0.v.iter().chain(&g.v).copied().collect(),
                format!(
                    "boundary faces {} and {} overlap on the hull, so tetrahedra T{} and T{} overlap",
                    ids(&f0.v),
                    ids(&g.v),
                    f0.tet,
                    g.tet
                ),
            ));
        }
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two triangles sharing edge (0, 1) the same way round, and a third using it the
    /// other way: every other edge is open once, listed by directed edge with the
    /// tetrahedron of its face, and (0, 1) counts 2 against 1.
    #[test]
    fn open_edges_are_listed_by_directed_edge_with_their_counts() {
        let face = |v: [u32; 3], tet| BoundaryFace { v, tet };
        let boundary = [face([0, 1, 2], 7), face([0, 1, 3], 5), face([1, 0, 4], 9)];
        let (open, non_manifold) = check_closed(&boundary);
        assert!(non_manifold.is_empty());
        let edges: Vec<(u32, u32, u32)> = open
            .iter()
            .map(|p| (p.vertices[0], p.vertices[1], p.cells[0]))
            .collect();
        let expected = [
            (0, 1, 5),
            (0, 4, 9),
            (1, 0, 9),
            (1, 2, 7),
            (1, 3, 5),
            (2, 0, 7),
            (3, 0, 5),
            (4, 1, 9),
        ];
        assert_eq!(edges, expected);
        assert!(
            open[0]
                .detail
                .contains("used 2 times in one direction and 1")
        );
        assert!(
            open[2]
                .detail
                .contains("used 1 times in one direction and 2")
        );
    }

    /// Boxes touching along an edge form a valid mesh of a non-manifold domain, like
    /// boxes touching at a corner; the edge is named as non-manifold, and refused only
    /// when a manifold boundary is required.
    #[test]
    fn non_manifold_edges_are_valid_and_named() {
        let edge = crate::generate::two_cubes([1.0, 1.0, 0.0]);
        assert_eq!(edge.points.len(), 14);
        let r = verify(&edge.points, &edge.tets, None);
        assert!(r.is_valid(), "{:?}", r.problems);
        assert_eq!(r.non_manifold.len(), 1);
        assert_eq!(r.non_manifold[0].kind, ProblemKind::NonManifoldEdge);
        let strict = r.require_manifold();
        assert!(!strict.is_valid());
        let corner = crate::generate::two_cubes([1.0, 1.0, 1.0]);
        let r = verify(&corner.points, &corner.tets, None);
        assert!(
            r.is_valid() && r.non_manifold.is_empty(),
            "{:?}",
            r.problems
        );
        // Overlapping boxes sharing that edge are still refused.
        let overlap = crate::generate::two_cubes([0.5, 0.5, 0.0]);
        assert!(!verify(&overlap.points, &overlap.tets, None).is_valid());
    }

    fn cube() -> (Vec<Point3>, Vec<[u32; 4]>) {
        // Kuhn subdivision of the unit cube into 6 tetrahedra around the diagonal 0–7.
        let pts: Vec<Point3> = (0..8)
            .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64])
            .collect();
        let mut tets = vec![
            [0, 1, 3, 7],
            [0, 1, 5, 7],
            [0, 2, 3, 7],
            [0, 2, 6, 7],
            [0, 4, 5, 7],
            [0, 4, 6, 7],
        ];
        for t in &mut tets {
            let p = |k: usize| &pts[t[k] as usize];
            if orient3d(p(0), p(1), p(2), p(3)) < 0 {
                t.swap(2, 3);
            }
        }
        (pts, tets)
    }

    #[test]
    fn kuhn_cube_is_valid() {
        let (pts, tets) = cube();
        let r = verify(&pts, &tets, Some(&Hull3::new(&pts)));
        assert!(r.is_valid(), "{:?}", r.problems);
        assert_eq!(r.boundary_faces, 12);
    }

    #[test]
    fn missing_tet_is_caught() {
        let (pts, mut tets) = cube();
        tets.pop();
        let r = verify(&pts, &tets, Some(&Hull3::new(&pts)));
        assert!(
            r.problems
                .iter()
                .any(|p| p.kind == ProblemKind::BoundaryNotOnHull)
        );
    }

    #[test]
    fn doubled_mesh_is_caught_by_degree() {
        // The cube tetrahedralized twice in two different ways: every face pairs up
        // locally, boundary lies on the hull, but the covering has degree 2.
        let (pts, tets) = cube();
        let mut both = tets.clone();
        // The other Kuhn subdivision around the diagonal 1–6.
        let mut other: Vec<[u32; 4]> = vec![
            [1, 0, 2, 6],
            [1, 0, 4, 6],
            [1, 3, 2, 6],
            [1, 3, 7, 6],
            [1, 5, 4, 6],
            [1, 5, 7, 6],
        ];
        for t in &mut other {
            let p = |k: usize| &pts[t[k] as usize];
            if orient3d(p(0), p(1), p(2), p(3)) < 0 {
                t.swap(2, 3);
            }
        }
        both.extend(other);
        let r = verify(&pts, &both, Some(&Hull3::new(&pts)));
        assert!(!r.is_valid());
    }

    #[test]
    fn extra_overlapping_tet_is_caught() {
        let (pts, mut tets) = cube();
        tets.push([1, 2, 4, 7]);
        let r = verify(&pts, &tets, Some(&Hull3::new(&pts)));
        assert!(!r.is_valid());
        let r = verify(&pts, &tets, None);
        assert!(
            !r.is_valid(),
            "local checks alone catch a tet sharing faces"
        );
    }

    /// Face pairing names both tetrahedra on one side of a face, and every tetrahedron of
    /// a face shared by three; one tetrahedron has four boundary faces.
    #[test]
    fn face_pairing_problems_name_their_tetrahedra() {
        let pts = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.2, 0.2, 2.0],
            [0.2, 0.2, -1.0],
        ];
        let run = |tets: &[[u32; 4]]| {
            let mut t = crate::mesh::Tetrahedralization {
                points: pts.clone(),
                tets: tets.to_vec(),
            };
            t.orient_positively();
            verify(&t.points, &t.tets, None)
        };
        let of_kind = |r: &Report, kind| -> Vec<(Vec<u32>, Vec<u32>)> {
            r.problems
                .iter()
                .filter(|p| p.kind == kind)
                .map(|p| (p.cells.clone(), p.vertices.clone()))
                .collect()
        };
        let r = run(&[[0, 1, 2, 3]]);
        assert!(r.is_valid() && r.boundary_faces == 4);
        let r = run(&[[0, 1, 2, 3], [0, 1, 2, 4]]);
        let same = of_kind(&r, ProblemKind::SameSide);
        assert_eq!(same, vec![(vec![0, 1], vec![0, 1, 2])], "{:?}", r.problems);
        let r = run(&[[0, 1, 2, 3], [0, 1, 2, 4], [0, 1, 2, 5]]);
        let shared = of_kind(&r, ProblemKind::FaceSharedByMore);
        assert_eq!(
            shared,
            vec![(vec![0, 1, 2], vec![0, 1, 2])],
            "{:?}",
            r.problems
        );
    }

    fn kinds(r: &Report) -> Vec<ProblemKind> {
        r.problems.iter().map(|p| p.kind).collect()
    }

    #[test]
    fn non_convex_mesh_is_valid_without_hull() {
        // Kuhn 2x2x2 grid with the column of cubes at (1, 1, *) removed: an L-shaped prism.
        let t = crate::generate::kuhn(2);
        let tets: Vec<[u32; 4]> = t
            .tets
            .iter()
            .enumerate()
            .filter(|(i, _)| (i / 6) / 2 != 3)
            .map(|(_, x)| *x)
            .collect();
        let used: Vec<Point3> = t.points.clone();
        let r = verify(&used, &tets, None);
        assert!(r.is_valid(), "{:?}", r.problems);
        assert!(!verify(&used, &tets, Some(&Hull3::new(&used))).is_valid());
    }

    #[test]
    fn extra_tet_with_new_faces_is_an_overlap() {
        let t = crate::generate::kuhn(3);
        let mut tets = t.tets.clone();
        // Interior corners (1,1,2), (1,2,1), (2,1,1), (2,2,1) of the middle cube: no face of
        // the extra tetrahedron is a Kuhn face or touches the boundary.
        let mut extra = [22, 25, 37, 41];
        let p = |i: u32| &t.points[i as usize];
        if orient3d(p(extra[0]), p(extra[1]), p(extra[2]), p(extra[3])) < 0 {
            extra.swap(2, 3);
        }
        tets.push(extra);
        let r = verify(&t.points, &tets, None);
        assert!(
            kinds(&r).contains(&ProblemKind::Overlap),
            "{:?}",
            r.problems
        );
        assert!(
            r.problems
                .iter()
                .any(|p| p.cells.contains(&(tets.len() as u32 - 1)))
        );
    }

    #[test]
    fn interpenetrating_pieces_have_a_self_intersecting_boundary() {
        let (pts, tets) = cube();
        let mut all_pts = pts.clone();
        all_pts.extend(pts.iter().map(|p| [p[0] + 0.5, p[1] + 0.25, p[2] + 0.125]));
        let mut all = tets.clone();
        all.extend(tets.iter().map(|t| t.map(|v| v + 8)));
        let r = verify(&all_pts, &all, None);
        assert!(
            kinds(&r).contains(&ProblemKind::BoundarySelfIntersection),
            "{:?}",
            r.problems
        );
        // Disjoint pieces are fine but noted.
        let far: Vec<Point3> = pts
            .iter()
            .chain(
                pts.iter()
                    .map(|p| [p[0] + 5.0, p[1], p[2]])
                    .collect::<Vec<_>>()
                    .iter(),
            )
            .copied()
            .collect();
        let r = verify(&far, &all, None);
        assert!(r.is_valid(), "{:?}", r.problems);
    }

    /// A 3x3x3 Kuhn block without its middle cube (a closed cavity), plus a small cube
    /// of 6 tetrahedra: valid inside the cavity, an overlap inside the solid (no
    /// boundary faces meet and every vertex star is fine, so only the nesting test
    /// sees it).
    #[test]
    fn nested_pieces_are_checked() {
        let block = crate::generate::kuhn(3);
        let p = |i: u32| block.points[i as usize];
        let middle = |t: &[u32; 4]| {
            t.iter().all(|&v| {
                (1.0..=2.0).contains(&p(v)[0])
                    && (1.0..=2.0).contains(&p(v)[1])
                    && (1.0..=2.0).contains(&p(v)[2])
            })
        };
        let shell: Vec<[u32; 4]> = block.tets.iter().copied().filter(|t| !middle(t)).collect();
        assert_eq!(shell.len(), block.tets.len() - 6);
        let (small, small_tets) = cube();
        let with_piece = |offset: f64| {
            let mut pts = block.points.clone();
            let base = pts.len() as u32;
            pts.extend(small.iter().map(|q| q.map(|c| offset + 0.5 * c)));
            let mut tets = shell.clone();
            tets.extend(small_tets.iter().map(|t| t.map(|v| v + base)));
            verify(&pts, &tets, None)
        };
        let r = with_piece(1.25);
        assert!(r.is_valid(), "{:?}", r.problems);
        let r = with_piece(0.25);
        assert!(
            kinds(&r).contains(&ProblemKind::Overlap),
            "{:?}",
            r.problems
        );
        assert!(r.problems.iter().all(|q| q.kind == ProblemKind::Overlap));
    }

    #[test]
    fn inverted_and_degenerate() {
        let (pts, mut tets) = cube();
        tets[0].swap(0, 1);
        tets.push([0, 1, 2, 3]);
        let r = verify(&pts, &tets, None);
        let kinds: Vec<_> = r.problems.iter().map(|p| p.kind).collect();
        assert!(kinds.contains(&ProblemKind::Inverted));
        assert!(kinds.contains(&ProblemKind::Degenerate));
    }
}
