//! `raystep hint chNN EXERCISE [--level 1|2|3]`: the hints for one
//! exercise or paper question, each level more concrete than the last
//! (the idea; the step usually missed; the shape of the code, or of the
//! working, without the code or the answer).
//!
//! They are kept beside the stubs, in the chapter's
//! `exercise/hints.toml` (one table per exercise and question, with the
//! keys `idea`, `step` and `shape`), so the student edition has them.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;
use std::process::ExitCode;

use raystep_figure::Chapter;
use serde::Deserialize;

use crate::error::Error;
use crate::shown_path::relative;
use crate::{chapters, questions, workspace};

/// The hints file, in the chapter's `exercise/` folder.
pub const HINTS: &str = "hints.toml";

/// The three hints of one exercise or question.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Hints {
    /// Level 1: the idea.
    pub idea: String,
    /// Level 2: the step usually missed.
    pub step: String,
    /// Level 3: the shape of the code (or the working), without it.
    pub shape: String,
}

impl Hints {
    /// The hints up to `level` (1 to 3), each on a paragraph of its own.
    fn up_to(&self, level: u8) -> Vec<(&'static str, &str)> {
        [
            ("the idea", self.idea.as_str()),
            ("the step usually missed", self.step.as_str()),
            ("the shape, without the code", self.shape.as_str()),
        ]
        .into_iter()
        .take(usize::from(level))
        .collect()
    }
}

/// What `raystep hint` was asked.
#[derive(Debug)]
pub struct Options {
    /// `ch02`, `02` or `2`.
    pub chapter: String,
    /// An exercise (`ray_plane`) or a paper question (`q1`).
    pub exercise: String,
    /// How far to go: 1, 2 or 3.
    pub level: u8,
}

/// Runs `raystep hint`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let chapter = chapters::find(&options.chapter, chapters::CHAPTERS)?;
    let names = exercise_names(&root, chapter)?;
    if !names.contains(&options.exercise) {
        return Err(Error::Usage(format!(
            "{}: no such exercise or paper question in {}; there are {}",
            options.exercise,
            chapter.id,
            names.join(", ")
        )));
    }
    let all = read(&root, chapter)?;
    let hints = all.get(&options.exercise).ok_or_else(|| {
        Error::Usage(format!(
            "{}: no hints for {} (the chapter's exercise/{HINTS} lacks them)",
            chapter.id, options.exercise
        ))
    })?;
    print!(
        "{}",
        shown(chapter, &options.exercise, hints, options.level)
    );
    Ok(ExitCode::SUCCESS)
}

/// The chapter's exercises, then its paper questions, by name.
fn exercise_names(
    root: &Path, chapter: &Chapter,
) -> Result<Vec<String>, Error> {
    let mut names: Vec<String> =
        chapter.exercises.iter().map(|e| e.to_string()).collect();
    if let Some(file) = questions::read(root, chapter)? {
        names.extend(file.questions.into_iter().map(|q| q.id));
    }
    Ok(names)
}

/// The hints file of `chapter` in the workspace at `root`, read; a file
/// that does not parse is an error naming its line.
fn read(
    root: &Path, chapter: &Chapter,
) -> Result<BTreeMap<String, Hints>, Error> {
    let path = root
        .join("chapters")
        .join(chapter.package)
        .join("exercise")
        .join(HINTS);
    let text =
        std::fs::read_to_string(&path).map_err(|e| Error::io(&path, e))?;
    toml::from_str(&text).map_err(|e| {
        let at = e.span().map_or(0, |s| s.start);
        let line = text[..at.min(text.len())].matches('\n').count() + 1;
        Error::Usage(format!(
            "{}:{line}: {}",
            relative(&path).display(),
            e.message().trim()
        ))
    })
}

/// The hints as printed: a heading with the difficulty, each hint up to
/// `level` on its own paragraph, and how to ask for the next.
fn shown(
    chapter: &Chapter, exercise: &str, hints: &Hints, level: u8,
) -> String {
    let stars = chapter
        .difficulty(exercise)
        .map(|s| format!(" ({s})"))
        .unwrap_or_default();
    let mut text = format!("{} {exercise}{stars}\n", chapter.id);
    for (k, (what, hint)) in hints.up_to(level).into_iter().enumerate() {
        let hint = hint.split_whitespace().collect::<Vec<_>>().join(" ");
        let _ = write!(text, "\nHint {} of 3, {what}: {hint}\n", k + 1);
    }
    if level < 3 {
        let _ = write!(
            text,
            "\nMore: raystep hint {} {exercise} --level {}\n",
            chapter.id,
            level + 1
        );
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chapters::CHAPTERS;

    /// Every exercise and paper question of every chapter has its three
    /// hints, none empty, and the file has no hints for anything else.
    #[test]
    fn every_exercise_and_question_has_three_hints() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        for chapter in CHAPTERS.iter().filter(|c| !c.exercises.is_empty()) {
            let hints = read(&root, chapter).unwrap();
            let mut names = exercise_names(&root, chapter).unwrap();
            let mut listed: Vec<String> = hints.keys().cloned().collect();
            names.sort();
            listed.sort();
            assert_eq!(listed, names, "{}", chapter.id);
            for (name, h) in &hints {
                for hint in [&h.idea, &h.step, &h.shape] {
                    assert!(
                        hint.trim().len() > 20,
                        "{} {name}: {hint:?}",
                        chapter.id
                    );
                }
                assert!(h.idea != h.step && h.step != h.shape, "{name}");
            }
        }
    }

    #[test]
    fn hints_are_shown_up_to_the_level_asked() {
        let chapter = CHAPTERS[1];
        let hints = Hints {
            idea: "The plane's\n  equation along the ray.".into(),
            step: "N·D can be zero.".into(),
            shape: "Three cases.".into(),
        };
        assert_eq!(
            shown(chapter, "ray_plane", &hints, 1),
            "ch02 ray_plane (★)\n\nHint 1 of 3, the idea: The plane's \
             equation along the ray.\n\nMore: raystep hint ch02 ray_plane \
             --level 2\n"
        );
        let all = shown(chapter, "ray_plane", &hints, 3);
        assert!(all.contains("Hint 2 of 3, the step usually missed: N·D"));
        assert!(all.ends_with(
            "Hint 3 of 3, the shape, without the code: Three cases.\n"
        ));
    }
}
