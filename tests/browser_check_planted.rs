//! The browser check on planted pages: a listing shown as prose fails,
//! naming its page and its first line of Rust; prose that names code in
//! inline `code` passes. Needs Chromium, as `browser-check` does (feature
//! `browser`): `cargo test -p raystep-tests --features browser --test
//! browser_check_planted`.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// An unfenced include of chapter 11's compact walk, as Markdown shows it:
/// one paragraph, its `<Hit>` taken for an HTML tag.
const PLANTED: &str = "<p>The walk of the compact tree:\n\
/// The closest hit of the ray, if any.\n\
pub fn walk(&amp;self, ray: &amp;Ray32) -&gt; Option<hit> {\n\
let mut stack = [0u32; 64];\n\
}</hit></p>";

/// Prose that names code as the book does, in `code` spans.
const CLEAN: &str = "<p>Each step is a <code>pub fn</code> of its own; \
<code>let mut stack</code> keeps the nodes still to visit, and \
<code>#[derive(Debug)]</code> prints a node. <code>impl Shape for Sphere \
{</code> is chapter 3's.</p>\n<ul><li>The walk calls <code>fn walk(</code> \
once per ray.</li></ul>";

/// A folder holding one page, `name`, whose `<main>` holds `body`.
fn book(name: &str, body: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "raystep-browser-planted-{name}-{}",
        std::process::id()
    ));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let page = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>{name}</title></head>\n<body><main>\n{body}\n</main></body>\
         </html>\n"
    );
    fs::write(dir.join(format!("{name}.html")), page).unwrap();
    dir
}

/// The check's exit code and what it printed.
fn check(book: &Path) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_browser-check"))
        .arg(book)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr);
    fs::remove_dir_all(book).unwrap();
    (out.status.code(), format!("{stdout}{stderr}"))
}

#[test]
fn a_listing_shown_as_prose_fails_naming_page_and_line() {
    let (code, said) = check(&book("planted", PLANTED));
    assert_eq!(code, Some(1), "{said}");
    let row = said
        .lines()
        .position(|l| l.starts_with("planted.html"))
        .unwrap_or_else(|| panic!("no row for the page: {said}"));
    let problem = said.lines().nth(row + 1).unwrap_or("");
    assert_eq!(
        problem.trim(),
        "Rust in the prose (a listing outside a code block?): \
         /// The closest hit of the ray, if any.",
        "{said}"
    );
}

#[test]
fn code_named_in_inline_code_passes() {
    let (code, said) = check(&book("clean", CLEAN));
    assert_eq!(code, Some(0), "{said}");
    assert!(
        said.contains("1 pages at 1280×900 px: 0 problems"),
        "{said}"
    );
}
