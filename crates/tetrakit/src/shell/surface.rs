//! The current hull `P̄` as a triangulated sphere, and the one operation both methods are
//! made of: removing outer vertices from it, each removal a star-shaped piece coned from
//! its tip (thesis §4.2, Lemma 4.1).
//!
//! **Removing a vertex `v`** (a cap, §4.1). Let `L` be the link of `v` (its neighbours,
//! a cycle) and `H' = CH(V(P̄) − v ∪ V(Q))` the new hull. The cap `P̄ − H'` lies in
//! `CH(v ∪ L)`, so the only points that can appear on its bottom are `L` and the hidden
//! inner vertices `C` in that region (in practice those in the closed `CH(v ∪ L)` and
//! not strictly inside `CH(L)`, found in a tree of boxes, see [`Hidden`](super::hidden);
//! any superset of inner vertices would do). Let `K = CH(L ∪ C) ⊆ H'`. Every facet of `H'` that `v` sees is a face of `K` (its
//! vertices are in `L ∪ C`), and conversely a facet of `K` that `v` sees strictly lies on
//! `∂H'` (a point of `K` that `v` sees is not in the interior of `H'`, else the segment
//! from `v` would meet `∂H'` first, on a visible facet of `K`). So the bottom is the disk
//! of `∂K` bounded by `L` on `v`'s side: the triangles of `K` reached from the link edges,
//! directed as in the star, without crossing a link edge. Its triangles that `v` sees
//! strictly are the bottoms of the cap's tetrahedra `v·t`; those in a plane through `v`
//! (a coplanar facet of `P̄`) are kept on the surface without a tetrahedron. When `L ∪ C`
//! is flat, `K` is a polygon and the bottom is the base of `CH(v ∪ L ∪ C)`, reversed (a
//! fan of it when `C` is empty and every point of `L` is a corner, [`flat_fan`]).
//!
//! **Big bottoms.** The argument asks only `L ∪ C ⊆ K ⊆ H'`, so `K = CH(L ∪ V(Q))`
//! serves as well: `Q`'s hull with the ring's other points inserted
//! ([`Hull3::extended`]), a fraction of the cost of a new hull where the candidates are a
//! large part of `Q` (the corner family's first caps at 10^3: 400 to 600 of 992 vertices),
//! of which only the facets facing the tip are searched ([`facing_facets`]). Its facets
//! hold `Q`'s exposed vertices too, so one may cross a ring edge; there, and on any other
//! refusal, the candidates' hull decides.
//!
//! **Removing several at once** (a bigcap, §4.2): the same with `v`'s star replaced by
//! the union of the stars of a connected vertex set `U` whose removal leaves a disk
//! visible from `v`; see [`Surface::plan`]. The removed region `P̄ − H'` lies in
//! `CH(U ∪ L)` here too: a point `x` of it is strictly beyond some plane `h` with `H'`
//! on the other side, so the vertices of `P̄` beyond `h` are in `U`; `P̄`'s part beyond
//! `h` is the hull of those vertices and of the points where `h` cuts `P̄`'s edges
//! leaving them, edges whose other ends are in `U` or its ring `L` (every neighbour of
//! `U` is); so its candidates are cut to `CH(U ∪ L)` as a cap's are.
//!
//! Every step is checked (the bottom is a disk bounded by the link, every bottom triangle
//! seen from the tip or coplanar with it): a removal that fails a check changes nothing
//! and is reported, and the caller tries another tip. The final mesh is certified anyway
//! ([`crate::mesh::certify_shell`]).

use super::Shell;
use super::hidden::{Hidden, Region};
use super::recover;
use crate::geom::{
    Hull2, Hull3, Plane, Point3, bounding_box, collinear3, drop_axis, orient2d_drop, orient3d,
    projection_axis,
};
use rustc_hash::FxHashMap as HashMap;
use std::cell::OnceCell;
use std::sync::Arc;

/// The triangulated surface of the current hull (cloned by Step 3a's search, which tries
/// orders of removal on copies).
#[derive(Clone)]
pub(super) struct Surface<'a> {
    /// The shell's points ([`Shell::points`]).
    pts: &'a [Point3],
    tris: Vec<[u32; 3]>,
    alive: Vec<bool>,
    /// Directed edge → the live triangle that has it.
    edge: HashMap<(u32, u32), u32>,
    /// Triangles by vertex (dead ones are dropped lazily).
    incident: Vec<Vec<u32>>,
    /// The live triangles at each vertex (its degree), kept as triangles come and go.
    live: Vec<u32>,
    /// Inner vertices not yet on the surface.
    pub(super) hidden: Hidden,
    /// The shell: `P`'s hull (to tell the surface's facets on `∂P` from those inside
    /// it), Q's edges (recovered wherever a facet of the surface holds them) and Q's hull
    /// (when a bottom is read off it, [`Surface::big_hull`]).
    shell: &'a Shell,
    /// `Q`'s hull on its vertices, made at the first bottom that needs it (shared by
    /// the copies of step 3a's search).
    q_hull: OnceCell<Option<Arc<QHull>>>,
    /// The most triangles a cut of several vertices has taken (what bounds its cost).
    #[cfg(test)]
    pub(super) largest_cut: usize,
}

/// What a removal takes off the surface (triangle ids) and the bottom it leaves.
pub(super) struct Cut {
    region: Vec<u32>,
    /// The new surface triangles, facing out of the new hull (into the piece).
    pub(super) bottom: Vec<[u32; 3]>,
}

/// A removal planned: the surface triangles it takes, the bottom it leaves, and its
/// tetrahedra.
pub(super) struct Piece {
    region: Vec<u32>,
    bottom: Vec<[u32; 3]>,
    /// The tetrahedra, coned from the tip.
    pub(super) tets: Vec<[u32; 4]>,
}

/// `Q`'s hull on its vertices, numbered as [`Shell::inner`] lists them, and each
/// shell vertex's number there (`u32::MAX`: not a vertex of `Q`).
struct QHull {
    hull: Hull3,
    number: Vec<u32>,
}

impl QHull {
    /// `None` when `Q`'s input has points besides its vertices (inside, on an edge or a
    /// facet, repeated), which its hull's triangles may have as corners.
    fn new(shell: &Shell) -> Option<QHull> {
        if !shell.inner_ignored.is_empty() {
            return None;
        }
        let mut by_input = vec![u32::MAX; shell.inner_source.len()];
        for (k, &i) in shell.inner_source.iter().enumerate() {
            by_input[i as usize] = k as u32;
        }
        let name = |i: u32| Some(by_input[i as usize]).filter(|&k| k != u32::MAX);
        let hull = shell
            .inner_hull
            .clone()
            .renumbered(&shell.inner_source, name)?;
        let mut number = vec![u32::MAX; shell.points.len()];
        for (k, &v) in shell.inner.iter().enumerate() {
            number[v as usize] = k as u32;
        }
        Some(QHull { hull, number })
    }
}

impl Piece {
    /// The triangles it leaves on the surface.
    pub(super) fn bottom(&self) -> &[[u32; 3]] {
        &self.bottom
    }
}

/// True when the directed edges (sorted) form one cycle: each vertex starts one edge,
/// and the walk from the first comes back after all of them.
fn one_cycle(edges: &[(u32, u32)]) -> bool {
    let Some(&(start, _)) = edges.first() else {
        return false;
    };
    if edges.windows(2).any(|w| w[0].0 == w[1].0) {
        return false;
    }
    let (mut v, mut steps) = (start, 0);
    loop {
        let Some(w) = starting_at(edges, v) else {
            return false;
        };
        v = w;
        steps += 1;
        if v == start || steps > edges.len() {
            break;
        }
    }
    v == start && steps == edges.len()
}

/// The end of the edge that starts at `v` among `edges` (sorted), if one does.
fn starting_at(edges: &[(u32, u32)], v: u32) -> Option<u32> {
    super::with_key(edges, v).first().map(|e| e.1)
}

/// Why a removal was not made (the surface is unchanged). The reason is read in a
/// debugger and in test failures only: a refused removal is not an error (the tip is
/// tried again, and what stays refused is placed).
#[derive(Debug)]
#[allow(dead_code)]
pub(super) struct Refused(pub(super) &'static str);

impl<'a> Surface<'a> {
    /// The surface of `P` (the hull of all the points, every outer point a vertex of
    /// it), with the inner vertices that are not outer ones hidden below it.
    ///
    /// The inner vertices on `∂P` (on a facet or an edge of the outer hull,
    /// [`Shell::touching`]) are vertices of the surface from the start. Refused when a
    /// facet of `P` cannot be triangulated with the inner vertices and edges on it.
    pub(super) fn new(shell: &'a Shell) -> Result<Surface<'a>, Refused> {
        let pts = &shell.points;
        let n_outer = shell.outer.len() as u32;
        let hidden: Vec<u32> = (shell.inner.iter().copied())
            .filter(|&v| v >= n_outer)
            .collect();
        let tris = (shell.q_edges)
            .facet_triangles(pts, &shell.hull, &shell.touching)
            .ok_or(Refused("a facet of P with inner vertices or edges on it"))?;
        let mut s = Surface {
            pts,
            tris: Vec::new(),
            alive: Vec::new(),
            // A surface of v vertices has 6v − 12 directed edges: no rehash on the way.
            edge: HashMap::with_capacity_and_hasher(6 * pts.len(), Default::default()),
            incident: vec![Vec::new(); pts.len()],
            live: vec![0; pts.len()],
            hidden: Hidden::new(pts, &hidden),
            shell,
            q_hull: OnceCell::new(),
            #[cfg(test)]
            largest_cut: 0,
        };
        for &v in &shell.touching {
            s.hidden.expose(v);
        }
        for t in tris {
            s.add(t);
        }
        Ok(s)
    }

    fn add(&mut self, t: [u32; 3]) {
        let id = self.tris.len() as u32;
        self.tris.push(t);
        self.alive.push(true);
        for i in 0..3 {
            self.edge.insert((t[i], t[(i + 1) % 3]), id);
            self.incident[t[i] as usize].push(id);
            self.live[t[i] as usize] += 1;
        }
    }

    fn kill(&mut self, id: u32) {
        let t = self.tris[id as usize];
        self.alive[id as usize] = false;
        for i in 0..3 {
            self.live[t[i] as usize] -= 1;
            let e = (t[i], t[(i + 1) % 3]);
            if self.edge.get(&e) == Some(&id) {
                self.edge.remove(&e);
            }
        }
    }

    /// True when triangle `t` lies in a facet of `P` (nothing is behind it).
    fn on_outer(&self, t: &[u32; 3]) -> bool {
        let h = &self.shell.hull;
        h.common_facet(t[0] as usize, t[1] as usize, t[2] as usize)
            .is_some()
    }

    /// The live triangles.
    pub(super) fn triangles(&self) -> Vec<[u32; 3]> {
        (self.tris.iter().zip(&self.alive))
            .filter_map(|(t, &a)| a.then_some(*t))
            .collect()
    }

    /// The live triangles, each turned to start at its least vertex, sorted: two
    /// surfaces are the same exactly when their keys are.
    pub(super) fn key(&self) -> Vec<[u32; 3]> {
        canonical(&self.triangles())
    }

    /// The live triangles that `v` sees: `v` strictly beyond their planes (after a
    /// piece at `v`, its view, thesis §4.2).
    pub(super) fn seen_from(&self, v: u32) -> Vec<u32> {
        let p = |x: u32| &self.pts[x as usize];
        (0..self.tris.len() as u32)
            .filter(|&t| self.alive[t as usize])
            .filter(|&t| {
                let [a, b, c] = self.tris[t as usize];
                orient3d(p(a), p(b), p(c), p(v)) == 1
            })
            .collect()
    }

    /// Triangle `t` is still on the surface.
    pub(super) fn is_live(&self, t: u32) -> bool {
        self.alive[t as usize]
    }

    /// The live triangle across the edge `ab` from the one that has it directed `a → b`.
    pub(super) fn across(&self, a: u32, b: u32) -> Option<u32> {
        self.edge.get(&(b, a)).copied()
    }

    /// The live triangles at `v`.
    pub(super) fn star(&mut self, v: u32) -> Vec<u32> {
        let alive = &self.alive;
        self.incident[v as usize].retain(|&t| alive[t as usize]);
        self.incident[v as usize].clone()
    }

    /// Every point (the shell's).
    pub(super) fn points(&self) -> &'a [Point3] {
        self.pts
    }

    /// The vertices of triangle `t`.
    pub(super) fn triangle(&self, t: u32) -> [u32; 3] {
        self.tris[t as usize]
    }

    /// The number of live triangles at `v` (its degree on the surface).
    pub(super) fn degree(&self, v: u32) -> usize {
        self.live[v as usize] as usize
    }

    /// The neighbours of `v` on the surface.
    pub(super) fn neighbours(&mut self, v: u32) -> Vec<u32> {
        let star = self.star(v);
        star.iter()
            .map(|&t| {
                let tri = self.tris[t as usize];
                let i = tri.iter().position(|&x| x == v).unwrap_or(0);
                tri[(i + 1) % 3]
            })
            .collect()
    }

    /// Plans the removal of the vertices `set` (containing `tip`): the region between the
    /// surface and the hull without them, coned from `tip`, to be made by
    /// [`Surface::apply`]. Refused (nothing changes) unless the union of their stars is a
    /// disk whose vertices are removed or on its boundary, and the region is star-shaped
    /// from `tip` (on the inner side of every face) and meets earlier pieces face to face.
    pub(super) fn plan(&mut self, tip: u32, set: &[u32]) -> Result<Piece, Refused> {
        let Cut { region, bottom } = self.cut(tip, set)?;
        self.cone(tip, region, bottom)
    }

    /// The region removing `set` takes off the surface and the bottom it leaves (`tip`
    /// decides a flat bottom's side), checked to be a disk that surrounds no vertex.
    pub(super) fn cut(&mut self, tip: u32, set: &[u32]) -> Result<Cut, Refused> {
        // Sorted vectors, not hash sets: most sets are one vertex with a star of six.
        let mut removed = set.to_vec();
        removed.sort_unstable();
        let is_removed = |v: &u32| removed.binary_search(v).is_ok();
        let mut region: Vec<u32> = set.iter().flat_map(|&u| self.star(u)).collect();
        region.sort_unstable();
        region.dedup();
        #[cfg(test)]
        if set.len() > 1 {
            self.largest_cut = self.largest_cut.max(region.len());
        }
        // The boundary of the union of the stars: the directed edges of its triangles
        // whose reverse is not one of them.
        let mut inside: Vec<(u32, u32)> = (region.iter())
            .flat_map(|&t| {
                let tri = self.tris[t as usize];
                (0..3).map(move |i| (tri[i], tri[(i + 1) % 3]))
            })
            .collect();
        super::sort_pairs(&mut inside);
        inside.dedup();
        let boundary: Vec<(u32, u32)> = (inside.iter())
            .filter(|&&(a, b)| inside.binary_search(&(b, a)).is_err())
            .copied()
            .collect();
        if boundary.iter().any(|(a, b)| is_removed(a) || is_removed(b)) {
            return Err(Refused(
                "a removed vertex is on the boundary of the removed region",
            ));
        }
        let ring: Vec<u32> = boundary.iter().map(|e| e.0).collect();
        if !one_cycle(&boundary) {
            return Err(Refused("the removed region is not a disk"));
        }
        // Every vertex of the region is removed or on its boundary: a vertex the set
        // surrounds would leave the surface unremoved.
        let on_ring = |v: &u32| starting_at(&boundary, *v).is_some();
        let enclosed = region.iter().flat_map(|&t| self.tris[t as usize]);
        if enclosed.clone().any(|v| !is_removed(&v) && !on_ring(&v)) {
            return Err(Refused(
                "the removed set surrounds a vertex it does not remove",
            ));
        }
        let bottom = self.bottom(tip, set, &ring, &boundary)?;
        Ok(Cut { region, bottom })
    }

    /// The piece between `region` and `bottom` coned from `tip`.
    fn cone(&self, tip: u32, region: Vec<u32>, bottom: Vec<[u32; 3]>) -> Result<Piece, Refused> {
        // The region is star-shaped from the tip when the tip is on the inner side of
        // every face (the kernel is the intersection of those half-spaces): then the
        // cones from the tip over the faces not at it tile it.
        let p = |v: u32| &self.pts[v as usize];
        let mut tets = Vec::new();
        for t in &bottom {
            match orient3d(p(t[0]), p(t[1]), p(t[2]), p(tip)) {
                1 => tets.push([t[0], t[1], t[2], tip]),
                // A bottom triangle in a plane through the tip stays on the surface with
                // nothing behind it: only right where that plane is a facet of P. In a
                // plane inside P (a facet of P̄ made by earlier pieces) the triangles
                // there are faces of earlier tetrahedra, which the new ones must meet
                // face to face; a new coplanar triangle would not.
                0 if self.on_outer(t) => {}
                0 => {
                    return Err(Refused(
                        "a bottom triangle lies in a plane of earlier pieces through the tip",
                    ));
                }
                _ => return Err(Refused("a bottom triangle is behind the tip")),
            }
        }
        for t in region.iter().map(|&t| self.tris[t as usize]) {
            if t.contains(&tip) {
                continue;
            }
            match orient3d(p(t[0]), p(t[1]), p(t[2]), p(tip)) {
                -1 => tets.push([t[0], t[2], t[1], tip]),
                // Left without a tetrahedron: only where nothing is behind it.
                0 if self.on_outer(&t) => {}
                0 => {
                    return Err(Refused(
                        "a removed triangle of earlier pieces is flat to the tip",
                    ));
                }
                _ => return Err(Refused("a removed triangle is behind the tip")),
            }
        }
        if tets.is_empty() {
            return Err(Refused("the removed region is flat"));
        }
        Ok(Piece {
            region,
            bottom,
            tets,
        })
    }

    /// Removes a planned piece: its region leaves the surface, its bottom joins it.
    pub(super) fn apply(&mut self, piece: Piece) -> Vec<[u32; 4]> {
        let Piece {
            region,
            bottom,
            tets,
        } = piece;
        for t in region {
            self.kill(t);
        }
        for t in bottom {
            for v in t {
                self.hidden.expose(v);
            }
            self.add(t);
        }
        tets
    }

    /// The hidden inner vertices that can be on the bottom of removing the last
    /// `removed` points of `around` (the ring, then the removed set): those in the
    /// region of [`Hidden::within`]. The exact planes cost small hulls, about what as
    /// many candidates cost the bottom's hull, so they are built only when the box
    /// alone holds more than the ring (and 16): `CH(U ∪ ring)`'s first, then, when the
    /// candidates still outnumber the ring [`RING_STAGE`] times (thousands under a star
    /// spanning the shell, on arcs), `CH(ring)`'s.
    fn candidates(&self, around: &[Point3], removed: usize) -> Vec<u32> {
        let (lo, hi) = bounding_box(around);
        let ring = around.len() - removed;
        let mut region = Region {
            lo,
            hi,
            within: &[],
            ring: &[],
        };
        if let Some(c) = self.hidden.within(self.pts, &region, ring.max(16)) {
            return c;
        }
        let cap = hull_planes(around);
        region.within = &cap;
        if let Some(c) = self.hidden.within(self.pts, &region, RING_STAGE * ring) {
            return c;
        }
        let inside = hull_planes(&around[..ring]);
        region.ring = &inside;
        self.hidden
            .within(self.pts, &region, usize::MAX)
            .unwrap_or_default()
    }

    /// The new surface inside the region bounded by `boundary` (directed as in the
    /// triangles `region` that removing `set` takes): the disk of
    /// `∂CH(ring ∪ hidden below)` on the tip's side.
    fn bottom(
        &self,
        tip: u32,
        set: &[u32],
        ring: &[u32],
        boundary: &[(u32, u32)],
    ) -> Result<Vec<[u32; 3]>, Refused> {
        let around: Vec<Point3> = ring
            .iter()
            .chain(set)
            .map(|&v| self.pts[v as usize])
            .collect();
        let candidates = self.candidates(&around, set.len());
        // Big bottoms off Q's hull (the module's doc); where that refuses, as below.
        if candidates.len() * BIG_BOTTOM >= self.shell.inner.len()
            && let Some((local, hull)) = self.big_hull(ring)
            && let Ok(bottom) = self.hull_disk((tip, boundary), &local, &hull, true)
        {
            return Ok(bottom);
        }
        if candidates.is_empty()
            && let Some(tris) = simplicial_hull(self.pts, ring)
        {
            return disk(tip, &tris, &recover::edges_of(&tris), boundary);
        }
        if candidates.is_empty()
            && let Some(tris) = flat_fan(self.pts, ring, tip)
        {
            // Q's edges between corners of the polygon may be its diagonals.
            let mut corners = ring.to_vec();
            corners.sort_unstable();
            return self.recovered_disk(tip, tris, &corners, boundary);
        }
        let mut local: Vec<u32> = ring.to_vec();
        local.extend(candidates);
        let coords: Vec<Point3> = local.iter().map(|&v| self.pts[v as usize]).collect();
        self.hull_disk((tip, boundary), &local, &Hull3::new(&coords), false)
    }

    /// The bottom bounded by `boundary` on `hull`, the hull of the points `local` names
    /// (when flat, the base of the cone from `tip`); with `facing_only`, searched in the
    /// facets facing the tip alone ([`facing_facets`]). (Not on the candidates' hull: a
    /// point inside an edge between a facet facing the tip and one that does not is
    /// refined into both, and the facing triangle alone has no twin there ([`refine`]),
    /// so some removals the whole hull allows were refused; on the degenerate shells of
    /// `tests/shell.rs` the placing ended 258 of the 2,298 runs instead of 49. On `Q`'s
    /// hull with the ring, every refusal falls back to the candidates' hull.)
    fn hull_disk(
        &self,
        (tip, boundary): (u32, &[(u32, u32)]),
        local: &[u32],
        hull: &Hull3,
        facing_only: bool,
    ) -> Result<Vec<[u32; 3]>, Refused> {
        let facing = match facing_only {
            true => facing_facets(self.pts, hull, local, tip),
            false => vec![true; hull.facet_count()],
        };
        // The triangles and the points on the hull, by their place in `local`.
        let (tris, on_hull): (Vec<[u32; 3]>, Vec<usize>) = if hull.dimension == 3 {
            let tris = (hull.triangles.iter().zip(&hull.triangle_facet))
                .filter(|&(_, &f)| facing[f as usize])
                .map(|(t, _)| *t)
                .collect();
            let on =
                (0..local.len()).filter(|&k| hull.facets_of(k).iter().any(|&f| facing[f as usize]));
            (tris, on.collect())
        } else {
            // A flat ring: the base of the cone from the tip, facing the tip.
            let mut with_tip: Vec<Point3> = local.iter().map(|&v| self.pts[v as usize]).collect();
            with_tip.push(self.pts[tip as usize]);
            let cone = Hull3::new(&with_tip);
            let apex = local.len() as u32;
            let tris = (cone.triangles.iter())
                .filter(|t| !t.contains(&apex))
                .map(|t| [t[0], t[2], t[1]])
                .collect();
            (
                tris,
                (0..local.len()).filter(|&k| cone.on_boundary(k)).collect(),
            )
        };
        // Points on the hull but not corners of its triangles (on an edge, or inside a
        // coplanar facet) are on the new surface where it is the bottom: they become
        // vertices there, or a later piece would meet them mid-face (and a ring vertex
        // on an edge of the hull would leave its ring edges out). On the far side of the
        // hull they stay hidden.
        let mut corner = vec![false; local.len()];
        for &k in tris.iter().flatten() {
            corner[k as usize] = true;
        }
        let flat: Vec<u32> = (on_hull.into_iter())
            .filter(|&k| !corner[k])
            .map(|k| local[k])
            .collect();
        let mut tris: Vec<[u32; 3]> = (tris.iter())
            .map(|t| t.map(|k| local[k as usize]))
            .collect();
        if refine(self.pts, &mut tris, &flat)? != flat.len() {
            return Err(Refused("a point on the hull is on none of its triangles"));
        }
        // An edge of Q between two corners in a facet's plane lies in that facet, so it
        // can be missing only where the facet has more triangles than one, or where
        // points were refined in.
        let loose = match (hull.dimension, flat.is_empty()) {
            (3, true) => polygon_corners(hull, local, &facing),
            _ => {
                let corners = (0..local.len()).filter(|&k| corner[k]).map(|k| local[k]);
                let mut loose: Vec<u32> = corners.chain(flat).collect();
                loose.sort_unstable();
                loose.dedup();
                loose
            }
        };
        self.recovered_disk(tip, tris, &loose, boundary)
    }

    /// `Q`'s hull on its vertices, made at the first call.
    fn q_hull(&self) -> Option<&QHull> {
        let made = self
            .q_hull
            .get_or_init(|| QHull::new(self.shell).map(Arc::new));
        made.as_deref()
    }

    /// `CH(ring ∪ V(Q))` and its points (the vertices of `Q` as [`Shell::inner`] lists
    /// them, then the ring's others): `Q`'s hull with the ring inserted, where the hidden
    /// vertices that can be on the bottom are a large part of `Q`'s ([`BIG_BOTTOM`]), at
    /// a fraction of the cost of a new hull of the ring and those vertices. Its bottom is
    /// theirs: both hulls lie between `CH(ring ∪ C)` and `H'` (the module's doc).
    fn big_hull(&self, ring: &[u32]) -> Option<(Vec<u32>, Hull3)> {
        let q = self.q_hull()?;
        let mut local = self.shell.inner.clone();
        local.extend(ring.iter().filter(|&&v| q.number[v as usize] == u32::MAX));
        let coords: Vec<Point3> = local.iter().map(|&v| self.pts[v as usize]).collect();
        Some((local, q.hull.extended(&coords)?))
    }

    /// The [`disk`] of `tris` bounded by `boundary`, once Q's edges between the `loose`
    /// corners (sorted) are edges of `tris`.
    fn recovered_disk(
        &self,
        tip: u32,
        mut tris: Vec<[u32; 3]>,
        loose: &[u32],
        boundary: &[(u32, u32)],
    ) -> Result<Vec<[u32; 3]>, Refused> {
        let mut edges = recover::edges_of(&tris);
        if !loose.is_empty() {
            self.shell
                .q_edges
                .recover(self.pts, (&mut tris, &mut edges), boundary, loose)
                .map_err(Refused)?;
        }
        disk(tip, &tris, &edges, boundary)
    }
}

/// The corners of `hull`'s triangles that share their facet with another triangle, named
/// by `name`, sorted.
fn polygon_corners(hull: &Hull3, name: &[u32], facing: &[bool]) -> Vec<u32> {
    let mut count = vec![0u32; hull.facet_count()];
    for &f in &hull.triangle_facet {
        count[f as usize] += 1;
    }
    let mut out: Vec<u32> = (hull.triangles.iter().zip(&hull.triangle_facet))
        .filter(|&(_, &f)| count[f as usize] > 1 && facing[f as usize])
        .flat_map(|(t, _)| t.map(|k| name[k as usize]))
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// For each facet of `hull` (on the points `local` names), whether `tip` is on its plane
/// or beyond it: a bottom is made of such facets (it is seen from the tip or lies in a
/// plane through it, [`Surface::cone`]), so the others need not be refined or searched.
fn facing_facets(pts: &[Point3], hull: &Hull3, local: &[u32], tip: u32) -> Vec<bool> {
    let p = |k: u32| &pts[local[k as usize] as usize];
    (hull.facet_planes.iter())
        .map(|f| orient3d(p(f[0]), p(f[1]), p(f[2]), &pts[tip as usize]) >= 0)
        .collect()
}

/// The disk of the closed triangulated surface `tris` (with its `edges`) bounded by
/// `boundary` (directed as in the triangles inside it): the triangles reached from the
/// boundary edges without crossing one. Refused when a boundary edge is not an edge of
/// `tris`, the surface is not closed there, or the disk reaches `tip`.
fn disk(
    tip: u32,
    tris: &[[u32; 3]],
    edges: &recover::Edges,
    boundary: &[(u32, u32)],
) -> Result<Vec<[u32; 3]>, Refused> {
    let with_edge = |(a, b): (u32, u32)| edges.get(&(a, b)).copied();
    let mut seen = vec![false; tris.len()];
    let mut stack = Vec::with_capacity(tris.len());
    for &e in boundary {
        let t = with_edge(e).ok_or(Refused("a link edge is not an edge of the bottom"))?;
        stack.push(t);
    }
    let mut out = Vec::with_capacity(tris.len());
    while let Some(t) = stack.pop() {
        if std::mem::replace(&mut seen[t], true) {
            continue;
        }
        let tri = tris[t];
        out.push(tri);
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            if boundary.binary_search(&(a, b)).is_ok() {
                continue; // a wall: the bottom ends at the ring
            }
            let u = with_edge((b, a)).ok_or(Refused("the bottom is not closed"))?;
            stack.push(u);
        }
    }
    if out.iter().any(|t| t.contains(&tip)) {
        return Err(Refused("the bottom reaches the tip"));
    }
    Ok(out)
}

/// How many times the candidates in `CH(U ∪ ring)` must outnumber the ring before
/// [`Surface::candidates`] leaves out those strictly inside `CH(ring)`. That stage costs
/// the ring's hull and a query testing every candidate against its planes, and the
/// bottom's hull takes a point strictly inside for little (it is proved inside as it is
/// dropped), so it pays only where it leaves out most. At 10^4 (5 alternating runs
/// each), coaxial cylinders took 0.206 s and the corner 0.075 s with the stage wherever
/// the candidates outnumber the ring, 0.171 s and 0.070 s with it from eightfold on;
/// bent arcs 0.074 s either way and 0.40 s without the stage.
const RING_STAGE: usize = 8;

/// A bottom is read off `Q`'s hull ([`Surface::big_hull`]) when its candidates number at
/// least `1 / BIG_BOTTOM` of `Q`'s vertices: then inserting the ring into `Q`'s hull
/// costs less than a new hull of the candidates.
const BIG_BOTTOM: usize = 3;

/// The most ring vertices [`simplicial_hull`] takes (it tests every triple).
const SMALL_RING: usize = 8;

/// The facets of `CH(ring)`, outward, when the ring has 4 to [`SMALL_RING`] points, all
/// of them corners, and no plane supporting the hull holds four of them: then every
/// triple with all other points strictly on one side is a facet, and there are `2d − 4`
/// (exact, by every triple). `None` otherwise (flat, a facet with four points or more):
/// what [`Hull3`] makes of it, with its points on facets and edges, decides. Most caps
/// have a ring of five or six and nothing hidden below: this is most of their bottoms.
fn simplicial_hull(pts: &[Point3], ring: &[u32]) -> Option<Vec<[u32; 3]>> {
    let d = ring.len();
    if !(4..=SMALL_RING).contains(&d) {
        return None;
    }
    let p = |v: u32| &pts[v as usize];
    let mut tris = Vec::with_capacity(2 * d - 4);
    for i in 0..d {
        for j in i + 1..d {
            for k in j + 1..d {
                let (a, b, c) = (ring[i], ring[j], ring[k]);
                let (mut below, mut above, mut on) = (false, false, false);
                for &x in ring {
                    if x == a || x == b || x == c {
                        continue;
                    }
                    match orient3d(p(a), p(b), p(c), p(x)) {
                        0 => on = true,
                        -1 => below = true,
                        _ => above = true,
                    }
                    if below && above {
                        break; // no supporting plane
                    }
                }
                match (below, above) {
                    (true, true) => {}
                    // A supporting plane through four points, or a flat ring.
                    _ if on => return None,
                    (true, false) => tris.push([a, b, c]),
                    (false, true) => tris.push([a, c, b]),
                    (false, false) => return None,
                }
            }
        }
    }
    (tris.len() == 2 * d - 4).then_some(tris)
}

/// The bottom of a flat ring with nothing below it, when the ring is a strictly convex
/// polygon (every point a corner) and the tip is off its plane: a fan of the polygon, each
/// triangle facing the tip. What the flat ring's two hulls (the ring's, then the cone's
/// from the tip) would give up to the choice of diagonals, at a fraction of the cost (a
/// hundred such rings on the lattice spheres of 10^3 vertices). `None` otherwise: the
/// hulls decide, with the ring's points on edges.
fn flat_fan(pts: &[Point3], ring: &[u32], tip: u32) -> Option<Vec<[u32; 3]>> {
    let p = |v: u32| &pts[v as usize];
    let (a, b) = (*ring.first()?, *ring.get(1)?);
    let c = *ring[2..].iter().find(|&&c| !collinear3(p(a), p(b), p(c)))?;
    let off = |x: u32| orient3d(p(a), p(b), p(c), p(x)) != 0;
    if !off(tip) || ring.iter().any(|&x| off(x)) {
        return None;
    }
    let axis = projection_axis(p(a), p(b), p(c))?;
    let flat: Vec<_> = ring.iter().map(|&v| drop_axis(p(v), axis)).collect();
    let polygon = Hull2::new(&flat).vertices;
    if polygon.len() != ring.len() {
        return None;
    }
    let v = |k: usize| ring[polygon[k] as usize];
    let fan = (1..polygon.len() - 1).map(|k| [v(0), v(k), v(k + 1)]);
    // Every triangle of the fan turns as its polygon does: the first decides.
    Some(match orient3d(p(v(0)), p(v(1)), p(v(2)), p(tip)) > 0 {
        true => fan.collect(),
        false => fan.map(|[x, y, z]| [x, z, y]).collect(),
    })
}

/// Each triangle turned to start at its least corner, sorted: two sets of oriented
/// triangles are the same exactly when these are.
fn canonical(tris: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut out: Vec<[u32; 3]> = (tris.iter())
        .map(|&[a, b, c]| match a.min(b).min(c) {
            m if m == a => [a, b, c],
            m if m == b => [b, c, a],
            _ => [c, a, b],
        })
        .collect();
    out.sort_unstable();
    out
}

/// Splits the triangles `tris` (a triangulated surface piece) at each point of `points`
/// that lies on one of them, inside it (into three) or inside an edge it shares with
/// another triangle of `tris` (both into two): a point on a surface is a vertex of it.
/// Returns how many points were inserted; a point inside an edge of `tris`'s boundary
/// is refused (the triangle outside would keep the unsplit edge).
fn refine(pts: &[Point3], tris: &mut Vec<[u32; 3]>, points: &[u32]) -> Result<usize, Refused> {
    let mut inserted = 0;
    for &q in points {
        let x = &pts[q as usize];
        let Some((i, place)) = tris
            .iter()
            .enumerate()
            .find_map(|(i, t)| locate(pts, t, x).map(|p| (i, p)))
        else {
            continue;
        };
        let t = tris[i];
        match place {
            Place::Inside => {
                tris[i] = [t[0], t[1], q];
                tris.push([t[1], t[2], q]);
                tris.push([t[2], t[0], q]);
            }
            Place::Edge(k) => {
                let (a, b, c) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
                let twin = tris
                    .iter()
                    .position(|u| (0..3).any(|m| u[m] == b && u[(m + 1) % 3] == a))
                    .ok_or(Refused(
                        "a hidden point lies on the edge of the removed region",
                    ))?;
                let u = tris[twin];
                let m = (0..3).find(|&m| u[m] == b).unwrap_or(0);
                let d = u[(m + 2) % 3];
                tris[i] = [a, q, c];
                tris.push([q, b, c]);
                tris[twin] = [b, q, d];
                tris.push([q, a, d]);
            }
        }
        inserted += 1;
    }
    Ok(inserted)
}

/// Where a point lies on a triangle.
enum Place {
    Inside,
    /// Inside edge `k` (from corner `k` to corner `k + 1`).
    Edge(usize),
}

/// The planes of the facets of `CH(pts)`, the inside negative (none when it is flat).
fn hull_planes(pts: &[Point3]) -> Vec<Plane> {
    let hull = Hull3::facets_only(pts);
    if hull.dimension < 3 {
        return Vec::new();
    }
    let p = |k: u32| &pts[k as usize];
    hull.facet_planes
        .iter()
        .map(|f| Plane::new(p(f[0]), p(f[1]), p(f[2])))
        .collect()
}

/// Where `x` lies on the closed triangle `t`, if it does (exact: coplanar, then the
/// three edge sides in a projection that keeps the triangle non-degenerate).
fn locate(pts: &[Point3], t: &[u32; 3], x: &Point3) -> Option<Place> {
    let p = |k: usize| &pts[t[k] as usize];
    // A point of the closed triangle lies in its box (exact comparisons): most
    // triangles are rejected before the exact plane test, which is slow on coplanar input.
    let outside_box = (0..3).any(|d| {
        let c = [p(0)[d], p(1)[d], p(2)[d]];
        x[d] < c[0].min(c[1]).min(c[2]) || x[d] > c[0].max(c[1]).max(c[2])
    });
    if outside_box || orient3d(p(0), p(1), p(2), x) != 0 {
        return None;
    }
    let axis = projection_axis(p(0), p(1), p(2))?;
    let o = orient2d_drop(p(0), p(1), p(2), axis);
    let sides = [0, 1, 2].map(|k| orient2d_drop(p(k), p((k + 1) % 3), x, axis));
    if sides.iter().any(|&s| s == -o) {
        return None;
    }
    match sides.iter().filter(|&&s| s == 0).count() {
        0 => Some(Place::Inside),
        1 => sides.iter().position(|&s| s == 0).map(Place::Edge),
        _ => None, // a corner: already a vertex
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`simplicial_hull`] against [`Hull3`] on 4 to 9 points: random floats (general
    /// position) and points of a `3 × 3 × 3` grid (four on a plane everywhere). It
    /// answers exactly when the hull is simplicial with every point a corner and no
    /// fourth point on a facet's plane, and then with the hull's triangles.
    #[test]
    fn small_hulls_agree_with_hull3() {
        let mut rng = crate::rng::Rng::new(41);
        let (mut answered, mut declined) = (0, 0);
        for case in 0..6000 {
            let n = 4 + case % 6;
            let grid = case % 3 == 0;
            let mut pts: Vec<Point3> = Vec::new();
            while pts.len() < n {
                let p = match grid {
                    true => [0; 3].map(|_| rng.below(3) as f64),
                    false => [0; 3].map(|_| rng.unit()),
                };
                if !pts.contains(&p) {
                    pts.push(p);
                }
            }
            let ring: Vec<u32> = (0..n as u32).collect();
            let hull = Hull3::new(&pts);
            let plain = hull.dimension == 3
                && hull.facet_count() == hull.triangles.len()
                && (0..n).all(|i| hull.facets_of(i).len() >= 3)
                && hull.triangles.iter().all(|t| {
                    let on = |x: &Point3| {
                        orient3d(
                            &pts[t[0] as usize],
                            &pts[t[1] as usize],
                            &pts[t[2] as usize],
                            x,
                        ) == 0
                    };
                    pts.iter().filter(|x| on(x)).count() == 3
                });
            let got = simplicial_hull(&pts, &ring);
            assert_eq!(
                got.is_some(),
                plain && n <= SMALL_RING,
                "case {case}: {pts:?}"
            );
            if let Some(tris) = got {
                assert_eq!(canonical(&tris), canonical(&hull.triangles), "case {case}");
                answered += 1;
            } else {
                declined += 1;
            }
        }
        assert!(answered > 2000 && declined > 2000, "{answered} {declined}");
    }

    /// [`flat_fan`] against the cone's hull on 3 to 8 points of a tilted plane's integer
    /// grid (collinear points and points inside the polygon common), the tip off the plane
    /// or in it. It answers exactly when the tip is off the plane and every point is a
    /// corner of the polygon, and then with `k − 2` triangles facing the tip whose boundary
    /// (the directed edges without their reverse) is the base of the cone's hull, reversed.
    #[test]
    fn flat_fans_agree_with_the_cone_hull() {
        let mut rng = crate::rng::Rng::new(7);
        let boundary = |tris: &[[u32; 3]]| {
            let e: Vec<(u32, u32)> = (tris.iter())
                .flat_map(|t| (0..3).map(move |i| (t[i], t[(i + 1) % 3])))
                .collect();
            let mut b: Vec<_> = e
                .iter()
                .filter(|&&(a, b)| !e.contains(&(b, a)))
                .copied()
                .collect();
            b.sort_unstable();
            b
        };
        let (mut answered, mut declined) = (0, 0);
        for case in 0..4000 {
            let n = 3 + case % 6;
            let mut pts: Vec<Point3> = Vec::new();
            while pts.len() < n {
                let (x, y) = (rng.below(4) as f64, rng.below(4) as f64);
                let p = [x, y, 2.0 * x - y];
                if !pts.contains(&p) {
                    pts.push(p);
                }
            }
            let (x, y) = (rng.below(4) as f64, rng.below(4) as f64);
            let lift = [0.0, 1.0, -3.0][case % 3];
            pts.push([x, y, 2.0 * x - y + lift]);
            let (ring, tip): (Vec<u32>, u32) = ((0..n as u32).collect(), n as u32);
            let cone = Hull3::new(&pts);
            let flat: Vec<Point3> = pts[..n].to_vec();
            let corners = Hull3::new(&flat);
            let convex = corners.dimension == 2 && {
                let axis = projection_axis(&pts[0], &pts[1], &pts[2])
                    .or_else(|| (3..n).find_map(|k| projection_axis(&pts[0], &pts[1], &pts[k])));
                axis.is_some_and(|ax| {
                    let d: Vec<_> = flat.iter().map(|p| drop_axis(p, ax)).collect();
                    Hull2::new(&d).vertices.len() == n
                })
            };
            let got = flat_fan(&pts, &ring, tip);
            assert_eq!(got.is_some(), lift != 0.0 && convex, "case {case}: {pts:?}");
            let Some(tris) = got else {
                declined += 1;
                continue;
            };
            answered += 1;
            assert_eq!(tris.len(), n - 2, "case {case}");
            let p = |v: u32| &pts[v as usize];
            assert!(
                tris.iter()
                    .all(|t| orient3d(p(t[0]), p(t[1]), p(t[2]), p(tip)) > 0)
            );
            let base: Vec<[u32; 3]> = (cone.triangles.iter())
                .filter(|t| !t.contains(&tip))
                .map(|t| [t[0], t[2], t[1]])
                .collect();
            assert_eq!(boundary(&tris), boundary(&base), "case {case}: {pts:?}");
        }
        assert!(answered > 500 && declined > 1000, "{answered} {declined}");
    }
}
