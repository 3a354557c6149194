//! What several integration test files use.
#![allow(dead_code)] // each test file uses its own part

/// This run's scratch directory: new and empty, so no earlier run's files (left by a
/// process that had the same id) can be in the way.
pub fn scratch() -> &'static std::path::Path {
    static DIR: std::sync::OnceLock<tempfile::TempDir> = std::sync::OnceLock::new();
    DIR.get_or_init(|| {
        tempfile::Builder::new()
            .prefix("tetrakit-")
            .tempdir()
            .unwrap()
    })
    .path()
}
