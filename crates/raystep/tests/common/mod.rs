//! What the command line's integration tests share: where the workspace and
//! the outer build's target folder are.

use std::path::{Path, PathBuf};

/// The workspace this test was built from.
pub fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap()
}

/// The outer build's target folder: `CARGO_TARGET_TMPDIR` is `<target>/tmp`.
pub fn outer_target() -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR"))
        .parent()
        .expect("CARGO_TARGET_TMPDIR is <target>/tmp")
        .to_path_buf()
}
