use std::path::PathBuf;

use thiserror::Error;

/// Why a benchmark cannot run. Each names the file or the argument.
#[derive(Debug, Error)]
pub enum BenchError {
    /// The mesh cannot be read.
    #[error("{0}")]
    Mesh(#[from] raystep_scene::MeshError),
    /// A ray file cannot be read.
    #[error("{}: {message}", file.display())]
    RayFile {
        /// The file as given.
        file: PathBuf,
        /// What is wrong with it.
        message: String,
    },
    /// An argument that parses but cannot be used.
    #[error("{argument}: {message}")]
    Argument {
        /// The argument, as `--threads`.
        argument: &'static str,
        /// What is wrong with its value.
        message: String,
    },
}
