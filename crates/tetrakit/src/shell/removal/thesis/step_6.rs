//! Step 6 of BIGCAP-REMOVE (thesis §4.3, Remark 2, Lemma 4.7). After Step 3b, `P_b` is
//! the boundary of `view(v_1, …, v_m)`: the surface triangles that some tip of the
//! round saw right after its piece went, those still there. A chain `y_1 … y_k` of
//! `P_b` whose inner vertices are outer vertices next to no vertex of `Q` (not in the
//! new `P_a`), between two vertices of the new `P_a` joined by a surface edge that
//! faces a vertex of `Q` on both `Q_a` and `Q'_a`, is removed chord by chord: for each
//! chord `y_i y_j` (a surface edge between two vertices of the chain, the longest
//! stretch first: a linear extension of the thesis's decreasing partial order), a
//! vertex `y_l` between them whose `S_b`-bigcap, `S_b = P_b − {y_{i+1}, …, y_{j−1}}`,
//! takes all of `y_{i+1} … y_{j−1}` is removed, and the chord replaces the stretch.
//!
//! Departures: an `S_b`-bigcap the surface refuses is repaired only at an ear (one
//! vertex between the chord's ends, which Remark 2 says always exists), else its
//! stretch waits for the next round; a `P_b` that passes a vertex twice (pinched) is passed over; a
//! chord is any surface edge between two vertices of the chain (the thesis takes those
//! in the disk the chain bounds, where Lemma 4.7 puts no vertex).

use super::{Round, Sight, ThesisSteps, grown, u_v};
use crate::control::{Control, Stopped};
use crate::shell::removal::Removal;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::cmp::Reverse;

/// Step 6 after a round whose Step 2 was `old` and whose tips saw `views`.
pub(super) fn run(
    r: &mut Removal,
    old: &Round,
    views: &[u32],
    (inner, sight): (&[u32], &Sight),
    (steps, ctl): (&mut ThesisSteps, &Control),
) -> Result<(), Stopped> {
    let region: HashSet<u32> = (views.iter().copied())
        .filter(|&t| r.surface.is_live(t))
        .collect();
    let Some(cycles) = boundary(r, &region) else {
        return Ok(());
    };
    let p_b: HashSet<u32> = cycles.iter().flatten().copied().collect();
    let new = Round::new(r, inner);
    for cycle in &cycles {
        for chain in chains(r, cycle, old, &new) {
            steps.step_6_chains += 1;
            steps.step_6_bigcaps += by_chords(r, chain, (&p_b, sight), ctl)?;
        }
    }
    Ok(())
}

/// The cycles bounding `region` (directed as its triangles), or `None` where a
/// vertex starts two boundary edges.
fn boundary(r: &Removal, region: &HashSet<u32>) -> Option<Vec<Vec<u32>>> {
    let mut next: HashMap<u32, u32> = HashMap::default();
    for &t in region {
        let tri = r.surface.triangle(t);
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            let outside = r.surface.across(a, b).is_none_or(|u| !region.contains(&u));
            if outside && next.insert(a, b).is_some() {
                return None;
            }
        }
    }
    let mut starts: Vec<u32> = next.keys().copied().collect();
    starts.sort_unstable();
    let mut cycles = Vec::new();
    for s in starts {
        let Some(mut v) = next.remove(&s) else {
            continue;
        };
        let mut cycle = vec![s];
        while v != s {
            cycle.push(v);
            v = next.remove(&v)?;
        }
        cycles.push(cycle);
    }
    Some(cycles)
}

/// The chains of `cycle` that Step 6 removes (see the module docs), each from `y_1`
/// to `y_k`.
fn chains(r: &mut Removal, cycle: &[u32], old: &Round, new: &Round) -> Vec<Vec<u32>> {
    let Some(first) = cycle.iter().position(|v| new.p_a.contains(v)) else {
        return Vec::new();
    };
    let inner_vertex = |v: &u32| r.left.contains(v) && !new.p_a.contains(v);
    let turned: Vec<u32> = (0..=cycle.len())
        .map(|k| cycle[(first + k) % cycle.len()])
        .collect();
    let mut found = Vec::new();
    let mut start = 0;
    for k in 1..turned.len() {
        if inner_vertex(&turned[k]) {
            continue;
        }
        let chain = &turned[start..=k];
        if chain.len() > 2 && new.p_a.contains(&turned[k]) {
            found.push(chain.to_vec());
        }
        start = k;
    }
    found.retain(|c| faces_q(r, c[0], c[c.len() - 1], old, new));
    found
}

/// `y_1 y_k` is a surface edge on a triangle whose third vertex is in `Q_a ∩ Q'_a`.
fn faces_q(r: &mut Removal, y_1: u32, y_k: u32, old: &Round, new: &Round) -> bool {
    r.surface.star(y_1).into_iter().any(|t| {
        let tri = r.surface.triangle(t);
        tri.contains(&y_k) && (tri.iter()).any(|q| old.q_a.contains(q) && new.q_a.contains(q))
    })
}

/// `y` sees every vertex of `stretch` past `Q` (what holds whatever the surface, so
/// before `U_y^{S_b}` is computed).
fn sees_stretch(r: &Removal, y: u32, stretch: &[u32], sight: &Sight) -> bool {
    let p = r.surface.points();
    (stretch.iter()).all(|&s| s == y || sight.sees(p, y, s))
}

/// Step 6b and 6c on one chain; the `S_b`-bigcaps removed.
fn by_chords(
    r: &mut Removal,
    mut chain: Vec<u32>,
    (p_b, sight): (&HashSet<u32>, &Sight),
    ctl: &Control,
) -> Result<usize, Stopped> {
    let mut removed = 0;
    'chain: while chain.len() > 2 {
        ctl.check()?;
        let mut chords = Vec::new();
        for i in 0..chain.len() {
            let around = r.surface.neighbours(chain[i]);
            chords.extend(
                (i + 2..chain.len())
                    .filter(|&j| around.contains(&chain[j]))
                    .map(|j| (i, j)),
            );
        }
        chords.sort_by_key(|&(i, j)| (Reverse(j - i), i));
        // `U_y^{S_b}` is `U_y^∅` without `S_b` (what `y` sees does not depend on `S`):
        // each `y` is looked at once per surface.
        let mut seen: HashMap<u32, Vec<u32>> = HashMap::default();
        for (i, j) in chords {
            let stretch = &chain[i + 1..j];
            for &y in stretch {
                if !sees_stretch(r, y, stretch, sight) {
                    continue;
                }
                let all = match seen.get(&y) {
                    Some(all) => all.clone(),
                    None => u_v(r, y, &HashSet::default(), sight),
                };
                seen.insert(y, all.clone());
                // S_b = P_b − stretch.
                let set: Vec<u32> = (all.into_iter())
                    .filter(|u| stretch.contains(u) || !p_b.contains(u))
                    .collect();
                let whole = stretch.iter().all(|s| set.contains(s)) && r.piece(y, &set);
                // An ear (Remark 2: one vertex between the chord's ends) whose
                // S_b-bigcap the surface refuses is repaired, as in Step 3.
                if whole || (stretch.len() == 1 && grown(r, y, &set)) {
                    removed += 1;
                    chain.drain(i + 1..j);
                    continue 'chain;
                }
            }
        }
        break;
    }
    Ok(removed)
}
