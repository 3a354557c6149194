//! Exact incremental 3D convex hull with conflict lists (Clarkson–Shor), degenerate input
//! allowed.
//!
//! The hull surface is kept as outward-oriented triangles; a point becomes a vertex only
//! when it is *strictly* beyond some triangle, so points on the hull that are not needed
//! stay off the surface. Coplanar neighbouring triangles are merged into polygon
//! [facets](Hull3::facet_planes) afterwards, and every input point is told exactly which
//! facets it lies on, so "is `p` on the boundary", "is triangle `abc` on the boundary" and
//! "which points lie on this polytope edge" are exact questions.
//!
//! Correctness of the degenerate case rests on two facts: the triangles strictly visible
//! from an outside point form a disk (visibility is per facet plane), and a point outside
//! the new hull that saw a deleted triangle sees one of the new triangles, so orphaned
//! conflict points need only be tested against new triangles.

use super::predicates::{
    Plane, PlaneFilter, Point3, collinear3, lex_cmp, orient3d, orient3d_unfiltered,
};
use crate::partition;
use rayon::prelude::*;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

const NONE: u32 = u32::MAX;

/// New triangles an orphaned conflict point is tested against in order before the search
/// starts where the last orphan's ended (`Builder::insert`). Small cones, the common case,
/// keep the plain first-seen choice and so the same hulls as before.
const FIRST_SCANNED: usize = 32;

/// Below this many points [`FacetGrid`] is one cell (its resolution would be 1).
const SMALL_GRID: usize = 64;

/// The most triangles a [`Builder`] reserves room for at once.
const ROOM_MAX: usize = 1 << 21;

/// The convex hull of a point set in 3D.
///
/// ```
/// use tetrakit::geom::Hull3;
/// // A unit cube with a point in the middle of the bottom face and one inside.
/// let mut pts = vec![];
/// for i in 0..8 { pts.push([(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64]); }
/// pts.push([0.5, 0.5, 0.0]);
/// pts.push([0.5, 0.5, 0.5]);
/// let h = Hull3::new(&pts);
/// assert_eq!(h.dimension, 3);
/// assert_eq!(h.facet_planes.len(), 6);
/// assert!(h.on_boundary(8) && !h.on_boundary(9));
/// ```
#[derive(Clone, Debug, Default)]
pub struct Hull3 {
    /// Affine dimension of the point set: 0 (all equal), 1, 2 or 3.
    pub dimension: usize,
    /// Outward-oriented triangles of the hull surface (empty unless `dimension == 3`).
    pub triangles: Vec<[u32; 3]>,
    /// The facet of each triangle.
    pub triangle_facet: Vec<u32>,
    /// For each facet, three non-collinear points on it, oriented so that every point `x`
    /// has `orient3d(p0, p1, p2, x) <= 0`.
    pub facet_planes: Vec<[u32; 3]>,
    /// `neighbours[t][i]`: the triangle across edge `i` of triangle `t` (from its corner
    /// `i` to corner `i + 1`).
    neighbours: Vec<[u32; 3]>,
    facet_start: Vec<u32>,
    facet_list: Vec<u32>,
}

struct Tri {
    v: [u32; 3],
    nb: [u32; 3],
    /// The triangle's place in the order of creation ([`NONE`]: deleted, its slot free).
    /// Slots are reused, so this, not the slot, orders the triangles.
    born: u32,
    /// The last insertion that looked at this triangle ([`Builder::insert`]).
    seen: u32,
    /// The first and last points of its conflict list ([`NONE`]: empty), linked on
    /// through [`Builder::next`]: no allocation per triangle.
    first: u32,
    last: u32,
}

impl Tri {
    fn alive(&self) -> bool {
        self.born != NONE
    }

    fn new(v: [u32; 3], nb: [u32; 3], born: u32) -> Tri {
        Tri {
            v,
            nb,
            born,
            seen: 0,
            first: NONE,
            last: NONE,
        }
    }
}

impl Hull3 {
    /// Computes the hull of `points` exactly. Duplicate points are allowed.
    pub fn new(points: &[Point3]) -> Hull3 {
        let (mut h, inside) = Hull3::build(points);
        if h.dimension == 3 {
            h.assign_points(points, &inside);
        }
        h
    }

    /// The hull's triangles and facets, without telling each point which facets it lies
    /// on ([`Hull3::facets_of`] is empty for every point): what a caller that needs only
    /// the facet planes pays (the assignment is most of a small hull's cost).
    pub fn facets_only(points: &[Point3]) -> Hull3 {
        Hull3::build(points).0
    }

    /// The hull's triangles and facets, and which points the construction proved
    /// strictly inside ([`Builder::inside`]; empty when flat).
    fn build(points: &[Point3]) -> (Hull3, Vec<bool>) {
        let Some((seed, dimension)) = initial_simplex(points) else {
            let h = Hull3 {
                dimension: affine_dimension(points),
                ..Default::default()
            };
            return (h, Vec::new());
        };
        let mut b = Builder::new(points);
        b.start(seed, 0..points.len() as u32);
        b.run();
        let (triangles, neighbours) = b.alive();
        let mut h = Hull3 {
            dimension,
            triangles,
            ..Default::default()
        };
        h.build_facets(points, &neighbours, |_, _| None);
        h.neighbours = neighbours;
        (h, b.inside)
    }

    /// The hull of `points`, whose first ones must be the points this hull was built on
    /// (the same, in the same order), from a copy of it with the others inserted one by
    /// one: for a few points added to a large hull, a fraction of building it anew.
    /// `None` when this hull is flat or has more points than `points`.
    ///
    /// A point added that sees no triangle strictly is on or inside the hull and is not
    /// inserted. A corner whose triangles are all gone is strictly inside: the point
    /// inserted that saw them all strictly lies beyond every plane of its triangles, so
    /// the corner is inside the segment from that point to a point strictly inside the
    /// old hull. With the points strictly inside this hull, those are not looked up;
    /// points on its boundary that are no corner are (see [`Hull3::facets_of`]).
    pub(crate) fn extended(&self, points: &[Point3]) -> Option<Hull3> {
        let base = self.facet_start.len().checked_sub(1)?;
        if self.dimension != 3 || points.len() < base {
            return None;
        }
        let mut b = Builder::new(points);
        for (v, nb) in self.triangles.iter().zip(&self.neighbours) {
            b.push(*v, *nb);
        }
        let mut was_corner = vec![false; points.len()];
        for &v in self.triangles.iter().flatten() {
            was_corner[v as usize] = true;
        }
        for i in 0..base {
            b.inside[i] = !self.on_boundary(i);
        }
        for q in base as u32..points.len() as u32 {
            let seen = (0..b.tris.len()).find(|&t| b.tris[t].alive() && b.sees(t, q));
            if let Some(t) = seen {
                b.insert(t, q);
                was_corner[q as usize] = true;
            }
        }
        let (triangles, neighbours) = b.alive();
        // The triangles kept, by their number here (they were made first, in order).
        let mut born: Vec<u32> = (b.tris.iter())
            .filter(|t| t.alive())
            .map(|t| t.born)
            .collect();
        born.sort_unstable();
        let kept = |t: usize| Some(born[t] as usize).filter(|&k| k < self.triangles.len());
        // Two kept neighbours are coplanar exactly when they were in one facet here.
        let coplanar = |t: usize, u: usize| {
            let facet = |k: usize| self.triangle_facet[k];
            Some(facet(kept(t)?) == facet(kept(u)?))
        };
        let mut corner = vec![false; points.len()];
        for &v in triangles.iter().flatten() {
            corner[v as usize] = true;
        }
        let mut inside = b.inside;
        for (i, inside) in inside.iter_mut().enumerate() {
            *inside |= was_corner[i] && !corner[i];
        }
        let mut h = Hull3 {
            dimension: 3,
            triangles,
            ..Default::default()
        };
        h.build_facets(points, &neighbours, coplanar);
        h.neighbours = neighbours;
        h.assign_points(points, &inside);
        Some(h)
    }

    /// The triangle across edge `i` of triangle `t` (the edge from its corner `i` to
    /// corner `i + 1`, taken the other way there).
    pub fn neighbour(&self, t: usize, i: usize) -> usize {
        self.neighbours[t][i] as usize
    }

    /// The same hull on renumbered points: point `k` of the new numbering is point
    /// `old[k]` (it takes its facets), and `new(i)` is the new number of point `i` (a
    /// repeated point may be named as another copy of itself). `None` when a corner of a
    /// triangle has no new number.
    pub(crate) fn renumbered(self, old: &[u32], new: impl Fn(u32) -> Option<u32>) -> Option<Hull3> {
        let rename = |ts: &[[u32; 3]]| -> Option<Vec<[u32; 3]>> {
            ts.iter()
                .map(|t| Some([new(t[0])?, new(t[1])?, new(t[2])?]))
                .collect()
        };
        let (triangles, facet_planes) = (rename(&self.triangles)?, rename(&self.facet_planes)?);
        let mut facet_start = Vec::with_capacity(old.len() + 1);
        let mut facet_list = Vec::with_capacity(self.facet_list.len());
        facet_start.push(0);
        for &i in old {
            facet_list.extend_from_slice(self.facets_of(i as usize));
            facet_start.push(facet_list.len() as u32);
        }
        Some(Hull3 {
            dimension: self.dimension,
            triangles,
            triangle_facet: self.triangle_facet,
            facet_planes,
            neighbours: self.neighbours,
            facet_start,
            facet_list,
        })
    }

    /// Number of facets (maximal coplanar polygons).
    pub fn facet_count(&self) -> usize {
        self.facet_planes.len()
    }

    /// Facets containing point `i`, sorted (empty for interior points).
    pub fn facets_of(&self, i: usize) -> &[u32] {
        if self.facet_start.is_empty() {
            return &[];
        }
        &self.facet_list[self.facet_start[i] as usize..self.facet_start[i + 1] as usize]
    }

    /// True when point `i` lies on the boundary of the hull (3D hulls only).
    pub fn on_boundary(&self, i: usize) -> bool {
        !self.facets_of(i).is_empty()
    }

    /// A facet containing all three points, if any: then triangle `abc` lies on the hull
    /// boundary.
    pub fn common_facet(&self, a: usize, b: usize, c: usize) -> Option<u32> {
        // Each list is sorted: the shortest is scanned, the others searched (a corner of
        // a fan, such as a bent arc's end, is on tens of thousands of facets).
        let mut lists = [self.facets_of(a), self.facets_of(b), self.facets_of(c)];
        lists.sort_unstable_by_key(|l| l.len());
        let [short, x, y] = lists;
        short
            .iter()
            .copied()
            .find(|f| x.binary_search(f).is_ok() && y.binary_search(f).is_ok())
    }

    /// Points lying on each edge of the polytope, sorted along the edge: consecutive
    /// entries must be joined in any tetrahedralization of the points.
    pub fn polytope_edges(&self, points: &[Point3]) -> Vec<Vec<u32>> {
        let mut adjacent: HashSet<(u32, u32)> = HashSet::default();
        let edges = self.triangle_edges();
        for (&(a, b), &(t, _)) in &edges {
            if let Some(&(u, _)) = edges.get(&(b, a)) {
                let (f, g) = (self.triangle_facet[t], self.triangle_facet[u]);
                if f != g {
                    adjacent.insert((f.min(g), f.max(g)));
                }
            }
        }
        let mut groups: HashMap<(u32, u32), Vec<u32>> = HashMap::default();
        for p in 0..points.len() {
            let fs = self.facets_of(p);
            for (k, &f) in fs.iter().enumerate() {
                for &g in &fs[k + 1..] {
                    let key = (f.min(g), f.max(g));
                    if adjacent.contains(&key) {
                        groups.entry(key).or_default().push(p as u32);
                    }
                }
            }
        }
        let mut out: Vec<Vec<u32>> = groups.into_values().collect();
        for g in &mut out {
            g.sort_by(|&a, &b| lex_cmp(&points[a as usize], &points[b as usize]));
        }
        out.sort();
        out
    }

    fn triangle_edges(&self) -> HashMap<(u32, u32), (usize, usize)> {
        let mut m = HashMap::with_capacity_and_hasher(self.triangles.len() * 3, Default::default());
        for (t, tri) in self.triangles.iter().enumerate() {
            for i in 0..3 {
                let [a, b] = edge_of(tri, i);
                m.insert((a, b), (t, i));
            }
        }
        m
    }

    /// Joins neighbouring coplanar triangles into facets (`neighbours[t][i]` is the
    /// triangle across edge `i` of triangle `t`).
    ///
    /// `coplanar(t, u)`, when `Some`, tells whether neighbours `t` and `u` are coplanar
    /// without a predicate.
    fn build_facets(
        &mut self,
        pts: &[Point3],
        neighbours: &[[u32; 3]],
        coplanar: impl Fn(usize, usize) -> Option<bool>,
    ) {
        let n = self.triangles.len();
        let mut parent = partition::singletons(n);
        let p = |i: u32| &pts[i as usize];
        for (t, nb) in neighbours.iter().enumerate() {
            let tv = self.triangles[t];
            for &u in nb.iter().filter(|&&u| u as usize > t) {
                let flat = coplanar(t, u as usize).unwrap_or_else(|| {
                    let apex = *self.triangles[u as usize]
                        .iter()
                        .find(|x| !tv.contains(x))
                        .expect("neighbouring triangles share two corners");
                    orient3d(p(tv[0]), p(tv[1]), p(tv[2]), p(apex)) == 0
                });
                if flat {
                    partition::union(&mut parent, t as u32, u);
                }
            }
        }
        let mut id = vec![NONE; n];
        self.triangle_facet = (0..n)
            .map(|t| {
                let r = partition::find(&mut parent, t as u32) as usize;
                if id[r] == NONE {
                    id[r] = self.facet_planes.len() as u32;
                    self.facet_planes.push(self.triangles[r]);
                }
                id[r]
            })
            .collect();
    }

    /// The facets of the triangles at each point, sorted and without repeats (empty for
    /// points that are no triangle's corner), as `(start, list)`: point `i`'s are
    /// `list[start[i]..start[i + 1]]`.
    fn incident_facets(&self, n: usize) -> (Vec<u32>, Vec<u32>) {
        let mut start = vec![0u32; n + 1];
        for &v in self.triangles.iter().flatten() {
            start[v as usize + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut list = vec![0u32; start[n] as usize];
        for (t, &f) in self.triangles.iter().zip(&self.triangle_facet) {
            for &v in t {
                list[fill[v as usize] as usize] = f;
                fill[v as usize] += 1;
            }
        }
        // Sort and deduplicate each point's run, compacting the list.
        let mut kept = 0;
        for i in 0..n {
            let (a, b) = (start[i] as usize, start[i + 1] as usize);
            list[a..b].sort_unstable();
            start[i] = kept as u32;
            for k in a..b {
                if k == a || list[k] != list[k - 1] {
                    list[kept] = list[k];
                    kept += 1;
                }
            }
        }
        start[n] = kept as u32;
        list.truncate(kept);
        (start, list)
    }

    /// Tells each point the facets it lies on; `inside[i]`: point `i` is known to be
    /// strictly inside (on none).
    fn assign_points(&mut self, pts: &[Point3], inside: &[bool]) {
        let (start, incident) = self.incident_facets(pts.len());
        // The planes and the grid only for points that are neither corners nor known to
        // be inside (few on a small hull, none on most).
        let lookup = std::sync::OnceLock::new();
        let on = |i: usize, x: &Point3, out: &mut Vec<u32>| {
            // A triangle's corner lies on exactly the facets of its triangles (the
            // surface is embedded: no other triangle holds it), so they name them all;
            // a point that is no triangle's corner is looked up.
            let at = &incident[start[i] as usize..start[i + 1] as usize];
            if !at.is_empty() {
                out.extend_from_slice(at);
                return;
            }
            if inside[i] {
                return;
            }
            let (planes, grid): &(Vec<Plane>, FacetGrid) = lookup.get_or_init(|| {
                let p = |k: u32| &pts[k as usize];
                let planes = (self.facet_planes.iter())
                    .map(|f| Plane::new(p(f[0]), p(f[1]), p(f[2])))
                    .collect();
                (planes, FacetGrid::new(pts, self))
            });
            let on_plane = |f: &u32| planes[*f as usize].side(x) == 0;
            out.extend(grid.candidates(x).iter().filter(|f| on_plane(f)));
        };
        let mut facet_start = Vec::with_capacity(pts.len() + 1);
        let mut facet_list = Vec::with_capacity(incident.len());
        facet_start.push(0);
        // Small hulls (the shell's local ones, thousands a second) stay on this thread.
        if pts.len() < 4096 {
            for (i, x) in pts.iter().enumerate() {
                on(i, x, &mut facet_list);
                facet_start.push(facet_list.len() as u32);
            }
        } else {
            let lists: Vec<Vec<u32>> = (pts.par_iter().enumerate())
                .map(|(i, x)| {
                    let mut l = Vec::new();
                    on(i, x, &mut l);
                    l
                })
                .collect();
            for l in &lists {
                facet_list.extend_from_slice(l);
                facet_start.push(facet_list.len() as u32);
            }
        }
        (self.facet_start, self.facet_list) = (facet_start, facet_list);
    }
}

/// A coarse grid over the bounding box listing, per cell, the facets whose plane may pass
/// through the cell. The float box–plane test is padded far beyond its rounding error, so
/// it only skips facets whose plane provably misses the cell; membership itself is decided
/// by the exact [`Plane::side`].
struct FacetGrid {
    lo: Point3,
    inv: Point3,
    res: usize,
    start: Vec<u32>,
    list: Vec<u32>,
}

impl FacetGrid {
    fn new(pts: &[Point3], hull: &Hull3) -> Self {
        let facets = &hull.facet_planes;
        let (lo, hi) = super::predicates::bounding_box(pts);
        if pts.len() < SMALL_GRID {
            // One cell holding every facet: what the grid below would make, without its
            // planes and boxes (a small hull's lookups are few).
            return FacetGrid {
                lo,
                inv: [0.0; 3],
                res: 1,
                start: vec![0, facets.len() as u32],
                list: (0..facets.len() as u32).collect(),
            };
        }
        // A point on a facet's plane lies in the facet (the plane supports the hull), so
        // only the cells of the facet's bounding box can hold it.
        let mut boxes = vec![([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]); facets.len()];
        for (t, &f) in hull.triangles.iter().zip(&hull.triangle_facet) {
            let b = &mut boxes[f as usize];
            for &v in t {
                for (k, &x) in pts[v as usize].iter().enumerate() {
                    b.0[k] = b.0[k].min(x);
                    b.1[k] = b.1[k].max(x);
                }
            }
        }
        // About one cell per 64 points, at most 64 per side.
        let res = ((pts.len() as f64 / 64.0).cbrt().ceil() as usize).clamp(1, 64);
        let size: Point3 =
            std::array::from_fn(|k| ((hi[k] - lo[k]) / res as f64).max(f64::MIN_POSITIVE));
        let inv = size.map(|s| 1.0 / s);
        let cells = res * res * res;
        let mut per_cell: Vec<Vec<u32>> = vec![Vec::new(); cells];
        for (fi, f) in facets.iter().enumerate() {
            let (a, b, c) = (pts[f[0] as usize], pts[f[1] as usize], pts[f[2] as usize]);
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let n = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            let nn = n[0].abs() + n[1].abs() + n[2].abs();
            let scale: f64 = (0..3)
                .map(|k| hi[k].abs().max(lo[k].abs()))
                .fold(0.0, f64::max);
            // The rounding of `n` is about `ε |u| |w|`, which a thin triangle's `|n|` need
            // not dominate: the pad covers both.
            let uw = u.iter().fold(0.0f64, |m, x| m.max(x.abs()))
                * w.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let pad = 1e-6
                * (nn + 1e-4 * uw)
                * (scale + 1.0 + size.iter().fold(0.0f64, |m, s| m.max(*s)));
            // The same (monotone) cell formula as `candidates`, so a point inside the box
            // is in a cell of this range.
            let cell_of = |x: f64, k: usize| (((x - lo[k]) * inv[k]) as usize).min(res - 1);
            let (blo, bhi) = boxes[fi];
            let range: [std::ops::RangeInclusive<usize>; 3] =
                std::array::from_fn(|k| cell_of(blo[k], k)..=cell_of(bhi[k], k));
            // The cells of each column along the normal's largest axis `d` that the
            // plane can meet (widened by a cell and the pad), not the whole box: a long
            // facet's box is most of the grid.
            let d = (0..3)
                .max_by(|&x, &y| n[x].abs().total_cmp(&n[y].abs()))
                .unwrap_or(2);
            let (i, j) = ((d + 1) % 3, (d + 2) % 3);
            let widened = |k: usize, c: usize| {
                let margin = 1e-6 * size[k] + 1e-9 * scale;
                let c0 = lo[k] + c as f64 * size[k] - margin;
                (c0, c0 + size[k] + 2.0 * margin)
            };
            let column = |x: usize, y: usize| -> std::ops::RangeInclusive<usize> {
                if n[d] == 0.0 {
                    return range[d].clone();
                }
                let ((x0, x1), (y0, y1)) = (widened(i, x), widened(j, y));
                let heights = [(x0, y0), (x0, y1), (x1, y0), (x1, y1)]
                    .map(|(u, v)| a[d] - (n[i] * (u - a[i]) + n[j] * (v - a[j])) / n[d]);
                let slack = size[d] + 1e-9 * scale + pad / n[d].abs();
                if heights.iter().any(|h| h.is_nan()) {
                    return range[d].clone();
                }
                // Below the grid a cell index is 0, above it `res − 1` (saturating).
                let from = cell_of(
                    heights.iter().fold(f64::INFINITY, |m, &h| m.min(h)) - slack,
                    d,
                );
                let to = cell_of(
                    heights.iter().fold(f64::NEG_INFINITY, |m, &h| m.max(h)) + slack,
                    d,
                );
                from.max(*range[d].start())..=to.min(*range[d].end())
            };
            for x in range[i].clone() {
                for y in range[j].clone() {
                    for z in column(x, y) {
                        let mut idx = [0; 3];
                        (idx[i], idx[j], idx[d]) = (x, y, z);
                        let cell = (idx[0] * res + idx[1]) * res + idx[2];
                        // Signed distances (times |n|) of the cell's corners from the plane.
                        let (mut dmin, mut dmax) = (0.0f64, 0.0f64);
                        for k in 0..3 {
                            // The cell, widened far beyond the rounding of the cell index
                            // computed for a point (a point may be filed one ulp across a
                            // cell boundary).
                            let (c0, c1) = widened(k, idx[k]);
                            let (c0, c1) = (c0 - a[k], c1 - a[k]);
                            dmin += (n[k] * c0).min(n[k] * c1);
                            dmax += (n[k] * c0).max(n[k] * c1);
                        }
                        if dmin <= pad && dmax >= -pad {
                            per_cell[cell].push(fi as u32);
                        }
                    }
                }
            }
        }
        let mut start = Vec::with_capacity(cells + 1);
        let mut list = Vec::new();
        start.push(0);
        for l in per_cell {
            list.extend(l);
            start.push(list.len() as u32);
        }
        FacetGrid {
            lo,
            inv,
            res,
            start,
            list,
        }
    }

    fn candidates(&self, p: &Point3) -> &[u32] {
        let cell: [usize; 3] = std::array::from_fn(|k| {
            (((p[k] - self.lo[k]) * self.inv[k]) as usize).min(self.res - 1)
        });
        let c = (cell[0] * self.res + cell[1]) * self.res + cell[2];
        &self.list[self.start[c] as usize..self.start[c + 1] as usize]
    }
}

fn edge_of(t: &[u32; 3], i: usize) -> [u32; 2] {
    [t[i], t[(i + 1) % 3]]
}

/// Affine dimension of a point set (exact).
pub fn affine_dimension(points: &[Point3]) -> usize {
    match initial_simplex(points) {
        Some((_, d)) => d,
        None => {
            let Some(a) = points.first() else { return 0 };
            let Some(b) = points.iter().find(|p| *p != a) else {
                return 0;
            };
            if points.iter().all(|c| collinear3(a, b, c)) {
                1
            } else {
                2
            }
        }
    }
}

/// The placing (beneath–beyond) triangulation of the region between two nested hulls:
/// the boundary of `CH(first)` as the triangles of a first hull, then each point of
/// `then`, in order, coned to the triangles of the current hull it strictly sees. The
/// tetrahedra, positively oriented, tile `CH(first ∪ then) − int CH(first)` with no point
/// added; `None` when `first` is flat.
///
/// Why it never fails, in any order and on any degenerate input: the triangles a point
/// `p` outside a convex polytope `H` strictly sees form a disk (visibility is per facet
/// plane, and the visible planes are connected), the cones over them tile
/// `CH(H ∪ {p}) − H`, and the new triangles from `p` to the disk's horizon close the
/// surface again; where `p` lies in the plane of a facet it does not see, the triangles
/// at that facet's horizon edges extend the facet and make no tetrahedron. A point of
/// `then` that is not strictly outside the current hull when its turn comes is skipped
/// (it is no vertex). The count depends on the order: placing in the reverse of a cap
/// removal's order fills the removal's caps again, each the same region (triangulated
/// alike up to the choice of diagonals in coplanar facets).
///
/// ```
/// use tetrakit::geom::placing;
/// let mut pts: Vec<[f64; 3]> = (0..8)
///     .map(|i| [(i & 1) as f64 * 4.0, ((i >> 1) & 1) as f64 * 4.0, (i >> 2) as f64 * 4.0])
///     .collect();
/// pts.extend([[1.0, 1.0, 1.0], [3.0, 1.0, 1.0], [1.0, 3.0, 1.0], [1.0, 1.0, 3.0]]);
/// let tets = placing(&pts, &[8, 9, 10, 11], &[0, 1, 2, 3, 4, 5, 6, 7]).unwrap();
/// // Six volume: the cube's 384 less the inner tetrahedron's 8.
/// let six: f64 = tets.iter().map(|t| tetrakit::geom::orient3d_value(
///     &pts[t[0] as usize], &pts[t[1] as usize], &pts[t[2] as usize], &pts[t[3] as usize]).estimate()).sum();
/// assert_eq!(six, 376.0);
/// ```
pub fn placing(points: &[Point3], first: &[u32], then: &[u32]) -> Option<Vec<[u32; 4]>> {
    let first_points: Vec<Point3> = first.iter().map(|&i| points[i as usize]).collect();
    let (seed, _) = initial_simplex(&first_points)?;
    let seed = seed.map(|k| first[k as usize]);
    let mut b = Builder::new(points);
    let mut eligible = vec![false; points.len()];
    for &q in first {
        eligible[q as usize] = true;
    }
    let mut candidates: Vec<u32> = first.iter().chain(then).copied().collect();
    candidates.sort_unstable();
    candidates.dedup();
    b.eligible = Some(eligible);
    b.start(seed, candidates.into_iter());
    b.run();
    b.tets = Some(Vec::new());
    for &q in then {
        let t = b.owner[q as usize];
        if t != NONE {
            b.insert(t as usize, q);
        }
    }
    b.tets
}

/// Four affinely independent points, or `None` when the set is flat.
pub(super) fn initial_simplex(pts: &[Point3]) -> Option<([u32; 4], usize)> {
    let lo = (0..pts.len()).min_by(|&i, &j| lex_cmp(&pts[i], &pts[j]))?;
    let hi = (0..pts.len()).max_by(|&i, &j| lex_cmp(&pts[i], &pts[j]))?;
    if pts[lo] == pts[hi] {
        return None;
    }
    let c = (0..pts.len()).find(|&k| !collinear3(&pts[lo], &pts[hi], &pts[k]))?;
    let d = (0..pts.len()).find(|&k| orient3d(&pts[lo], &pts[hi], &pts[c], &pts[k]) != 0)?;
    Some(([lo as u32, hi as u32, c as u32, d as u32], 3))
}

struct Builder<'a> {
    pts: &'a [Point3],
    /// The triangles by slot: a deleted triangle's slot is taken by the next one made,
    /// so the slots in use never outnumber the hull's triangles (a hull of `n` points
    /// makes about five triangles a point in all, and has at most `2n - 4` at a time):
    /// fewer fresh pages, and the live triangles closer together.
    tris: Vec<Tri>,
    /// Each slot's plane filter, for its many visibility tests ([`Builder::sees`]).
    planes: Vec<PlaneFilter>,
    /// The free slots.
    free: Vec<u32>,
    /// The triangles made so far.
    made: u32,
    /// The triangle whose conflict list holds each point ([`NONE`]: none).
    owner: Vec<u32>,
    /// The point after each one in its conflict list ([`NONE`]: the last).
    next: Vec<u32>,
    /// The points [`Builder::run`] may insert (all when `None`).
    eligible: Option<Vec<bool>>,
    /// The points left out strictly behind every triangle they were last tested
    /// against, so strictly inside the hull (see [`Builder::insert`]): they need no
    /// facet lookup. False where unknown.
    inside: Vec<bool>,
    /// The tetrahedra each insertion makes with the triangles it sees, when recording.
    tets: Option<Vec<[u32; 4]>>,
    /// Insertions so far: the stamp of the triangles the current one has looked at.
    round: u32,
    /// Scratch space of [`Builder::insert`], kept between insertions.
    scratch: Scratch,
}

#[derive(Default)]
struct Scratch {
    visible: Vec<usize>,
    /// `(a, b, outer triangle, its edge index)` for each horizon edge `ab`.
    horizon: Vec<(u32, u32, usize, usize)>,
    orphans: Vec<u32>,
    /// `(a, k)` for each horizon edge `ab`, the `k`-th of the cone, sorted.
    by_start: Vec<(u32, usize)>,
}

impl<'a> Builder<'a> {
    fn p(&self, i: u32) -> &Point3 {
        &self.pts[i as usize]
    }

    fn sees(&self, t: usize, q: u32) -> bool {
        self.side(t, q) > 0
    }

    /// [`Builder::sees`], noting in `flat` when `q` is on the plane.
    fn sees_noting(&self, t: usize, q: u32, flat: &mut bool) -> bool {
        let side = self.side(t, q);
        *flat |= side == 0;
        side > 0
    }

    /// The exact side of triangle `t`'s plane `q` is on: 1 beyond, 0 on, −1 behind.
    fn side(&self, t: usize, q: u32) -> i8 {
        let v = self.tris[t].v;
        (self.planes[t].sign(self.p(v[0]), self.p(q))).unwrap_or_else(|| {
            orient3d_unfiltered(self.p(v[0]), self.p(v[1]), self.p(v[2]), self.p(q))
        })
    }

    /// Adds the triangle `v` with neighbours `nb`, in a free slot if there is one;
    /// returns its slot.
    fn push(&mut self, v: [u32; 3], nb: [u32; 3]) -> usize {
        let (a, b, c) = (self.p(v[0]), self.p(v[1]), self.p(v[2]));
        let (plane, tri) = (PlaneFilter::new(a, b, c), Tri::new(v, nb, self.made));
        self.made += 1;
        match self.free.pop() {
            Some(t) => {
                (self.planes[t as usize], self.tris[t as usize]) = (plane, tri);
                t as usize
            }
            None => {
                self.planes.push(plane);
                self.tris.push(tri);
                self.tris.len() - 1
            }
        }
    }

    fn new(pts: &'a [Point3]) -> Builder<'a> {
        // Room for every slot at once (at most `2n - 4` are ever in use, see `tris`), not
        // a vector regrown and copied a dozen times, each copy into fresh pages (a page
        // fault every 4 KiB, the dearest part of a cold hull).
        let room = (2 * pts.len() + 4).min(ROOM_MAX);
        Builder {
            pts,
            tris: Vec::with_capacity(room),
            planes: Vec::with_capacity(room),
            free: Vec::new(),
            made: 0,
            owner: vec![NONE; pts.len()],
            next: vec![NONE; pts.len()],
            eligible: None,
            inside: vec![false; pts.len()],
            tets: None,
            round: 0,
            scratch: Scratch::default(),
        }
    }

    /// Files `q` in the conflict list of triangle `t`.
    fn file(&mut self, t: usize, q: u32) {
        let tri = &mut self.tris[t];
        match tri.last {
            NONE => tri.first = q,
            l => self.next[l as usize] = q,
        }
        tri.last = q;
        self.next[q as usize] = NONE;
        self.owner[q as usize] = t as u32;
    }

    /// The conflict list of `t`, in filing order.
    fn conflicts(&self, t: usize) -> impl Iterator<Item = u32> + '_ {
        let first = Some(self.tris[t].first).filter(|&q| q != NONE);
        std::iter::successors(first, |&q| {
            Some(self.next[q as usize]).filter(|&n| n != NONE)
        })
    }

    /// Starts from the simplex `s`; the points of `candidates` outside it go in the
    /// conflict lists.
    fn start(&mut self, s: [u32; 4], candidates: impl Iterator<Item = u32>) {
        let [a, mut b, mut c, d] = s;
        if orient3d(self.p(a), self.p(b), self.p(c), self.p(d)) < 0 {
            std::mem::swap(&mut b, &mut c);
        }
        for v in [[b, c, d], [a, d, c], [a, b, d], [a, c, b]] {
            self.push(v, [NONE; 3]);
        }
        for t in 0..4 {
            for i in 0..3 {
                let [x, y] = edge_of(&self.tris[t].v, i);
                let twin = (0..4).find(|&u| (0..3).any(|j| edge_of(&self.tris[u].v, j) == [y, x]));
                self.tris[t].nb[i] = twin.expect("a tetrahedron's faces pair up") as u32;
            }
        }
        for q in candidates {
            if s.contains(&q) {
                continue;
            }
            let mut flat = false;
            match (0..4).find(|&t| self.sees_noting(t, q, &mut flat)) {
                Some(t) => self.file(t, q),
                None => self.inside[q as usize] = !flat,
            }
        }
    }

    /// The live triangles in the order they were made, and their neighbours across
    /// each edge.
    fn alive(&self) -> (Vec<[u32; 3]>, Vec<[u32; 3]>) {
        let mut slot_of = vec![NONE; self.made as usize];
        for (i, t) in self.tris.iter().enumerate().filter(|(_, t)| t.alive()) {
            slot_of[t.born as usize] = i as u32;
        }
        let order: Vec<u32> = slot_of.into_iter().filter(|&i| i != NONE).collect();
        let mut index = vec![NONE; self.tris.len()];
        for (k, &i) in order.iter().enumerate() {
            index[i as usize] = k as u32;
        }
        let tri = |i: u32| &self.tris[i as usize];
        let triangles = order.iter().map(|&i| tri(i).v).collect();
        let neighbours = (order.iter())
            .map(|&i| tri(i).nb.map(|n| index[n as usize]))
            .collect();
        (triangles, neighbours)
    }

    /// Inserts every eligible conflict point. The triangles are taken first in, first
    /// out: taking the newest first builds one side of a prism before the other, and
    /// every vertex of the second side then takes over a fan of the first (quadratic:
    /// 39 million triangles made for a 50,000-vertex twisted prism, 190,000 this way).
    fn run(&mut self) {
        // Each triangle with the place it was made in: a slot taken again since it was
        // queued holds another triangle.
        let mut work: std::collections::VecDeque<(usize, u32)> =
            (0..4).map(|t| (t, t as u32)).collect();
        while let Some((t, born)) = work.pop_front() {
            if self.tris[t].born != born {
                continue;
            }
            let Some(p) = self.furthest(t) else { continue };
            let new = self.insert(t, p);
            let waiting = new.into_iter().filter(|&u| self.tris[u].first != NONE);
            work.extend(waiting.map(|u| (u, self.tris[u].born)));
        }
    }

    /// The eligible conflict point of `t` furthest from its plane (by estimate: any
    /// conflict point is a correct choice).
    fn furthest(&self, t: usize) -> Option<u32> {
        let v = self.tris[t].v;
        let plane = Plane::new(self.p(v[0]), self.p(v[1]), self.p(v[2]));
        let eligible = |q: &u32| self.eligible.as_ref().is_none_or(|e| e[*q as usize]);
        self.conflicts(t).filter(eligible).max_by(|&a, &b| {
            plane
                .estimate(self.p(a))
                .total_cmp(&plane.estimate(self.p(b)))
        })
    }

    /// Adds `p` (strictly beyond triangle `t0`); returns the new triangles.
    fn insert(&mut self, t0: usize, p: u32) -> Vec<usize> {
        self.round += 1;
        let mut s = std::mem::take(&mut self.scratch);
        self.horizon(t0, p, &mut s);
        for &t in &s.visible {
            s.orphans.extend(self.conflicts(t));
            let tri = &mut self.tris[t];
            tri.born = NONE;
            (tri.first, tri.last) = (NONE, NONE);
            if let Some(tets) = &mut self.tets {
                let [a, b, c] = tri.v;
                tets.push([a, b, c, p]);
            }
        }
        // Free once every one is read: the cone takes these slots first.
        self.free.extend(s.visible.iter().map(|&t| t as u32));
        self.owner[p as usize] = NONE;
        let new = self.cone(p, &mut s);
        // Each orphan goes to the first new triangle it sees among the first
        // `FIRST_SCANNED`, else to the next one it sees from the last found on: orphans of
        // one old triangle come together and mostly see the same new one (on cocircular
        // prisms a scan of all from the first made a hull of 10^4 points take seconds:
        // thousands of new triangles per insertion).
        //
        // An orphan no new triangle sees is inside the new hull (see the module's doc)
        // and outside the old one (it saw a deleted triangle), so it is on the new
        // boundary only on a new triangle: strictly behind all of them, it is strictly
        // inside, for good (hulls only grow).
        let mut last = 0;
        for &q in s.orphans.iter().filter(|&&q| q != p) {
            self.owner[q as usize] = NONE;
            let mut flat = false;
            let mut sees = |u: &usize| self.sees_noting(*u, q, &mut flat);
            let first = FIRST_SCANNED.min(new.len());
            let found = (new[..first].iter().position(&mut sees)).or_else(|| {
                // The first `first` are known not to see `q`: search the others only.
                let start = last.max(first);
                let k = (new[start..].iter().chain(&new[first..start])).position(&mut sees)?;
                Some(first + (start - first + k) % (new.len() - first))
            });
            match found {
                Some(k) => {
                    last = k;
                    self.file(new[k], q);
                }
                None => self.inside[q as usize] = !flat,
            }
        }
        s.orphans.clear();
        self.scratch = s;
        new
    }

    /// The triangles `p` sees, from `t0` on, in `s.visible`, and the edges between them
    /// and the others in `s.horizon`.
    fn horizon(&mut self, t0: usize, p: u32, s: &mut Scratch) {
        s.visible.clear();
        s.horizon.clear();
        s.visible.push(t0);
        self.tris[t0].seen = self.round;
        let mut k = 0;
        while k < s.visible.len() {
            let t = s.visible[k];
            k += 1;
            for i in 0..3 {
                let n = self.tris[t].nb[i] as usize;
                if self.tris[n].seen == self.round {
                    continue;
                }
                if self.sees(n, p) {
                    self.tris[n].seen = self.round;
                    s.visible.push(n);
                } else {
                    let [a, b] = edge_of(&self.tris[t].v, i);
                    let j = (0..3).find(|&j| self.tris[n].nb[j] as usize == t).unwrap();
                    s.horizon.push((a, b, n, j));
                }
            }
        }
    }

    /// Cones `p` to the horizon edges: the new triangles, linked to their neighbours.
    fn cone(&mut self, p: u32, s: &mut Scratch) -> Vec<usize> {
        s.by_start.clear();
        let mut new = Vec::with_capacity(s.horizon.len());
        for &(a, b, n, j) in &s.horizon {
            let id = self.push([a, b, p], [n as u32, NONE, NONE]);
            self.tris[n].nb[j] = id as u32;
            s.by_start.push((a, new.len()));
            new.push(id);
        }
        s.by_start.sort_unstable();
        for &id in &new {
            let b = self.tris[id].v[1];
            let k = s.by_start.partition_point(|&(a, _)| a < b);
            let next = new[s.by_start[k].1];
            self.tris[id].nb[1] = next as u32;
            self.tris[next].nb[2] = id as u32;
        }
        new
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(k: usize) -> Vec<Point3> {
        let mut v = vec![];
        for i in 0..k {
            for j in 0..k {
                for l in 0..k {
                    v.push([i as f64, j as f64, l as f64]);
                }
            }
        }
        v
    }

    #[test]
    fn grid_hull_has_six_facets_and_all_surface_points() {
        let pts = grid(4);
        let h = Hull3::new(&pts);
        assert_eq!(h.facet_count(), 6);
        let boundary = (0..pts.len()).filter(|&i| h.on_boundary(i)).count();
        assert_eq!(boundary, 64 - 8);
        // every corner lies on three facets, edge points on two
        assert_eq!(h.facets_of(0).len(), 3);
        assert_eq!(h.facets_of(1).len(), 2);
        let edges = h.polytope_edges(&pts);
        assert_eq!(edges.len(), 12);
        assert!(edges.iter().all(|e| e.len() == 4));
    }

    #[test]
    fn every_point_is_inside_every_facet_plane() {
        let mut s = 12345u64;
        let mut rnd = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s % 7) as f64
        };
        let pts: Vec<Point3> = (0..200).map(|_| [rnd(), rnd(), rnd()]).collect();
        assert_is_hull(&pts, &Hull3::new(&pts));
    }

    /// Zeros written -0 or 0 at random (equal numbers that `total_cmp` alone tells
    /// apart) give the hull of the same points: the same facets, boundary and polytope
    /// edges.
    #[test]
    fn signed_zeros_are_zeros() {
        let mut rng = crate::rng::Rng::new(41);
        for round in 0..2000 {
            let side = 2 + round % 4;
            let len = 4 + rng.below(30);
            let mut coordinate = || rng.below(side) as f64 - (side / 2) as f64;
            let pts: Vec<Point3> = (0..len).map(|_| [0; 3].map(|_| coordinate())).collect();
            let signed: Vec<Point3> = (pts.iter())
                .map(|p| {
                    p.map(|x| {
                        if x == 0.0 && rng.below(2) == 0 {
                            -0.0
                        } else {
                            x
                        }
                    })
                })
                .collect();
            let (h, s) = (Hull3::new(&pts), Hull3::new(&signed));
            assert_eq!(h.dimension, s.dimension, "{signed:?}");
            if h.dimension < 3 {
                continue;
            }
            assert_is_hull(&signed, &s);
            assert_eq!(h.facet_count(), s.facet_count(), "{signed:?}");
            assert_eq!(
                h.polytope_edges(&pts),
                s.polytope_edges(&signed),
                "{signed:?}"
            );
        }
    }

    /// Every point on the inner side of every facet plane, on the boundary exactly when
    /// on a facet plane, and the triangles a closed surface.
    fn assert_is_hull(pts: &[Point3], h: &Hull3) {
        for f in &h.facet_planes {
            let p = |i: u32| &pts[i as usize];
            for x in pts {
                assert!(orient3d(p(f[0]), p(f[1]), p(f[2]), x) <= 0);
            }
        }
        // Boundary points are exactly those on some facet plane.
        for (i, x) in pts.iter().enumerate() {
            let on = h.facet_planes.iter().any(|f| {
                let p = |i: u32| &pts[i as usize];
                orient3d(p(f[0]), p(f[1]), p(f[2]), x) == 0
            });
            assert_eq!(on, h.on_boundary(i));
        }
        // The surface is closed: every directed edge has its reverse.
        let e: HashSet<(u32, u32)> = h
            .triangles
            .iter()
            .flat_map(|t| (0..3).map(move |i| (t[i], t[(i + 1) % 3])))
            .collect();
        assert!(e.iter().all(|&(a, b)| e.contains(&(b, a))));
        // Each triangle's neighbour across an edge has that edge reversed.
        for (t, tri) in h.triangles.iter().enumerate() {
            for i in 0..3 {
                let [a, b] = edge_of(tri, i);
                let u = h.triangles[h.neighbour(t, i)];
                assert!((0..3).any(|j| edge_of(&u, j) == [b, a]), "{t} {i}");
            }
        }
    }

    /// Two cocircular polygons in parallel planes and a point beyond one of them (a
    /// bottom of the coaxial prisms of BENCHMARKS.md): insertions whose cones have
    /// thousands of triangles, where orphans are filed from the last one found.
    #[test]
    fn cocircular_prisms_with_an_apex() {
        let circle = |k: usize, of: usize, z: f64| {
            (0..k).map(move |i| {
                let a = std::f64::consts::TAU * i as f64 / of as f64;
                [0.95 * a.cos(), 0.95 * a.sin(), z]
            })
        };
        let mut pts: Vec<Point3> = circle(1500, 2000, -0.95)
            .chain(circle(800, 2000, 0.95))
            .collect();
        pts.push([1.0, 0.0, -1.0]);
        assert_is_hull(&pts, &Hull3::new(&pts));
    }

    /// The facet grid must never hide a facet from a point on it: compare with the
    /// exhaustive exact test on many boundary points, including a tilted facet.
    #[test]
    fn grid_filtered_membership_is_exhaustive() {
        let mut rng = crate::rng::Rng::new(77);
        let mut pts: Vec<Point3> = (0..4000)
            .map(|_| {
                [
                    rng.below(13) as f64,
                    rng.below(13) as f64,
                    rng.below(13) as f64,
                ]
            })
            .collect();
        // Points exactly on the plane x + y + z = 1 (a facet of the set below) and inside.
        for a in 0..=16 {
            for b in 0..=(16 - a) {
                pts.push([
                    a as f64 / 16.0,
                    b as f64 / 16.0,
                    1.0 - (a + b) as f64 / 16.0,
                ]);
            }
        }
        pts.extend((0..3000).map(|_| [rng.unit() * 0.3, rng.unit() * 0.3, rng.unit() * 0.3]));
        pts.push([0.0, 0.0, 0.0]);
        // Small sets too (one grid cell, corners named by their triangles): grid points,
        // repeats and points inside edges and facets included.
        let small: Vec<Vec<Point3>> = (0..300)
            .map(|k| {
                (0..5 + k % 60)
                    .map(|_| [0; 3].map(|_| rng.below(4) as f64))
                    .collect()
            })
            .collect();
        let sets = [&pts[..4000], &pts[4000..]];
        for set in sets.into_iter().chain(small.iter().map(|s| &s[..])) {
            let h = Hull3::new(set);
            if h.dimension < 3 {
                continue;
            }
            for (i, x) in set.iter().enumerate() {
                let exact: Vec<u32> = (0..h.facet_planes.len() as u32)
                    .filter(|&f| {
                        let q = h.facet_planes[f as usize].map(|j| set[j as usize]);
                        orient3d(&q[0], &q[1], &q[2], x) == 0
                    })
                    .collect();
                assert_eq!(h.facets_of(i), &exact[..], "point {i} {x:?}");
            }
            // The common facet of three points is the least facet on all three.
            let on: Vec<usize> = (0..set.len()).filter(|&i| h.on_boundary(i)).collect();
            for _ in 0..if set.len() < 64 { 30 } else { 3000 } {
                let [a, b, c] = [0; 3].map(|_| on[rng.below(on.len())]);
                let least = h
                    .facets_of(a)
                    .iter()
                    .copied()
                    .find(|f| h.facets_of(b).contains(f) && h.facets_of(c).contains(f));
                assert_eq!(h.common_facet(a, b, c), least, "{a} {b} {c}");
            }
        }
    }

    /// The points the construction leaves out as strictly inside (they skip the facet
    /// lookup) are strictly behind every facet plane, and they are most of the interior:
    /// random floats in a ball, and a small integer grid (points on facets, repeats).
    #[test]
    fn points_proved_inside_are_strictly_inside() {
        let mut rng = crate::rng::Rng::new(5);
        let ball: Vec<Point3> = (0..3000)
            .map(|_| [0; 3].map(|_| rng.unit() * 2.0 - 1.0))
            .filter(|x| x.iter().map(|c| c * c).sum::<f64>() <= 1.0)
            .collect();
        let grid: Vec<Point3> = (0..3000)
            .map(|_| [0; 3].map(|_| rng.below(9) as f64))
            .collect();
        for (set, least) in [(&ball, 0.95), (&grid, 0.8)] {
            let (h, inside) = Hull3::build(set);
            let side = |f: &[u32; 3], x| {
                let q = f.map(|j| set[j as usize]);
                orient3d(&q[0], &q[1], &q[2], x)
            };
            let interior = (set.iter())
                .filter(|x| h.facet_planes.iter().all(|f| side(f, x) < 0))
                .count();
            for (x, _) in set.iter().zip(&inside).filter(|(_, i)| **i) {
                assert!(h.facet_planes.iter().all(|f| side(f, x) < 0), "{x:?}");
            }
            let proved = inside.iter().filter(|&&i| i).count();
            assert!(
                proved as f64 >= least * interior as f64,
                "{proved} of {interior}"
            );
        }
    }

    #[test]
    fn flat_sets_report_their_dimension() {
        assert_eq!(Hull3::new(&[[1.0, 2.0, 3.0]; 5]).dimension, 0);
        assert_eq!(
            Hull3::new(&[[0.0; 3], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]]).dimension,
            1
        );
        assert_eq!(
            Hull3::new(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [3.0, 3.0, 0.0]]).dimension,
            2
        );
    }

    /// A hull extended by points ([`Hull3::extended`]) is the hull of all of them: on
    /// small integer grids (repeats, points on facets and edges, new points inside, on
    /// the hull or beyond it), with the facets, as the points on each, of a hull built
    /// anew.
    #[test]
    fn extended_hulls_are_the_hulls_of_all_points() {
        let mut rng = crate::rng::Rng::new(41);
        let facets = |pts: &[Point3], h: &Hull3| {
            let mut fs: Vec<Vec<usize>> = (0..h.facet_count())
                .map(|f| {
                    (0..pts.len())
                        .filter(|&i| h.facets_of(i).contains(&(f as u32)))
                        .collect()
                })
                .collect();
            fs.sort();
            fs
        };
        let mut extended = 0;
        for k in 0..3000 {
            let side = 3 + k % 4;
            let n = 6 + k % 40;
            let pts: Vec<Point3> = (0..n)
                .map(|_| [0; 3].map(|_| rng.below(side) as f64))
                .collect();
            let base = 4 + rng.below(n - 3);
            let h = Hull3::new(&pts[..base]);
            let Some(e) = h.extended(&pts) else {
                assert!(h.dimension < 3);
                continue;
            };
            extended += 1;
            assert_is_hull(&pts, &e);
            assert_eq!(
                facets(&pts, &e),
                facets(&pts, &Hull3::new(&pts)),
                "{pts:?} {base}"
            );
        }
        assert!(extended > 2000, "{extended}");
    }
}
