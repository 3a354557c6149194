//! Every tetrahedralization that uses every point, each found once: a depth-first search
//! that closes open faces.
//!
//! The search starts from the candidates holding the anchor (every tetrahedralization
//! has exactly one). A chosen tetrahedron *opens* each of its faces that is not on the
//! hull, asking for a tetrahedron on the other side; the search picks the open face with
//! the fewest compatible candidates there and branches on them. A state with no open face
//! is a tetrahedralization: its tetrahedra meet properly (the compatibility table), and
//! their union is closed with its boundary on the hull, so it is the hull (a closed set
//! whose boundary lies on the boundary of a convex body, and which meets its interior, is
//! the body); it uses every point because candidates are empty. Each tetrahedralization
//! `T` is found once: the first choice is `T`'s tetrahedron at the anchor, and at every
//! later state the open face is a function of the state, and `T` has one tetrahedron on
//! its other side.

use super::candidates::Candidates;
use crate::control::Control;

/// Why the enumeration ended before the last tetrahedralization.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Cut {
    /// The `limit` tetrahedralizations were found.
    Limit,
    /// The time limit passed, or a stop was requested.
    TimeLimit,
    /// The caller had what it was looking for ([`super::for_each_tetrahedralization`]).
    Done,
}

/// Tetrahedralizations as candidate ids, ascending, one after another in one array.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct Family {
    members: Vec<u16>,
    starts: Vec<u32>,
}

impl Family {
    pub fn len(&self) -> usize {
        self.starts.len()
    }

    pub fn get(&self, i: usize) -> &[u16] {
        let end = self
            .starts
            .get(i + 1)
            .map_or(self.members.len(), |&e| e as usize);
        &self.members[self.starts[i] as usize..end]
    }

    fn push(&mut self, t: &[u16]) {
        self.starts.push(self.members.len() as u32);
        self.members.extend_from_slice(t);
    }
}

/// The tetrahedralizations found, and whether the search ended early.
pub(super) struct Found {
    pub all: Family,
    pub cut: Option<Cut>,
    /// Search states visited.
    pub states: u64,
}

struct Search<'a> {
    c: &'a Candidates,
    /// Per depth: the candidates compatible with every chosen one.
    allowed: Vec<Vec<u64>>,
    chosen: Vec<u16>,
    /// Per face: the side (0 or 1) a tetrahedron is asked for, or `NONE`.
    need: Vec<u8>,
    open: Vec<u32>,
    /// Each tetrahedralization found, as candidate ids ascending: `false` ends the search.
    visit: &'a mut dyn FnMut(&[u16]) -> bool,
    count: usize,
    limit: usize,
    states: u64,
    ctl: &'a Control,
    cut: Option<Cut>,
}

const NONE: u8 = u8::MAX;

/// Every tetrahedralization, or the first `limit`, starting from the candidates `start`
/// that hold the anchor.
pub(super) fn enumerate(c: &Candidates, start: &[u16], limit: usize, ctl: &Control) -> Found {
    let mut all = Family::default();
    let mut keep = |t: &[u16]| {
        all.push(t);
        true
    };
    let (cut, states) = visit(c, start, limit, ctl, &mut keep);
    Found { all, cut, states }
}

/// Each tetrahedralization (at most `limit`) handed to `each` as it is found, until it
/// returns `false`: why the search ended early, if it did, and the states visited.
pub(super) fn visit(
    c: &Candidates,
    start: &[u16],
    limit: usize,
    ctl: &Control,
    each: &mut dyn FnMut(&[u16]) -> bool,
) -> (Option<Cut>, u64) {
    let mut s = Search {
        c,
        allowed: vec![vec![u64::MAX; c.words]],
        chosen: Vec::new(),
        need: vec![NONE; c.faces.len()],
        open: Vec::new(),
        visit: each,
        count: 0,
        limit,
        states: 0,
        ctl,
        cut: None,
    };
    for &t in start {
        s.choose(t);
        s.search();
        s.unchoose(t);
        if s.cut.is_some() {
            break;
        }
    }
    (s.cut, s.states)
}

impl Search<'_> {
    fn search(&mut self) {
        self.states += 1;
        if self.states.is_multiple_of(4096) && self.ctl.is_stopped() {
            self.cut = Some(Cut::TimeLimit);
            return;
        }
        let Some(face) = self.narrowest() else {
            return;
        };
        let Some(face) = face else {
            let mut t = self.chosen.clone();
            t.sort_unstable();
            self.count += 1;
            if !(self.visit)(&t) {
                self.cut = Some(Cut::Done);
            } else if self.count >= self.limit {
                self.cut = Some(Cut::Limit);
            }
            return;
        };
        let side = self.need[face as usize] as usize;
        let depth = self.chosen.len();
        for &t in &self.c.faces[face as usize].sides[side] {
            if !bit(&self.allowed[depth], t) {
                continue;
            }
            self.choose(t);
            self.search();
            self.unchoose(t);
            if self.cut.is_some() {
                return;
            }
        }
    }

    /// The open face with the fewest allowed candidates across it: `Some(None)` when
    /// nothing is open (a tetrahedralization), `None` when some open face has none (a
    /// dead end).
    fn narrowest(&self) -> Option<Option<u32>> {
        let allowed = &self.allowed[self.chosen.len()];
        let mut best: Option<(usize, u32)> = None;
        for &f in &self.open {
            let side = self.need[f as usize] as usize;
            let n = self.c.faces[f as usize].sides[side]
                .iter()
                .filter(|&&t| bit(allowed, t))
                .count();
            if n == 0 {
                return None;
            }
            if best.is_none_or(|(m, _)| n < m) {
                best = Some((n, f));
            }
        }
        Some(best.map(|(_, f)| f))
    }

    fn choose(&mut self, t: u16) {
        let depth = self.chosen.len();
        if self.allowed.len() == depth + 1 {
            self.allowed.push(vec![0; self.c.words]);
        }
        let (below, above) = self.allowed.split_at_mut(depth + 1);
        for ((out, &a), &r) in above[0].iter_mut().zip(&below[depth]).zip(self.c.row(t)) {
            *out = a & r;
        }
        self.chosen.push(t);
        for &(f, side) in &self.c.tet_faces[t as usize] {
            if self.c.faces[f as usize].hull {
                continue;
            }
            if self.need[f as usize] == side {
                self.need[f as usize] = NONE;
                let at = self.open.iter().position(|&g| g == f).expect("open face");
                self.open.swap_remove(at);
            } else {
                self.need[f as usize] = 1 - side;
                self.open.push(f);
            }
        }
    }

    fn unchoose(&mut self, t: u16) {
        self.chosen.pop();
        for &(f, side) in self.c.tet_faces[t as usize].iter().rev() {
            if self.c.faces[f as usize].hull {
                continue;
            }
            if self.need[f as usize] == 1 - side {
                self.need[f as usize] = NONE;
                let at = self.open.iter().position(|&g| g == f).expect("open face");
                self.open.swap_remove(at);
            } else {
                self.need[f as usize] = side;
                self.open.push(f);
            }
        }
    }
}

fn bit(words: &[u64], t: u16) -> bool {
    words[t as usize / 64] >> (t % 64) & 1 == 1
}
