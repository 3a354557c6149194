//! BIGCAP-REMOVE (thesis §4.3): Steps 1 to 7, Step 3a by exact search within a budget,
//! visibility decided against the closed `Q`, refused pieces repaired.
//!
//! - **Step 1.** While no vertex of `Q` is on the surface next to an outer vertex, the cap
//!   at an outer vertex of least degree.
//! - **Step 2.** `Q_a`: the vertices of `Q` on the surface next to an outer vertex still
//!   there; `P_a`: the outer vertices next to one of them (the polygons around the exposed
//!   part of `Q`); `V_a^P`: those of `P_a` on a surface triangle whose other two corners
//!   are vertices of `Q`. `V_a^P` cuts `P_a` into chains (`C_a`): here the components of
//!   the surface edges between vertices of `P_a`, cut at the vertices of `V_a^P`, each
//!   with the `V_a^P` vertices at its ends. `S_a(v)` is every chain but `v`'s.
//! - **Step 3.** Tips from `P_a − V_a^P`, then from `V_a^P` (Remark 1: the bridges to `Q`
//!   stay as long as possible); each removes its `S_a(v)`-bigcap: `U_v^S`, the outer
//!   vertices `u ∉ V(S)` on the surface that `v` sees together with every surface
//!   triangle at `u` (the segment, and the cone from `v` over each triangle, miss the
//!   closed `Q`: exact, [`sight`]).
//! - **Step 3a** by exact search ([`step_3a`]): the fewest tips whose S-bigcaps, in
//!   order, remove every vertex of `P_a`, ties broken by the fewest tetrahedra, within a
//!   deterministic budget; a round it cannot decide takes every tip (Lemma 4.4's order).
//! - **Step 5.** `Q'_a` and `P'_a` on the new surface.
//! - **Step 6** ([`step_6`]): the chains of `P_b` (the boundary of the round's view)
//!   whose inner vertices are next to no vertex of `Q`, removed chord by chord by
//!   `S_b`-bigcaps.
//! - **Step 7.** Back to Step 2.
//!
//! Where `U_v^S` is not a piece [`Surface::plan`](super::super::surface) accepts (the
//! bigcap is not star-shaped from its tip, as Lemma 4.1 claims it is, or its region is
//! not a disk), the piece is **repaired**: grown from the tip within `U_v^S`, neighbours
//! in increasing number, kept while accepted (the repaired definition: S-bigcaps
//! restricted to what the tip sees). [`ThesisSteps`] counts both. A round that removes
//! nothing ends in a Step-1 cap, and what no piece removes is left to Bern's loop and
//! then to placing.

mod sight;
mod step_3a;
mod step_6;

pub(super) use sight::Sight;

use super::Removal;
use crate::control::{Control, Stopped};
use crate::geom::Point3;
use rustc_hash::FxHashSet as HashSet;
use serde::Serialize;

/// What BIGCAP-REMOVE's steps did on one run ([`crate::shell::Method::Thesis`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct ThesisSteps {
    /// Step 1's caps (before `Q` shows, or after a round that removed nothing).
    pub step_1_caps: usize,
    /// Rounds of Steps 2–3.
    pub rounds: usize,
    /// S-bigcaps removed whole, as the thesis defines them.
    pub s_bigcaps: usize,
    /// S-bigcaps the surface refused (not star-shaped from the tip, or not a disk),
    /// removed repaired.
    pub repaired: usize,
    /// Rounds whose tips Step 3a's exact search chose: the fewest that remove every
    /// vertex of `P_a` (ties: the fewest tetrahedra).
    pub step_3a_exact: usize,
    /// Rounds where `P_a` had more than 12 vertices or the search passed its budget of
    /// work before deciding, and every tip of `P_a` was taken (Lemma 4.4's order).
    pub step_3a_every_tip: usize,
    /// The largest `P_a` the exact search decided.
    pub largest_p_a_searched: usize,
    /// Step 6's chains of `P_b` (their inner vertices next to no vertex of `Q`)
    /// removed chord by chord.
    pub step_6_chains: usize,
    /// Step 6's S_b-bigcaps.
    pub step_6_bigcaps: usize,
}

/// How [`s_bigcap`] removed its piece.
pub(super) enum Taken {
    Whole,
    Repaired,
}

/// Removes `v`'s `S_a(v)`-bigcap, or the repaired one where the surface refuses it;
/// `None` when `v` is gone or even its cap is refused.
fn s_bigcap(r: &mut Removal, v: u32, round: &Round, sight: &Sight) -> Option<Taken> {
    if !r.left.contains(&v) {
        return None;
    }
    let set = u_v(r, v, &round.s_a(v), sight);
    if r.piece(v, &set) {
        Some(Taken::Whole)
    } else if grown(r, v, &set) {
        Some(Taken::Repaired)
    } else {
        None
    }
}

/// The rounds of Steps 1–7 on `r`, until no outer vertex is left or none of them can
/// be removed.
pub(super) fn run(
    r: &mut Removal,
    inner: &[u32],
    sight: &Sight,
    ctl: &Control,
) -> Result<ThesisSteps, Stopped> {
    let mut steps = ThesisSteps::default();
    while !r.left.is_empty() {
        ctl.check()?;
        let round = Round::new(r, inner);
        if round.p_a.is_empty() {
            if !step_1(r) {
                break;
            }
            steps.step_1_caps += 1;
            continue;
        }
        steps.rounds += 1;
        let before = r.left.len();
        let step_3 = step_3a::step_3(r, &round, sight, ctl)?;
        if step_3.decided {
            steps.step_3a_exact += 1;
            steps.largest_p_a_searched = steps.largest_p_a_searched.max(round.p_a.len());
        } else {
            steps.step_3a_every_tip += 1;
        }
        for t in &step_3.taken {
            match t {
                Taken::Whole => steps.s_bigcaps += 1,
                Taken::Repaired => steps.repaired += 1,
            }
        }
        step_6::run(r, &round, &step_3.views, (inner, sight), (&mut steps, ctl))?;
        if r.left.len() == before {
            if !step_1(r) {
                break;
            }
            steps.step_1_caps += 1;
        }
    }
    Ok(steps)
}

/// The cap at the outer vertex of least degree that the surface accepts.
fn step_1(r: &mut Removal) -> bool {
    let mut tips: Vec<(usize, u32)> = r.left.iter().map(|&v| (0, v)).collect();
    for t in &mut tips {
        t.0 = r.surface.degree(t.1);
    }
    tips.sort_unstable();
    tips.into_iter().any(|(_, v)| r.cap(v))
}

/// Step 2's sets on the current surface.
struct Round {
    /// `Q_a`.
    q_a: HashSet<u32>,
    /// `P_a`.
    p_a: HashSet<u32>,
    /// `V_a^P`.
    v_a: HashSet<u32>,
    /// The surface edges between vertices of `P_a`.
    edges: Vec<[u32; 2]>,
}

impl Round {
    fn new(r: &mut Removal, inner: &[u32]) -> Round {
        let is_inner: HashSet<u32> = inner.iter().copied().collect();
        let (mut p_a, mut q_a) = (HashSet::default(), HashSet::default());
        for &q in inner {
            for u in r.surface.neighbours(q) {
                if r.left.contains(&u) {
                    p_a.insert(u);
                    q_a.insert(q);
                }
            }
        }
        let mut v_a = HashSet::default();
        let mut edges = Vec::new();
        for &v in &p_a {
            for t in r.surface.star(v) {
                let tri = r.surface.triangle(t);
                let others: Vec<u32> = tri.into_iter().filter(|&x| x != v).collect();
                if others.iter().all(|x| is_inner.contains(x)) {
                    v_a.insert(v);
                }
                edges.extend(others.iter().filter(|x| p_a.contains(x)).map(|&x| [v, x]));
            }
        }
        Round {
            q_a,
            p_a,
            v_a,
            edges,
        }
    }

    /// Tips of `P_a − V_a^P` by degree, then those of `V_a^P` by degree.
    fn tips(&self, r: &mut Removal) -> Vec<u32> {
        let mut tips: Vec<(bool, usize, u32)> = self
            .p_a
            .iter()
            .map(|&v| (self.v_a.contains(&v), 0, v))
            .collect();
        for t in &mut tips {
            t.1 = r.surface.degree(t.2);
        }
        tips.sort_unstable();
        tips.into_iter().map(|t| t.2).collect()
    }

    /// A lower bound on Step 3a's count: the fewest tips that could take every vertex
    /// of `P_a`. A tip `v`'s piece takes vertices of `U_v^S` only: none of `S_a(v)`,
    /// and none whose segment to `v` meets `Q` (whatever the surface, as `Q` stays). So
    /// every vertex of `P_a` is a tip or such a vertex of one. For at most
    /// [`STEP_3A_LARGEST`] vertices, by trying every set of tips.
    fn fewest_tips(&self, points: &[Point3], sight: &Sight) -> usize {
        let p_a: Vec<u32> = self.p_a.iter().copied().collect();
        let k = p_a.len();
        let reach: Vec<u32> = (p_a.iter())
            .map(|&v| {
                let s = self.s_a(v);
                let seen = |u: u32| u == v || (!s.contains(&u) && sight.sees(points, v, u));
                (0..k).filter(|&i| seen(p_a[i])).map(|i| 1 << i).sum()
            })
            .collect();
        let covers = |set: u32| {
            let union = (0..k)
                .filter(|i| set >> i & 1 == 1)
                .fold(0, |u, i| u | reach[i]);
            union == (1 << k) - 1
        };
        (0..1u32 << k)
            .filter(|&set| covers(set))
            .map(|set| set.count_ones() as usize)
            .min()
            .unwrap_or(k)
    }

    /// `V(S_a(v))`: the vertices of `P_a` on no chain through `v`.
    fn s_a(&self, v: u32) -> HashSet<u32> {
        // v's chains: from v along edges of P_a, not through a vertex of V_a^P (their
        // ends belong to the chain).
        let mut mine: HashSet<u32> = HashSet::default();
        let mut stack = vec![v];
        mine.insert(v);
        while let Some(x) = stack.pop() {
            if x != v && self.v_a.contains(&x) {
                continue;
            }
            for e in self.edges.iter().filter(|e| e[0] == x) {
                if mine.insert(e[1]) {
                    stack.push(e[1]);
                }
            }
        }
        self.p_a
            .iter()
            .copied()
            .filter(|u| !mine.contains(u))
            .collect()
    }
}

/// `U_v^S`: the tip and the outer vertices `u ∉ s` left on the surface that `v` sees
/// with every surface triangle at `u` (past the closed `Q`).
fn u_v(r: &mut Removal, v: u32, s: &HashSet<u32>, sight: &Sight) -> Vec<u32> {
    let pts = r.surface.points();
    let mut candidates: Vec<u32> = r
        .left
        .iter()
        .copied()
        .filter(|u| *u != v && !s.contains(u))
        .collect();
    candidates.sort_unstable();
    let mut set = vec![v];
    for u in candidates {
        let seen = sight.sees(pts, v, u)
            && (r.surface.star(u).into_iter())
                .all(|t| sight.sees_triangle(pts, v, r.surface.triangle(t)));
        if seen {
            set.push(u);
        }
    }
    set
}

/// The repaired S-bigcap: grown from `{v}` within `within`, neighbours in increasing
/// number, each kept while the surface accepts the piece; false when even the cap at
/// `v` is refused.
fn grown(r: &mut Removal, v: u32, within: &[u32]) -> bool {
    let allowed: HashSet<u32> = within.iter().copied().collect();
    r.grow(v, Some(&allowed), &super::Bounds::NONE)
}
