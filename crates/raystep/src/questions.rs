//! The paper questions' two files, and how `check` judges them.
//!
//! * `book/src/figures/chNN/questions.toml`: each question with the answer
//!   the chapter's code computes, written by `raystep figures` (and checked
//!   by `--check`) like a figure; the book shows the questions from it.
//! * `chapters/chNN-*/exercise/answers.toml`: the student's answers, one
//!   key per question; its stub says `"todo"` for each.
//!
//! The rules (what passes, the messages, the student edition's digests)
//! are `raystep_check::questions`.

use std::path::{Path, PathBuf};

use raystep_check::questions::{Questions, untouched};
use raystep_check::verdicts::Verdict;
use raystep_figure::Chapter;

use crate::error::Error;
use crate::shown_path::relative;

/// The student's answers file, in the chapter's `exercise/` folder.
pub const ANSWERS: &str = "answers.toml";

/// The most of `answers.toml` that is read: a file larger than this fails
/// every question.
const ANSWERS_LIMIT: u64 = 64 * 1024;

/// The questions file of `chapter` in the workspace at `root`.
pub fn file(root: &Path, chapter: &Chapter) -> PathBuf {
    crate::workspace::figures_dir(root)
        .join(chapter.id)
        .join("questions.toml")
}

/// The questions of `chapter` as its code states them, `None` if it has
/// none.
pub fn from_code(chapter: &Chapter) -> Option<Questions> {
    let questions = (chapter.questions)();
    (!questions.is_empty()).then_some(Questions { questions })
}

/// The questions file's text, as `raystep figures` writes it.
pub fn text(chapter: &Chapter, questions: &Questions) -> String {
    questions.to_toml(&format!(
        "Chapter {}'s paper questions, with the answers its code computes\n\
         (chapters/{}/figures/src/questions.rs). Written by `raystep \
         figures`:\nnever edit it by hand. `raystep check {}` judges \
         exercise/{ANSWERS} with it.",
        raystep_check::questions::chapter_number(chapter.id),
        chapter.package,
        chapter.id
    ))
}

/// The questions file of `chapter` in the workspace at `root`, `None` if
/// it has none.
pub fn read(
    root: &Path, chapter: &Chapter,
) -> Result<Option<Questions>, Error> {
    let path = file(root, chapter);
    let text = match std::fs::read_to_string(&path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(Error::io(&path, e)),
    };
    let shown = relative(&path).display().to_string();
    Questions::parse(&shown, &text).map(Some).map_err(|e| {
        Error::Usage(format!("{e} (redraw with `raystep figures`)"))
    })
}

/// The verdict on each paper question of `chapter` in the workspace at
/// `root`: the reference answers judged (`reference`), else the student's
/// `exercise/answers.toml` (none yet: not attempted).
pub fn judge(
    root: &Path, chapter: &Chapter, reference: bool,
) -> Result<Vec<(String, Verdict)>, Error> {
    let Some(questions) = read(root, chapter)? else {
        return Ok(Vec::new());
    };
    if reference {
        return Ok(questions.judge_reference(chapter.id));
    }
    let name = format!("exercise/{ANSWERS}");
    let path = root
        .join("chapters")
        .join(chapter.package)
        .join("exercise")
        .join(ANSWERS);
    let answers = match std::fs::metadata(&path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(e) => return Err(Error::io(&path, e)),
        Ok(meta) if meta.len() > ANSWERS_LIMIT => {
            let why = format!(
                "{name}: {} bytes; an answers file holds at most {} KiB",
                meta.len(),
                ANSWERS_LIMIT / 1024
            );
            return Ok(questions
                .questions
                .iter()
                .map(|q| (q.id.clone(), Verdict::Failed(why.clone())))
                .collect());
        }
        Ok(_) => match std::fs::read(&path) {
            Ok(bytes) => Some(
                String::from_utf8(bytes)
                    .map_err(|_| format!("{name}: not UTF-8 text")),
            ),
            Err(e) => return Err(Error::io(&path, e)),
        },
    };
    Ok(match answers {
        Some(Err(why)) => questions
            .questions
            .iter()
            .map(|q| (q.id.clone(), Verdict::Failed(why.clone())))
            .collect(),
        Some(Ok(text)) => questions.judge(chapter.id, &name, Some(&text)),
        None => questions.judge(chapter.id, &name, None),
    })
}

/// Writes the stub of `exercise/answers.toml` into the chapter of the
/// workspace at `copy`, from the questions file there (nothing if the
/// chapter has no questions).
pub fn write_stub(copy: &Path, chapter: &Chapter) -> Result<(), Error> {
    if let Some(questions) = read(copy, chapter)? {
        let path = copy
            .join("chapters")
            .join(chapter.package)
            .join("exercise")
            .join(ANSWERS);
        std::fs::write(&path, questions.answers_stub(chapter.id))
            .map_err(|e| Error::io(&path, e))?;
    }
    Ok(())
}

/// Writes the stub of `exercise/answers.toml` of `chapter` in the
/// workspace at `root` from `questions` where it is missing or still
/// untouched (no answer in it yet: an instructor's answers are never
/// overwritten); the path if it was written.
pub fn refresh_stub(
    root: &Path, chapter: &Chapter, questions: &Questions,
) -> Result<Option<PathBuf>, Error> {
    let path = root
        .join("chapters")
        .join(chapter.package)
        .join("exercise")
        .join(ANSWERS);
    let stub = questions.answers_stub(chapter.id);
    match std::fs::read_to_string(&path) {
        Ok(text) if text == stub || !untouched(&text) => return Ok(None),
        Ok(_) => {}
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
        Err(e) => return Err(Error::io(&path, e)),
    }
    crate::atomic_file::write(&path, stub.as_bytes())?;
    Ok(Some(path))
}

/// Replaces the questions file of `chapter` in the workspace at `copy` by
/// the same questions without their answers (the student edition).
pub fn drop_answers(copy: &Path, chapter: &Chapter) -> Result<(), Error> {
    if let Some(questions) = read(copy, chapter)? {
        let path = file(copy, chapter);
        let hidden = questions.without_answers(chapter.id);
        std::fs::write(&path, text(chapter, &hidden))
            .map_err(|e| Error::io(&path, e))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chapters::CHAPTERS;

    /// Every chapter of the lecture asks at least two paper questions, each
    /// of one to three stars; the committed file is what the code states
    /// (as `raystep figures --check` also says), and the committed stub of
    /// `answers.toml` asks every question, untouched.
    #[test]
    fn every_chapter_asks_two_questions_and_its_files_agree() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        for chapter in CHAPTERS.iter().filter(|c| !c.exercises.is_empty()) {
            let questions = from_code(chapter).unwrap_or_default();
            assert!(questions.questions.len() >= 2, "{}", chapter.id);
            for q in &questions.questions {
                assert!((1..=3).contains(&q.stars), "{} {}", chapter.id, q.id);
            }
            let committed = read(&root, chapter).unwrap();
            assert_eq!(committed.as_ref(), Some(&questions), "{}", chapter.id);
            let stub = std::fs::read_to_string(
                root.join("chapters")
                    .join(chapter.package)
                    .join("exercise")
                    .join(ANSWERS),
            )
            .unwrap();
            assert_eq!(
                stub,
                questions.answers_stub(chapter.id),
                "{}",
                chapter.id
            );
        }
    }

    /// Each chapter lists one difficulty per exercise, of one to three
    /// stars, and the exercise's stub says it in its first line
    /// (`//! Exercise 2 (★★): …`).
    #[test]
    fn every_exercise_has_a_difficulty() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        for chapter in CHAPTERS {
            assert_eq!(
                chapter.stars.len(),
                chapter.exercises.len(),
                "{}",
                chapter.id
            );
            assert!(chapter.stars.iter().all(|s| (1..=3).contains(s)));
            for exercise in chapter.exercises {
                let stars = chapter.difficulty(exercise).unwrap();
                let stub = root
                    .join("chapters")
                    .join(chapter.package)
                    .join("exercise")
                    .join(format!("{exercise}.rs"));
                let text = std::fs::read_to_string(&stub).unwrap();
                let first = text.lines().next().unwrap_or_default();
                assert!(
                    first.starts_with("//! Exercise ")
                        && first.contains(&format!(" ({stars}): ")),
                    "{}: {first}",
                    stub.display()
                );
            }
        }
    }

    /// The introduction's course map names every exercise and paper
    /// question with the difficulty the chapter gives it.
    #[test]
    fn the_course_map_agrees_with_the_chapters() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let intro =
            std::fs::read_to_string(root.join("book/src/introduction.md"))
                .unwrap();
        for chapter in CHAPTERS.iter().filter(|c| !c.exercises.is_empty()) {
            // The map's rows of this chapter (chapter 8 has two).
            let rows: Vec<&str> = intro
                .lines()
                .filter(|l| {
                    l.starts_with("| [")
                        && l.contains(&format!("]({}", chapter.id))
                        && l.contains('★')
                })
                .collect();
            let rows = rows.join("\n");
            assert!(!rows.is_empty(), "no map row for {}", chapter.id);
            for exercise in chapter.exercises {
                let stars = chapter.difficulty(exercise).unwrap();
                let named = format!("`{exercise}` {stars}");
                assert!(
                    rows.contains(&format!("{named},"))
                        || rows.contains(&format!("{named} |")),
                    "{}: {named}",
                    chapter.id
                );
            }
            for q in from_code(chapter).unwrap().questions {
                let named = format!(
                    "q{} {} {}",
                    q.id.trim_start_matches('q'),
                    q.difficulty(),
                    q.title
                );
                assert!(rows.contains(&named), "{}: {named}", chapter.id);
            }
        }
    }
}
