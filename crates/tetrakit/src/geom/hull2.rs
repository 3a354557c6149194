//! Exact 2D convex hull (Andrew's monotone chain) with boundary membership for every point,
//! collinear and duplicate points included.

use super::predicates::{Point2, orient2d};

/// The convex hull of a planar point set.
///
/// ```
/// use tetrakit::geom::Hull2;
/// let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.0], [1.0, 1.0]];
/// let h = Hull2::new(&pts);
/// assert_eq!(h.vertices.len(), 4);
/// assert!(h.on_boundary[4] && !h.on_boundary[5]);
/// ```
#[derive(Clone, Debug)]
pub struct Hull2 {
    /// Extreme points in counter-clockwise order (collinear boundary points excluded).
    pub vertices: Vec<u32>,
    /// For each input point, whether it lies on the boundary of the hull.
    pub on_boundary: Vec<bool>,
}

impl Hull2 {
    /// Computes the hull of `points` exactly.
    ///
    /// `O(n log n)`: a point is on the boundary exactly when it is on a vertical side or
    /// on the line of the lower or upper chain edge below or above it, found by binary
    /// search.
    pub fn new(points: &[Point2]) -> Hull2 {
        let mut idx: Vec<u32> = (0..points.len() as u32).collect();
        let p = |i: u32| &points[i as usize];
        idx.sort_by(|&a, &b| {
            p(a)[0]
                .total_cmp(&p(b)[0])
                .then(p(a)[1].total_cmp(&p(b)[1]))
        });
        idx.dedup_by(|a, b| p(*a) == p(*b));
        // Counter-clockwise monotone chains, collinear points dropped: the lower from the
        // first point to the last, the upper back.
        let chain = |seq: &mut dyn Iterator<Item = u32>| {
            let mut c: Vec<u32> = Vec::new();
            for i in seq {
                while c.len() >= 2 && orient2d(p(c[c.len() - 2]), p(c[c.len() - 1]), p(i)) <= 0 {
                    c.pop();
                }
                c.push(i);
            }
            c
        };
        let lower = chain(&mut idx.iter().copied());
        let mut upper = chain(&mut idx.iter().rev().copied());
        let mut vertices: Vec<u32> = lower[..lower.len().saturating_sub(1)].to_vec();
        vertices.extend_from_slice(&upper[..upper.len().saturating_sub(1)]);
        if idx.len() == 1 {
            vertices = idx.clone();
        }
        upper.reverse();
        let on_boundary = if vertices.len() < 3 {
            vec![true; points.len()]
        } else {
            let (lo, hi) = (p(idx[0])[0], p(idx[idx.len() - 1])[0]);
            // On the line of the chain edge spanning x's abscissa (lo < x < hi).
            let on_chain = |c: &[u32], x: &Point2| {
                let k = c
                    .partition_point(|&v| p(v)[0] <= x[0])
                    .clamp(1, c.len() - 1);
                orient2d(p(c[k - 1]), p(c[k]), x) == 0
            };
            let vertical_side = |x: &Point2| x[0] == lo || x[0] == hi;
            (points.iter())
                .map(|x| vertical_side(x) || on_chain(&lower, x) || on_chain(&upper, x))
                .collect()
        };
        Hull2 {
            vertices,
            on_boundary,
        }
    }
}

impl Hull2 {
    /// For each hull edge `vertices[i] → vertices[i+1]`, the boundary points along it in
    /// order, both ends included (collinear boundary points are the ones `vertices`
    /// leaves out). Exact: membership by orientation, order by coordinates along the line.
    ///
    /// ```
    /// use tetrakit::geom::Hull2;
    /// let pts = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [1.0, 0.0]];
    /// let h = Hull2::new(&pts);
    /// assert!(h.boundary_chains(&pts).contains(&vec![0, 3, 1]));
    /// ```
    pub fn boundary_chains(&self, points: &[Point2]) -> Vec<Vec<u32>> {
        let mut is_vertex = vec![false; points.len()];
        for &v in &self.vertices {
            is_vertex[v as usize] = true;
        }
        let extra: Vec<u32> = (0..points.len() as u32)
            .filter(|&i| self.on_boundary[i as usize] && !is_vertex[i as usize])
            .collect();
        let h = self.vertices.len();
        (0..h)
            .map(|k| {
                let (a, b) = (self.vertices[k], self.vertices[(k + 1) % h]);
                let (pa, pb) = (&points[a as usize], &points[b as usize]);
                let mut chain: Vec<u32> = extra
                    .iter()
                    .copied()
                    .filter(|&c| orient2d(pa, pb, &points[c as usize]) == 0)
                    .collect();
                // Collinear points: lexicographic order is monotone along the line.
                let lex = |x: &u32, y: &u32| {
                    let (px, py) = (&points[*x as usize], &points[*y as usize]);
                    px[0].total_cmp(&py[0]).then(px[1].total_cmp(&py[1]))
                };
                chain.sort_by(lex);
                if lex(&a, &b).is_gt() {
                    chain.reverse();
                }
                chain.insert(0, a);
                chain.push(b);
                chain
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn collinear_and_duplicate_points() {
        let pts = [
            [0.0, 0.0],
            [1.0, 1.0],
            [2.0, 2.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [0.5, 1.5],
        ];
        let h = Hull2::new(&pts);
        assert_eq!(h.vertices.len(), 3, "{:?}", h.vertices);
        assert_eq!(h.on_boundary, [true, true, true, true, true, false]);
        let h = Hull2::new(&[[0.0, 0.0], [1.0, 0.0], [3.0, 0.0]]);
        assert_eq!(h.vertices.len(), 2);
    }

    /// Boundary membership against its definition (on the line of a hull edge, which
    /// is a supporting line), on grids full of collinear and duplicate points; every
    /// point inside, every vertex a strict left turn.
    #[test]
    fn boundary_matches_the_edge_lines() {
        let mut rng = crate::rng::Rng::new(5);
        for round in 0..3000 {
            let side = 2 + round % 6;
            let pts: Vec<Point2> = (0..1 + rng.below(12))
                .map(|_| [rng.below(side) as f64, rng.below(side) as f64])
                .collect();
            let h = Hull2::new(&pts);
            let k = h.vertices.len();
            let edge = |j: usize| {
                let (a, b) = (h.vertices[j], h.vertices[(j + 1) % k]);
                (&pts[a as usize], &pts[b as usize])
            };
            for (i, x) in pts.iter().enumerate() {
                let on_line = (0..k).any(|j| orient2d(edge(j).0, edge(j).1, x) == 0);
                assert_eq!(h.on_boundary[i], k < 3 || on_line, "{pts:?} point {i}");
                let inside = (0..k).all(|j| orient2d(edge(j).0, edge(j).1, x) >= 0);
                assert!(k < 3 || inside, "{pts:?} point {i}");
            }
            for j in (0..k).filter(|_| k >= 3) {
                let c = &pts[h.vertices[(j + 2) % k] as usize];
                assert_eq!(orient2d(edge(j).0, edge(j).1, c), 1, "{pts:?}");
            }
        }
    }
}
