//! Files written whole or not at all: the bytes go to a temporary file
//! beside the target, which then replaces it in one rename. A reader never
//! sees half a file, and a failure leaves the old file as it was.

use std::io::Write;
use std::path::Path;

use crate::error::Error;

/// An error naming `path` if [`write`] could not write it: its folder
/// does not exist, or it is a folder. To check before long work.
pub fn can_write(path: &Path) -> Result<(), Error> {
    let folder = folder_of(path);
    if path.is_dir() {
        return Err(Error::io(path, std::io::Error::other("is a folder")));
    }
    if !folder.is_dir() {
        return Err(Error::io(
            path,
            std::io::Error::other(format!(
                "no folder {} to write it in",
                folder.display()
            )),
        ));
    }
    Ok(())
}

/// The folder a file goes in (`.` for a bare file name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    }
}

/// Writes `bytes` to `path` atomically; errors name `path`.
pub fn write(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let error = |source| Error::io(path, source);
    let folder = folder_of(path);
    if path.is_dir() {
        return Err(error(std::io::Error::other("is a folder")));
    }
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".partial");
    // A report anyone may read, as `fs::write` would make it (a temporary
    // file is private by default).
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o644));
    let mut file = builder.tempfile_in(folder).map_err(error)?;
    file.write_all(bytes).map_err(error)?;
    file.as_file().sync_all().map_err(error)?;
    file.persist(path).map_err(|e| error(e.error))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_replaced_whole_and_nothing_is_left_beside_it() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("report.json");
        write(&path, b"first").unwrap();
        write(&path, b"second").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "second");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&path).unwrap().permissions().mode();
            assert_eq!(mode & 0o644, 0o644, "readable by all: {mode:o}");
        }
        let names: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, ["report.json"]);
    }

    #[test]
    fn errors_name_the_path() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("no/such/folder/out.csv");
        let error = write(&missing, b"x").unwrap_err().to_string();
        assert!(error.starts_with(&missing.display().to_string()), "{error}");
        let error = write(dir.path(), b"x").unwrap_err().to_string();
        assert!(error.ends_with("is a folder"), "{error}");
        let error = can_write(&missing).unwrap_err().to_string();
        assert!(
            error.starts_with(&missing.display().to_string())
                && error.contains(": no folder ")
                && error.ends_with("no/such/folder to write it in"),
            "{error}"
        );
        assert!(can_write(&dir.path().join("new.csv")).is_ok());
    }
}
