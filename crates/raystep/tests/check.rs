//! `raystep check` on the real chapters: the reference solution passes every
//! exercise, and the untouched stubs pass none.
//!
//! This runs cargo from inside `cargo test`, twice per chapter (with and
//! without the `exercise` feature). The nested cargo shares the outer target
//! folder (`RAYSTEP_CHECK_TARGET_DIR` = the parent of `CARGO_TARGET_TMPDIR`),
//! so it reuses every compiled dependency and rebuilds only the chapter: cargo
//! releases its build lock before it runs test binaries, so nothing blocks.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The outer build's target folder: `CARGO_TARGET_TMPDIR` is `<target>/tmp`.
fn outer_target() -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR"))
        .parent()
        .expect("CARGO_TARGET_TMPDIR is <target>/tmp")
        .to_path_buf()
}

/// (chapter id, exercises) for every `chapters/chNN-*` folder.
fn chapters() -> Vec<(String, Vec<String>)> {
    let mut chapters: Vec<(String, Vec<String>)> = fs::read_dir(workspace().join("chapters"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("Cargo.toml").is_file())
        .map(|dir| {
            let name = dir.file_name().unwrap().to_str().unwrap().to_string();
            let id = name.split('-').next().unwrap().to_string();
            let mut exercises: Vec<String> = fs::read_dir(dir.join("exercise"))
                .map(|entries| {
                    entries
                        .map(|e| e.unwrap().path())
                        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
                        .map(|p| p.file_stem().unwrap().to_str().unwrap().to_string())
                        .collect()
                })
                .unwrap_or_default();
            exercises.sort();
            (id, exercises)
        })
        .collect();
    chapters.sort();
    chapters
}

/// Runs `raystep check <args>`: (success, stdout, stderr).
fn check(args: &[&str]) -> (bool, String, String) {
    let started = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .arg("check")
        .args(args)
        .arg("--quiet")
        .current_dir(workspace())
        .env("RAYSTEP_CHECK_TARGET_DIR", outer_target())
        .output()
        .expect("raystep runs");
    eprintln!(
        "raystep check {} took {:.1?}",
        args.join(" "),
        started.elapsed()
    );
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The verdict printed for `exercise`: the text after its name.
fn verdict<'a>(report: &'a str, stderr: &str, exercise: &str) -> &'a str {
    report
        .lines()
        .find_map(|line| {
            let rest = line.strip_prefix("  ")?.strip_prefix(exercise)?;
            rest.starts_with(' ').then(|| rest.trim())
        })
        .unwrap_or_else(|| panic!("no line for exercise {exercise} in:\n{report}{stderr}"))
}

#[test]
fn the_reference_passes_and_the_stubs_do_not() {
    for (chapter, exercises) in chapters() {
        let (ok, report, stderr) = check(&[&chapter, "--reference"]);
        for exercise in &exercises {
            assert_eq!(
                verdict(&report, &stderr, exercise),
                "passed",
                "{chapter} reference:\n{report}{stderr}"
            );
        }
        assert!(
            report.contains("other tests") && report.contains(" 0 failed"),
            "{report}"
        );
        assert!(ok, "{chapter} --reference failed:\n{report}{stderr}");

        let (ok, report, stderr) = check(&[&chapter]);
        for exercise in &exercises {
            let verdict = verdict(&report, &stderr, exercise);
            assert!(
                verdict == "not attempted" || verdict.starts_with("failed: "),
                "{chapter}: the stub of {exercise} is {verdict:?}:\n{report}{stderr}"
            );
        }
        assert_eq!(
            ok,
            exercises.is_empty(),
            "{chapter} student mode:\n{report}{stderr}"
        );
    }
}
