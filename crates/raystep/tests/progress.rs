//! `raystep progress` end to end: it shows what `raystep check` recorded
//! (student mode only), in a throwaway one-chapter workspace.

use std::fs;
use std::path::Path;
use std::process::Command;

mod common;
mod one_chapter;
use common::text;

/// Runs `raystep <args>` in `root`, building in its own target folder:
/// (success, stdout, stderr).
fn raystep(root: &Path, args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(args)
        .current_dir(root)
        .env("RAYSTEP_CHECK_TARGET_DIR", root.join("target"))
        .output()
        .expect("raystep runs");
    (out.status.success(), text(&out.stdout), text(&out.stderr))
}

/// The table's row for `exercise`, its columns one space apart.
fn row(progress: &str, exercise: &str) -> String {
    progress
        .lines()
        .find(|l| {
            l.strip_prefix("  ")
                .is_some_and(|l| l.starts_with(&format!("{exercise} ")))
        })
        .unwrap_or_else(|| panic!("no row for {exercise}:\n{progress}"))
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn progress_shows_what_check_recorded() {
    let root =
        one_chapter::workspace("progress-record", one_chapter::WRONG_SLOPE);

    let (ok, before, stderr) = raystep(&root, &["progress"]);
    assert!(ok, "{stderr}");
    assert!(before.starts_with("nothing checked yet: "), "{before}");
    assert!(
        before.contains(
            " records each verdict\n\nch01 Implicit lines and planes\n"
        ),
        "{before}"
    );
    assert_eq!(
        row(&before, "line_through_points"),
        "line_through_points ★ not checked"
    );
    assert!(
        before.contains("\n  0 of 2 exercises passed, not checked yet\n")
            && before.ends_with(
                "next: raystep watch ch01 (exercise line_through_points)\n"
            ),
        "{before}"
    );

    let (ok, report, stderr) = raystep(&root, &["check", "ch01", "--quiet"]);
    assert!(
        !ok && report.contains("1 of 2 exercises passed"),
        "{report}{stderr}"
    );
    let (ok, after, stderr) = raystep(&root, &["progress"]);
    assert!(ok, "{stderr}");
    assert!(
        row(&after, "line_through_points").starts_with(
            "line_through_points ★ failed: slope_of_a_diagonal \
             (tests/line_through_points.rs:"
        ),
        "{after}"
    );
    assert_eq!(
        row(&after, "plane_through_points"),
        "plane_through_points ★ passed"
    );
    let counts = after
        .lines()
        .find(|l| l.starts_with("  1 of 2 exercises passed, checked "))
        .unwrap_or_else(|| panic!("{after}"));
    assert!(counts.ends_with(" UTC"), "{counts}");
    // The other chapters of the lecture are there, not checked.
    assert!(after.contains("\nch02 Plane and polygon hits\n"), "{after}");
    assert!(after.contains("\noverall: 1 of "), "{after}");
    assert!(
        after.ends_with(
            "next: raystep watch ch01 (exercise line_through_points)\n"
        ),
        "{after}"
    );

    // The reference is not the student's work: nothing is recorded.
    let recorded = fs::read(root.join(".raystep/progress.json")).unwrap();
    let (ok, _, stderr) =
        raystep(&root, &["check", "ch01", "--quiet", "--reference"]);
    assert!(ok, "{stderr}");
    assert_eq!(
        fs::read(root.join(".raystep/progress.json")).unwrap(),
        recorded
    );

    // A file that is not a progress file is named; nothing counts.
    fs::write(root.join(".raystep/progress.json"), "{\"chapters\": [").unwrap();
    let (ok, broken, stderr) = raystep(&root, &["progress"]);
    assert!(ok, "{stderr}");
    let first = broken.lines().next().unwrap();
    assert!(
        first.starts_with(".raystep/progress.json: not a progress file (")
            && first.ends_with("; showing every exercise as not checked"),
        "{broken}"
    );
    assert_eq!(
        row(&broken, "plane_through_points"),
        "plane_through_points ★ not checked"
    );
}
