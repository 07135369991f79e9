//! LaTeX math in the pages, typeset as MathML when the book is built:
//! `$…$` inline, `$$…$$` on lines of their own for a displayed equation.
//! The browser draws MathML itself, so nothing is downloaded and no script
//! runs; the book ships a math font (see `raystep book`).

use math_core::{LatexToMathML, MathCoreConfig, MathDisplay};
use std::sync::OnceLock;

/// The converter, configured once.
fn converter() -> &'static LatexToMathML {
    static CONVERTER: OnceLock<LatexToMathML> = OnceLock::new();
    CONVERTER.get_or_init(|| {
        LatexToMathML::new(MathCoreConfig::default())
            .expect("no custom macros to parse")
    })
}

/// MathML for one formula, or the converter's complaint.
fn mathml(latex: &str, display: MathDisplay) -> Result<String, String> {
    converter()
        .convert_with_local_state(latex, display)
        .map(|result| result.mathml)
        .map_err(|e| format!("math `{latex}`: {}", describe(&e)))
}

/// The converter's error in words.
fn describe(error: &math_core::LatexError) -> String {
    let text = format!("{error:?}");
    // `LatexError(0..4, UnknownCommand("bad"))` → `UnknownCommand("bad") at 0..4`
    match text
        .strip_prefix("LatexError(")
        .and_then(|t| t.strip_suffix(')'))
        .and_then(|t| t.split_once(", "))
    {
        Some((span, kind)) => format!("{kind} at bytes {span}"),
        None => text,
    }
}

/// A displayed equation: one HTML block the Markdown renderer leaves alone.
pub fn display(latex: &str) -> Result<String, String> {
    let math = mathml(latex.trim(), MathDisplay::Block)?;
    Ok(format!(r#"<div class="equation">{math}</div>"#))
}

/// A line of running text with its `$…$` formulas as MathML. Code spans
/// (`` `…` ``) are left alone and `\$` stays a dollar sign; the rest keeps
/// its numbers in one piece ([`crate::typography`]).
pub fn inline(line: &str) -> Result<String, String> {
    let mut out = String::with_capacity(line.len());
    let mut rest = line;
    while let Some(at) = rest.find(['$', '`', '\\']) {
        out.push_str(&crate::typography::tie_numbers(&rest[..at]));
        let tail = &rest[at..];
        if let Some(escaped) = tail.strip_prefix('\\') {
            // A backslash escapes the next character, as in Markdown.
            let next = escaped.chars().next().map_or(0, char::len_utf8);
            out.push_str(&tail[..1 + next]);
            rest = &tail[1 + next..];
        } else if tail.starts_with('`') {
            let ticks = tail.len() - tail.trim_start_matches('`').len();
            let fence = &tail[..ticks];
            match tail[ticks..].find(fence) {
                Some(close) => {
                    let end = ticks + close + ticks;
                    out.push_str(&tail[..end]);
                    rest = &tail[end..];
                }
                None => {
                    out.push_str(fence);
                    rest = &tail[ticks..];
                }
            }
        } else {
            let body = &tail[1..];
            let close = closing_dollar(body).ok_or_else(|| {
                format!("`$` opens a formula that does not close on this line: `{tail}`")
            })?;
            let latex = &body[..close];
            if latex.trim().is_empty() {
                return Err("empty formula `$$` inside a line".into());
            }
            let math = for_markdown(&mathml(latex, MathDisplay::Inline)?);
            // The words touching the formula stay on its line.
            let pre = out.split_off(glued_end(&out));
            let after = &body[close + 1..];
            let post = &after[..glued_start(after)];
            out.push_str(&format!(
                r#"<span class="nowrap">{pre}{math}{post}</span>"#
            ));
            rest = &after[post.len()..];
        }
    }
    out.push_str(&crate::typography::tie_numbers(rest));
    Ok(out)
}

/// Characters that a browser may break a line at next to a formula (an
/// inline `<math>` is one unbreakable box), and that can sit inside an
/// HTML span without changing how Markdown reads them: not spaces, not
/// Markdown's own `*`, `_`, `` ` ``, `[`, `]`, `\`, `<`, `>`, `$`.
fn glues(c: char) -> bool {
    !c.is_whitespace() && !"*_`[]\\<>$|".contains(c)
}

/// Where the glued characters at the end of `text` begin (a byte offset).
fn glued_end(text: &str) -> usize {
    text.char_indices()
        .rev()
        .take_while(|(_, c)| glues(*c))
        .last()
        .map_or(text.len(), |(i, _)| i)
}

/// How many bytes of glued characters `text` starts with.
fn glued_start(text: &str) -> usize {
    text.char_indices()
        .find(|(_, c)| !glues(*c))
        .map_or(text.len(), |(i, _)| i)
}

/// Where the formula in `body` ends: the first `$` not escaped by `\`.
fn closing_dollar(body: &str) -> Option<usize> {
    let mut escaped = false;
    for (i, c) in body.char_indices() {
        match c {
            '\\' => escaped = !escaped,
            '$' if !escaped => return Some(i),
            _ => escaped = false,
        }
    }
    None
}

/// Inline MathML sits in running Markdown, which would still read `*`, `_`,
/// `|` or a quote between its tags: those become character references.
fn for_markdown(mathml: &str) -> String {
    let mut out = String::with_capacity(mathml.len());
    for c in mathml.chars() {
        match c {
            '*' | '_' | '\\' | '`' | '[' | ']' | '|' | '~' | '\'' => {
                out.push_str(&format!("&#{};", c as u32));
            }
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inline_formulas_become_mathml_and_code_is_left_alone() {
        let line = inline(r"at $t = -d$, see `a $b$` and \$5").unwrap();
        assert!(
            line.starts_with(r#"at <span class="nowrap"><math><mi>t</mi>"#),
            "{line}"
        );
        assert!(line.contains("</math>,</span> see"), "{line}");
        assert!(line.contains("`a $b$`"), "{line}");
        assert!(line.ends_with(r"and \$5"), "{line}");
    }

    #[test]
    fn punctuation_touching_a_formula_stays_on_its_line() {
        let line = inline(r"see ($x$’s value), or **$y$**").unwrap();
        assert!(
            line.contains(r#"see <span class="nowrap">(<math>"#),
            "{line}"
        );
        assert!(line.contains("</math>’s</span> value)"), "{line}");
        // Markdown's own characters are never pulled into the span.
        assert!(line.contains(r#"**<span class="nowrap"><math>"#), "{line}");
        assert!(line.ends_with("</math></span>**"), "{line}");
    }

    #[test]
    fn markdown_characters_inside_formulas_are_escaped() {
        // `|` would split a table cell.
        let line = inline(r"$|x|$").unwrap();
        assert!(line.contains("&#124;") && !line.contains('|'), "{line}");
    }

    #[test]
    fn errors_name_the_formula() {
        let error = inline(r"an $\unknown{x}$").unwrap_err();
        assert!(error.contains(r"\unknown{x}"), "{error}");
        assert!(error.contains("UnknownCommand"), "{error}");
        assert!(inline("costs $5").unwrap_err().contains("does not close"));
    }

    #[test]
    fn a_displayed_equation_is_one_html_block() {
        let block = display(r"\frac{a}{b}").unwrap();
        assert!(
            block
                .starts_with(r#"<div class="equation"><math display="block">"#)
        );
        assert!(!block.contains('\n'));
    }
}
