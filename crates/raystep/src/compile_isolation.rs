//! One exercise that does not compile must not hide the others' verdicts.
//!
//! `grade` puts a failing student file back to its stub in its scratch
//! copy. `check` runs in the student's own workspace, which it never
//! changes: it builds instead in a copy where only the chapter's folder is
//! real (with the exercises that do not compile as their committed stubs)
//! and every other file of the workspace is a symbolic link to the
//! original. That copy builds into the same target folder: every other
//! crate's artifacts are the ones the workspace's own build makes (with
//! its settings, where it builds into a target folder not its own), and
//! the chapter's are apart (a setting of their own, as
//! [`crate::separate_artifacts`] explains), so only the chapter is
//! compiled again, and neither build takes the other's chapter for fresh.

use std::path::{Path, PathBuf};

use raystep_figure::Chapter;

use raystep_check::verdicts::{BuildFailure, CargoFailure, Report, Verdict};

use crate::error::Error;
use crate::run_options::Run;
use crate::test_build::{Artifacts, build, cargo_program};
use crate::test_run::run_built;
use crate::{committed_stubs, workspace_copy};

/// `chapters/<package>/exercise/x.rs:3:9` → `exercise/x.rs:3:9`.
fn in_package<'a>(at: &'a str, package: &str) -> &'a str {
    at.strip_prefix(&format!("chapters/{package}/"))
        .unwrap_or(at)
}

/// The exercises (among `candidates`) whose own file or test file holds a
/// compiler error.
pub fn blamed_files(
    failure: &BuildFailure, package: &str, candidates: &[String],
) -> Vec<String> {
    candidates
        .iter()
        .filter(|exercise| {
            failure.errors.iter().any(|error| {
                error.at.as_deref().is_some_and(|at| {
                    let at = in_package(at, package);
                    at.starts_with(&format!("exercise/{exercise}.rs:"))
                        || at.starts_with(&format!("tests/{exercise}.rs:"))
                })
            })
        })
        .cloned()
        .collect()
}

/// The first compiler error in the exercise's own files, else the build's
/// first error.
pub fn compile_message(
    failure: &BuildFailure, package: &str, exercise: &str,
) -> String {
    let own = failure.errors.iter().find_map(|error| {
        let at = in_package(error.at.as_deref()?, package);
        (at.starts_with(&format!("exercise/{exercise}.rs:"))
            || at.starts_with(&format!("tests/{exercise}.rs:")))
        .then(|| format!("{} (at {at})", error.message))
    });
    own.unwrap_or_else(|| failure.failure.to_string())
}

/// The report of `check` when the chapter at `root` did not compile
/// (`failure`): the exercises whose files hold the errors do not compile,
/// the others are judged in a copy where those are their stubs. `None`
/// when that cannot be told: no error is in an exercise's files, every
/// exercise has one, the stubs are not to be had, or the copy does not
/// build either.
pub fn check_others(
    root: &Path, chapter: &Chapter, run: &Run, failure: &BuildFailure,
) -> Result<Option<Report>, Error> {
    if !matches!(failure.failure, CargoFailure::DoesNotCompile(_))
        || !cfg!(unix)
    {
        return Ok(None);
    }
    let exercises: Vec<String> =
        chapter.exercises.iter().map(|e| e.to_string()).collect();
    let mut blamed: Vec<(String, String)> =
        blamed_files(failure, chapter.package, &exercises)
            .into_iter()
            .map(|e| {
                let message = compile_message(failure, chapter.package, &e);
                (e, message)
            })
            .collect();
    if blamed.is_empty() || blamed.len() == exercises.len() {
        return Ok(None);
    }
    let Ok(stubs) = committed_stubs::committed(root, &[chapter]) else {
        return Ok(None);
    };
    let scratch = tempfile::Builder::new()
        .prefix("raystep-check-")
        .tempdir()
        .map_err(|e| Error::io(&std::env::temp_dir(), e))?;
    let copy = scratch.path().join("workspace");
    link_all_but(root, &copy, chapter)?;
    let target = target_dir(root, run);
    let isolated = Run {
        target_dir: Some(target),
        sandbox: run
            .sandbox
            .as_ref()
            .map(|sandbox| sandbox.also_writable(scratch.path())),
        ..run.clone()
    };
    if !run.quiet {
        let names: Vec<&str> = blamed.iter().map(|(e, _)| e.as_str()).collect();
        eprintln!(
            "{} do{} not compile: the other exercises are checked with {} \
             stub{}…",
            names.join(", "),
            if names.len() == 1 { "es" } else { "" },
            if names.len() == 1 { "its" } else { "their" },
            if names.len() == 1 { "" } else { "s" },
        );
    }
    let cargo = cargo_program();
    loop {
        let dir = copy.join("chapters").join(chapter.package);
        for (exercise, _) in &blamed {
            let path = dir.join("exercise").join(format!("{exercise}.rs"));
            std::fs::write(&path, stubs.text(chapter, exercise))
                .map_err(|e| Error::io(&path, e))?;
        }
        match build(
            &cargo,
            &copy,
            chapter.package,
            &isolated,
            Artifacts::OwnPackage(root),
        )? {
            Ok(built) => {
                let mut report = run_built(&copy, chapter, run, built);
                for (exercise, verdict) in &mut report.exercises {
                    if let Some((_, message)) =
                        blamed.iter().find(|(e, _)| e == exercise)
                    {
                        *verdict = Verdict::NotBuilt(
                            CargoFailure::DoesNotCompile(message.clone()),
                        );
                    }
                }
                // The copy's held-out program is gone with the copy.
                report.held_out_runner = None;
                return Ok(Some(report));
            }
            Err(again) => {
                let left: Vec<String> = exercises
                    .iter()
                    .filter(|e| !blamed.iter().any(|(b, _)| b == *e))
                    .cloned()
                    .collect();
                let more = blamed_files(&again, chapter.package, &left);
                if more.is_empty() || more.len() == left.len() {
                    return Ok(None);
                }
                blamed.extend(more.into_iter().map(|e| {
                    let message = compile_message(&again, chapter.package, &e);
                    (e, message)
                }));
            }
        }
    }
}

/// The target folder a build of the workspace at `root` uses: `--target-dir`,
/// else `CARGO_TARGET_DIR`, else `root/target`; absolute.
fn target_dir(root: &Path, run: &Run) -> PathBuf {
    let dir = run
        .target_dir
        .clone()
        .or_else(|| std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from))
        .unwrap_or_else(|| root.join("target"));
    if dir.is_absolute() {
        dir
    } else {
        root.join(dir)
    }
}

/// `copy` becomes the workspace at `root` with every entry a symbolic link
/// to the original, but for `chapters/<chapter>`, which is copied, and the
/// build output and git's folder, which are left out.
fn link_all_but(
    root: &Path, copy: &Path, chapter: &Chapter,
) -> Result<(), Error> {
    let root = root.canonicalize().map_err(|e| Error::io(root, e))?;
    let link = |from: &Path, to: &Path| -> Result<(), Error> {
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(from, to).map_err(|e| Error::io(to, e))
        }
        #[cfg(not(unix))]
        {
            let _ = (from, to);
            Err(Error::Usage("no symbolic links here".into()))
        }
    };
    let entries = |dir: &Path| -> Result<Vec<PathBuf>, Error> {
        let mut all: Vec<PathBuf> = std::fs::read_dir(dir)
            .map_err(|e| Error::io(dir, e))?
            .flatten()
            .map(|e| e.path())
            .collect();
        all.sort();
        Ok(all)
    };
    let chapters = copy.join("chapters");
    std::fs::create_dir_all(&chapters).map_err(|e| Error::io(&chapters, e))?;
    for entry in entries(&root)? {
        let name = entry.file_name().unwrap_or_default();
        if name == "chapters" || name == "target" || name == ".git" {
            continue;
        }
        link(&entry, &copy.join(name))?;
    }
    for entry in entries(&root.join("chapters"))? {
        let name = entry.file_name().unwrap_or_default();
        let to = chapters.join(name);
        if name == chapter.package {
            workspace_copy::copy_sources(&entry, &to, &[])?;
        } else {
            link(&entry, &to)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_check::verdicts::CompileError;

    use crate::test_files::names;

    #[test]
    fn compiler_errors_blame_the_file_they_are_in() {
        let failure = BuildFailure {
            failure: CargoFailure::DoesNotCompile("error[E0308]".into()),
            errors: vec![
                CompileError {
                    message: "error[E0425]: cannot find value `x`".into(),
                    at: Some(
                        "chapters/ch02-x/exercise/ray_plane.rs:9:5".into(),
                    ),
                },
                CompileError {
                    message: "error[E0061]: wrong arguments".into(),
                    at: Some(
                        "chapters/ch02-x/tests/inside_polygon.rs:3:1".into(),
                    ),
                },
            ],
        };
        let submitted = names(&["ray_plane", "inside_polygon", "third"]);
        assert_eq!(
            blamed_files(&failure, "ch02-x", &submitted),
            ["ray_plane", "inside_polygon"]
        );
        assert_eq!(
            compile_message(&failure, "ch02-x", "ray_plane"),
            "error[E0425]: cannot find value `x` (at exercise/ray_plane.rs:9:5)"
        );
        assert_eq!(
            compile_message(&failure, "ch02-x", "third"),
            "the tests do not compile: error[E0308]"
        );
    }
}
