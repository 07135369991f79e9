//! Running `git` in a folder, apart from the caller's repository
//! variables (`GIT_DIR`, `GIT_WORK_TREE`, `GIT_INDEX_FILE`), with nothing
//! on its stdin; `None` when git is not installed.

use std::io;
use std::path::Path;
use std::process::{Command, Output, Stdio};

use crate::error::Error;

/// `git <args>` in `dir`, its output captured; `None` if there is no git.
pub fn git(dir: &Path, args: &[&str]) -> Result<Option<Output>, Error> {
    let out = Command::new("git")
        .args(args)
        .current_dir(dir)
        .env_remove("GIT_DIR")
        .env_remove("GIT_WORK_TREE")
        .env_remove("GIT_INDEX_FILE")
        .stdin(Stdio::null())
        .output();
    match out {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(Error::Spawn {
            program: "git".to_string(),
            source: e,
        }),
        Ok(out) => Ok(Some(out)),
    }
}
