//! Whether the prose of a page holds a line of Rust: the browser check's
//! guard against a listing that lost its code fence. Markdown runs such a
//! listing's lines together into a paragraph, so a reader sees
//! `pub fn hit(ray: &Ray) -> Option { let mut t = …` as text.
//!
//! The text judged is what a paragraph, list item, table cell or heading
//! shows without its inline `code`, math and listings, so prose that names
//! code in `code` spans is never judged. What remains is Rust when one of its
//! lines holds one of these, each a shape prose does not take:
//!
//! - a comment starting the line: `/// Doc.`, `// Step 4: …`;
//! - an attribute: `#[derive(`, `#[inline]`, `#![`;
//! - a function: `fn name(` or `fn name<`;
//! - `pub` before an item: `pub fn`, `pub(crate) struct`, `pub use`, …;
//! - a type: `struct Name {`, `enum Name<`, `trait Name:` (a capital name,
//!   then `{`, `<`, `(`, `;` or `:`);
//! - `impl<`, or `impl ` on a line that ends with `{`;
//! - a binding: `let mut name`, `let name =`, `let name:`, `let (…) = …;`;
//! - an import: `use name::`;
//! - a constant: `const NAME:`, `static NAME:`;
//! - a macro call: `name!(` or `name![`;
//! - a block: a line ending in `{` that starts with `if`, `for`, `while`,
//!   `match`, `loop`, `else` or `} else`, or a line that is only `}`, `};`,
//!   `},`, `})` or `});`.

/// The first line of `text` (a block of prose as the page shows it) that
/// reads as Rust, trimmed.
pub fn rust_line(text: &str) -> Option<&str> {
    text.lines().map(str::trim).find(|line| reads_as_rust(line))
}

/// Whether one trimmed line of prose is a line of Rust (the shapes of the
/// module documentation).
pub fn reads_as_rust(line: &str) -> bool {
    comment(line)
        || attribute(line)
        || function(line)
        || public_item(line)
        || type_definition(line)
        || implementation(line)
        || binding(line)
        || import(line)
        || constant(line)
        || macro_call(line)
        || block(line)
}

/// `/// Doc.`, `//! Doc.`, `// Step 4: …`.
fn comment(line: &str) -> bool {
    line.strip_prefix("//").is_some_and(|rest| {
        rest.is_empty() || rest.starts_with([' ', '/', '!'])
    })
}

/// `#[derive(Debug)]`, `#[inline]`, `#![allow(…)]`.
fn attribute(line: &str) -> bool {
    ["#[", "#!["].into_iter().any(|open| {
        after(line, open)
            .any(|rest| rest.starts_with(|c: char| c.is_ascii_alphabetic()))
    })
}

/// `fn hit(` and `fn build<`.
fn function(line: &str) -> bool {
    after(line, "fn ").any(|rest| {
        identifier(rest.trim_start())
            .is_some_and(|(_, then)| then.starts_with(['(', '<']))
    })
}

/// `pub` (or `pub(crate)`, `pub(super)`) before an item's keyword.
fn public_item(line: &str) -> bool {
    const ITEMS: [&str; 13] = [
        "fn", "struct", "enum", "trait", "mod", "const", "static", "type",
        "use", "unsafe", "async", "extern", "impl",
    ];
    ["pub ", "pub(crate) ", "pub(super) "]
        .into_iter()
        .flat_map(|p| after(line, p))
        .any(|rest| {
            identifier(rest.trim_start()).is_some_and(|(word, then)| {
                ITEMS.contains(&word) && then.starts_with(' ')
            })
        })
}

/// `struct Node {`, `enum Split<`, `struct Hit(`, `trait Shape:`.
fn type_definition(line: &str) -> bool {
    ["struct ", "enum ", "trait ", "union "]
        .into_iter()
        .flat_map(|keyword| after(line, keyword))
        .any(|rest| {
            identifier(rest.trim_start()).is_some_and(|(name, then)| {
                name.starts_with(|c: char| c.is_ascii_uppercase())
                    && then.trim_start().starts_with(['{', '<', '(', ';', ':'])
            })
        })
}

/// `impl<T> …`, `impl Shape for Sphere {`.
fn implementation(line: &str) -> bool {
    after(line, "impl<").next().is_some()
        || (after(line, "impl ").next().is_some() && line.ends_with('{'))
}

/// `let mut t`, `let hit =`, `let t: f64`, `let (a, b) = …;`.
fn binding(line: &str) -> bool {
    after(line, "let ").any(|rest| {
        let rest = rest.trim_start();
        if let Some(name) = rest.strip_prefix("mut ") {
            return identifier(name.trim_start()).is_some();
        }
        if rest.starts_with('(') {
            return rest.contains(" = ") && line.ends_with(';');
        }
        identifier(rest).is_some_and(|(_, then)| {
            let then = then.trim_start();
            then.starts_with(':') && !then.starts_with("::")
                || then.starts_with('=') && !then.starts_with("==")
        })
    })
}

/// `use crate::…`, `use std::…`, `use ch08::…`.
fn import(line: &str) -> bool {
    after(line, "use ").any(|rest| {
        identifier(rest.trim_start())
            .is_some_and(|(_, then)| then.starts_with("::"))
    })
}

/// `const FIXED: usize`, `static TABLE:`.
fn constant(line: &str) -> bool {
    ["const ", "static "]
        .into_iter()
        .flat_map(|keyword| after(line, keyword))
        .any(|rest| {
            identifier(rest.trim_start()).is_some_and(|(name, then)| {
                name.starts_with(|c: char| c.is_ascii_uppercase())
                    && then.starts_with(':')
            })
        })
}

/// `assert!(`, `todo!()`, `vec![`: a snake_case name right before `!(` or
/// `![`.
fn macro_call(line: &str) -> bool {
    line.match_indices(['!']).any(|(at, _)| {
        let before = &line[..at];
        let name_start = before
            .rfind(|c: char| !is_identifier_char(c))
            .map_or(0, |i| i + 1);
        let name = &before[name_start..];
        line[at + 1..].starts_with(['(', '['])
            && name.starts_with(|c: char| c.is_ascii_lowercase())
            && name.chars().all(|c| {
                c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_'
            })
    })
}

/// `if t < best {`, `for node in nodes {`, `} else {`, and a lone `}`.
fn block(line: &str) -> bool {
    const OPENERS: [&str; 7] =
        ["if", "for", "while", "match", "loop", "else", "}"];
    let first = line.split_whitespace().next().unwrap_or("");
    (line.ends_with('{') && line.len() > 1 && OPENERS.contains(&first))
        || matches!(line, "}" | "};" | "}," | "})" | "});")
}

/// The rest of `line` after each place `pattern` starts a word (no letter,
/// digit or `_` just before it).
fn after<'a>(
    line: &'a str, pattern: &'a str,
) -> impl Iterator<Item = &'a str> + 'a {
    line.match_indices(pattern)
        .filter(|(at, _)| !line[..*at].ends_with(is_identifier_char))
        .map(move |(at, _)| &line[at + pattern.len()..])
}

/// The identifier `text` starts with, and what follows it.
fn identifier(text: &str) -> Option<(&str, &str)> {
    if !text.starts_with(|c: char| c.is_alphabetic() || c == '_') {
        return None;
    }
    let end = text
        .find(|c: char| !is_identifier_char(c))
        .unwrap_or(text.len());
    Some(text.split_at(end))
}

fn is_identifier_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lines of the lecture's listings, as a paragraph shows them when a
    /// listing loses its fence (Markdown has eaten `<Hit>` and `*`).
    const LISTING_LINES: [&str; 22] = [
        "/// The closest hit of the ray, if any.",
        "// Step 4: t = −(N·P₀ + d) / (N·D).",
        "#[derive(Debug, Clone, Copy)]",
        "#[inline]",
        "pub fn hit(ray: &Ray, t_max: f64) -> Option {",
        "fn walk(",
        "pub(crate) struct Node {",
        "pub struct Bvh {",
        "struct Wide(",
        "impl Shape for Sphere {",
        "impl Bvh {",
        "let mut stack = Vec::new();",
        "let t = -(n.dot(origin) + d) / n.dot(direction);",
        "let hit: Option = None;",
        "let (near, far) = (t0.min(t1), t0.max(t1));",
        "use crate::ray::Ray;",
        "const FIXED: usize = 32;",
        "debug_assert!(t >= 0.0);",
        "while let Some(node) = stack.pop() {",
        "} else {",
        "}",
        "});",
    ];

    /// Lines of the book's prose, with its inline code left out as the
    /// check leaves it out (a span becomes nothing).
    const PROSE_LINES: [&str; 14] = [
        "Each function starts as  ; the tests wait for it.",
        "The walk keeps a stack of nodes; for trees up to 32 deep it stays",
        "on the call stack (the fixed array of ).",
        "We use the closest-hit loop of chapter 3, and let the tracer ask",
        "let the ray be the one through the pixel center:",
        "Let t be the distance along the ray.",
        "A struct of arrays holds the boxes (SoA): four children at once.",
        "The impl block of  holds every step.",
        "for each child, if its box is hit {nearer first}",
        "Stop! (The rest is for engineers.)",
        "see https://pbr-book.org/4ed/Shapes//Triangle_Meshes for the test",
        "The enum Split names the axis; const time per node.",
        "C++ (Embree: 1.2 Grays/s) vs Rust (obvhs: 0.9)",
        "A = {x | f(x) = 0}",
    ];

    #[test]
    fn listing_lines_read_as_rust() {
        for line in LISTING_LINES {
            assert!(reads_as_rust(line), "{line}");
        }
    }

    #[test]
    fn prose_lines_do_not() {
        for line in PROSE_LINES {
            assert!(!reads_as_rust(line), "{line}");
        }
    }

    #[test]
    fn a_listing_run_into_a_paragraph_is_found_by_its_first_rust_line() {
        let paragraph = "The walk of the compact tree:\n\
                         pub fn walk(&self, ray: &Ray32) -> Option {\n    \
                         let mut stack = [0u32; 64];";
        assert_eq!(
            rust_line(paragraph),
            Some("pub fn walk(&self, ray: &Ray32) -> Option {")
        );
        assert_eq!(rust_line(PROSE_LINES.join("\n").as_str()), None);
    }
}
