//! What a vertex sees past `Q` (the thesis's visibility, §4.3), with each test of a
//! segment or triangle between vertices made once.
//!
//! [`Blocker::misses`] decides `conv(s) ∩ Q = ∅` from four kinds of test: a vertex of
//! `s` in `Q`, a segment between two points of `s` through `Q`'s boundary, a vertex of
//! `Q` in `conv(s)`, and an edge of `Q` through a triangle of three points of `s`. The
//! cone from a tip `v` over a surface triangle `abc` shares its segments and triangles
//! with the cones over the triangles around it, and its base `abc` and the base's edges
//! with every tip's cone over `abc`; so the segments and triangles are tested by vertex
//! indices and remembered (each memory is cleared when it passes [`REMEMBERED`] entries,
//! so it stays bounded).

use crate::geom::Point3;
use crate::shell::blocker::Blocker;
use rustc_hash::FxHashMap as HashMap;
use std::cell::RefCell;
use std::hash::Hash;

/// The most answers each of [`Sight`]'s memories keeps before it starts again.
const REMEMBERED: usize = 1 << 20;

/// Visibility past a fixed `Q` between vertices of a fixed point set.
pub(in crate::shell::removal) struct Sight {
    q: Blocker,
    /// Vertex in the closed `Q`.
    buried: RefCell<HashMap<u32, bool>>,
    /// Segment meets a closed boundary triangle of `Q`, by sorted ends.
    crossed: RefCell<HashMap<[u32; 2], bool>>,
    /// An edge of `Q` meets the closed triangle, by sorted corners.
    pierced: RefCell<HashMap<[u32; 3], bool>>,
}

/// The answer for `key`, computed by `f` the first time.
fn remembered<K: Hash + Eq>(
    memory: &RefCell<HashMap<K, bool>>,
    key: K,
    f: impl FnOnce() -> bool,
) -> bool {
    if let Some(&b) = memory.borrow().get(&key) {
        return b;
    }
    let b = f();
    let mut m = memory.borrow_mut();
    if m.len() >= REMEMBERED {
        m.clear();
    }
    m.insert(key, b);
    b
}

impl Sight {
    pub(in crate::shell::removal) fn new(q: Blocker) -> Sight {
        Sight {
            q,
            buried: RefCell::default(),
            crossed: RefCell::default(),
            pierced: RefCell::default(),
        }
    }

    /// `Q`'s number of points (for Step 3a's budget of work).
    pub(super) fn len(&self) -> usize {
        self.q.len()
    }

    fn buried(&self, pts: &[Point3], v: u32) -> bool {
        remembered(&self.buried, v, || self.q.contains(&pts[v as usize]))
    }

    fn crossed(&self, pts: &[Point3], a: u32, b: u32) -> bool {
        let key = [a.min(b), a.max(b)];
        remembered(&self.crossed, key, || {
            self.q.crossed(&pts[a as usize], &pts[b as usize])
        })
    }

    fn pierced(&self, pts: &[Point3], mut t: [u32; 3]) -> bool {
        t.sort_unstable();
        remembered(&self.pierced, t, || {
            let [a, b, c] = t.map(|i| pts[i as usize]);
            self.q.pierces(&a, &b, &c)
        })
    }

    /// The closed segment `vu` misses the closed `Q`.
    pub(super) fn sees(&self, pts: &[Point3], v: u32, u: u32) -> bool {
        self.q.apart(&[pts[v as usize], pts[u as usize]])
            || !(self.buried(pts, v) || self.crossed(pts, v, u))
    }

    /// The closed cone `conv({v} ∪ t)` misses the closed `Q`.
    pub(super) fn sees_triangle(&self, pts: &[Point3], v: u32, t: [u32; 3]) -> bool {
        let [a, b, c] = t;
        let corners = [v, a, b, c].map(|i| pts[i as usize]);
        if self.q.apart(&corners) {
            return true;
        }
        let segments = [[v, a], [v, b], [v, c], [a, b], [b, c], [c, a]];
        let faces = [[v, a, b], [v, b, c], [v, c, a], t];
        !(self.buried(pts, v)
            || segments.iter().any(|&[x, y]| self.crossed(pts, x, y))
            || self.q.inside(&corners)
            || faces.iter().any(|&f| self.pierced(pts, f)))
    }
}
