//! A Hamiltonian path in a small-degree graph: depth-first, the neighbour with the fewest
//! unvisited neighbours first (Warnsdorff's rule), within a budget of steps. A step is
//! undone at once when what is left cannot be finished: the unvisited nodes not all
//! reachable from the head through unvisited nodes, or more than one of them (away from
//! the head) with at most one unvisited neighbour (each such node must end the path).

use crate::control::Control;
use crate::rng::Rng;

/// A path through every node of `adj` (undirected adjacency lists), or `None` when the
/// search found none within `budget` steps (added to `steps`) or `ctl` stopped it.
pub(super) fn hamiltonian_path(
    adj: &[Vec<u32>],
    budget: u64,
    ctl: &Control,
    steps: &mut u64,
) -> Option<Vec<u32>> {
    let n = adj.len();
    if n <= 1 {
        return Some((0..n as u32).collect());
    }
    if adj.iter().any(Vec::is_empty) {
        return None;
    }
    let leaves: Vec<u32> = (0..n as u32)
        .filter(|&v| adj[v as usize].len() == 1)
        .collect();
    if leaves.len() > 2 {
        return None;
    }
    let starts: Vec<u32> = if leaves.is_empty() {
        let mut by_degree: Vec<u32> = (0..n as u32).collect();
        by_degree.sort_by_key(|&v| adj[v as usize].len());
        by_degree.truncate(4);
        by_degree
    } else {
        leaves
    };
    // Restarts with ties broken at random: a depth-first search's time is heavy-tailed.
    let tries = 8 * starts.len() as u64;
    let mut rng = Rng::new(0x9a7);
    (0..tries).find_map(|k| {
        let start = starts[k as usize % starts.len()];
        let seed = if k < starts.len() as u64 {
            None
        } else {
            Some(rng.next_u64())
        };
        Search::new(adj, seed).run(start, budget / tries, ctl, steps)
    })
}

/// A path through every node of `adj`, searched completely (no budget; only the
/// pruning above, which never drops a path): `Some(None)` when there is none, `None` when
/// `ctl` stopped the search. A leaf must end the path, so the search starts there when
/// there is one, and from every node otherwise.
pub(super) fn exact_path(
    adj: &[Vec<u32>],
    ctl: &Control,
    steps: &mut u64,
) -> Option<Option<Vec<u32>>> {
    let n = adj.len();
    if n <= 1 {
        return Some(Some((0..n as u32).collect()));
    }
    let leaves: Vec<u32> = (0..n as u32)
        .filter(|&v| adj[v as usize].len() <= 1)
        .collect();
    if leaves.len() > 2 || adj.iter().any(Vec::is_empty) {
        return Some(None);
    }
    let starts: Vec<u32> = match leaves.first() {
        Some(&leaf) => vec![leaf],
        None => (0..n as u32).collect(),
    };
    for s in starts {
        if let Some(p) = Search::new(adj, None).run(s, u64::MAX, ctl, steps) {
            return Some(Some(p));
        }
        if ctl.is_stopped() {
            return None;
        }
    }
    Some(None)
}

struct Search<'a> {
    adj: &'a [Vec<u32>],
    /// Breaks ties between equally constrained neighbours (none: the adjacency order).
    rng: Option<Rng>,
    visited: Vec<bool>,
    /// Unvisited neighbours of each node.
    free: Vec<u32>,
}

impl<'a> Search<'a> {
    fn new(adj: &'a [Vec<u32>], seed: Option<u64>) -> Self {
        Search {
            adj,
            rng: seed.map(Rng::new),
            visited: vec![false; adj.len()],
            free: adj.iter().map(|a| a.len() as u32).collect(),
        }
    }

    fn visit(&mut self, v: u32, on: bool) {
        self.visited[v as usize] = on;
        for &w in &self.adj[v as usize] {
            if on {
                self.free[w as usize] -= 1;
            } else {
                self.free[w as usize] += 1;
            }
        }
    }

    /// `v`'s unvisited neighbours, the one with the fewest unvisited neighbours last.
    fn choices(&mut self, v: u32) -> Vec<u32> {
        let mut c: Vec<u32> = (self.adj[v as usize].iter().copied())
            .filter(|&w| !self.visited[w as usize])
            .collect();
        if let Some(rng) = &mut self.rng {
            rng.shuffle(&mut c);
        }
        c.sort_by_key(|&w| std::cmp::Reverse(self.free[w as usize]));
        c
    }

    /// With the path's head at `z` and `left` nodes unvisited: can a path from `z`
    /// still cover them? (Necessary conditions: see the module docs.)
    fn open(&self, z: u32, left: usize, queue: &mut Vec<u32>, seen: &mut [bool]) -> bool {
        queue.clear();
        queue.push(z);
        seen[z as usize] = true;
        let (mut reached, mut ends, mut i) = (0, 0, 0);
        while i < queue.len() {
            let u = queue[i];
            i += 1;
            for &w in &self.adj[u as usize] {
                if self.visited[w as usize] || seen[w as usize] {
                    continue;
                }
                seen[w as usize] = true;
                reached += 1;
                let next_to_head = u == z;
                if self.free[w as usize] <= 1 && !next_to_head {
                    ends += 1;
                }
                queue.push(w);
            }
        }
        for &u in queue.iter() {
            seen[u as usize] = false;
        }
        reached == left && ends <= 1
    }

    fn run(mut self, start: u32, budget: u64, ctl: &Control, steps: &mut u64) -> Option<Vec<u32>> {
        let n = self.adj.len();
        let mut used = 0u64;
        self.visit(start, true);
        let mut path = vec![start];
        let mut levels = vec![self.choices(start)];
        let (mut queue, mut seen) = (Vec::with_capacity(n), vec![false; n]);
        loop {
            if path.len() == n {
                return Some(path);
            }
            let next = levels.last_mut().and_then(Vec::pop);
            let Some(z) = next else {
                levels.pop();
                let z = path.pop()?;
                if path.is_empty() {
                    return None;
                }
                self.visit(z, false);
                continue;
            };
            used += 1;
            *steps += 1;
            if used > budget || (used.is_multiple_of(1024) && ctl.is_stopped()) {
                return None;
            }
            self.visit(z, true);
            if !self.open(z, n - path.len() - 1, &mut queue, &mut seen) {
                self.visit(z, false);
                continue;
            }
            path.push(z);
            levels.push(self.choices(z));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::path::tests::{brute_force, is_path, random_graph};

    /// The complete search agrees with trying every order, on 3000 random graphs of at
    /// most 8 nodes and degree at most 4 (a dual graph's), paths and none alike.
    #[test]
    fn the_complete_search_is_complete() {
        let mut rng = Rng::new(17);
        let (ctl, mut steps) = (Control::new(), 0);
        let mut counts = [0; 2];
        for _ in 0..3000 {
            let adj = random_graph(&mut rng, 8);
            let found = exact_path(&adj, &ctl, &mut steps).expect("never stopped");
            assert_eq!(found.is_some(), brute_force(&adj), "{adj:?}");
            if let Some(p) = found {
                assert!(is_path(&adj, &p), "{adj:?}: {p:?}");
            }
            counts[usize::from(brute_force(&adj))] += 1;
        }
        assert!(counts[0] > 300 && counts[1] > 300, "{counts:?}");
    }
}
