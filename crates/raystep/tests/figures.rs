//! `raystep figures` from the outside: writing, checking, and its errors.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Output;
use std::sync::OnceLock;

use raystep_figure::{BOOK_COLUMN_PX, MIN_TEXT_PX};

mod common;
use common::{fails_in_one_line, raystep, succeeds, text};

/// A fresh, empty scratch folder for one test.
fn scratch(name: &str) -> PathBuf {
    common::scratch("raystep-figures", name)
}

/// Every file under `dir` with its bytes, by path relative to `dir`.
fn files(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut found = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else {
                found.insert(
                    path.strip_prefix(dir).unwrap().to_path_buf(),
                    fs::read(&path).unwrap(),
                );
            }
        }
    }
    found
}

/// Writes every figure (of `chapter`, if given) into a scratch folder;
/// returns the folder. Only one test draws every chapter: the others test
/// the command on chapter 1's few figures.
fn write_all(name: &str, chapter: Option<&str>) -> PathBuf {
    let dir = scratch(name);
    let mut args = vec!["figures", "--out", dir.to_str().unwrap()];
    args.extend(chapter.map(|c| ["--chapter", c]).into_iter().flatten());
    succeeds(&args);
    dir
}

/// `raystep figures --check --chapter 01 --out <dir>`.
fn check_chapter_01(dir: &Path) -> Output {
    raystep(&[
        "figures",
        "--check",
        "--chapter",
        "01",
        "--out",
        dir.to_str().unwrap(),
    ])
}

#[test]
fn checking_an_empty_folder_reports_every_figure_missing() {
    let expected = files(&write_all("reference", Some("01"))).len();
    let empty = scratch("empty");
    let out = check_chapter_01(&empty);
    let stdout = text(&out.stdout);
    if expected == 0 {
        // No chapter draws a figure yet: nothing can be missing.
        assert!(out.status.success(), "{}", text(&out.stderr));
        assert!(stdout.contains("figures up to date (0 files)"), "{stdout}");
    } else {
        assert!(
            !out.status.success(),
            "--check passed on an empty folder: {stdout}"
        );
        assert_eq!(
            stdout
                .lines()
                .filter(|l| l.starts_with("missing: "))
                .count(),
            expected,
            "{stdout}"
        );
        assert!(
            text(&out.stderr).contains("out of date"),
            "{}",
            text(&out.stderr)
        );
    }
    assert!(files(&empty).is_empty(), "--check wrote files");
}

#[test]
fn a_changed_or_extra_figure_file_is_named() {
    let dir = write_all("tampered", Some("01"));
    let chapter = dir.join("ch01");
    fs::write(chapter.join("stray.svg"), "<svg/>").unwrap();
    let first = files(&chapter)
        .into_keys()
        .find(|p| p.to_str() != Some("stray.svg"));
    if let Some(first) = &first {
        fs::write(chapter.join(first), b"changed").unwrap();
    }
    let out = check_chapter_01(&dir);
    let stdout = text(&out.stdout);
    assert!(!out.status.success());
    assert!(stdout.contains("stray.svg"), "{stdout}");
    if let Some(first) = first {
        assert!(stdout.contains(first.to_str().unwrap()), "{stdout}");
    }
}

/// Every chapter's figures, drawn once into a scratch folder that the
/// tests below share (drawing them all is the slow part), and what the
/// drawing printed.
fn every_chapter() -> &'static (PathBuf, String) {
    static DRAWN: OnceLock<(PathBuf, String)> = OnceLock::new();
    DRAWN.get_or_init(|| {
        let dir = scratch("every");
        let stdout = succeeds(&["figures", "--out", dir.to_str().unwrap()]);
        (dir, stdout)
    })
}

/// The page width of an SVG file (its `<svg width="...">`).
fn svg_width(svg: &str) -> Option<f64> {
    let svg = &svg[svg.find("<svg")?..];
    let tag = &svg[..svg.find('>')?];
    let (_, value) = tag.split_once(" width=\"")?;
    value.split('"').next()?.parse().ok()
}

/// The smallest text an SVG file records in its raystep comment: the size
/// in px, `Some(None)` for `no text`, or `None` without the comment.
fn recorded_text(svg: &str) -> Option<Option<f64>> {
    if svg.contains("<!-- raystep: no text -->") {
        return Some(None);
    }
    let (_, rest) = svg.split_once("<!-- raystep: smallest text ")?;
    let (value, _) = rest.split_once(" px -->")?;
    value.parse().ok().map(Some)
}

/// Every figure fits the book's column, where it is shown 1:1, and its
/// smallest text (as the SVG file records it) is large enough to read.
#[test]
fn every_figure_fits_the_column_with_legible_text() {
    let mut failures = Vec::new();
    let mut count = 0;
    for (path, bytes) in files(&every_chapter().0) {
        if path.extension().is_none_or(|e| e != "svg") {
            continue;
        }
        count += 1;
        let svg = text(&bytes);
        let width = svg_width(&svg);
        let smallest = recorded_text(&svg);
        let fits = width.is_some_and(|w| w <= BOOK_COLUMN_PX);
        let legible =
            smallest.is_some_and(|s| s.is_none_or(|s| s >= MIN_TEXT_PX));
        if !(fits && legible) {
            let show =
                |v: Option<f64>| v.map_or("?".into(), |v| format!("{v:.1}"));
            failures.push(format!(
                "{:<34} {:>7} {:>10}",
                path.with_extension("").display(),
                show(width),
                match smallest {
                    Some(None) => "no text".to_string(),
                    Some(Some(s)) => format!("{s:.1}"),
                    None => "?".to_string(),
                }
            ));
        }
    }
    assert!(count > 0, "no figure drawn");
    assert!(
        failures.is_empty(),
        "{} of {count} figures are wider than {BOOK_COLUMN_PX} px or have \
         text under {MIN_TEXT_PX} px:\n{:<34} {:>7} {:>10}\n{}",
        failures.len(),
        "figure",
        "width",
        "text (px)",
        failures.join("\n")
    );
}

/// Every chapter's figures, drawn a second time, come out byte for byte
/// the same: `--check` draws them again (in memory) and compares every
/// byte with the first drawing's files. (CI's `figures --check` does the
/// same against the committed files, drawn in another process.)
#[test]
fn drawing_again_gives_identical_files_that_check_clean() {
    let (dir, stdout) = every_chapter();
    let before = files(dir);
    // One line per file written, and a summary.
    assert_eq!(stdout.lines().count(), before.len() + 1);
    let out = raystep(&["figures", "--check", "--out", dir.to_str().unwrap()]);
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", text(&out.stderr));
    assert!(
        stdout.contains(&format!("figures up to date ({} file", before.len())),
        "{stdout}"
    );
}

#[test]
fn one_chapter_only() {
    let dir = scratch("one");
    succeeds(&["figures", "--chapter", "1", "--out", dir.to_str().unwrap()]);
    let folders: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(folders, ["ch01"]);
}

#[test]
fn an_unknown_chapter_is_one_clear_error() {
    for args in [
        &["figures", "--chapter", "ch99", "--check"][..],
        &["figures", "--chapter", "99"],
        &["check", "ch99"],
    ] {
        // one line, naming every chapter (the list grows with the lecture)
        let stderr = fails_in_one_line(args);
        assert!(
            stderr.starts_with(
                "error: ch99: no such chapter; chapters are ch01, ch02, ch03"
            ),
            "{args:?}: {stderr}"
        );
    }
}

#[test]
fn an_unwritable_folder_is_one_clear_error() {
    let dir = scratch("unwritable");
    let file = dir.join("a-file");
    fs::write(&file, "not a folder").unwrap();
    let stderr = fails_in_one_line(&[
        "figures",
        "--out",
        file.join("figures").to_str().unwrap(),
    ]);
    assert!(
        stderr.starts_with("error: ") && stderr.contains("a-file"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
}

#[test]
fn a_bad_format_is_refused() {
    let dir = scratch("format");
    let stderr = fails_in_one_line(&[
        "figures",
        "--format",
        "gif",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(stderr.contains("invalid value 'gif'"), "{stderr}");
    assert!(files(&dir).is_empty());
}
