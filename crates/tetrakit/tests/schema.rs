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

#[test]
fn the_check_schema_names_every_problem_kind() {
    let ours: Vec<String> = ProblemKind::ALL.iter().map(|k| k.to_string()).collect();
    assert_eq!(kinds("check", "problem"), ours);
}

#[test]
fn the_detect_schema_names_every_witness_kind() {
    let ours: Vec<String> = WitnessKind::ALL.iter().map(|k| k.to_string()).collect();
    assert_eq!(kinds("detect", "witness"), ours);
}

#[test]
fn the_tetrahedralize_schema_names_every_witness_kind() {
    let ours: Vec<String> = tetrakit::exact::WitnessKind::ALL
        .iter()
        .map(|k| k.to_string())
        .collect();
    assert_eq!(kinds("tetrahedralize", "witness"), ours);
}

#[test]
fn the_constrain_schema_names_every_witness_kind() {
    let ours: Vec<String> = tetrakit::constrain::WitnessKind::ALL
        .iter()
        .map(|k| k.to_string())
        .collect();
    assert_eq!(kinds("constrain", "witness"), ours);
}
