//! Where a test binary ran: the folders that the snapshot files its
//! failures name are read from, and that panic locations are said relative
//! to (`tests/recursion.rs:212`, not an absolute path or `src/../`).

use std::path::{Path, PathBuf};

/// Where a test binary ran: to read the snapshot files its failures name,
/// and to say panic locations relative to the package.
#[derive(Debug, Clone, Default)]
pub struct Context {
    /// The workspace root (rustc's and insta's paths are relative to it).
    pub workspace: Option<PathBuf>,
    /// The package folder.
    pub package: Option<PathBuf>,
}

impl Context {
    /// The text of a snapshot file insta named (relative to the workspace
    /// root, or to the package).
    pub(crate) fn snapshot(&self, file: &str) -> Option<String> {
        [&self.workspace, &self.package]
            .into_iter()
            .flatten()
            .find_map(|dir| std::fs::read_to_string(dir.join(file)).ok())
    }

    /// `path:line[:column]` as `path:line`, the path relative to the
    /// package when it is inside it, without `src/../`; `None` for a path
    /// outside the workspace (a library, the standard library).
    pub fn location(&self, raw: &str) -> Option<String> {
        let is_number =
            |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
        let (rest, last) = raw.trim().rsplit_once(':')?;
        let (path, line) = match rest.rsplit_once(':') {
            Some((path, line)) if is_number(line) && is_number(last) => {
                (path, line)
            }
            _ if is_number(last) => (rest, last),
            _ => return None,
        };
        let path = lexically_normal(Path::new(path));
        let absolute = if path.is_absolute() {
            path.clone()
        } else {
            match &self.workspace {
                Some(root) => lexically_normal(&root.join(&path)),
                None => return Some(format!("{}:{line}", slashed(&path))),
            }
        };
        let within = |dir: &Option<PathBuf>| {
            let dir = lexically_normal(dir.as_ref()?);
            absolute.strip_prefix(dir).ok().map(Path::to_path_buf)
        };
        let shown =
            within(&self.package).or_else(|| within(&self.workspace))?;
        Some(format!("{}:{line}", slashed(&shown)))
    }
}

/// `a/src/../b` as `a/b`, `./a` as `a` (without touching the file system).
pub fn lexically_normal(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut normal = PathBuf::new();
    for part in path.components() {
        match part {
            Component::CurDir => {}
            Component::ParentDir
                if matches!(
                    normal.components().next_back(),
                    Some(Component::Normal(_))
                ) =>
            {
                normal.pop();
            }
            other => normal.push(other),
        }
    }
    normal
}

/// A relative path with `/` between its parts, on every system.
fn slashed(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}
