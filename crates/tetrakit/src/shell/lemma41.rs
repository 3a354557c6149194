//! Lemma 4.1 of the thesis, checked exactly: "S-bigcap(v) is a star-shaped polyhedron
//! with v in its kernel". It is false as stated, and this module finds where.
//!
//! The definitions, at the start of BIGCAP-REMOVE (`P̄ = P`, `S = ∅`):
//! - `u` is *visible* to `v` when the segment `uv` misses `Q`; a facet `f` is visible to
//!   `v` when every point of it is, that is when `conv({v} ∪ f)` misses `Q`;
//! - `U_v` = the vertices `u` of `P` that are visible to `v` together with every facet of
//!   `P` at `u` (`v ∈ U_v`);
//! - the bigcap of `v` is the closed region between `P` and `H = CH((V(P) − U_v) ∪ V(Q))`;
//!   its *dome* is the facets of `P` that are not facets of `H`, its *bottom* the facets of
//!   `H` that are not facets of `P`; the lemma is stated for bigcaps that are simple
//!   polyhedra (their boundary, dome and bottom together, a 2-sphere).
//!
//! The lemma's proof says a bottom point hidden from `v` would hide a point of the dome's
//! rim as well. It need not: `U_v` may hold a vertex `u` far from `v` (visible past `Q`
//! from a small or off-centre `Q`), and the facets of `H` that replace `u`'s star face
//! away from `v`. Then `v` lies strictly on `H`'s side of such a bottom facet's plane and
//! sees none of its interior, while the bigcap is still simple. On random small shells
//! this happens for some tip in nearly every shell; [`counterexample`] is the smallest we
//! found (10 points, integer coordinates, no four coplanar), where `U_v` is the tip and
//! one neighbour.
//!
//! Everything is decided with exact predicates: visibility by `Blocker`'s exact
//! intersection test of a cone with the closed `Q`, every side by `orient3d`. Shells where `Q` touches `P` are not
//! examined (the thesis's visibility is not defined where the segment runs along `Q`).

use super::Shell;
use super::blocker::Blocker;
use crate::control::{Control, Stopped};
use crate::geom::{Hull3, Point3, orient3d};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

/// A tip whose simple bigcap is not star-shaped from it. Indices are into
/// [`Shell::points`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lemma41Witness {
    /// The tip `v`.
    pub tip: u32,
    /// `U_v`, the outer vertices the bigcap removes (the tip among them), sorted.
    pub removed: Vec<u32>,
    /// A triangle of a bottom facet, oriented out of `H`: `orient3d(a, b, c, x) <= 0` for
    /// every vertex `x` of `H`, and `orient3d(a, b, c, tip) < 0` (the tip is behind it;
    /// `orient3d` has the sign of `det[b − a, c − a, x − a]`).
    pub bottom: [u32; 3],
    /// A vertex of `H` strictly on that side, the same side as the tip.
    pub kept: u32,
}

/// What the check of Lemma 4.1 found on a shell.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Lemma41 {
    /// Every tip's bigcap is star-shaped from it, or not simple (the lemma's hypothesis
    /// fails, so it says nothing there).
    Holds {
        /// Tips whose bigcap is simple.
        simple: usize,
        /// Tips whose bigcap is not.
        not_simple: usize,
    },
    /// The lemma fails at a tip.
    Fails(Lemma41Witness),
    /// The check does not apply: `Q` touches `P`.
    NotExamined,
}

/// The bigcap of one tip.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Bigcap {
    /// `U_v`, sorted.
    pub removed: Vec<u32>,
    /// Its boundary, dome and bottom, is a 2-sphere with no flat sheet.
    pub simple: bool,
    /// A bottom triangle the tip does not see, and a vertex of `H` on the tip's side.
    pub hidden: Option<([u32; 3], u32)>,
}

/// Checks Lemma 4.1 at every tip of `P` (`P̄ = P`, `S = ∅`) and returns the first tip
/// where it fails, in the order of the outer vertices; `ctl` is checked at every tip.
pub fn lemma_4_1(shell: &Shell, ctl: &Control) -> Result<Lemma41, Stopped> {
    let Some(ctx) = Context::new(shell) else {
        return Ok(Lemma41::NotExamined);
    };
    let (mut simple, mut not_simple) = (0, 0);
    for &tip in &shell.outer {
        ctl.check()?;
        let b = ctx.bigcap(tip);
        match (b.simple, b.hidden) {
            (true, Some((bottom, kept))) => {
                return Ok(Lemma41::Fails(Lemma41Witness {
                    tip,
                    removed: b.removed,
                    bottom,
                    kept,
                }));
            }
            (true, None) => simple += 1,
            (false, _) => not_simple += 1,
        }
    }
    Ok(Lemma41::Holds { simple, not_simple })
}

/// The bigcap of `tip` (an outer vertex) as the thesis defines it, or `None` where `Q`
/// touches `P`.
pub fn bigcap(shell: &Shell, tip: u32) -> Option<Bigcap> {
    Context::new(shell).map(|ctx| ctx.bigcap(tip))
}

/// The smallest counterexample to Lemma 4.1 we found: `(outer, inner, tip)`, the tip an
/// index into `outer`. Six outer and four inner points with integer coordinates, no four
/// of the ten coplanar; `U_v` is the tip and its neighbour `outer[5]`, and the bottom
/// triangle `outer[0] outer[1] outer[3]` faces away from the tip.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::shell::{Shell, lemma41};
/// let (outer, inner, tip) = lemma41::counterexample();
/// let shell = Shell::new(&outer, &inner).unwrap();
/// match lemma41::lemma_4_1(&shell, &Control::new()).unwrap() {
///     lemma41::Lemma41::Fails(w) => assert_eq!(w.tip, tip),
///     other => panic!("{other:?}"),
/// }
/// ```
pub fn counterexample() -> (Vec<Point3>, Vec<Point3>, u32) {
    let outer = vec![
        [24.0, 38.0, 20.0],
        [-36.0, 13.0, -23.0],
        [-10.0, 46.0, -19.0],
        [3.0, -20.0, 28.0],
        [33.0, -42.0, -14.0],
        [10.0, 45.0, 19.0],
    ];
    let inner = vec![
        [7.0, -5.0, -1.0],
        [11.0, 15.0, 6.0],
        [7.0, -10.0, 14.0],
        [10.0, 1.0, -4.0],
    ];
    (outer, inner, 2)
}

/// `P`'s hull and facets, and `Q` as a blocker.
struct Context<'a> {
    points: &'a [Point3],
    outer: &'a [u32],
    inner: &'a [u32],
    hull: Hull3,
    facets: Vec<Vec<u32>>,
    q: Blocker,
}

impl<'a> Context<'a> {
    fn new(shell: &'a Shell) -> Option<Self> {
        let n_outer = shell.outer.len();
        let shared = shell.inner.iter().any(|&q| (q as usize) < n_outer);
        if shared || !shell.touching.is_empty() {
            return None;
        }
        let hull = Hull3::new(&shell.points[..n_outer]);
        let facets = points_of_facets(&hull, n_outer, |i| i as u32);
        let inner_points: Vec<Point3> = shell
            .inner
            .iter()
            .map(|&q| shell.points[q as usize])
            .collect();
        Some(Context {
            points: &shell.points,
            outer: &shell.outer,
            inner: &shell.inner,
            q: Blocker::new(&inner_points),
            hull,
            facets,
        })
    }

    fn p(&self, i: u32) -> Point3 {
        self.points[i as usize]
    }

    /// `u` and its facets are visible to `tip`.
    fn in_u(&self, tip: u32, u: u32) -> bool {
        if u != tip && !self.q.misses(&[self.p(u), self.p(tip)]) {
            return false;
        }
        self.hull.facets_of(u as usize).iter().all(|&f| {
            let mut s: Vec<Point3> = self.facets[f as usize].iter().map(|&x| self.p(x)).collect();
            s.push(self.p(tip));
            self.q.misses(&s)
        })
    }

    fn bigcap(&self, tip: u32) -> Bigcap {
        let removed: Vec<u32> = self
            .outer
            .iter()
            .copied()
            .filter(|&u| self.in_u(tip, u))
            .collect();
        let gone: HashSet<u32> = removed.iter().copied().collect();
        let kept: Vec<u32> = self
            .outer
            .iter()
            .chain(self.inner)
            .copied()
            .filter(|u| !gone.contains(u))
            .collect();
        let kept_points: Vec<Point3> = kept.iter().map(|&k| self.p(k)).collect();
        let h = Hull3::new(&kept_points);
        let h_facets = points_of_facets(&h, kept.len(), |i| kept[i]);
        let key = |f: &[u32]| {
            let mut k = f.to_vec();
            k.sort_unstable();
            k
        };
        let of_p: HashSet<Vec<u32>> = self.facets.iter().map(|f| key(f)).collect();
        let of_h: HashSet<Vec<u32>> = h_facets.iter().map(|f| key(f)).collect();
        let dome: Vec<usize> = (0..self.facets.len())
            .filter(|&f| !of_h.contains(&key(&self.facets[f])))
            .collect();
        let bottom: Vec<usize> = (0..h_facets.len())
            .filter(|&f| !of_p.contains(&key(&h_facets[f])))
            .collect();
        let mut surface = triangles_of(&self.hull, &dome, |i| i);
        surface.extend(triangles_of(&h, &bottom, |i| kept[i as usize]));
        let flat = self.sheet(&dome, &h, &bottom, &kept);
        let simple = !flat && is_sphere(&surface);
        let hidden = bottom.iter().find_map(|&f| {
            let plane = h.facet_planes[f].map(|i| kept[i as usize]);
            let [a, b, c] = plane.map(|i| self.p(i));
            (orient3d(&a, &b, &c, &self.p(tip)) < 0).then(|| {
                let t = h
                    .triangles
                    .iter()
                    .zip(&h.triangle_facet)
                    .find(|&(_, &g)| g as usize == f)
                    .map(|(t, _)| t.map(|i| kept[i as usize]))
                    .unwrap_or(plane);
                let [a, b, c] = t.map(|i| self.p(i));
                let behind = kept
                    .iter()
                    .copied()
                    .find(|&x| orient3d(&a, &b, &c, &self.p(x)) < 0)
                    .unwrap_or(kept[0]);
                (t, behind)
            })
        });
        Bigcap {
            removed,
            simple,
            hidden,
        }
    }

    /// A bottom facet in the plane of a dome facet: the region has a flat sheet there and
    /// is not a simple polyhedron.
    fn sheet(&self, dome: &[usize], h: &Hull3, bottom: &[usize], kept: &[u32]) -> bool {
        bottom.iter().any(|&g| {
            let [a, b, c] = h.facet_planes[g].map(|i| self.p(kept[i as usize]));
            dome.iter().any(|&f| {
                self.facets[f]
                    .iter()
                    .all(|&x| orient3d(&a, &b, &c, &self.p(x)) == 0)
            })
        })
    }
}

/// For each facet of `hull` (of `n` points), the points on it, by `global(i)`.
fn points_of_facets(hull: &Hull3, n: usize, global: impl Fn(usize) -> u32) -> Vec<Vec<u32>> {
    let mut facets = vec![Vec::new(); hull.facet_count()];
    for i in 0..n {
        for &f in hull.facets_of(i) {
            facets[f as usize].push(global(i));
        }
    }
    facets
}

/// The hull's triangles in the given facets, by `global(i)`.
fn triangles_of(hull: &Hull3, facets: &[usize], global: impl Fn(u32) -> u32) -> Vec<[u32; 3]> {
    let chosen: HashSet<u32> = facets.iter().map(|&f| f as u32).collect();
    hull.triangles
        .iter()
        .zip(&hull.triangle_facet)
        .filter(|(_, f)| chosen.contains(f))
        .map(|(t, _)| t.map(&global))
        .collect()
}

/// The triangles form a combinatorial 2-sphere: every edge in two of them, the link of
/// every vertex one cycle, Euler characteristic 2.
fn is_sphere(tris: &[[u32; 3]]) -> bool {
    let mut edges: HashMap<(u32, u32), u32> = HashMap::default();
    let mut links: HashMap<u32, Vec<(u32, u32)>> = HashMap::default();
    for t in tris {
        for k in 0..3 {
            let (a, b, c) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            *edges.entry((a.min(b), a.max(b))).or_default() += 1;
            links.entry(a).or_default().push((b, c));
        }
    }
    let euler = links.len() as i64 - edges.len() as i64 + tris.len() as i64;
    !tris.is_empty()
        && edges.values().all(|&c| c == 2)
        && links.values().all(|l| is_cycle(l))
        && euler == 2
}

/// The edges form one cycle through every vertex they touch.
fn is_cycle(edges: &[(u32, u32)]) -> bool {
    let mut adj: HashMap<u32, Vec<u32>> = HashMap::default();
    for &(a, b) in edges {
        adj.entry(a).or_default().push(b);
        adj.entry(b).or_default().push(a);
    }
    if adj.values().any(|n| n.len() != 2) {
        return false;
    }
    let start = edges[0].0;
    let (mut prev, mut cur, mut steps) = (start, adj[&start][0], 1);
    while cur != start {
        let next = adj[&cur]
            .iter()
            .copied()
            .find(|&x| x != prev)
            .unwrap_or(prev);
        (prev, cur, steps) = (cur, next, steps + 1);
        if steps > adj.len() {
            return false;
        }
    }
    steps == adj.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycles_and_spheres() {
        assert!(is_cycle(&[(1, 2), (2, 3), (3, 1)]));
        assert!(!is_cycle(&[(1, 2), (2, 1), (3, 4), (4, 3)]));
        let tet = [[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]];
        assert!(is_sphere(&tet));
        let mut two = tet.to_vec();
        two.extend(tet.iter().map(|t| t.map(|v| v + 4)));
        assert!(!is_sphere(&two), "two spheres");
    }
}
