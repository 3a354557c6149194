//! The Delaunay triangulation of a planar point set (the `spade` crate, whose predicates
//! are exact), in index form, with a certificate of the Delaunay property.

use super::PlanarError;
use crate::geom::{Point2, incircle, orient2d};
use rayon::prelude::*;
use spade::{DelaunayTriangulation, HasPosition, Triangulation};

/// A vertex carrying its input index through `spade`'s bulk loading.
#[derive(Clone, Copy, Debug)]
struct Site {
    pos: spade::Point2<f64>,
    index: u32,
}

impl HasPosition for Site {
    type Scalar = f64;
    fn position(&self) -> spade::Point2<f64> {
        self.pos
    }
}

/// An edge `pq` of a Delaunay triangulation with the apices of its two triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DelaunayEdge {
    /// First endpoint.
    pub p: u32,
    /// Second endpoint.
    pub q: u32,
    /// Apex of the triangle left of `p → q` (none on the hull).
    pub left: Option<u32>,
    /// Apex of the triangle right of `p → q`.
    pub right: Option<u32>,
    /// Index of the left triangle in [`Delaunay::triangles`].
    pub left_face: Option<u32>,
    /// Index of the right triangle.
    pub right_face: Option<u32>,
}

/// A Delaunay triangulation: counter-clockwise triangles and every edge once.
#[derive(Clone, Debug, Default)]
pub struct Delaunay {
    /// Triangles, counter-clockwise.
    pub triangles: Vec<[u32; 3]>,
    /// Edges with their apices.
    pub edges: Vec<DelaunayEdge>,
}

/// Computes a Delaunay triangulation of distinct points and checks the empty-circle
/// property edge by edge (locally Delaunay everywhere implies Delaunay), exactly.
///
/// ```
/// use tetrakit::planar::delaunay;
/// let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]];
/// let dt = delaunay(&pts).unwrap();
/// assert_eq!((dt.triangles.len(), dt.edges.len()), (2, 5));
/// ```
pub fn delaunay(points: &[Point2]) -> Result<Delaunay, PlanarError> {
    let dt = triangulate(points)?;
    // Triangles are indexed by spade's face index minus one (face 0 is the outer face).
    let faces: Vec<_> = dt.fixed_inner_faces().collect();
    debug_assert!(faces.iter().enumerate().all(|(k, f)| f.index() == k + 1));
    let triangles: Vec<[u32; 3]> = faces
        .par_iter()
        .map(|&f| {
            let face = dt.face(f);
            let v = face.vertices().map(|v| v.data().index);
            let p = |i: usize| &points[v[i] as usize];
            if orient2d(p(0), p(1), p(2)) > 0 {
                v
            } else {
                [v[0], v[2], v[1]]
            }
        })
        .collect();
    let face_of = |f: usize| (f as u32).checked_sub(1);
    let handles: Vec<_> = dt.fixed_undirected_edges().collect();
    let edges: Vec<DelaunayEdge> = handles
        .par_iter()
        .map(|&h| {
            let d = dt.undirected_edge(h).as_directed();
            let apex = |e: spade::handles::DirectedEdgeHandle<'_, Site, (), (), ()>| {
                e.opposite_vertex().map(|v| v.data().index)
            };
            DelaunayEdge {
                p: d.from().data().index,
                q: d.to().data().index,
                left: apex(d),
                right: apex(d.rev()),
                left_face: apex(d).and(face_of(d.face().fix().index())),
                right_face: apex(d.rev()).and(face_of(d.rev().face().fix().index())),
            }
        })
        .collect();
    if let Some(e) = edges
        .par_iter()
        .find_any(|e| !locally_delaunay(points, e.p, e.q, e.left, e.right))
    {
        return Err(not_delaunay(e.p, e.q));
    }
    Ok(Delaunay { triangles, edges })
}

/// spade's triangulation of checked coordinates; coinciding sites are an error naming
/// two of them.
fn triangulate(points: &[Point2]) -> Result<DelaunayTriangulation<Site>, PlanarError> {
    super::check_coordinates(points)?;
    let sites: Vec<Site> = points
        .iter()
        .enumerate()
        .map(|(i, p)| Site {
            pos: spade::Point2::new(p[0], p[1]),
            index: i as u32,
        })
        .collect();
    let dt = DelaunayTriangulation::<Site>::bulk_load(sites).map_err(|_| {
        PlanarError::internal("spade triangulates sites in the supported range", [])
    })?;
    if dt.num_vertices() != points.len() {
        return Err(match super::coincident_sites(points) {
            Some(sites) => PlanarError::CoincidentSites {
                sites,
                point: points[sites[0] as usize],
            },
            None => PlanarError::internal("spade keeps distinct sites apart", []),
        });
    }
    Ok(dt)
}

/// The empty-circle certificate of edge `pq` with apices `l` (left) and `r`.
fn locally_delaunay(points: &[Point2], p: u32, q: u32, l: Option<u32>, r: Option<u32>) -> bool {
    let pt = |i: u32| (i, points[i as usize]);
    let view = EdgeView {
        p: pt(p),
        q: pt(q),
        left: l.map(pt),
        right: r.map(pt),
    };
    view.locally_delaunay()
}

fn not_delaunay(p: u32, q: u32) -> PlanarError {
    PlanarError::internal(
        "the Delaunay triangulation passes the empty-circle test at every edge",
        [p, q],
    )
}

/// A Delaunay edge `pq` with the apices of its triangles (left of `p → q`, right), each
/// site as its index and position.
pub(crate) struct EdgeView {
    pub p: (u32, Point2),
    pub q: (u32, Point2),
    pub left: Option<(u32, Point2)>,
    pub right: Option<(u32, Point2)>,
}

impl EdgeView {
    fn locally_delaunay(&self) -> bool {
        let (Some(l), Some(r)) = (self.left, self.right) else {
            return true;
        };
        let (p, q) = (&self.p.1, &self.q.1);
        orient2d(p, q, &l.1) > 0 && incircle(p, q, &l.1, &r.1) <= 0
    }
}

/// The Delaunay edges `[p, q]` (`p < q`, sorted) for which `keep` holds, each certified
/// as in [`delaunay`], and the number of Delaunay edges: one parallel pass over the
/// triangulation, reading positions from it, without building triangle or edge lists.
pub(crate) fn delaunay_edges_where(
    points: &[Point2],
    keep: impl Fn(&EdgeView) -> bool + Sync,
) -> Result<(Vec<[u32; 2]>, usize), PlanarError> {
    let dt = triangulate(points)?;
    let handles: Vec<_> = dt.fixed_undirected_edges().collect();
    let site = |v: spade::handles::VertexHandle<'_, Site, (), (), ()>| {
        let s = v.data();
        (s.index, [s.pos.x, s.pos.y])
    };
    let kept: Result<Vec<[u32; 2]>, PlanarError> = handles
        .par_iter()
        .filter_map(|&h| {
            let d = dt.undirected_edge(h).as_directed();
            let view = EdgeView {
                p: site(d.from()),
                q: site(d.to()),
                left: d.opposite_vertex().map(site),
                right: d.rev().opposite_vertex().map(site),
            };
            let (p, q) = (view.p.0, view.q.0);
            if !view.locally_delaunay() {
                return Some(Err(not_delaunay(p, q)));
            }
            keep(&view).then_some(Ok([p.min(q), p.max(q)]))
        })
        .collect();
    Ok((sort_by_first(kept?, points.len()), handles.len()))
}

/// Sorts pairs with first entries below `n` by counting sort on the first entry.
fn sort_by_first(pairs: Vec<[u32; 2]>, n: usize) -> Vec<[u32; 2]> {
    let (start, mut out) = crate::rows::buckets(n, pairs.iter().map(|e| (e[0] as usize, *e)));
    for w in start.windows(2) {
        out[w[0] as usize..w[1] as usize].sort_unstable();
    }
    out
}
