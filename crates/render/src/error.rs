//! [`RenderError`]: what can go wrong while rendering, reading or writing.

use std::io;
use std::path::PathBuf;

/// Everything that can go wrong while rendering, reading or writing an
/// image. Each message names the argument or the file at fault.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RenderError {
    /// `RenderOptions::threads` was `Some(0)`.
    #[error(
        "render option `threads` is 0: use Some(n) with n ≥ 1 for n threads, or None for all cores"
    )]
    ZeroThreads,
    /// The dedicated thread pool could not be created.
    #[error("could not start a thread pool of {threads} threads: {source}")]
    ThreadPool {
        /// How many threads were asked for.
        threads: usize,
        /// Why rayon could not build the pool.
        source: rayon::ThreadPoolBuildError,
    },
    /// A width or height of 0 (or a pixel count too large to hold).
    #[error(
        "cannot make a {width}×{height} image: width and height must be at least 1 and the pixel count must fit in memory"
    )]
    InvalidSize {
        /// The requested width.
        width: u32,
        /// The requested height.
        height: u32,
    },
    /// Writing a PNG file failed.
    #[error("could not write PNG file {}: {source}", path.display())]
    Write {
        /// The file that was to be written.
        path: PathBuf,
        /// The underlying I/O error.
        source: io::Error,
    },
    /// Reading a PNG file failed.
    #[error("could not read PNG file {}: {source}", path.display())]
    Read {
        /// The file that was to be read.
        path: PathBuf,
        /// The underlying I/O error.
        source: io::Error,
    },
    /// A file was read but is not a PNG image the decoder understands.
    #[error("could not decode PNG file {}: {source}", path.display())]
    Decode {
        /// The file that was read.
        path: PathBuf,
        /// What the decoder reported.
        source: ::image::ImageError,
    },
}
