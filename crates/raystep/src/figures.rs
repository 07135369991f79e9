//! `raystep figures`: draw every lecture figure into the book, or check that
//! the committed ones are up to date.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::{Error, shown, workspace};
use raystep_figure::{Figure, Format};

/// A chapter id and the function that draws its figures.
pub type ChapterFigures = (&'static str, fn() -> Vec<Figure>);

/// Every chapter's figures, in lecture order: the one place that names the
/// chapter crates. A new chapter adds its line here (and its dependency in
/// `crates/raystep/Cargo.toml`).
pub const CHAPTERS: &[ChapterFigures] = &[
    ("ch01", ch01::figures::all),
    ("ch02", ch02::figures::all),
    ("ch03", ch03::figures::all),
    ("ch04", ch04::figures::all),
    ("ch05", ch05::figures::all),
    ("ch06", ch06::figures::all),
    ("ch07", ch07::figures::all),
];

/// What `raystep figures` was asked to do.
#[derive(Debug)]
pub struct Options {
    /// One chapter (`01`, `ch01`, …) or every chapter.
    pub chapter: Option<String>,
    /// The parent of the per-chapter folders; `<workspace>/book/src/figures` by default.
    pub out: Option<PathBuf>,
    /// Which files to draw for each figure.
    pub format: Format,
    /// Compare instead of writing.
    pub check: bool,
}

/// The figure folder of the book: `<workspace>/book/src/figures`.
pub fn default_out(root: &Path) -> PathBuf {
    root.join("book").join("src").join("figures")
}

/// Runs `raystep figures`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let chapters: Vec<ChapterFigures> = match &options.chapter {
        Some(arg) => vec![*workspace::resolve(arg, CHAPTERS, |c| c.0)?],
        None => CHAPTERS.to_vec(),
    };
    let out = match &options.out {
        Some(out) => out.clone(),
        None => crate::relative(&default_out(&workspace::root())),
    };
    if options.check {
        check(&chapters, &out, options.format)
    } else {
        write(&chapters, &out, options.format)
    }
}

/// Writes every figure and lists the files.
fn write(chapters: &[ChapterFigures], out: &Path, format: Format) -> Result<ExitCode, Error> {
    let mut counts = Vec::new();
    let mut total = 0;
    for (id, figures) in chapters {
        let written = raystep_figure::write_all(&figures(), &out.join(id), format)?;
        for path in &written {
            println!("{}", shown(path));
        }
        total += written.len();
        counts.push(format!("{id}: {}", written.len()));
    }
    println!(
        "wrote {total} {} into {} ({})",
        plural(total, "file"),
        shown(out),
        counts.join(", ")
    );
    Ok(ExitCode::SUCCESS)
}

/// Compares every figure with the files in `out`, writing nothing.
fn check(chapters: &[ChapterFigures], out: &Path, format: Format) -> Result<ExitCode, Error> {
    let mut mismatches = Vec::new();
    let mut expected = 0;
    for (id, figures) in chapters {
        let figures = figures();
        expected += figures.len() * format.extensions().len();
        mismatches.extend(raystep_figure::check_all(&figures, &out.join(id), format)?);
    }
    if mismatches.is_empty() {
        println!(
            "figures up to date ({expected} {})",
            plural(expected, "file")
        );
        return Ok(ExitCode::SUCCESS);
    }
    for mismatch in &mismatches {
        println!("{mismatch}");
    }
    eprintln!(
        "error: {} {} out of date in {}; redraw with `cargo run --release -- figures`",
        mismatches.len(),
        plural(mismatches.len(), "figure file"),
        shown(out)
    );
    Ok(ExitCode::FAILURE)
}

fn plural(n: usize, word: &str) -> String {
    if n == 1 {
        word.to_string()
    } else {
        format!("{word}s")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_figure_table_lists_every_chapter_folder_in_order() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let folders: Vec<String> = workspace::chapters(&root)
            .unwrap()
            .into_iter()
            .map(|c| c.id)
            .collect();
        let table: Vec<&str> = CHAPTERS.iter().map(|c| c.0).collect();
        assert_eq!(table, folders);
    }
}
