//! The inner vertices not yet on the current surface, each filed under the surface
//! triangle its ray from a fixed point `c` strictly inside `Q` crosses.
//!
//! Why a removal need only look under the triangles it takes: every surface is the
//! boundary of a convex `P̄ ⊇ Q`, so the ray from `c` through a hidden vertex `q` crosses
//! it exactly once, at a point `x` of the closed triangle `q` is filed under, with `q`
//! strictly between `c` and `x`. A removal keeps every triangle outside its region, so
//! if `q`'s triangle is not in the region, `x` stays on the new surface and `q`, before
//! it on the ray, stays strictly inside: only the vertices under the region can reach
//! the new surface. The others under the region are filed again under the bottom, which
//! covers the same rays (both are disks on the ring, on surfaces star-shaped from `c`).
//! Work is proportional to what is filed under the removed triangles, not to a box that a
//! long surface edge makes as wide as the shell (the thin twisted prisms of
//! BENCHMARKS.md).

use crate::geom::Point3;

/// Hidden inner vertices by the surface triangle above them.
#[derive(Clone)]
pub(super) struct Hidden {
    /// The centre of the rays: a point strictly inside `Q`.
    pub(super) centre: Point3,
    hidden: Vec<bool>,
    /// By surface triangle id: the vertices filed under it (some exposed since: they
    /// are dropped when read).
    under: Vec<Vec<u32>>,
    /// Vertices no walk or scan placed under a triangle (none, by the argument above;
    /// kept so that the candidates stay a superset even then): candidates everywhere.
    loose: Vec<u32>,
    count: usize,
}

impl Hidden {
    /// No vertex filed yet; `hidden` are marked hidden.
    pub(super) fn new(points: usize, hidden: &[u32], centre: Point3) -> Hidden {
        let mut h = vec![false; points];
        for &v in hidden {
            h[v as usize] = true;
        }
        Hidden {
            centre,
            hidden: h,
            under: Vec::new(),
            loose: Vec::new(),
            count: hidden.len(),
        }
    }

    /// True while `v` is a hidden inner vertex.
    pub(super) fn is_hidden(&self, v: u32) -> bool {
        self.hidden.get(v as usize).copied().unwrap_or(false)
    }

    /// `v` is on the surface now.
    pub(super) fn expose(&mut self, v: u32) {
        if self.is_hidden(v) {
            self.hidden[v as usize] = false;
            self.count -= 1;
        }
    }

    /// Files `v` under triangle `t` (`None`: under every triangle).
    pub(super) fn file(&mut self, v: u32, t: Option<u32>) {
        let Some(t) = t else {
            self.loose.push(v);
            return;
        };
        let t = t as usize;
        if self.under.len() <= t {
            self.under.resize_with(t + 1, Vec::new);
        }
        self.under[t].push(v);
    }

    /// The hidden vertices filed under the triangles `region` (and the loose ones).
    pub(super) fn under(&self, region: &[u32]) -> Vec<u32> {
        region
            .iter()
            .filter_map(|&t| self.under.get(t as usize))
            .flatten()
            .chain(&self.loose)
            .copied()
            .filter(|&v| self.is_hidden(v))
            .collect()
    }

    /// Takes the hidden vertices filed under the triangles `region` (removed).
    pub(super) fn take(&mut self, region: &[u32]) -> Vec<u32> {
        let mut out = Vec::new();
        for &t in region {
            if let Some(list) = self.under.get_mut(t as usize) {
                out.append(list);
            }
        }
        out.retain(|&v| self.is_hidden(v));
        out
    }

    /// How many inner vertices are still hidden.
    pub(super) fn count(&self) -> usize {
        self.count
    }
}
