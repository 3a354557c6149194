//! Disjoint sets over `0..n` as a parent array (union-find with path halving): the
//! facets of a hull, the components of a boundary surface, the cocircular cells of a
//! Delaunay triangulation, the faces of the MWT's certain edges.

/// `0..n`, each element its own set.
pub(crate) fn singletons(n: usize) -> Vec<u32> {
    (0..n as u32).collect()
}

/// The root of `x`'s set, halving the path on the way.
pub(crate) fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        parent[x as usize] = parent[parent[x as usize] as usize];
        x = parent[x as usize];
    }
    x
}

/// Joins the sets of `a` and `b` under `b`'s root; false when they were one set already.
pub(crate) fn union(parent: &mut [u32], a: u32, b: u32) -> bool {
    let (ra, rb) = (find(parent, a), find(parent, b));
    parent[ra as usize] = rb;
    ra != rb
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unions_join_sets_and_report_repeats() {
        let mut p = singletons(5);
        assert!(union(&mut p, 0, 1));
        assert!(union(&mut p, 3, 4));
        assert!(!union(&mut p, 1, 0));
        assert!(union(&mut p, 1, 4));
        let roots: Vec<u32> = (0..5).map(|x| find(&mut p, x)).collect();
        assert!(roots[0] == roots[3] && roots[0] == roots[4] && roots[2] == 2);
        assert_ne!(roots[0], roots[2]);
    }
}
