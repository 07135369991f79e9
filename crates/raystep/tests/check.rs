//! `raystep check` end to end: on the real chapters the reference solution
//! passes every exercise and the untouched stubs pass none, whatever the
//! user's cargo settings; on a throwaway chapter an endless loop times out.
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

mod common;
mod one_chapter;
use common::{outer_target, workspace};

/// (chapter id, exercises) for every `chapters/chNN-*` folder.
fn chapters() -> Vec<(String, Vec<String>)> {
    let mut chapters: Vec<(String, Vec<String>)> =
        fs::read_dir(workspace().join("chapters"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.join("Cargo.toml").is_file())
            .map(|dir| {
                let name =
                    dir.file_name().unwrap().to_str().unwrap().to_string();
                let id = name.split('-').next().unwrap().to_string();
                let mut exercises: Vec<String> =
                    fs::read_dir(dir.join("exercise"))
                        .map(|entries| {
                            entries
                                .map(|e| e.unwrap().path())
                                .filter(|p| {
                                    p.extension().is_some_and(|x| x == "rs")
                                })
                                .map(|p| {
                                    p.file_stem()
                                        .unwrap()
                                        .to_str()
                                        .unwrap()
                                        .to_string()
                                })
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
    args: &[&str], dir: &Path, configure: impl FnOnce(&mut Command),
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

/// The verdict printed for `exercise`: the text after its name (and
/// its difficulty).
fn verdict<'a>(report: &'a str, stderr: &str, exercise: &str) -> &'a str {
    report
        .lines()
        .find_map(|line| {
            let rest = line.strip_prefix("  ")?.strip_prefix(exercise)?;
            let rest = rest.strip_prefix(" (paper)").unwrap_or(rest);
            rest.starts_with(' ')
                .then(|| rest.trim().trim_start_matches('★').trim_start())
        })
        .unwrap_or_else(|| {
            panic!("no line for exercise {exercise} in:\n{report}{stderr}")
        })
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
            report.contains("other tests") && !report.contains("failed"),
            "{report}"
        );
        assert!(ok, "{chapter} --reference failed:\n{report}{stderr}");
        // Every chapter with exercises asks two paper questions or more:
        // the reference answers pass, the untouched stub attempts none.
        let questions = ["q1", "q2"];
        if !exercises.is_empty() {
            for q in questions {
                assert_eq!(verdict(&report, &stderr, q), "passed", "{report}");
            }
        }

        let (ok, report, stderr) = check(&[&chapter]);
        for exercise in &exercises {
            let verdict = verdict(&report, &stderr, exercise);
            assert!(
                verdict == "not attempted" || verdict.starts_with("failed: "),
                "{chapter}: the stub of {exercise} is {verdict:?}:\n{report}{stderr}"
            );
        }
        if !exercises.is_empty() {
            for q in questions {
                let verdict = verdict(&report, &stderr, q);
                assert_eq!(verdict, "not attempted", "{chapter}:\n{report}");
            }
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

    let (ok, configured, stderr) =
        raystep(&["ch01"], &workspace(), |command| {
            command
                .envs(SETTINGS)
                .env("CARGO_TARGET_DIR", outer_target())
                .env_remove("RAYSTEP_CHECK_TARGET_DIR");
        });
    assert!(!ok, "{configured}{stderr}");
    assert_eq!(configured, plain, "with {SETTINGS:?}:\n{stderr}");
}

/// The throwaway chapter where the stub of `line_through_points` loops
/// forever and the one of `plane_through_points` is right.
fn looping_workspace() -> PathBuf {
    one_chapter::with_stubs(
        "check-timeout",
        one_chapter::LOOPING_SLOPE,
        one_chapter::RIGHT_NORMAL,
    )
}

/// Runs `raystep check ch01` in the throwaway workspace `root` with
/// `args`: (success, report, stderr).
fn check_throwaway(root: &Path, args: &[&str]) -> (bool, String, String) {
    let target = root.join("target");
    let mut all = vec!["ch01", "--target-dir", target.to_str().unwrap()];
    all.extend(args);
    raystep(&all, root, |_| {})
}

/// A test that asks for memory without end (a walk that never ends while
/// it records every visit) is stopped at `--memory`, and one that prints
/// without end at `--output`; each fails its exercise, naming the limit
/// and the test, and the machine is none the worse.
#[test]
fn memory_and_output_floods_are_stopped_at_their_limits() {
    let root = one_chapter::with_stubs(
        "check-limits",
        "pub fn slope(p0: (f64, f64), p1: (f64, f64)) -> f64 {\n\
         \x20   let mut visits = Vec::new();\n\
         \x20   loop {\n\
         \x20       visits.push((p0, p1));\n\
         \x20   }\n\
         }\n",
        "pub fn normal_z(a: (f64, f64), b: (f64, f64)) -> f64 {\n\
         \x20   use std::io::Write as _;\n\
         \x20   let mut out = std::io::stdout();\n\
         \x20   loop {\n\
         \x20       let _ = writeln!(out, \"{a:?} {b:?}: a flood of output\");\n\
         \x20   }\n\
         }\n",
    );
    // The defaults: 2 GiB and 8 MiB.
    let (ok, report, stderr) = check_throwaway(&root, &[]);
    assert_eq!(
        verdict(&report, &stderr, "line_through_points"),
        "failed: out of memory (limit 2 GiB, --memory) while running \
         slope_of_a_diagonal",
        "{report}{stderr}"
    );
    assert_eq!(
        verdict(&report, &stderr, "plane_through_points"),
        "failed: printed more than 8 MiB (limit, --output) while running \
         normal_of_the_xy_plane",
        "{report}{stderr}"
    );
    assert!(!ok, "{report}{stderr}");
    // Limits of one's own.
    let (_, report, stderr) =
        check_throwaway(&root, &["--memory", "512MiB", "--output", "64KiB"]);
    assert!(
        verdict(&report, &stderr, "line_through_points")
            .starts_with("failed: out of memory (limit 512 MiB, --memory)"),
        "{report}{stderr}"
    );
    assert!(
        verdict(&report, &stderr, "plane_through_points")
            .starts_with("failed: printed more than 64 KiB (limit, --output)"),
        "{report}{stderr}"
    );
}

/// A test whose code starts a process and returns leaves nothing running:
/// the process dies with its test binary's process group (and the file,
/// which reaches the operating system, is refused).
#[cfg(target_os = "linux")]
#[test]
fn nothing_a_test_started_outlives_the_check() {
    // A sleep no other process runs: 4000.25 s.
    let marker = "4000.25";
    let root = one_chapter::with_stubs(
        "check-forks",
        &format!(
            "pub fn slope(p0: (f64, f64), p1: (f64, f64)) -> f64 {{\n\
             \x20   let _ = std::process::Command::new(\"sleep\").arg(\"{marker}\").spawn();\n\
             \x20   (p1.1 - p0.1) / (p1.0 - p0.0)\n\
             }}\n"
        ),
        one_chapter::RIGHT_NORMAL,
    );
    let (_, report, stderr) = check_throwaway(&root, &[]);
    assert!(
        verdict(&report, &stderr, "line_through_points")
            .starts_with("refused: exercise/line_through_points.rs:2:"),
        "{report}{stderr}"
    );
    let sleeping: Vec<String> = fs::read_dir("/proc")
        .unwrap()
        .flatten()
        .filter_map(|entry| fs::read(entry.path().join("cmdline")).ok())
        .map(|cmdline| String::from_utf8_lossy(&cmdline).replace('\0', " "))
        .filter(|cmdline| cmdline.contains(marker))
        .collect();
    assert!(sleeping.is_empty(), "still running: {sleeping:?}");
}

/// An endless loop in a stub is stopped at `--timeout` and named; the other
/// exercise is still judged.
#[test]
fn an_endless_loop_times_out() {
    let root = looping_workspace();
    let target = root.join("target");
    let (ok, report, stderr) = raystep(
        &[
            "ch01",
            "--timeout",
            "3",
            "--target-dir",
            target.to_str().unwrap(),
        ],
        &root,
        |_| {},
    );
    assert_eq!(
        verdict(&report, &stderr, "line_through_points"),
        "timed out after 3 s (still running: slope_of_a_diagonal)",
        "{report}{stderr}"
    );
    assert_eq!(
        verdict(&report, &stderr, "plane_through_points"),
        "passed",
        "{report}{stderr}"
    );
    assert!(
        report.lines().any(
            |l| l.starts_with("  other tests ") && l.ends_with(" 1 passed")
        ),
        "{report}"
    );
    assert!(
        !ok,
        "a timed-out exercise must fail the check:\n{report}{stderr}"
    );
}
