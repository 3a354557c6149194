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
    pub fn new(points: &[Point2]) -> Hull2 {
        let mut idx: Vec<u32> = (0..points.len() as u32).collect();
        let p = |i: u32| &points[i as usize];
        idx.sort_by(|&a, &b| {
            p(a)[0]
                .total_cmp(&p(b)[0])
                .then(p(a)[1].total_cmp(&p(b)[1]))
        });
        idx.dedup_by(|a, b| p(*a) == p(*b));
        let mut hull: Vec<u32> = Vec::new();
        for pass in 0..2 {
            let start = hull.len();
            let seq: Box<dyn Iterator<Item = &u32>> = if pass == 0 {
                Box::new(idx.iter())
            } else {
                Box::new(idx.iter().rev())
            };
            for &i in seq {
                while hull.len() >= start + 2
                    && orient2d(p(hull[hull.len() - 2]), p(hull[hull.len() - 1]), p(i)) <= 0
                {
                    hull.pop();
                }
                hull.push(i);
            }
            hull.pop();
        }
        if idx.len() == 1 {
            hull = idx.clone();
        }
        let on_boundary = points
            .iter()
            .map(|x| {
                let k = hull.len();
                if k < 3 {
                    return true;
                }
                (0..k).any(|i| {
                    let (a, b) = (p(hull[i]), p(hull[(i + 1) % k]));
                    orient2d(a, b, x) == 0
                })
            })
            .collect();
        Hull2 {
            vertices: hull,
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
}
