//! Q's facet edges on the current surface: where `Q` touches `P̄` in a facet (Q's facet
//! inside a facet of `P`, or inside a flat facet of the bottom a removal leaves), the
//! triangulation of that facet must have Q's edges, so that Q's facet is a union of its
//! triangles and no tetrahedron is ever built on a triangle reaching into `Q`.
//!
//! On `P` itself, at the start, each facet holding vertices or edges of `Q` is
//! triangulated with Q's edges as constraints ([`QEdges::facet_triangles`]). In a flat
//! bottom a removal leaves, each missing edge `ab` is recovered by 2-2 flips inside the
//! planar facet that holds both ends (Sloan's edge insertion, exact): an edge of the facet's triangulation that
//! `ab` crosses is flipped when its quadrilateral is strictly convex, preferring flips
//! whose new diagonal no longer crosses `ab`. One crossing edge is always flippable, and
//! no vertex lies inside `ab` (a vertex of `P` or `Q` inside an edge of `Q` would not be
//! a corner), so the edge appears; the wall edges of a removal's region are never
//! flipped, and an edge that cannot be recovered refuses the removal (the error is
//! the reason, which the surface reports).

use crate::geom::{
    Hull3, Point3, bounding_box, drop_axis, orient2d_drop, orient3d, projection_axis,
};
use rustc_hash::FxHashMap as HashMap;
use spade::{ConstrainedDelaunayTriangulation, Triangulation};

/// Q's edges, each both ways, sorted: `(v, w)` for every `w` joined to `v` by an edge of
/// `Q` (one sorted list, not a vector per vertex: read off a hull of 10^3 corners
/// without a thousand allocations).
#[derive(Clone, Debug, Default)]
pub(super) struct QEdges {
    edges: Vec<(u32, u32)>,
}

impl QEdges {
    /// The edges of the polytope `Q` from `hull`, the hull of its input points:
    /// `corner(i)` is the shell index of input point `i` when it is a corner of `Q` (a
    /// repeat of a corner included), `None` otherwise. A polytope edge is the line where
    /// two facets meet; the hull's triangles may have points inside it as corners, so each
    /// edge is followed from a corner through those to the corner at its other end.
    pub(super) fn from_hull(hull: &Hull3, corner: impl Fn(u32) -> Option<u32>) -> QEdges {
        // The triangle edges between two facets, both ways, by input point, sorted.
        let mut along: Vec<(u32, u32)> = Vec::new();
        for (t, tri) in hull.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let f = |t: usize| hull.triangle_facet[t];
                if a < b && f(hull.neighbour(t, k)) != f(t) {
                    along.extend([(a, b), (b, a)]);
                }
            }
        }
        super::sort_pairs(&mut along);
        let mut edges = Vec::with_capacity(along.len());
        for run in along.chunk_by(|x, y| x.0 == y.0) {
            let Some(sa) = corner(run[0].0) else { continue };
            for &(a, first) in run {
                if let Some(sb) = edge_end(&along, &corner, a, first) {
                    edges.push((sa, sb));
                }
            }
        }
        super::sort_pairs(&mut edges);
        QEdges { edges }
    }

    /// The same edges with vertex `v` named `name(v)`.
    pub(super) fn renamed(mut self, name: impl Fn(u32) -> u32) -> QEdges {
        for e in &mut self.edges {
            *e = (name(e.0), name(e.1));
        }
        super::sort_pairs(&mut self.edges);
        self
    }

    /// The vertices joined to `v` by an edge of `Q`, sorted.
    fn at(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        super::with_key(&self.edges, v).iter().map(|e| e.1)
    }

    /// Recovers in `tris` every edge of `Q` whose ends are both among `corners` (sorted
    /// corners of `tris`: those where an edge may be missing) and lie in the plane of
    /// one of its facets, keeping `edge` (`tris`'s [`Edges`]) up to date; `walls`
    /// (sorted) are never flipped.
    pub(super) fn recover(
        &self,
        pts: &[Point3],
        (tris, edge): (&mut [[u32; 3]], &mut Edges),
        walls: &[(u32, u32)],
        corners: &[u32],
    ) -> Result<(), &'static str> {
        if self.edges.is_empty() {
            return Ok(());
        }
        let here = |w: &u32| corners.binary_search(w).is_ok();
        let mut wanted: Vec<(u32, u32)> = (corners.iter())
            .flat_map(|&v| self.at(v).map(move |w| (v, w)))
            .filter(|&(v, w)| v < w && here(&w))
            .collect();
        // Most bottoms have every such edge already (or none): no mesh to build.
        let has = |(a, b): (u32, u32)| edge.contains_key(&(a, b)) || edge.contains_key(&(b, a));
        if wanted.iter().all(|&e| has(e)) {
            return Ok(());
        }
        wanted.sort_unstable();
        let mut mesh = Mesh::new(tris, std::mem::take(edge));
        for (a, b) in wanted {
            if !mesh.has_edge(a, b) {
                recover_edge(pts, &mut mesh, [a, b], walls)?;
            }
        }
        *edge = mesh.edge;
        Ok(())
    }

    /// The surface of `P` (the hull `hull` of `pts`) with the inner vertices `on_outer`
    /// that lie on it as vertices and every edge of `Q` that lies on it: the hull's
    /// triangles, except on each facet that holds one of those vertices or edges, which
    /// is triangulated again with Q's edges in it as constraints (`spade`'s constrained Delaunay triangulation, exact, in the facet's
    /// projection along an axis it is not parallel to). Linear in the facet's size where
    /// inserting the vertices one by one and flipping Q's edges in was quadratic (Q's
    /// vertices on circles on a cube's facets). `None` when `spade` refuses a coordinate
    /// or a constraint (never for valid input: Q's edges in a facet of `P` are edges of
    /// one convex face of `Q`, so they do not cross and no vertex lies inside one).
    pub(super) fn facet_triangles(
        &self,
        pts: &[Point3],
        hull: &Hull3,
        on_outer: &[u32],
    ) -> Option<Vec<[u32; 3]>> {
        let mut members: HashMap<u32, Vec<u32>> = HashMap::default();
        for &v in on_outer {
            for &f in hull.facets_of(v as usize) {
                members.entry(f).or_default().push(v);
            }
        }
        // An edge of Q between two vertices of P (a facet shared with P).
        for &(v, w) in self.edges.iter().filter(|(v, w)| v < w) {
            let fw = hull.facets_of(w as usize);
            for &f in hull.facets_of(v as usize).iter().filter(|f| fw.contains(f)) {
                members.entry(f).or_default().extend([v, w]);
            }
        }
        let mut out = Vec::with_capacity(hull.triangles.len() + 2 * on_outer.len());
        for (t, f) in hull.triangles.iter().zip(&hull.triangle_facet) {
            match members.get_mut(f) {
                Some(m) => m.extend_from_slice(t),
                None => out.push(*t),
            }
        }
        for (f, mut m) in members {
            m.sort_unstable();
            m.dedup();
            out.extend(self.triangulate_facet(pts, hull.facet_planes[f as usize], &m)?);
        }
        Some(out)
    }

    /// The constrained Delaunay triangulation of the facet with vertices `m` whose
    /// outward triangle is `plane`, with Q's edges between its vertices, oriented out.
    fn triangulate_facet(
        &self,
        pts: &[Point3],
        plane: [u32; 3],
        m: &[u32],
    ) -> Option<Vec<[u32; 3]>> {
        let p = |v: u32| &pts[v as usize];
        let [a, b, c] = plane.map(p);
        let axis = projection_axis(a, b, c)?;
        let outward = orient2d_drop(a, b, c, axis);
        let mut cdt: ConstrainedDelaunayTriangulation<spade::Point2<f64>> = Default::default();
        let mut handle = HashMap::default();
        let mut vertex = HashMap::default();
        for &v in m {
            let [x, y] = drop_axis(p(v), axis);
            let h = cdt.insert(spade::Point2::new(x, y)).ok()?;
            handle.insert(v, h);
            vertex.insert(h, v);
        }
        if vertex.len() != m.len() {
            return None; // two vertices on one projected point: not a facet's corners
        }
        for &v in m {
            for w in self.at(v) {
                if let (true, Some(&hw)) = (v < w, handle.get(&w))
                    && cdt.try_add_constraint(handle[&v], hw).is_empty()
                {
                    return None;
                }
            }
        }
        let tris = cdt.inner_faces().map(|face| {
            let [x, y, z] = face.vertices().map(|h| vertex.get(&h.fix()).copied());
            let (x, y, z) = (x?, y?, z?);
            Some(match orient2d_drop(p(x), p(y), p(z), axis) == outward {
                true => [x, y, z],
                false => [x, z, y],
            })
        });
        tris.collect()
    }
}

/// The corner of `Q` at the end of the edge that leaves corner `a` through the point
/// `first` (`along`: the hull's triangle edges between two facets, both ways, sorted; `corner` as in
/// [`QEdges::from_hull`]).
fn edge_end(
    along: &[(u32, u32)],
    corner: &impl Fn(u32) -> Option<u32>,
    a: u32,
    first: u32,
) -> Option<u32> {
    let (mut prev, mut at) = (a, first);
    // A point inside an edge of Q has the edge's two pieces there and no more: the walk
    // goes along the edge, through fewer points than there are.
    for _ in 0..along.len() {
        if let Some(s) = corner(at) {
            return Some(s);
        }
        let mut out = super::with_key(along, at).iter().map(|x| x.1);
        let n = out.find(|&n| n != prev)?;
        (prev, at) = (at, n);
    }
    None
}

/// Each directed edge of a triangulated surface piece, with the triangle that has it
/// (the last one, should two have it).
pub(super) type Edges = HashMap<(u32, u32), usize>;

/// The [`Edges`] of `tris`.
pub(super) fn edges_of(tris: &[[u32; 3]]) -> Edges {
    let mut edge = Edges::with_capacity_and_hasher(3 * tris.len(), Default::default());
    for (i, t) in tris.iter().enumerate() {
        edge.extend((0..3).map(|k| ((t[k], t[(k + 1) % 3]), i)));
    }
    edge
}

/// A triangulated surface piece with its directed edges and the triangles at each vertex,
/// kept up to date through flips.
struct Mesh<'t> {
    tris: &'t mut [[u32; 3]],
    edge: Edges,
    incident: HashMap<u32, Vec<usize>>,
    /// The facets found so far (each a maximal connected set of coplanar triangles,
    /// sorted), and each triangle's facet (`usize::MAX` until found): a flip keeps its
    /// two triangles in their facet. Found where an edge is recovered, not everywhere: a
    /// large bottom has thousands of triangles and few missing edges.
    facets: Vec<Vec<usize>>,
    facet_of: Vec<usize>,
}

impl<'t> Mesh<'t> {
    /// The mesh of `tris`, whose [`Edges`] are `edge`.
    fn new(tris: &'t mut [[u32; 3]], edge: Edges) -> Mesh<'t> {
        let mut incident: HashMap<u32, Vec<usize>> =
            HashMap::with_capacity_and_hasher(tris.len() / 2 + 3, Default::default());
        for (i, t) in tris.iter().enumerate() {
            for &v in t {
                incident.entry(v).or_default().push(i);
            }
        }
        let facet_of = vec![usize::MAX; tris.len()];
        Mesh {
            tris,
            edge,
            incident,
            facets: Vec::new(),
            facet_of,
        }
    }

    fn has_edge(&self, a: u32, b: u32) -> bool {
        self.edge.contains_key(&(a, b)) || self.edge.contains_key(&(b, a))
    }

    /// Replaces triangles `i` and `j` by `ti` and `tj` (the same four corners).
    fn replace(&mut self, [i, j]: [usize; 2], [ti, tj]: [[u32; 3]; 2]) {
        for (idx, new) in [(i, ti), (j, tj)] {
            let old = self.tris[idx];
            for k in 0..3 {
                self.edge.remove(&(old[k], old[(k + 1) % 3]));
                if let Some(list) = self.incident.get_mut(&old[k]) {
                    list.retain(|&x| x != idx);
                }
            }
            self.tris[idx] = new;
        }
        for idx in [i, j] {
            let t = self.tris[idx];
            for k in 0..3 {
                self.edge.insert((t[k], t[(k + 1) % 3]), idx);
                self.incident.entry(t[k]).or_default().push(idx);
            }
        }
    }

    /// The facet holding `a` whose plane holds `b` (sorted triangle indices), if any.
    fn patch(&mut self, pts: &[Point3], a: u32, b: u32) -> Option<Vec<usize>> {
        let p = |v: u32| &pts[v as usize];
        let at = self.incident[&a].iter().copied().find(|&i| {
            let [x, y, z] = self.tris[i].map(p);
            orient3d(x, y, z, p(b)) == 0
        })?;
        let f = self.facet(pts, at);
        Some(self.facets[f].clone())
    }

    /// The facet of triangle `i`, found the first time by a walk over its neighbours in
    /// its plane.
    fn facet(&mut self, pts: &[Point3], i: usize) -> usize {
        if self.facet_of[i] != usize::MAX {
            return self.facet_of[i];
        }
        let p = |v: u32| &pts[v as usize];
        let f = self.facets.len();
        let (mut list, mut next) = (vec![i], 0);
        self.facet_of[i] = f;
        while let Some(&t) = list.get(next) {
            next += 1;
            let tri = self.tris[t];
            let [x, y, z] = tri.map(p);
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                let Some(&j) = self.edge.get(&(b, a)) else {
                    continue;
                };
                if self.facet_of[j] == usize::MAX
                    && orient3d(x, y, z, p(apex(self.tris[j], b, a))) == 0
                {
                    self.facet_of[j] = f;
                    list.push(j);
                }
            }
        }
        list.sort_unstable();
        self.facets.push(list);
        f
    }
}

/// The most flips one edge may take (far beyond what a facet's triangulation needs).
const FLIP_LIMIT: usize = 100_000;

/// `e` is one of the sorted `walls`.
fn is_wall(walls: &[(u32, u32)], e: (u32, u32)) -> bool {
    walls.binary_search(&e).is_ok()
}

/// Recovers the edge `ab` in the facet of the mesh that holds both ends, if there is one.
fn recover_edge(
    pts: &[Point3],
    mesh: &mut Mesh,
    [a, b]: [u32; 2],
    walls: &[(u32, u32)],
) -> Result<(), &'static str> {
    let p = |v: u32| &pts[v as usize];
    let Some(patch) = mesh.patch(pts, a, b) else {
        return Ok(()); // no facet at `a` in a plane with `b`
    };
    if !patch.iter().any(|&i| mesh.tris[i].contains(&b)) {
        return Ok(()); // not in one facet: the segment is not on the surface
    }
    let [x, y, z] = mesh.tris[patch[0]].map(p);
    let axis = projection_axis(x, y, z).ok_or("a degenerate facet triangle")?;
    let side = |u: u32, v: u32, w: u32| orient2d_drop(p(u), p(v), p(w), axis);
    let crosses =
        |c: u32, d: u32| side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0;
    // An edge crossing `ab` has a triangle whose box meets the box of `ab` (exact
    // comparisons): the others are skipped before any orientation test.
    let (lo, hi) = bounding_box(&[*p(a), *p(b)]);
    let meets = |t: &[u32; 3]| {
        (0..3).all(|d| {
            let c = t.map(|v| p(v)[d]);
            c[0].max(c[1]).max(c[2]) >= lo[d] && c[0].min(c[1]).min(c[2]) <= hi[d]
        })
    };
    for _ in 0..FLIP_LIMIT {
        let mut crossing: Vec<(u32, u32, usize, usize)> = patch
            .iter()
            .filter(|&&i| meets(&mesh.tris[i]))
            .flat_map(|&i| {
                let t = mesh.tris[i];
                (0..3).map(move |k| (t[k], t[(k + 1) % 3], i))
            })
            .filter(|&(c, d, _)| c < d && !is_wall(walls, (c, d)) && !is_wall(walls, (d, c)))
            .filter_map(|(c, d, i)| mesh.edge.get(&(d, c)).map(|&j| (c, d, i, j)))
            .filter(|&(_, _, _, j)| patch.binary_search(&j).is_ok())
            .filter(|&(c, d, _, _)| crosses(c, d))
            .collect();
        crossing.sort_unstable(); // the same flips, whatever the hash order
        let (mut first, mut best) = (None, None);
        for (c, d, i, j) in crossing {
            let (x, y) = (apex(mesh.tris[i], c, d), apex(mesh.tris[j], d, c));
            // Strictly convex: c and d strictly on either side of the new diagonal xy.
            if side(x, y, c) * side(x, y, d) >= 0 {
                continue;
            }
            first.get_or_insert((i, j, c, d, x, y));
            if !crosses(x, y) {
                best = Some((i, j, c, d, x, y));
                break;
            }
        }
        let Some((i, j, c, d, x, y)) = best.or(first) else {
            return Err("an edge of Q in a facet cannot be recovered");
        };
        // [c, d, x] and [d, c, y] become [c, y, x] and [y, d, x] (counter-clockwise
        // quadrilateral c, y, d, x).
        mesh.replace([i, j], [[c, y, x], [y, d, x]]);
        if mesh.has_edge(a, b) {
            return Ok(());
        }
    }
    Err("an edge of Q in a facet took too many flips")
}

/// The corner of triangle `t` other than `c` and `d` (`t` has the directed edge `cd`).
fn apex(t: [u32; 3], c: u32, d: u32) -> u32 {
    t.into_iter().find(|&v| v != c && v != d).unwrap_or(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::point_key;

    /// Q's edges read off a hull of its input points (points inside edges and facets,
    /// repeats) equal the pairs of corners that share two facets.
    #[test]
    fn edges_from_a_hull_are_the_pairs_of_corners_on_two_facets() {
        let mut rng = crate::rng::Rng::new(41);
        let mut checked = 0;
        for k in 0..400 {
            let side = 2 + k % 4;
            let pts: Vec<Point3> = (0..6 + k % 40)
                .map(|_| [0; 3].map(|_| rng.below(side) as f64))
                .collect();
            let hull = Hull3::new(&pts);
            if hull.dimension < 3 {
                continue;
            }
            // Corners by their first occurrence, named by that index.
            let mut first: HashMap<[u64; 3], u32> = HashMap::default();
            for (i, p) in pts.iter().enumerate() {
                if hull.facets_of(i).len() >= 3 {
                    first.entry(point_key(p)).or_insert(i as u32);
                }
            }
            let corner = |i: u32| {
                let at = hull.facets_of(i as usize).len() >= 3;
                at.then(|| first[&point_key(&pts[i as usize])])
            };
            let q = QEdges::from_hull(&hull, corner);
            let mut want: Vec<(u32, u32)> = Vec::new();
            for (&a, &b) in first
                .values()
                .flat_map(|a| first.values().map(move |b| (a, b)))
            {
                let (fa, fb) = (hull.facets_of(a as usize), hull.facets_of(b as usize));
                if a != b && fa.iter().filter(|f| fb.contains(f)).count() >= 2 {
                    want.push((a, b));
                }
            }
            want.sort_unstable();
            assert_eq!(q.edges, want, "set {k}: {pts:?}");
            checked += 1;
        }
        assert!(checked > 300, "{checked}");
    }
}
