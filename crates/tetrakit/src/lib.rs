//! # tetrakit
//!
//! Exact algorithms for tetrahedralization problems, after the thesis *Studies of several
//! tetrahedralization problems* (B. Yang): deciding whether a set of segments is exactly
//! the edge set of a tetrahedralization (ch. 2), validating tetrahedral meshes, minimal
//! tetrahedralizations of polyhedra (ch. 3: [`polyhedra`] for MINTETRA on BP-polyhedra,
//! [`exact`] for an exact SAT-based minimum of any polyhedron or point set), and
//! generating test instances.
//!
//! Data flows one way: [`io`] → [`geom`] / [`mesh`] → algorithm ([`detect`],
//! [`polyhedra`], [`exact`]) →
//! [`mesh::verify`] → [`io`]. Every geometric decision is exact ([`geom`]); every
//! tetrahedralization returned has passed [`mesh::verify`].
//!
//! ```
//! use tetrakit::control::Control;
//! use tetrakit::detect::{Options, detect};
//! use tetrakit::generate;
//! let mesh = generate::kuhn(2);
//! let edges = mesh.edges();
//! let outcome = detect(&mesh.points, &edges, &Options::default(), &Control::new()).unwrap();
//! assert!(outcome.is_yes());
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bug;
pub mod constrain;
pub mod control;
pub mod detect;
pub mod distributed;
pub mod dualpath;
pub mod exact;
pub mod flip;
pub mod flipgraph;
pub mod generate;
pub mod geom;
pub mod io;
pub mod mesh;
pub mod numbering;
pub mod params;
mod partition;
pub mod planar;
pub mod polyhedra;
pub mod reduce;
pub mod report;
pub mod rng;
mod rows;
pub mod shell;
pub mod witness;
