//! Exact 2D convex hull (Andrew's monotone chain) with boundary membership for every point,
//! collinear and duplicate points included.

use super::predicates::{Point2, orient2d};

/// Lexicographic order of points, by `x` then `y`, with `-0.0` equal to `0.0` (as
/// [`super::lex_cmp`]).
fn lex(a: &Point2, b: &Point2) -> std::cmp::Ordering {
    let key = |x: f64| x + 0.0;
    key(a[0])
        .total_cmp(&key(b[0]))
        .then(key(a[1]).total_cmp(&key(b[1])))
}

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
        idx.sort_by(|&a, &b| lex(p(a), p(b)));
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
        let h = self.vertices.len();
        let mut is_vertex = vec![false; points.len()];
        for &v in &self.vertices {
            is_vertex[v as usize] = true;
        }
        let mut chains: Vec<Vec<u32>> = vec![Vec::new(); h];
        let at = |k: usize| &points[self.vertices[k] as usize];
        let top = (0..h).max_by(|&a, &b| lex(at(a), at(b))).unwrap_or(0);
        for c in (0..points.len() as u32).filter(|&c| self.on_boundary[c as usize]) {
            if is_vertex[c as usize] {
                continue;
            }
            match self.edge_holding(points, top, &points[c as usize]) {
                Some(k) => chains[k].push(c),
                // Few vertices, or a copy of a vertex: every edge whose line holds it.
                None => {
                    for (k, chain) in chains.iter_mut().enumerate() {
                        let (a, b) = (self.vertices[k], self.vertices[(k + 1) % h]);
                        if orient2d(
                            &points[a as usize],
                            &points[b as usize],
                            &points[c as usize],
                        ) == 0
                        {
                            chain.push(c);
                        }
                    }
                }
            }
        }
        // Collinear points: lexicographic order is monotone along the line.
        for (k, chain) in chains.iter_mut().enumerate() {
            chain.sort_by(|&x, &y| lex(&points[x as usize], &points[y as usize]));
            if lex(at(k), at((k + 1) % h)).is_gt() {
                chain.reverse();
            }
            chain.insert(0, self.vertices[k]);
            chain.push(self.vertices[(k + 1) % h]);
        }
        chains
    }

    /// The hull edge `k` (`vertices[k] → vertices[k+1]`) whose relative interior holds
    /// `x` (`None` if none does, or with fewer than three vertices); `top` is the index
    /// of the lexicographically largest vertex.
    ///
    /// `vertices` runs along the lower chain (abscissa non-decreasing) to the
    /// lexicographically largest vertex, then back along the upper chain; a binary
    /// search on each proposes the edge spanning `x`'s abscissa, the two vertical sides
    /// are the other candidates, and the exact test decides.
    fn edge_holding(&self, points: &[Point2], top: usize, x: &Point2) -> Option<usize> {
        let h = self.vertices.len();
        if h < 3 {
            return None;
        }
        let v = |k: usize| &points[self.vertices[k % h] as usize];
        let holds = |k: usize| {
            let (a, b) = (v(k), v(k + 1));
            let (s, t) = (lex(a, x), lex(x, b));
            orient2d(a, b, x) == 0 && s.is_ne() && s == t
        };
        // The first index in `lo..hi` where `pred` fails (it holds on a prefix).
        let split = |mut lo: usize, mut hi: usize, pred: &dyn Fn(usize) -> bool| {
            while lo < hi {
                let mid = lo + (hi - lo) / 2;
                if pred(mid) { lo = mid + 1 } else { hi = mid }
            }
            lo
        };
        let lower = split(0, top + 1, &|k| v(k)[0] <= x[0]);
        let upper = split(top, h + 1, &|k| v(k)[0] >= x[0]);
        let candidates = [
            lower.saturating_sub(1),
            upper.saturating_sub(1).min(h - 1),
            top.saturating_sub(1),
            h - 1,
        ];
        candidates.into_iter().find(|&k| holds(k))
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
    /// point inside, every vertex a strict left turn. Zeros are -0 or 0 at random (equal
    /// numbers that `total_cmp` alone tells apart).
    #[test]
    fn boundary_matches_the_edge_lines() {
        let mut rng = crate::rng::Rng::new(5);
        for round in 0..3000 {
            let side = 2 + round % 6;
            let len = 1 + rng.below(12);
            let mut coordinate = || match rng.below(side) as f64 - (side / 2) as f64 {
                0.0 if rng.below(2) == 0 => -0.0,
                x => x,
            };
            let pts: Vec<Point2> = (0..len).map(|_| [coordinate(), coordinate()]).collect();
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
            // Each chain: the points on its edge's line (copies of the ends included),
            // ordered from one end to the other.
            let chains = h.boundary_chains(&pts);
            for j in 0..k {
                let (a, b) = edge(j);
                let d = |x: &Point2| (x[0] - a[0]).abs() + (x[1] - a[1]).abs();
                let mut want: Vec<u32> = (0..pts.len() as u32)
                    .filter(|&c| !h.vertices.contains(&c))
                    .filter(|&c| orient2d(a, b, &pts[c as usize]) == 0)
                    .collect();
                want.sort_by(|&x, &y| d(&pts[x as usize]).total_cmp(&d(&pts[y as usize])));
                let got = &chains[j][1..chains[j].len() - 1];
                let at = |v: &[u32]| v.iter().map(|&c| pts[c as usize]).collect::<Vec<_>>();
                assert_eq!(at(got), at(&want), "{pts:?} edge {j}");
            }
        }
    }
}
