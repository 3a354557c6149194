//! The committed JSON contract (`docs/schema/`) names every problem and witness kind the
//! library reports, in order.

use tetrakit::detect::WitnessKind;
use tetrakit::mesh::ProblemKind;

/// The `enum` of `kind` under `$defs/def` in `docs/schema/name.json`.
fn kinds(name: &str, def: &str) -> Vec<String> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../../docs/schema/{name}.json"));
    let text = std::fs::read_to_string(path).unwrap();
    let schema: serde_json::Value = serde_json::from_str(&text).unwrap();
    let list = schema["$defs"][def]["properties"]["kind"]["enum"]
        .as_array()
        .unwrap();
    list.iter()
        .map(|k| k.as_str().unwrap().to_string())
        .collect()
}

/// The names of `all`, as the library prints them.
fn names<T: std::fmt::Display>(all: &[T]) -> Vec<String> {
    all.iter().map(|k| k.to_string()).collect()
}

#[test]
fn every_schema_names_every_kind_in_order() {
    assert_eq!(kinds("check", "problem"), names(&ProblemKind::ALL));
    assert_eq!(kinds("detect", "witness"), names(&WitnessKind::ALL));
    let exact = names(&tetrakit::exact::WitnessKind::ALL);
    assert_eq!(kinds("tetrahedralize", "witness"), exact);
    let constrain = names(&tetrakit::constrain::WitnessKind::ALL);
    assert_eq!(kinds("constrain", "witness"), constrain);
}
