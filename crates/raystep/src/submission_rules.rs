//! What a submitted exercise file may not say: anything that reaches past
//! its own text and the lecture's arithmetic.
//!
//! An exercise is judged on the code in its one file. A file that includes
//! another (`#[path]`, `mod name;`, `include!`, `include_str!`,
//! `include_bytes!`), reads the build's environment (`env!`,
//! `option_env!`, `CARGO_MANIFEST_DIR` among it) or reaches the operating
//! system (`std::process`, `std::fs`, `std::net`, `std::os`, `std::env`,
//! `unsafe`, `extern`, inline assembly, linker attributes, macros that could
//! spell any of these) could hand in the reference solution, read the
//! tests' expected answers, or end the test binary with a verdict of its
//! own. No exercise needs any of them, so `check` and `grade` refuse such a
//! file with its line and column instead of running it.
//!
//! The scan reads the file as Rust tokens: comments and string literals
//! are skipped, so a doc comment that mentions `include!` is fine.

/// Why a file is refused: where, and what it says.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    /// 1-based line of the token.
    pub line: usize,
    /// 1-based column (in characters) of the token.
    pub column: usize,
    /// What the token does, for the verdict.
    pub what: String,
}

impl Refusal {
    /// `exercise/x.rs:3:1: #[path] names another file; …`.
    pub fn describe(&self, file: &str) -> String {
        format!(
            "{file}:{}:{}: {} (an exercise is judged on its own code: no \
             other file, no environment, no operating system)",
            self.line, self.column, self.what
        )
    }
}

/// Identifiers refused wherever they stand, and what each does.
const REFUSED: &[(&str, &str)] = &[
    ("include", "`include!` takes code from another file"),
    ("include_str", "`include_str!` reads another file"),
    ("include_bytes", "`include_bytes!` reads another file"),
    ("option_env", "`option_env!` reads the build's environment"),
    ("unsafe", "`unsafe` code"),
    ("extern", "`extern` links to code outside the exercise"),
    ("asm", "inline assembly"),
    ("global_asm", "inline assembly"),
    ("naked_asm", "inline assembly"),
    (
        "macro_rules",
        "`macro_rules!` (a macro could spell what is refused here)",
    ),
];

/// Modules of `std` refused where they are named as a path (`std::fs`,
/// `fs::read`, `use std::{fs}`, `env!`), so that a variable may still be
/// called `fs`.
const REFUSED_PATHS: &[(&str, &str)] = &[
    (
        "env",
        "`env` reads the build's or the program's environment",
    ),
    ("process", "`std::process` starts or ends processes"),
    ("fs", "`std::fs` reads or writes files"),
    ("net", "`std::net` opens network connections"),
    ("os", "`std::os` reaches the operating system"),
];

/// Names refused inside an attribute (`#[…]`, `#![…]`).
const REFUSED_IN_ATTRIBUTES: &[(&str, &str)] = &[
    ("path", "`#[path]` names another file"),
    (
        "no_mangle",
        "`#[no_mangle]` replaces a symbol of the program",
    ),
    (
        "export_name",
        "`#[export_name]` replaces a symbol of the program",
    ),
    ("link", "`#[link]` links to code outside the exercise"),
    (
        "link_name",
        "`#[link_name]` links to code outside the exercise",
    ),
    (
        "link_section",
        "`#[link_section]` places code outside the exercise",
    ),
    ("used", "`#[used]` keeps code the exercise does not call"),
];

/// The first thing in `text` that a submission may not say, if any.
pub fn first_refusal(text: &str) -> Option<Refusal> {
    let tokens = tokens(text);
    // Depth of `[` inside an attribute, while in one.
    let mut attribute_depth: Option<usize> = None;
    // Inside a `use` declaration (until its `;`).
    let mut in_use = false;
    for (i, token) in tokens.iter().enumerate() {
        let refuse = |what: &str| Refusal {
            line: token.line,
            column: token.column,
            what: what.to_string(),
        };
        match &token.kind {
            Kind::Punct('#') if attribute_depth.is_none() => {
                let next = |k: usize| tokens.get(i + k).map(|t| &t.kind);
                if next(1) == Some(&Kind::Punct('['))
                    || (next(1) == Some(&Kind::Punct('!'))
                        && next(2) == Some(&Kind::Punct('[')))
                {
                    attribute_depth = Some(0);
                }
            }
            Kind::Punct('[') => {
                if let Some(depth) = attribute_depth.as_mut() {
                    *depth += 1;
                }
            }
            Kind::Punct(']') => {
                if let Some(depth) = attribute_depth.as_mut() {
                    *depth -= 1;
                    if *depth == 0 {
                        attribute_depth = None;
                    }
                }
            }
            Kind::Punct(';') => in_use = false,
            Kind::Ident(name) => {
                if let Some((_, what)) = REFUSED.iter().find(|(n, _)| n == name)
                {
                    return Some(refuse(what));
                }
                in_use |= name == "use";
                let punct = |k: Option<usize>| {
                    k.and_then(|k| tokens.get(k)).and_then(|t| match t.kind {
                        Kind::Punct(c) => Some(c),
                        Kind::Ident(_) => None,
                    })
                };
                let as_path = in_use
                    || punct(i.checked_sub(1)) == Some(':')
                    || matches!(punct(Some(i + 1)), Some(':' | '!'));
                if as_path
                    && let Some((_, what)) =
                        REFUSED_PATHS.iter().find(|(n, _)| n == name)
                {
                    return Some(refuse(what));
                }
                if attribute_depth.is_some()
                    && let Some((_, what)) =
                        REFUSED_IN_ATTRIBUTES.iter().find(|(n, _)| n == name)
                {
                    return Some(refuse(what));
                }
                // `mod name;`: a module in another file.
                let is_ident = |k: usize| {
                    matches!(
                        tokens.get(i + k).map(|t| &t.kind),
                        Some(Kind::Ident(_))
                    )
                };
                if name == "mod"
                    && is_ident(1)
                    && tokens.get(i + 2).map(|t| &t.kind)
                        == Some(&Kind::Punct(';'))
                {
                    return Some(refuse(
                        "`mod name;` takes a module from another file",
                    ));
                }
            }
            Kind::Punct(_) => {}
        }
    }
    None
}

/// A token that matters to the rules: an identifier (raw ones without
/// `r#`) or one punctuation character. Literals, lifetimes and comments
/// are dropped.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Kind {
    Ident(String),
    Punct(char),
}

#[derive(Debug)]
struct Token {
    kind: Kind,
    line: usize,
    column: usize,
}

/// The characters of a text with their 1-based line and column.
struct Cursor {
    chars: Vec<char>,
    at: usize,
    line: usize,
    column: usize,
}

impl Cursor {
    fn peek(&self, ahead: usize) -> Option<char> {
        self.chars.get(self.at + ahead).copied()
    }

    fn bump(&mut self) -> Option<char> {
        let c = self.peek(0)?;
        self.at += 1;
        if c == '\n' {
            self.line += 1;
            self.column = 1;
        } else {
            self.column += 1;
        }
        Some(c)
    }

    /// Skips a quoted literal whose opening quote is next, with `\`
    /// escapes unless `raw`; a raw literal ends at the quote followed by
    /// `hashes` `#`s.
    fn skip_quoted(&mut self, quote: char, raw: bool, hashes: usize) {
        self.bump();
        while let Some(c) = self.bump() {
            if c == '\\' && !raw {
                self.bump();
            } else if c == quote
                && (0..hashes).all(|k| self.peek(k) == Some('#'))
            {
                for _ in 0..hashes {
                    self.bump();
                }
                return;
            }
        }
    }

    /// Skips a (nested) block comment whose `/*` is next.
    fn skip_block_comment(&mut self) {
        self.bump();
        self.bump();
        let mut depth = 1;
        while depth > 0 {
            match (self.bump(), self.peek(0)) {
                (Some('/'), Some('*')) => {
                    self.bump();
                    depth += 1;
                }
                (Some('*'), Some('/')) => {
                    self.bump();
                    depth -= 1;
                }
                (None, _) => return,
                _ => {}
            }
        }
    }
}

fn is_ident_start(c: char) -> bool {
    c == '_' || c.is_alphabetic()
}

fn is_ident_continue(c: char) -> bool {
    c == '_' || c.is_alphanumeric()
}

/// The identifiers and punctuation of `text`, in order.
fn tokens(text: &str) -> Vec<Token> {
    let mut cursor = Cursor {
        chars: text.chars().collect(),
        at: 0,
        line: 1,
        column: 1,
    };
    let mut tokens = Vec::new();
    while let Some(c) = cursor.peek(0) {
        let (line, column) = (cursor.line, cursor.column);
        match c {
            _ if c.is_whitespace() => {
                cursor.bump();
            }
            '/' if cursor.peek(1) == Some('/') => {
                while cursor.peek(0).is_some_and(|c| c != '\n') {
                    cursor.bump();
                }
            }
            '/' if cursor.peek(1) == Some('*') => cursor.skip_block_comment(),
            '"' => cursor.skip_quoted('"', false, 0),
            '\'' => {
                // A char literal ('a', '\n', '\u{1F600}') or a lifetime ('a).
                let is_char = matches!(
                    (cursor.peek(1), cursor.peek(2)),
                    (Some('\\'), _) | (Some(_), Some('\''))
                );
                if is_char {
                    cursor.skip_quoted('\'', false, 0);
                } else {
                    cursor.bump();
                    while cursor.peek(0).is_some_and(is_ident_continue) {
                        cursor.bump();
                    }
                }
            }
            _ if c.is_ascii_digit() => {
                // A number, with its suffix and exponent (`1e-3f64`).
                while let Some(c) = cursor.peek(0) {
                    let sign = (c == '-' || c == '+')
                        && matches!(
                            cursor.chars.get(cursor.at.wrapping_sub(1)),
                            Some('e' | 'E')
                        );
                    if is_ident_continue(c) || c == '.' || sign {
                        if c == '.' && cursor.peek(1) == Some('.') {
                            break; // a range: 0..n
                        }
                        cursor.bump();
                    } else {
                        break;
                    }
                }
            }
            _ if is_ident_start(c) => {
                let mut name = String::new();
                while let Some(c) =
                    cursor.peek(0).filter(|&c| is_ident_continue(c))
                {
                    name.push(c);
                    cursor.bump();
                }
                // Literal prefixes: b"…", r"…", r#"…"#, br"…", c"…", b'x'.
                let next = cursor.peek(0);
                let raw = matches!(name.as_str(), "r" | "br" | "cr");
                if raw && (next == Some('"') || next == Some('#')) {
                    let mut hashes = 0;
                    while cursor.peek(hashes) == Some('#') {
                        hashes += 1;
                    }
                    if cursor.peek(hashes) == Some('"') {
                        for _ in 0..hashes {
                            cursor.bump();
                        }
                        cursor.skip_quoted('"', true, hashes);
                        continue;
                    }
                    if name == "r" && hashes == 1 {
                        // A raw identifier: r#name.
                        cursor.bump();
                        let (line, column) = (cursor.line, cursor.column);
                        let mut raw_name = String::new();
                        while let Some(c) =
                            cursor.peek(0).filter(|&c| is_ident_continue(c))
                        {
                            raw_name.push(c);
                            cursor.bump();
                        }
                        tokens.push(Token {
                            kind: Kind::Ident(raw_name),
                            line,
                            column,
                        });
                        continue;
                    }
                }
                if matches!(name.as_str(), "b" | "c") && next == Some('"') {
                    cursor.skip_quoted('"', false, 0);
                    continue;
                }
                if name == "b" && next == Some('\'') {
                    cursor.skip_quoted('\'', false, 0);
                    continue;
                }
                tokens.push(Token {
                    kind: Kind::Ident(name),
                    line,
                    column,
                });
            }
            _ => {
                cursor.bump();
                tokens.push(Token {
                    kind: Kind::Punct(c),
                    line,
                    column,
                });
            }
        }
    }
    tokens
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(text: &str) -> Option<(usize, usize, String)> {
        first_refusal(text).map(|r| (r.line, r.column, r.what))
    }

    #[test]
    fn a_plain_solution_passes() {
        let text = r##"
//! Exercise 1: mentions include!("x") and #[path = "y"] in a comment.
use crate::{Degenerate, Line2};
/* a block /* nested */ comment: std::process::exit(0) */
pub fn rotate90(v: DVec2) -> DVec2 {
    let s = "std::fs::read(\"x\") in a string";
    let r = r#"include_str!("../src/x.rs")"#;
    let b = b"env!";
    let c = 'e';
    let path = Path::new(1e-3, 0..3, 2.5e+10f64, b'x', '\'');
    let (fs, env, os) = (path.f(), 1.0, [0u8]);
    let _: &'static str = s;
    DVec2::new(v.x, -v.y)
}
#[allow(clippy::needless_range_loop)]
mod inline { pub fn f() {} }
"##;
        assert_eq!(refused(text), None);
    }

    #[test]
    fn every_trick_is_refused_where_it_is() {
        let cases: &[(&str, (usize, usize), &str)] = &[
            (
                "#[path = \"../src/line_through_points.rs\"]\nmod reference;",
                (1, 3),
                "`#[path]`",
            ),
            (
                "#[cfg_attr(all(), path = \"/abs/x.rs\")]\nmod r { }",
                (1, 19),
                "`#[path]`",
            ),
            (
                "mod reference;\npub use reference::*;",
                (1, 1),
                "`mod name;`",
            ),
            (
                "fn f() { include!(\"../src/x.rs\") }",
                (1, 10),
                "`include!`",
            ),
            (
                "const S: &str = include_str!(\"x\");",
                (1, 17),
                "`include_str!`",
            ),
            (
                "const B: &[u8] = include_bytes!(\"x\");",
                (1, 18),
                "`include_bytes!`",
            ),
            ("let d = env!(\"CARGO_MANIFEST_DIR\");", (1, 9), "`env`"),
            ("let d = option_env!(\"HOME\");", (1, 9), "`option_env!`"),
            ("let d = std::env::var(\"HOME\");", (1, 14), "`env`"),
            ("use std::{io, process::exit};", (1, 15), "`std::process`"),
            ("let t = std::fs::read(\"x\");", (1, 14), "`std::fs`"),
            ("use std::net::TcpStream;", (1, 10), "`std::net`"),
            ("use std::os::unix::process;", (1, 10), "`std::os`"),
            ("fn f() { unsafe { g() } }", (1, 10), "`unsafe`"),
            (
                "unsafe extern \"C\" { fn exit(c: i32); }",
                (1, 1),
                "`unsafe`",
            ),
            ("extern \"C\" { fn exit(c: i32); }", (1, 1), "`extern`"),
            ("extern crate std as s;", (1, 1), "`extern`"),
            (
                "macro_rules! m { ($x:ident) => { $x!() } }",
                (1, 1),
                "`macro_rules!`",
            ),
            ("fn f() { r#include!(\"x\") }", (1, 12), "`include!`"),
            ("#[unsafe(no_mangle)] fn main() {}", (1, 3), "`unsafe`"),
            ("#[no_mangle] pub fn f() {}", (1, 3), "`#[no_mangle]`"),
            ("#![cfg_attr(x, path = \"y\")]", (1, 16), "`#[path]`"),
            (
                "fn f() { core::arch::asm!(\"nop\") }",
                (1, 22),
                "inline assembly",
            ),
            ("fn f() {}\n  /* x */ mod other;", (2, 11), "`mod name;`"),
        ];
        for (text, (line, column), what) in cases {
            let got = refused(text);
            let Some((l, c, w)) = got.clone() else {
                panic!("{text:?}: expected a refusal, got none");
            };
            assert!(
                (l, c) == (*line, *column) && w.starts_with(what),
                "{text:?}: expected {what} at {line}:{column}, got {got:?}"
            );
        }
    }

    #[test]
    fn the_refusal_names_file_line_and_column() {
        let refusal =
            first_refusal("\n\n  #[path = \"x.rs\"]\nmod r;").unwrap();
        assert_eq!(
            refusal.describe("exercise/line_through_points.rs"),
            "exercise/line_through_points.rs:3:5: `#[path]` names another \
             file (an exercise is judged on its own code: no other file, no \
             environment, no operating system)"
        );
    }

    /// Every exercise stub and every reference module of the lecture
    /// passes: the rules refuse nothing a solution needs.
    #[test]
    fn the_lecture_s_own_exercise_files_pass() {
        let root =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let mut seen = 0;
        for chapter in crate::chapters::CHAPTERS {
            let dir = root.join("chapters").join(chapter.package);
            for exercise in chapter.exercises {
                let stub = dir.join("exercise").join(format!("{exercise}.rs"));
                let module =
                    crate::reference_module::reference_module(&dir, exercise)
                        .unwrap();
                for path in [stub, module] {
                    let text = std::fs::read_to_string(&path).unwrap();
                    if let Some(refusal) = first_refusal(&text) {
                        panic!(
                            "{}",
                            refusal.describe(&path.display().to_string())
                        );
                    }
                    seen += 1;
                }
            }
        }
        assert_eq!(seen, 50, "25 exercises, stub and reference each");
    }
}
