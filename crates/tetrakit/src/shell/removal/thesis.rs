//! BIGCAP-REMOVE's order (thesis §4.3), as far as it is built: Steps 1, 2, 3 and 5, with
//! Step 3a greedy and Step 6 left to caps.
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
//!   stay as long as possible), least degree first; each removes its `S_a(v)`-bigcap:
//!   `U_v^S`, the outer vertices `u ∉ V(S)` on the surface that `v` sees together with
//!   every surface triangle at `u` (the segment, and the cone from `v` over each
//!   triangle, miss the closed `Q`: exact, by separating planes). The thesis finds the
//!   fewest tips by an exact search (3a); here every tip of the round is taken.
//! - **Step 5.** Back to Step 2 on the new surface.
//!
//! Where `U_v^S` is not a piece [`Surface::plan`](super::super::surface) accepts (the
//! bigcap is not star-shaped from its tip, as Lemma 4.1 claims it is, or its region is
//! not a disk), the piece is **repaired**: grown from the tip within `U_v^S`, neighbours
//! in increasing number, kept while accepted (the repaired definition: S-bigcaps
//! restricted to what the tip sees). [`ThesisSteps`] counts both. Step 6 (chains of
//! `P_b` removed chord by chord) is not built: a round that removes nothing ends in a
//! Step-1 cap, and what no piece removes is left to Bern's loop and then to placing.

use super::Removal;
use crate::control::{Control, Stopped};
use crate::geom::Point3;
use crate::shell::lemma41::Blocker;
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
}

/// The rounds of Steps 1–3 and 5 on `r`, until no outer vertex is left or none of
/// them can be removed.
pub(super) fn run(
    r: &mut Removal,
    inner: &[u32],
    q: &Blocker,
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
        for v in round.tips(r) {
            ctl.check()?;
            if !r.left.contains(&v) {
                continue;
            }
            let set = u_v(r, v, &round.s_a(v), q);
            if r.piece(v, &set) {
                steps.s_bigcaps += 1;
            } else if grown(r, v, &set) {
                steps.repaired += 1;
            }
        }
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
        let mut p_a = HashSet::default();
        for &q in inner {
            for u in r.surface.neighbours(q) {
                if r.left.contains(&u) {
                    p_a.insert(u);
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
        Round { p_a, v_a, edges }
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
fn u_v(r: &mut Removal, v: u32, s: &HashSet<u32>, q: &Blocker) -> Vec<u32> {
    let pts = r.surface.points();
    let pv = pts[v as usize];
    let mut candidates: Vec<u32> = r
        .left
        .iter()
        .copied()
        .filter(|u| *u != v && !s.contains(u))
        .collect();
    candidates.sort_unstable();
    let mut set = vec![v];
    for u in candidates {
        if !q.misses(&[pts[u as usize], pv]) {
            continue;
        }
        let seen = r.surface.star(u).into_iter().all(|t| {
            let cone: Vec<Point3> = r
                .surface
                .triangle(t)
                .iter()
                .map(|&x| pts[x as usize])
                .chain([pv])
                .collect();
            q.misses(&cone)
        });
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
    r.grow(v, Some(&allowed), usize::MAX, usize::MAX)
}
