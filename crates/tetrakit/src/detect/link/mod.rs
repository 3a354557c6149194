//! The puncture-free link of one vertex (thesis §2.4, Steps 2–3, generalized to degenerate
//! input).
//!
//! For a vertex `v` with neighbours `N(v)`, `L_v` is the set of segments between two
//! neighbours. The thesis deletes a segment `ab` of `L_v` when another segment of `L_v`
//! punctures the triangle `vab` (DELETE-SEGMENT), then checks that what is left is a
//! (closed) triangulation seen from `v`. We delete `ab` when *any* segment of `L(v)` —
//! `L_v` plus the segments `vc` — punctures `vab`; with no four points coplanar the two
//! rules agree, and the extra case (a neighbour `c` coplanar with `v, a, b` and seen
//! strictly inside the angle `avb`) is what grids and other coplanar inputs need.
//!
//! Why the deletion is complete (it leaves exactly the link when `L` is the edge set of a
//! tetrahedralization `T`): a link edge `ab` spans a face `vab` of `T`, which no segment
//! punctures, so it is never deleted. A non-link edge `ab` of `L_v`, seen from `v` on the
//! link sphere, leaves the link vertex `a` either along the direction of a neighbour `c`
//! inside the angle `avb` (then `vc` punctures `vab`), or into a link triangle `acd` which
//! it must leave across the edge `cd`; at that crossing `cd` is nearer to `v` than `ab`
//! (were `ab` nearer it would puncture the face `vcd`, were they at the same depth two
//! edges of `T` would cross), so `cd` punctures `vab`. Every deletion is therefore safe and
//! every non-link edge is deleted, in any order.
//!
//! Finding the punctures, two ways ([`LinkMethod`]):
//! - **The sphere sweep** (default; [`sweep`]), the thesis's
//!   CHECK-CLOSED-TRIANGULATION made exact: a meridian rotates about a polar axis through
//!   `v`, arcs that become adjacent are tested, and the punctured one of a crossing pair
//!   is deleted. `O(|L_v| log |L_v|)` exact predicates, the same for hull vertices (whose
//!   link is a disk on the sphere; the thesis projects those onto a plane instead).
//! - **The sign table**: for every segment `ab` of `L_v` the signs of
//!   `orient3d(v, a, b, c)` for all neighbours `c` are tabulated once (`|L_v|·|N(v)|`
//!   filtered tests, one dot product each). Seen from `v`, two segments can only puncture
//!   one another's triangles when their arcs on the sphere of directions cross, which needs
//!   each to straddle the other's plane through `v` (a bitmask test) and the two candidate
//!   crossing points `±(a×b)×(c×d)` to agree (a sign comparison). Deletions are tested
//!   against the whole of `L(v)` at once, with no order at all. `O(|L_v|·(|N(v)| +
//!   |L_v|))` cheap tests: fine on small links, quadratic on the skew-lines family.
//!
//! Both end in one exact `orient3d(a, b, c, d)` per crossing, which tells which segment is
//! nearer `v` (or that they intersect: a witness).
//!
//! The embedding. The link triangles come first from signs (the table's, or computed for
//! the few candidates): for each kept segment `ab`, the apex on each side of the plane
//! `vab` is the common kept neighbour of `a` and `b` nearest in angle around `v→a`. When that gives a consistent triangulated sphere
//! (or disk on the hull) it is the link; otherwise the surviving segments are sorted exactly
//! by angle around each link vertex (a rotation system) and its faces traced, which either
//! yields the link or names what is wrong. Each link triangle must be a positively oriented
//! `(v, a, b, c)`, a hull vertex has one outer face lying on the hull, and the whole is a
//! connected sphere (Euler characteristic 2, so Theorem 2.4's count holds). These checks only
//! need to be *complete*: soundness of a YES comes from the independent verifier.
//!
mod sweep;

use super::graph::{Graph, intersect_sorted};
use super::rotation::{connected, trace_faces};
use super::witness::{Witness, WitnessKind};
use crate::geom::{
    Dir, Frame, Hull3, Point3, collinear3, orient2d_drop, orient3d, projection_axis, segments_meet,
};
use crate::numbering::ids;
use std::cmp::Ordering;

/// Shared read-only context.
pub(super) struct Ctx<'a> {
    pub pts: &'a [Point3],
    pub g: &'a Graph,
    pub hull: &'a Hull3,
    pub method: LinkMethod,
}

/// How the per-vertex pass finds the punctured segments of `L_v`. Both give the same
/// verdict; each is tested against the other and against the brute-force oracle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum LinkMethod {
    /// The exact sphere sweep of thesis §2.4.2: `O(|L_v| log |L_v|)` exact tests, the
    /// faster on every family we measured (Delaunay, grids, skew lines).
    #[default]
    Sweep,
    /// A table of the signs of every neighbour against every segment's plane through `v`
    /// and a bitmask test per pair of segments: `O(|L_v|·(|N(v)| + |L_v|))` cheap tests,
    /// no sweep order at all (the independent second method).
    #[cfg_attr(feature = "clap", value(name = "table"))]
    SignTable,
}

/// Appends the link triangles of `v` to `out` (each `(a, b, c)` with `(v, a, b, c)`
/// positively oriented), or returns a witness that `L` is not the edge set of a
/// tetrahedralization.
pub(super) fn link_into(ctx: &Ctx, v: u32, out: &mut Vec<[u32; 3]>) -> Result<(), Witness> {
    BUFFERS.with(|b| link_with(ctx, v, &mut b.borrow_mut(), out))
}

/// Per-thread buffers reused from one vertex to the next (a vertex's work is small, so
/// allocation would otherwise be a tenth of it).
#[derive(Default)]
struct Buffers {
    pts: Vec<Point3>,
    dirs: Vec<Dir>,
    unit: Vec<Point3>,
    order: Vec<usize>,
    edges: Vec<(u32, u32)>,
    side: Vec<i8>,
    keep: Vec<bool>,
    masks: Vec<(u64, u64, u64)>,
    deg: Vec<u32>,
    fill: Vec<u32>,
    adj: Vec<u32>,
    faces: Vec<[u32; 3]>,
    sweep: sweep::Buffers,
}

thread_local! {
    static BUFFERS: std::cell::RefCell<Buffers> = std::cell::RefCell::new(Buffers::default());
}

fn link_with(ctx: &Ctx, v: u32, b: &mut Buffers, out: &mut Vec<[u32; 3]>) -> Result<(), Witness> {
    let nb = ctx.g.nbrs(v);
    let k = nb.len();
    let pv = &ctx.pts[v as usize];
    if k < 3 {
        return Err(bad(
            v,
            format!(
                "vertex #{v} has {k} neighbour(s); every vertex of a tetrahedralization has at least 3"
            ),
        ));
    }
    let frame = Frame::new(pv);
    b.pts.clear();
    b.pts.extend(nb.iter().map(|&a| ctx.pts[a as usize]));
    b.dirs.clear();
    b.dirs.extend(b.pts.iter().map(|x| frame.dir(x)));
    same_direction(v, nb, pv, &b.pts, &b.dirs, &mut b.unit, &mut b.order)?;
    local_edges(ctx.g, nb, &mut b.edges);
    let lv = LocalView {
        v,
        pv,
        nb,
        p: &b.pts,
        d: &b.dirs,
        frame,
    };
    // The sweep clears `keep` for punctured segments; without a valid pole (adversarial
    // input only) the sign table decides instead.
    b.keep.clear();
    b.keep.resize(b.edges.len(), true);
    let swept = ctx.method == LinkMethod::Sweep
        && sweep::puncture_free_by_sweep(&lv, &b.edges, &mut b.keep, &mut b.sweep)?;
    if !swept {
        puncture_free_by_signs(&lv, &b.edges, &mut b.side, &mut b.keep, &mut b.masks)?;
    }
    let (edges, table) = (&b.edges, &b.side);
    let side = |e: usize, c: u32| {
        if swept {
            let (a, b) = edges[e];
            lv.orient(a as usize, b as usize, c as usize)
        } else {
            table[e * k + c as usize]
        }
    };
    let csr = (&mut b.deg, &mut b.fill, &mut b.adj, &mut b.faces);
    if faces_from_signs(&lv, ctx.hull, edges, &b.keep, side, csr) {
        out.extend(b.faces.iter().step_by(3).map(|f| f.map(|x| lv.g(x))));
        return Ok(());
    }
    out.extend(faces_from_rotation(&lv, ctx.hull, edges, &b.keep)?);
    Ok(())
}

/// The link triangles from the exact rotation system of the kept segments.
fn faces_from_rotation(
    lv: &LocalView,
    hull: &Hull3,
    edges: &[(u32, u32)],
    keep: &[bool],
) -> Result<Vec<[u32; 3]>, Witness> {
    let kept: Vec<(u32, u32)> = edges
        .iter()
        .zip(keep)
        .filter(|(_, k)| **k)
        .map(|(e, _)| *e)
        .collect();
    let rot = rotation_system(lv, &kept)?;
    faces(lv, hull, &rot, kept.len())
}

/// Scratch for [`faces_from_signs`]: degree prefix sums, fill cursors, adjacency, faces.
type CsrBuffers<'b> = (
    &'b mut Vec<u32>,
    &'b mut Vec<u32>,
    &'b mut Vec<u32>,
    &'b mut Vec<[u32; 3]>,
);

/// The fast path to the link triangles: for each kept segment `ab`, the face on each side
/// of the plane `vab` has as apex the common kept neighbour of `a` and `b` on that side that
/// comes first in angle around the axis `v→a` (signs already in the table; more than one
/// candidate only around separating triangles of the link). When every triangle is then
/// seen from its three edges, the boundary lies on the hull, the Euler characteristic is
/// right and the link is connected, these are the faces of the link; anything else returns
/// `false` and the exact rotation system decides (and names the problem). On success the
/// faces are in `faces`, each three times in a row, local indices.
fn faces_from_signs(
    lv: &LocalView,
    hull: &Hull3,
    edges: &[(u32, u32)],
    keep: &[bool],
    side: impl Fn(usize, u32) -> i8,
    (deg, fill, adj, faces): CsrBuffers,
) -> bool {
    let k = lv.nb.len();
    deg.clear();
    deg.resize(k + 1, 0);
    for (e, &(a, b)) in edges.iter().enumerate() {
        if keep[e] {
            deg[a as usize + 1] += 1;
            deg[b as usize + 1] += 1;
        }
    }
    for i in 0..k {
        deg[i + 1] += deg[i];
    }
    fill.clear();
    fill.extend_from_slice(deg);
    adj.clear();
    adj.resize(deg[k] as usize, 0);
    for (e, &(a, b)) in edges.iter().enumerate() {
        if keep[e] {
            adj[fill[a as usize] as usize] = b;
            fill[a as usize] += 1;
            adj[fill[b as usize] as usize] = a;
            fill[b as usize] += 1;
        }
    }
    for i in 0..k {
        adj[deg[i] as usize..deg[i + 1] as usize].sort_unstable();
    }
    let nbr = |a: u32| &adj[deg[a as usize] as usize..deg[a as usize + 1] as usize];
    let on_hull = hull.on_boundary(lv.v as usize);
    faces.clear();
    let mut kept_edges = 0usize;
    for (e, &(a, b)) in edges.iter().enumerate() {
        if !keep[e] {
            continue;
        }
        kept_edges += 1;
        let (mut plus, mut minus) = (u32::MAX, u32::MAX);
        let (na, nb) = (nbr(a), nbr(b));
        let mut ambiguous = false;
        intersect_sorted(na, nb, |j| {
            let c = nb[j];
            // Around the axis v→a, the face apex on each side is the candidate nearest to
            // b in angle (orient3d(v, a, x, y) > 0: x comes first ccw).
            let (slot, nearer) = match side(e, c) {
                1 => (&mut plus, 1),
                -1 => (&mut minus, -1),
                _ => return,
            };
            if *slot != u32::MAX {
                match lv.orient(a as usize, c as usize, *slot as usize) * nearer {
                    1 => {}
                    -1 => return,
                    _ => ambiguous = true,
                }
            }
            *slot = c;
        });
        if ambiguous {
            return false;
        }
        for (apex, tri) in [(plus, [a, b, plus]), (minus, [b, a, minus])] {
            if apex != u32::MAX {
                faces.push(tri);
            } else if !on_hull
                || hull
                    .common_facet(lv.v as usize, lv.g(a) as usize, lv.g(b) as usize)
                    .is_none()
            {
                return false;
            }
        }
    }
    // Each face must have been seen from its three edges, in one rotation.
    for f in faces.iter_mut() {
        *f = min_first(*f);
    }
    faces.sort_unstable();
    if !faces.len().is_multiple_of(3) || faces.chunks(3).any(|c| c[0] != c[1] || c[1] != c[2]) {
        return false;
    }
    let f = faces.len() / 3;
    let euler = k as i64 - kept_edges as i64 + f as i64;
    if euler != if on_hull { 1 } else { 2 }
        || !connected(k, |x| &adj[deg[x] as usize..deg[x + 1] as usize])
    {
        return false;
    }
    true
}

/// The same oriented triangle, rotated to start at its smallest vertex.
#[inline]
fn min_first([a, b, c]: [u32; 3]) -> [u32; 3] {
    if a < b && a < c {
        [a, b, c]
    } else if b < c {
        [b, c, a]
    } else {
        [c, a, b]
    }
}

fn bad(v: u32, detail: String) -> Witness {
    Witness::new(WitnessKind::BadLink, vec![v], vec![], detail)
}

/// The neighbourhood of one vertex `v` in local indices (positions in `nb`).
pub(super) struct LocalView<'a> {
    pub v: u32,
    pub pv: &'a Point3,
    pub nb: &'a [u32],
    pub p: &'a [Point3],
    pub d: &'a [Dir],
    pub frame: Frame,
}

impl LocalView<'_> {
    /// Exact `orient3d(v, a, b, c)` for local indices.
    #[inline]
    fn orient(&self, a: usize, b: usize, c: usize) -> i8 {
        self.frame.sign(
            &self.p[a], &self.p[b], &self.p[c], &self.d[a], &self.d[b], &self.d[c],
        )
    }
    /// The global index of local vertex `i`.
    pub fn g(&self, i: u32) -> u32 {
        self.nb[i as usize]
    }
}

/// Two neighbours on one ray from `v` make the segments `va` and `vb` overlap.
fn same_direction(
    v: u32,
    nb: &[u32],
    pv: &Point3,
    p: &[Point3],
    d: &[Dir],
    unit: &mut Vec<Point3>,
    order: &mut Vec<usize>,
) -> Result<(), Witness> {
    unit.clear();
    unit.extend(d.iter().map(|x| {
        let x = &x.d;
        let l = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
        [x[0] / l, x[1] / l, x[2] / l]
    }));
    order.clear();
    order.extend(0..nb.len());
    order.sort_unstable_by(|&a, &b| unit[a][0].total_cmp(&unit[b][0]));
    // Exactly equal directions differ by a few ulps after rounding: 1e-9 is a safe window.
    const WINDOW: f64 = 1e-9;
    for (x, &i) in order.iter().enumerate() {
        for &j in &order[x + 1..] {
            if unit[j][0] - unit[i][0] > WINDOW {
                break;
            }
            let close = (1..3).all(|c| (unit[j][c] - unit[i][c]).abs() <= WINDOW);
            if close
                && collinear3(pv, &p[i], &p[j])
                && !crate::geom::strictly_between(&p[i], pv, &p[j])
            {
                return Err(Witness::overlap_on_ray(v, nb[i], nb[j]));
            }
        }
    }
    Ok(())
}

/// The segments among neighbours, as pairs of local indices (listed from the neighbours'
/// sorted adjacency lists, never by scanning all segments). Each neighbour's list is
/// intersected with the neighbours after it by galloping, so the work adapts to how the
/// two lists interleave: on the skew-lines family, where a neighbour has Θ(n) neighbours
/// of its own but shares four with `v`, it is logarithmic instead of linear.
fn local_edges(g: &Graph, nb: &[u32], edges: &mut Vec<(u32, u32)>) {
    edges.clear();
    for (i, &a) in nb.iter().enumerate() {
        let na = g.nbrs(a);
        let after = &na[na.partition_point(|&b| b <= a)..];
        intersect_sorted(after, &nb[i + 1..], |j| {
            edges.push((i as u32, (i + 1 + j) as u32));
        });
    }
}

/// Which segments of `L_v` survive the generalized puncture rule.
fn puncture_free_by_signs(
    lv: &LocalView,
    edges: &[(u32, u32)],
    side: &mut Vec<i8>,
    keep: &mut Vec<bool>,
    masks: &mut Vec<(u64, u64, u64)>,
) -> Result<(), Witness> {
    let k = lv.nb.len();
    let m = edges.len();
    // side[e * k + c] = orient3d(v, a, b, c) for edge e = (a, b).
    side.clear();
    side.resize(m * k, 0);
    keep.clear();
    keep.resize(m, true);
    for (e, &(a, b)) in edges.iter().enumerate() {
        let (a, b) = (a as usize, b as usize);
        let row = &mut side[e * k..(e + 1) * k];
        let mut coplanar = Vec::new();
        let plane = lv.frame.plane(&lv.d[a], &lv.d[b]);
        for (c, slot) in row.iter_mut().enumerate() {
            if c != a && c != b {
                *slot = lv
                    .frame
                    .side(&plane, &lv.p[a], &lv.p[b], &lv.p[c], &lv.d[c]);
                if *slot == 0 {
                    coplanar.push(c);
                }
            }
        }
        if coplanar.len() + 2 == k && collinear3(lv.pv, &lv.p[a], &lv.p[b]) {
            // Not on one ray (checked before), so v lies inside segment ab.
            let (ga, gb) = (lv.g(a as u32), lv.g(b as u32));
            return Err(Witness::new(
                WitnessKind::VertexOnSegment,
                vec![lv.v, ga, gb],
                vec![[ga, gb]],
                format!("vertex #{} lies inside segment (#{ga}, #{gb})", lv.v),
            ));
        }
        if !coplanar.is_empty() && blocked(lv, a, b, &coplanar) {
            keep[e] = false;
        }
    }
    // Bitmasks of the neighbours strictly on each side of each segment's plane through v,
    // and of each segment's endpoints (when there are at most 64 neighbours), turn the
    // straddle tests into bit operations: cd straddles the plane vab when each side of it
    // holds one endpoint (segments sharing an endpoint never do: it has sign 0).
    masks.clear();
    if k <= 64 {
        masks.extend((0..m).map(|e| {
            let row = &side[e * k..(e + 1) * k];
            let (p, q) = row
                .iter()
                .enumerate()
                .fold((0u64, 0u64), |(p, q), (c, &x)| {
                    (p | (u64::from(x > 0) << c), q | (u64::from(x < 0) << c))
                });
            (p, q, (1u64 << edges[e].0) | (1u64 << edges[e].1))
        }));
    }
    let (side, masks) = (&*side, &*masks);
    let straddles =
        |e: usize, c: u32, d: u32| side[e * k + c as usize] * side[e * k + d as usize] < 0;
    for e in 0..m {
        let (a, b) = edges[e];
        let mut check = |f: usize| -> Result<(), Witness> {
            let (c, d) = edges[f];
            let (sa, sc) = (side[f * k + a as usize], side[e * k + c as usize]);
            // The great circles of ab and cd meet in ±X with X = (a×b)×(c×d) (directions
            // from v); the point on arc cd is sign(orient(v,a,b,d))·X and the point on arc
            // ab is sign(orient(v,c,d,a))·X. Different signs: the arcs meet only
            // antipodally, and neither segment can puncture the other's triangle.
            if side[e * k + d as usize] != sa {
                return Ok(());
            }
            match crossing(lv, (a, b), (c, d), sa, sc)? {
                Some(true) => keep[e] = false,
                Some(false) => keep[f] = false,
                None => {}
            }
            Ok(())
        };
        // Seen from v, the arcs ab and cd can only cross (and a segment only puncture the
        // other's triangle) when each straddles the other's plane through v.
        if let Some(&(pe, qe, me)) = masks.get(e) {
            for (f, &(pf, qf, mf)) in masks.iter().enumerate().skip(e + 1) {
                if (pe & mf != 0) & (qe & mf != 0) & (pf & me != 0) & (qf & me != 0) {
                    check(f)?;
                }
            }
        } else {
            for (f, &(c, d)) in edges.iter().enumerate().skip(e + 1) {
                if straddles(e, c, d) && straddles(f, a, b) {
                    check(f)?;
                }
            }
        }
    }
    Ok(())
}

/// For segments `ab`, `cd` of `L_v` that straddle each other's planes through `v`
/// (`sa = orient3d(v, c, d, a)`, `sc = orient3d(v, a, b, c)`, both non-zero): `Some(true)`
/// when `cd` punctures the triangle `vab`, `Some(false)` when `ab` punctures `vcd`, `None`
/// when their arcs meet only antipodally. Segments that intersect are a witness.
///
/// Of the three orientations deciding whether line `cd` passes inside triangle `vab`, two
/// are `orient3d(c, d, v, a) = sa` and `orient3d(c, d, b, v) = −orient3d(v, c, d, b) = sa`;
/// the third, `orient3d(c, d, a, b) = orient3d(a, b, c, d)`, is the only new test, and
/// symmetrically for `ab` inside `vcd` (against `sc`).
pub(super) fn crossing(
    lv: &LocalView,
    (a, b): (u32, u32),
    (c, d): (u32, u32),
    sa: i8,
    sc: i8,
) -> Result<Option<bool>, Witness> {
    let q = |i: u32| &lv.p[i as usize];
    let t = orient3d(q(a), q(b), q(c), q(d));
    if t == sa {
        return Ok(Some(true));
    }
    if t == sc {
        return Ok(Some(false));
    }
    if t == 0 && segments_meet(q(a), q(b), q(c), q(d)).is_some() {
        let (ga, gb, gc, gd) = (lv.g(a), lv.g(b), lv.g(c), lv.g(d));
        return Err(Witness::new(
            WitnessKind::CrossingSegments,
            vec![ga, gb, gc, gd],
            vec![[ga, gb], [gc, gd]],
            format!("segments (#{ga}, #{gb}) and (#{gc}, #{gd}) cross"),
        ));
    }
    Ok(None)
}

/// Does a neighbour `c`, coplanar with `v, a, b`, lie strictly inside the angle `avb`?
/// Then the segment `vc` punctures the triangle `vab`.
fn blocked(lv: &LocalView, a: usize, b: usize, coplanar: &[usize]) -> bool {
    let Some(axis) = projection_axis(lv.pv, &lv.p[a], &lv.p[b]) else {
        return false;
    };
    let s = orient2d_drop(lv.pv, &lv.p[a], &lv.p[b], axis);
    coplanar.iter().any(|&c| {
        orient2d_drop(lv.pv, &lv.p[a], &lv.p[c], axis) == s
            && orient2d_drop(lv.pv, &lv.p[c], &lv.p[b], axis) == s
    })
}

/// For each local vertex, its kept neighbours sorted counter-clockwise around the axis
/// from `v` through it.
fn rotation_system(lv: &LocalView, kept: &[(u32, u32)]) -> Result<Vec<Vec<u32>>, Witness> {
    let k = lv.nb.len();
    let mut adj: Vec<Vec<u32>> = vec![Vec::new(); k];
    for &(a, b) in kept {
        adj[a as usize].push(b);
        adj[b as usize].push(a);
    }
    for (a, list) in adj.iter_mut().enumerate() {
        if list.len() < 2 {
            let u = lv.g(a as u32);
            return Err(bad(
                lv.v,
                format!(
                    "neighbour #{u} of vertex #{} keeps {} segment(s) to other neighbours once punctured segments are removed; a link vertex needs at least 2",
                    lv.v,
                    list.len()
                ),
            ));
        }
        sort_around(lv, a, list)?;
    }
    Ok(adj)
}

/// Sorts `list` by angle around the axis `v → a`, exactly.
fn sort_around(lv: &LocalView, a: usize, list: &mut [u32]) -> Result<(), Witness> {
    let b0 = list[0] as usize;
    let axis = projection_axis(lv.pv, &lv.p[a], &lv.p[b0]).expect("checked non-collinear");
    let s0 = orient2d_drop(lv.pv, &lv.p[a], &lv.p[b0], axis);
    let half = |b: usize| -> u8 {
        if b == b0 {
            return 0;
        }
        match lv.orient(a, b0, b) {
            1 => 1,
            -1 => 3,
            _ if orient2d_drop(lv.pv, &lv.p[a], &lv.p[b], axis) == s0 => 0,
            _ => 2,
        }
    };
    let mut keyed: Vec<(u8, u32)> = list.iter().map(|&b| (half(b as usize), b)).collect();
    keyed.sort_by(|x, y| {
        x.0.cmp(&y.0).then_with(|| {
            if x.0 % 2 == 0 {
                return Ordering::Equal;
            }
            match lv.orient(a, x.1 as usize, y.1 as usize) {
                1 => Ordering::Less,
                -1 => Ordering::Greater,
                _ => Ordering::Equal,
            }
        })
    });
    for w in keyed.windows(2) {
        let same = w[0].0 == w[1].0
            && (w[0].0 % 2 == 0 || lv.orient(a, w[0].1 as usize, w[1].1 as usize) == 0);
        if same {
            let (u, x, y) = (lv.g(a as u32), lv.g(w[0].1), lv.g(w[1].1));
            return Err(bad(
                lv.v,
                format!(
                    "seen from vertex #{}, segments (#{u}, #{x}) and (#{u}, #{y}) leave #{u} in the same direction",
                    lv.v
                ),
            ));
        }
    }
    for (slot, (_, b)) in list.iter_mut().zip(keyed) {
        *slot = b;
    }
    Ok(())
}

/// Traces the faces of the rotation system and checks they form the link of `v`.
fn faces(
    lv: &LocalView,
    hull: &Hull3,
    rot: &[Vec<u32>],
    edge_count: usize,
) -> Result<Vec<[u32; 3]>, Witness> {
    let v = lv.v;
    let k = rot.len();
    let mut inner = Vec::new();
    let mut outer: Vec<Vec<u32>> = Vec::new();
    let all = trace_faces(rot);
    let face_count = all.len();
    for cycle in all {
        if cycle.len() == 3
            && lv.orient(cycle[0] as usize, cycle[1] as usize, cycle[2] as usize) > 0
        {
            inner.push([lv.g(cycle[0]), lv.g(cycle[1]), lv.g(cycle[2])]);
        } else {
            outer.push(cycle);
        }
    }
    let euler = k as i64 - edge_count as i64 + face_count as i64;
    if euler != 2 || !connected(k, |x| &rot[x]) {
        return Err(bad(
            v,
            format!(
                "once punctured segments are removed, the link of vertex #{v} has {k} vertices, {edge_count} edges and {face_count} faces (V-E+F = {euler}{}), not a triangulated sphere",
                if connected(k, |x| &rot[x]) {
                    ""
                } else {
                    ", disconnected"
                }
            ),
        ));
    }
    let on_hull = hull.on_boundary(v as usize);
    let expected_outer = usize::from(on_hull);
    if outer.len() != expected_outer {
        let f = outer.iter().find(|c| c.len() != 3).or(outer.first());
        let names: Vec<u32> = f
            .map(|c| c.iter().map(|&x| lv.g(x)).collect())
            .unwrap_or_default();
        let detail = if on_hull {
            format!(
                "vertex #{v} is on the hull, so its link must be a triangulated disk, but it has {} non-triangular or reflex faces (one of them: {})",
                outer.len(),
                ids(&names)
            )
        } else {
            format!(
                "vertex #{v} is inside the hull, so its link must be a closed triangulated surface around it, but face {} is not a triangle seen positively from #{v}",
                ids(&names)
            )
        };
        let mut w = bad(v, detail);
        w.vertices.extend(names);
        return Err(w);
    }
    if let Some(cycle) = outer.first() {
        for i in 0..cycle.len() {
            let (x, y) = (lv.g(cycle[i]), lv.g(cycle[(i + 1) % cycle.len()]));
            if hull
                .common_facet(v as usize, x as usize, y as usize)
                .is_none()
            {
                return Err(Witness::new(
                    WitnessKind::BadLink,
                    vec![v, x, y],
                    vec![[x, y]],
                    format!(
                        "the boundary of the link of hull vertex #{v} passes along segment (#{x}, #{y}), but triangle (#{v}, #{x}, #{y}) is not on the hull"
                    ),
                ));
            }
        }
    }
    Ok(inner)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate;

    /// At every vertex of `t` (a valid tetrahedralization): the sphere sweep keeps exactly
    /// the segments the sign table keeps (the link), and the faces from signs, when they
    /// are found, equal the faces of the exact rotation system. Returns how many vertices
    /// took the fast faces.
    fn check_methods_agree(t: &crate::mesh::Tetrahedralization) -> usize {
        let segs = t.edges();
        let g = Graph::new(t.points.len(), &segs).unwrap();
        let hull = Hull3::new(&t.points);
        let mut fast_hits = 0;
        for v in 0..t.points.len() as u32 {
            let nb = g.nbrs(v);
            let frame = Frame::new(&t.points[v as usize]);
            let p: Vec<Point3> = nb.iter().map(|&a| t.points[a as usize]).collect();
            let d: Vec<Dir> = p.iter().map(|x| frame.dir(x)).collect();
            let lv = LocalView {
                v,
                pv: &t.points[v as usize],
                nb,
                p: &p,
                d: &d,
                frame,
            };
            let mut edges = Vec::new();
            local_edges(&g, nb, &mut edges);
            let (mut side, mut keep, mut masks) = (Vec::new(), Vec::new(), Vec::new());
            puncture_free_by_signs(&lv, &edges, &mut side, &mut keep, &mut masks).unwrap();
            let mut swept = vec![true; edges.len()];
            let mut bufs = Default::default();
            let swept_ok = super::sweep::puncture_free_by_sweep(&lv, &edges, &mut swept, &mut bufs);
            assert!(swept_ok.unwrap());
            assert_eq!(swept, keep, "sweep and sign table disagree at vertex {v}");
            let mut slow = faces_from_rotation(&lv, &hull, &edges, &keep).unwrap();
            let norm = |f: &mut Vec<[u32; 3]>| {
                f.iter_mut().for_each(|x| *x = min_first(*x));
                f.sort_unstable();
            };
            norm(&mut slow);
            let mut bufs = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
            let csr = (&mut bufs.0, &mut bufs.1, &mut bufs.2, &mut bufs.3);
            let k = nb.len();
            let side = |e: usize, c: u32| side[e * k + c as usize];
            if faces_from_signs(&lv, &hull, &edges, &keep, side, csr) {
                let mut fast: Vec<[u32; 3]> = bufs
                    .3
                    .iter()
                    .step_by(3)
                    .map(|f| f.map(|x| lv.g(x)))
                    .collect();
                norm(&mut fast);
                assert_eq!(fast, slow, "vertex {v}");
                fast_hits += 1;
            }
        }
        fast_hits
    }

    /// Grids, random, cospherical and skew-lines tetrahedralizations.
    #[test]
    fn link_methods_and_face_paths_agree() {
        let meshes = [
            generate::kuhn(3),
            generate::random_tetrahedralization(300, 600, 3, None),
            generate::random_tetrahedralization(200, 300, 4, Some(6)),
            generate::tetrahedralize_points(generate::cospherical_points(50), 2),
            generate::skew_lines(16),
            generate::skew_lines(61),
            generate::kuhn(5),
        ];
        let fast_hits: usize = meshes.iter().map(check_methods_agree).sum();
        assert!(
            fast_hits > 500,
            "the fast path should handle most vertices: {fast_hits}"
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        /// Random tetrahedralizations, on floats or on small integer grids (coplanar and
        /// cocircular points everywhere), with random flips.
        #[test]
        fn link_methods_agree_on_random_tetrahedralizations(
            n in 8usize..80,
            flips in 0usize..200,
            seed in 0u64..1_000_000,
            grid in proptest::option::of(2u32..6),
        ) {
            let t = generate::random_tetrahedralization(n, flips, seed, grid);
            if !t.tets.is_empty() {
                check_methods_agree(&t);
            }
        }
    }
}
