//! insta's report of a failed snapshot, read back: which snapshot, where
//! it is asserted, and the new text rebuilt from the expected snapshot file
//! and the diff insta printed (which leaves out unchanged lines far from a
//! change), so that [`super::snapshot_table`] can compare the two whole.

use super::snapshot_table;

/// One row of insta's diff: `  old   new │±text`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum DiffRow {
    /// ` ` an unchanged line, at these 1-based line numbers.
    Same {
        old: usize,
        new: usize,
        text: String,
    },
    /// `-` a line of the expected snapshot that the new text lacks.
    Removed { old: usize, text: String },
    /// `+` a line of the new text that the expected snapshot lacks.
    Added { new: usize, text: String },
}

/// What insta printed for one failed snapshot assertion.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct InstaFailure {
    /// `Snapshot file:`, relative to the workspace root (or to the package).
    pub file: Option<String>,
    /// `Snapshot:`, the snapshot's name.
    pub name: Option<String>,
    /// `Source:`, the assertion's `file:line`.
    pub source: Option<String>,
    /// The diff's rows, in order.
    pub rows: Vec<DiffRow>,
}

impl InstaFailure {
    /// Reads insta's report out of a failed test's captured output; `None`
    /// if it holds none.
    pub fn parse(lines: &[&str]) -> Option<InstaFailure> {
        let start =
            lines.iter().position(|l| l.contains("Snapshot Summary"))?;
        let mut failure = InstaFailure::default();
        let mut in_diff = false;
        for line in &lines[start..] {
            let field = |label: &str| {
                line.strip_prefix(label).map(|v| v.trim().to_string())
            };
            if let Some(file) = field("Snapshot file:") {
                failure.file = Some(file);
            } else if let Some(name) = field("Snapshot:") {
                failure.name = Some(name);
            } else if let Some(source) = field("Source:") {
                failure.source = Some(source);
            } else if line.contains("┬") {
                in_diff = true;
            } else if line.contains("┴") {
                break;
            } else if in_diff {
                failure.rows.extend(diff_row(line));
            }
        }
        Some(failure)
    }

    /// The snapshot's name, else `the snapshot`.
    pub fn name(&self) -> &str {
        self.name.as_deref().unwrap_or("the snapshot")
    }

    /// The new text: the expected `old` text with the diff applied. `None`
    /// if the diff does not fit `old` (the file changed since, or insta
    /// printed something else).
    pub fn new_text(&self, old: &str) -> Option<String> {
        let old: Vec<&str> = old.lines().collect();
        let mut new: Vec<String> = Vec::new();
        // The next old line not yet copied (0-based).
        let mut next = 0;
        let copy_until = |new: &mut Vec<String>, next: &mut usize, end| {
            while *next < end {
                new.push(old.get(*next)?.to_string());
                *next += 1;
            }
            Some(())
        };
        for row in &self.rows {
            match row {
                DiffRow::Same {
                    old: at, new: to, ..
                } => {
                    copy_until(&mut new, &mut next, at.checked_sub(1)?)?;
                    if new.len() + 1 != *to {
                        return None;
                    }
                    new.push(old.get(next)?.to_string());
                    next += 1;
                }
                DiffRow::Removed { old: at, text } => {
                    copy_until(&mut new, &mut next, at.checked_sub(1)?)?;
                    if old.get(next)?.trim_end() != text.trim_end() {
                        return None;
                    }
                    next += 1;
                }
                DiffRow::Added { new: to, text } => {
                    while new.len() + 1 < *to {
                        new.push(old.get(next)?.to_string());
                        next += 1;
                    }
                    if new.len() + 1 != *to {
                        return None;
                    }
                    new.push(text.clone());
                }
            }
        }
        copy_until(&mut new, &mut next, old.len())?;
        Some(new.join("\n"))
    }

    /// The first difference, said for a person: by row and column for a
    /// table ([`snapshot_table::first_difference`]) when the expected
    /// snapshot text is known, else the first removed and added lines of
    /// the diff that differ in more than their padding.
    pub fn describe(&self, expected: Option<&str>) -> String {
        let name = self.name();
        if let Some(old) = expected
            && let Some(new) = self.new_text(old)
        {
            return snapshot_table::first_difference(name, old, &new)
                .unwrap_or_else(|| {
                    format!("snapshot {name} differs (in spacing only)")
                });
        }
        self.diff_difference()
    }

    /// Without the expected text: the first removed line and the first
    /// added line, pairs that differ only in padding (a table's rule or a
    /// re-padded row) skipped.
    fn diff_difference(&self) -> String {
        let name = self.name();
        let removed = self.rows.iter().filter_map(|r| match r {
            DiffRow::Removed { old, text } => Some((*old, text.as_str())),
            _ => None,
        });
        let added: Vec<(usize, &str)> = self
            .rows
            .iter()
            .filter_map(|r| match r {
                DiffRow::Added { new, text } => Some((*new, text.as_str())),
                _ => None,
            })
            .collect();
        // A rule's cells are all dashes: any number of them is the same rule.
        let cells = |text: &str| -> Vec<String> {
            text.split('|')
                .map(str::trim)
                .map(|c| if c.chars().all(|d| d == '-') { "" } else { c })
                .map(str::to_string)
                .collect()
        };
        let mut added_iter = added.iter();
        for (line, old) in removed {
            match added_iter.next() {
                Some((_, new)) if cells(old) == cells(new) => continue,
                Some((_, new)) => {
                    return format!(
                        "snapshot {name}, line {line}: expected `{}`, got `{}`",
                        squeezed(old),
                        squeezed(new)
                    );
                }
                None => {
                    return format!(
                        "snapshot {name}, line {line}: missing `{}`",
                        squeezed(old)
                    );
                }
            }
        }
        match added_iter.next() {
            Some((line, new)) => format!(
                "snapshot {name}, line {line}: not expected `{}`",
                squeezed(new)
            ),
            None => format!("snapshot {name} does not match"),
        }
    }
}

/// Runs of spaces as one.
fn squeezed(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// One row of the diff, `"{old:>5} {new:>5} │{sign}{text}"`; `None` for the
/// lines between groups of rows (`┈┈┈┼┈┈┈`) and anything else.
fn diff_row(line: &str) -> Option<DiffRow> {
    let (numbers, rest) = line.split_once('│')?;
    let mut numbers = numbers.split_whitespace().map(str::parse::<usize>);
    let mut chars = rest.chars();
    let sign = chars.next()?;
    let text = chars.as_str().to_string();
    match sign {
        '+' => Some(DiffRow::Added {
            new: numbers.next()?.ok()?,
            text,
        }),
        '-' => Some(DiffRow::Removed {
            old: numbers.next()?.ok()?,
            text,
        }),
        ' ' => Some(DiffRow::Same {
            old: numbers.next()?.ok()?,
            new: numbers.next()?.ok()?,
            text,
        }),
        _ => None,
    }
}

/// The text of an insta snapshot file: what follows its header (the lines
/// between the first two `---`), trailing blank lines removed, as insta
/// compares it.
pub fn snapshot_contents(file: &str) -> String {
    let mut lines = file.lines();
    let contents = match lines.next() {
        Some(first) if first.trim_end() == "---" => {
            // Skip the metadata up to the closing `---`.
            let mut rest = lines.by_ref().skip_while(|l| l.trim_end() != "---");
            rest.next();
            rest.collect::<Vec<_>>().join("\n")
        }
        _ => file.to_string(),
    };
    contents.trim_end().replace("\r\n", "\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// insta's report of `ray_plane_table` with a dropped minus sign: the
    /// column grows by one, every line changes, the context is elided.
    const REPORT: &str = "\
━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━ Snapshot Summary ━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━
Snapshot file: chapters/ch02/tests/snapshots/ray__table.snap
Snapshot: table
Source: chapters/ch02/tests/ray.rs:56
────────────────────────────────────────────────────────────────────────────────
Expression: table.to_string()
────────────────────────────────────────────────────────────────────────────────
-old snapshot
+new results
────────────┬───────────────────────────────────────────────────────────────────
    1       │-case | t
    2       │----------|-------
          1 │+case | t
          2 │+---------|--------
    3     3 │ a        | 1.0000
    4       │-b        | 2.0000
          4 │+b        | -2.0000
┈┈┈┈┈┈┈┈┈┈┈┈┼┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈┈
    9       │-h        | 8.0000
          9 │+h        | 8.5000
────────────┴───────────────────────────────────────────────────────────────────
Stopped on the first failure. Run `cargo insta test` to run all snapshots.";

    const FILE: &str = "---\nsource: chapters/ch02/tests/ray.rs\nexpression: table.to_string()\n---\n\
        case | t\n---------|-------\na        | 1.0000\nb        | 2.0000\nc        | 3.0000\n\
        d        | 4.0000\ne        | 5.0000\nf        | 6.0000\nh        | 8.0000\n";

    fn report() -> InstaFailure {
        let lines: Vec<&str> = REPORT.lines().collect();
        InstaFailure::parse(&lines).unwrap()
    }

    #[test]
    fn the_report_is_read() {
        let failure = report();
        assert_eq!(
            failure.file.as_deref(),
            Some("chapters/ch02/tests/snapshots/ray__table.snap")
        );
        assert_eq!(failure.name(), "table");
        assert_eq!(
            failure.source.as_deref(),
            Some("chapters/ch02/tests/ray.rs:56")
        );
        assert_eq!(failure.rows.len(), 9);
        assert_eq!(
            failure.rows[4],
            DiffRow::Same {
                old: 3,
                new: 3,
                text: "a        | 1.0000".into()
            }
        );
        assert!(InstaFailure::parse(&["thread 'x' panicked"]).is_none());
    }

    #[test]
    fn the_new_text_is_rebuilt_across_elided_lines() {
        let old = snapshot_contents(FILE);
        assert!(old.starts_with("case | t\n"));
        assert_eq!(
            report().new_text(&old).unwrap(),
            "case | t\n---------|--------\na        | 1.0000\nb        | -2.0000\n\
             c        | 3.0000\nd        | 4.0000\ne        | 5.0000\nf        | 6.0000\n\
             h        | 8.5000"
        );
        // A diff that does not fit the file is refused.
        assert_eq!(report().new_text("case | t\n"), None);
    }

    #[test]
    fn a_table_is_described_by_its_first_differing_row() {
        let old = snapshot_contents(FILE);
        assert_eq!(
            report().describe(Some(&old)),
            "snapshot table, row 2 (case \"b\"): t expected `2.0000`, got `-2.0000`"
        );
    }

    #[test]
    fn without_the_file_padding_changes_are_skipped() {
        assert_eq!(
            report().describe(None),
            "snapshot table, line 4: expected `b | 2.0000`, got `b | -2.0000`"
        );
    }
}
