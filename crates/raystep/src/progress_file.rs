//! The student's progress: the last verdict `raystep check` gave each
//! exercise and paper question, kept in `.raystep/progress.json` at the
//! workspace root (ignored by git, left out of the student edition and of
//! `grade`'s scratch copies). `raystep progress` shows it; `raystep watch`
//! starts from the first chapter it says is not done.
//!
//! Only `check` in student mode writes it, after each check, whole (a
//! temporary file renamed over it); a chapter checked again replaces that
//! chapter's entries.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use raystep_check::verdicts::Report;
use serde::{Deserialize, Serialize};

use crate::atomic_file;
use crate::error::Error;
use crate::shown_path::shown;

/// The folder, at the workspace root.
pub const FOLDER: &str = ".raystep";

/// The file, in [`FOLDER`].
pub const FILE: &str = "progress.json";

/// Every chapter checked so far, by id (`ch01`).
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Progress {
    pub chapters: BTreeMap<String, ChapterProgress>,
}

/// One chapter's last check.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChapterProgress {
    /// When, in seconds since 1970 (UTC).
    pub checked: u64,
    /// Each exercise, then each paper question, as `check` listed them.
    pub exercises: Vec<Entry>,
}

/// One exercise's or paper question's verdict.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    /// `line_through_points`, `q1`.
    pub exercise: String,
    /// `code` or `paper`, as in `check --json`.
    pub kind: String,
    /// `passed`, `failed`, `not attempted`, … ([`Verdict::kind`]).
    ///
    /// [`Verdict::kind`]: raystep_check::verdicts::Verdict::kind
    pub verdict: String,
    /// The rest of the verdict, on one line, if any.
    pub message: Option<String>,
}

impl Entry {
    /// The verdict as `check` says it: `failed: <message>`, `not
    /// attempted`, `timed out after 3 s (…)`.
    pub fn shown(&self) -> String {
        match (&self.message, self.verdict.as_str()) {
            // `Verdict`'s Display: these two put their kind first.
            (Some(message), "failed" | "refused") => {
                format!("{}: {message}", self.verdict)
            }
            (Some(message), _) => message.clone(),
            (None, _) => self.verdict.clone(),
        }
    }

    pub fn passed(&self) -> bool {
        self.verdict == "passed"
    }
}

impl Progress {
    /// The recorded verdict of `exercise` in `chapter`, if it was checked.
    pub fn entry(&self, chapter: &str, exercise: &str) -> Option<&Entry> {
        self.chapters
            .get(chapter)?
            .exercises
            .iter()
            .find(|e| e.exercise == exercise)
    }
}

/// `<root>/.raystep/progress.json`.
pub fn path(root: &Path) -> PathBuf {
    root.join(FOLDER).join(FILE)
}

/// The progress of the workspace at `root`: `None` if nothing was checked
/// yet (no file), an error naming the file if it cannot be read or is not
/// a progress file.
pub fn read(root: &Path) -> Result<Option<Progress>, Error> {
    let path = path(root);
    let text = match std::fs::read_to_string(&path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(Error::io(&path, e)),
    };
    serde_json::from_str(&text).map(Some).map_err(|e| {
        Error::Usage(format!("{}: not a progress file ({e})", shown(&path)))
    })
}

/// Records `report`, the check of chapter `chapter` just made, in the
/// progress file of the workspace at `root`, replacing what that chapter
/// had; the other chapters stay (an unreadable file starts afresh).
pub fn record(
    root: &Path, chapter: &str, report: &Report,
) -> Result<(), Error> {
    let mut progress = read(root).ok().flatten().unwrap_or_default();
    let checked = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    progress
        .chapters
        .insert(chapter.to_string(), entries(report, checked));
    let folder = root.join(FOLDER);
    std::fs::create_dir_all(&folder).map_err(|e| Error::io(&folder, e))?;
    let mut json =
        serde_json::to_string_pretty(&progress).expect("progress serialises");
    json.push('\n');
    atomic_file::write(&path(root), json.as_bytes())
}

/// The entries of one check made at `checked`.
fn entries(report: &Report, checked: u64) -> ChapterProgress {
    let exercises = report
        .exercises
        .iter()
        .map(|(exercise, verdict)| {
            let paper = report.labels.get(exercise).is_some_and(|l| l.paper);
            Entry {
                exercise: exercise.clone(),
                kind: if paper { "paper" } else { "code" }.to_string(),
                verdict: verdict.kind().to_string(),
                message: verdict.message().map(|m| one_line(&m)),
            }
        })
        .collect();
    ChapterProgress { checked, exercises }
}

/// `text`'s lines, trimmed, joined by spaces.
fn one_line(text: &str) -> String {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_check::verdicts::{Label, Verdict};

    fn report(verdicts: &[(&str, Verdict, bool)]) -> Report {
        let mut report = Report::default();
        for (name, verdict, paper) in verdicts {
            report.exercises.push((name.to_string(), verdict.clone()));
            let label = Label {
                stars: "★".into(),
                paper: *paper,
            };
            report.labels.insert(name.to_string(), label);
        }
        report
    }

    #[test]
    fn a_chapter_checked_again_replaces_its_entries_only() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        assert_eq!(read(root).unwrap(), None);
        let failed = Verdict::Failed("t (tests/a.rs:3):\n  left 1\n".into());
        record(
            root,
            "ch01",
            &report(&[("a", failed, false), ("q1", Verdict::Passed, true)]),
        )
        .unwrap();
        record(
            root,
            "ch02",
            &report(&[("b", Verdict::NotAttempted, false)]),
        )
        .unwrap();
        let progress = read(root).unwrap().unwrap();
        let a = progress.entry("ch01", "a").unwrap();
        assert_eq!(a.kind, "code");
        assert_eq!(a.shown(), "failed: t (tests/a.rs:3): left 1");
        assert!(!a.passed());
        assert_eq!(progress.entry("ch01", "q1").unwrap().kind, "paper");
        assert!(progress.chapters["ch01"].checked > 1_700_000_000);

        record(root, "ch01", &report(&[("a", Verdict::Passed, false)]))
            .unwrap();
        let progress = read(root).unwrap().unwrap();
        assert!(progress.entry("ch01", "a").unwrap().passed());
        assert_eq!(progress.entry("ch01", "q1"), None);
        assert_eq!(
            progress.entry("ch02", "b").unwrap().shown(),
            "not attempted"
        );
        let names: Vec<_> = std::fs::read_dir(root.join(FOLDER))
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, [FILE]);
    }

    #[test]
    fn a_corrupt_file_is_named_and_then_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        std::fs::create_dir(root.join(FOLDER)).unwrap();
        std::fs::write(path(root), "{\"chapters\": 3").unwrap();
        let error = read(root).unwrap_err().to_string();
        assert!(
            error.contains(".raystep/progress.json: not a progress file ("),
            "{error}"
        );
        record(root, "ch03", &report(&[("c", Verdict::Passed, false)]))
            .unwrap();
        assert!(read(root).unwrap().unwrap().entry("ch03", "c").is_some());
    }

    #[test]
    fn verdicts_are_shown_as_check_shows_them() {
        let entry = |verdict: &str, message: Option<&str>| Entry {
            exercise: "a".into(),
            kind: "code".into(),
            verdict: verdict.into(),
            message: message.map(String::from),
        };
        assert_eq!(entry("passed", None).shown(), "passed");
        assert_eq!(
            entry("refused", Some("exercise/a.rs:1:1: `unsafe`")).shown(),
            "refused: exercise/a.rs:1:1: `unsafe`"
        );
        assert_eq!(
            entry("timed out", Some("timed out after 3 s")).shown(),
            "timed out after 3 s"
        );
    }

    /// The progress file is the student's own: not handed out with the
    /// student edition, nor copied into `grade`'s scratch workspace.
    #[test]
    fn workspace_copies_leave_the_progress_out() {
        assert!(crate::workspace_copy::is_skipped(Path::new(FOLDER)));
    }
}
