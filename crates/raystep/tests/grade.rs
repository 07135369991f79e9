//! `raystep grade` end to end on chapter 1 (the smallest): five fake
//! submissions, each gets its verdicts, and the instructor's workspace is
//! left as it was.
//!
//! The nested cargo builds in the outer target folder (as
//! `tests/check.rs` does), so only the scratch copy's own crates compile.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

mod common;
use common::{outer_target, workspace};

const CHAPTER: &str = "chapters/ch01-implicit-lines-planes";

/// The reference module `src/<exercise>.rs` of chapter 1.
fn reference(exercise: &str) -> String {
    fs::read_to_string(workspace().join(format!("{CHAPTER}/src/{exercise}.rs")))
        .unwrap()
}

/// `text` with `from` replaced by `to` once; `from` must be in it. (Short
/// fragments, never a whole line of the reference: `tests/student_edition.rs`
/// looks for those in the student edition, which holds this file.)
fn edited(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from:?} is not in the reference");
    text.replacen(from, to, 1)
}

/// Writes `files` (relative path → text) into `dir`.
fn write_all(dir: &Path, files: &[(&str, String)]) {
    for (path, text) in files {
        let path = dir.join(path);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, text).unwrap();
    }
}

/// The text of every file below `dir`, by path.
fn snapshot_of(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut files = BTreeMap::new();
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files.extend(snapshot_of(&path));
        } else {
            files.insert(path.clone(), fs::read(&path).unwrap());
        }
    }
    files
}

#[test]
fn each_submission_gets_its_verdicts() {
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("grade");
    if root.exists() {
        fs::remove_dir_all(&root).unwrap();
    }
    let submissions = root.join("submissions");
    let line = reference("line_through_points");
    let plane = reference("plane_through_points");
    // right: the reference bodies, one in exercise/, one beside it.
    write_all(
        &submissions.join("right"),
        &[
            ("exercise/line_through_points.rs", line.clone()),
            ("plane_through_points.rs", plane.clone()),
        ],
    );
    // wrong: the line's constant c with its minus sign dropped.
    write_all(
        &submissions.join("wrong"),
        &[
            (
                "exercise/line_through_points.rs",
                edited(&line, "c = -normal", "c = normal"),
            ),
            ("exercise/plane_through_points.rs", plane.clone()),
            ("notes.txt", "my notes".to_string()),
        ],
    );
    // looping: the line's eval never returns.
    write_all(
        &submissions.join("looping"),
        &[
            (
                "exercise/line_through_points.rs",
                edited(&line, "+ self.c", "+ { let c: f64 = loop {}; c }"),
            ),
            ("exercise/plane_through_points.rs", plane.clone()),
        ],
    );
    // missing: only the plane.
    write_all(
        &submissions.join("missing"),
        &[("exercise/plane_through_points.rs", plane.clone())],
    );
    // broken: the line's file does not compile.
    write_all(
        &submissions.join("broken"),
        &[
            (
                "exercise/line_through_points.rs",
                edited(&line, "(-v.y, v.x)", "(-v.y, v.x, 0)"),
            ),
            ("exercise/plane_through_points.rs", plane.clone()),
        ],
    );

    let instructor = workspace().join(CHAPTER);
    let before = (
        snapshot_of(&instructor.join("exercise")),
        snapshot_of(&instructor.join("tests")),
    );
    let csv = root.join("grades.csv");
    let json = root.join("grades.json");
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(["grade", submissions.to_str().unwrap(), "--chapter", "ch01"])
        .args(["--out", csv.to_str().unwrap()])
        .args(["--json", json.to_str().unwrap()])
        .args(["--timeout", "5"])
        .args(["--target-dir", outer_target().to_str().unwrap()])
        .current_dir(workspace())
        .output()
        .expect("raystep runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stdout}{stderr}");

    let table: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(&json).unwrap()).unwrap();
    let rows = table["rows"].as_array().unwrap();
    let verdict = |student: &str, exercise: &str| -> (String, String) {
        let row = rows
            .iter()
            .find(|r| r["student"] == student && r["exercise"] == exercise)
            .unwrap_or_else(|| {
                panic!("no row {student} {exercise}:\n{table:#}")
            });
        (
            row["verdict"].as_str().unwrap().to_string(),
            row["message"].as_str().unwrap().to_string(),
        )
    };
    let context = format!("{table:#}\n{stdout}{stderr}");
    let plane = "plane_through_points";
    let line = "line_through_points";
    for student in ["right", "wrong", "looping", "missing", "broken"] {
        assert_eq!(verdict(student, plane).0, "passed", "{student}: {context}");
    }
    assert_eq!(verdict("right", line).0, "passed", "{context}");

    let (kind, message) = verdict("wrong", line);
    assert_eq!(kind, "failed", "{context}");
    assert!(
        message.contains("(tests/line_through_points.rs:"),
        "the failing test's location: {context}"
    );

    let (kind, message) = verdict("looping", line);
    assert_eq!(kind, "timed out", "{context}");
    assert!(message.starts_with("timed out after 5 s"), "{context}");

    let (kind, message) = verdict("missing", line);
    assert_eq!(kind, "missing file", "{context}");
    assert_eq!(
        message, "no exercise/line_through_points.rs (the stub was used)",
        "{context}"
    );

    let (kind, message) = verdict("broken", line);
    assert_eq!(kind, "does not compile", "{context}");
    assert!(
        message.contains("(at exercise/line_through_points.rs:"),
        "{context}"
    );

    // Students in name order, two rows each; the CSV holds the same table.
    let students: Vec<&str> = rows
        .iter()
        .map(|r| r["student"].as_str().unwrap())
        .collect();
    assert_eq!(
        students,
        [
            "broken", "broken", "looping", "looping", "missing", "missing",
            "right", "right", "wrong", "wrong"
        ]
    );
    let csv_text = fs::read_to_string(&csv).unwrap();
    assert!(csv_text.starts_with("student,exercise,verdict,message\n"));
    assert_eq!(csv_text.lines().count(), 11, "{csv_text}");
    assert_eq!(
        table["ignored"],
        serde_json::json!([{"student": "wrong", "file": "notes.txt"}])
    );
    assert!(stdout.contains("ignored: wrong/notes.txt"), "{stdout}");

    // The instructor's exercise stubs and snapshots are untouched.
    let after = (
        snapshot_of(&instructor.join("exercise")),
        snapshot_of(&instructor.join("tests")),
    );
    assert!(before == after, "grade changed the instructor's chapter");
}

/// A folder that does not exist is an error naming it.
#[test]
fn a_missing_submissions_folder_is_named() {
    let missing = Path::new(env!("CARGO_TARGET_TMPDIR")).join("no-such-folder");
    let out = Command::new(env!("CARGO_BIN_EXE_raystep"))
        .args(["grade", missing.to_str().unwrap(), "--chapter", "ch01"])
        .current_dir(workspace())
        .output()
        .expect("raystep runs");
    assert!(!out.status.success());
    // The path as the user would type it: relative to the current folder.
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.starts_with("error: ")
            && stderr.trim_end().ends_with(
                "tmp/no-such-folder: not a folder of submissions (one folder \
                 per student)"
            ),
        "{stderr}"
    );
    assert!(!workspace().join("grades.csv").exists());
}
