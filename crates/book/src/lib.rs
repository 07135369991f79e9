//! What the book shows, from the pages in `book/src/`.
//!
//! `raystep book` runs this inside mdBook, and `mdbook build book` /
//! `mdbook serve book` run it through `raystep book-preprocessor`, so both
//! show the same pages. For each page, in one pass over its lines:
//!
//! 1. **Listings.** `{{#include file:anchor}}` is expanded as mdBook would,
//!    but the region loses its common indentation (a method from an `impl`
//!    block starts at column 0). A listing stands in a fenced code block
//!    (```` ``` ```` or `~~~`, indented too, as in a list item); an include
//!    anywhere else is refused, since Markdown would run its lines together
//!    into prose. Only a Markdown fragment (`.md`, the stability table) is
//!    included into the text. A block indented four spaces without a fence
//!    does not count: in a list item those lines are the item's text.
//! 2. **Exercises.** A listing that is an exercise's region (a file
//!    `chapters/<ch>/src/<e>.rs` with a stub `chapters/<ch>/exercise/<e>.rs`)
//!    shows the stub: its signature, docs and the lecture step it asks for.
//!    The reference code follows inside a closed `<details class="solution">`
//!    fold, never in the open.
//! 3. **Questions.** `{{#question q1}}` on a line of its own states a paper
//!    question from the chapter's `figures/chNN/questions.toml`, its worked
//!    answer in a closed fold ([`question`]).
//! 4. **Math.** `$…$` in running text and `$$…$$` on lines of their own are
//!    LaTeX, typeset as MathML ([`math`]).
//! 5. **Numbers.** `3.7 %`, `160 × 90` and `39 171` are never split at a
//!    line end ([`typography`]).
//!
//! Every error names the page and line.

mod error;
pub mod include;
pub mod math;
pub mod question;
pub mod typography;

use std::path::Path;

pub use error::BookError;

/// The summary line of a solution fold.
pub const SOLUTION_SUMMARY: &str =
    "Solution: the reference code (try the exercise first)";

/// The opening tag of a solution fold.
pub const SOLUTION_OPEN: &str = r#"<details class="solution">"#;

/// The page `page` (a file of `book/src/`) with text `text`, as the book
/// shows it (see the crate documentation).
pub fn preprocess(page: &Path, text: &str) -> Result<String, BookError> {
    let dir = page.parent().unwrap_or(Path::new(""));
    let lines: Vec<&str> = text.lines().collect();
    let mut out = String::with_capacity(text.len() * 2);
    let mut fence: Option<&str> = None;
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let fail = |message: String| BookError {
            page: page.to_path_buf(),
            line: i + 1,
            message,
        };
        let trimmed = line.trim_start();
        if let Some(open) = fence {
            if closes(trimmed, open) {
                fence = None;
                push(&mut out, line);
            } else {
                push(&mut out, &expand(dir, line).map_err(fail)?);
            }
            i += 1;
            continue;
        }
        if let Some(marker) = fence_marker(trimmed) {
            if let Some(fold) = exercise_listing(dir, &lines[i..], marker) {
                out.push_str(&fold.map_err(fail)?);
                i += 3;
                continue;
            }
            fence = Some(marker);
            push(&mut out, line);
            i += 1;
            continue;
        }
        if let Some(id) = question::directive(trimmed) {
            // A paper question, from the chapter's questions.toml.
            let block = question::render(dir, page, id).map_err(fail)?;
            for block_line in block.lines() {
                push(&mut out, &math::inline(block_line).map_err(fail)?);
            }
            i += 1;
            continue;
        }
        if let Some(listing) = include::includes(line)
            .into_iter()
            .find(|d| !d.is_markdown())
        {
            return Err(fail(outside_a_fence(&listing)));
        }
        if trimmed.starts_with("$$") {
            // A displayed equation: up to the line that ends with `$$`.
            let last = (i..lines.len())
                .find(|&j| {
                    let t = lines[j].trim_end();
                    t.ends_with("$$") && (j > i || t.trim_start().len() >= 4)
                })
                .ok_or_else(|| {
                    fail("`$$` opens an equation that never closes".into())
                })?;
            let joined: Vec<&str> =
                lines[i..=last].iter().map(|l| l.trim()).collect();
            let joined = joined.join("\n");
            let latex = &joined[2..joined.len() - 2];
            let indent = &line[..line.len() - trimmed.len()];
            let block = math::display(latex).map_err(fail)?;
            push(&mut out, &format!("{indent}{block}"));
            i = last + 1;
            continue;
        }
        let typeset = math::inline(line).map_err(fail)?;
        push(&mut out, &expand(dir, &typeset).map_err(fail)?);
        i += 1;
    }
    Ok(out)
}

fn push(out: &mut String, line: &str) {
    out.push_str(line);
    out.push('\n');
}

/// Why a listing may not stand in the text: Markdown would run its lines
/// together into a paragraph of prose.
fn outside_a_fence(listing: &include::Include) -> String {
    format!(
        "{{{{#{} {}}}}} is outside a fenced code block, so its lines would \
         show as prose: put it on a line of its own between ```rust,ignore \
         (or ```text) and ``` (only a Markdown fragment, .md, belongs in \
         the text)",
        listing.directive, listing.argument
    )
}

/// The fence a line opens (```` ``` ```` or `~~~`, any longer run included).
fn fence_marker(trimmed: &str) -> Option<&str> {
    let marker = ["```", "~~~"]
        .into_iter()
        .find(|m| trimmed.starts_with(m))?;
    let c = marker.as_bytes()[0] as char;
    let run = trimmed.len() - trimmed.trim_start_matches(c).len();
    Some(&trimmed[..run])
}

/// Whether a line closes the fence `open`.
fn closes(trimmed: &str, open: &str) -> bool {
    let c = open.as_bytes()[0] as char;
    let run = trimmed.len() - trimmed.trim_start_matches(c).len();
    run >= open.len() && trimmed[run..].trim().is_empty()
}

/// A line with its include directives replaced by what they include (the
/// last newline dropped, as mdBook does).
fn expand(dir: &Path, line: &str) -> Result<String, String> {
    let found = include::includes(line);
    if found.is_empty() {
        return Ok(line.to_string());
    }
    let mut out = String::new();
    let mut last = 0;
    for directive in &found {
        out.push_str(&line[last..directive.start]);
        let text = include::read(dir, directive).map_err(|message| {
            format!(
                "{{{{#{} {}}}}}: {message}",
                directive.directive, directive.argument
            )
        })?;
        out.push_str(text.strip_suffix('\n').unwrap_or(&text));
        last = directive.end;
    }
    out.push_str(&line[last..]);
    Ok(out)
}

/// If `lines` start with a fenced block holding just one include of an
/// exercise's region: the stub's listing and the reference folded below it.
fn exercise_listing(
    dir: &Path, lines: &[&str], marker: &str,
) -> Option<Result<String, String>> {
    let [open, body, close, ..] = lines else {
        return None;
    };
    if !closes(close.trim_start(), marker) {
        return None;
    }
    let found = include::includes(body.trim());
    let [directive] = found.as_slice() else {
        return None;
    };
    if directive.start != 0 || directive.end != body.trim().len() {
        return None;
    }
    let stub = include::exercise_stub(&dir.join(directive.path()))?;
    Some(fold(dir, open, marker, directive, &stub))
}

/// The stub's region in the open, the reference's in a solution fold.
fn fold(
    dir: &Path, open: &str, marker: &str, directive: &include::Include,
    stub: &Path,
) -> Result<String, String> {
    let named = |message: String| {
        format!(
            "{{{{#{} {}}}}}: {message}",
            directive.directive, directive.argument
        )
    };
    let reference = include::read(dir, directive).map_err(named)?;
    let stub_text = std::fs::read_to_string(stub)
        .map_err(|e| named(format!("cannot read {}: {e}", stub.display())))?;
    let exercise =
        include::select(&stub_text, directive.selector()).map_err(|m| {
            named(format!("the exercise stub {}: {m}", stub.display()))
        })?;
    let indent = &open[..open.len() - open.trim_start().len()];
    let mut out = format!("{open}\n{exercise}{indent}{marker}\n");
    if exercise != reference {
        out.push_str(&format!(
            "\n{indent}{SOLUTION_OPEN}\n{indent}<summary>{SOLUTION_SUMMARY}</summary>\n\n\
             {open}\n{reference}{indent}{marker}\n\n{indent}</details>\n"
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    /// A chapter folder with one exercise module and its stub.
    fn chapter(root: &Path) -> std::path::PathBuf {
        let ch = root.join("chapters/ch99");
        fs::create_dir_all(ch.join("src")).unwrap();
        fs::create_dir_all(ch.join("exercise")).unwrap();
        fs::create_dir_all(root.join("book/src")).unwrap();
        fs::write(
            ch.join("src/ex.rs"),
            "// ANCHOR: f\npub fn f() -> u32 {\n    42\n}\n// ANCHOR_END: f\n",
        )
        .unwrap();
        fs::write(
            ch.join("exercise/ex.rs"),
            "// ANCHOR: f\npub fn f() -> u32 {\n    // TODO: the answer\n    todo!()\n}\n// ANCHOR_END: f\n",
        )
        .unwrap();
        fs::write(ch.join("src/plain.rs"), "impl A {\n    // ANCHOR: g\n    fn g() {}\n    // ANCHOR_END: g\n}\n").unwrap();
        root.join("book/src/page.md")
    }

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir()
            .join(format!("raystep-book-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn an_exercise_listing_shows_the_stub_and_folds_the_reference() {
        let root = scratch("fold");
        let page = chapter(&root);
        let text = "Text.\n\n```rust,ignore\n{{#include ../../chapters/ch99/src/ex.rs:f}}\n```\n\nMore.\n";
        let out = preprocess(&page, text).unwrap();
        let (open, folded) = out.split_once(SOLUTION_OPEN).unwrap();
        assert!(open.contains("todo!()") && !open.contains("42"), "{out}");
        assert!(folded.contains("    42\n") && folded.contains("</details>"));
        assert!(out.ends_with("More.\n"));
        fs::remove_dir_all(root).unwrap();
    }

    #[test]
    fn other_listings_are_expanded_and_dedented() {
        let root = scratch("plain");
        let page = chapter(&root);
        let text =
            "```rust\n{{#include ../../chapters/ch99/src/plain.rs:g}}\n```\n";
        let out = preprocess(&page, text).unwrap();
        assert_eq!(out, "```rust\nfn g() {}\n```\n");
        fs::remove_dir_all(root).unwrap();
    }

    #[test]
    fn math_is_typeset_outside_code_only() {
        let page = Path::new("book/src/page.md");
        let text = "Let $x_0$ be.\n\n$$\nt = 1\n$$\n\n```text\n$x$\n```\n";
        let out = preprocess(page, text).unwrap();
        assert!(out.starts_with(r#"Let <span class="nowrap"><math><msub>"#));
        assert!(
            out.contains(r#"<div class="equation"><math display="block">"#)
        );
        assert!(out.contains("```text\n$x$\n```"), "{out}");
    }

    /// The page `text` gives with the chapter of [`chapter`] around it.
    fn preprocessed(name: &str, text: &str) -> Result<String, BookError> {
        let root = scratch(name);
        let page = chapter(&root);
        fs::write(root.join("book/src/table.md"), "| a |\n|---|\n| 1 |\n")
            .unwrap();
        let out = preprocess(&page, text);
        fs::remove_dir_all(root).unwrap();
        out
    }

    /// The listing of [`chapter`]'s `plain.rs` (which shows `fn g() {}`).
    const G: &str = "{{#include ../../chapters/ch99/src/plain.rs:g}}";

    #[test]
    fn a_listing_outside_a_fence_is_refused_naming_page_and_line() {
        let text = format!("# Page\n\nThe walk:\n\n{G}\n\nMore.\n");
        let error = preprocessed("prose", &text).unwrap_err();
        assert!(error.page.ends_with("book/src/page.md"), "{error}");
        assert_eq!(error.line, 5, "{error}");
        assert!(error.message.contains("plain.rs:g"), "{error}");
        assert!(error.message.contains("outside a fenced code block"));
        // In running text, and any file: a listing of a scene or a mesh too.
        for line in [
            "See {{#include ../../chapters/ch99/src/ex.rs:f}} here.",
            "{{#include ../../chapters/ch99/scenes/a.toml}}",
            "{{#rustdoc_include ../../chapters/ch99/src/ex.rs}}",
            "- {{#include ../../shared/meshes/quad.obj}}",
        ] {
            let error =
                preprocessed("any", &format!("a\n{line}\n")).unwrap_err();
            assert_eq!(error.line, 2, "{line}: {error}");
            assert!(error.message.contains("outside a fenced"), "{error}");
        }
    }

    #[test]
    fn a_listing_in_a_rust_fence_passes() {
        let text = format!("Text.\n\n```rust,ignore\n{G}\n```\n");
        let out = preprocessed("fenced", &text).unwrap();
        assert_eq!(out, "Text.\n\n```rust,ignore\nfn g() {}\n```\n");
    }

    #[test]
    fn a_listing_in_a_tilde_or_list_item_fence_passes() {
        // `~~~` and a fence indented into a list item are code blocks too.
        let text = format!(
            "~~~rust\n{G}\n~~~\n\n1. The walk:\n\n   ```rust\n   {G}\n   ```\n"
        );
        let out = preprocessed("tilde", &text).unwrap();
        assert_eq!(out, text.replace(G, "fn g() {}"));
    }

    #[test]
    fn a_listing_indented_without_a_fence_is_refused() {
        // Four spaces are code only outside a list; in an item they are its
        // text, so a listing needs a fence.
        let text = format!("- The walk:\n\n    {G}\n");
        let error = preprocessed("indented", &text).unwrap_err();
        assert_eq!(error.line, 3, "{error}");
    }

    #[test]
    fn a_markdown_fragment_is_included_into_the_text() {
        let text = "## Table\n\n{{#include table.md}}\n";
        let out = preprocessed("fragment", text).unwrap();
        assert_eq!(out, "## Table\n\n| a |\n|---|\n| 1 |\n");
    }

    #[test]
    fn errors_name_the_page_and_line() {
        let page = Path::new("book/src/page.md");
        let error = preprocess(page, "ok\n\n$\\nope$\n").unwrap_err();
        assert_eq!((error.page.as_path(), error.line), (page, 3));
        let error = preprocess(page, "```\n{{#include missing.rs}}\n```\n")
            .unwrap_err();
        assert_eq!(error.line, 2);
        assert!(error.message.contains("missing.rs"), "{error}");
        let error = preprocess(page, "$$\nx\n").unwrap_err();
        assert!(
            error.to_string().starts_with("book/src/page.md:1: "),
            "{error}"
        );
    }
}
