//! The order of removal: Bern's minimum-degree order for both methods (a lazy heap),
//! each tip's piece a cap or a greedy bigcap, and the fallbacks for tips every cone
//! refuses (retry, a pair, the exact solver on one piece).

use super::surface::{self, Surface};
use super::{Method, ShellError};
use crate::control::Control;
use crate::geom::{Hull3, Point3};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// The most vertices one bigcap removes (each added vertex costs a local hull).
const BIGCAP_LIMIT: usize = 32;

/// The time the exact solver gets for one piece that no cone tiles.
const EXACT_PIECE_SECONDS: u64 = 10;

/// The removal in progress: the surface, the outer vertices still on it, and the
/// tetrahedra so far.
struct Removal<'s, 'a> {
    surface: &'s mut Surface<'a>,
    left: HashSet<u32>,
    heap: BinaryHeap<Reverse<(usize, u64, u32)>>,
    /// The tie-break among tips of one degree (see [`run`]).
    seed: u64,
    tets: Vec<[u32; 4]>,
    pieces: usize,
    /// The caller's control (the exact fallback stops with it).
    ctl: Control,
}

impl Removal<'_, '_> {
    /// Removes the cap at `v` and requeues its neighbours with their new degrees; false
    /// (nothing changed) when the cap's checks refuse it.
    fn cap(&mut self, v: u32) -> bool {
        self.piece(v, &[v])
    }

    /// Removes `set` coned from `tip` (see [`Surface::plan`]).
    fn piece(&mut self, tip: u32, set: &[u32]) -> bool {
        match self.surface.plan(tip, set) {
            Ok(p) => {
                self.take(p, set);
                true
            }
            Err(_) => false,
        }
    }

    /// Removes a bigcap at `v`: the largest set grown greedily from `{v}` (neighbours of
    /// the set in increasing number, at most [`BIGCAP_LIMIT`]) whose piece is still
    /// star-shaped from `v` and passes every check of [`Surface::plan`]; false when even
    /// the cap at `v` is refused.
    fn bigcap(&mut self, v: u32) -> bool {
        let mut set = vec![v];
        let Ok(mut best) = self.surface.plan(v, &set) else {
            return false;
        };
        let mut tried: HashSet<u32> = set.iter().copied().collect();
        loop {
            let mut next: Vec<u32> = set
                .iter()
                .flat_map(|&u| self.surface.neighbours(u))
                .filter(|u| self.left.contains(u) && !tried.contains(u))
                .collect();
            next.sort_unstable();
            next.dedup();
            if next.is_empty() {
                break;
            }
            for u in next {
                tried.insert(u);
                if set.len() >= BIGCAP_LIMIT {
                    break;
                }
                set.push(u);
                match self.surface.plan(v, &set) {
                    Ok(p) => best = p,
                    Err(_) => {
                        set.pop();
                    }
                }
            }
            if set.len() >= BIGCAP_LIMIT {
                break;
            }
        }
        self.take(best, &set);
        true
    }

    /// Applies a planned piece removing `set`, and requeues the neighbours.
    fn take(&mut self, piece: surface::Piece, set: &[u32]) {
        let mut around: Vec<u32> = set
            .iter()
            .flat_map(|&u| self.surface.neighbours(u))
            .collect();
        around.sort_unstable();
        around.dedup();
        self.tets.extend(self.surface.apply(piece));
        self.pieces += 1;
        for v in set {
            self.left.remove(v);
        }
        for u in around {
            if self.left.contains(&u) {
                let key = (self.surface.degree(u), rank(u, self.seed), u);
                self.heap.push(Reverse(key));
            }
        }
    }

    /// The piece removing `set` as a polyhedron (its old surface triangles and its bottom
    /// reversed), tetrahedralized by the exact solver instead of a cone: for the pieces
    /// no vertex is a kernel vertex of (two tips each coplanar with a triangle of the
    /// other's star that has tetrahedra behind it). At most [`EXACT_PIECE_SECONDS`].
    fn exact_piece(&mut self, set: &[u32]) -> bool {
        let Ok(cut) = self.surface.cut(set[0], set) else {
            return false;
        };
        let mut faces = self.surface.region_triangles(&cut);
        faces.extend(cut.bottom.iter().map(|t| [t[0], t[2], t[1]]));
        let mut ids: Vec<u32> = faces.iter().flatten().copied().collect();
        ids.sort_unstable();
        ids.dedup();
        if ids.len() > crate::exact::MAX_VERTICES {
            return false;
        }
        let local = |v: u32| ids.binary_search(&v).unwrap_or(0) as u32;
        let points = ids.iter().map(|&v| self.surface.point(v)).collect();
        let faces = faces.iter().map(|f| f.map(local)).collect();
        let Ok(poly) = crate::mesh::Polyhedron::new(points, faces) else {
            return false;
        };
        let Some(tets) = exact_tets(crate::exact::Domain::Polyhedron(&poly), &self.ctl) else {
            return false;
        };
        let tets = tets.iter().map(|t| t.map(|k| ids[k as usize])).collect();
        self.take(cut.with_tets(tets), set);
        true
    }

    /// The last resort: a refused tip alone, or with one removable neighbour, as an exact
    /// piece.
    fn exact(&mut self, refused: &[u32]) -> bool {
        for &v in refused {
            if self.exact_piece(&[v]) {
                return true;
            }
            for u in self.surface.neighbours(v) {
                if self.left.contains(&u) && self.exact_piece(&[v, u]) {
                    return true;
                }
            }
        }
        false
    }

    /// The last resort when every removal is refused (the current hull and `Q` in
    /// shared or parallel planes, where the flat parts of a piece would not meet earlier
    /// tetrahedra face to face): the whole region left, `P̄ − int Q`, tetrahedralized by
    /// the exact solver when it has at most [`crate::exact::MAX_VERTICES`] vertices, with
    /// the surface's triangles fixed (earlier tetrahedra are on them) and the hidden
    /// facets of `Q` free.
    fn exact_finish(&mut self, inner: &[u32]) -> bool {
        let q_points: Vec<Point3> = inner.iter().map(|&v| self.surface.point(v)).collect();
        let q = Hull3::new(&q_points);
        let local: HashMap<u32, usize> = inner.iter().enumerate().map(|(k, &v)| (v, k)).collect();
        let on_q = |t: &[u32; 3]| {
            let [a, b, c] = t.map(|v| local.get(&v).copied());
            matches!((a, b, c), (Some(a), Some(b), Some(c)) if q.common_facet(a, b, c).is_some())
        };
        let faces: Vec<[u32; 3]> = self
            .surface
            .triangles()
            .into_iter()
            .filter(|t| !on_q(t))
            .collect();
        let mut ids: Vec<u32> = faces.iter().flatten().chain(inner).copied().collect();
        ids.sort_unstable();
        ids.dedup();
        if faces.is_empty() || ids.len() > crate::exact::MAX_VERTICES {
            return false;
        }
        let local_id = |v: u32| ids.binary_search(&v).unwrap_or(0) as u32;
        let points: Vec<Point3> = ids.iter().map(|&v| self.surface.point(v)).collect();
        let faces: Vec<[u32; 3]> = faces.iter().map(|f| f.map(local_id)).collect();
        let inner_local: Vec<u32> = inner.iter().map(|&v| local_id(v)).collect();
        let domain = crate::exact::Domain::Shell {
            points: &points,
            inner: &inner_local,
            outer_faces: Some(&faces),
        };
        let Some(tets) = exact_tets(domain, &self.ctl) else {
            return false;
        };
        self.tets
            .extend(tets.iter().map(|t| t.map(|k| ids[k as usize])));
        self.pieces += 1;
        self.surface.clear();
        self.left.clear();
        true
    }

    /// When every cap is refused (coplanar facets of the current hull inside `P`, where a
    /// tip is not an ear of every such facet's triangulation): a tip with one removable
    /// neighbour, removed together.
    fn pair(&mut self, refused: &[u32]) -> bool {
        for &v in refused {
            for u in self.surface.neighbours(v) {
                if self.left.contains(&u) && self.piece(v, &[v, u]) {
                    return true;
                }
            }
        }
        false
    }
}

/// Any tetrahedralization of `domain` by the exact solver, within
/// [`EXACT_PIECE_SECONDS`] and `ctl` (certified by [`crate::exact::solve`]).
pub(super) fn exact_tets(domain: crate::exact::Domain, ctl: &Control) -> Option<Vec<[u32; 4]>> {
    let limit = std::time::Duration::from_secs(EXACT_PIECE_SECONDS);
    let ctl = ctl.child().with_time_limit(limit);
    let options = crate::exact::Options {
        unique: false,
        any: true,
    };
    match crate::exact::minimal_tetrahedralization(domain, &options, &ctl) {
        Ok((
            crate::exact::Outcome::Found { tets } | crate::exact::Outcome::Optimal { tets, .. },
            _,
        )) => Some(tets),
        _ => None,
    }
}

/// The tie-break of tips of one degree: by number for seed 0, else a fixed shuffle.
fn rank(v: u32, seed: u64) -> u64 {
    if seed == 0 {
        return v as u64;
    }
    let mut x = (v as u64) ^ seed.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    x ^ (x >> 31)
}

/// Bern's order: the removable vertex of least degree first (ties broken by
/// [`rank`] with `seed`), degrees updated as the surface changes (a lazy heap: stale
/// entries are skipped). A refused cap is tried again once the surface has changed.
pub(super) fn run(
    surface: &mut Surface,
    removable: &[u32],
    inner: &[u32],
    (method, seed): (Method, u64),
    ctl: &Control,
) -> Result<(Vec<[u32; 4]>, usize), ShellError> {
    let heap = removable
        .iter()
        .map(|&v| Reverse((surface.degree(v), rank(v, seed), v)))
        .collect();
    let mut r = Removal {
        surface,
        left: removable.iter().copied().collect(),
        heap,
        tets: Vec::new(),
        pieces: 0,
        ctl: ctl.clone(),
        seed,
    };
    let total = removable.len();
    let mut refused: Vec<u32> = Vec::new();
    loop {
        let Some(Reverse((d, _, v))) = r.heap.pop() else {
            // Some refused tips have been removed since, by a pair.
            refused.retain(|v| r.left.contains(v));
            if refused.is_empty() {
                break;
            }
            let before = r.left.len();
            refused.retain(|&v| !r.cap(v));
            if r.left.len() == before
                && !r.pair(&refused)
                && !r.exact(&refused)
                && !r.exact_finish(inner)
            {
                ctl.check()?; // the exact fallback gave up because the run was stopped
                return Err(ShellError::Internal(format!(
                    "{} caps refused",
                    refused.len()
                )));
            }
            continue;
        };
        if !r.left.contains(&v) || r.surface.degree(v) != d {
            continue;
        }
        ctl.check()?;
        let done = match method {
            Method::Cap => r.cap(v),
            Method::Bigcap | Method::Thesis => r.bigcap(v),
        };
        if done {
            ctl.items((total - r.left.len()) as u64, total as u64);
        } else {
            refused.push(v);
        }
    }
    Ok((r.tets, r.pieces))
}
