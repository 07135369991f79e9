//! A copy of the workspace's sources (for `raystep grade`'s scratch
//! workspace and for `raystep student-edition`): every file but build
//! output, generated output and git's own folder.

use std::fs;
use std::path::{Path, PathBuf};

use walkdir::WalkDir;

use crate::error::Error;

/// Folders never copied, wherever they are: cargo's build output, git's
/// folder (a worktree has a `.git` file instead), test output.
const SKIPPED_NAMES: &[&str] = &["target", ".git", "test-output"];

/// Folders never copied, relative to the workspace root: the book's HTML
/// (`mdbook build`), scratch output and the student's progress
/// (`.raystep/`, see `progress_file`), all in `.gitignore`.
const SKIPPED_PATHS: &[&str] = &["book/book", "out", ".raystep"];

/// Files never copied: insta's proposals for new snapshots.
const SKIPPED_SUFFIXES: &[&str] = &[".snap.new", ".pending-snap"];

/// Is the entry at `relative` (to the workspace root) left out?
pub fn is_skipped(relative: &Path) -> bool {
    let name = relative
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let slashed = relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/");
    SKIPPED_NAMES.contains(&name.as_str())
        || SKIPPED_PATHS.contains(&slashed.as_str())
        || SKIPPED_SUFFIXES.iter().any(|s| name.ends_with(s))
}

/// Copies the workspace at `from` into the folder `to` (created if need
/// be), leaving out [`is_skipped`] entries and the folders in `exclude`
/// (absolute, e.g. the copy itself when it is inside the workspace).
/// Symbolic links are copied as links. Returns the files copied, relative
/// to `from`.
pub fn copy_sources(
    from: &Path, to: &Path, exclude: &[PathBuf],
) -> Result<Vec<PathBuf>, Error> {
    let exclude: Vec<PathBuf> = exclude
        .iter()
        .map(|p| p.canonicalize().unwrap_or_else(|_| p.clone()))
        .collect();
    let from_canonical = from.canonicalize().map_err(|e| Error::io(from, e))?;
    fs::create_dir_all(to).map_err(|e| Error::io(to, e))?;
    let walk = WalkDir::new(&from_canonical)
        .follow_links(false)
        .sort_by_file_name()
        .into_iter()
        .filter_entry(|entry| {
            let relative = entry
                .path()
                .strip_prefix(&from_canonical)
                .unwrap_or(entry.path());
            !is_skipped(relative) && !exclude.iter().any(|x| x == entry.path())
        });
    let mut copied = Vec::new();
    for entry in walk {
        let entry = entry.map_err(|e| {
            let path = e.path().unwrap_or(from).to_path_buf();
            Error::io(&path, e.into())
        })?;
        let relative = entry
            .path()
            .strip_prefix(&from_canonical)
            .expect("walkdir stays below its root");
        if relative.as_os_str().is_empty() {
            continue;
        }
        let target = to.join(relative);
        let kind = entry.file_type();
        if kind.is_dir() {
            fs::create_dir_all(&target).map_err(|e| Error::io(&target, e))?;
        } else if kind.is_symlink() {
            copy_link(entry.path(), &target)?;
            copied.push(relative.to_path_buf());
        } else {
            fs::copy(entry.path(), &target)
                .map_err(|e| Error::io(entry.path(), e))?;
            copied.push(relative.to_path_buf());
        }
    }
    Ok(copied)
}

/// Recreates the symbolic link `link` at `target` (its file's content where
/// links cannot be made).
fn copy_link(link: &Path, target: &Path) -> Result<(), Error> {
    #[cfg(unix)]
    {
        let points_to = fs::read_link(link).map_err(|e| Error::io(link, e))?;
        std::os::unix::fs::symlink(points_to, target)
            .map_err(|e| Error::io(target, e))
    }
    #[cfg(not(unix))]
    {
        fs::copy(link, target)
            .map(|_| ())
            .map_err(|e| Error::io(link, e))
    }
}

/// Replaces the folder `to` with a copy of the folder `from` (its files
/// only, no sub-folders beyond what `from` holds).
pub fn replace_folder(from: &Path, to: &Path) -> Result<(), Error> {
    if to.exists() {
        fs::remove_dir_all(to).map_err(|e| Error::io(to, e))?;
    }
    if from.is_dir() {
        copy_sources(from, to, &[])?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_files::folder_with;

    #[test]
    fn build_output_and_git_are_left_out() {
        let from = folder_with(&[
            "Cargo.toml",
            "book/src/ch01.md",
            "book/book/index.html",
            "target/debug/x",
            ".git/HEAD",
            "chapters/ch01/tests/snapshots/a.snap",
            "chapters/ch01/tests/snapshots/a.snap.new",
            "chapters/ch01/target/y",
            "out/figure.svg",
            "skip-me/file",
        ]);
        let root = from.path();
        let to = tempfile::tempdir().unwrap();
        let copied =
            copy_sources(root, to.path(), &[root.join("skip-me")]).unwrap();
        let copied: Vec<String> = copied
            .iter()
            .map(|p| p.to_string_lossy().replace('\\', "/"))
            .collect();
        assert_eq!(
            copied,
            [
                "Cargo.toml",
                "book/src/ch01.md",
                "chapters/ch01/tests/snapshots/a.snap",
            ]
        );
        assert_eq!(
            fs::read_to_string(to.path().join("book/src/ch01.md")).unwrap(),
            "book/src/ch01.md"
        );
        assert!(!to.path().join("target").exists());
    }

    #[test]
    fn a_folder_is_replaced_whole() {
        let dir = tempfile::tempdir().unwrap();
        let (from, to) = (dir.path().join("from"), dir.path().join("to"));
        fs::create_dir_all(&from).unwrap();
        fs::create_dir_all(&to).unwrap();
        fs::write(from.join("a.rs"), "stub").unwrap();
        fs::write(to.join("a.rs"), "student").unwrap();
        fs::write(to.join("b.snap.new"), "proposal").unwrap();
        replace_folder(&from, &to).unwrap();
        assert_eq!(fs::read_to_string(to.join("a.rs")).unwrap(), "stub");
        assert!(!to.join("b.snap.new").exists());
    }
}
