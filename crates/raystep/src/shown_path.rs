//! Paths as the user would type them: relative to the current folder when
//! inside it.

use std::path::{Path, PathBuf};

/// A path as the user would type it: relative to the current directory when inside it.
pub fn relative(path: &Path) -> PathBuf {
    std::env::current_dir()
        .ok()
        .and_then(|cwd| path.strip_prefix(cwd).ok().map(Path::to_path_buf))
        .filter(|rel| !rel.as_os_str().is_empty())
        .unwrap_or_else(|| path.to_path_buf())
}

/// [`relative`], for messages.
pub fn shown(path: &Path) -> String {
    relative(path).display().to_string()
}
