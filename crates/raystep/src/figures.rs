//! `raystep figures`: draw every lecture figure into the book, or check that
//! the committed ones are up to date.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::chapters::{CHAPTERS, find};
use crate::error::Error;
use crate::shown_path::{relative, shown};
use crate::{atomic_file, questions, workspace};
use raystep_figure::{Chapter, Format};

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

/// Runs `raystep figures`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let chapters: Vec<&Chapter> = match &options.chapter {
        Some(arg) => vec![find(arg, CHAPTERS)?],
        None => CHAPTERS.to_vec(),
    };
    let out = match &options.out {
        Some(out) => out.clone(),
        None => relative(&workspace::figures_dir(&workspace::root())),
    };
    if options.check {
        check(&chapters, &out, options.format)
    } else {
        write(&chapters, &out, options.format)
    }
}

/// Writes every figure and lists the files.
fn write(
    chapters: &[&Chapter], out: &Path, format: Format,
) -> Result<ExitCode, Error> {
    let mut counts = Vec::new();
    let mut total = 0;
    for chapter in chapters {
        let id = chapter.id;
        let written = raystep_figure::write_all(
            &chapter.all_figures(),
            &out.join(id),
            format,
        )?;
        for path in &written {
            println!("{}", shown(path));
        }
        let mut count = written.len();
        // The paper questions, with the answers the code computes.
        if let Some(file) = questions::from_code(chapter) {
            let path = out.join(id).join("questions.toml");
            atomic_file::write(
                &path,
                questions::text(chapter, &file).as_bytes(),
            )?;
            println!("{}", shown(&path));
            count += 1;
            // The answers' stub asks the same questions.
            let root = workspace::root();
            if let Some(stub) = questions::refresh_stub(&root, chapter, &file)?
            {
                println!("{}", shown(&relative(&stub)));
            }
        }
        total += count;
        counts.push(format!("{id}: {count}"));
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
fn check(
    chapters: &[&Chapter], out: &Path, format: Format,
) -> Result<ExitCode, Error> {
    let mut mismatches = Vec::new();
    let mut expected = 0;
    for chapter in chapters {
        let figures = chapter.all_figures();
        expected += figures.len() * format.extensions().len();
        mismatches.extend(
            raystep_figure::check_all(&figures, &out.join(chapter.id), format)?
                .iter()
                .map(ToString::to_string),
        );
        if let Some(file) = questions::from_code(chapter) {
            expected += 1;
            let path = out.join(chapter.id).join("questions.toml");
            match std::fs::read_to_string(&path) {
                Ok(text) if text == questions::text(chapter, &file) => {}
                Ok(_) => {
                    mismatches.push(format!("differs: {}", path.display()))
                }
                Err(_) => {
                    mismatches.push(format!("missing: {}", path.display()))
                }
            }
        }
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
