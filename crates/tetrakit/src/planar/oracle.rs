//! A brute-force oracle: every triangulation of a small point set.
//!
//! Exponential; for tests of the exact stages against exhaustive search (at most about
//! ten points).

use crate::geom::{Point2, orient2d};
use std::collections::HashSet;

/// Every triangulation of a small point set, as sorted edge lists `[p, q]`, `p < q`
/// (advancing front from a hull edge; collinear hull points are on the hull).
///
/// ```
/// // A square has two triangulations, one per diagonal.
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// assert_eq!(tetrakit::planar::triangulations(&square).len(), 2);
/// ```
pub fn triangulations(points: &[Point2]) -> Vec<Vec<[u32; 2]>> {
    let n = points.len() as u32;
    let hull = crate::geom::Hull2::new(points);
    let p = |i: u32| &points[i as usize];
    // Directed hull edges counter-clockwise, collinear boundary points included.
    let mut hull_dir: HashSet<(u32, u32)> = HashSet::new();
    let h = hull.vertices.len();
    for k in 0..h {
        let (a, b) = (hull.vertices[k], hull.vertices[(k + 1) % h]);
        let mut chain: Vec<u32> = (0..n)
            .filter(|&c| {
                c != a
                    && c != b
                    && hull.on_boundary[c as usize]
                    && orient2d(p(a), p(b), p(c)) == 0
                    && crate::geom::corner_dot_sign(p(a), p(b), p(c)) < 0
            })
            .collect();
        chain.sort_by(|&x, &y| {
            let d = |c: u32| (p(c)[0] - p(a)[0]).abs() + (p(c)[1] - p(a)[1]).abs();
            d(x).total_cmp(&d(y))
        });
        chain.insert(0, a);
        chain.push(b);
        for w in chain.windows(2) {
            hull_dir.insert((w[0], w[1]));
        }
    }
    let empty = |a: u32, b: u32, c: u32| {
        (0..n).all(|r| {
            r == a || r == b || r == c || {
                let (o1, o2, o3) = (
                    orient2d(p(a), p(b), p(r)),
                    orient2d(p(b), p(c), p(r)),
                    orient2d(p(c), p(a), p(r)),
                );
                o1 < 0 || o2 < 0 || o3 < 0
            }
        })
    };
    let crosses = |e: &[u32; 2], f: &[u32; 2]| {
        e[0] != f[0]
            && e[0] != f[1]
            && e[1] != f[0]
            && e[1] != f[1]
            && orient2d(p(e[0]), p(e[1]), p(f[0])) * orient2d(p(e[0]), p(e[1]), p(f[1])) < 0
            && orient2d(p(f[0]), p(f[1]), p(e[0])) * orient2d(p(f[0]), p(f[1]), p(e[1])) < 0
    };
    struct St {
        edges: Vec<[u32; 2]>,
        used: HashSet<(u32, u32)>,
        out: Vec<Vec<[u32; 2]>>,
    }
    fn key(a: u32, b: u32) -> [u32; 2] {
        [a.min(b), a.max(b)]
    }
    fn rec(
        st: &mut St,
        stack: Vec<(u32, u32)>,
        n: u32,
        hull_dir: &HashSet<(u32, u32)>,
        empty: &dyn Fn(u32, u32, u32) -> bool,
        crosses: &dyn Fn(&[u32; 2], &[u32; 2]) -> bool,
        left: &dyn Fn(u32, u32, u32) -> bool,
    ) {
        let mut stack = stack;
        let (a, b) = loop {
            match stack.pop() {
                None => {
                    let mut e = st.edges.clone();
                    e.sort_unstable();
                    e.dedup();
                    st.out.push(e);
                    return;
                }
                Some(x) if st.used.contains(&x) => continue,
                Some(x) => break x,
            }
        };
        for r in 0..n {
            if r == a || r == b || !left(a, b, r) || !empty(a, b, r) {
                continue;
            }
            if st.used.contains(&(b, r)) || st.used.contains(&(r, a)) {
                continue;
            }
            let new: Vec<[u32; 2]> = [key(b, r), key(r, a)]
                .into_iter()
                .filter(|e| !st.edges.contains(e))
                .collect();
            if new.iter().any(|e| st.edges.iter().any(|f| crosses(e, f))) {
                continue;
            }
            let mark = [(a, b), (b, r), (r, a)];
            for m in mark {
                st.used.insert(m);
            }
            let before = st.edges.len();
            st.edges.extend(new);
            let mut next = stack.clone();
            for (x, y) in [(r, b), (a, r)] {
                if !hull_dir.contains(&(y, x)) {
                    next.push((x, y));
                }
            }
            rec(st, next, n, hull_dir, empty, crosses, left);
            st.edges.truncate(before);
            for m in mark {
                st.used.remove(&m);
            }
        }
    }
    let start = *hull_dir.iter().min().unwrap();
    let mut st = St {
        edges: hull_dir.iter().map(|&(a, b)| key(a, b)).collect(),
        used: HashSet::new(),
        out: Vec::new(),
    };
    let left = |a: u32, b: u32, r: u32| orient2d(p(a), p(b), p(r)) > 0;
    rec(&mut st, vec![start], n, &hull_dir, &empty, &crosses, &left);
    st.out
}
