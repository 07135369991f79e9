//! [`SceneError`] and how a byte span in the file becomes
//! `FILE:LINE:COLUMN: FIELD`.

use std::ops::Range;
use std::path::PathBuf;

use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// Why a scene could not be loaded. Every variant's `Display` is one line.
///
/// All but [`SceneError::Read`] read `FILE:LINE:COLUMN: FIELD: what is wrong`,
/// for example
/// `scenes/bad.toml:14:10: objects[2].sphere.radius: must be positive, got -1`.
/// Lines and columns count from 1; columns count characters, not bytes.
/// `FIELD` is the dotted path to the value in the file, array entries
/// counted from 0 (`objects[0]` is the first `[[objects]]` entry).
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file could not be read.
    #[error("{}: cannot read the scene file: {source}", path.display())]
    Read {
        /// The path given to [`load`](crate::load).
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
    /// The file is not valid TOML.
    #[error("{file}:{line}:{column}: TOML syntax: {message}")]
    Syntax {
        /// The file name given to [`parse`](crate::parse).
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column, in characters.
        column: usize,
        /// The TOML parser's message.
        message: String,
    },
    /// The file is TOML but not a valid scene: an unknown or missing field,
    /// a value of the wrong type, or a value out of range.
    #[error("{file}:{line}:{column}: {}{message}", field_prefix(field))]
    Invalid {
        /// The file name given to [`parse`](crate::parse).
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column, in characters.
        column: usize,
        /// The path to the offending value, like `objects[2].sphere.radius`
        /// (empty only if the error concerns the whole file).
        field: String,
        /// What is wrong with it.
        message: String,
    },
}

fn field_prefix(field: &str) -> String {
    if field.is_empty() {
        String::new()
    } else {
        format!("{field}: ")
    }
}

/// One key or array entry of the parsed document.
struct Node {
    path: String,
    key: Option<Range<usize>>,
    value: Range<usize>,
    depth: usize,
}

/// Turns spans into locations and field paths, for one file.
pub(crate) struct Context<'a> {
    source: &'a str,
    file: &'a str,
    nodes: Vec<Node>,
}

impl<'a> Context<'a> {
    /// Remembers the path and span of every value in `document`.
    pub(crate) fn new(
        source: &'a str, file: &'a str, document: &Spanned<DeTable<'_>>,
    ) -> Self {
        let mut nodes = Vec::new();
        collect_table(document.get_ref(), "", 1, &mut nodes);
        Context {
            source,
            file,
            nodes,
        }
    }

    /// 1-based line and column (in characters) of byte `offset`.
    pub(crate) fn line_column(&self, offset: usize) -> (usize, usize) {
        line_column(self.source, offset)
    }

    /// The path of the smallest key or value that contains `span`, or ""
    /// for an empty span (serde's errors about the whole document).
    fn field_at(&self, span: &Range<usize>) -> String {
        if span.is_empty() {
            return String::new();
        }
        let contains =
            |r: &Range<usize>| r.start <= span.start && span.end <= r.end;
        let mut best: Option<(usize, usize, &str)> = None;
        for node in &self.nodes {
            let candidates = [Some(&node.value), node.key.as_ref()];
            for r in candidates.into_iter().flatten() {
                if contains(r) {
                    let better = match best {
                        None => true,
                        Some((len, depth, _)) => {
                            r.len() < len
                                || (r.len() == len && node.depth > depth)
                        }
                    };
                    if better {
                        best = Some((r.len(), node.depth, &node.path));
                    }
                }
            }
        }
        best.map(|(_, _, path)| path.to_owned()).unwrap_or_default()
    }

    /// An error about the value at `span`; the field is found from the span.
    pub(crate) fn error(
        &self, span: Range<usize>, message: impl Into<String>,
    ) -> SceneError {
        let field = self.field_at(&span);
        self.error_in(span, field, message)
    }

    /// An error about `field`, located at `span` (used when the field is
    /// absent and `span` is its table's).
    pub(crate) fn error_in(
        &self, span: Range<usize>, field: String, message: impl Into<String>,
    ) -> SceneError {
        let (line, column) = self.line_column(span.start);
        SceneError::Invalid {
            file: self.file.to_owned(),
            line,
            column,
            field,
            message: message.into(),
        }
    }

    /// The field of a missing value `name` in the table at `span`.
    pub(crate) fn child(&self, span: &Range<usize>, name: &str) -> String {
        join(&self.field_at(span), name)
    }

    /// Rewords one of serde's (or toml's) errors and locates it.
    pub(crate) fn serde_error(&self, error: &toml::de::Error) -> SceneError {
        let span = error.span().unwrap_or(0..0);
        let message = error.message();
        if let Some(name) = between(message, "missing field `", "`") {
            let field = self.child(&span, name);
            return self.error_in(span, field, "required, but missing");
        }
        let message = if let Some(rest) = message
            .strip_prefix("unknown field `")
            .and_then(|m| m.split_once("`, ").map(|(_, rest)| rest))
        {
            let name =
                between(message, "unknown field `", "`").unwrap_or_default();
            let parent = self.field_at(&span);
            if TOP_LEVEL.contains(&name) && parent.contains('.') {
                // `objects = [...]` written below `[camera]` is read as
                // `camera.objects`.
                format!(
                    "unknown field, {rest} (`{name}` belongs at the top of the file, \
                     above the first [table] header)"
                )
            } else {
                format!("unknown field, {rest}")
            }
        } else if let Some((got, expected)) = message
            .strip_prefix("invalid type: ")
            .and_then(|m| m.split_once(", expected "))
        {
            format!("expected {}, got {}", type_name(expected), type_name(got))
        } else {
            message.to_owned()
        };
        self.error(span, message)
    }
}

/// The top-level keys of a scene file.
const TOP_LEVEL: [&str; 9] = [
    "image",
    "camera",
    "ambient",
    "background",
    "lights",
    "materials",
    "objects",
    "meshes",
    "instances",
];

/// Serde's names for what it expected or found, in TOML's words.
fn type_name(name: &str) -> &str {
    match name {
        "map" | "a map" => "a table",
        "sequence" | "a sequence" => "an array",
        "i64" => "an integer",
        "a string" => "a string",
        other => other,
    }
}

/// The text between `prefix` at the start of `s` and the next `end`.
fn between<'s>(s: &'s str, prefix: &str, end: &str) -> Option<&'s str> {
    s.strip_prefix(prefix)?.split_once(end).map(|(x, _)| x)
}

fn join(parent: &str, key: &str) -> String {
    let bare = !key.is_empty()
        && key
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    let key = if bare {
        key.to_owned()
    } else {
        format!("{key:?}")
    };
    if parent.is_empty() {
        key
    } else {
        format!("{parent}.{key}")
    }
}

fn collect_table(
    table: &DeTable<'_>, path: &str, depth: usize, nodes: &mut Vec<Node>,
) {
    for (key, value) in table.iter() {
        let path = join(path, key.get_ref());
        nodes.push(Node {
            path: path.clone(),
            key: Some(key.span()),
            value: value.span(),
            depth,
        });
        collect_value(value.get_ref(), &path, depth + 1, nodes);
    }
}

fn collect_value(
    value: &DeValue<'_>, path: &str, depth: usize, nodes: &mut Vec<Node>,
) {
    match value {
        DeValue::Table(table) => collect_table(table, path, depth, nodes),
        DeValue::Array(array) => {
            for (i, item) in array.iter().enumerate() {
                let path = format!("{path}[{i}]");
                nodes.push(Node {
                    path: path.clone(),
                    key: None,
                    value: item.span(),
                    depth,
                });
                collect_value(item.get_ref(), &path, depth + 1, nodes);
            }
        }
        _ => {}
    }
}

/// 1-based line and column (in characters) of byte `offset` in `source`.
pub(crate) fn line_column(source: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(source.len());
    while !source.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &source[..offset];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let line = before.matches('\n').count() + 1;
    let column = before[line_start..].chars().count() + 1;
    (line, column)
}
