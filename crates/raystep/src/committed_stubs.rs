//! The exercise stubs as committed to git, not as the working tree holds
//! them: an instructor who solves the exercises in `exercise/` to try them
//! must not hand the solutions out (`student-edition`) or to a student who
//! left a file out (`grade`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use raystep_figure::Chapter;

use crate::error::Error;
use crate::git::git;
use crate::reference_module::reference_module;

/// Every stub of some chapters, and the working-tree files that differ.
#[derive(Debug, Default)]
pub struct Stubs {
    /// `(package, exercise)` → the stub's text.
    texts: BTreeMap<(String, String), String>,
    /// Exercise files (relative to the workspace) whose working-tree text
    /// is not their committed stub.
    pub differing: Vec<PathBuf>,
}

impl Stubs {
    /// The stub of `exercise` in `chapter`.
    pub fn text(&self, chapter: &Chapter, exercise: &str) -> &str {
        self.texts
            .get(&(chapter.package.to_string(), exercise.to_string()))
            .map_or("", String::as_str)
    }

    /// Writes the chapter's stubs into `exercise/` and, when `modules`,
    /// over the exercise modules in `src/` (wherever below it each lives)
    /// of the workspace at `copy`.
    pub fn write(
        &self, copy: &Path, chapter: &Chapter, modules: bool,
    ) -> Result<(), Error> {
        let dir = copy.join("chapters").join(chapter.package);
        for exercise in chapter.exercises {
            let text = self.text(chapter, exercise);
            let mut paths =
                vec![dir.join("exercise").join(format!("{exercise}.rs"))];
            if modules {
                paths.push(reference_module(&dir, exercise)?);
            }
            for path in paths {
                std::fs::write(&path, text).map_err(|e| Error::io(&path, e))?;
            }
        }
        Ok(())
    }

    /// The note for files that differ from their stubs, if any.
    pub fn note(&self) -> Option<String> {
        (!self.differing.is_empty()).then(|| {
            let files: Vec<String> = self
                .differing
                .iter()
                .map(|p| p.display().to_string())
                .collect();
            format!(
                "note: {} differ{} from the committed stub{} (solutions being \
                 tried?); the committed stub{} used instead: {}",
                if files.len() == 1 {
                    "one exercise file"
                } else {
                    "exercise files"
                },
                if files.len() == 1 { "s" } else { "" },
                if files.len() == 1 { "" } else { "s" },
                if files.len() == 1 { " is" } else { "s are" },
                files.join(", ")
            )
        })
    }
}

/// The committed stubs of `chapters` in the workspace at `root`.
///
/// Each comes from git (`HEAD`); where git or the commit is missing (a
/// copy without its repository), the working tree's file is taken only if
/// it is still a stub (it holds a `todo!()`), else the export stops,
/// naming the file.
pub fn committed(root: &Path, chapters: &[&Chapter]) -> Result<Stubs, Error> {
    let mut stubs = Stubs::default();
    for chapter in chapters {
        for exercise in chapter.exercises {
            let relative = PathBuf::from("chapters")
                .join(chapter.package)
                .join("exercise")
                .join(format!("{exercise}.rs"));
            let path = root.join(&relative);
            let working = std::fs::read_to_string(&path)
                .map_err(|e| Error::io(&path, e))?;
            let text = match from_git(root, &relative)? {
                Some(text) => text,
                None if working.contains("todo!(") => working.clone(),
                None => {
                    return Err(Error::Usage(format!(
                        "{}: not in a git commit, and not a stub (no todo!() \
                         in it): restore the stub before exporting",
                        relative.display()
                    )));
                }
            };
            if text != working {
                stubs.differing.push(relative.clone());
            }
            stubs.texts.insert(
                (chapter.package.to_string(), exercise.to_string()),
                text,
            );
        }
    }
    Ok(stubs)
}

/// The text of `relative` (to `root`) in git's `HEAD`, `None` if git, the
/// repository or the file in it is missing.
fn from_git(root: &Path, relative: &Path) -> Result<Option<String>, Error> {
    let spec = format!(
        "HEAD:./{}",
        relative
            .components()
            .map(|c| c.as_os_str().to_string_lossy())
            .collect::<Vec<_>>()
            .join("/")
    );
    Ok(match git(root, &["show", &spec])? {
        Some(out) if out.status.success() => String::from_utf8(out.stdout).ok(),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use std::process::Command;

    use super::*;

    fn git(dir: &Path, args: &[&str]) {
        let out = Command::new("git")
            .args(["-c", "user.name=t", "-c", "user.email=t@t"])
            .args(["-c", "commit.gpgsign=false"])
            .args(args)
            .current_dir(dir)
            .output()
            .unwrap();
        assert!(out.status.success(), "git {args:?}");
    }

    /// A chapter `ch01` of package `ch01-a` with exercises `a` and `b`.
    fn chapter() -> Chapter {
        Chapter {
            id: "ch01",
            package: "ch01-a",
            exercises: &["a", "b"],
            ..*crate::chapters::CHAPTERS[0]
        }
    }

    fn write(root: &Path, exercise: &str, text: &str) {
        let path = format!("chapters/ch01-a/exercise/{exercise}.rs");
        crate::test_files::write(&root.join(path), text);
    }

    /// An instructor tries exercise `a` in place: the committed stub is
    /// taken, and the file is named.
    #[test]
    fn the_committed_stub_is_taken_not_the_solution_being_tried() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        write(root, "a", "fn a() { todo!() }\n");
        write(root, "b", "fn b() { todo!() }\n");
        git(root, &["init", "--quiet"]);
        git(root, &["add", "--all"]);
        git(root, &["commit", "--quiet", "-m", "stubs"]);
        write(root, "a", "fn a() { 42 }\n");
        let chapter = chapter();
        let stubs = committed(root, &[&chapter]).unwrap();
        assert_eq!(stubs.text(&chapter, "a"), "fn a() { todo!() }\n");
        assert_eq!(stubs.text(&chapter, "b"), "fn b() { todo!() }\n");
        assert_eq!(
            stubs.differing,
            [PathBuf::from("chapters/ch01-a/exercise/a.rs")]
        );
        let note = stubs.note().unwrap();
        assert!(
            note.starts_with(
                "note: one exercise file differs from the committed stub"
            ) && note.ends_with("chapters/ch01-a/exercise/a.rs"),
            "{note}"
        );
        // Written into a copy: exercise/ and, if asked, over the reference
        // modules wherever they live below src/.
        let copy = tempfile::tempdir().unwrap();
        let chapter_dir = copy.path().join("chapters/ch01-a");
        for folder in ["exercise", "src/part"] {
            std::fs::create_dir_all(chapter_dir.join(folder)).unwrap();
        }
        std::fs::write(chapter_dir.join("src/a.rs"), "fn a() { 1 }").unwrap();
        std::fs::write(chapter_dir.join("src/part/b.rs"), "fn b() { 2 }")
            .unwrap();
        stubs.write(copy.path(), &chapter, true).unwrap();
        let read =
            |p: &str| std::fs::read_to_string(chapter_dir.join(p)).unwrap();
        assert_eq!(read("exercise/a.rs"), "fn a() { todo!() }\n");
        assert_eq!(read("src/a.rs"), "fn a() { todo!() }\n");
        assert_eq!(read("src/part/b.rs"), "fn b() { todo!() }\n");
    }

    /// Without git, a file is taken only while it is still a stub.
    #[test]
    fn without_git_a_solution_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        write(root, "a", "fn a() { todo!() }\n");
        write(root, "b", "fn b() { 42 }\n");
        let chapter = chapter();
        let error = committed(root, &[&chapter]).unwrap_err().to_string();
        let stub_word = "stub (no todo!() in it)";
        assert_eq!(
            error,
            format!(
                "chapters/ch01-a/exercise/b.rs: not in a git commit, and not \
                 a {stub_word}: restore the stub before exporting"
            )
        );
        write(root, "b", "fn b() { todo!() }\n");
        let stubs = committed(root, &[&chapter]).unwrap();
        assert!(stubs.differing.is_empty());
        assert_eq!(stubs.note(), None);
    }
}
