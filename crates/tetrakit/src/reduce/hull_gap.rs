//! Lemma 2.6: the region between a simple polyhedron `Q` whose vertices are all vertices
//! of its convex hull and that hull is tetrahedralized by flipping reflex edges outward.
//!
//! A reflex edge `ab` of the current polyhedron, with faces `abc` and `bad`, is replaced
//! by `cd`: the tetrahedron `abcd` is added, the faces `abc`, `bad` give way to `acd`,
//! `bdc`, and the polyhedron grows by `abcd`. The thesis proves that `cd` never meets
//! the polyhedron inside (every vertex being a hull vertex); this module checks each
//! flip exactly anyway (the tetrahedron holds no other vertex and meets no other face
//! improperly), tries the next reflex edge when a check fails, and refuses only when
//! none passes. Ends when no edge is reflex: the polyhedron is then its hull.

use crate::bug::Bug;
use crate::control::{Control, Stopped};
use crate::geom::{Hull3, orient3d, point_in_closed_tetrahedron, triangle_meets_tet};
use crate::mesh::{Polyhedron, Problem, certify_boundary};
use std::collections::HashMap;

/// Why [`hull_gap`] refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum HullGapError {
    /// A vertex of `Q` is not a vertex of its hull (Lemma 2.6's condition).
    NotHullVertex(u32),
    /// Reflex edges remain but no flip passes the exact checks (a counterexample to the
    /// lemma's proof, or a degenerate input it does not cover: coplanar faces).
    Stuck([u32; 2]),
    /// The run-control stopped the flips.
    Stopped(Stopped),
    /// The tetrahedra failed the certificate (a bug): the verifier's problem.
    Uncertified(Problem),
    /// A face left after the flips is not on the hull (a bug).
    Internal(Bug),
}

impl std::fmt::Display for HullGapError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            HullGapError::NotHullVertex(v) => {
                write!(
                    f,
                    "vertex #{v} is not a vertex of the convex hull (Lemma 2.6 needs V(Q) = V(CH(Q)))"
                )
            }
            HullGapError::Stuck([a, b]) => {
                write!(f, "no reflex edge can be flipped (first: (#{a}, #{b}))")
            }
            HullGapError::Stopped(_) => write!(f, "stopped before the gap was filled"),
            HullGapError::Uncertified(p) => write!(
                f,
                "internal error, please report the input: the tetrahedra fail their certificate: {p}"
            ),
            HullGapError::Internal(bug) => bug.fmt(f),
        }
    }
}

impl std::error::Error for HullGapError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            HullGapError::Stopped(s) => Some(s),
            HullGapError::Uncertified(p) => Some(p),
            HullGapError::Internal(bug) => Some(bug),
            _ => None,
        }
    }
}

/// The tetrahedra filling `CH(Q) − Q` (positively oriented), certified: a valid mesh
/// whose boundary is exactly the hull's triangles that are not faces of `Q` and `Q`'s
/// faces that are not on the hull, reversed.
///
/// ```
/// use tetrakit::mesh::Polyhedron;
/// use tetrakit::reduce::hull_gap;
/// // A square pyramid whose base, one corner raised, is split along the diagonal that
/// // dents it in: one reflex edge, one tetrahedron of gap.
/// let pts = vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [2.0, 2.0, 0.5], [1.0, 1.0, 3.0]];
/// let faces = vec![[0, 2, 3], [0, 3, 1], [0, 1, 4], [1, 3, 4], [3, 2, 4], [2, 0, 4]];
/// let q = Polyhedron::new(pts, faces).unwrap();
/// let gap = hull_gap(&q, &tetrakit::control::Control::new()).unwrap();
/// assert_eq!(gap.len(), 1);
/// ```
pub fn hull_gap(q: &Polyhedron, ctl: &Control) -> Result<Vec<[u32; 4]>, HullGapError> {
    let pts = &q.points;
    let hull = Hull3::new(pts);
    if let Some(v) = (0..pts.len()).find(|&v| hull.facets_of(v).len() < 3) {
        return Err(HullGapError::NotHullVertex(v as u32));
    }
    let mut faces = q.faces.clone();
    let mut tets = Vec::new();
    loop {
        if ctl.is_stopped() {
            return Err(HullGapError::Stopped(Stopped));
        }
        let reflex = reflex_edges(pts, &faces);
        let Some(first) = reflex.first() else {
            break;
        };
        let Some(flip) = reflex.iter().find_map(|r| try_flip(pts, &faces, r)) else {
            return Err(HullGapError::Stuck(first.edge));
        };
        tets.push(flip.tet);
        for (k, f) in flip.faces.into_iter().zip(flip.new) {
            faces[k] = f;
        }
    }
    if tets.is_empty() {
        return Ok(tets);
    }
    if let Some(f) = faces.iter().find(|f| {
        hull.common_facet(f[0] as usize, f[1] as usize, f[2] as usize)
            .is_none()
    }) {
        let check = "every face left after the flips is on the hull";
        return Err(HullGapError::Internal(Bug::at(check, *f)));
    }
    // The gap's boundary: the hull's triangles that are not faces of Q, and Q's faces
    // that are not on the hull, reversed.
    let key = |f: &[u32; 3]| crate::mesh::sorted_face(*f);
    let kept: std::collections::HashSet<[u32; 3]> = faces.iter().map(key).collect();
    let original: std::collections::HashSet<[u32; 3]> = q.faces.iter().map(key).collect();
    let mut boundary: Vec<[u32; 3]> = faces
        .into_iter()
        .filter(|f| !original.contains(&key(f)))
        .collect();
    boundary.extend(
        q.faces
            .iter()
            .filter(|f| !kept.contains(&key(f)))
            .map(|&[a, b, c]| [a, c, b]),
    );
    certify_boundary(pts, &tets, &boundary).map_err(HullGapError::Uncertified)?;
    Ok(tets)
}

/// A reflex edge `ab` and its faces `abc`, `bad` (indices).
struct Reflex {
    edge: [u32; 2],
    faces: [usize; 2],
}

/// A flip: the tetrahedron added, the two faces it replaces, their replacements.
struct Flip {
    tet: [u32; 4],
    faces: [usize; 2],
    new: [[u32; 3]; 2],
}

/// Reflex edges: `d` strictly outside face `abc`, in a fixed order.
fn reflex_edges(pts: &[[f64; 3]], faces: &[[u32; 3]]) -> Vec<Reflex> {
    let mut by_edge: HashMap<(u32, u32), usize> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            by_edge.insert((f[k], f[(k + 1) % 3]), i);
        }
    }
    let third =
        |f: &[u32; 3], a: u32, b: u32| *f.iter().find(|&&v| v != a && v != b).expect("a triangle");
    let p = |v: u32| &pts[v as usize];
    let mut out = Vec::new();
    for (&(a, b), &i) in &by_edge {
        if a > b {
            continue;
        }
        let Some(&j) = by_edge.get(&(b, a)) else {
            continue;
        };
        let (c, d) = (third(&faces[i], a, b), third(&faces[j], a, b));
        if orient3d(p(a), p(b), p(c), p(d)) > 0 {
            out.push(Reflex {
                edge: [a, b],
                faces: [i, j],
            });
        }
    }
    out.sort_unstable_by_key(|r| r.edge);
    out
}

/// The flip of reflex edge `ab` (faces `abc`, `bad`) if its tetrahedron `abcd` holds no
/// other vertex and meets no other face improperly: the tetrahedron (positively
/// oriented) and the two new faces `acd`, `bdc`.
fn try_flip(pts: &[[f64; 3]], faces: &[[u32; 3]], r: &Reflex) -> Option<Flip> {
    let ([a, b], [fi, fj]) = (r.edge, r.faces);
    let rotate = |f: [u32; 3], v: u32| {
        let k = f.iter().position(|&x| x == v).expect("vertex of face");
        [f[k], f[(k + 1) % 3], f[(k + 2) % 3]]
    };
    // faces[fi] = (a, b, c) and faces[fj] = (b, a, d) up to rotation.
    let [_, _, c] = rotate(faces[fi], a);
    let [_, _, d] = rotate(faces[fj], b);
    let p = |v: u32| pts[v as usize];
    let t = [a, b, c, d];
    let geo = t.map(p);
    if orient3d(&geo[0], &geo[1], &geo[2], &geo[3]) == 0 {
        return None;
    }
    if (0..pts.len() as u32)
        .any(|v| !t.contains(&v) && point_in_closed_tetrahedron(&pts[v as usize], &geo))
    {
        return None;
    }
    let clash = faces
        .iter()
        .enumerate()
        .any(|(k, f)| k != fi && k != fj && triangle_meets_tet(&f.map(p), *f, &geo, &t));
    if clash {
        return None;
    }
    let tet = if orient3d(&geo[0], &geo[1], &geo[2], &geo[3]) > 0 {
        t
    } else {
        [a, c, b, d]
    };
    // Each new face outward: the tetrahedron's fourth vertex behind it (a point in front
    // of an outward face has positive orientation, as in `reflex_edges`).
    let outward = |[x, y, z]: [u32; 3], behind: u32| {
        if orient3d(&p(x), &p(y), &p(z), &p(behind)) > 0 {
            [x, z, y]
        } else {
            [x, y, z]
        }
    };
    Some(Flip {
        tet,
        faces: [fi, fj],
        new: [outward([a, c, d], b), outward([b, d, c], a)],
    })
}
