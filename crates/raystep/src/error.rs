//! Everything that stops a command, shown as one line on stderr.

use std::io;
use std::path::{Path, PathBuf};

use crate::shown_path::shown;

/// Everything that stops a command; shown as one line on stderr.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The chapter argument names no chapter.
    #[error("{wanted}: no such chapter; chapters are {known}")]
    NoSuchChapter {
        /// The normalised argument, `ch99`.
        wanted: String,
        /// `ch01, ch02`.
        known: String,
    },
    /// A file or folder could not be read or written.
    #[error("{}: {source}", shown(path))]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// What went wrong.
        source: io::Error,
    },
    /// The figure kit failed (its message names the path).
    #[error(transparent)]
    Figure(#[from] raystep_figure::FigureError),
    /// A bad argument or input file; the message names it.
    #[error("{0}")]
    Usage(String),
    /// `cargo` could not be started.
    #[error("cannot run `{program}`: {source}")]
    Spawn {
        /// The cargo program.
        program: String,
        /// What went wrong.
        source: io::Error,
    },
}

impl Error {
    /// A file or folder at `path` could not be read or written.
    pub fn io(path: &Path, source: io::Error) -> Error {
        Error::Io {
            path: path.to_path_buf(),
            source,
        }
    }
}
