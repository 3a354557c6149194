//! The committed JSON contract names every problem kind the verifier reports, in order.

use tetrakit::mesh::ProblemKind;

#[test]
fn the_check_schema_names_every_problem_kind() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/schema/check.json");
    let schema: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let kinds: Vec<&str> = schema["$defs"]["problem"]["properties"]["kind"]["enum"]
        .as_array()
        .unwrap()
        .iter()
        .map(|k| k.as_str().unwrap())
        .collect();
    let ours: Vec<String> = ProblemKind::ALL.iter().map(|k| k.to_string()).collect();
    assert_eq!(kinds, ours);
}
