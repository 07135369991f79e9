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

/// The width of the book's content column in CSS px. The book shows a
/// figure up to this wide at 1:1 (one page px is one CSS px); a wider one
/// is shrunk, and its text with it. Every figure fits it.
pub const BOOK_COLUMN_PX: f64 = 900.0;

/// The smallest text a figure may have, in page px (so in CSS px in the
/// book): sub- and superscripts, tick labels and notes included. Smaller
/// text is hard to read on a screen.
pub const MIN_TEXT_PX: f64 = 11.0;

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
#[derive(Clone, Debug, PartialEq)]
pub struct Rendered {
    /// The SVG file.
    pub svg: Vec<u8>,
    /// The PNG file (2× the page size).
    pub png: Vec<u8>,
    /// The page width in page px.
    pub width: f64,
    /// The font size of the smallest text on the page in page px (every
    /// span, sub- and superscripts included, scaled by any transform), or
    /// `None` for a page without text. The SVG file records it in a comment
    /// (see [`smallest_text_comment`]).
    pub smallest_text: Option<f64>,
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
    let smallest_text = smallest_text(tree.root());
    let svg = with_comment(
        &tree.to_string(&write),
        &smallest_text_comment(smallest_text),
    )
    .into_bytes();

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
    Ok(Rendered {
        svg,
        png,
        width: f64::from(tree.size().width()),
        smallest_text,
    })
}

/// The font size of the smallest non-blank text span under `group`, in
/// page px: each span's size scaled by the text's transform (its area
/// scale, so a rotation keeps the size).
fn smallest_text(group: &usvg::Group) -> Option<f64> {
    let mut smallest: Option<f64> = None;
    for node in group.children() {
        let size = match node {
            usvg::Node::Group(g) => smallest_text(g),
            usvg::Node::Text(text) => {
                let t = text.abs_transform();
                let scale = f64::from((t.sx * t.sy - t.kx * t.ky).abs()).sqrt();
                text.chunks()
                    .iter()
                    .flat_map(|chunk| {
                        chunk.spans().iter().filter(|span| {
                            chunk.text()[span.start()..span.end()]
                                .chars()
                                .any(|c| !c.is_whitespace())
                        })
                    })
                    .map(|span| f64::from(span.font_size().get()) * scale)
                    .reduce(f64::min)
            }
            _ => None,
        };
        if let Some(size) = size {
            smallest = Some(smallest.map_or(size, |s| s.min(size)));
        }
    }
    smallest
}

/// The comment the SVG file records its smallest text in, rounded down to
/// 0.1 px so it never says more than is there:
/// `<!-- raystep: smallest text 11.2 px -->` (`no text` without text).
pub fn smallest_text_comment(size: Option<f64>) -> String {
    match size {
        // to 4 decimals first: a size of 11.2 is 11.1999998 as an f32
        Some(size) => {
            let tenths = ((size * 1e4).round() / 1e3).floor() / 10.0;
            format!("<!-- raystep: smallest text {tenths:.1} px -->")
        }
        None => "<!-- raystep: no text -->".to_string(),
    }
}

/// `svg` with `comment` on its own line right after the opening `<svg ...>`
/// element.
fn with_comment(svg: &str, comment: &str) -> String {
    let end = svg
        .find("<svg")
        .and_then(|start| svg[start..].find('>').map(|end| start + end + 1))
        .unwrap_or(0);
    format!("{}\n{comment}{}", &svg[..end], &svg[end..])
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
    figures: &[Figure], dir: &Path, format: Format,
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
    figures: &[Figure], dir: &Path, format: Format,
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
