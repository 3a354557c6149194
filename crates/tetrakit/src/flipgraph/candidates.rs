//! The empty tetrahedra of a point set, their faces, and which pairs can sit in one
//! tetrahedralization.

use super::FlipError;
use crate::geom::{
    Point3, orient3d, point_in_closed_tetrahedron, segment_punctures_triangle, segments_meet,
};
use rayon::prelude::*;
use rustc_hash::FxHashMap as HashMap;

/// The most candidates enumerated (ids are `u16`; the compatibility table is
/// `MAX_CANDIDATES²` bits, 8 MB).
pub const MAX_CANDIDATES: usize = 8192;

/// A triangle spanned by candidates' faces.
pub(super) struct Face {
    /// Its corners, ascending.
    pub v: [u32; 3],
    /// Its plane supports the point set (every point on one closed side): a tetrahedron on
    /// it has no partner across it.
    pub hull: bool,
    /// The candidates having it as a face with their fourth vertex below (`[0]`,
    /// `orient3d < 0`) and above (`[1]`) the plane of `v` in this order.
    pub sides: [Vec<u16>; 2],
}

/// Every empty tetrahedron of the points (four affinely independent points, no other point
/// in the closed tetrahedron): the tetrahedra of the tetrahedralizations that use every
/// point are exactly these.
pub(super) struct Candidates {
    /// Corners, ascending.
    pub tets: Vec<[u32; 4]>,
    /// `tets` back to ids.
    pub ids: HashMap<[u32; 4], u16>,
    pub faces: Vec<Face>,
    /// Per candidate: its four faces and the side (0 or 1) of [`Face::sides`] it is on.
    pub tet_faces: Vec<[(u32, u8); 4]>,
    /// Per candidate, `words` words: bit `j` set when candidates `i` and `j` meet
    /// properly (in a common face, possibly empty). The diagonal is clear.
    pub compatible: Vec<u64>,
    pub words: usize,
}

impl Candidates {
    /// The row of candidate `c` in [`Candidates::compatible`].
    pub fn row(&self, c: u16) -> &[u64] {
        let start = c as usize * self.words;
        &self.compatible[start..start + self.words]
    }
}

/// The candidates of `pts`, which must be distinct and not all coplanar.
pub(super) fn candidates(pts: &[Point3]) -> Result<Candidates, FlipError> {
    let tets = empty_tetrahedra(pts)?;
    let ids: HashMap<[u32; 4], u16> = (0..tets.len()).map(|i| (tets[i], i as u16)).collect();
    let (faces, tet_faces) = faces(pts, &tets);
    let words = tets.len().div_ceil(64);
    let rows: Vec<Vec<u64>> = (0..tets.len())
        .into_par_iter()
        .map(|i| {
            let mut row = vec![0u64; words];
            for j in 0..tets.len() {
                if j != i && compatible(pts, &tets[i], &tets[j]) {
                    row[j / 64] |= 1 << (j % 64);
                }
            }
            row
        })
        .collect();
    Ok(Candidates {
        tets,
        ids,
        faces,
        tet_faces,
        compatible: rows.concat(),
        words,
    })
}

fn empty_tetrahedra(pts: &[Point3]) -> Result<Vec<[u32; 4]>, FlipError> {
    let n = pts.len() as u32;
    let quads: Vec<[u32; 4]> = (0..n)
        .flat_map(|a| (a + 1..n).flat_map(move |b| (b + 1..n).map(move |c| [a, b, c])))
        .flat_map(|[a, b, c]| (c + 1..n).map(move |d| [a, b, c, d]))
        .collect();
    let tets: Vec<[u32; 4]> = quads
        .into_par_iter()
        .filter(|t| {
            let g = t.map(|v| pts[v as usize]);
            orient3d(&g[0], &g[1], &g[2], &g[3]) != 0
                && (0..n)
                    .all(|x| t.contains(&x) || !point_in_closed_tetrahedron(&pts[x as usize], &g))
        })
        .collect();
    if tets.len() > MAX_CANDIDATES {
        return Err(FlipError::TooManyCandidates(tets.len()));
    }
    Ok(tets)
}

/// The faces of the candidates, each once, and each candidate's four.
fn faces(pts: &[Point3], tets: &[[u32; 4]]) -> (Vec<Face>, Vec<[(u32, u8); 4]>) {
    let mut index: HashMap<[u32; 3], u32> = HashMap::default();
    let mut faces: Vec<Face> = Vec::new();
    let mut tet_faces = Vec::with_capacity(tets.len());
    for (id, t) in tets.iter().enumerate() {
        let mut four = [(0u32, 0u8); 4];
        for (k, slot) in four.iter_mut().enumerate() {
            let mut v = [0u32; 3];
            let mut m = 0;
            for (i, &x) in t.iter().enumerate() {
                if i != k {
                    v[m] = x;
                    m += 1;
                }
            }
            let f = *index.entry(v).or_insert_with(|| {
                faces.push(Face {
                    v,
                    hull: supports(pts, &v),
                    sides: [Vec::new(), Vec::new()],
                });
                faces.len() as u32 - 1
            });
            let [a, b, c] = v.map(|x| &pts[x as usize]);
            let side = u8::from(orient3d(a, b, c, &pts[t[k] as usize]) > 0);
            faces[f as usize].sides[side as usize].push(id as u16);
            *slot = (f, side);
        }
        tet_faces.push(four);
    }
    (faces, tet_faces)
}

/// Every point on one closed side of the plane of `v`.
fn supports(pts: &[Point3], v: &[u32; 3]) -> bool {
    let [a, b, c] = v.map(|x| &pts[x as usize]);
    let (mut below, mut above) = (false, false);
    for p in pts {
        match orient3d(a, b, c, p) {
            s if s < 0 => below = true,
            s if s > 0 => above = true,
            _ => {}
        }
    }
    !(below && above)
}

/// True when the empty tetrahedra `s` and `t` (corner indices) meet in a common face of
/// both (possibly empty), as two tetrahedra of one tetrahedralization must.
///
/// They meet improperly exactly when some vertex set `A` of `s` and a disjoint vertex set
/// `B` of `t` have intersecting hulls (take the carriers of a point of `s ∩ t` outside
/// their common face and subtract its two barycentric expressions). A minimal such pair
/// is a circuit of at most five points; a single point of either in the other is
/// impossible, both being empty, so only an edge meeting an edge and an edge meeting a
/// triangle remain. A face plane of one with every other vertex of the other strictly
/// beyond it proves them proper first.
pub(super) fn compatible(pts: &[Point3], s: &[u32; 4], t: &[u32; 4]) -> bool {
    if separated(pts, s, t) || separated(pts, t, s) {
        return true;
    }
    const EDGES: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    const FACES: [(usize, usize, usize); 4] = [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)];
    let p = |v: u32| &pts[v as usize];
    let crossing = |x: &[u32; 4], y: &[u32; 4]| {
        EDGES.iter().any(|&(i, j)| {
            let e = [x[i], x[j]];
            FACES.iter().any(|&(a, b, c)| {
                let f = [y[a], y[b], y[c]];
                !f.iter().any(|v| e.contains(v))
                    && segment_punctures_triangle(p(e[0]), p(e[1]), p(f[0]), p(f[1]), p(f[2]))
            })
        })
    };
    let edges_meet = EDGES.iter().any(|&(i, j)| {
        EDGES.iter().any(|&(k, l)| {
            let (e, f) = ([s[i], s[j]], [t[k], t[l]]);
            !f.iter().any(|v| e.contains(v))
                && segments_meet(p(e[0]), p(e[1]), p(f[0]), p(f[1])).is_some()
        })
    });
    !(edges_meet || crossing(s, t) || crossing(t, s))
}

/// A face plane of `s` with every vertex of `t` strictly on the far side of `s`'s fourth
/// vertex or a corner of that face.
fn separated(pts: &[Point3], s: &[u32; 4], t: &[u32; 4]) -> bool {
    let p = |v: u32| &pts[v as usize];
    (0..4).any(|k| {
        let f = [s[(k + 1) % 4], s[(k + 2) % 4], s[(k + 3) % 4]];
        let apex = orient3d(p(f[0]), p(f[1]), p(f[2]), p(s[k]));
        t.iter()
            .all(|&w| f.contains(&w) || apex * orient3d(p(f[0]), p(f[1]), p(f[2]), p(w)) < 0)
    })
}
