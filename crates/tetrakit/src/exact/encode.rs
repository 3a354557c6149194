//! Candidate tetrahedra and the CNF of "these candidates form a tetrahedralization".

use crate::control::Control;
use crate::geom::{
    Hull3, Point3, orient3d, point_in_closed_tetrahedron, segment_meets_tet_improperly,
    segment_punctures_triangle, segments_meet, triangle_meets_tet,
};
use crate::mesh::Polyhedron;
use std::collections::HashMap;

/// The domain to tetrahedralize.
#[derive(Clone, Copy, Debug)]
pub enum Domain<'a> {
    /// A simple polyhedron, with its vertices only.
    Polyhedron(&'a Polyhedron),
    /// The convex hull of a point set, using every point (a *fine* triangulation).
    Points(&'a [Point3]),
    /// The region between two nested convex polytopes `P ⊇ Q` (they may touch): `P` the
    /// hull of `points`, `Q` the hull of `points[inner]`. A polygon facet of `Q` may be
    /// triangulated in any way; so may one of `P` unless `outer_faces` fixes the
    /// triangles of `∂P` (each oriented outward, as a removal's surface is fixed by the
    /// tetrahedra already made).
    Shell {
        /// The vertices of `P` and `Q` (no other points).
        points: &'a [Point3],
        /// The vertices of `Q`.
        inner: &'a [u32],
        /// The triangles of `∂P`, when they are fixed.
        outer_faces: Option<&'a [[u32; 3]]>,
    },
}

impl Domain<'_> {
    pub(crate) fn points(&self) -> &[Point3] {
        match self {
            Domain::Polyhedron(p) => &p.points,
            Domain::Points(p) => p,
            Domain::Shell { points, .. } => points,
        }
    }

    /// The boundary triangles the tetrahedralization must have (none for a point set,
    /// whose hull facets may be triangulated in any way).
    pub(crate) fn faces(&self) -> &[[u32; 3]] {
        match self {
            Domain::Polyhedron(p) => &p.faces,
            Domain::Points(_) => &[],
            Domain::Shell { outer_faces, .. } => outer_faces.unwrap_or(&[]),
        }
    }
}

/// One triangle of some candidate, with the candidates on each side of its plane.
#[derive(Default)]
pub(crate) struct TriangleUse {
    /// Candidates whose fourth vertex is on the positive side of `orient3d(a, b, c, ·)`
    /// for the sorted triple `(a, b, c)`.
    pub(crate) pos: Vec<u32>,
    /// ... on the negative side.
    pub(crate) neg: Vec<u32>,
    /// On the boundary with its triangulation free (used at most once): in a supporting
    /// plane of a point set, or of a shell's `P` when its faces are not fixed, or on a
    /// facet of a shell's `Q`.
    pub(crate) on_hull: bool,
}

/// Candidates and the structure the clauses need.
pub(crate) struct Candidates {
    /// Non-degenerate tetrahedra on the domain's vertices, containing no other vertex.
    pub(crate) tets: Vec<[u32; 4]>,
    /// Every face of a candidate, by sorted triple.
    pub(crate) triangles: HashMap<[u32; 3], TriangleUse>,
    /// Every edge not on the domain's boundary, with the candidates containing it.
    pub(crate) interior_edges: Vec<([u32; 2], Vec<u32>)>,
    /// For each required segment ([`Edges::required`]), the candidates having it as an
    /// edge.
    pub(crate) required: Vec<Vec<u32>>,
    /// The number of tetrahedra is `interior edges used + offset`.
    pub(crate) offset: i64,
}

/// Which edges a tetrahedralization may, or must, have: the TETRAD and CT problems of
/// thesis §2.5–2.6. The default is no restriction.
///
/// ```
/// use tetrakit::exact::Edges;
/// let l = [[0, 1], [0, 2]];
/// let within = Edges { allowed: Some(&l), ..Edges::default() };
/// assert!(within.required.is_empty());
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Edges<'a> {
    /// Only these segments may be edges (TETRAD: the segment set *contains* the edge
    /// set); a candidate tetrahedron has all six edges among them.
    pub allowed: Option<&'a [[u32; 2]]>,
    /// Every one of these segments must be an edge (CT: a constrained
    /// tetrahedralization); a candidate meets none of them other than in shared vertices
    /// or as one of its edges. They must not cross each other nor pass through a vertex
    /// (checked by the caller: such input has no answer to search for).
    pub required: &'a [[u32; 2]],
}

/// More 4-cliques of the allowed edges than the solver takes.
pub(crate) struct TooMany(pub(crate) usize);

/// The largest number of candidate tetrahedra enumerated.
pub const MAX_CANDIDATES: usize = 4_000_000;

/// Enumerates candidates: every 4-subset of vertices, with all six edges allowed, that
/// spans a tetrahedron whose closed set holds no other vertex and meets no required
/// segment improperly; for a polyhedron, also no facet meeting it other than in shared
/// vertices and edges, and the inner side of any facet it has. `None` once `ctl` stops.
pub(crate) fn candidates(
    domain: Domain,
    edges: Edges,
    ctl: &Control,
) -> Result<Option<Candidates>, TooMany> {
    let pts = domain.points();
    let facets: Vec<[u32; 3]> = domain.faces().to_vec();
    let facet_set: HashMap<[u32; 3], [u32; 3]> = facets
        .iter()
        .map(|&f| (crate::mesh::sorted_face(f), f))
        .collect();
    let inner = inner_polytope(domain);
    let cliques = four_cliques(pts.len(), edges.allowed)?;
    let empty = EmptinessIndex::new(pts);
    let mut tets = Vec::new();
    for (k, t) in cliques.into_iter().enumerate() {
        if k % 4096 == 0 && ctl.is_stopped() {
            return Ok(None);
        }
        let geo = t.map(|v| pts[v as usize]);
        if orient3d(&geo[0], &geo[1], &geo[2], &geo[3]) == 0 || !empty.is_empty(&geo) {
            continue;
        }
        if !facets.is_empty() && !fits_polyhedron(pts, &facets, &facet_set, t) {
            continue;
        }
        if inner
            .as_ref()
            .is_some_and(|(q, local)| crosses_inner(q, local, &t, &geo))
        {
            continue;
        }
        if edges.required.iter().any(|&s| {
            segment_meets_tet_improperly(&pts[s[0] as usize], &pts[s[1] as usize], s, &geo, &t)
        }) {
            continue;
        }
        tets.push(t);
    }
    Ok(Some(structure(domain, edges, tets, inner.as_ref())))
}

/// The sorted 4-subsets `a < b < c < d` whose six pairs are all allowed (all of them
/// when `allowed` is `None`), or [`TooMany`].
fn four_cliques(n: usize, allowed: Option<&[[u32; 2]]>) -> Result<Vec<[u32; 4]>, TooMany> {
    // Forward adjacency: the neighbours above each vertex, sorted.
    let up: Vec<Vec<u32>> = match allowed {
        None => (0..n as u32).map(|a| (a + 1..n as u32).collect()).collect(),
        Some(list) => {
            let mut up = vec![Vec::new(); n];
            for &[a, b] in list {
                if a != b {
                    up[a.min(b) as usize].push(a.max(b));
                }
            }
            for l in &mut up {
                l.sort_unstable();
                l.dedup();
            }
            up
        }
    };
    let meet = |x: &[u32], y: &[u32]| -> Vec<u32> {
        x.iter()
            .filter(|v| y.binary_search(v).is_ok())
            .copied()
            .collect()
    };
    let mut out = Vec::new();
    for a in 0..n {
        for &b in &up[a] {
            let ab = meet(&up[a], &up[b as usize]);
            for (i, &c) in ab.iter().enumerate() {
                for &d in &ab[i + 1..] {
                    if up[c as usize].binary_search(&d).is_ok() {
                        out.push([a as u32, b, c, d]);
                        if out.len() > MAX_CANDIDATES {
                            return Err(TooMany(out.len()));
                        }
                    }
                }
            }
        }
    }
    Ok(out)
}

/// The points sorted by x, so that a tetrahedron's emptiness test looks only at those in
/// its bounding box's x-range.
struct EmptinessIndex<'a> {
    pts: &'a [Point3],
    by_x: Vec<u32>,
}

impl<'a> EmptinessIndex<'a> {
    fn new(pts: &'a [Point3]) -> Self {
        let mut by_x: Vec<u32> = (0..pts.len() as u32).collect();
        by_x.sort_by(|&i, &j| pts[i as usize][0].total_cmp(&pts[j as usize][0]));
        EmptinessIndex { pts, by_x }
    }

    /// True when no point other than the corners lies in the closed tetrahedron `geo`.
    fn is_empty(&self, geo: &[Point3; 4]) -> bool {
        let (lo, hi) = crate::geom::bounding_box(geo);
        let x = |i: &u32| self.pts[*i as usize][0];
        let from = self.by_x.partition_point(|i| x(i) < lo[0]);
        let to = self.by_x.partition_point(|i| x(i) <= hi[0]);
        self.by_x[from..to].iter().all(|&i| {
            let p = &self.pts[i as usize];
            (1..3).any(|k| p[k] < lo[k] || p[k] > hi[k]) || !point_in_closed_tetrahedron(p, geo)
        })
    }
}

/// The triangles, edges and Euler offset of the candidates `tets`.
fn structure(
    domain: Domain,
    edges: Edges,
    tets: Vec<[u32; 4]>,
    inner: Option<&(super::separate::Convex, Vec<u32>)>,
) -> Candidates {
    let pts = domain.points();
    let facets = domain.faces();
    let mut triangles: HashMap<[u32; 3], TriangleUse> = HashMap::new();
    let mut holders: HashMap<[u32; 2], Vec<u32>> = HashMap::new();
    for (i, t) in tets.iter().enumerate() {
        for k in 0..4 {
            let mut f = [0u32; 3];
            let mut m = 0;
            for (j, &v) in t.iter().enumerate() {
                if j != k {
                    f[m] = v;
                    m += 1;
                }
            }
            let [x, y, z] = f.map(|v| &pts[v as usize]);
            let side = orient3d(x, y, z, &pts[t[k] as usize]);
            let entry = triangles.entry(f).or_default();
            if side > 0 {
                entry.pos.push(i as u32)
            } else {
                entry.neg.push(i as u32)
            }
        }
        for x in 0..4 {
            for y in x + 1..4 {
                holders.entry([t[x], t[y]]).or_default().push(i as u32);
            }
        }
    }
    // Free boundary triangles, and Euler: t = e_i + offset (see the module docs). A
    // candidate triangle's plane supports the points exactly when its corners share a
    // facet of their hull.
    let free_hull = match domain {
        Domain::Points(_)
        | Domain::Shell {
            outer_faces: None, ..
        } => Some(Hull3::new(pts)),
        _ => None,
    };
    let supporting = |f: &[u32; 3]| {
        free_hull.as_ref().is_some_and(|h| {
            h.common_facet(f[0] as usize, f[1] as usize, f[2] as usize)
                .is_some()
        })
    };
    for (f, usage) in triangles.iter_mut() {
        usage.on_hull = match (domain, inner) {
            (Domain::Points(_), _) => supporting(f),
            (Domain::Shell { outer_faces, .. }, Some((q, local))) => {
                let on_q = f.map(|v| local[v as usize]);
                let on_q = !on_q.contains(&u32::MAX)
                    && q.common_facet(on_q[0] as usize, on_q[1] as usize, on_q[2] as usize)
                        .is_some();
                on_q || (outer_faces.is_none() && supporting(f))
            }
            _ => false,
        };
    }
    let boundary_edges: std::collections::HashSet<[u32; 2]> = triangles
        .iter()
        .filter(|(_, usage)| usage.on_hull)
        .map(|(f, _)| *f)
        .chain(facets.iter().map(|&f| crate::mesh::sorted_face(f)))
        .flat_map(|f| [[f[0], f[1]], [f[0], f[2]], [f[1], f[2]]])
        .collect();
    let offset = euler_offset(domain);
    let required = edges
        .required
        .iter()
        .map(|&[a, b]| {
            holders
                .get(&[a.min(b), a.max(b)])
                .cloned()
                .unwrap_or_default()
        })
        .collect();
    let mut interior_edges: Vec<([u32; 2], Vec<u32>)> = holders
        .into_iter()
        .filter(|(e, _)| !boundary_edges.contains(e))
        .collect();
    interior_edges.sort_unstable();
    Candidates {
        tets,
        triangles,
        interior_edges,
        required,
        offset,
    }
}

/// The number of tetrahedra minus the interior edges used, the same for every
/// tetrahedralization of `domain` (see the module docs); a lower bound for a shell.
pub(crate) fn euler_offset(domain: Domain) -> i64 {
    let pts = domain.points();
    let n = pts.len() as i64;
    match domain {
        // χ = 1 for a ball: t = χ − n + e_b − f_b / 2 + e_i = e_i + n − 3.
        Domain::Polyhedron(_) => n - 3,
        Domain::Points(_) => {
            let hull = Hull3::new(pts);
            let nb = (0..pts.len()).filter(|&i| hull.on_boundary(i)).count();
            2 * nb as i64 - n - 3
        }
        // Lemma 4.9's n − 6 needs simplicial, disjoint polytopes; 1 is always below.
        Domain::Shell { .. } => 1,
    }
}

/// True when the tetrahedron `t` (points `geo`) meets the interior of `Q`: at once when
/// an edge joins two vertices of `Q` on no common facet, else by the separation test.
fn crosses_inner(
    q: &super::separate::Convex,
    local: &[u32],
    t: &[u32; 4],
    geo: &[Point3; 4],
) -> bool {
    let on_q: Vec<usize> = t
        .iter()
        .map(|&v| local[v as usize])
        .filter(|&k| k != u32::MAX)
        .map(|k| k as usize)
        .collect();
    for (i, &a) in on_q.iter().enumerate() {
        if on_q[i + 1..].iter().any(|&b| q.chord(a, b)) {
            return true;
        }
    }
    q.meets_interior(geo)
}

/// A shell's `Q` and, for each point, its index among `Q`'s vertices (`u32::MAX` if
/// not one).
fn inner_polytope(domain: Domain) -> Option<(super::separate::Convex, Vec<u32>)> {
    let Domain::Shell { points, inner, .. } = domain else {
        return None;
    };
    let mut local = vec![u32::MAX; points.len()];
    for (k, &v) in inner.iter().enumerate() {
        local[v as usize] = k as u32;
    }
    let q = inner.iter().map(|&v| points[v as usize]).collect();
    Some((super::separate::Convex::new(q), local))
}

fn fits_polyhedron(
    pts: &[Point3],
    facets: &[[u32; 3]],
    facet_set: &HashMap<[u32; 3], [u32; 3]>,
    t: [u32; 4],
) -> bool {
    let geo = t.map(|v| pts[v as usize]);
    // A face that is a facet must have the fourth vertex on its inner side.
    for (k, apex) in geo.iter().enumerate() {
        let face: Vec<u32> = (0..4).filter(|&j| j != k).map(|j| t[j]).collect();
        if let Some(f) = facet_set.get(&[face[0], face[1], face[2]]) {
            let [x, y, z] = f.map(|v| &pts[v as usize]);
            if orient3d(x, y, z, apex) >= 0 {
                return false;
            }
        }
    }
    !facets.iter().any(|f| {
        let tri = f.map(|v| pts[v as usize]);
        triangle_meets_tet(&tri, *f, &geo, &t)
    })
}

/// The vertex pairs of a polyhedron whose segment meets no facet other than in shared
/// vertices and edges (bounding boxes first, then exact tests). Every edge of a
/// candidate is one, since a candidate meets no facet improperly; so the 4-cliques of
/// these pairs include every candidate, and enumerating them instead of all 4-subsets
/// changes no formula. `None` once `ctl` stops.
pub(crate) fn unobstructed_pairs(
    pts: &[Point3],
    facets: &[[u32; 3]],
    ctl: &Control,
) -> Option<Vec<[u32; 2]>> {
    let boxes: Vec<(Point3, Point3)> = facets
        .iter()
        .map(|f| crate::geom::bounding_box(&f.map(|v| pts[v as usize])))
        .collect();
    let mut out = Vec::new();
    for u in 0..pts.len() as u32 {
        if ctl.is_stopped() {
            return None;
        }
        for v in u + 1..pts.len() as u32 {
            let (p, q) = (&pts[u as usize], &pts[v as usize]);
            let blocked = facets.iter().zip(&boxes).any(|(f, (lo, hi))| {
                let outside = (0..3).any(|k| p[k].max(q[k]) < lo[k] || p[k].min(q[k]) > hi[k]);
                !outside && segment_meets_facet(p, q, [u, v], f, pts)
            });
            if !blocked {
                out.push([u, v]);
            }
        }
    }
    Some(out)
}

/// The pairs among `pairs` whose diametral ball holds at most `m` vertices strictly
/// inside (short, Delaunay-like segments: every Gabriel edge has `m = 0`), with every
/// facet edge, sorted. The balls are measured in floating point: this only chooses which
/// candidates to try first and decides nothing.
pub(crate) fn short_pairs(
    pts: &[Point3],
    pairs: &[[u32; 2]],
    facets: &[[u32; 3]],
    m: usize,
) -> Vec<[u32; 2]> {
    let d2 = |x: &Point3, c: &Point3| -> f64 { (0..3).map(|i| (x[i] - c[i]).powi(2)).sum() };
    let mut out: Vec<[u32; 2]> = pairs
        .iter()
        .filter(|&&[a, b]| {
            let (p, q) = (&pts[a as usize], &pts[b as usize]);
            let c = [0, 1, 2].map(|i| (p[i] + q[i]) / 2.0);
            let r2 = d2(p, &c);
            pts.iter().filter(|x| d2(x, &c) < r2).take(m + 1).count() <= m
        })
        .copied()
        .collect();
    for f in facets {
        out.extend((0..3).map(|i| {
            let (a, b) = (f[i], f[(i + 1) % 3]);
            [a.min(b), a.max(b)]
        }));
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// Whether segment `pq` (vertices `s`) meets facet `f` beyond their shared vertices and
/// edge: through its interior, or across, along or onto one of its edges.
fn segment_meets_facet(p: &Point3, q: &Point3, s: [u32; 2], f: &[u32; 3], pts: &[Point3]) -> bool {
    if f.contains(&s[0]) && f.contains(&s[1]) {
        return false; // an edge of the facet
    }
    let [a, b, c] = f.map(|v| &pts[v as usize]);
    segment_punctures_triangle(p, q, a, b, c)
        || (0..3).any(|i| {
            let (x, y) = (&pts[f[i] as usize], &pts[f[(i + 1) % 3] as usize]);
            segments_meet(p, q, x, y).is_some()
        })
}

/// A point strictly inside some candidate and on no candidate triangle
/// ([`geom::anchor`](crate::geom::anchor)): the candidates containing it.
pub(crate) fn anchor(pts: &[Point3], c: &Candidates) -> Option<Vec<u32>> {
    let triangles: Vec<[u32; 3]> = c.triangles.keys().copied().collect();
    crate::geom::anchor(pts, &c.tets, &triangles)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::polyhedra::hard;

    /// Restricting a polyhedron's candidates to the 4-cliques of its unobstructed pairs
    /// keeps every candidate: the same set as over all 4-subsets, on dented polyhedra,
    /// Chazelle's and Schönhardt towers.
    #[test]
    fn unobstructed_pairs_keep_every_candidate() {
        let mut polys: Vec<Polyhedron> = (0..12)
            .map(|s| hard::perturbed(10 + s as usize, 0.2 + 0.06 * s as f64, s).unwrap())
            .collect();
        polys.push(hard::chazelle(2).unwrap());
        polys.push(hard::schonhardt_tower(4, 10.0).unwrap());
        polys.push(hard::schonhardt_tower(3, -20.0).unwrap());
        let ctl = Control::new();
        let mut pruned = 0;
        for (k, p) in polys.iter().enumerate() {
            let d = Domain::Polyhedron(p);
            let pairs = unobstructed_pairs(&p.points, &p.faces, &ctl).unwrap();
            let all = candidates(d, Edges::default(), &ctl)
                .ok()
                .flatten()
                .unwrap();
            let restricted = Edges {
                allowed: Some(&pairs),
                ..Edges::default()
            };
            let some = candidates(d, restricted, &ctl).ok().flatten().unwrap();
            assert_eq!(all.tets, some.tets, "polyhedron {k}");
            pruned += p.points.len() * (p.points.len() - 1) / 2 - pairs.len();
        }
        assert!(pruned > 100, "{pruned} pairs pruned");
    }
}
