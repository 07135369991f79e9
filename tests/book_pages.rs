//! What the book shows, page by page, after the book's preprocessing
//! (`raystep_book::preprocess`, the same code `raystep book` runs):
//!
//! - every page builds: every include, anchor and formula is good;
//! - every listing fits the column: at most 80 characters a line, and no
//!   line keeps the indentation of an `impl` block;
//! - no exercise's reference code is in the open: every line that only the
//!   reference has (not the stub, nor any other source file) appears
//!   inside a solution fold, never outside one, and every exercise region
//!   of every stub is listed;
//! - the sidebar numbers each chapter once.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

use raystep_book::{SOLUTION_OPEN, include, preprocess};

/// The longest listing line the book's column shows without a scrollbar.
const COLUMNS: usize = 80;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every page of the book, with its text as the book shows it.
fn pages() -> Vec<(PathBuf, String, String)> {
    let src = root().join("book/src");
    let mut pages: Vec<PathBuf> = fs::read_dir(&src)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    pages.sort();
    pages
        .into_iter()
        .map(|page| {
            let text = fs::read_to_string(&page).unwrap();
            let shown = preprocess(&page, &text)
                .unwrap_or_else(|e| panic!("the book does not build: {e}"));
            (page, text, shown)
        })
        .collect()
}

fn name(page: &Path) -> String {
    page.file_name().unwrap().to_string_lossy().into_owned()
}

/// The lines inside fenced code blocks, with their page line number in the
/// shown text.
fn listing_lines(shown: &str) -> Vec<(usize, &str)> {
    let mut fence: Option<String> = None;
    let mut found = Vec::new();
    for (i, line) in shown.lines().enumerate() {
        let trimmed = line.trim_start();
        let marker: String = trimmed
            .chars()
            .take_while(|c| *c == '`' || *c == '~')
            .collect();
        match &fence {
            Some(open)
                if marker.len() >= open.len()
                    && trimmed.len() == marker.len() =>
            {
                fence = None;
            }
            Some(_) => found.push((i + 1, line)),
            None if marker.len() >= 3 => fence = Some(marker),
            None => {}
        }
    }
    found
}

#[test]
fn every_listing_fits_the_column_without_impl_indent() {
    let mut wide = Vec::new();
    for (page, _, shown) in pages() {
        for (line, text) in listing_lines(&shown) {
            let width = text.chars().count();
            if width > COLUMNS {
                wide.push(format!(
                    "{}:{line}: {width} columns: {text}",
                    name(&page)
                ));
            }
        }
    }
    assert!(
        wide.is_empty(),
        "{} listing lines are wider than {COLUMNS} columns (rustfmt.toml \
         keeps code at 80; wrap long comments):\n{}",
        wide.len(),
        wide.join("\n")
    );
}

#[test]
fn an_impl_method_is_listed_without_its_indent() {
    // Chapter 1 lists `Line2::through`, a method inside `impl Line2`.
    let (_, _, shown) = pages()
        .into_iter()
        .find(|(p, _, _)| name(p).starts_with("ch01"))
        .expect("chapter 1's page");
    assert!(
        shown.lines().any(|l| l.starts_with("pub fn through(")),
        "Line2::through should start at column 0"
    );
}

/// The page's text outside every solution fold.
fn outside_folds(shown: &str) -> String {
    let mut out = String::new();
    let mut rest = shown;
    while let Some(open) = rest.find(SOLUTION_OPEN) {
        out.push_str(&rest[..open]);
        let close = rest[open..]
            .find("</details>")
            .expect("every solution fold closes");
        rest = &rest[open + close..];
    }
    out.push_str(rest);
    out
}

/// The lines of an exercise region that are its answer: trimmed, long
/// enough to say something (a lone `}` or `None` would match anywhere), not
/// in the stub, and in no other source file of the lecture (Fresnel's
/// listing computes cos φ as `refract` does; that line is the lecture's,
/// not the exercise's alone).
fn answer_lines(
    reference: &str, stub: &str, elsewhere: &BTreeSet<String>,
) -> Vec<String> {
    let stub_lines: Vec<&str> = stub.lines().map(str::trim).collect();
    reference
        .lines()
        .map(str::trim)
        .filter(|l| l.len() >= 12 && !stub_lines.contains(l))
        .filter(|l| !elsewhere.contains(*l))
        .map(str::to_string)
        .collect()
}

/// Every trimmed line of the lecture's Rust sources that are not exercise
/// modules (`chapters/*/src`, `crates/*/src`).
fn lines_outside_exercises() -> BTreeSet<String> {
    let mut lines = BTreeSet::new();
    let mut dirs: Vec<PathBuf> = Vec::new();
    for top in ["chapters", "crates"] {
        for entry in fs::read_dir(root().join(top)).unwrap() {
            dirs.push(entry.unwrap().path().join("src"));
        }
    }
    while let Some(dir) = dirs.pop() {
        let Ok(entries) = fs::read_dir(&dir) else {
            continue;
        };
        for path in entries.map(|e| e.unwrap().path()) {
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|x| x == "rs")
                && include::exercise_stub(&path).is_none()
            {
                let text = fs::read_to_string(&path).unwrap();
                lines.extend(text.lines().map(|l| l.trim().to_string()));
            }
        }
    }
    lines
}

#[test]
fn no_exercise_answer_is_shown_outside_a_solution_fold() {
    let mut leaks = Vec::new();
    let elsewhere = lines_outside_exercises();
    let mut listed = BTreeSet::new();
    for (page, text, shown) in pages() {
        let dir = page.parent().unwrap();
        let open = outside_folds(&shown);
        let open_lines: Vec<&str> = open.lines().map(str::trim).collect();
        let shown_lines: Vec<&str> = shown.lines().map(str::trim).collect();
        for line in text.lines() {
            for found in include::includes(line) {
                let file = dir.join(found.path());
                let Some(stub) = include::exercise_stub(&file) else {
                    continue;
                };
                let reference = include::read(dir, &found).unwrap();
                let stub_text = fs::read_to_string(&stub).unwrap();
                let stub_region =
                    include::select(&stub_text, found.selector()).unwrap();
                let only = answer_lines(&reference, &stub_region, &elsewhere);
                // A student edition holds the stub in src/ too: no answer.
                let is_reference = reference != stub_region;
                assert!(
                    !(is_reference && only.is_empty()),
                    "{}: {} has no line of its own: the test has no teeth",
                    name(&page),
                    found.argument
                );
                for answer in &only {
                    if open_lines.contains(&answer.as_str()) {
                        leaks.push(format!(
                            "{}: `{answer}` ({})",
                            name(&page),
                            found.argument
                        ));
                    }
                    assert!(
                        shown_lines.contains(&answer.as_str()),
                        "{}: the fold of {} lacks `{answer}`",
                        name(&page),
                        found.argument
                    );
                }
                let stub = fs::canonicalize(&stub).unwrap();
                listed.insert((stub, found.selector().to_string()));
            }
        }
    }
    assert!(
        leaks.is_empty(),
        "exercise answers outside a solution fold:\n{}",
        leaks.join("\n")
    );
    // Every exercise region of every stub is on some page, folded.
    let mut missing = Vec::new();
    for stub in exercise_stubs() {
        let text = fs::read_to_string(&stub).unwrap();
        for line in text.lines() {
            if let Some(anchor) = include::anchor_of(line, "ANCHOR:") {
                let key =
                    (fs::canonicalize(&stub).unwrap(), anchor.to_string());
                if !listed.contains(&key) {
                    missing.push(format!("{}:{anchor}", stub.display()));
                }
            }
        }
    }
    assert!(
        missing.is_empty(),
        "exercise regions no page lists:\n{}",
        missing.join("\n")
    );
}

/// Every `chapters/*/exercise/*.rs`.
fn exercise_stubs() -> Vec<PathBuf> {
    let mut stubs = Vec::new();
    for chapter in fs::read_dir(root().join("chapters")).unwrap() {
        let dir = chapter.unwrap().path().join("exercise");
        let Ok(entries) = fs::read_dir(&dir) else {
            continue;
        };
        stubs.extend(
            entries
                .map(|e| e.unwrap().path())
                .filter(|p| p.extension().is_some_and(|x| x == "rs")),
        );
    }
    stubs.sort();
    stubs
}

#[test]
fn the_sidebar_numbers_each_chapter_once() {
    let summary =
        fs::read_to_string(root().join("book/src/SUMMARY.md")).unwrap();
    let doubled: Vec<&str> = summary
        .lines()
        .filter(|l| l.trim_start().starts_with("- ["))
        .filter(|l| {
            let title = l.trim_start().trim_start_matches("- [");
            title.starts_with(|c: char| c.is_ascii_digit())
        })
        .collect();
    assert!(
        doubled.is_empty(),
        "mdBook numbers the chapters itself; these titles number them again:\n{}",
        doubled.join("\n")
    );
}
