//! The order of removal: Bern's minimum-degree order for both methods (a lazy heap),
//! each tip's piece a cap or a greedy bigcap, a tip and a neighbour together where every
//! cap is refused, and the order removed so far when nothing more is (for the placing
//! that finishes the shell, see [`super::tetrahedralize`]).

mod thesis;

use super::Method;
use super::blocker::Blocker;
use super::ledger::Record;
use super::surface::{self, Surface};
use crate::control::{Control, Stopped};
use rustc_hash::FxHashSet as HashSet;
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use thesis::Sight;
pub use thesis::ThesisSteps;

/// The most vertices one bigcap removes (each added vertex costs a local hull).
const BIGCAP_LIMIT: usize = 32;

/// The most sets one bigcap tries (a refused one costs a local hull too: where a tip has
/// thousands of neighbours, trying them all made bigcaps quadratic per tip).
const BIGCAP_TRIES: usize = BIGCAP_LIMIT + 4;

/// The most triangles (the sum of the degrees) the stars of one bigcap's set may have.
/// A set's plan costs about as much as its stars; without a bound, the hubs of a prism's
/// cap polygon (degrees in the thousands, growing with `n`) joined set after set, and
/// bigcaps on twisted prisms took `n^1.3`.
const BIGCAP_STAR: usize = 4 * BIGCAP_LIMIT;

/// How far [`Removal::grow`] grows a set.
struct Bounds {
    /// The most vertices.
    vertices: usize,
    /// The most sets tried.
    tries: usize,
    /// The most triangles in the set's stars (the sum of their degrees).
    star: usize,
}

impl Bounds {
    /// No bound.
    const NONE: Bounds = Bounds {
        vertices: usize::MAX,
        tries: usize::MAX,
        star: usize::MAX,
    };
}

/// The most pairs one round of [`Removal::pair`] tries (each costs a local hull; where
/// the last tips of a prism's cap are refused, trying every pair took two thirds of the
/// time and found none).
const PAIR_TRIES: usize = 32;

/// The removal in progress: the surface, the outer vertices still on it, and the
/// tetrahedra so far.
struct Removal<'s, 'a> {
    surface: &'s mut Surface<'a>,
    left: HashSet<u32>,
    /// `(degree, vertex)` as one integer ([`heap_key`]), least first.
    heap: BinaryHeap<Reverse<u64>>,
    tets: Vec<[u32; 4]>,
    records: Vec<Record>,
    /// The removed vertices, in the order of removal (a piece's tip first).
    order: Vec<u32>,
}

/// What a removal did: its tetrahedra, and the vertices it could not remove.
pub(super) struct Removed {
    pub tets: Vec<[u32; 4]>,
    /// Its pieces, in order (for the ledger of §4.4).
    pub records: Vec<Record>,
    /// The removed vertices, in the order of removal.
    pub order: Vec<u32>,
    /// The vertices no piece removed (every cap, pair and bigcap at them refused).
    pub left: Vec<u32>,
    /// What BIGCAP-REMOVE's steps did ([`Method::Thesis`]).
    pub thesis: Option<ThesisSteps>,
}

impl<'s, 'a> Removal<'s, 'a> {
    /// A removal on `surface` with `left` left and nothing removed yet (Step 3a's search
    /// tries orders on copies).
    fn new(surface: &'s mut Surface<'a>, left: HashSet<u32>) -> Self {
        Removal {
            surface,
            left,
            heap: BinaryHeap::new(),
            tets: Vec::new(),
            records: Vec::new(),
            order: Vec::new(),
        }
    }

    /// Removes the cap at `v` and requeues its neighbours with their new degrees; false
    /// (nothing changed) when the cap's checks refuse it.
    fn cap(&mut self, v: u32) -> bool {
        self.piece(v, &[v])
    }

    /// Removes `set` coned from `tip` (see [`Surface::plan`]).
    fn piece(&mut self, tip: u32, set: &[u32]) -> bool {
        match self.surface.plan(tip, set) {
            Ok(p) => {
                self.take(tip, p, set);
                true
            }
            Err(_) => false,
        }
    }

    /// Removes a bigcap at `v`: the largest set grown greedily from `{v}` (neighbours of
    /// the set in increasing number, at most [`BIGCAP_LIMIT`] vertices, [`BIGCAP_TRIES`]
    /// sets tried and [`BIGCAP_STAR`] triangles in their stars) whose piece is still
    /// star-shaped from `v` and passes every check of [`Surface::plan`]; false when even
    /// the cap at `v` is refused.
    fn bigcap(&mut self, v: u32) -> bool {
        let bounds = Bounds {
            vertices: BIGCAP_LIMIT,
            tries: BIGCAP_TRIES,
            star: BIGCAP_STAR,
        };
        self.grow(v, None, &bounds)
    }

    /// Removes the largest set grown greedily from `{v}` over the vertices left (and in
    /// `within`, if given): neighbours of the set in increasing number, each kept while
    /// [`Surface::plan`] accepts the piece, within `bounds`; false when even the cap at
    /// `v` is refused.
    fn grow(&mut self, v: u32, within: Option<&HashSet<u32>>, bounds: &Bounds) -> bool {
        let mut set = vec![v];
        let Ok(mut best) = self.surface.plan(v, &set) else {
            return false;
        };
        let mut star = self.surface.degree(v);
        let mut tried: HashSet<u32> = set.iter().copied().collect();
        while tried.len() < bounds.tries {
            let mut next: Vec<u32> = set
                .iter()
                .flat_map(|&u| self.surface.neighbours(u))
                .filter(|u| self.left.contains(u) && !tried.contains(u))
                .filter(|u| within.is_none_or(|w| w.contains(u)))
                .collect();
            next.sort_unstable();
            next.dedup();
            if next.is_empty() {
                break;
            }
            for u in next {
                tried.insert(u);
                if set.len() >= bounds.vertices || tried.len() > bounds.tries {
                    break;
                }
                let degree = self.surface.degree(u);
                if star + degree > bounds.star {
                    continue;
                }
                set.push(u);
                match self.surface.plan(v, &set) {
                    Ok(p) => {
                        best = p;
                        star += degree;
                    }
                    Err(_) => {
                        set.pop();
                    }
                }
            }
            if set.len() >= bounds.vertices {
                break;
            }
        }
        self.take(v, best, &set);
        true
    }

    /// Applies a planned piece removing `set`, and requeues the neighbours.
    fn take(&mut self, tip: u32, piece: surface::Piece, set: &[u32]) {
        let mut around: Vec<u32> = set
            .iter()
            .flat_map(|&u| self.surface.neighbours(u))
            .collect();
        around.sort_unstable();
        around.dedup();
        let start = self.tets.len();
        let bottom = piece.bottom().to_vec();
        self.tets.extend(self.surface.apply(piece));
        self.records.push(Record {
            tip,
            removed: set.len(),
            bottom,
            tets: start..self.tets.len(),
        });
        for v in set {
            self.left.remove(v);
        }
        self.order.extend_from_slice(set);
        for u in around {
            if self.left.contains(&u) {
                self.heap.push(Reverse(heap_key(self.surface.degree(u), u)));
            }
        }
    }

    /// When every cap is refused (coplanar facets of the current hull inside `P`, where a
    /// tip is not an ear of every such facet's triangulation): a tip with one removable
    /// neighbour, removed together; at most [`PAIR_TRIES`] pairs.
    fn pair(&mut self, refused: &[u32]) -> bool {
        let mut tries = 0;
        for &v in refused {
            for u in self.surface.neighbours(v) {
                if !self.left.contains(&u) {
                    continue;
                }
                if self.piece(v, &[v, u]) {
                    return true;
                }
                tries += 1;
                if tries >= PAIR_TRIES {
                    return false;
                }
            }
        }
        false
    }
}

/// `(degree, v)` as one integer ordered like the pair (a degree is below 2^32).
fn heap_key(degree: usize, v: u32) -> u64 {
    ((degree as u64) << 32) | u64::from(v)
}

/// Bern's order: the removable vertex of least degree first (ties by number), degrees
/// updated as the surface changes (a lazy heap: stale entries are skipped). A refused cap
/// is tried again once the surface has changed, and where every cap is refused, a tip
/// with a neighbour; what is still refused then is [`Removed::left`]. For
/// [`Method::Thesis`], BIGCAP-REMOVE's rounds ([`thesis`]) first, `inner` being `Q`'s
/// vertices; Bern's order takes what they leave. `None` when `go_on`, told the number of
/// tetrahedra made after each piece, answers `false` (the removal is then abandoned).
pub(super) fn run(
    surface: &mut Surface,
    removable: &[u32],
    inner: &[u32],
    (method, go_on): (Method, &mut dyn FnMut(usize) -> bool),
    ctl: &Control,
) -> Result<Option<Removed>, Stopped> {
    let mut r = Removal::new(surface, removable.iter().copied().collect());
    let thesis = match method {
        Method::Thesis => {
            let pts = r.surface.points();
            let q: Vec<_> = inner.iter().map(|&v| pts[v as usize]).collect();
            Some(thesis::run(
                &mut r,
                inner,
                &Sight::new(Blocker::new(&q)),
                ctl,
            )?)
        }
        _ => None,
    };
    let mut left: Vec<u32> = r.left.iter().copied().collect();
    left.sort_unstable();
    r.heap = left
        .into_iter()
        .map(|v| Reverse(heap_key(r.surface.degree(v), v)))
        .collect();
    let total = removable.len();
    let mut refused: Vec<u32> = Vec::new();
    loop {
        let Some(Reverse(key)) = r.heap.pop() else {
            // Some refused tips have been removed since, by a pair.
            refused.retain(|v| r.left.contains(v));
            if refused.is_empty() {
                break;
            }
            let before = r.left.len();
            refused.retain(|&v| !r.cap(v));
            if r.left.len() == before && !r.pair(&refused) {
                break;
            }
            continue;
        };
        let (d, v) = ((key >> 32) as usize, key as u32);
        if !r.left.contains(&v) || r.surface.degree(v) != d {
            continue;
        }
        ctl.check()?;
        let done = match method {
            Method::Cap | Method::Thesis => r.cap(v),
            Method::Bigcap => r.bigcap(v),
        };
        if !go_on(r.tets.len()) {
            return Ok(None);
        }
        if done {
            ctl.items((total - r.left.len()) as u64, total as u64);
        } else {
            refused.push(v);
        }
    }
    let mut left: Vec<u32> = r.left.into_iter().collect();
    left.sort_unstable();
    Ok(Some(Removed {
        tets: r.tets,
        records: r.records,
        order: r.order,
        left,
        thesis,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Point3;
    use crate::shell::Shell;

    /// Two `k`-gon prisms, the inner one slightly smaller and turned: every outer vertex
    /// is on a cap polygon, whose triangulation has vertices of degree about `k`.
    fn prisms(k: usize) -> (Vec<Point3>, Vec<Point3>) {
        let prism = |r: f64, h: f64, turn: f64| -> Vec<Point3> {
            let ring = |z: f64| {
                (0..k).map(move |j| {
                    let a = std::f64::consts::TAU * j as f64 / k as f64 + turn;
                    [r * a.cos(), r * a.sin(), z]
                })
            };
            ring(-h).chain(ring(h)).collect()
        };
        (prism(1.0, 1.0, 0.0), prism(0.99, 0.99, 0.01))
    }

    /// No bigcap tries a set whose stars have more than [`BIGCAP_STAR`] triangles: the
    /// hubs of the bottoms on a prism's cap polygons (degrees in the hundreds) are left
    /// out of the sets grown around them, where each try cost a hull of their stars.
    #[test]
    fn bigcaps_leave_out_the_hubs() {
        let (outer, inner) = prisms(400);
        let shell = Shell::new(&outer, &inner).expect("nested prisms");
        let mut surface = Surface::new(&shell).expect("a surface");
        let mut r = Removal::new(&mut surface, shell.outer.iter().copied().collect());
        let (mut refused, mut largest_set, mut hub) = (HashSet::default(), 0, 0);
        while let Some(v) = (r.left.iter().copied())
            .filter(|v| !refused.contains(v))
            .min_by_key(|&v| (r.surface.degree(v), v))
        {
            let around = r.surface.neighbours(v).into_iter();
            hub = hub.max(around.map(|u| r.surface.degree(u)).max().unwrap_or(0));
            let before = r.order.len();
            if !r.bigcap(v) {
                refused.insert(v);
            }
            largest_set = largest_set.max(r.order.len() - before);
        }
        assert!(
            hub > BIGCAP_STAR && largest_set > 4,
            "hub {hub}, sets {largest_set}"
        );
        let largest_cut = r.surface.largest_cut;
        assert!(
            largest_cut <= BIGCAP_STAR,
            "a cut of {largest_cut} triangles"
        );
    }
}
