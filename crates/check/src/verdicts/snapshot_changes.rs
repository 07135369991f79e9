//! Snapshot files that are not the reference: changed or new `.snap` files
//! in a chapter's `tests/snapshots` (against git's `HEAD`, when the chapter
//! is in a git repository) and insta's proposals (`*.snap.new`,
//! `*.pending-snap`). A test compared with such a file proves nothing, so
//! `raystep check` names them.

use std::fmt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// How a snapshot file differs from the reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Change {
    /// A committed snapshot was edited.
    Modified,
    /// A committed snapshot was deleted.
    Deleted,
    /// A snapshot that was never committed.
    New,
    /// insta's proposal for a new snapshot (`.snap.new`, `.pending-snap`).
    Proposal,
}

impl fmt::Display for Change {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Change::Modified => "changed",
            Change::Deleted => "deleted",
            Change::New => "new, not committed",
            Change::Proposal => "insta's proposal",
        })
    }
}

/// A snapshot file that is not the reference.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct ChangedSnapshot {
    /// Relative to the package folder: `tests/snapshots/x__y.snap`.
    pub path: String,
    /// How.
    pub change: Change,
}

/// The snapshot files of the package in `package_dir` that are not the
/// reference, sorted by path. Without git (or outside a repository) only
/// insta's proposals are found.
pub fn changed_snapshots(package_dir: &Path) -> Vec<ChangedSnapshot> {
    let dir = package_dir.join("tests").join("snapshots");
    let mut changed = proposals(&dir);
    changed.extend(against_head(package_dir));
    changed.sort();
    changed
}

/// `*.snap.new` and `*.pending-snap` files in `dir` and below.
fn proposals(dir: &Path) -> Vec<ChangedSnapshot> {
    let mut found = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            let name = entry.file_name().to_string_lossy().into_owned();
            if is_proposal(&name) {
                found.push(ChangedSnapshot {
                    path: package_relative(dir, &path),
                    change: Change::Proposal,
                });
            }
        }
    }
    found
}

/// insta's proposal for a snapshot: `*.snap.new`, `*.pending-snap`.
fn is_proposal(name: &str) -> bool {
    name.ends_with(".snap.new") || name.ends_with(".pending-snap")
}

/// `tests/snapshots/<below dir>`, with `/` between folders.
fn package_relative(dir: &Path, path: &Path) -> String {
    let below = path.strip_prefix(dir).unwrap_or(path);
    let mut text = String::from("tests/snapshots");
    for part in below.components() {
        text.push('/');
        text.push_str(&part.as_os_str().to_string_lossy());
    }
    text
}

/// The snapshot files git sees as modified, deleted or new (untracked and
/// not ignored) against `HEAD`; nothing if git cannot tell.
fn against_head(package_dir: &Path) -> Vec<ChangedSnapshot> {
    let git = |args: &[&str]| -> Option<String> {
        let out = Command::new("git")
            .args(args)
            .current_dir(package_dir)
            .stdin(Stdio::null())
            .stderr(Stdio::null())
            .output()
            .ok()?;
        out.status
            .success()
            .then(|| String::from_utf8_lossy(&out.stdout).into_owned())
    };
    let Some(diff) = git(&[
        "diff",
        "--name-status",
        "--no-renames",
        "--relative",
        "-z",
        "HEAD",
        "--",
        "tests/snapshots",
    ]) else {
        return Vec::new();
    };
    let mut changed = Vec::new();
    let mut fields = diff.split('\0');
    while let (Some(status), Some(path)) = (fields.next(), fields.next()) {
        let change = match status {
            "D" => Change::Deleted,
            "A" => Change::New,
            _ => Change::Modified,
        };
        changed.push(ChangedSnapshot {
            path: path.to_string(),
            change,
        });
    }
    let untracked = git(&[
        "ls-files",
        "--others",
        "--exclude-standard",
        "-z",
        "--",
        "tests/snapshots",
    ])
    .unwrap_or_default();
    changed.extend(
        untracked
            .split('\0')
            .filter(|p| !p.is_empty() && !is_proposal(p))
            .map(|path| ChangedSnapshot {
                path: path.to_string(),
                change: Change::New,
            }),
    );
    changed
}

/// What to tell the user, line by line: which files, and how to get the
/// reference back (`package` is the package folder, as the user would type it).
pub fn advice(changed: &[ChangedSnapshot], package: &Path) -> Vec<String> {
    if changed.is_empty() {
        return Vec::new();
    }
    let mut lines = vec![
        "warning: these snapshot files are not the reference, so the tests \
         that use them prove nothing:"
            .to_string(),
    ];
    for snapshot in changed {
        lines.push(format!("  {} ({})", snapshot.path, snapshot.change));
    }
    let shown = |path: &str| {
        let path: PathBuf = package.join(path);
        path.display().to_string()
    };
    let restore: Vec<String> = changed
        .iter()
        .filter(|s| matches!(s.change, Change::Modified | Change::Deleted))
        .map(|s| shown(&s.path))
        .collect();
    if !restore.is_empty() {
        lines.push(format!(
            "restore them: git checkout -- {}",
            restore.join(" ")
        ));
    }
    let remove: Vec<String> = changed
        .iter()
        .filter(|s| matches!(s.change, Change::New | Change::Proposal))
        .map(|s| shown(&s.path))
        .collect();
    if !remove.is_empty() {
        lines.push(format!("remove them: rm {}", remove.join(" ")));
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn proposals_are_found_in_any_folder() {
        let dir = tempfile::tempdir().unwrap();
        let snapshots = dir.path().join("tests/snapshots/nested");
        std::fs::create_dir_all(&snapshots).unwrap();
        std::fs::write(snapshots.join("a__b.snap.new"), "x").unwrap();
        std::fs::write(dir.path().join("tests/snapshots/c.pending-snap"), "")
            .unwrap();
        std::fs::write(dir.path().join("tests/snapshots/d.snap"), "").unwrap();
        assert_eq!(
            changed_snapshots(dir.path()),
            [
                ChangedSnapshot {
                    path: "tests/snapshots/c.pending-snap".into(),
                    change: Change::Proposal
                },
                ChangedSnapshot {
                    path: "tests/snapshots/nested/a__b.snap.new".into(),
                    change: Change::Proposal
                },
            ]
        );
    }

    /// In a repository: edited, deleted and new snapshot files against
    /// `HEAD`, beside insta's proposals; a clean folder has none.
    #[test]
    fn changes_against_head_are_found_in_a_repository() {
        let dir = tempfile::tempdir().unwrap();
        let package = dir.path().join("chapters/ch01");
        let snapshots = package.join("tests/snapshots");
        std::fs::create_dir_all(&snapshots).unwrap();
        for name in ["a.snap", "b.snap", "kept.snap"] {
            std::fs::write(snapshots.join(name), name).unwrap();
        }
        let git = |args: &[&str]| {
            let status = Command::new("git")
                .args(["-c", "user.name=t", "-c", "user.email=t@t"])
                .args(["-c", "commit.gpgsign=false"])
                .args(args)
                .current_dir(dir.path())
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .status()
                .expect("git runs");
            assert!(status.success(), "git {args:?}");
        };
        git(&["init", "--quiet"]);
        git(&["add", "--all"]);
        git(&["commit", "--quiet", "--message", "snapshots"]);
        assert_eq!(changed_snapshots(&package), []);

        std::fs::write(snapshots.join("a.snap"), "accepted by hand").unwrap();
        std::fs::remove_file(snapshots.join("b.snap")).unwrap();
        std::fs::write(snapshots.join("c.snap"), "new").unwrap();
        std::fs::write(snapshots.join("d.snap.new"), "proposal").unwrap();
        let changed: Vec<(String, Change)> = changed_snapshots(&package)
            .into_iter()
            .map(|s| (s.path, s.change))
            .collect();
        assert_eq!(
            changed,
            [
                ("tests/snapshots/a.snap".to_string(), Change::Modified),
                ("tests/snapshots/b.snap".to_string(), Change::Deleted),
                ("tests/snapshots/c.snap".to_string(), Change::New),
                ("tests/snapshots/d.snap.new".to_string(), Change::Proposal),
            ]
        );
    }

    #[test]
    fn the_advice_names_each_file_and_the_command() {
        let changed = [
            ChangedSnapshot {
                path: "tests/snapshots/a.snap".into(),
                change: Change::Modified,
            },
            ChangedSnapshot {
                path: "tests/snapshots/b.snap.new".into(),
                change: Change::Proposal,
            },
        ];
        assert_eq!(
            advice(&changed, Path::new("chapters/ch02")),
            [
                "warning: these snapshot files are not the reference, so the \
                 tests that use them prove nothing:",
                "  tests/snapshots/a.snap (changed)",
                "  tests/snapshots/b.snap.new (insta's proposal)",
                "restore them: git checkout -- chapters/ch02/tests/snapshots/a.snap",
                "remove them: rm chapters/ch02/tests/snapshots/b.snap.new",
            ]
        );
        assert!(advice(&[], Path::new("x")).is_empty());
    }
}
