//! `raystep check` end to end: on the real chapters the reference solution
//! passes every exercise and the untouched stubs pass none, whatever the
//! user's cargo settings.
//!
//! This runs cargo from inside `cargo test`. For the real chapters the nested
//! cargo shares the outer target folder (`RAYSTEP_CHECK_TARGET_DIR` = the
//! parent of `CARGO_TARGET_TMPDIR`), so it reuses every compiled dependency
//! and rebuilds only the chapter; `raystep check` runs the test binaries
//! after cargo has finished (and released its build lock).

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

/// Runs `raystep check <args> --quiet` in the workspace, building in the
/// outer target folder: (success, stdout, stderr).
fn check(args: &[&str]) -> (bool, String, String) {
    raystep(args, &workspace(), |command| {
        command.env("RAYSTEP_CHECK_TARGET_DIR", outer_target());
    })
}

/// Runs `raystep check <args> --quiet` in `dir`, its environment adjusted by
/// `configure`: (success, stdout, stderr).
fn raystep(
    args: &[&str],
    dir: &Path,
    configure: impl FnOnce(&mut Command),
) -> (bool, String, String) {
    let started = Instant::now();
    let mut command = Command::new(env!("CARGO_BIN_EXE_raystep"));
    command
        .arg("check")
        .args(args)
        .arg("--quiet")
        .current_dir(dir);
    configure(&mut command);
    let out = command.output().expect("raystep runs");
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

/// Cargo settings that change what cargo prints (no `Running` lines, coloured
/// or verbose output) do not change a verdict.
#[test]
fn verdicts_do_not_depend_on_cargo_settings() {
    const SETTINGS: [(&str, &str); 4] = [
        ("CARGO_TERM_QUIET", "true"),
        ("CARGO_TERM_COLOR", "always"),
        ("CARGO_TERM_VERBOSE", "true"),
        ("CARGO_BUILD_JOBS", "1"),
    ];
    let (ok, plain, stderr) = raystep(&["ch01"], &workspace(), |command| {
        for (name, _) in SETTINGS {
            command.env_remove(name);
        }
        command.env("RAYSTEP_CHECK_TARGET_DIR", outer_target());
    });
    assert!(!ok, "{plain}{stderr}");
    for exercise in ["line_through_points", "plane_through_points"] {
        assert_eq!(
            verdict(&plain, &stderr, exercise),
            "not attempted",
            "{plain}{stderr}"
        );
    }

    let (ok, configured, stderr) = raystep(&["ch01"], &workspace(), |command| {
        command
            .envs(SETTINGS)
            .env("CARGO_TARGET_DIR", outer_target())
            .env_remove("RAYSTEP_CHECK_TARGET_DIR");
    });
    assert!(!ok, "{configured}{stderr}");
    assert_eq!(configured, plain, "with {SETTINGS:?}:\n{stderr}");
}
