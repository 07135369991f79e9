//! One error type: every message names the page and line.

use std::path::PathBuf;

/// Why a page cannot be turned into what the book shows.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}:{line}: {message}", page.display())]
pub struct BookError {
    /// The markdown page.
    pub page: PathBuf,
    /// Its 1-based line.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}
