//! Flips that keep a tetrahedralization's vertices and boundary: Lawson's flips towards
//! the constrained Delaunay tetrahedralization, and 3-2 flips that lower the count.
//!
//! A **2-3 flip** replaces two tetrahedra `abcd`, `abce` sharing the face `abc` by the
//! three around the new edge `de`; it applies when `de` crosses the interior of `abc`
//! (then the two form a convex bipyramid, which the three tile). A **3-2 flip** is the
//! inverse: the three tetrahedra around an edge `ab` of degree 3, with link `cde`,
//! become `cdea` and `cdeb` when `ab` crosses the interior of `cde`. Both act inside the
//! union of the tetrahedra they replace, so the vertices, the boundary triangles and the
//! region stay as they were; every decision is an exact sign (orient3d, insphere), and a
//! configuration on the boundary of a test (four coplanar points, five cospherical ones)
//! is left alone. Faces with one tetrahedron (the boundary) are never flipped.
//!
//! **Delaunay.** [`delaunay`] flips every interior face whose opposite vertex lies
//! strictly inside the circumsphere of the tetrahedron on the other side, when one of the
//! two flips applies. Each such flip lowers the lifted surface of the tetrahedralization
//! (the points lifted to the paraboloid), so the flipping ends; in three dimensions it
//! can end before the Delaunay tetrahedralization, at faces no flip applies to. The
//! count changes by +1 per 2-3 flip and −1 per 3-2 flip.
//!
//! **Fewer tetrahedra.** [`reduce`] applies 3-2 flips while any applies; each removes one
//! tetrahedron and one interior edge.
//!
//! ```
//! use tetrakit::control::Control;
//! use tetrakit::flip;
//! // Three tetrahedra around the edge from (0,0,-1) to (0,0,1), which crosses the
//! // triangle of their other vertices: one 3-2 flip leaves two.
//! let pts = [[0.0, 0.0, -1.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [-0.5, 1.0, 0.0], [-0.5, -1.0, 0.0]];
//! let mut tets = vec![[0, 1, 2, 3], [0, 1, 3, 4], [0, 1, 4, 2]];
//! assert_eq!(flip::reduce(&pts, &mut tets, &Control::new()).unwrap(), 1);
//! assert_eq!(tets.len(), 2);
//! ```

use crate::control::{Control, Stopped};
use crate::geom::{Point3, insphere, orient3d};
use std::collections::VecDeque;

const NONE: u32 = u32::MAX;

/// The flips [`delaunay`] made.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Flips {
    /// 2-3 flips (one tetrahedron more each).
    pub two_three: usize,
    /// 3-2 flips (one tetrahedron fewer each).
    pub three_two: usize,
}

/// Lawson's flips until every interior face is locally Delaunay or no flip applies to it
/// (see the module docs). `tets` are rewritten, positively oriented.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::flip;
/// // Two tetrahedra on the face (1,2,3); the apex 4 lies inside the sphere of 0123.
/// let pts = [[0.0, 0.0, 2.0], [1.0, 0.0, 0.0], [-0.5, 0.9, 0.0], [-0.5, -0.9, 0.0], [0.0, 0.0, -0.2]];
/// let mut tets = vec![[0, 1, 2, 3], [4, 1, 3, 2]];
/// let f = flip::delaunay(&pts, &mut tets, &Control::new()).unwrap();
/// assert_eq!((f.two_three, tets.len()), (1, 3));
/// ```
pub fn delaunay(
    points: &[Point3],
    tets: &mut Vec<[u32; 4]>,
    ctl: &Control,
) -> Result<Flips, Stopped> {
    let mut m = Mesh::new(points, tets);
    let mut queue: VecDeque<(u32, usize)> = m.interior_faces().into();
    let mut flips = Flips::default();
    let mut steps = Steps::new(ctl);
    while let Some((t1, k)) = queue.pop_front() {
        steps.tick()?;
        let Some(t2) = m.across(t1, k) else {
            continue;
        };
        let t = m.tets[t1 as usize];
        let key = face(&t, k);
        let (d, e) = (t[k], m.apex(t2, &key));
        let p = |v: u32| &points[v as usize];
        if insphere(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e)) <= 0 {
            continue;
        }
        if let Some(new) = m.two_three(t1, t2, key, d, e) {
            flips.two_three += 1;
            queue.extend(m.outer_faces(&new));
            continue;
        }
        for (a, b) in [(key[0], key[1]), (key[1], key[2]), (key[0], key[2])] {
            if let Some(new) = m.three_two(a, b, t1) {
                flips.three_two += 1;
                queue.extend(m.outer_faces(&new));
                break;
            }
        }
    }
    *tets = m.into_tets();
    Ok(flips)
}

/// 3-2 flips while any applies; returns how many were made (the tetrahedra removed).
pub fn reduce(
    points: &[Point3],
    tets: &mut Vec<[u32; 4]>,
    ctl: &Control,
) -> Result<usize, Stopped> {
    ctl.check()?;
    let mut m = Mesh::new(points, tets);
    let mut queue: VecDeque<([u32; 2], u32)> = m.flippable_edges().into();
    let mut done = 0;
    let mut steps = Steps::new(ctl);
    while let Some(([a, b], t)) = queue.pop_front() {
        steps.tick()?;
        if let Some(new) = m.three_two(a, b, t) {
            done += 1;
            // The edges of the two new tetrahedra may have reached degree 3.
            for &id in new.get() {
                queue.extend(m.tet_edges(id));
            }
        }
    }
    *tets = m.into_tets();
    Ok(done)
}

/// A step counter that asks the control every 4096 steps.
struct Steps<'c> {
    ctl: &'c Control,
    n: usize,
}

impl<'c> Steps<'c> {
    fn new(ctl: &'c Control) -> Self {
        Steps { ctl, n: 0 }
    }

    fn tick(&mut self) -> Result<(), Stopped> {
        self.n += 1;
        if self.n.is_multiple_of(4096) {
            self.ctl.check()?;
        }
        Ok(())
    }
}

/// The ids of at most three tetrahedra: those a flip makes.
#[derive(Clone, Copy, Default)]
struct Few {
    ids: [u32; 3],
    len: usize,
}

impl Few {
    fn push(&mut self, id: u32) {
        self.ids[self.len] = id;
        self.len += 1;
    }

    fn get(&self) -> &[u32] {
        &self.ids[..self.len]
    }
}

/// The four faces (sorted) of each of the tetrahedra `ids` (at most three).
fn faces_of(ids: &[u32], tets: &[[u32; 4]]) -> [[[u32; 3]; 4]; 3] {
    let mut out = [[[0; 3]; 4]; 3];
    for (slot, &t) in out.iter_mut().zip(ids) {
        *slot = [0, 1, 2, 3].map(|k| face(&tets[t as usize], k));
    }
    out
}

/// Tetrahedra with their neighbours: `nb[t][k]` is the tetrahedron across the face of
/// `t` opposite its vertex `k` ([`NONE`] on the boundary).
struct Mesh<'a> {
    pts: &'a [Point3],
    tets: Vec<[u32; 4]>,
    alive: Vec<bool>,
    nb: Vec<[u32; 4]>,
    /// Dead slots, reused by the next new tetrahedra.
    free: Vec<u32>,
}

fn sorted<const N: usize>(mut v: [u32; N]) -> [u32; N] {
    v.sort_unstable();
    v
}

/// The vertices of `t` in increasing order, each with its corner in `t`.
fn by_vertex(t: &[u32; 4]) -> [(u32, u8); 4] {
    let mut s = [0, 1, 2, 3].map(|k| (t[k], k as u8));
    s.sort_unstable();
    s
}

/// The vertices of `s` but its `off`-th, in order.
fn without(s: &[(u32, u8); 4], off: usize) -> [u32; 3] {
    let v = s.map(|x| x.0);
    match off {
        0 => [v[1], v[2], v[3]],
        1 => [v[0], v[2], v[3]],
        2 => [v[0], v[1], v[3]],
        _ => [v[0], v[1], v[2]],
    }
}

/// The face of `t` opposite its vertex `k`, sorted.
fn face(t: &[u32; 4], k: usize) -> [u32; 3] {
    let mut f = [0; 3];
    let mut i = 0;
    for (j, &v) in t.iter().enumerate() {
        if j != k {
            f[i] = v;
            i += 1;
        }
    }
    sorted(f)
}

impl<'a> Mesh<'a> {
    fn new(pts: &'a [Point3], tets: &[[u32; 4]]) -> Self {
        let mut m = Mesh {
            pts,
            tets: Vec::with_capacity(tets.len()),
            alive: vec![true; tets.len()],
            nb: vec![[NONE; 4]; tets.len()],
            free: Vec::new(),
        };
        m.tets = tets.iter().map(|&t| m.oriented(t)).collect();
        m.link_faces();
        m
    }

    /// Links each face to the tetrahedron on its other side: the faces bucketed by their
    /// greatest vertex ([`crate::rows::buckets`]; most buckets hold a few faces), each bucket
    /// sorted by the face's two other vertices as one integer, then by the tetrahedron
    /// (sorting every face as one `u128` made [`reduce`] on 2407 tetrahedra a fifth
    /// slower). A face of more than two tetrahedra (no tetrahedralization) links each of
    /// them to the next in that order.
    fn link_faces(&mut self) {
        let n = self.pts.len();
        let sorted: Vec<[(u32, u8); 4]> = self.tets.iter().map(by_vertex).collect();
        // `(the face's two least vertices, 4 · tetrahedron + the corner off the face)`.
        let faces = sorted.iter().enumerate().flat_map(|(t, s)| {
            (0..4).map(move |off| {
                let [a, b, c] = without(s, off);
                let corner = 4 * t as u64 + u64::from(s[off].1);
                (c as usize, (u64::from(a) << 32 | u64::from(b), corner))
            })
        });
        let (start, mut faces) = crate::rows::buckets(n, faces);
        for v in 0..n {
            let bucket = &mut faces[start[v] as usize..start[v + 1] as usize];
            bucket.sort_unstable();
            for w in bucket.windows(2).filter(|w| w[0].0 == w[1].0) {
                let [(t, k), (u, j)] =
                    [w[0].1, w[1].1].map(|x| ((x / 4) as usize, (x % 4) as usize));
                (self.nb[t][k], self.nb[u][j]) = (u as u32, t as u32);
            }
        }
    }

    fn into_tets(self) -> Vec<[u32; 4]> {
        self.tets
            .into_iter()
            .zip(self.alive)
            .filter_map(|(t, a)| a.then_some(t))
            .collect()
    }

    fn orient(&self, a: u32, b: u32, c: u32, d: u32) -> i8 {
        let p = |v: u32| &self.pts[v as usize];
        orient3d(p(a), p(b), p(c), p(d))
    }

    /// `t` reordered to be positively oriented.
    fn oriented(&self, mut t: [u32; 4]) -> [u32; 4] {
        if self.orient(t[0], t[1], t[2], t[3]) < 0 {
            t.swap(0, 1);
        }
        t
    }

    /// Every interior face once, as (tetrahedron, opposite corner), in order.
    fn interior_faces(&self) -> Vec<(u32, usize)> {
        (0..self.tets.len() as u32)
            .flat_map(|t| (0..4).map(move |k| (t, k)))
            .filter(|&(t, k)| {
                let n = self.nb[t as usize][k];
                n != NONE && t < n
            })
            .collect()
    }

    /// The tetrahedron across the face of the live `t` opposite its corner `k`.
    fn across(&self, t: u32, k: usize) -> Option<u32> {
        let n = self.nb[t as usize][k];
        (self.alive[t as usize] && n != NONE).then_some(n)
    }

    /// The faces of the new tetrahedra `new` that are not between two of them.
    fn outer_faces<'m>(&'m self, new: &'m Few) -> impl Iterator<Item = (u32, usize)> + 'm {
        (new.get().iter())
            .flat_map(|&t| (0..4).map(move |k| (t, k)))
            .filter(|&(t, k)| !new.get().contains(&self.nb[t as usize][k]))
    }

    /// Replaces the live tetrahedra `old` by `new` (the same region, so every face of a
    /// new one is a face of another new one or of an old one), linking the neighbours;
    /// returns the new ids. The new tetrahedra take the slots of dead ones first, so the
    /// arrays stay the size of the mesh and neighbours stay near in memory.
    fn replace(&mut self, old: &[u32], new: &[[u32; 4]]) -> Few {
        // The tetrahedra across the old ones' outer faces, read before a slot is reused.
        let mut outside = [([0; 3], NONE); 12];
        let mut m = 0;
        for &t in old {
            for k in 0..4 {
                let n = self.nb[t as usize][k];
                if !old.contains(&n) {
                    outside[m] = (face(&self.tets[t as usize], k), n);
                    m += 1;
                }
            }
            self.alive[t as usize] = false;
            self.free.push(t);
        }
        let mut ids = Few::default();
        for &t in new {
            let t = self.oriented(t);
            let id = self.free.pop().unwrap_or_else(|| {
                self.tets.push(t);
                self.alive.push(false);
                self.nb.push([NONE; 4]);
                self.tets.len() as u32 - 1
            });
            self.tets[id as usize] = t;
            self.alive[id as usize] = true;
            ids.push(id);
        }
        let faces = faces_of(ids.get(), &self.tets);
        for (i, &id) in ids.get().iter().enumerate() {
            for (k, f) in faces[i].iter().enumerate() {
                let twin = (0..ids.len).find(|&j| j != i && faces[j].contains(f));
                let n = match twin {
                    Some(j) => ids.get()[j],
                    None => (outside[..m].iter().find(|(g, _)| g == f)).map_or(NONE, |o| o.1),
                };
                self.nb[id as usize][k] = n;
                if twin.is_none() && n != NONE {
                    // `n`'s slot for this face: opposite its vertex off the face.
                    let tn = &self.tets[n as usize];
                    if let Some(kk) = tn.iter().position(|v| !f.contains(v)) {
                        self.nb[n as usize][kk] = id;
                    }
                }
            }
        }
        ids
    }

    /// The vertex of tetrahedron `t` not on `key`.
    fn apex(&self, t: u32, key: &[u32; 3]) -> u32 {
        let tet = &self.tets[t as usize];
        *tet.iter().find(|v| !key.contains(v)).expect("a face of t")
    }

    /// The 2-3 flip of the face `key = abc` between `t1 = abcd` and `t2 = abce`, if `de`
    /// crosses its interior; returns the three new tetrahedra.
    fn two_three(&mut self, t1: u32, t2: u32, key: [u32; 3], d: u32, e: u32) -> Option<Few> {
        let [a, b, c] = key;
        if !self.line_through(d, e, key) {
            return None;
        }
        let new = [(a, b), (b, c), (c, a)].map(|(x, y)| [x, y, d, e]);
        Some(self.replace(&[t1, t2], &new))
    }

    /// True when the line `pq` passes through the interior of the triangle `t`.
    fn line_through(&self, p: u32, q: u32, t: [u32; 3]) -> bool {
        let [a, b, c] = t;
        let s = [
            self.orient(p, q, a, b),
            self.orient(p, q, b, c),
            self.orient(p, q, c, a),
        ];
        s[0] != 0 && s.iter().all(|&x| x == s[0])
    }

    /// The 3-2 flip removing the edge `ab`, if it has degree 3, is interior, and crosses
    /// the interior of the triangle `cde` of its other vertices; returns the two new
    /// tetrahedra.
    fn three_two(&mut self, a: u32, b: u32, t0: u32) -> Option<Few> {
        let t = &self.tets[t0 as usize];
        if !self.alive[t0 as usize] || !t.contains(&a) || !t.contains(&b) {
            return None; // gone, or its slot reused by a tetrahedron off `ab`
        }
        let (ts, [c, d, e]) = self.ring(a, b, t0, |_| false)?;
        if self.orient(c, d, e, a) * self.orient(c, d, e, b) >= 0
            || !self.line_through(a, b, [c, d, e])
        {
            return None;
        }
        Some(self.replace(&ts, &[[c, d, e, a], [c, d, e, b]]))
    }

    /// For an interior edge `ab` of degree 3 on the tetrahedron `t0`: its three
    /// tetrahedra and their three other vertices, or `None` (another degree, or on the
    /// boundary, or a tetrahedron for which `skip` is true met on the way). Walks around
    /// the edge through the faces `abx`.
    fn ring(
        &self,
        a: u32,
        b: u32,
        t0: u32,
        skip: impl Fn(u32) -> bool,
    ) -> Option<([u32; 3], [u32; 3])> {
        let others = |t: u32| {
            let mut o = self.tets[t as usize]
                .into_iter()
                .filter(|&v| v != a && v != b);
            (o.next(), o.next())
        };
        let (Some(c), Some(mut v)) = others(t0) else {
            return None; // t0 is not on ab
        };
        let (mut ts, mut link, mut cur, mut behind) = ([t0; 3], [c, v, 0], t0, c);
        for k in 1..=3 {
            // Across the face `abv` of `cur`: the one opposite its fourth vertex.
            let opposite = self.tets[cur as usize].iter().position(|&x| x == behind)?;
            let next = self.nb[cur as usize][opposite];
            if next == NONE || skip(next) {
                return None;
            }
            if next == t0 {
                return (k == 3).then_some((ts, link));
            }
            if k == 3 {
                return None;
            }
            let (Some(x), Some(y)) = others(next) else {
                return None;
            };
            behind = v;
            v = if x == v { y } else { x };
            ts[k] = next;
            if k == 1 {
                link[2] = v;
            }
            cur = next;
        }
        None
    }

    /// The six edges of tetrahedron `id`, each with `id`.
    fn tet_edges(&self, id: u32) -> [([u32; 2], u32); 6] {
        let t = self.tets[id as usize];
        [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)].map(|(i, j)| (sorted([t[i], t[j]]), id))
    }

    /// Every interior edge of degree 3, once (with the lowest of its tetrahedra), in
    /// order: the edges a 3-2 flip may remove now. An edge whose degree a flip changes
    /// is an edge of the flip's new tetrahedra, which [`reduce`] queues then.
    fn flippable_edges(&self) -> Vec<([u32; 2], u32)> {
        let mut e: Vec<([u32; 2], u32)> = (0..self.tets.len() as u32)
            .flat_map(|id| self.tet_edges(id))
            // Walked from its lowest tetrahedron only: from any other, given up on
            // meeting a lower one.
            .filter(|&([a, b], id)| self.ring(a, b, id, |t| t < id).is_some())
            .collect();
        e.sort_unstable();
        e
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Hull3;
    use crate::mesh::certify_hull;
    use proptest::prelude::*;

    /// The pulling tetrahedralization of points in convex position: vertex 0 coned to
    /// every hull triangle not in a plane through it (far from Delaunay: many flips).
    fn pulled(points: &[Point3]) -> Vec<[u32; 4]> {
        let hull = Hull3::new(points);
        hull.triangles
            .iter()
            .filter(|t| {
                let p = |v: u32| &points[v as usize];
                orient3d(p(t[0]), p(t[1]), p(t[2]), &points[0]) != 0
            })
            .map(|t| {
                let mut tet = [t[0], t[1], t[2], 0];
                let p = |v: u32| &points[v as usize];
                if orient3d(p(tet[0]), p(tet[1]), p(tet[2]), p(tet[3])) < 0 {
                    tet.swap(0, 1);
                }
                tet
            })
            .collect()
    }

    fn sphere_points(seeds: &[(f64, f64)]) -> Vec<Point3> {
        seeds
            .iter()
            .map(|&(u, v)| {
                let (z, t) = (2.0 * u - 1.0, std::f64::consts::TAU * v);
                let r = (1.0 - z * z).sqrt();
                [r * t.cos(), r * t.sin(), z]
            })
            .collect()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// From a pulling tetrahedralization, Delaunay flips then 3-2 flips: still a
        /// tetrahedralization of the hull with every point, and the count moves by one
        /// per flip in the stated direction.
        #[test]
        fn flips_keep_a_tetrahedralization(seeds in proptest::collection::vec((0.0f64..1.0, 0.0f64..1.0), 6..40)) {
            let pts = sphere_points(&seeds);
            let hull = Hull3::new(&pts);
            prop_assume!(hull.dimension == 3 && (0..pts.len()).all(|i| hull.on_boundary(i)));
            let mut tets = pulled(&pts);
            prop_assume!(certify_hull(&pts, &tets).is_ok()); // a point on a hull edge
            let start = tets.len();
            let f = delaunay(&pts, &mut tets, &Control::new()).unwrap();
            prop_assert_eq!(certify_hull(&pts, &tets), Ok(()));
            prop_assert_eq!(tets.len() + f.three_two, start + f.two_three);
            let mid = tets.len();
            let r = reduce(&pts, &mut tets, &Control::new()).unwrap();
            prop_assert_eq!(certify_hull(&pts, &tets), Ok(()));
            prop_assert_eq!(tets.len() + r, mid);
        }
    }

    /// The pulled tetrahedralizations of `count` sets of random points on a sphere, of
    /// 8, 9, 10, … points.
    fn pulled_spheres(seed: u64, count: usize) -> Vec<(Vec<Point3>, Vec<[u32; 4]>)> {
        let mut rng = crate::rng::Rng::new(seed);
        (0..count)
            .map(|case| {
                let seeds: Vec<(f64, f64)> =
                    (0..8 + case).map(|_| (rng.unit(), rng.unit())).collect();
                let pts = sphere_points(&seeds);
                let tets = pulled(&pts);
                (pts, tets)
            })
            .collect()
    }

    /// Each tetrahedron's neighbour across each face is the other tetrahedron with that
    /// face, as a search of all finds it (none on the boundary), and the pulled meshes of
    /// random points on a sphere, far from Delaunay, do flip.
    #[test]
    fn neighbours_are_across_each_face() {
        let mut flipped = 0;
        for (pts, tets) in pulled_spheres(3, 40) {
            let m = Mesh::new(&pts, &tets);
            for (t, tet) in m.tets.iter().enumerate() {
                for k in 0..4 {
                    let f = face(tet, k);
                    let other = (0..m.tets.len())
                        .find(|&u| u != t && (0..4).any(|j| face(&m.tets[u], j) == f))
                        .map_or(NONE, |u| u as u32);
                    assert_eq!(m.nb[t][k], other, "{t} {k}");
                }
            }
            let mut tets = tets;
            let f = delaunay(&pts, &mut tets, &Control::new()).unwrap();
            flipped += f.two_three + f.three_two;
        }
        assert!(flipped > 100, "{flipped} flips");
    }

    /// Cospherical points (a cube's corners, and a 3×3×3 grid's Kuhn cells): no point is
    /// strictly inside any sphere, so no Delaunay flip; the meshes stay valid.
    #[test]
    fn cospherical_points_are_not_flipped() {
        let cube: Vec<Point3> = (0..8)
            .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64])
            .collect();
        let mut tets = pulled(&cube);
        assert_eq!(tets.len(), 6);
        let f = delaunay(&cube, &mut tets, &Control::new()).unwrap();
        assert_eq!(f, Flips::default());
        reduce(&cube, &mut tets, &Control::new()).unwrap();
        assert_eq!(certify_hull(&cube, &tets), Ok(()));
        let grid = crate::generate::kuhn(3);
        let mut tets = grid.tets.clone();
        let f = delaunay(&grid.points, &mut tets, &Control::new()).unwrap();
        assert_eq!((f, tets.len()), (Flips::default(), grid.tets.len()));
    }

    /// A queued edge whose tetrahedron's slot now holds a tetrahedron off the edge (the
    /// slots of dead tetrahedra are reused) is no flip: `three_two` asked of an edge its
    /// tetrahedron does not have returns `None` and changes nothing, on 20 random sets.
    #[test]
    fn a_reused_slot_is_not_flipped_as_the_old_edge() {
        let mut rng = crate::rng::Rng::new(5);
        for _ in 0..20 {
            let seeds: Vec<(f64, f64)> = (0..12).map(|_| (rng.unit(), rng.unit())).collect();
            let pts = sphere_points(&seeds);
            let tets = pulled(&pts);
            for t in 0..tets.len() as u32 {
                for a in 0..pts.len() as u32 {
                    for b in a + 1..pts.len() as u32 {
                        let tet = tets[t as usize];
                        if tet.contains(&a) && tet.contains(&b) {
                            continue;
                        }
                        let mut m = Mesh::new(&pts, &tets);
                        assert!(m.three_two(a, b, t).is_none(), "{a} {b} on T{t}");
                    }
                }
            }
        }
    }

    /// [`reduce`] ends where no 3-2 flip applies to any edge of any tetrahedron (each
    /// tried on a fresh mesh), having flipped: pulled meshes of random points on a
    /// sphere, as they are and after the Delaunay flips.
    #[test]
    fn reduce_leaves_no_flip() {
        let mut flipped = 0;
        for (case, (pts, mut tets)) in pulled_spheres(8, 30).into_iter().enumerate() {
            if case % 2 == 1 {
                delaunay(&pts, &mut tets, &Control::new()).unwrap();
            }
            flipped += reduce(&pts, &mut tets, &Control::new()).unwrap();
            let m = Mesh::new(&pts, &tets);
            for t in 0..m.tets.len() as u32 {
                for ([a, b], _) in m.tet_edges(t) {
                    let mut fresh = Mesh::new(&pts, &tets);
                    assert!(fresh.three_two(a, b, t).is_none(), "{a}{b} on T{t}");
                }
            }
        }
        assert!(flipped > 30, "{flipped} flips");
    }

    /// A stopped control stops the flipping (checked first, then every 4096 steps).
    #[test]
    fn a_stopped_control_stops() {
        let grid = crate::generate::kuhn(8);
        let ctl = Control::new();
        ctl.stop();
        let mut tets = grid.tets.clone();
        assert!(reduce(&grid.points, &mut tets, &ctl).is_err());
    }
}
