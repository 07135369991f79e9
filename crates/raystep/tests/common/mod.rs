//! What the command line's integration tests share: where the workspace and
//! the outer build's target folder are, scratch folders, and running the
//! `raystep` binary. (Each test file uses only some of these.)
#![allow(dead_code)]

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

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

/// A fresh, empty scratch folder for one test: `<tmp>/<group>/<name>`.
pub fn scratch(group: &str, name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(group)
        .join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the raystep binary with `args` and returns its output.
pub fn raystep(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(args)
        .output()
        .expect("raystep runs")
}

/// Runs `raystep <args>`, which must succeed (else the test fails with
/// its stderr); returns what it printed on stdout.
pub fn succeeds(args: &[&str]) -> String {
    let run = raystep(args);
    assert!(run.status.success(), "{args:?}: {}", text(&run.stderr));
    text(&run.stdout)
}

/// Runs `raystep <args>`, which must fail with one line on stderr;
/// returns that line.
pub fn fails_in_one_line(args: &[&str]) -> String {
    let run = raystep(args);
    let stderr = text(&run.stderr);
    assert!(!run.status.success(), "{args:?} was accepted");
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    stderr
}

/// What a program printed, as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The JSON document in the file at `path`.
pub fn read_json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&fs::read_to_string(path).unwrap()).unwrap()
}
