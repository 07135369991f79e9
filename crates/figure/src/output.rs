//! From a figure to bytes (SVG and PNG) and files.
//!
//! The page's SVG source is parsed by usvg with a font database holding only the embedded
//! DejaVu Sans, so every label becomes glyph outlines and nothing depends on the fonts of the
//! machine. The SVG file is written back from the parsed tree with fixed precision; the PNG is
//! the same tree rendered by resvg at 2× on white. Both are byte-identical from run to run.

use std::collections::BTreeSet;
use std::fmt;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

use resvg::tiny_skia;
use resvg::usvg;

use crate::Figure;
use crate::error::FigureError;

/// PNG pixels per page px.
const PNG_SCALE: f32 = 2.0;

/// Which files to write or check.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// `<name>.svg` only.
    Svg,
    /// `<name>.png` only.
    Png,
    /// Both.
    Both,
}

impl Format {
    /// The file extensions of this format.
    pub fn extensions(self) -> &'static [&'static str] {
        match self {
            Format::Svg => &["svg"],
            Format::Png => &["png"],
            Format::Both => &["svg", "png"],
        }
    }
}

impl std::str::FromStr for Format {
    type Err = String;

    /// `svg`, `png` or `both`.
    fn from_str(s: &str) -> Result<Format, String> {
        match s {
            "svg" => Ok(Format::Svg),
            "png" => Ok(Format::Png),
            "both" => Ok(Format::Both),
            other => Err(format!(
                "unknown format {other:?} (expected svg, png or both)"
            )),
        }
    }
}

/// A rendered figure: the SVG file's bytes (text as outlines) and the PNG file's bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rendered {
    /// The SVG file.
    pub svg: Vec<u8>,
    /// The PNG file (2× the page size).
    pub png: Vec<u8>,
}

impl Rendered {
    /// The bytes of the file with extension `ext` ("svg" or "png").
    fn bytes(&self, ext: &str) -> &[u8] {
        if ext == "svg" { &self.svg } else { &self.png }
    }
}

/// A committed figure file that does not match what the code draws now.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Mismatch {
    /// The file exists but its bytes differ.
    Differs(PathBuf),
    /// A figure would write this file but it does not exist.
    Missing(PathBuf),
    /// A `.svg`/`.png` file in the directory that no figure produces.
    Extra(PathBuf),
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Mismatch::Differs(p) => write!(f, "differs: {}", p.display()),
            Mismatch::Missing(p) => write!(f, "missing: {}", p.display()),
            Mismatch::Extra(p) => write!(f, "extra: {}", p.display()),
        }
    }
}

/// Parse options whose font database holds only the embedded DejaVu Sans.
fn usvg_options() -> usvg::Options<'static> {
    static FONTS: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    let fontdb = FONTS.get_or_init(|| {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(dejavu::sans::regular().to_vec());
        db.set_sans_serif_family("DejaVu Sans");
        Arc::new(db)
    });
    usvg::Options {
        font_family: "DejaVu Sans".to_string(),
        fontdb: Arc::clone(fontdb),
        ..usvg::Options::default()
    }
}

/// Renders a figure to SVG and PNG bytes.
pub fn render(figure: &Figure) -> Result<Rendered, FigureError> {
    let source = figure.page.to_svg_source();
    let tree = usvg::Tree::from_str(&source, &usvg_options()).map_err(|e| {
        FigureError::Parse {
            figure: figure.name.clone(),
            message: e.to_string(),
        }
    })?;

    let write = usvg::WriteOptions {
        coordinates_precision: 2,
        transforms_precision: 4,
        indent: usvg::Indent::Spaces(1),
        ..usvg::WriteOptions::default()
    };
    let svg = tree.to_string(&write).into_bytes();

    let width = (tree.size().width() * PNG_SCALE).ceil() as u32;
    let height = (tree.size().height() * PNG_SCALE).ceil() as u32;
    let mut pixmap =
        tiny_skia::Pixmap::new(width, height).ok_or_else(|| {
            FigureError::Rasterise {
                figure: figure.name.clone(),
                width,
                height,
            }
        })?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(PNG_SCALE, PNG_SCALE),
        &mut pixmap.as_mut(),
    );
    let png = pixmap.encode_png().map_err(|e| FigureError::EncodePng {
        figure: figure.name.clone(),
        message: e.to_string(),
    })?;
    Ok(Rendered { svg, png })
}

/// Checks that figure names are plain, distinct file stems.
fn check_names(figures: &[Figure]) -> Result<(), FigureError> {
    let mut seen = BTreeSet::new();
    for figure in figures {
        let name = &figure.name;
        let plain = !name.is_empty()
            && !name.starts_with('.')
            && name.chars().all(|c| {
                c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.')
            });
        if !plain {
            return Err(FigureError::BadName { name: name.clone() });
        }
        if !seen.insert(name.as_str()) {
            return Err(FigureError::DuplicateName { name: name.clone() });
        }
    }
    Ok(())
}

/// Writes `bytes` to `path` through a temporary file in the same directory and a rename, so
/// the file is either the old one or the complete new one.
fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), FigureError> {
    let file_name = path
        .file_name()
        .map(|n| n.to_string_lossy())
        .unwrap_or_default();
    let tmp =
        path.with_file_name(format!(".{file_name}.{}.tmp", std::process::id()));
    let result = (|| -> io::Result<()> {
        let mut file = fs::File::create(&tmp)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        fs::rename(&tmp, path)
    })();
    result.map_err(|source| {
        // best effort: the temporary file may not exist at all
        let _ = fs::remove_file(&tmp);
        FigureError::Write {
            path: path.to_path_buf(),
            source,
        }
    })
}

/// Writes each figure as `<dir>/<name>.svg` and/or `<dir>/<name>.png`, creating `dir`.
///
/// Each file goes to a temporary file in `dir` first and is then renamed into place, so an
/// interrupted run never leaves a half-written file. Returns the paths written, in figure order.
pub fn write_all(
    figures: &[Figure],
    dir: &Path,
    format: Format,
) -> Result<Vec<PathBuf>, FigureError> {
    check_names(figures)?;
    fs::create_dir_all(dir).map_err(|source| FigureError::CreateDir {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut written = Vec::new();
    for figure in figures {
        let rendered = render(figure)?;
        for ext in format.extensions() {
            let path = dir.join(format!("{}.{ext}", figure.name));
            write_atomically(&path, rendered.bytes(ext))?;
            written.push(path);
        }
    }
    Ok(written)
}

/// Compares the files in `dir` with what the figures draw now, without writing anything.
///
/// Returns one entry per file that differs or is missing (in figure order), then one per extra
/// file: a file in `dir` with an extension of `format` (`.svg` and/or `.png`) that no figure
/// produces (sorted by name). A missing `dir` makes every file missing.
pub fn check_all(
    figures: &[Figure],
    dir: &Path,
    format: Format,
) -> Result<Vec<Mismatch>, FigureError> {
    check_names(figures)?;
    let mut mismatches = Vec::new();
    let mut expected = BTreeSet::new();
    for figure in figures {
        let rendered = render(figure)?;
        for ext in format.extensions() {
            let path = dir.join(format!("{}.{ext}", figure.name));
            match fs::read(&path) {
                Ok(bytes) if bytes == rendered.bytes(ext) => {}
                Ok(_) => mismatches.push(Mismatch::Differs(path.clone())),
                Err(e) if e.kind() == io::ErrorKind::NotFound => {
                    mismatches.push(Mismatch::Missing(path.clone()));
                }
                Err(source) => return Err(FigureError::Read { path, source }),
            }
            expected.insert(path);
        }
    }

    let entries = match fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(mismatches),
        Err(source) => {
            return Err(FigureError::Read {
                path: dir.to_path_buf(),
                source,
            });
        }
    };
    let mut extra = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|source| FigureError::Read {
            path: dir.to_path_buf(),
            source,
        })?;
        let path = entry.path();
        let ours = path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| format.extensions().contains(&e));
        if ours && path.is_file() && !expected.contains(&path) {
            extra.push(path);
        }
    }
    extra.sort();
    mismatches.extend(extra.into_iter().map(Mismatch::Extra));
    Ok(mismatches)
}
