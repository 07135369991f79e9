//! What can go wrong turning figures into files. Every message names the figure or the path.

use std::io;
use std::path::PathBuf;

/// An error rendering, writing or checking figures.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// usvg rejected the SVG source the page produced (a bug in the figure kit or a `raw_svg`).
    #[error("figure {figure}: the drawn SVG does not parse: {message}")]
    Parse {
        /// Figure name.
        figure: String,
        /// usvg's description.
        message: String,
    },
    /// The page is too large (or small) to rasterise.
    #[error("figure {figure}: cannot rasterise a {width} × {height} px image")]
    Rasterise {
        /// Figure name.
        figure: String,
        /// Image width in pixels.
        width: u32,
        /// Image height in pixels.
        height: u32,
    },
    /// PNG encoding failed.
    #[error("figure {figure}: cannot encode the PNG: {message}")]
    EncodePng {
        /// Figure name.
        figure: String,
        /// The encoder's description.
        message: String,
    },
    /// A figure name that is not a plain file stem.
    #[error(
        "figure name {name:?} is not a plain file stem (use letters, digits, '-' and '_')"
    )]
    BadName {
        /// The offending name.
        name: String,
    },
    /// Two figures would write the same files.
    #[error("two figures are named {name}")]
    DuplicateName {
        /// The repeated name.
        name: String,
    },
    /// The output directory could not be created.
    #[error("cannot create directory {path}: {source}")]
    CreateDir {
        /// The directory.
        path: PathBuf,
        /// The cause.
        source: io::Error,
    },
    /// A file could not be written (or moved into place).
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: io::Error,
    },
    /// A file or directory could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file or directory.
        path: PathBuf,
        /// The cause.
        source: io::Error,
    },
}
