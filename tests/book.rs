//! The book's links hold: every `{{#include}}` / `{{#rustdoc_include}}` names
//! an existing file (and, with `:anchor`, an anchor marked in it by both
//! `ANCHOR: name` and `ANCHOR_END: name`), every link to a figure or another
//! page points at a file that exists, and every page in `SUMMARY.md` exists.

use std::collections::HashMap;
use std::fmt;
use std::fs;
use std::path::{Component, Path, PathBuf};

use raystep_book::include;

/// Reads the files a page refers to; a map stands in for the disk in unit tests.
trait Files {
    fn exists(&self, path: &Path) -> bool;
    fn read(&self, path: &Path) -> Option<String>;
}

struct Disk;

impl Files for Disk {
    fn exists(&self, path: &Path) -> bool {
        path.exists()
    }
    fn read(&self, path: &Path) -> Option<String> {
        fs::read_to_string(path).ok()
    }
}

impl Files for HashMap<PathBuf, String> {
    fn exists(&self, path: &Path) -> bool {
        self.contains_key(&normalise(path))
    }
    fn read(&self, path: &Path) -> Option<String> {
        self.get(&normalise(path)).cloned()
    }
}

/// `a/b/../c` → `a/c` (without touching the disk).
fn normalise(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for component in path.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir if out.file_name().is_some() => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// One broken reference: where it is and what is wrong.
#[derive(Debug, PartialEq, Eq)]
struct Problem {
    file: PathBuf,
    line: usize,
    message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file.display(), self.line, self.message)
    }
}

/// Every broken include and link of the page `page` whose text is `text`.
fn problems(page: &Path, text: &str, files: &dyn Files) -> Vec<Problem> {
    let dir = page.parent().unwrap_or(Path::new(""));
    let is_summary = page.file_name().is_some_and(|n| n == "SUMMARY.md");
    let mut found = Vec::new();
    let mut in_fence = false;
    for (index, line) in text.lines().enumerate() {
        let mut report = |message: String| {
            found.push(Problem {
                file: page.to_path_buf(),
                line: index + 1,
                message,
            })
        };
        // mdbook expands includes everywhere, code blocks included.
        for found in include::includes(line) {
            if let Err(message) = check_include(dir, &found, files) {
                let (directive, argument) = (found.directive, found.argument);
                report(format!("{{{{#{directive} {argument}}}}}: {message}"));
            }
        }
        let trimmed = line.trim_start();
        if trimmed.starts_with("```") || trimmed.starts_with("~~~") {
            in_fence = !in_fence;
            continue;
        }
        if in_fence {
            continue;
        }
        for target in link_targets(line) {
            let Some(path) = local_target(target) else {
                continue;
            };
            if !files.exists(&dir.join(path)) {
                let what = if is_summary {
                    "chapter page"
                } else {
                    "link target"
                };
                report(format!("{what} {path} does not exist"));
            }
        }
    }
    found
}

/// Checks `path`, `path:anchor`, `path:N`, `path:N:M`, `path::M`, `path:N:`
/// the way the book reads them (`raystep_book::include`).
fn check_include(
    dir: &Path, include: &include::Include, files: &dyn Files,
) -> Result<(), String> {
    let path = include.path();
    if path.is_empty() {
        return Err("no file named".into());
    }
    let Some(text) = files.read(&dir.join(path)) else {
        return Err(format!("{path} does not exist"));
    };
    include::select(&text, include.selector())
        .map(|_| ())
        .map_err(|message| format!("{path}: {message}"))
}

/// Link and image targets of a line: `[text](target "title")`, `[label]: target`,
/// `src="target"` and `href="target"`; inline code spans are skipped.
fn link_targets(line: &str) -> Vec<&str> {
    let mut targets = Vec::new();
    let code_free = without_code_spans(line);
    let mut search = 0;
    while let Some(at) = code_free[search..].find("](") {
        let start = search + at + 2;
        let end = code_free[start..]
            .find(')')
            .map_or(code_free.len(), |e| start + e);
        targets.push(line[start..end].split_whitespace().next().unwrap_or(""));
        search = end;
    }
    let trimmed = line.trim_start();
    if trimmed.starts_with('[')
        && !trimmed.starts_with("[^")
        && let Some((_, target)) = trimmed.split_once("]: ")
    {
        targets.push(target.split_whitespace().next().unwrap_or(""));
    }
    for attribute in ["src=\"", "href=\""] {
        let mut search = 0;
        while let Some(at) = code_free[search..].find(attribute) {
            let start = search + at + attribute.len();
            let end = code_free[start..]
                .find('"')
                .map_or(code_free.len(), |e| start + e);
            targets.push(&line[start..end]);
            search = end;
        }
    }
    targets
}

/// The line with every `inline code` span blanked out (same byte positions).
fn without_code_spans(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut in_code = false;
    for c in line.chars() {
        if c == '`' {
            in_code = !in_code;
        }
        if in_code || c == '`' {
            out.extend(std::iter::repeat_n(' ', c.len_utf8()));
        } else {
            out.push(c);
        }
    }
    out
}

/// The file a link points at, if it is one this test checks: a figure
/// (`figures/…`) or another page (`….md`), without its `#fragment`.
fn local_target(target: &str) -> Option<&str> {
    let target = target.trim_start_matches('<').trim_end_matches('>');
    if target.is_empty()
        || target.contains("://")
        || target.starts_with('#')
        || target.starts_with("mailto:")
    {
        return None;
    }
    let path = target.split(['#', '?']).next().unwrap_or(target);
    let is_figure = path.starts_with("figures/") || path.contains("/figures/");
    (is_figure || path.ends_with(".md")).then_some(path)
}

/// Every `.md` file under `dir`, sorted.
fn markdown_files(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        let entries = fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
        for entry in entries {
            let path = entry.expect("directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}

#[test]
fn every_include_link_and_figure_of_the_book_resolves() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let src = root.join("book").join("src");
    let summary = src.join("SUMMARY.md");
    assert!(
        summary.is_file(),
        "{} is missing: the book has no table of contents",
        summary.display()
    );
    let mut all = Vec::new();
    for page in markdown_files(&src) {
        let text = fs::read_to_string(&page)
            .unwrap_or_else(|e| panic!("{}: {e}", page.display()));
        let shown = page.strip_prefix(&root).unwrap_or(&page);
        all.extend(problems(&page, &text, &Disk).into_iter().map(|p| {
            Problem {
                file: shown.to_path_buf(),
                ..p
            }
        }));
    }
    let listed: Vec<String> = all.iter().map(Problem::to_string).collect();
    assert!(
        all.is_empty(),
        "{} broken reference(s) in the book:\n{}",
        all.len(),
        listed.join("\n")
    );
}

#[cfg(test)]
mod parsing {
    use super::*;

    fn files() -> HashMap<PathBuf, String> {
        HashMap::from([
            (
                PathBuf::from("chapters/ch01/src/line.rs"),
                "// ANCHOR: line\npub struct Line2;\n// ANCHOR_END: line\n// ANCHOR: half\nfn f() {}\n"
                    .to_string(),
            ),
            (PathBuf::from("book/src/figures/ch01/line.svg"), "<svg/>".to_string()),
            (PathBuf::from("book/src/ch01.md"), String::new()),
        ])
    }

    fn check(text: &str) -> Vec<String> {
        problems(Path::new("book/src/ch01.md"), text, &files())
            .iter()
            .map(Problem::to_string)
            .collect()
    }

    #[test]
    fn good_references_pass() {
        let page = "# Lines\n\
            {{#include ../../chapters/ch01/src/line.rs:line}}\n\
            ```rust\n{{#rustdoc_include ../../chapters/ch01/src/line.rs}}\n```\n\
            {{#include ../../chapters/ch01/src/line.rs:2:3}} and {{#include ../../chapters/ch01/src/line.rs::2}}\n\
            ![a line](figures/ch01/line.svg \"title\") [page](ch01.md#top) [web](https://example.org/figures/x.svg)\n\
            <img src=\"figures/ch01/line.svg\" alt=\"\">\n\
            `![not a link](figures/none.svg)` \\{{#include nothing.rs}}\n";
        assert_eq!(check(page), Vec::<String>::new());
    }

    #[test]
    fn a_missing_anchor_is_reported_with_file_and_line() {
        let page =
            "intro\n\n{{#include ../../chapters/ch01/src/line.rs:plane}}\n";
        assert_eq!(
            check(page),
            [
                "book/src/ch01.md:3: {{#include ../../chapters/ch01/src/line.rs:plane}}: \
              ../../chapters/ch01/src/line.rs: no anchor `plane`"
            ]
        );
    }

    #[test]
    fn a_half_marked_anchor_is_reported() {
        let page = "{{#rustdoc_include ../../chapters/ch01/src/line.rs:half}}";
        assert_eq!(
            check(page),
            [
                "book/src/ch01.md:1: {{#rustdoc_include ../../chapters/ch01/src/line.rs:half}}: \
              ../../chapters/ch01/src/line.rs: no `ANCHOR_END: half`"
            ]
        );
    }

    #[test]
    fn a_missing_included_file_is_reported() {
        assert_eq!(
            check("a\n{{#include ../../chapters/ch01/src/plane.rs}}"),
            [
                "book/src/ch01.md:2: {{#include ../../chapters/ch01/src/plane.rs}}: \
              ../../chapters/ch01/src/plane.rs does not exist"
            ]
        );
    }

    #[test]
    fn a_missing_figure_is_reported_with_file_and_line() {
        let page = "one\ntwo\n![plane](figures/ch01/plane.svg)\n<img src=\"figures/ch01/plane.png\">";
        assert_eq!(
            check(page),
            [
                "book/src/ch01.md:3: link target figures/ch01/plane.svg does not exist",
                "book/src/ch01.md:4: link target figures/ch01/plane.png does not exist",
            ]
        );
    }

    #[test]
    fn a_missing_chapter_page_in_the_summary_is_reported() {
        let summary =
            "# Summary\n\n- [Lines](ch01.md)\n- [Hits](ch02.md)\n- [Draft]()\n";
        let found: Vec<String> =
            problems(Path::new("book/src/SUMMARY.md"), summary, &files())
                .iter()
                .map(Problem::to_string)
                .collect();
        assert_eq!(
            found,
            ["book/src/SUMMARY.md:4: chapter page ch02.md does not exist"]
        );
    }

    #[test]
    fn links_inside_code_blocks_are_not_checked() {
        assert_eq!(
            check("```md\n![x](figures/none.svg)\n```\n"),
            Vec::<String>::new()
        );
    }

    #[test]
    fn line_ranges_past_the_end_are_reported() {
        assert_eq!(
            check("{{#include ../../chapters/ch01/src/line.rs:40:}}"),
            [
                "book/src/ch01.md:1: {{#include ../../chapters/ch01/src/line.rs:40:}}: \
              ../../chapters/ch01/src/line.rs: no lines 40: (the file has 5)"
            ]
        );
    }
}
