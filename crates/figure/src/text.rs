//! Label markup and the SVG `<text>` elements it turns into.
//!
//! Markup: `_` makes the next character, or the `{...}` group after it, a subscript
//! (`"P_0"`, `"E_{12}"`); `^` likewise makes a superscript (`"x^2"`, `"e^{-t}"`). Everything else is
//! literal text, so `"f(x, y) > 0"` is fine, and Greek letters are typed directly (`"θ"`, `"φ"`).
//! A backslash makes the next character literal (`"a\_b"` shows `a_b`). XML special characters are
//! escaped. Sub- and superscripts are `<tspan>`s with a smaller font size and a `baseline-shift`
//! in user units, which usvg lays out.

use crate::style::{Color, num};

/// Sub- and superscripts are this fraction of the label's font size.
const SCRIPT_SIZE: f64 = 0.7;
/// A subscript's baseline sits this fraction of the font size below the text's baseline.
const SUB_SHIFT: f64 = 0.2;
/// A superscript's baseline sits this fraction of the font size above the text's baseline.
const SUPER_SHIFT: f64 = 0.38;
/// Height of DejaVu Sans capitals as a fraction of the font size (1493 / 2048 units).
pub(crate) const CAP_HEIGHT: f64 = 0.73;

/// One run of label text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Run {
    /// Text on the baseline.
    Normal(String),
    /// A subscript.
    Sub(String),
    /// A superscript.
    Super(String),
}

/// Splits label markup into runs (see the module documentation).
pub(crate) fn parse_markup(text: &str) -> Vec<Run> {
    let mut runs = Vec::new();
    let mut normal = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => normal.push(chars.next().unwrap_or('\\')),
            '_' | '^' if chars.peek().is_some() => {
                let mut script = String::new();
                if chars.peek() == Some(&'{') {
                    chars.next();
                    for g in chars.by_ref() {
                        if g == '}' {
                            break;
                        }
                        script.push(g);
                    }
                } else if let Some(g) = chars.next() {
                    script.push(g);
                }
                if !normal.is_empty() {
                    runs.push(Run::Normal(std::mem::take(&mut normal)));
                }
                runs.push(if c == '_' {
                    Run::Sub(script)
                } else {
                    Run::Super(script)
                });
            }
            _ => normal.push(c),
        }
    }
    if !normal.is_empty() {
        runs.push(Run::Normal(normal));
    }
    runs
}

/// Escapes the XML special characters of `text`.
pub(crate) fn escape_xml(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            _ => out.push(c),
        }
    }
    out
}

/// The contents of a `<text>` element of font size `size` showing label
/// markup `text`: escaped text, scripts as `<tspan>`s.
pub(crate) fn markup_spans(text: &str, size: f64) -> String {
    let script = |body: &str, shift: f64| {
        format!(
            r#"<tspan font-size="{}" baseline-shift="{}">{}</tspan>"#,
            num(SCRIPT_SIZE * size),
            num(shift * size),
            escape_xml(body)
        )
    };
    let mut s = String::new();
    for run in parse_markup(text) {
        match run {
            Run::Normal(t) => s.push_str(&escape_xml(&t)),
            Run::Sub(t) => s.push_str(&script(&t, -SUB_SHIFT)),
            Run::Super(t) => s.push_str(&script(&t, SUPER_SHIFT)),
        }
    }
    s
}

/// `text` with the XML entities [`escape_xml`] writes turned back into
/// their characters.
pub(crate) fn unescape_xml(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// How a text line lines up with its `x`: the SVG `text-anchor`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Align {
    Start,
    Middle,
    End,
}

/// A `<text>` element for label markup `text` with its baseline starting (or centred, or ending)
/// at page point (`x`, `y`).
pub(crate) fn text_element(
    x: f64, y: f64, text: &str, align: Align, size: f64, color: Color,
) -> String {
    let anchor = match align {
        Align::Start => "start",
        Align::Middle => "middle",
        Align::End => "end",
    };
    let mut s = format!(
        r#"<text x="{}" y="{}" font-size="{}" fill="{}" text-anchor="{anchor}">"#,
        num(x),
        num(y),
        num(size),
        color.hex()
    );
    s.push_str(&markup_spans(text, size));
    s.push_str("</text>");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subscripts_and_superscripts() {
        assert_eq!(
            parse_markup("P_0"),
            vec![Run::Normal("P".into()), Run::Sub("0".into())]
        );
        assert_eq!(
            parse_markup("E_{12} + x^2"),
            vec![
                Run::Normal("E".into()),
                Run::Sub("12".into()),
                Run::Normal(" + x".into()),
                Run::Super("2".into())
            ]
        );
        assert_eq!(parse_markup(r"a\_b"), vec![Run::Normal("a_b".into())]);
        assert_eq!(parse_markup("θ_"), vec![Run::Normal("θ_".into())]);
    }

    #[test]
    fn text_is_escaped() {
        let t = text_element(
            0.0,
            0.0,
            "f < 0 & g > 0",
            Align::Start,
            16.0,
            Color::rgb(0, 0, 0),
        );
        assert!(t.contains("f &lt; 0 &amp; g &gt; 0"), "{t}");
    }
}
