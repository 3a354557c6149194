//! The check of a partitioned mesh, part by part: the verdict and the problems of
//! [`check`](super::check) on the merged mesh, computed from [`Part`]s that each hold some
//! of the tetrahedra in their own numbering, so that the work (and, under MPI, the
//! memory) is per part.
//!
//! **Ownership.** Every vertex is *owned* by one part that holds every tetrahedron around
//! it: a vertex that only one piece's tetrahedra use is owned by that piece; a vertex on
//! an interface (used by two pieces or more) is owned by a *layer*, a part holding every
//! tetrahedron around the interface vertices it owns, whatever their piece. A face or an
//! edge is decided by the owner of its vertex with the smallest number in the whole mesh.
//! That owner sees every tetrahedron having the face (each has that vertex), so its
//! pairing of the face is the merged mesh's; it sees every boundary face through the edge,
//! so its count of the edge's two directions is the merged mesh's; it sees the whole star
//! of each vertex it owns, so its cone tests there are the merged mesh's. Each tetrahedron
//! is reported (orientation) by its piece's part alone. What is global and small is done
//! once, on the gathered results: the boundary faces (self-intersection, the components
//! and the nesting test, the hull), the coincident vertices.
//!
//! Problems are put in the merged check's order (tetrahedra, faces, edges, vertices, each
//! by number), so the kept problems, their count and the witness are the merged mesh's.

use super::embed;
use super::report::{Problem, Report};
use super::verify::{
    BoundaryFace, check_closed, check_hull, check_tets, coincident_vertices, pair_faces,
};
use super::{CheckOptions, CheckOutcome, check, reorient};
use crate::geom::{Hull3, Point3};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// A part of a mesh, checked on its own: points and tetrahedra in the part's own
/// numbering, each with its number in the whole mesh.
#[derive(Clone, Debug, Default)]
pub struct Part {
    /// The part's points.
    pub points: Vec<Point3>,
    /// The part's tetrahedra, over `points`, in the whole mesh's order.
    pub tets: Vec<[u32; 4]>,
    /// Each point's number in the whole mesh, ascending.
    pub vertex_labels: Vec<u32>,
    /// Each tetrahedron's number in the whole mesh, ascending.
    pub tet_labels: Vec<u32>,
    /// The points this part decides for (see the module docs): every tetrahedron around
    /// each of them is in the part.
    pub owned: Vec<bool>,
    /// Whether the part reports its tetrahedra's own problems (each tetrahedron is
    /// reported by one part).
    pub reports_tets: bool,
}

/// What a part decides about faces and edges, in the whole mesh's numbering.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct PartFaces {
    /// Index, repeated-vertex and orientation problems of the part's tetrahedra.
    pub tet_problems: Vec<Problem>,
    /// Faces shared wrongly (same side, three tetrahedra or more).
    pub face_problems: Vec<Problem>,
    /// Boundary edges used unequally in the two directions.
    pub open_edges: Vec<Problem>,
    /// Non-manifold boundary edges.
    pub non_manifold: Vec<Problem>,
    /// The boundary faces the part decides, outward, as `(vertices, tetrahedron)`.
    pub boundary: Vec<([u32; 3], u32)>,
    /// The places of the vertices of `boundary`, as `(vertex, place)`.
    pub places: Vec<(u32, Point3)>,
    /// For each of the part's points, whether it is on a boundary face (right for the
    /// points the part owns), for [`Part::vertex_overlaps`].
    #[serde(skip)]
    pub on_boundary: Vec<bool>,
}

impl Part {
    /// Whether the part decides for the vertices `local` (the owner of the one with the
    /// smallest number in the whole mesh).
    fn decides(&self, local: &[u32]) -> bool {
        let first = local
            .iter()
            .min_by_key(|&&v| self.vertex_labels[v as usize]);
        first.is_some_and(|&v| self.owned[v as usize])
    }

    fn relabeled(&self, mut p: Problem) -> Problem {
        p.relabel(&|v| self.vertex_labels[v as usize], &|t| {
            self.tet_labels[t as usize]
        });
        p
    }

    fn relabeled_all(&self, problems: Vec<Problem>) -> Vec<Problem> {
        problems.into_iter().map(|p| self.relabeled(p)).collect()
    }

    /// Conditions 1–3 of [`verify`](super::verify) for what the part decides.
    pub fn faces(&self) -> PartFaces {
        let (tet_problems, signs) = check_tets(&self.points, &self.tets);
        // Faces without a vertex of the part's are another part's to decide.
        let owned = Some(&self.owned[..]);
        let (boundary, pairing) = pair_faces(self.points.len(), &self.tets, &signs, owned);
        let face_problems = pairing
            .into_iter()
            .filter(|p| self.decides(&p.vertices))
            .collect();
        let near: Vec<BoundaryFace> = (boundary.iter())
            .filter(|f| f.v.iter().any(|&x| self.owned[x as usize]))
            .copied()
            .collect();
        let (open, non_manifold) = check_closed(&near);
        let mut on_boundary = vec![false; self.points.len()];
        near.iter()
            .for_each(|f| f.v.iter().for_each(|&x| on_boundary[x as usize] = true));
        let decided = |ps: Vec<Problem>| -> Vec<Problem> {
            let mine = ps.into_iter().filter(|p| self.decides(&p.vertices));
            self.relabeled_all(mine.collect())
        };
        let label = |f: &BoundaryFace| {
            let v = f.v.map(|x| self.vertex_labels[x as usize]);
            (v, self.tet_labels[f.tet as usize])
        };
        let mine: Vec<&BoundaryFace> = boundary.iter().filter(|f| self.decides(&f.v)).collect();
        let mut places: Vec<(u32, Point3)> = (mine.iter())
            .flat_map(|f| f.v)
            .map(|x| (self.vertex_labels[x as usize], self.points[x as usize]))
            .collect();
        places.sort_unstable_by_key(|p| p.0);
        places.dedup_by_key(|p| p.0);
        PartFaces {
            places,
            tet_problems: match self.reports_tets {
                true => self.relabeled_all(tet_problems),
                false => Vec::new(),
            },
            face_problems: self.relabeled_all(face_problems),
            open_edges: decided(open),
            non_manifold: decided(non_manifold),
            boundary: mine.into_iter().map(label).collect(),
            on_boundary,
        }
    }

    /// The overlaps near the vertices the part owns (positively oriented tetrahedra;
    /// `on_boundary` from this part's [`faces`](Self::faces)).
    pub fn vertex_overlaps(&self, on_boundary: &[bool]) -> Vec<Problem> {
        let owned = |v: usize| self.owned[v];
        let found = embed::vertex_overlaps(&self.points, &self.tets, on_boundary, &owned);
        self.relabeled_all(found)
    }

    /// For each query `(x, v)` (`v` a vertex number in the whole mesh), the smallest
    /// number of a tetrahedron of the part without the corner `v` whose closure holds
    /// `x`, with its corners (whole-mesh numbers).
    pub fn containing(&self, queries: &[(Point3, u32)]) -> Vec<Option<(u32, [u32; 4])>> {
        let local: Vec<(Point3, u32)> = queries
            .iter()
            .map(|&(x, v)| {
                let k = self
                    .vertex_labels
                    .binary_search(&v)
                    .map_or(u32::MAX, |k| k as u32);
                (x, k)
            })
            .collect();
        embed::containing_tets(&self.points, &self.tets, &local)
            .into_iter()
            .map(|t| {
                t.map(|t| {
                    let corners = self.tets[t as usize].map(|v| self.vertex_labels[v as usize]);
                    (self.tet_labels[t as usize], corners)
                })
            })
            .collect()
    }
}

impl Part {
    /// The part of the tetrahedra `tets` over `points`, numbered `tet_labels` in the
    /// whole mesh (ascending): point `k` is vertex `label(k)` of the whole mesh (points
    /// with one label are one vertex), and the part owns the vertices whose points
    /// `owned` picks.
    pub fn new(
        points: &[Point3],
        label: impl Fn(u32) -> u32 + Sync,
        tets: &[[u32; 4]],
        tet_labels: Vec<u32>,
        owned: impl Fn(u32) -> bool,
        reports_tets: bool,
    ) -> Part {
        let (used, lookup) = used_vertices(tets, &label);
        let local = |k: u32| lookup.local(label(k));
        Part {
            points: used.iter().map(|u| points[u.1 as usize]).collect(),
            tets: tets.par_iter().map(|t| t.map(local)).collect(),
            owned: used.iter().map(|u| owned(u.1)).collect(),
            vertex_labels: used.iter().map(|u| u.0).collect(),
            tet_labels,
            reports_tets,
        }
    }
}

/// From a vertex label to its place in a part: a table when the labels are dense
/// enough, else a search among the sorted labels.
enum Lookup {
    Table(Vec<u32>),
    Sorted(Vec<u32>),
}

impl Lookup {
    fn local(&self, label: u32) -> u32 {
        match self {
            Lookup::Table(t) => t[label as usize],
            Lookup::Sorted(s) => s.binary_search(&label).unwrap_or(0) as u32,
        }
    }
}

/// The vertices of `tets` as `(label, first point with it)`, by label, and the lookup
/// of their places: one pass over a table of the labels when they are dense enough
/// (a part of a mesh in one process), else a sort (a rank's layer).
fn used_vertices(
    tets: &[[u32; 4]],
    label: &(impl Fn(u32) -> u32 + Sync),
) -> (Vec<(u32, u32)>, Lookup) {
    let top = (tets.iter().flatten().map(|&k| label(k)).max()).map_or(0, |m| m as usize + 1);
    if top > 16 * tets.len() + 1024 {
        let mut used: Vec<(u32, u32)> = tets.iter().flatten().map(|&k| (label(k), k)).collect();
        used.par_sort_unstable();
        used.dedup_by_key(|u| u.0);
        let sorted = used.iter().map(|u| u.0).collect();
        return (used, Lookup::Sorted(sorted));
    }
    let mut table = vec![u32::MAX; top];
    for &k in tets.iter().flatten().rev() {
        table[label(k) as usize] = k;
    }
    let mut used = Vec::new();
    for (l, slot) in table.iter_mut().enumerate() {
        if *slot != u32::MAX {
            used.push((l as u32, *slot));
            *slot = (used.len() - 1) as u32;
        }
    }
    (used, Lookup::Table(table))
}

/// A part holding the tetrahedra `which` (ascending) of `tets` over `points`, owning the
/// vertices `owned` picks.
fn part_of(
    points: &[Point3],
    tets: &[[u32; 4]],
    which: &[u32],
    owned: impl Fn(u32) -> bool,
    reports_tets: bool,
) -> Part {
    let mine: Vec<[u32; 4]> = which.iter().map(|&t| tets[t as usize]).collect();
    Part::new(points, |v| v, &mine, which.to_vec(), owned, reports_tets)
}

/// The parts of a mesh in pieces (piece `p` holds the tetrahedra from `first_tet[p]` to
/// the next piece's first): one part per piece, owning the vertices only its tetrahedra
/// use, and one layer per piece, owning the interface vertices whose first piece it is.
pub fn parts(points: &[Point3], tets: &[[u32; 4]], first_tet: &[u32]) -> Vec<Part> {
    let k = first_tet.len();
    let range = |p: usize| {
        let end = first_tet.get(p + 1).map_or(tets.len(), |&e| e as usize);
        first_tet[p]..end as u32
    };
    let (mut first, mut shared) = (vec![u32::MAX; points.len()], vec![false; points.len()]);
    for p in 0..k {
        for t in range(p) {
            for v in tets[t as usize] {
                let f = &mut first[v as usize];
                if *f == u32::MAX {
                    *f = p as u32;
                } else if *f != p as u32 {
                    shared[v as usize] = true;
                }
            }
        }
    }
    let mut layers: Vec<Vec<u32>> = vec![Vec::new(); k];
    for (t, tet) in tets.iter().enumerate() {
        let mut owners: Vec<u32> = (tet.iter())
            .filter(|&&v| shared[v as usize])
            .map(|&v| first[v as usize])
            .collect();
        owners.sort_unstable();
        owners.dedup();
        owners
            .iter()
            .for_each(|&r| layers[r as usize].push(t as u32));
    }
    let pieces = (0..k).into_par_iter().map(|p| {
        let which: Vec<u32> = range(p).collect();
        part_of(points, tets, &which, |v| !shared[v as usize], true)
    });
    let layers = layers.into_par_iter().enumerate().map(|(r, which)| {
        let owned = |v: u32| shared[v as usize] && first[v as usize] == r as u32;
        part_of(points, tets, &which, owned, false)
    });
    let mut all: Vec<Part> = pieces.collect();
    all.extend(layers.collect::<Vec<Part>>());
    all
}

/// The faces' results of every part in the merged check's order: the report of
/// conditions 1–3 and the boundary faces, outward, sorted as the merged check lists them.
pub(crate) fn assemble_faces(found: Vec<PartFaces>) -> (Report, Vec<BoundaryFace>) {
    let (mut tet, mut face, mut open, mut nm, mut boundary) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for f in found {
        tet.extend(f.tet_problems);
        face.extend(f.face_problems);
        open.extend(f.open_edges);
        nm.extend(f.non_manifold);
        boundary.extend(f.boundary);
    }
    tet.sort_by_key(|p| p.cells[0]);
    face.sort_by(|a, b| a.vertices.cmp(&b.vertices));
    open.sort_by_key(|p| (p.vertices[0], p.vertices[1]));
    nm.sort_by_key(|p| (p.vertices[0], p.vertices[1]));
    boundary.par_sort_unstable_by_key(|(v, _)| {
        let mut s = *v;
        s.sort_unstable();
        s
    });
    let mut report = Report::default();
    for p in tet.into_iter().chain(face).chain(open) {
        report.push(p);
    }
    report.boundary_faces = boundary.len();
    report.non_manifold = nm;
    let boundary = boundary
        .into_iter()
        .map(|(v, tet)| BoundaryFace { v, tet })
        .collect();
    (report, boundary)
}

/// Checks a mesh in pieces (piece `p` holds the tetrahedra from `first_tet[p]` on) part
/// by part, in parallel: the outcome of [`check`] on the same arrays (see the module
/// docs), problems, their order and the witness included.
///
/// ```
/// use tetrakit::mesh::{CheckOptions, check, check_pieces};
/// let t = tetrakit::generate::kuhn(2);
/// let half = (t.tets.len() / 2) as u32;
/// let whole = check(&t.points, t.tets.clone(), CheckOptions::default());
/// let pieces = check_pieces(&t.points, t.tets, &[0, half], CheckOptions::default());
/// assert!(pieces.is_valid());
/// assert_eq!(pieces.boundary_faces, whole.boundary_faces);
/// ```
pub fn check_pieces(
    points: &[Point3],
    mut tets: Vec<[u32; 4]>,
    first_tet: &[u32],
    opts: CheckOptions,
) -> CheckOutcome {
    let n = points.len() as u32;
    let bad_index = tets.iter().flatten().any(|&v| v >= n);
    if first_tet.len() < 2 || bad_index {
        return check(points, tets, opts);
    }
    let reoriented = opts.reorient.then(|| reorient(points, &mut tets));
    let parts = parts(points, &tets, first_tet);
    let mut faces: Vec<PartFaces> = parts.par_iter().map(Part::faces).collect();
    let on_boundary: Vec<Vec<bool>> = (faces.iter_mut())
        .map(|f| std::mem::take(&mut f.on_boundary))
        .collect();
    let (mut report, boundary) = assemble_faces(faces);
    for p in coincident_vertices(points, &tets) {
        report.push(p);
    }
    if opts.convex {
        let hull = Hull3::new(points);
        for p in check_hull(points, &tets, &boundary, &hull) {
            report.push(p);
        }
    } else if report.is_valid() {
        let faces: Vec<([u32; 3], u32)> = boundary.iter().map(|f| (f.v, f.tet)).collect();
        embedding(points, &parts, &on_boundary, &faces, &mut report);
    }
    if opts.manifold {
        report = report.require_manifold();
    }
    super::check::outcome(report, tets, points.len(), opts, reoriented)
}

/// The embedding checks of a valid-so-far mesh: cone tests in every part, the boundary's
/// self-intersections and nested components on the gathered boundary.
fn embedding(
    points: &[Point3],
    parts: &[Part],
    on_boundary: &[Vec<bool>],
    faces: &[([u32; 3], u32)],
    report: &mut Report,
) {
    let mut overlaps: Vec<Problem> = (parts.par_iter().zip(on_boundary))
        .flat_map_iter(|(part, on)| part.vertex_overlaps(on))
        .collect();
    overlaps.sort_by_key(|p| p.vertices[0]);
    for p in overlaps {
        report.push(p);
    }
    for p in embed::boundary_self_intersections(points, faces) {
        report.push(p);
    }
    let reps = embed::boundary_components(faces);
    if reps.len() < 2 {
        return;
    }
    let queries: Vec<(Point3, u32)> = reps.iter().map(|&(v, _)| (points[v as usize], v)).collect();
    let mut first: Vec<Option<(u32, [u32; 4])>> = vec![None; reps.len()];
    for part in parts.iter().filter(|p| p.reports_tets) {
        first_hits(&mut first, part.containing(&queries));
    }
    for (&(v, own), hit) in reps.iter().zip(first) {
        if let Some((t, corners)) = hit {
            report.push(embed::nested_problem(v, own, t, &corners));
        }
    }
}

/// Keeps, per query of [`Part::containing`], the hit with the smallest tetrahedron.
pub(crate) fn first_hits(
    best: &mut [Option<(u32, [u32; 4])>],
    found: Vec<Option<(u32, [u32; 4])>>,
) {
    for (b, hit) in best.iter_mut().zip(found) {
        if hit.is_some_and(|h| b.is_none_or(|g| h.0 < g.0)) {
            *b = hit;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two unit cubes' Kuhn meshes side by side, one of them shifted into the other: the
    /// overlap crosses the pieces and both checks name it alike.
    #[test]
    fn an_overlap_across_pieces_is_found_as_in_the_merged_mesh() {
        let a = crate::generate::kuhn(2);
        let mut points = a.points.clone();
        let shift = points.len() as u32;
        points.extend(a.points.iter().map(|p| [p[0] + 0.5, p[1], p[2]]));
        let mut tets = a.tets.clone();
        tets.extend(a.tets.iter().map(|t| t.map(|v| v + shift)));
        let first = [0, a.tets.len() as u32];
        let whole = check(&points, tets.clone(), CheckOptions::default());
        let pieces = check_pieces(&points, tets, &first, CheckOptions::default());
        assert!(!whole.is_valid());
        assert_eq!(pieces.problems, whole.problems);
        assert_eq!(pieces.problem_count, whole.problem_count);
    }
}
