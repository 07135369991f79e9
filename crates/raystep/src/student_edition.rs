//! `raystep student-edition OUT`: the workspace for students, with no
//! reference solution anywhere in it.
//!
//! The sources are copied (no `target/`, no `.git`, no book output); then,
//! for every chapter and exercise `e`, `exercise/<e>.rs` and `src/<e>.rs`
//! get the text of the stub as committed to git (not what `exercise/`
//! holds now: an instructor may be trying the exercises), so the crates build, the book's listings show
//! the stubs, and `raystep check` works as in the instructor's workspace.
//! With no reference left, a chapter's `exercise` feature also turns on
//! the `exercise` feature of the chapters it builds on: chapter 2's tests
//! then run on the student's own chapter 1.
//!
//! The held-out programs of `raystep grade` (`examples/chNN_held_out.rs`)
//! are left out. The paper questions stay, without their answers and
//! worked solutions: each answer is kept as digests, which `check` judges
//! with as it would with the answer (`raystep_check::questions`); the
//! answers file is its stub.
//!
//! The copy is made in a temporary folder beside OUT and renamed to OUT
//! when complete, so OUT is never left half written.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use raystep_figure::Chapter;

use crate::committed_stubs::{self, Stubs};
use crate::error::Error;
use crate::shown_path::shown;
use crate::{chapters, git, questions, workspace, workspace_copy};

/// Runs `raystep student-edition OUT`.
pub fn run(out: &Path) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let (git, stubs) = export(&root, out, chapters::CHAPTERS)?;
    if let Some(note) = stubs.note() {
        eprintln!("{note}");
    }
    let exercises: usize =
        chapters::CHAPTERS.iter().map(|c| c.exercises.len()).sum();
    println!(
        "wrote {}: {} chapters, {exercises} exercises as stubs{}",
        shown(out),
        chapters::CHAPTERS.len(),
        match git {
            Git::Committed => ", one git commit",
            Git::Missing => " (no git found: no repository made)",
        }
    );
    println!(
        "students: cd {} && cargo run --release -- check ch01",
        shown(out)
    );
    Ok(ExitCode::SUCCESS)
}

/// Whether the export is a git repository.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Git {
    /// A new repository holding the export in one commit.
    Committed,
    /// `git` could not be started: no repository.
    Missing,
}

/// Writes the student edition of the workspace at `root` to `out`, which
/// must not exist or be an empty folder. The stubs are the committed ones
/// (see [`committed_stubs`]), whatever `exercise/` holds now; the returned
/// [`Stubs`] name the exercise files that differ from them.
pub fn export(
    root: &Path, out: &Path, chapters: &[&Chapter],
) -> Result<(Git, Stubs), Error> {
    refuse_non_empty(out)?;
    let stubs = committed_stubs::committed(root, chapters)?;
    let parent = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    fs::create_dir_all(&parent).map_err(|e| Error::io(&parent, e))?;
    let name = out
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .ok_or_else(|| {
            Error::Usage(format!("{}: not a folder name", out.display()))
        })?;
    let partial = tempfile::Builder::new()
        .prefix(&format!(".{name}.partial-"))
        .tempdir_in(&parent)
        .map_err(|e| Error::io(&parent, e))?;
    let mut exclude = vec![partial.path().to_path_buf()];
    if out.exists() {
        exclude.push(out.to_path_buf());
    }
    workspace_copy::copy_sources(root, partial.path(), &exclude)?;
    for chapter in chapters {
        stubs.write(partial.path(), chapter, true)?;
        chain_exercise_feature(partial.path(), chapter, chapters)?;
        drop_held_out(partial.path(), chapter)?;
        // The paper questions stay, their answers go (digests judge).
        questions::drop_answers(partial.path(), chapter)?;
        questions::write_stub(partial.path(), chapter)?;
    }
    let git = commit(partial.path())?;
    // The rename replaces an empty OUT; a non-empty one (made meanwhile)
    // makes it fail, and the temporary folder is removed.
    let partial_path = partial.path().to_path_buf();
    fs::rename(&partial_path, out).map_err(|e| Error::io(out, e))?;
    // Renamed away: nothing left for the guard to remove.
    let _ = partial.keep();
    Ok((git, stubs))
}

/// An error unless `out` does not exist or is an empty folder.
fn refuse_non_empty(out: &Path) -> Result<(), Error> {
    match fs::read_dir(out) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(()),
        Err(e) if out.is_file() || e.kind() == io::ErrorKind::NotADirectory => {
            Err(Error::Usage(format!(
                "{}: is a file; the student edition needs a new or empty folder",
                shown(out)
            )))
        }
        Err(e) => Err(Error::io(out, e)),
        Ok(mut entries) => match entries.next() {
            None => Ok(()),
            Some(_) => Err(Error::Usage(format!(
                "{}: not empty; the student edition is written only into a \
                 new or empty folder",
                shown(out)
            ))),
        },
    }
}

/// Removes the chapter's held-out program (`examples/chNN_held_out.rs`,
/// and `examples/` if nothing else is in it): it is `grade`'s, and its
/// case generators work out answers of their own to keep their inputs
/// clear of ambiguous ones.
fn drop_held_out(copy: &Path, chapter: &Chapter) -> Result<(), Error> {
    let examples = copy.join("chapters").join(chapter.package).join("examples");
    let program = examples
        .join(format!("{}.rs", crate::held_out::held_out_name(chapter)));
    if program.exists() {
        fs::remove_file(&program).map_err(|e| Error::io(&program, e))?;
    }
    if fs::read_dir(&examples).is_ok_and(|mut entries| entries.next().is_none())
    {
        fs::remove_dir(&examples).map_err(|e| Error::io(&examples, e))?;
    }
    Ok(())
}

/// The chapters the chapter's `Cargo.toml` depends on (its
/// `[dependencies]`, by the name it gives them), among `chapters`.
fn chapter_dependencies(
    manifest: &toml::Table, workspace: &toml::Table, chapters: &[&Chapter],
) -> Vec<String> {
    let Some(dependencies) =
        manifest.get("dependencies").and_then(|d| d.as_table())
    else {
        return Vec::new();
    };
    let shared = workspace
        .get("workspace")
        .and_then(|w| w.get("dependencies"))
        .and_then(|d| d.as_table());
    let mut found = Vec::new();
    for (name, spec) in dependencies {
        let spec = match spec.get("workspace").and_then(|w| w.as_bool()) {
            Some(true) => shared.and_then(|s| s.get(name)).unwrap_or(spec),
            _ => spec,
        };
        let package =
            spec.get("package").and_then(|p| p.as_str()).unwrap_or(name);
        if chapters.iter().any(|c| c.package == package) {
            found.push(name.clone());
        }
    }
    found.sort();
    found
}

/// Makes the chapter's `exercise` feature turn on `<dep>/exercise` for
/// every chapter it depends on (its `exercise = []` line rewritten).
fn chain_exercise_feature(
    copy: &Path, chapter: &Chapter, chapters: &[&Chapter],
) -> Result<(), Error> {
    let path = copy
        .join("chapters")
        .join(chapter.package)
        .join("Cargo.toml");
    let text = fs::read_to_string(&path).map_err(|e| Error::io(&path, e))?;
    let parse = |text: &str, path: &Path| -> Result<toml::Table, Error> {
        text.parse::<toml::Table>().map_err(|e| {
            Error::Usage(format!("{}: {}", path.display(), e.message()))
        })
    };
    let manifest = parse(&text, &path)?;
    let root_path = copy.join("Cargo.toml");
    let root_text =
        fs::read_to_string(&root_path).map_err(|e| Error::io(&root_path, e))?;
    let workspace = parse(&root_text, &root_path)?;
    let features: Vec<String> =
        chapter_dependencies(&manifest, &workspace, chapters)
            .iter()
            .map(|name| format!("{name}/exercise"))
            .collect();
    if features.is_empty() {
        return Ok(());
    }
    let line = format!(
        "exercise = [{}]",
        features
            .iter()
            .map(|f| format!("\"{f}\""))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let mut section = String::new();
    let mut replaced = false;
    let mut edited = String::new();
    for original in text.lines() {
        let trimmed = original.trim();
        if trimmed.starts_with('[') {
            section = trimmed.to_string();
        }
        if section == "[features]"
            && trimmed.replace(' ', "") == "exercise=[]"
            && !replaced
        {
            edited.push_str(&line);
            replaced = true;
        } else {
            edited.push_str(original);
        }
        edited.push('\n');
    }
    let wanted: Vec<toml::Value> =
        features.iter().cloned().map(toml::Value::String).collect();
    let got = parse(&edited, &path)?
        .get("features")
        .and_then(|f| f.get("exercise"))
        .and_then(|e| e.as_array())
        .cloned();
    if !replaced || got.as_ref() != Some(&wanted) {
        return Err(Error::Usage(format!(
            "{}: expected `exercise = []` under [features] (to make it `{line}`)",
            path.display()
        )));
    }
    fs::write(&path, edited).map_err(|e| Error::io(&path, e))
}

/// A new git repository in `dir` holding everything in one commit; no
/// repository if `git` is not installed.
fn commit(dir: &Path) -> Result<Git, Error> {
    let git = |args: &[&str]| -> Result<Option<()>, Error> {
        let config = [
            "-c",
            "user.name=raystep",
            "-c",
            "user.email=raystep@localhost",
            "-c",
            "commit.gpgsign=false",
            "-c",
            "init.defaultBranch=main",
            "-c",
            "core.autocrlf=false",
        ];
        match git::git(dir, &[&config[..], args].concat())? {
            None => Ok(None),
            Some(out) if out.status.success() => Ok(Some(())),
            Some(out) => Err(Error::Usage(format!(
                "git {} in {}: {}",
                args.join(" "),
                dir.display(),
                String::from_utf8_lossy(&out.stderr).trim()
            ))),
        }
    };
    if git(&["init", "--quiet"])?.is_none() {
        return Ok(Git::Missing);
    }
    git(&["add", "--all"])?;
    git(&[
        "commit",
        "--quiet",
        "--no-verify",
        "--message",
        "raystep student edition: every exercise module holds its stub",
    ])?;
    Ok(Git::Committed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_non_empty_folder_or_a_file_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        assert!(refuse_non_empty(&dir.path().join("new")).is_ok());
        assert!(refuse_non_empty(dir.path()).is_ok());
        fs::write(dir.path().join("file"), "").unwrap();
        let error = refuse_non_empty(dir.path()).unwrap_err().to_string();
        assert!(
            error.ends_with(
                ": not empty; the student edition is written only \
                             into a new or empty folder"
            ),
            "{error}"
        );
        assert!(
            error.starts_with(&dir.path().display().to_string()),
            "{error}"
        );
        let error = refuse_non_empty(&dir.path().join("file"))
            .unwrap_err()
            .to_string();
        assert!(error.contains("is a file"), "{error}");
    }

    #[test]
    fn chapter_dependencies_are_found_through_the_workspace() {
        let workspace: toml::Table = r#"
            [workspace.dependencies]
            ch01 = { path = "chapters/ch01-a", package = "ch01-a" }
            glam = "0.34"
        "#
        .parse()
        .unwrap();
        let manifest: toml::Table = r#"
            [dependencies]
            ch01.workspace = true
            glam.workspace = true
            [dev-dependencies]
            insta.workspace = true
        "#
        .parse()
        .unwrap();
        let ch01 = Chapter {
            id: "ch01",
            package: "ch01-a",
            ..*chapters::CHAPTERS[0]
        };
        assert_eq!(
            chapter_dependencies(&manifest, &workspace, &[&ch01]),
            ["ch01"]
        );
    }
}
