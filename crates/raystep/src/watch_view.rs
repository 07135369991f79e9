//! What `raystep watch` shows after each check: read from the report the
//! check wrote (`check --json`), the first exercise not passed with its
//! message, what passed, how to ask for a hint, or what is next.

use std::fmt::Write as _;

use serde::Deserialize;

use crate::progress::summary;

/// The parts of `check --json`'s report the view needs (the format is
/// `report_formats::json`).
#[derive(Debug, Deserialize)]
pub struct CheckReport {
    /// `ch01`.
    pub chapter: String,
    /// `ch01-implicit-lines-planes`.
    pub package: String,
    /// Everything passed.
    pub passed: bool,
    pub exercises: Vec<Exercise>,
    pub other_tests: OtherTests,
    pub changed_snapshots: Vec<Snapshot>,
}

/// One exercise's or paper question's verdict.
#[derive(Debug, Deserialize)]
pub struct Exercise {
    pub exercise: String,
    /// `code` or `paper`.
    pub kind: String,
    pub stars: Option<usize>,
    /// `passed`, `failed`, `not attempted`, …
    pub verdict: String,
    pub message: Option<String>,
}

/// The chapter's other tests.
#[derive(Debug, Deserialize)]
pub struct OtherTests {
    pub waiting: usize,
    pub failed: Vec<String>,
}

/// A snapshot file that is not the reference.
#[derive(Debug, Deserialize)]
pub struct Snapshot {
    pub path: String,
    pub change: String,
}

impl CheckReport {
    /// The report in `text`, or why it is not one.
    pub fn parse(text: &str) -> Result<CheckReport, String> {
        serde_json::from_str(text).map_err(|e| e.to_string())
    }
}

impl Exercise {
    fn paper(&self) -> bool {
        self.kind == "paper"
    }
}

/// The view of `report`: the chapter, the first exercise not passed and
/// its message, the counts, the hint command; or that the chapter passes
/// and `next` (the chapter to watch next, `None` if every chapter passes);
/// and the folder being `watched`.
pub fn view(report: &CheckReport, next: Option<&str>, watched: &str) -> String {
    let id = &report.chapter;
    let mut text = format!("{} (student mode)\n", report.package);
    let first = report.exercises.iter().find(|e| e.verdict != "passed");
    if let Some(exercise) = first {
        let what = if exercise.paper() {
            "paper question"
        } else {
            "exercise"
        };
        let stars = exercise
            .stars
            .map(|n| format!(" ({})", "★".repeat(n)))
            .unwrap_or_default();
        let _ = writeln!(
            text,
            "{what} {}{stars}: {}",
            exercise.exercise, exercise.verdict
        );
        for line in message(exercise).lines() {
            let _ = writeln!(text, "  {line}");
        }
    }
    let count = |paper: bool| {
        let of_kind = report.exercises.iter().filter(|e| e.paper() == paper);
        let passed = of_kind.clone().filter(|e| e.verdict == "passed");
        (passed.count(), of_kind.count())
    };
    let ((code, code_of), (paper, paper_of)) = (count(false), count(true));
    let _ = writeln!(text, "{}", summary(code, code_of, paper, paper_of));
    if let Some(exercise) = first {
        let _ =
            writeln!(text, "stuck? raystep hint {id} {}", exercise.exercise);
    } else if report.passed {
        match next {
            Some(next) => {
                let _ = writeln!(
                    text,
                    "all of {id} passes — next: raystep watch {next}"
                );
            }
            None => {
                let _ =
                    writeln!(text, "all of {id} passes — every chapter passes");
            }
        }
    } else {
        text.push_str(&why_not_passed(report));
    }
    let _ = writeln!(
        text,
        "watching {watched} — save a file to check again, Ctrl-C to quit"
    );
    text
}

/// What there is to say of an exercise not passed beyond its verdict.
fn message(exercise: &Exercise) -> String {
    match (&exercise.message, exercise.paper()) {
        (Some(message), _) => message.clone(),
        (None, false) => format!(
            "still todo!(): write it in exercise/{}.rs",
            exercise.exercise
        ),
        (None, true) => format!(
            "still \"todo\": write your answer for {} in exercise/answers.toml",
            exercise.exercise
        ),
    }
}

/// Every exercise passed, but the chapter does not: why.
fn why_not_passed(report: &CheckReport) -> String {
    let mut text = String::from("every exercise passes, but:\n");
    if let Some(first) = report.other_tests.failed.first() {
        let _ = writeln!(
            text,
            "  {} other tests failed (first: {first})",
            report.other_tests.failed.len()
        );
    }
    if report.other_tests.waiting > 0 {
        let _ = writeln!(
            text,
            "  {} other tests wait at a todo!()",
            report.other_tests.waiting
        );
    }
    for snapshot in &report.changed_snapshots {
        let _ = writeln!(
            text,
            "  {} ({}) is not the reference snapshot: `raystep check {}` \
             says how to restore it",
            snapshot.path, snapshot.change, report.chapter
        );
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    fn report(json: &str) -> CheckReport {
        CheckReport::parse(json).unwrap()
    }

    const FAILING: &str = r#"{
      "chapter": "ch01", "package": "ch01-lines", "mode": "student",
      "passed": false,
      "exercises": [
        {"exercise": "line", "kind": "code", "stars": 1,
         "verdict": "passed", "message": null},
        {"exercise": "plane", "kind": "code", "stars": 2,
         "verdict": "failed",
         "message": "normal (tests/plane.rs:4): assertion failed\nleft: 1"},
        {"exercise": "q1", "kind": "paper", "stars": 1,
         "verdict": "not attempted", "message": null}
      ],
      "other_tests": {"passed": 3, "waiting": 0, "failed": []},
      "build_failure": null,
      "changed_snapshots": []
    }"#;

    #[test]
    fn the_first_exercise_not_passed_is_shown_with_its_message() {
        assert_eq!(
            view(
                &report(FAILING),
                Some("ch02"),
                "chapters/ch01-lines/exercise/"
            ),
            "ch01-lines (student mode)\n\
             exercise plane (★★): failed\n\
             \x20 normal (tests/plane.rs:4): assertion failed\n\
             \x20 left: 1\n\
             1 of 2 exercises and 0 of 1 paper questions passed\n\
             stuck? raystep hint ch01 plane\n\
             watching chapters/ch01-lines/exercise/ — save a file to check \
             again, Ctrl-C to quit\n"
        );
    }

    #[test]
    fn an_untouched_stub_says_where_to_write() {
        let untouched = FAILING
            .replace("\"verdict\": \"failed\"", "\"verdict\": \"passed\"");
        let text = view(&report(&untouched), None, "x/");
        assert!(
            text.contains(
                "paper question q1 (★): not attempted\n  still \"todo\": \
                 write your answer for q1 in exercise/answers.toml\n\
                 2 of 2 exercises and 0 of 1 paper questions passed\n\
                 stuck? raystep hint ch01 q1\n"
            ),
            "{text}"
        );
    }

    #[test]
    fn a_chapter_that_passes_says_what_is_next() {
        let passing = r#"{
          "chapter": "ch01", "package": "ch01-lines", "mode": "student",
          "passed": true,
          "exercises": [{"exercise": "line", "kind": "code", "stars": null,
                         "verdict": "passed", "message": null}],
          "other_tests": {"passed": 3, "waiting": 0, "failed": []},
          "build_failure": null, "changed_snapshots": []
        }"#;
        assert_eq!(
            view(&report(passing), Some("ch02"), "x/"),
            "ch01-lines (student mode)\n\
             1 of 1 exercises passed\n\
             all of ch01 passes — next: raystep watch ch02\n\
             watching x/ — save a file to check again, Ctrl-C to quit\n"
        );
        assert!(
            view(&report(passing), None, "x/")
                .contains("all of ch01 passes — every chapter passes\n")
        );
        let snapshot = passing.replace("true", "false").replace(
            "\"changed_snapshots\": []",
            "\"changed_snapshots\": [{\"path\": \"tests/snapshots/a.snap\", \
             \"change\": \"changed\"}]",
        );
        assert!(view(&report(&snapshot), None, "x/").contains(
            "every exercise passes, but:\n  tests/snapshots/a.snap (changed) \
             is not the reference snapshot: `raystep check ch01` says how to \
             restore it\n"
        ));
    }

    #[test]
    fn a_file_that_is_not_a_report_is_an_error() {
        assert!(CheckReport::parse("{}").is_err());
    }
}
