//! BIGCAP-REMOVE's order (thesis §4.3), as far as it is built: Steps 1, 2, 3 (3a by
//! exact search) and 5, with Step 6 left to caps.
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
//!   closed `Q`: exact, by separating planes).
//! - **Step 3a** by exact search ([`minimum`]): the fewest tips whose S-bigcaps, in
//!   order, remove every vertex of `P_a`, ties broken by the fewest tetrahedra (the
//!   thesis: the fewest edges added, which for pieces coned from their tips is the same
//!   order up to the pieces' bottoms). Lemma 4.4's order (every tip, least degree first)
//!   bounds the count from above, the chains and the segments past `Q` from below
//!   ([`Round::fewest_tips`]), and iterative deepening over copies of the surface tries
//!   the orders between, each surface reached once per count of tips and tetrahedra.
//!   The search is exponential; its budget ([`STEP_3A_WORK`], and `P_a` of at most
//!   [`STEP_3A_LARGEST`] vertices) is deterministic, and a round it cannot decide takes
//!   every tip ([`ThesisSteps::step_3a_every_tip`]). What it found: with visibility
//!   decided against the closed `Q`, a vertex of `P_a`, next to a vertex of `Q`, is in
//!   no other tip's `U_v^S` (the cone over its triangle at that vertex touches `Q`), so
//!   the fewest tips is `|P_a|` on every round we ran, and the search decides the order
//!   by the tie-break; on contact shells, where the lower bound stays far below
//!   `|P_a|`, its budget runs out and the round takes every tip.
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
use crate::shell::ledger::Record;
use crate::shell::lemma41::Blocker;
use crate::shell::surface::Surface;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
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
}

/// The most work Step 3a's exact search does in one round, counted as the outer
/// vertices left times the vertices of `Q` at each order tried (each order costs a copy
/// of the surface and an S-bigcap, whose `U_v^S` tests every outer vertex left against
/// `Q`): a deterministic budget, three times what the rounds of the small random shells
/// of the tests take at most (6,000), and about a tenth of a second of search per
/// round on the contact shells of BENCHMARKS.md, where it cannot decide.
const STEP_3A_WORK: usize = 20_000;

/// The largest `P_a` Step 3a searches: past it every tip is taken at once (on contact
/// shells `P_a` holds hundreds of vertices from the first round, and a search that
/// cannot finish would only cost its budget).
const STEP_3A_LARGEST: usize = 12;

/// How [`s_bigcap`] removed its piece.
enum Taken {
    Whole,
    Repaired,
}

/// Removes `v`'s `S_a(v)`-bigcap, or the repaired one where the surface refuses it;
/// `None` when `v` is gone or even its cap is refused.
fn s_bigcap(r: &mut Removal, v: u32, round: &Round, q: &Blocker) -> Option<Taken> {
    if !r.left.contains(&v) {
        return None;
    }
    let set = u_v(r, v, &round.s_a(v), q);
    if r.piece(v, &set) {
        Some(Taken::Whole)
    } else if grown(r, v, &set) {
        Some(Taken::Repaired)
    } else {
        None
    }
}

/// Step 3a by exact search (see the module docs): the fewest tips (those of `P_a − V_a^P` before those of
/// `V_a^P`) whose S-bigcaps, removed in order, remove every vertex of `P_a`, and among
/// them the fewest tetrahedra found within [`STEP_3A_WORK`]. Lemma 4.4's order (every
/// tip in turn, on a copy of the surface) bounds the count from above and the chains
/// ([`Round::fewest_tips`]) from below; iterative deepening over copies tries every
/// order in between. `None` (take every tip) when
/// `P_a` is larger than [`STEP_3A_LARGEST`], when Lemma 4.4's order leaves a vertex of
/// `P_a` (a refused piece: the thesis's premise fails, and no search is made), or when
/// the work passes [`STEP_3A_WORK`] before the count is proved. By Lemma 4.4, removing every vertex
/// of `P_a` also leaves `Q_a^view`'s vertices removed or on `P_b`, so that condition of
/// 3a is not searched separately (for a repaired piece the lemma is not proved; the
/// final mesh is certified either way).
fn minimum<'a>(
    r: &mut Removal<'_, 'a>,
    round: &Round,
    q: &Blocker,
    ctl: &Control,
) -> Result<(Choice<'a>, bool), Stopped> {
    let order = round.tips(r);
    if order.len() > STEP_3A_LARGEST {
        return Ok((Choice::EveryTip, false));
    }
    let every = trial(r, &order, round, q, ctl)?;
    let mut search = Search {
        round,
        q,
        order: &order,
        work: order.len() * r.left.len() * q.len(),
        best: None,
        seen: HashMap::default(),
    };
    if round.p_a.iter().any(|v| every.left.contains(v)) {
        return Ok((Choice::Tried(Box::new(every)), false));
    }
    let most = every.tips.len();
    search.best = Some((every.tips.clone(), every.tets.len()));
    for depth in round.fewest_tips(r.surface.points(), q)..=most {
        search.seen.clear();
        search.visit(r.surface, &r.left, &mut Vec::new(), (depth, 0), ctl)?;
        let found = search.best.as_ref().is_some_and(|b| b.0.len() <= depth);
        if found || search.work > STEP_3A_WORK {
            // An order shorter than `depth` cannot cover `P_a` or was tried and
            // failed, so a best of `depth` tips is the fewest even when the ties were
            // not all tried.
            return Ok(match search.best {
                Some((tips, _)) if found && tips != every.tips => (Choice::Order(tips), true),
                _ => (Choice::Tried(Box::new(every)), found),
            });
        }
    }
    Ok((Choice::Tried(Box::new(every)), false))
}

/// Step 3a's choice of tips for a round.
enum Choice<'a> {
    /// Tips taken on a copy of the surface, to be adopted: Lemma 4.4's order, which
    /// the search found best or could not better.
    Tried(Box<Trial<'a>>),
    /// The search's best order, to be taken.
    Order(Vec<u32>),
    /// Every tip in turn, not tried (`P_a` too large to search).
    EveryTip,
}

/// Tips taken in turn on a copy of the surface.
struct Trial<'a> {
    surface: Surface<'a>,
    left: HashSet<u32>,
    tets: Vec<[u32; 4]>,
    records: Vec<Record>,
    order: Vec<u32>,
    /// The tips that removed a piece, and how.
    tips: Vec<u32>,
    taken: Vec<Taken>,
}

/// `tips`' S-bigcaps in turn, on a copy of `r`'s surface (a tip already gone, or
/// whose cap is refused, is passed over).
fn trial<'a>(
    r: &Removal<'_, 'a>,
    tips: &[u32],
    round: &Round,
    q: &Blocker,
    ctl: &Control,
) -> Result<Trial<'a>, Stopped> {
    let mut surface = r.surface.clone();
    let mut sim = Removal::new(&mut surface, r.left.clone());
    let (mut used, mut taken) = (Vec::new(), Vec::new());
    for &v in tips {
        ctl.check()?;
        if let Some(t) = s_bigcap(&mut sim, v, round, q) {
            used.push(v);
            taken.push(t);
        }
    }
    let Removal {
        left,
        tets,
        records,
        order,
        ..
    } = sim;
    Ok(Trial {
        surface,
        left,
        tets,
        records,
        order,
        tips: used,
        taken,
    })
}

/// Makes a trial's removals `r`'s own; how each tip's piece was taken.
fn adopt<'a>(r: &mut Removal<'_, 'a>, t: Trial<'a>) -> Vec<Taken> {
    let start = r.tets.len();
    *r.surface = t.surface;
    r.left = t.left;
    r.tets.extend(t.tets);
    r.records.extend(t.records.into_iter().map(|mut rec| {
        rec.tets = rec.tets.start + start..rec.tets.end + start;
        rec
    }));
    r.order.extend(t.order);
    t.taken
}

/// Step 3a's search state.
struct Search<'r> {
    round: &'r Round,
    q: &'r Blocker,
    /// The tips of `P_a`, those of `P_a − V_a^P` first.
    order: &'r [u32],
    /// What the orders tried cost so far (see [`STEP_3A_WORK`]).
    work: usize,
    /// The best order so far and its tetrahedra.
    best: Option<(Vec<u32>, usize)>,
    /// Surfaces reached in this depth's pass ([`Surface::key`]), each with the tips and
    /// tetrahedra of the orders that reached it (those no other reached with fewer of
    /// both): an order reaching one again with no fewer of either is not searched again
    /// (what follows depends on the surface, the vertices left and the tips left only).
    seen: HashMap<Vec<[u32; 3]>, Vec<(usize, usize)>>,
}

impl Search<'_> {
    /// False when the surface was reached before with no more tips and tetrahedra (and
    /// the same freedom to take tips outside `V_a^P`); notes it otherwise.
    fn first_visit(&mut self, surface: &Surface, in_v_a: bool, cost: (usize, usize)) -> bool {
        let mut key = surface.key();
        key.push([u32::from(in_v_a), 0, 0]);
        let front = self.seen.entry(key).or_default();
        if front.iter().any(|b| b.0 <= cost.0 && b.1 <= cost.1) {
            return false;
        }
        front.retain(|b| !(cost.0 <= b.0 && cost.1 <= b.1));
        front.push(cost);
        true
    }

    /// Every order of at most `depth` tips extending `tips` (taken on `surface` with
    /// `left` left, `tets` tetrahedra so far).
    fn visit(
        &mut self,
        surface: &Surface,
        left: &HashSet<u32>,
        tips: &mut Vec<u32>,
        (depth, tets): (usize, usize),
        ctl: &Control,
    ) -> Result<(), Stopped> {
        if !self.round.p_a.iter().any(|v| left.contains(v)) {
            if self
                .best
                .as_ref()
                .is_none_or(|b| (tips.len(), tets) < (b.0.len(), b.1))
            {
                self.best = Some((tips.clone(), tets));
            }
            return Ok(());
        }
        let in_v_a = tips.last().is_some_and(|t| self.round.v_a.contains(t));
        if tips.len() == depth || !self.first_visit(surface, in_v_a, (tips.len(), tets)) {
            return Ok(());
        }
        for &v in self.order {
            if !left.contains(&v) || (in_v_a && !self.round.v_a.contains(&v)) {
                continue;
            }
            self.work += left.len() * self.q.len();
            if self.work > STEP_3A_WORK {
                return Ok(());
            }
            ctl.check()?;
            let mut copy = surface.clone();
            let mut r = Removal::new(&mut copy, left.clone());
            if s_bigcap(&mut r, v, self.round, self.q).is_some() {
                let (added, after) = (r.tets.len(), r.left);
                tips.push(v);
                self.visit(&copy, &after, tips, (depth, tets + added), ctl)?;
                tips.pop();
            }
        }
        Ok(())
    }
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
        let (choice, decided) = minimum(r, &round, q, ctl)?;
        if decided {
            steps.step_3a_exact += 1;
            steps.largest_p_a_searched = steps.largest_p_a_searched.max(round.p_a.len());
        } else {
            steps.step_3a_every_tip += 1;
        }
        let taken = match choice {
            Choice::Tried(t) => adopt(r, *t),
            Choice::Order(tips) => trial(r, &tips, &round, q, ctl).map(|t| adopt(r, t))?,
            Choice::EveryTip => {
                let tips = round.tips(r);
                trial(r, &tips, &round, q, ctl).map(|t| adopt(r, t))?
            }
        };
        for t in taken {
            match t {
                Taken::Whole => steps.s_bigcaps += 1,
                Taken::Repaired => steps.repaired += 1,
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

    /// A lower bound on Step 3a's count: the fewest tips that could take every vertex
    /// of `P_a`. A tip `v`'s piece takes vertices of `U_v^S` only: none of `S_a(v)`,
    /// and none whose segment to `v` meets `Q` (whatever the surface, as `Q` stays). So
    /// every vertex of `P_a` is a tip or such a vertex of one. For at most
    /// [`STEP_3A_LARGEST`] vertices, by trying every set of tips.
    fn fewest_tips(&self, points: &[Point3], q: &Blocker) -> usize {
        let p_a: Vec<u32> = self.p_a.iter().copied().collect();
        let k = p_a.len();
        let reach: Vec<u32> = (p_a.iter())
            .map(|&v| {
                let s = self.s_a(v);
                let seen = |u: u32| {
                    u == v
                        || (!s.contains(&u) && q.misses(&[points[u as usize], points[v as usize]]))
                };
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shell::{Shell, recover::QEdges};

    /// Every order of at most `depth` tips of `p_a` (those outside `V_a^P` first),
    /// replayed from scratch, with no bound and nothing remembered: true when one
    /// removes every vertex of `P_a`.
    fn some_order_within(
        r: &Removal,
        round: &Round,
        q: &Blocker,
        tips: &[u32],
        depth: usize,
    ) -> bool {
        let mut copy = r.surface.clone();
        let mut sim = Removal::new(&mut copy, r.left.clone());
        let taken = tips
            .iter()
            .all(|&v| s_bigcap(&mut sim, v, round, q).is_some());
        if !taken {
            return false;
        }
        if !round.p_a.iter().any(|v| sim.left.contains(v)) {
            return true;
        }
        if tips.len() == depth {
            return false;
        }
        let in_v_a = tips.last().is_some_and(|t| round.v_a.contains(t));
        round.p_a.iter().any(|&v| {
            let allowed = sim.left.contains(&v) && (!in_v_a || round.v_a.contains(&v));
            allowed && some_order_within(r, round, q, &[tips, &[v]].concat(), depth)
        })
    }

    /// On small random shells, each round's order from the search removes every
    /// vertex of `P_a`, and brute force over every shorter order finds none that does.
    #[test]
    fn step_3a_finds_the_fewest_tips() {
        let mut rng = crate::rng::Rng::new(3);
        let mut sphere = |m: usize, r: f64| -> Vec<Point3> {
            (0..m)
                .map(|_| {
                    let p = [0; 3].map(|_| 2.0 * rng.unit() - 1.0);
                    let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
                    p.map(|x| 0.02 + r * x / l)
                })
                .collect()
        };
        let (mut decided, mut shorter) = (0, 0);
        for k in 0..200 {
            let (outer, inner) = (sphere(8 + k % 6, 1.0), sphere(5 + k % 3, 0.4));
            let Ok(shell) = Shell::new(&outer, &inner) else {
                continue;
            };
            let hidden: Vec<u32> = (shell.inner.iter().copied())
                .filter(|&v| v as usize >= shell.outer.len())
                .collect();
            let q_edges = QEdges::new(&shell.points, &shell.inner);
            let Ok(mut surface) = Surface::new(
                &shell.points,
                &shell.hull,
                (&hidden, &shell.touching),
                &q_edges,
            ) else {
                continue;
            };
            let q_points: Vec<Point3> = shell
                .inner
                .iter()
                .map(|&v| shell.points[v as usize])
                .collect();
            let q = Blocker::new(&q_points);
            let mut r = Removal::new(&mut surface, shell.outer.iter().copied().collect());
            let ctl = Control::new();
            while !r.left.is_empty() {
                let round = Round::new(&mut r, &shell.inner);
                if round.p_a.is_empty() {
                    if !step_1(&mut r) {
                        break;
                    }
                    continue;
                }
                let order = round.tips(&mut r);
                let every = trial(&r, &order, &round, &q, &ctl).unwrap();
                let tips = match minimum(&mut r, &round, &q, &ctl).unwrap() {
                    (Choice::Order(tips), true) => tips,
                    (Choice::Tried(t), true) => t.tips,
                    _ => break,
                };
                decided += 1;
                assert!(
                    some_order_within(&r, &round, &q, &tips, tips.len()),
                    "shell {k}"
                );
                shorter += usize::from(tips.len() < every.tips.len());
                assert!(tips.len() >= round.fewest_tips(r.surface.points(), &q));
                assert!(
                    tips.len() == 1 || !some_order_within(&r, &round, &q, &[], tips.len() - 1),
                    "shell {k}: an order of fewer than {} tips",
                    tips.len()
                );
                let taken = trial(&r, &tips, &round, &q, &ctl).unwrap();
                adopt(&mut r, taken);
            }
        }
        eprintln!("{decided} rounds, {shorter} with fewer tips than Lemma 4.4's order");
        assert!(decided > 150, "{decided} rounds, {shorter} shorter");
    }
}
