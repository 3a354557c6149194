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
    let sites: Vec<Site> = points
        .iter()
        .enumerate()
        .map(|(i, p)| Site {
            pos: spade::Point2::new(p[0], p[1]),
            index: i as u32,
        })
        .collect();
    let dt = DelaunayTriangulation::<Site>::bulk_load(sites)
        .map_err(|e| PlanarError::new(format!("Delaunay triangulation failed: {e:?}")))?;
    if dt.num_vertices() != points.len() {
        return Err(PlanarError::new("duplicate points"));
    }
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
    let bad = edges.par_iter().find_any(|e| match (e.left, e.right) {
        (Some(l), Some(r)) => {
            let p = |i: u32| &points[i as usize];
            orient2d(p(e.p), p(e.q), p(l)) <= 0 || incircle(p(e.p), p(e.q), p(l), p(r)) > 0
        }
        _ => false,
    });
    if let Some(e) = bad {
        return Err(PlanarError::new(format!(
            "internal: the Delaunay triangulation fails the empty-circle test at edge {}-{}",
            e.p, e.q
        )));
    }
    Ok(Delaunay { triangles, edges })
}
