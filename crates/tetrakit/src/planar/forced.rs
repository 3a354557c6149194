//! Edges in every triangulation, and segments with a site inside them.
//!
//! A segment `ab` between two sites is an edge of every triangulation of the sites
//! exactly when no site lies in its open interior and no segment between two sites
//! crosses it: a triangulation is a maximal set of non-crossing site segments, so an
//! uncrossable segment is in all of them; conversely a crossing segment `cd` can be
//! shortened to a site-free one that still crosses `ab`, and that one is an edge of some
//! triangulation. This is the argument of thesis Lemma 5.6, which splits the
//! triangulations of Keil's set along such edges.
//!
//! [`edge_blocker`] decides it in `O(n log n)` with orientation tests only: `cd` (with `c`
//! left of `ab` and `d` right of it) crosses `ab` exactly when `c` and the reflection of
//! `d` come in one angular order around `a` and in the other around `b`, so a crossing
//! pair is an inversion between two sorted orders.

use crate::geom::{Point2, orient2d, strictly_between};
use rayon::prelude::*;
use std::cmp::Ordering;
use std::collections::HashSet;

/// Why a segment `ab` is not in every triangulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Blocker {
    /// A site in the open segment.
    Site(u32),
    /// Two sites whose segment crosses `ab` at an interior point of both.
    Crossing([u32; 2]),
}

/// `None` when the segment between sites `a` and `b` is an edge of every triangulation
/// of `points`; otherwise the witness that it is not. Exact, `O(n log n)`.
pub fn edge_blocker(points: &[Point2], a: u32, b: u32) -> Option<Blocker> {
    let p = |i: u32| &points[i as usize];
    let (pa, pb) = (p(a), p(b));
    // Sites off the line, with the side (+1 left, -1 right) used to reflect right
    // sites through the centre, so that every direction lies left of `ab`.
    let mut items: Vec<(u32, i8)> = Vec::new();
    for s in 0..points.len() as u32 {
        if s == a || s == b {
            continue;
        }
        match orient2d(pa, pb, p(s)) {
            0 if strictly_between(pa, p(s), pb) => return Some(Blocker::Site(s)),
            0 => {}
            o => items.push((s, o)),
        }
    }
    // cross(σs(s - c), σt(t - c)) = σs·σt·orient(c, s, t): `Less` when `s` comes first.
    let order = |c: &Point2, s: (u32, i8), t: (u32, i8)| -> Ordering {
        0.cmp(&(orient2d(c, p(s.0), p(t.0)) * s.1 * t.1))
    };
    items.sort_by(|&s, &t| order(pa, s, t));
    // Sweep in the order around `a`, keeping per side the item last around `b`.
    let mut last: [Option<(u32, i8)>; 2] = [None, None];
    let slot = |side: i8| usize::from(side < 0);
    let mut g = 0;
    while g < items.len() {
        let end = g + items[g..]
            .iter()
            .take_while(|&&t| order(pa, items[g], t) == Ordering::Equal)
            .count();
        for &t in &items[g..end] {
            if let Some(u) = last[slot(-t.1)]
                && order(pb, u, t) == Ordering::Greater
            {
                return Some(Blocker::Crossing([u.0, t.0]));
            }
        }
        for &t in &items[g..end] {
            let k = slot(t.1);
            if last[k].is_none_or(|u| order(pb, u, t) == Ordering::Less) {
                last[k] = Some(t);
            }
        }
        g = end;
    }
    None
}

/// Every pair of sites `[i, j]` (`i < j`) whose open segment holds another site. Exact,
/// `O(n² log n)`: the sites around each site sorted by direction, then by distance.
pub fn blocked_pairs(points: &[Point2]) -> HashSet<[u32; 2]> {
    let n = points.len() as u32;
    let p = |i: u32| &points[i as usize];
    (0..n)
        .into_par_iter()
        .flat_map_iter(|c| {
            let pc = p(c);
            let half = |s: u32| {
                let q = p(s);
                u8::from(!(q[1] > pc[1] || (q[1] == pc[1] && q[0] > pc[0])))
            };
            let direction = |s: u32, t: u32| {
                half(s)
                    .cmp(&half(t))
                    .then_with(|| 0.cmp(&orient2d(pc, p(s), p(t))))
            };
            // Along one ray from `c`, the farther site has the larger coordinate
            // difference on an axis the ray is not orthogonal to.
            let nearer = |s: u32, t: u32| {
                let (qs, qt) = (p(s), p(t));
                let axis = usize::from(qs[0] == pc[0]);
                let ord = qs[axis].total_cmp(&qt[axis]);
                if qs[axis] > pc[axis] {
                    ord
                } else {
                    ord.reverse()
                }
            };
            let mut around: Vec<u32> = (0..n).filter(|&s| s != c).collect();
            around.sort_by(|&s, &t| direction(s, t).then_with(|| nearer(s, t)));
            let mut out = Vec::new();
            for w in around.windows(2) {
                if direction(w[0], w[1]) == Ordering::Equal {
                    out.push([c.min(w[1]), c.max(w[1])]);
                }
            }
            out
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planar::mwt::cross;
    use crate::rng::Rng;

    #[test]
    fn edge_blocker_names_the_witness() {
        let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.0]];
        assert_eq!(edge_blocker(&pts, 0, 3), None); // a hull edge
        assert!(matches!(
            edge_blocker(&pts, 0, 2),
            Some(Blocker::Crossing(_))
        ));
        assert_eq!(edge_blocker(&pts, 0, 1), Some(Blocker::Site(4)));
    }

    #[test]
    fn blocked_pairs_have_a_site_between() {
        let pts = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [2.0, 0.0]];
        assert_eq!(
            blocked_pairs(&pts).into_iter().collect::<Vec<_>>(),
            vec![[0, 2]]
        );
    }

    /// Site `s` lies in the open segment `ab` (brute force: orientation and order).
    fn inside(pts: &[Point2], a: u32, b: u32, s: u32) -> bool {
        let p = |i: u32| &pts[i as usize];
        s != a && s != b && orient2d(p(a), p(b), p(s)) == 0 && strictly_between(p(a), p(s), p(b))
    }

    fn brute_blocker(pts: &[Point2], a: u32, b: u32) -> bool {
        let n = pts.len() as u32;
        let p = |i: u32| &pts[i as usize];
        (0..n).any(|s| inside(pts, a, b, s))
            || (0..n).any(|c| (0..n).any(|d| cross(p(a), p(b), p(c), p(d))))
    }

    /// Against the brute force on grids (many collinear and crossing ties) and random
    /// sets; every witness is checked.
    #[test]
    fn edge_blocker_matches_brute_force() {
        let mut rng = Rng::new(5);
        let mut uncrossable = 0;
        for case in 0..2000 {
            let n = 4 + rng.below(9);
            let side = if case % 2 == 0 { 4 } else { 1000 };
            let mut pts: Vec<Point2> = (0..n)
                .map(|_| [rng.below(side) as f64, rng.below(side) as f64])
                .collect();
            pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
            pts.dedup();
            let m = pts.len() as u32;
            let blocked = blocked_pairs(&pts);
            for a in 0..m {
                for b in a + 1..m {
                    let got = edge_blocker(&pts, a, b);
                    assert_eq!(got.is_some(), brute_blocker(&pts, a, b), "{pts:?} {a} {b}");
                    let p = |i: u32| &pts[i as usize];
                    match got {
                        None => uncrossable += 1,
                        Some(Blocker::Site(s)) => assert!(inside(&pts, a, b, s)),
                        Some(Blocker::Crossing([c, d])) => {
                            assert!(cross(p(a), p(b), p(c), p(d)))
                        }
                    }
                    let on = (0..m).any(|s| inside(&pts, a, b, s));
                    assert_eq!(blocked.contains(&[a, b]), on, "{pts:?} {a} {b}");
                }
            }
        }
        assert!(uncrossable > 3000);
    }
}
