//! Chapter 3: minimal tetrahedralizations of polyhedra.
//!
//! * [`Polyhedron`]: a simple polyhedron, validated exactly (closed, edge-manifold,
//!   orientable, genus 0, not self-intersecting) and oriented outward.
//! * [`SurfaceGraph`]: the graph G(P) of §3.2 (degrees, adjacency, tri(ab)).
//! * [`bp_nets`], [`is_proper`], [`are_disjoint`]: BP-nets of §3.3.1 (Theorem 3.4).
//! * [`mintetra`]: Algorithm MINTETRA of §3.4 for augmented and multi-level BP-polyhedra;
//!   [`solve_mintetra`], the capability: MINTETRA certified, with what it proves about
//!   minimality (optionally confirmed by the exact solver).
//! * [`certify_polyhedron`]: the independent check of a tetrahedralization of a
//!   polyhedron (from [`mesh`](crate::mesh)).
//! * [`generate`]: stacked polyhedra, bipyramids, BP-polyhedra, Schönhardt.
//! * [`hard`]: hard families for the exact solvers: Schönhardt towers, Chazelle's
//!   polyhedron, dented convex polyhedra.

mod bpnet;
pub mod generate;
mod graph;
pub mod hard;
mod mintetra;
mod outcome;
mod triangulated;

pub use crate::mesh::{Polyhedron, SurfaceError, certify_polyhedron};
pub use bpnet::{BpNet, are_disjoint, bp_nets, is_proper, proper_nets_disjoint};
pub use graph::SurfaceGraph;
pub use mintetra::{Checks, Mintetra, Seconds, minimality, mintetra, mintetra_certified};
pub use outcome::{Minimality, MintetraOptions, MintetraOutcome, MintetraWitness, solve_mintetra};
