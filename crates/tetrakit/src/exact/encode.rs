//! Candidate tetrahedra and the CNF of "these candidates form a tetrahedralization".

use crate::geom::{
    Point3, orient2d_drop, orient3d, point_in_closed_tetrahedron, projection_axis,
    triangle_meets_tet,
};
use crate::mesh::Polyhedron;
use crate::rng::Rng;
use std::collections::HashMap;

/// The domain to tetrahedralize.
#[derive(Clone, Copy, Debug)]
pub enum Domain<'a> {
    /// A simple polyhedron, with its vertices only.
    Polyhedron(&'a Polyhedron),
    /// The convex hull of a point set, using every point (a *fine* triangulation).
    Points(&'a [Point3]),
    /// The region between two nested convex polytopes (they may touch), by its boundary
    /// triangles, each oriented outward from the region: the outer surface's facing
    /// out, the inner surface's facing into the inner polytope. The tetrahedralizations
    /// are those with exactly these boundary triangles.
    Shell {
        /// The vertices (every one on a boundary triangle).
        points: &'a [Point3],
        /// The boundary triangles.
        faces: &'a [[u32; 3]],
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
            Domain::Shell { faces, .. } => faces,
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
    /// For a point set: the triangle lies in a supporting plane (on the hull's boundary).
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
    /// The number of tetrahedra is `interior edges used + offset`.
    pub(crate) offset: i64,
}

/// Enumerates candidates: every 4-subset of vertices that spans a tetrahedron whose
/// closed set holds no other vertex; for a polyhedron, also no facet meeting it other
/// than in shared vertices and edges, and the inner side of any facet it has.
pub(crate) fn candidates(domain: Domain) -> Candidates {
    let pts = domain.points();
    let n = pts.len() as u32;
    let mut tets = Vec::new();
    let facets: Vec<[u32; 3]> = domain.faces().to_vec();
    let facet_set: HashMap<[u32; 3], [u32; 3]> = facets
        .iter()
        .map(|&f| (crate::mesh::sorted_face(f), f))
        .collect();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                for d in c + 1..n {
                    let t = [a, b, c, d];
                    let geo = t.map(|v| pts[v as usize]);
                    if orient3d(&geo[0], &geo[1], &geo[2], &geo[3]) == 0 {
                        continue;
                    }
                    if (0..n).any(|x| {
                        !t.contains(&x) && point_in_closed_tetrahedron(&pts[x as usize], &geo)
                    }) {
                        continue;
                    }
                    if !facets.is_empty() && !fits_polyhedron(pts, &facets, &facet_set, t) {
                        continue;
                    }
                    tets.push(t);
                }
            }
        }
    }
    let mut triangles: HashMap<[u32; 3], TriangleUse> = HashMap::new();
    let mut edges: HashMap<[u32; 2], Vec<u32>> = HashMap::new();
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
                edges.entry([t[x], t[y]]).or_default().push(i as u32);
            }
        }
    }
    // Euler: t = e_i + offset (see the module docs of `exact`).
    let (boundary_edges, offset) = match domain {
        Domain::Polyhedron(_) | Domain::Shell { .. } => {
            let edges: std::collections::HashSet<[u32; 2]> = facets
                .iter()
                .flat_map(|f| [[f[0], f[1]], [f[1], f[2]], [f[0], f[2]]])
                .map(|[a, b]| [a.min(b), a.max(b)])
                .collect();
            // χ = 1 for a ball, 2 for the region between nested polytopes (P = region
            // ∪ Q, meeting in ∂Q: 1 = χ + 1 − 2), and t = χ − n + e_b − f_b / 2 + e_i.
            let chi = if matches!(domain, Domain::Shell { .. }) {
                2
            } else {
                1
            };
            let offset = chi - n as i64 + edges.len() as i64 - facets.len() as i64 / 2;
            (edges, offset)
        }
        Domain::Points(_) => {
            for (f, usage) in triangles.iter_mut() {
                usage.on_hull = supporting(pts, f);
            }
            let on_hull: std::collections::HashSet<[u32; 2]> = triangles
                .iter()
                .filter(|(_, usage)| usage.on_hull)
                .map(|(f, _)| f)
                .flat_map(|f| [[f[0], f[1]], [f[0], f[2]], [f[1], f[2]]])
                .collect();
            let hull = crate::geom::Hull3::new(pts);
            let nb = (0..pts.len()).filter(|&i| hull.on_boundary(i)).count();
            (on_hull, 2 * nb as i64 - n as i64 - 3)
        }
    };
    let mut interior_edges: Vec<([u32; 2], Vec<u32>)> = edges
        .into_iter()
        .filter(|(e, _)| !boundary_edges.contains(e))
        .collect();
    interior_edges.sort_unstable();
    Candidates {
        tets,
        triangles,
        interior_edges,
        offset,
    }
}

/// True when the plane of `f` supports the point set (all points on one closed side).
fn supporting(pts: &[Point3], f: &[u32; 3]) -> bool {
    let [a, b, c] = f.map(|v| &pts[v as usize]);
    let mut seen = 0i8;
    for p in pts {
        let s = orient3d(a, b, c, p);
        if s != 0 {
            if seen != 0 && s != seen {
                return false;
            }
            seen = s;
        }
    }
    true
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

/// A point strictly inside some candidate and on no candidate triangle: in every
/// tetrahedralization it is interior to exactly one tetrahedron. Returns the indices of
/// the candidates containing it.
pub(crate) fn anchor(pts: &[Point3], c: &Candidates) -> Option<Vec<u32>> {
    let mut rng = Rng::new(0x5eed);
    for attempt in 0..200 {
        let t = c.tets.get(if attempt == 0 {
            0
        } else {
            rng.below(c.tets.len())
        })?;
        let geo = t.map(|v| pts[v as usize]);
        let w: [f64; 4] = if attempt == 0 {
            [0.25; 4]
        } else {
            let r = [0, 1, 2, 3].map(|_| 0.5 + rng.unit());
            let s: f64 = r.iter().sum();
            r.map(|x| x / s)
        };
        let x: Point3 = [0, 1, 2].map(|i| (0..4).map(|k| w[k] * geo[k][i]).sum());
        if !strictly_inside(&x, &geo) {
            continue;
        }
        let on_triangle = c.triangles.keys().any(|f| {
            let [a, b, cc] = f.map(|v| &pts[v as usize]);
            orient3d(a, b, cc, &x) == 0 && in_closed_triangle(&x, a, b, cc)
        });
        if on_triangle {
            continue;
        }
        let holders = c
            .tets
            .iter()
            .enumerate()
            .filter(|(_, t)| strictly_inside(&x, &t.map(|v| pts[v as usize])))
            .map(|(i, _)| i as u32)
            .collect();
        return Some(holders);
    }
    None
}

fn strictly_inside(x: &Point3, t: &[Point3; 4]) -> bool {
    let s = orient3d(&t[0], &t[1], &t[2], &t[3]);
    [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)]
        .iter()
        .all(|&(a, b, c)| s * orient3d(&t[a], &t[b], &t[c], x) < 0)
}

fn in_closed_triangle(x: &Point3, a: &Point3, b: &Point3, c: &Point3) -> bool {
    let Some(axis) = projection_axis(a, b, c) else {
        return false;
    };
    let s = orient2d_drop(a, b, c, axis);
    [(a, b), (b, c), (c, a)]
        .iter()
        .all(|(p, q)| s * orient2d_drop(p, q, x, axis) >= 0)
}
