//! What every end-to-end test file uses: the binary, a scratch folder per test, and the
//! JSON printed.
#![allow(dead_code)] // each test file uses its own part

pub use std::path::{Path, PathBuf};
pub use std::process::{Command, Output};

pub fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tetrakit"))
}

/// This run's scratch directory: new and empty, so no earlier run's files (left by a
/// process that had the same id) can be in the way.
fn scratch() -> &'static std::path::Path {
    static DIR: std::sync::OnceLock<tempfile::TempDir> = std::sync::OnceLock::new();
    DIR.get_or_init(|| {
        tempfile::Builder::new()
            .prefix("tetrakit-cli-")
            .tempdir()
            .unwrap()
    })
    .path()
}

pub fn dir(name: &str) -> PathBuf {
    let d = scratch().join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

pub fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("binary runs")
}

pub fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

pub fn json(o: &Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout).expect("stdout is one JSON object")
}
