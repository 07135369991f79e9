//! `{{#include file}}` and `{{#include file:anchor}}`, as mdBook reads them,
//! with one difference: the included lines lose their common indentation,
//! so a method listed from inside an `impl` block starts at column 0.

use std::fs;
use std::path::{Path, PathBuf};

/// One `{{#include …}}` (or `{{#rustdoc_include …}}`) directive of a line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Include<'a> {
    /// `include` or `rustdoc_include`.
    pub directive: &'a str,
    /// What follows the directive: `path`, `path:anchor`, `path:N:M`.
    pub argument: &'a str,
    /// Where the directive starts in the line (byte offset of `{{`).
    pub start: usize,
    /// Where it ends (byte offset just after `}}`).
    pub end: usize,
}

impl Include<'_> {
    /// The file named, relative to the page's folder.
    pub fn path(&self) -> &str {
        self.argument
            .split_once(':')
            .map_or(self.argument, |(p, _)| p)
    }

    /// What comes after the file: an anchor, a line range, or "".
    pub fn selector(&self) -> &str {
        self.argument.split_once(':').map_or("", |(_, s)| s)
    }

    /// Whether it includes a Markdown fragment (`.md`), part of the text
    /// (the stability appendix's table); any other file is a listing.
    pub fn is_markdown(&self) -> bool {
        Path::new(self.path())
            .extension()
            .is_some_and(|x| x.eq_ignore_ascii_case("md"))
    }
}

/// The include directives of a line. Escaped ones (`\{{#include …}}`) are
/// skipped, as mdBook does.
pub fn includes(line: &str) -> Vec<Include<'_>> {
    let mut found = Vec::new();
    let mut offset = 0;
    while let Some(at) = line[offset..].find("{{#") {
        let start = offset + at;
        let Some(close) = line[start..].find("}}") else {
            break;
        };
        let end = start + close + 2;
        let body = line[start + 3..end - 2].trim();
        let (directive, argument) =
            body.split_once(char::is_whitespace).unwrap_or((body, ""));
        let escaped = line[..start].ends_with('\\');
        if !escaped && matches!(directive, "include" | "rustdoc_include") {
            found.push(Include {
                directive,
                argument: argument.trim(),
                start,
                end,
            });
        }
        offset = end;
    }
    found
}

/// The lines an include shows: the whole file, an anchored region or a
/// line range, without anchor marker lines and without their common
/// indentation. `dir` is the page's folder.
pub fn read(dir: &Path, include: &Include) -> Result<String, String> {
    let path = include.path();
    if path.is_empty() {
        return Err("no file named".into());
    }
    let file = dir.join(path);
    let text = fs::read_to_string(&file)
        .map_err(|e| format!("cannot read {path}: {e}"))?;
    select(&text, include.selector())
        .map_err(|message| format!("{path}: {message}"))
}

/// The lines of `text` chosen by `selector` (see [`read`]).
pub fn select(text: &str, selector: &str) -> Result<String, String> {
    let lines: Vec<&str> = text.lines().collect();
    let chosen: Vec<&str> = if selector.is_empty() {
        lines
    } else if selector.bytes().all(|b| b.is_ascii_digit() || b == b':') {
        let range = line_range(selector, lines.len())?;
        lines[range].to_vec()
    } else {
        anchored(&lines, selector)?
    };
    let kept: Vec<&str> = chosen
        .into_iter()
        .filter(|l| {
            anchor_of(l, "ANCHOR:").is_none()
                && anchor_of(l, "ANCHOR_END:").is_none()
        })
        .collect();
    Ok(dedent(&kept))
}

/// `N` (line N), `N:M`, `N:` and `:M`, 1-based and inclusive, as mdBook.
fn line_range(
    selector: &str, count: usize,
) -> Result<std::ops::Range<usize>, String> {
    let number = |s: &str, default: usize| -> Result<usize, String> {
        if s.is_empty() {
            Ok(default)
        } else {
            s.parse().map_err(|_| format!("bad line number `{s}`"))
        }
    };
    let (first, last) = match selector.split_once(':') {
        None => {
            let n = number(selector, 1)?;
            (n, n)
        }
        Some((a, b)) => (number(a, 1)?, number(b, count)?),
    };
    if first == 0 || first > count.max(1) || last < first {
        return Err(format!("no lines {selector} (the file has {count})"));
    }
    Ok(first - 1..last.min(count))
}

/// The lines between `ANCHOR: name` and `ANCHOR_END: name`.
fn anchored<'a>(lines: &[&'a str], name: &str) -> Result<Vec<&'a str>, String> {
    let is = |line: &str, marker: &str| anchor_of(line, marker) == Some(name);
    let start = lines.iter().position(|l| is(l, "ANCHOR:"));
    let end = lines.iter().position(|l| is(l, "ANCHOR_END:"));
    match (start, end) {
        (Some(s), Some(e)) if s < e => Ok(lines[s + 1..e].to_vec()),
        (Some(_), Some(_)) => Err(format!("`ANCHOR_END: {name}` comes first")),
        (None, None) => Err(format!("no anchor `{name}`")),
        (Some(_), None) => Err(format!("no `ANCHOR_END: {name}`")),
        (None, Some(_)) => Err(format!("no `ANCHOR: {name}`")),
    }
}

/// The anchor name after `marker` on a line, as mdBook reads it (`[\w-]+`).
pub fn anchor_of<'a>(line: &'a str, marker: &str) -> Option<&'a str> {
    let rest = line[line.find(marker)? + marker.len()..].trim_start();
    let end = rest
        .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '-'))
        .unwrap_or(rest.len());
    (end > 0).then(|| &rest[..end])
}

/// The lines without the indentation they all share (blank lines aside).
fn dedent(lines: &[&str]) -> String {
    let indent = lines
        .iter()
        .filter(|l| !l.trim().is_empty())
        .map(|l| l.len() - l.trim_start().len())
        .min()
        .unwrap_or(0);
    let mut out = String::new();
    for line in lines {
        out.push_str(line.get(indent..).unwrap_or("").trim_end());
        out.push('\n');
    }
    out
}

/// For an exercise's module `chapters/<ch>/src/**/<e>.rs` (directly in
/// `src/`, or in the folder of its part of the lecture, as chapter 8's
/// `src/primitives/slab.rs`), the student's stub
/// `chapters/<ch>/exercise/<e>.rs`, if the chapter has one.
pub fn exercise_stub(file: &Path) -> Option<PathBuf> {
    let src = file
        .ancestors()
        .skip(1)
        .find(|dir| dir.file_name() == Some("src".as_ref()))?;
    let stub = src.parent()?.join("exercise").join(file.file_name()?);
    stub.is_file().then_some(stub)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_exercise_module_in_a_part_s_folder_has_its_stub() {
        let dir = std::env::temp_dir()
            .join(format!("raystep-book-stub-{}", std::process::id()));
        let chapter = dir.join("chapters/ch08-x");
        std::fs::create_dir_all(chapter.join("src/part")).unwrap();
        std::fs::create_dir_all(chapter.join("exercise")).unwrap();
        for file in ["exercise/slab.rs", "src/part/slab.rs", "src/lib.rs"] {
            std::fs::write(chapter.join(file), "").unwrap();
        }
        let stub = chapter.join("exercise/slab.rs");
        let nested = exercise_stub(&chapter.join("src/part/slab.rs"));
        let not_one = exercise_stub(&chapter.join("src/lib.rs"));
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(nested, Some(stub));
        assert_eq!(not_one, None);
    }

    const FILE: &str = "\
use x;
impl A {
    // ANCHOR: f
    /// Doc.
    pub fn f() {
        // ANCHOR: inner
        g();
        // ANCHOR_END: inner
    }
    // ANCHOR_END: f
}
";

    #[test]
    fn an_anchored_method_loses_its_impl_indent_and_inner_markers() {
        assert_eq!(
            select(FILE, "f").unwrap(),
            "/// Doc.\npub fn f() {\n    g();\n}\n"
        );
        assert_eq!(select(FILE, "inner").unwrap(), "g();\n");
    }

    #[test]
    fn line_ranges_are_one_based_and_inclusive() {
        assert_eq!(select("a\nb\nc\n", "2").unwrap(), "b\n");
        assert_eq!(select("a\nb\nc\n", "2:").unwrap(), "b\nc\n");
        assert_eq!(select("a\nb\nc\n", ":2").unwrap(), "a\nb\n");
        assert!(select("a\n", "3").unwrap_err().contains("has 1"));
    }

    #[test]
    fn missing_anchors_are_named() {
        assert_eq!(select(FILE, "g").unwrap_err(), "no anchor `g`");
        assert_eq!(
            select("// ANCHOR: a\n", "a").unwrap_err(),
            "no `ANCHOR_END: a`"
        );
    }

    #[test]
    fn directives_are_found_and_escaped_ones_skipped() {
        let line = r"{{#include a.rs:x}} \{{#include b.rs}} {{#title T}}";
        let found = includes(line);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].path(), found[0].selector()), ("a.rs", "x"));
        assert_eq!(&line[found[0].start..found[0].end], "{{#include a.rs:x}}");
    }

    #[test]
    fn only_markdown_fragments_are_text() {
        let kinds: Vec<bool> = includes(
            "{{#include t.md}} {{#include a.rs:x}} {{#include s.toml}} \
             {{#include T.MD:2:3}} {{#include md}}",
        )
        .iter()
        .map(Include::is_markdown)
        .collect();
        assert_eq!(kinds, [true, false, false, true, false]);
    }
}
