//! The report layer: the one place where a capability's certified outcome becomes the
//! JSON contract (`--json`, and the fields of Python's results) and the text a person
//! reads, for the CLI and the Python package alike (as ripgrep's printer serves every
//! search). A front end parses its input, calls the capability, and hands the outcome
//! here with the few facts only it knows (timings, the file's other cells).
//!
//! Capabilities move here one by one (`check`, `detect`, `flips`, `shell`, `mintetra`, `tetrahedralize`, `contains`, `constrained`, `reduce`, `skeleton`, `mwt` and `keil`); until then a command
//! builds its JSON itself.

mod check;
mod constrain;
mod detect;
mod flips;
mod keil_picture;
mod planar;
mod poly;
mod reduce;
mod shell;

pub use check::{MeshFacts, check_printed, mesh_facts, problem_pieces};
pub use constrain::{constrain_json, constrain_text};
pub use detect::{detect_json, detect_text};
pub use flips::{flip_count_text, flip_graph_json, flips_text};
pub use keil_picture::keil_svg;
pub use planar::{
    check_random_json, check_random_text, keil_json, keil_text, mwt_json, mwt_text, skeleton_json,
    skeleton_text,
};
pub use poly::{ProofFiles, hamiltonian_text, mintetra_text, tetrahedralize_text};
pub use reduce::{hull_gap_text, quasi_prism_text, reduction_text};
pub use shell::shell_text;

pub use serde::Serialize;
use serde_json::{Map, Value};

/// An outcome's JSON object, with `extra` fields (timings, file facts) added after the
/// outcome's own.
///
/// ```
/// use tetrakit::mesh::{CheckOptions, check};
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let o = check(&pts, vec![[0, 1, 2, 3]], CheckOptions::default());
/// let v = tetrakit::report::json(&o, [("seconds", 0.5.into())]);
/// assert_eq!((v["verdict"].as_str(), v["tetrahedra"].as_u64()), (Some("yes"), Some(1)));
/// assert_eq!(v["seconds"], 0.5);
/// ```
pub fn json<'a, T: Serialize>(
    outcome: &T,
    extra: impl IntoIterator<Item = (&'a str, Value)>,
) -> Value {
    let mut object = match serde_json::to_value(outcome) {
        Ok(Value::Object(m)) => m,
        Ok(other) => Map::from_iter([("outcome".to_string(), other)]),
        Err(e) => Map::from_iter([("error".to_string(), Value::from(e.to_string()))]),
    };
    for (k, v) in extra {
        object.insert(k.to_string(), v);
    }
    Value::Object(object)
}
