//! What `raystep grade` finds: one row per student and exercise, and the
//! files of a submission not taken; the table, its JSON and the rows kept
//! for `--resume` are made of these.

use serde::{Deserialize, Serialize};

/// One row of the table: a student's verdict on one exercise.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Row {
    /// The student's folder name.
    pub student: String,
    /// The exercise.
    pub exercise: String,
    /// `passed`, `failed`, `not attempted`, `timed out`, `missing file`,
    /// `refused` (the file names another file, the environment or the
    /// operating system), `does not compile` (or `cargo failed`).
    pub verdict: String,
    /// The first failure (which test, where, why), if any.
    pub message: String,
}

/// A file of a submission that was not taken.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Ignored {
    /// The student's folder name (empty for a file beside the folders).
    pub student: String,
    /// The file, relative to the student's folder.
    pub file: String,
}

/// One student's rows and the files of theirs not taken.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq, Eq)]
pub struct Graded {
    /// The student's folder name.
    pub student: String,
    /// The student's verdicts, one row per exercise and question.
    pub rows: Vec<Row>,
    /// The student's files not taken.
    pub ignored: Vec<Ignored>,
}
