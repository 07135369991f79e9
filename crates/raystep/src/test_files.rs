//! What the unit tests share: files written into scratch folders, and
//! lists of names.

use std::path::Path;

/// Writes `text` to `path`, making its folder first.
pub fn write(path: &Path, text: &str) {
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, text).unwrap();
}

/// A new scratch folder holding `files` (paths below it), each holding
/// its own path; removed when dropped.
pub fn folder_with(files: &[&str]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for file in files {
        write(&dir.path().join(file), file);
    }
    dir
}

/// The names as owned strings.
pub fn names(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| s.to_string()).collect()
}
