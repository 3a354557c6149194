//! The independent check of every tetrahedralization the solver returns: the domain's
//! certificate ([`Domain::certify`]), then the rules on edges (only allowed segments,
//! every required one).

use super::{Domain, Edges, Outcome};
use std::collections::HashSet;

impl Outcome {
    /// The tetrahedralizations this answer holds: the minimum or the one found, the
    /// alternative minimum, the best one found before a stop.
    pub fn tetrahedralizations(&self) -> Vec<&[[u32; 4]]> {
        match self {
            Outcome::Optimal {
                tets, alternative, ..
            } => std::iter::once(tets.as_slice())
                .chain(alternative.as_deref())
                .collect(),
            Outcome::Found { tets } => vec![tets],
            Outcome::Undecided { best, .. } => best.as_deref().into_iter().collect(),
            Outcome::Infeasible => Vec::new(),
        }
    }
}

/// The first reason `tets` is not a tetrahedralization of `domain` obeying `edges`.
pub(super) fn certify(domain: Domain, edges: Edges, tets: &[[u32; 4]]) -> Result<(), Uncertified> {
    domain.certify(tets).map_err(Uncertified::Problem)?;
    if edges.allowed.is_none() && edges.required.is_empty() {
        return Ok(());
    }
    let key = |[a, b]: [u32; 2]| [a.min(b), a.max(b)];
    let used: HashSet<[u32; 2]> = crate::mesh::edges_of(tets).into_iter().collect();
    if let Some(allowed) = edges.allowed {
        let allowed: HashSet<[u32; 2]> = allowed.iter().map(|&s| key(s)).collect();
        if let Some(&e) = used.iter().find(|e| !allowed.contains(*e)) {
            return Err(Uncertified::NotAllowed(e));
        }
    }
    match edges.required.iter().find(|&&s| !used.contains(&key(s))) {
        Some(&e) => Err(Uncertified::RequiredMissing(e)),
        None => Ok(()),
    }
}

/// Why the solver's tetrahedra failed their certificate (a bug if it ever happens).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Uncertified {
    /// They do not tetrahedralize the domain: the verifier's problem.
    Problem(crate::mesh::Problem),
    /// An edge is not an allowed segment.
    NotAllowed([u32; 2]),
    /// A required segment is not an edge.
    RequiredMissing([u32; 2]),
}

impl std::fmt::Display for Uncertified {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Uncertified::Problem(p) => p.fmt(f),
            Uncertified::NotAllowed([a, b]) => {
                write!(f, "edge (#{a}, #{b}) is not an allowed segment")
            }
            Uncertified::RequiredMissing([a, b]) => {
                write!(f, "required segment (#{a}, #{b}) is not an edge")
            }
        }
    }
}

impl std::error::Error for Uncertified {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Uncertified::Problem(p) => Some(p),
            _ => None,
        }
    }
}
