//! Exact incremental tetrahedralization of a point set, for generating instances.
//!
//! Points are inserted in random order into a growing tetrahedralization of their hull:
//! a point inside the current hull splits the tetrahedra whose closure contains it
//! (1-4 inside a tetrahedron, 2-6 on a face, 2k on an edge); a point outside is joined to
//! every hull face it sees strictly (a placing step). Both steps keep a valid
//! tetrahedralization for any point set, degenerate or not. Point location is brute force:
//! this is a generator for test instances, not a mesher.

use crate::geom::{Hull3, Point3, orient3d};
use crate::mesh::Tetrahedralization;
use crate::rng::Rng;
use std::collections::HashMap;

/// A tetrahedralization of `points` (which must not be all coplanar, and must be distinct).
///
/// ```
/// let pts = tetrakit::generate::cospherical_points(9);
/// let t = tetrakit::generate::tetrahedralize_points(pts, 7);
/// assert!(t.verify_convex().is_valid());
/// ```
pub fn tetrahedralize_points(points: Vec<Point3>, seed: u64) -> Tetrahedralization {
    let hull = Hull3::new(&points);
    let mut t = Tetrahedralization {
        points,
        tets: Vec::new(),
    };
    if hull.dimension < 3 {
        return t;
    }
    // Seed with a non-degenerate hull triangle and a point off its plane.
    let f = hull.triangles[0];
    let p = |i: u32| t.points[i as usize];
    let apex = (0..t.points.len() as u32)
        .find(|&x| orient3d(&p(f[0]), &p(f[1]), &p(f[2]), &p(x)) != 0)
        .unwrap();
    let first = [f[0], f[1], f[2], apex];
    t.tets.push(first);
    t.orient_positively();
    let mut order: Vec<u32> = (0..t.points.len() as u32)
        .filter(|x| !first.contains(x))
        .collect();
    Rng::new(seed).shuffle(&mut order);
    for x in order {
        insert(&mut t, x);
    }
    t
}

fn insert(t: &mut Tetrahedralization, x: u32) {
    let px = t.points[x as usize];
    let p = |i: u32| &t.points[i as usize];
    // Faces of the tetrahedra: outward orientation (b,c,d), (a,d,c), (a,b,d), (a,c,b).
    let mut containing: Vec<(usize, Vec<usize>)> = Vec::new(); // tet, faces with x on them
    for (i, tet) in t.tets.iter().enumerate() {
        let [a, b, c, d] = *tet;
        let s = [
            orient3d(p(b), p(c), p(d), &px),
            orient3d(p(a), p(d), p(c), &px),
            orient3d(p(a), p(b), p(d), &px),
            orient3d(p(a), p(c), p(b), &px),
        ];
        if s.iter().all(|&v| v <= 0) {
            containing.push((i, (0..4).filter(|&k| s[k] == 0).collect()));
        }
    }
    if containing.is_empty() {
        place(t, x);
        return;
    }
    // Split every tetrahedron whose closure contains x: replace the vertex opposite each face
    // that does not contain x by x.
    let mut removed: Vec<usize> = containing.iter().map(|c| c.0).collect();
    let mut new = Vec::new();
    for (i, zero) in &containing {
        let tet = t.tets[*i];
        for k in 0..4 {
            if !zero.contains(&k) {
                let mut nt = tet;
                nt[k] = x;
                new.push(nt);
            }
        }
    }
    removed.sort_unstable();
    for &i in removed.iter().rev() {
        t.tets.swap_remove(i);
    }
    t.tets.extend(new);
}

/// Joins an outside point to every boundary face it strictly sees.
fn place(t: &mut Tetrahedralization, x: u32) {
    let mut count: HashMap<[u32; 3], (usize, [u32; 3])> = HashMap::new();
    for tet in &t.tets {
        let [a, b, c, d] = *tet;
        for f in [[b, c, d], [a, d, c], [a, b, d], [a, c, b]] {
            let mut k = f;
            k.sort_unstable();
            count.entry(k).or_insert((0, f)).0 += 1;
        }
    }
    let p = |i: u32| &t.points[i as usize];
    let px = t.points[x as usize];
    let mut new: Vec<[u32; 4]> = count
        .values()
        .filter(|(c, f)| *c == 1 && orient3d(p(f[0]), p(f[1]), p(f[2]), &px) > 0)
        .map(|(_, f)| [f[0], f[1], f[2], x])
        .collect();
    // In a fixed order: the map's is random, and later flips pick tetrahedra by index.
    new.sort_unstable();
    t.tets.extend(new);
}
