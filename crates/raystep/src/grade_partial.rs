//! `raystep grade --resume`: each student's rows are added to
//! `FILE.csv.partial` beside the table as soon as the student is graded,
//! so a run stopped by Ctrl-C, a crash or a reboot can go on where it
//! stopped. The file is JSON lines: the run (chapter, held-out seed), then
//! one line per student graded. It is removed once the table is written.

use std::fs::{self, File, OpenOptions};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::grade_rows::Graded;
use crate::shown_path::shown;

/// The first line: which run the rows belong to.
#[derive(Debug, Serialize, Deserialize, PartialEq, Eq)]
struct Header {
    chapter: String,
    held_out_seed: Option<u64>,
}

/// What an interrupted run left: its seed and the students it graded.
#[derive(Debug, PartialEq, Eq)]
pub struct Left {
    /// The held-out seed it drew its cases from.
    pub held_out_seed: Option<u64>,
    /// The students graded, in the order they finished.
    pub graded: Vec<Graded>,
}

/// Where the rows of a run writing `out` are kept: `out` + `.partial`.
pub fn path(out: &Path) -> PathBuf {
    let mut name = out.as_os_str().to_owned();
    name.push(".partial");
    PathBuf::from(name)
}

/// What the file at `path` kept of a run grading `chapter`: `None` if
/// there is no such file. A file of another chapter is an error naming it;
/// a line cut short by the crash (the last one) is dropped.
pub fn read(path: &Path, chapter: &str) -> Result<Option<Left>, Error> {
    let text = match fs::read_to_string(path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(Error::io(path, e)),
    };
    let mut lines = text.lines();
    let header: Header = lines
        .next()
        .and_then(|line| serde_json::from_str(line).ok())
        .ok_or_else(|| {
            Error::Usage(format!(
                "{}:1: not the rows of a grading run (remove it to start afresh)",
                shown(path)
            ))
        })?;
    if header.chapter != chapter {
        return Err(Error::Usage(format!(
            "{}: rows of a run grading {}, not {chapter} (remove it to start \
             afresh, or resume with --chapter {})",
            shown(path),
            header.chapter,
            header.chapter
        )));
    }
    let graded = lines
        .filter_map(|line| serde_json::from_str(line).ok())
        .collect();
    Ok(Some(Left {
        held_out_seed: header.held_out_seed,
        graded,
    }))
}

/// The file a run adds its students' rows to.
pub struct Partial {
    path: PathBuf,
    file: Mutex<File>,
}

impl Partial {
    /// Starts the file at `path` afresh for a run grading `chapter` with
    /// `held_out_seed`, holding the rows `kept` from an earlier run.
    pub fn start(
        path: &Path, chapter: &str, held_out_seed: Option<u64>, kept: &[Graded],
    ) -> Result<Partial, Error> {
        let header = Header {
            chapter: chapter.to_string(),
            held_out_seed,
        };
        let mut text = line(&header);
        for graded in kept {
            text.push_str(&line(graded));
        }
        crate::atomic_file::write(path, text.as_bytes())?;
        let file = OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(|e| Error::io(path, e))?;
        Ok(Partial {
            path: path.to_path_buf(),
            file: Mutex::new(file),
        })
    }

    /// Adds one student's rows, on disk before this returns.
    pub fn add(&self, graded: &Graded) -> Result<(), Error> {
        let mut file = self.file.lock().unwrap_or_else(|e| e.into_inner());
        file.write_all(line(graded).as_bytes())
            .and_then(|()| file.sync_data())
            .map_err(|e| Error::io(&self.path, e))
    }

    /// The table is written: the rows are no longer needed.
    pub fn finish(self) -> Result<(), Error> {
        drop(self.file);
        fs::remove_file(&self.path).map_err(|e| Error::io(&self.path, e))
    }
}

/// `value` as one line of JSON.
fn line(value: &impl Serialize) -> String {
    let mut text = serde_json::to_string(value).expect("rows serialise");
    text.push('\n');
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade_rows::{Ignored, Row};

    fn graded(student: &str) -> Graded {
        Graded {
            student: student.to_string(),
            rows: vec![Row {
                student: student.to_string(),
                exercise: "ray_plane".to_string(),
                verdict: "failed".to_string(),
                message: "t: expected 2, got \"3\"".to_string(),
            }],
            ignored: vec![Ignored {
                student: student.to_string(),
                file: "notes.txt".to_string(),
            }],
        }
    }

    #[test]
    fn rows_kept_are_read_back_and_a_cut_line_is_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let file = path(&dir.path().join("grades.csv"));
        assert_eq!(file.file_name().unwrap(), "grades.csv.partial");
        assert_eq!(read(&file, "ch02").unwrap(), None);
        let partial =
            Partial::start(&file, "ch02", Some(7), &[graded("ada")]).unwrap();
        partial.add(&graded("bob")).unwrap();
        // A crash while the next line was written.
        fs::OpenOptions::new()
            .append(true)
            .open(&file)
            .unwrap()
            .write_all(b"{\"student\":\"cy")
            .unwrap();
        let left = read(&file, "ch02").unwrap().unwrap();
        assert_eq!(
            left,
            Left {
                held_out_seed: Some(7),
                graded: vec![graded("ada"), graded("bob")],
            }
        );
        // Another chapter's rows are not taken.
        let error = read(&file, "ch03").unwrap_err().to_string();
        assert!(
            error.contains("rows of a run grading ch02, not ch03"),
            "{error}"
        );
        partial.finish().unwrap();
        assert!(!file.exists());
        fs::write(&file, "not json\n").unwrap();
        let error = read(&file, "ch02").unwrap_err().to_string();
        assert!(
            error.contains("grades.csv.partial:1: not the rows"),
            "{error}"
        );
    }
}
