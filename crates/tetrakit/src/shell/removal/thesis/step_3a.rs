//! Step 3a of BIGCAP-REMOVE by exact search ([`minimum`]): the fewest tips whose
//! S-bigcaps, in order, remove every vertex of `P_a`, ties broken by the fewest
//! tetrahedra (the thesis: the fewest edges added, which for pieces coned from their
//! tips is the same order up to the pieces' bottoms). Lemma 4.4's order (every tip,
//! least degree first) bounds the count from above, the chains and the segments past
//! `Q` from below ([`Round::fewest_tips`]), and iterative deepening over copies of the
//! surface tries the orders between, each surface reached once per count of tips and
//! tetrahedra.
//!
//! The search is exponential; its budget ([`STEP_3A_WORK`], and `P_a` of at most
//! [`STEP_3A_LARGEST`] vertices) is deterministic, and a round it cannot decide takes
//! every tip ([`ThesisSteps::step_3a_every_tip`](super::ThesisSteps)). What it found:
//! with visibility decided against the closed `Q`, a vertex of `P_a`, next to a vertex
//! of `Q`, is in no other tip's `U_v^S` (the cone over its triangle at that vertex
//! touches `Q`), so the fewest tips is `|P_a|` on every round we ran, and the search
//! decides the order by the tie-break; on contact shells, where the lower bound stays
//! far below `|P_a|`, its budget runs out and the round takes every tip.

use super::{Round, Sight, Taken, s_bigcap};
use crate::control::{Control, Stopped};
use crate::shell::ledger::Record;
use crate::shell::removal::Removal;
use crate::shell::surface::Surface;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

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
    sight: &Sight,
    ctl: &Control,
) -> Result<(Choice<'a>, bool), Stopped> {
    let order = round.tips(r);
    if order.len() > STEP_3A_LARGEST {
        return Ok((Choice::EveryTip, false));
    }
    let every = trial(r, &order, round, sight, ctl)?;
    let mut search = Search {
        round,
        sight,
        order: &order,
        work: order.len() * r.left.len() * sight.len(),
        best: None,
        seen: HashMap::default(),
    };
    if round.p_a.iter().any(|v| every.left.contains(v)) {
        return Ok((Choice::Tried(Box::new(every)), false));
    }
    let most = every.tips.len();
    search.best = Some((every.tips.clone(), every.tets.len()));
    for depth in round.fewest_tips(r.surface.points(), sight)..=most {
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
    /// `view(v_1, …, v_m)` as it grows: the surface triangles each tip saw right after
    /// its piece went (some gone since).
    views: Vec<u32>,
}

/// `tips`' S-bigcaps in turn, on a copy of `r`'s surface (a tip already gone, or
/// whose cap is refused, is passed over).
fn trial<'a>(
    r: &Removal<'_, 'a>,
    tips: &[u32],
    round: &Round,
    sight: &Sight,
    ctl: &Control,
) -> Result<Trial<'a>, Stopped> {
    let mut surface = r.surface.clone();
    let mut sim = Removal::new(&mut surface, r.left.clone());
    let (mut used, mut taken, mut views) = (Vec::new(), Vec::new(), Vec::new());
    for &v in tips {
        ctl.check()?;
        if let Some(t) = s_bigcap(&mut sim, v, round, sight) {
            used.push(v);
            taken.push(t);
            views.extend(sim.surface.seen_from(v));
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
        views,
    })
}

/// Makes a trial's removals `r`'s own.
fn adopt<'a>(r: &mut Removal<'_, 'a>, t: Trial<'a>) -> Step3 {
    let start = r.tets.len();
    *r.surface = t.surface;
    r.left = t.left;
    r.tets.extend(t.tets);
    r.records.extend(t.records.into_iter().map(|mut rec| {
        rec.tets = rec.tets.start + start..rec.tets.end + start;
        rec
    }));
    r.order.extend(t.order);
    Step3 {
        decided: false,
        taken: t.taken,
        views: t.views,
    }
}

/// What Steps 3a and 3b did in one round.
pub(super) struct Step3 {
    /// The search decided 3a's tips (else every tip was taken).
    pub decided: bool,
    /// How each tip's piece was taken, in order.
    pub taken: Vec<Taken>,
    /// The triangles of `view(v_1, …, v_m)`, some gone since (see [`Trial::views`]).
    pub views: Vec<u32>,
}

/// Steps 3a and 3b on `r`: the tips chosen, and their S-bigcaps removed in order.
pub(super) fn step_3(
    r: &mut Removal,
    round: &Round,
    sight: &Sight,
    ctl: &Control,
) -> Result<Step3, Stopped> {
    let (choice, decided) = minimum(r, round, sight, ctl)?;
    let t = match choice {
        Choice::Tried(t) => *t,
        Choice::Order(tips) => trial(r, &tips, round, sight, ctl)?,
        Choice::EveryTip => {
            let tips = round.tips(r);
            trial(r, &tips, round, sight, ctl)?
        }
    };
    Ok(Step3 {
        decided,
        ..adopt(r, t)
    })
}

/// Step 3a's search state.
struct Search<'r> {
    round: &'r Round,
    sight: &'r Sight,
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
            self.work += left.len() * self.sight.len();
            if self.work > STEP_3A_WORK {
                return Ok(());
            }
            ctl.check()?;
            let mut copy = surface.clone();
            let mut r = Removal::new(&mut copy, left.clone());
            if s_bigcap(&mut r, v, self.round, self.sight).is_some() {
                let (added, after) = (r.tets.len(), r.left);
                tips.push(v);
                self.visit(&copy, &after, tips, (depth, tets + added), ctl)?;
                tips.pop();
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::step_1;
    use super::*;
    use crate::geom::Point3;
    use crate::shell::Shell;

    /// Every order of at most `depth` tips of `p_a` (those outside `V_a^P` first),
    /// replayed from scratch, with no bound and nothing remembered: true when one
    /// removes every vertex of `P_a`.
    fn some_order_within(
        r: &Removal,
        round: &Round,
        sight: &Sight,
        tips: &[u32],
        depth: usize,
    ) -> bool {
        let mut copy = r.surface.clone();
        let mut sim = Removal::new(&mut copy, r.left.clone());
        let taken = tips
            .iter()
            .all(|&v| s_bigcap(&mut sim, v, round, sight).is_some());
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
            allowed && some_order_within(r, round, sight, &[tips, &[v]].concat(), depth)
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
            let Ok(mut surface) = Surface::new(&shell) else {
                continue;
            };
            let q_points: Vec<Point3> = shell
                .inner
                .iter()
                .map(|&v| shell.points[v as usize])
                .collect();
            let sight = Sight::new(crate::shell::blocker::Blocker::new(&q_points));
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
                let every = trial(&r, &order, &round, &sight, &ctl).unwrap();
                let tips = match minimum(&mut r, &round, &sight, &ctl).unwrap() {
                    (Choice::Order(tips), true) => tips,
                    (Choice::Tried(t), true) => t.tips,
                    _ => break,
                };
                decided += 1;
                assert!(
                    some_order_within(&r, &round, &sight, &tips, tips.len()),
                    "shell {k}"
                );
                shorter += usize::from(tips.len() < every.tips.len());
                assert!(tips.len() >= round.fewest_tips(r.surface.points(), &sight));
                assert!(
                    tips.len() == 1 || !some_order_within(&r, &round, &sight, &[], tips.len() - 1),
                    "shell {k}: an order of fewer than {} tips",
                    tips.len()
                );
                let taken = trial(&r, &tips, &round, &sight, &ctl).unwrap();
                adopt(&mut r, taken);
            }
        }
        eprintln!("{decided} rounds, {shorter} with fewer tips than Lemma 4.4's order");
        assert!(decided > 150, "{decided} rounds, {shorter} shorter");
    }
}
