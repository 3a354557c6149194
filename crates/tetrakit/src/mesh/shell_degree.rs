//! The covering degree of a shell's tetrahedra, pinned without a vertex-by-vertex overlap
//! test ([`certify_shell`](super::certify_shell), thesis ch. 4).
//!
//! Let `N(x)` count the tetrahedra containing a generic point `x`. Orientation and face
//! pairing make `N` constant away from the boundary triangles, and the boundary triangles
//! lie in `∂P ∪ ∂Q` (outer ones facing out of `P`, inner ones facing into `Q`). So
//! `N = 0` outside `P`, `N = d_Q` on `int(Q)`, and `N = d_C` on each connected component
//! `C` of `int(P) − Q` (there may be several: a cube around the tetrahedron on four of its
//! corners leaves four). Every tetrahedron is positive, so all degrees are `≥ 0`.
//!
//! **Components of `int(P) − Q` are components of `∂P − Q`.** From a point `o` inside `Q`
//! every ray leaves `Q` once and then stays outside it until it meets `∂P`, so the part
//! of each ray in `int(P) − Q` is one segment. Projecting from `o` therefore maps each
//! component `C` onto an open connected set of `∂P − Q`, different components onto
//! disjoint sets, and all of them together onto `∂P − Q`: the components of the two
//! sets correspond, and just inside a generic point `x` of `∂P − Q` lies the `C` of its
//! component. There `d_C` is the number of outer triangles covering `x`.
//!
//! **Every component `K` of `∂P − Q` holds a corner of `P`.** A point `x ∈ K` is outside
//! the convex `Q`, so a plane separates them; the part of `∂P` on `x`'s side is connected,
//! misses `Q`, and holds the corner of `P` farthest on that side.
//!
//! **Corners joined by a hull triangle's edge in a facet that misses `Q` lie in one
//! component**: the edge lies in that facet, so in `∂P − Q`. A facet `F` meets `Q` in a face
//! of `Q` (the plane of `F` supports both), which holds a vertex of `Q`: `F` misses `Q`
//! unless one of the points spanning `Q` lies on it. Classes that are one component
//! split are only checked more than once.
//!
//! **One corner per class decides its component.** Near a corner `a` of `P` outside `Q`,
//! only triangles with a vertex at `a` cover `∂P` (no inner triangle comes near: they lie
//! in `Q`). If one outer triangle `f₀` at `a` overlaps no other triangle at `a` on its
//! facet, points of `f₀` near `a` are covered once, so `d_C = 1`; if no outer triangle has
//! `a` as a vertex, `d_C = 0` and the check fails.
//!
//! **Then `d_Q = 0`.** Take an inner triangle `f` that is not in a facet of `P`: a generic
//! point `x` of it lies on `∂Q` inside `P`, with some component `C` just outside `Q`.
//! Crossing from `C` into `Q` at `x` goes through the inner triangles over `x`, each
//! facing into `Q`, so `d_Q = d_C − (their number) ≤ 1 − 1 = 0`. With no component at all
//! (`Q = P`) there must be no tetrahedron. Without such an `f` the check fails: when
//! `Q ≠ P`, part of `∂Q` lies inside `P`, and a shell mesh covers it by inner triangles.
//!
//! So `N` is 1 on `P − Q` and 0 elsewhere: the tetrahedra have disjoint interiors and fill
//! the shell (their volumes add up to `vol(P) − vol(Q)`), the boundary triangles tile `∂P`
//! and `∂Q`, and face pairing excludes hanging vertices, as for a convex hull
//! ([`verify`](super::verify)). The cost is linear: hashing, one pass over the hull's
//! triangles, and one triangle fan per class of corners.

use super::report::{Problem, ProblemKind};
use crate::geom::{Hull3, Point3, coplanar_triangles_overlap, point_key};
use crate::partition;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

/// An outer boundary triangle: its vertices (outward) and the facet of `P` it lies in.
#[derive(Clone, Copy, Debug)]
pub(super) struct OuterFace {
    pub(super) v: [u32; 3],
    pub(super) facet: u32,
    pub(super) tet: u32,
}

/// The vertex used by the tetrahedra at each point, or the first two used vertices at
/// one point: a tetrahedralization's vertices are distinct points.
pub(super) fn used_vertices(
    points: &[Point3],
    tets: &[[u32; 4]],
) -> Result<HashMap<[u64; 3], u32>, Problem> {
    let mut used = vec![false; points.len()];
    for &v in tets.iter().flatten() {
        used[v as usize] = true;
    }
    let mut at = HashMap::with_capacity_and_hasher(points.len(), Default::default());
    for v in (0..points.len() as u32).filter(|&v| used[v as usize]) {
        if let Some(&w) = at.get(&point_key(&points[v as usize])) {
            return Err(Problem::new(
                ProblemKind::RepeatedVertex,
                Vec::new(),
                vec![w, v],
                format!("vertices #{w} and #{v} are the same point"),
            ));
        }
        at.insert(point_key(&points[v as usize]), v);
    }
    Ok(at)
}

/// Checks `d_C = 1` on every component `C` of `int(P) − Q` (module docs) and returns the
/// number of classes of corners checked (0 when `Q = P`). `outer` is the hull of all
/// `points` (that is, `P`), `inner` the points spanning `Q` and `in_q` their keys, `used`
/// the map of [`used_vertices`].
pub(super) fn check_outer_degree(
    points: &[Point3],
    outer: &Hull3,
    inner: &[u32],
    in_q: &HashSet<[u64; 3]>,
    used: &HashMap<[u64; 3], u32>,
    faces: &[OuterFace],
) -> Result<usize, Problem> {
    let is_in_q = |i: u32| in_q.contains(&point_key(&points[i as usize]));
    // The corners of P outside Q, by the vertex the tetrahedra use there.
    let mut corner_id: HashMap<u32, u32> = HashMap::default();
    let mut corners: Vec<u32> = Vec::new();
    let mut unused: Option<u32> = None;
    for i in 0..points.len() as u32 {
        if outer.facets_of(i as usize).len() < 3 || is_in_q(i) {
            continue;
        }
        let Some(&v) = used.get(&point_key(&points[i as usize])) else {
            unused = unused.or(Some(i));
            continue;
        };
        corner_id.entry(v).or_insert_with(|| {
            corners.push(v);
            corners.len() as u32 - 1
        });
    }
    // Join corners along hull edges in facets that Q does not touch.
    let mut touched = vec![false; outer.facet_count()];
    for &f in inner.iter().flat_map(|&i| outer.facets_of(i as usize)) {
        touched[f as usize] = true;
    }
    let mut parent = partition::singletons(corners.len());
    for (t, &f) in outer.triangles.iter().zip(&outer.triangle_facet) {
        if touched[f as usize] {
            continue;
        }
        let id = |i: u32| {
            let v = used.get(&point_key(&points[i as usize]))?;
            corner_id.get(v).copied()
        };
        for k in 0..3 {
            if let (Some(a), Some(b)) = (id(t[k]), id(t[(k + 1) % 3])) {
                partition::union(&mut parent, a, b);
            }
        }
    }
    // One representative corner per class, and the outer triangles at it.
    let mut fan: HashMap<u32, Vec<usize>> = HashMap::default();
    for k in 0..corners.len() as u32 {
        if partition::find(&mut parent, k) == k {
            fan.insert(corners[k as usize], Vec::new());
        }
    }
    for (k, f) in faces.iter().enumerate() {
        for v in f.v {
            if let Some(list) = fan.get_mut(&v) {
                list.push(k);
            }
        }
    }
    let mut reps: Vec<(&u32, &Vec<usize>)> = fan.iter().collect();
    reps.sort_unstable();
    for &(&a, list) in &reps {
        check_fan(points, faces, a, list)?;
    }
    unused.map_or(Ok(reps.len()), |i| Err(uncovered(i)))
}

/// Checks `d_Q = 0` (module docs): with `classes` components outside `Q`, some inner
/// triangle off `∂P` (`off_p`); with none, no tetrahedron.
pub(super) fn check_inner_degree(classes: usize, tets: usize, off_p: bool) -> Result<(), Problem> {
    let detail = match (classes, tets, off_p) {
        (0, 0, _) | (1.., _, true) => return Ok(()),
        (0, _, _) => "the inner hull is the outer one, yet there are tetrahedra",
        _ => {
            "no boundary triangle lies on the inner hull inside the outer one: the tetrahedra cover the inner hull too"
        }
    };
    Err(Problem::new(
        ProblemKind::BoundaryNotSurface,
        Vec::new(),
        Vec::new(),
        detail.to_string(),
    ))
}

/// The outer triangles at corner `a` cover the points of the first one near `a` once.
fn check_fan(points: &[Point3], faces: &[OuterFace], a: u32, fan: &[usize]) -> Result<(), Problem> {
    let Some((&first, rest)) = fan.split_first() else {
        return Err(uncovered(a));
    };
    let f0 = &faces[first];
    let tri = |f: &OuterFace| f.v.map(|i| points[i as usize]);
    for g in rest.iter().map(|&k| &faces[k]) {
        if g.facet == f0.facet && coplanar_triangles_overlap(&tri(f0), &tri(g)) {
            return Err(Problem::new(
                ProblemKind::Overlap,
                vec![f0.tet, g.tet],
                f0.v.iter().chain(&g.v).copied().collect(),
                format!(
                    "boundary faces {} and {} overlap on the outer hull at its corner #{a}, so tetrahedra T{} and T{} overlap",
                    crate::numbering::ids(&f0.v),
                    crate::numbering::ids(&g.v),
                    f0.tet,
                    g.tet
                ),
            ));
        }
    }
    Ok(())
}

fn uncovered(a: u32) -> Problem {
    Problem::new(
        ProblemKind::BoundaryNotSurface,
        Vec::new(),
        vec![a],
        format!(
            "corner #{a} of the outer hull lies outside the inner one but is a vertex of no outer boundary triangle"
        ),
    )
}
