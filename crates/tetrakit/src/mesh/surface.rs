//! Simple polyhedra: a closed triangulated surface, checked exactly (thesis §3.2.1: "Let
//! P be a simple polyhedron"). The thesis assumes general position; nothing here does.

use crate::geom::{Expansion, Point3, collinear3, orient3d_value};
use std::fmt;

/// A simple polyhedron: its vertices and its triangular facets, each oriented
/// counter-clockwise seen from outside (`orient3d(a, b, c, x) < 0` for points `x` just
/// inside).
#[derive(Clone, Debug)]
pub struct Polyhedron {
    /// The vertices.
    pub points: Vec<Point3>,
    /// The facets, outward oriented.
    pub faces: Vec<[u32; 3]>,
}

/// Why a surface is not a simple polyhedron. Faces are named by their 0-based position in
/// the input and vertices by their 0-based index; the CLI shifts both to the file's
/// numbering.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SurfaceError {
    /// The faces involved.
    pub faces: Vec<usize>,
    /// The vertices involved.
    pub vertices: Vec<u32>,
    /// What is wrong, in words, without the names above.
    pub problem: String,
}

impl SurfaceError {
    fn new(faces: Vec<usize>, vertices: Vec<u32>, problem: impl Into<String>) -> Self {
        SurfaceError {
            faces,
            vertices,
            problem: problem.into(),
        }
    }

    /// The message with faces and vertices numbered from `base`.
    pub fn describe(&self, base: u32) -> String {
        let mut parts = Vec::new();
        if !self.faces.is_empty() {
            let f: Vec<String> = self
                .faces
                .iter()
                .map(|f| (f + base as usize).to_string())
                .collect();
            parts.push(format!("face {}", f.join(", ")));
        }
        if !self.vertices.is_empty() {
            let v: Vec<String> = self
                .vertices
                .iter()
                .map(|v| (v + base).to_string())
                .collect();
            parts.push(format!("vertex {}", v.join(", ")));
        }
        if parts.is_empty() {
            self.problem.clone()
        } else {
            format!("{}: {}", parts.join("; "), self.problem)
        }
    }
}

impl fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe(0))
    }
}

impl std::error::Error for SurfaceError {}

impl Polyhedron {
    /// Checks that `faces` bound a simple polyhedron and orients them outward: every face
    /// a proper triangle, every vertex on a face, every edge in exactly two faces, a disk
    /// around every vertex, one connected orientable piece of genus 0, and no two faces
    /// meeting other than in their shared vertices and edge (exact tests).
    ///
    /// ```
    /// use tetrakit::polyhedra::Polyhedron;
    /// let pts = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// // Inward-facing input is accepted and turned outward.
    /// let tet = Polyhedron::new(pts.clone(), vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]).unwrap();
    /// assert_eq!(tet.faces[0], [0, 2, 1]);
    /// let open = Polyhedron::new(pts, vec![[0, 1, 2], [0, 3, 1], [0, 2, 3]]).unwrap_err();
    /// assert!(open.to_string().contains("at least 4"));
    /// ```
    pub fn new(points: Vec<Point3>, faces: Vec<[u32; 3]>) -> Result<Polyhedron, SurfaceError> {
        check_faces(&points, &faces)?;
        let mut faces = faces;
        orient_consistently(&mut faces, points.len())?;
        check_vertex_disks(&faces, points.len())?;
        check_self_intersection(&points, &faces)?;
        match volume_sign(&points, &faces) {
            1 => {}
            -1 => faces.iter_mut().for_each(|f| f.swap(1, 2)),
            _ => {
                return Err(SurfaceError::new(
                    vec![],
                    vec![],
                    "the surface encloses no volume",
                ));
            }
        }
        Ok(Polyhedron { points, faces })
    }

    /// The edges, each once as `[lo, hi]`, sorted.
    pub fn edges(&self) -> Vec<[u32; 2]> {
        let mut e: Vec<[u32; 2]> = self
            .faces
            .iter()
            .flat_map(|f| [[f[0], f[1]], [f[1], f[2]], [f[2], f[0]]])
            .filter(|e| e[0] < e[1])
            .collect();
        e.sort_unstable();
        e
    }
}

fn check_faces(points: &[Point3], faces: &[[u32; 3]]) -> Result<(), SurfaceError> {
    if faces.len() < 4 {
        return Err(SurfaceError::new(
            vec![],
            vec![],
            format!("{} faces: a polyhedron needs at least 4", faces.len()),
        ));
    }
    let mut used = vec![false; points.len()];
    for (i, f) in faces.iter().enumerate() {
        if f[0] == f[1] || f[1] == f[2] || f[0] == f[2] {
            return Err(SurfaceError::new(vec![i], vec![], "repeats a vertex"));
        }
        let [a, b, c] = f.map(|v| &points[v as usize]);
        if collinear3(a, b, c) {
            return Err(SurfaceError::new(
                vec![i],
                f.to_vec(),
                "is degenerate (collinear vertices)",
            ));
        }
        f.iter().for_each(|&v| used[v as usize] = true);
    }
    if let Some(v) = used.iter().position(|u| !u) {
        return Err(SurfaceError::new(vec![], vec![v as u32], "is on no face"));
    }
    let mut sorted: Vec<([u32; 3], usize)> = faces
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let mut s = *f;
            s.sort_unstable();
            (s, i)
        })
        .collect();
    sorted.sort_unstable();
    if let Some(w) = sorted.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(SurfaceError::new(
            vec![w[0].1, w[1].1],
            vec![],
            "are the same triangle",
        ));
    }
    Ok(())
}

/// Every undirected edge with the faces containing it: `(lo, hi, face)`, sorted.
fn edge_incidences(faces: &[[u32; 3]]) -> Vec<(u32, u32, usize)> {
    let mut inc: Vec<(u32, u32, usize)> = faces
        .iter()
        .enumerate()
        .flat_map(|(i, f)| {
            [(f[0], f[1]), (f[1], f[2]), (f[2], f[0])].map(|(a, b)| (a.min(b), a.max(b), i))
        })
        .collect();
    inc.sort_unstable();
    inc
}

/// Checks that every edge has exactly two faces, flips faces so that the two traverse it
/// in opposite directions, and checks connectivity and genus 0.
fn orient_consistently(faces: &mut [[u32; 3]], n: usize) -> Result<(), SurfaceError> {
    let inc = edge_incidences(faces);
    let mut neighbours: Vec<[usize; 3]> = vec![[usize::MAX; 3]; faces.len()];
    let mut k = 0;
    while k < inc.len() {
        let mut j = k;
        while j < inc.len() && (inc[j].0, inc[j].1) == (inc[k].0, inc[k].1) {
            j += 1;
        }
        let (a, b) = (inc[k].0, inc[k].1);
        let owners: Vec<usize> = inc[k..j].iter().map(|x| x.2).collect();
        if owners.len() == 1 {
            return Err(SurfaceError::new(
                owners,
                vec![a, b],
                "the edge between these vertices has only this face: the surface is not closed",
            ));
        }
        if owners.len() > 2 {
            return Err(SurfaceError::new(
                owners,
                vec![a, b],
                "share the edge between these vertices: the surface is not edge-manifold",
            ));
        }
        for (x, y) in [(owners[0], owners[1]), (owners[1], owners[0])] {
            let slot = edge_slot(&faces[x], a, b);
            neighbours[x][slot] = y;
        }
        k = j;
    }
    let edges = inc.len() / 2;
    let mut flip: Vec<Option<bool>> = vec![None; faces.len()];
    flip[0] = Some(false);
    let mut stack = vec![0usize];
    let mut seen = 1;
    while let Some(f) = stack.pop() {
        let ff = oriented(&faces[f], flip[f] == Some(true));
        for (slot, &g) in neighbours[f].iter().enumerate() {
            let (a, b) = match slot {
                0 => (faces[f][0], faces[f][1]),
                1 => (faces[f][1], faces[f][2]),
                _ => (faces[f][2], faces[f][0]),
            };
            // The direction f (as oriented) traverses a-b; g must traverse it the other way.
            let f_forward = traverses(&ff, a, b);
            let g_forward = traverses(&faces[g], a, b);
            let want = f_forward == g_forward; // flip g iff it goes the same way
            match flip[g] {
                None => {
                    flip[g] = Some(want);
                    seen += 1;
                    stack.push(g);
                }
                Some(w) if w != want => {
                    return Err(SurfaceError::new(
                        vec![f, g],
                        vec![],
                        "cannot be oriented consistently: the surface is not orientable",
                    ));
                }
                _ => {}
            }
        }
    }
    if seen < faces.len() {
        let other = flip.iter().position(|f| f.is_none()).unwrap_or(0);
        return Err(SurfaceError::new(
            vec![0, other],
            vec![],
            "lie on different connected pieces of the surface",
        ));
    }
    for (f, fl) in faces.iter_mut().zip(&flip) {
        if *fl == Some(true) {
            f.swap(1, 2);
        }
    }
    let chi = n as i64 - edges as i64 + faces.len() as i64;
    if chi != 2 {
        return Err(SurfaceError::new(
            vec![],
            vec![],
            format!(
                "Euler characteristic V - E + F = {chi}: the surface has genus {} (a simple polyhedron has genus 0)",
                (2 - chi) / 2
            ),
        ));
    }
    Ok(())
}

fn edge_slot(f: &[u32; 3], a: u32, b: u32) -> usize {
    let has = |x: u32, y: u32| (x == a && y == b) || (x == b && y == a);
    if has(f[0], f[1]) {
        0
    } else if has(f[1], f[2]) {
        1
    } else {
        2
    }
}

fn oriented(f: &[u32; 3], flipped: bool) -> [u32; 3] {
    if flipped { [f[0], f[2], f[1]] } else { *f }
}

fn traverses(f: &[u32; 3], a: u32, b: u32) -> bool {
    (f[0] == a && f[1] == b) || (f[1] == a && f[2] == b) || (f[2] == a && f[0] == b)
}

/// Every vertex's faces form one disk (otherwise two cones touch at the vertex).
/// The star of every vertex, flat: the faces `(v, a, b)` of vertex `v` are the pairs
/// `(a, b)` in `link[start[v]..start[v + 1]]`.
pub(crate) fn vertex_stars(faces: &[[u32; 3]], n: usize) -> (Vec<usize>, Vec<(u32, u32)>) {
    let mut start = vec![0usize; n + 1];
    for f in faces {
        f.iter().for_each(|&v| start[v as usize + 1] += 1);
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut link = vec![(0u32, 0u32); start[n]];
    for f in faces {
        for r in 0..3 {
            let v = f[r] as usize;
            link[fill[v]] = (f[(r + 1) % 3], f[(r + 2) % 3]);
            fill[v] += 1;
        }
    }
    (start, link)
}

fn check_vertex_disks(faces: &[[u32; 3]], n: usize) -> Result<(), SurfaceError> {
    let (start, link) = vertex_stars(faces, n);
    for v in 0..n {
        let star = &link[start[v]..start[v + 1]];
        let mut cur = star[0].1;
        let mut steps = 1;
        while cur != star[0].0 && steps <= star.len() {
            match star.iter().find(|s| s.0 == cur) {
                Some(s) => cur = s.1,
                None => break,
            }
            steps += 1;
        }
        if steps != star.len() {
            return Err(SurfaceError::new(
                vec![],
                vec![v as u32],
                "its faces do not form a single disk (the surface pinches here)",
            ));
        }
    }
    Ok(())
}

/// No two faces meet except in shared vertices and edges (exact, behind a grid filter).
fn check_self_intersection(points: &[Point3], faces: &[[u32; 3]]) -> Result<(), SurfaceError> {
    match super::grid::improper_pairs(points, faces, 1).first() {
        Some(&(i, j)) => Err(SurfaceError::new(
            vec![i, j],
            vec![],
            "intersect other than in a shared vertex or edge: the surface is not simple",
        )),
        None => Ok(()),
    }
}

/// The sign of the enclosed volume (positive for outward-oriented faces): a filtered sum
/// of determinants with an exact fallback.
fn volume_sign(points: &[Point3], faces: &[[u32; 3]]) -> i8 {
    let o = points[faces[0][0] as usize];
    let mut sum = 0.0f64;
    let mut magnitude = 0.0f64;
    for f in faces {
        let [a, b, c] = f.map(|v| points[v as usize]);
        let u = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
        let v = [b[0] - o[0], b[1] - o[1], b[2] - o[2]];
        let w = [c[0] - o[0], c[1] - o[1], c[2] - o[2]];
        let det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]);
        let perm = u[0].abs() * (v[1] * w[2]).abs().max((v[2] * w[1]).abs()) * 2.0
            + u[1].abs() * (v[0] * w[2]).abs().max((v[2] * w[0]).abs()) * 2.0
            + u[2].abs() * (v[0] * w[1]).abs().max((v[1] * w[0]).abs()) * 2.0;
        sum += det;
        magnitude += perm;
    }
    // Each term is within 16 eps * perm of its exact value (differences, products and
    // sums each add a few roundings), and summing F terms adds at most F eps * magnitude.
    let bound = (32.0 + faces.len() as f64) * f64::EPSILON * magnitude;
    if sum.abs() > bound {
        return if sum > 0.0 { 1 } else { -1 };
    }
    faces
        .iter()
        .fold(Expansion::default(), |acc, f| {
            let [a, b, c] = f.map(|v| &points[v as usize]);
            acc.add(&orient3d_value(&o, a, b, c))
        })
        .sign()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> (Vec<Point3>, Vec<[u32; 3]>) {
        let pts: Vec<Point3> = (0..8)
            .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
            .collect();
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let faces = quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        (pts, faces)
    }

    #[test]
    fn a_cube_with_coplanar_facets_is_simple_and_outward() {
        let (pts, faces) = cube();
        let p = Polyhedron::new(pts.clone(), faces.clone()).unwrap();
        assert_eq!(p.faces, faces);
        let inward: Vec<[u32; 3]> = faces.iter().map(|f| [f[0], f[2], f[1]]).collect();
        assert_eq!(Polyhedron::new(pts, inward).unwrap().faces, faces);
    }

    #[test]
    fn mixed_orientations_are_made_consistent() {
        let (pts, mut faces) = cube();
        faces[3].swap(0, 1);
        faces[7].swap(1, 2);
        let p = Polyhedron::new(pts, faces).unwrap();
        assert_eq!(p.faces[3], [7, 6, 4]);
    }

    #[test]
    fn a_dented_face_that_pokes_through_is_rejected() {
        let (mut pts, faces) = cube();
        // Push a corner through the opposite side.
        pts[7] = [0.5, 0.5, -1.0];
        let err = Polyhedron::new(pts, faces).unwrap_err();
        assert!(err.problem.contains("not simple"), "{err}");
    }

    #[test]
    fn two_tetrahedra_are_two_pieces() {
        let mut pts = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        pts.extend(pts.clone().iter().map(|p| [p[0] + 5.0, p[1], p[2]]));
        let t = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let faces: Vec<[u32; 3]> = t
            .iter()
            .chain(t.iter())
            .enumerate()
            .map(|(i, f)| if i < 4 { *f } else { f.map(|v| v + 4) })
            .collect();
        let err = Polyhedron::new(pts, faces).unwrap_err();
        assert!(err.problem.contains("connected"), "{err}");
    }

    #[test]
    fn an_unused_vertex_is_named() {
        let (mut pts, faces) = cube();
        pts.push([9.0, 9.0, 9.0]);
        let err = Polyhedron::new(pts, faces).unwrap_err();
        assert_eq!(err.vertices, vec![8]);
    }

    #[test]
    fn a_non_manifold_edge_is_named() {
        let (pts, mut faces) = cube();
        faces.push([0, 2, 5]);
        let err = Polyhedron::new(pts, faces).unwrap_err();
        assert!(err.problem.contains("edge"), "{err}");
    }
}
