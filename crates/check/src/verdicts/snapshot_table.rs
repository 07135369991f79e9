//! A failed snapshot, said as the first row whose values differ.
//!
//! The chapters' snapshots are mostly tables from [`crate::Table`]: a
//! header line, a rule line (`------|-----`), then one row a line, the cells
//! padded to line up and joined by ` | `. When one value gets wider or
//! narrower, every line of the table changes (the padding and the rule), so
//! the first *line* that differs says nothing. This module reads both tables
//! back into cells and compares them cell by cell (trimmed); a snapshot that
//! is not such a table (an ASCII render) is compared line by line.

/// A snapshot table read back into its cells.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SnapshotTable {
    /// The column names.
    pub columns: Vec<String>,
    /// The rows, one cell per column, trimmed.
    pub rows: Vec<Vec<String>>,
}

impl SnapshotTable {
    /// Reads a table in [`crate::Table`]'s layout; `None` if `text`
    /// is not one (fewer than two columns, no rule line, a row with another
    /// number of cells).
    pub fn parse(text: &str) -> Option<SnapshotTable> {
        let mut lines = text.lines().map(|l| l.trim_end_matches('\r'));
        let header = lines.next()?;
        let widths = rule_widths(lines.next()?)?;
        let columns = cells(header, &widths)?;
        let rows = lines
            .filter(|l| !l.trim().is_empty())
            .map(|l| cells(l, &widths))
            .collect::<Option<Vec<_>>>()?;
        Some(SnapshotTable { columns, rows })
    }
}

/// The column widths of a rule line `-----|------|---` (at least two
/// columns), in characters: each column's dashes, joined by `-|-`.
fn rule_widths(rule: &str) -> Option<Vec<usize>> {
    let widths: Vec<usize> = rule
        .trim_end()
        .split("-|-")
        .map(|dashes| {
            (!dashes.is_empty() && dashes.chars().all(|c| c == '-'))
                .then(|| dashes.chars().count())
        })
        .collect::<Option<_>>()?;
    (widths.len() >= 2).then_some(widths)
}

/// The trimmed cells of one line: by the columns' positions (padded cells
/// joined by ` | `), else split at ` | ` if that gives one cell per column.
fn cells(line: &str, widths: &[usize]) -> Option<Vec<String>> {
    by_position(line, widths).or_else(|| {
        let cells: Vec<String> =
            line.split(" | ").map(|c| c.trim().to_string()).collect();
        (cells.len() == widths.len()).then_some(cells)
    })
}

/// The cells at the positions the widths give: cell `i` fills its width,
/// and ` | ` follows every cell but the last (the line was trimmed at its
/// end, so it is padded back first).
fn by_position(line: &str, widths: &[usize]) -> Option<Vec<String>> {
    let mut chars: Vec<char> = line.chars().collect();
    let full = widths.iter().sum::<usize>() + 3 * (widths.len() - 1);
    if chars.len() < full {
        chars.resize(full, ' ');
    }
    let mut cells = Vec::with_capacity(widths.len());
    let mut start = 0;
    for (i, &width) in widths.iter().enumerate() {
        let last = i + 1 == widths.len();
        let end = if last { chars.len() } else { start + width };
        let cell: String = chars.get(start..end)?.iter().collect();
        cells.push(cell.trim().to_string());
        if !last {
            let separator: String = chars.get(end..end + 3)?.iter().collect();
            if separator != " | " {
                return None;
            }
            start = end + 3;
        }
    }
    Some(cells)
}

/// At most this many differing cells of a row are named.
const CELLS_NAMED: usize = 3;

/// The first difference between two snapshot texts of the snapshot `name`:
/// the first row whose values differ (with the column names) if both are
/// tables, else the first line that differs. `None` if they agree (tables:
/// cell by cell; other text: line by line, trailing spaces ignored).
pub fn first_difference(
    name: &str, expected: &str, got: &str,
) -> Option<String> {
    match (SnapshotTable::parse(expected), SnapshotTable::parse(got)) {
        (Some(expected), Some(got)) => table_difference(name, &expected, &got),
        _ => line_difference(name, expected, got),
    }
}

/// The first row of `got` whose cells differ from `expected`'s:
/// ``snapshot t, row 3 (case "oblique"): result expected `hit`, got `miss` ``.
pub fn table_difference(
    name: &str, expected: &SnapshotTable, got: &SnapshotTable,
) -> Option<String> {
    if expected.columns != got.columns {
        return Some(format!(
            "snapshot {name}: columns expected `{}`, got `{}`",
            expected.columns.join(" | "),
            got.columns.join(" | ")
        ));
    }
    let key = key_column(expected);
    let rows = expected.rows.len().max(got.rows.len());
    for i in 0..rows {
        let label = |row: &[String]| {
            format!(
                "row {} ({} \"{}\")",
                i + 1,
                expected.columns[key],
                row[key]
            )
        };
        match (expected.rows.get(i), got.rows.get(i)) {
            (Some(want), Some(have)) => {
                let differing: Vec<String> = expected
                    .columns
                    .iter()
                    .zip(want.iter().zip(have))
                    .filter(|(_, (w, h))| w != h)
                    .map(|(column, (w, h))| {
                        format!("{column} expected `{w}`, got `{h}`")
                    })
                    .collect();
                if differing.is_empty() {
                    continue;
                }
                let mut said =
                    differing[..differing.len().min(CELLS_NAMED)].join("; ");
                match differing.len() - differing.len().min(CELLS_NAMED) {
                    0 => {}
                    1 => said.push_str("; and 1 more cell"),
                    more => said.push_str(&format!("; and {more} more cells")),
                }
                return Some(format!(
                    "snapshot {name}, {}: {said}",
                    label(want)
                ));
            }
            (Some(want), None) => {
                return Some(format!(
                    "snapshot {name}, {}: missing (the table ends after {} rows)",
                    label(want),
                    got.rows.len()
                ));
            }
            (None, Some(extra)) => {
                return Some(format!(
                    "snapshot {name}, row {}: not expected (the table has {} rows): `{}`",
                    i + 1,
                    expected.rows.len(),
                    extra.join(" | ")
                ));
            }
            (None, None) => {}
        }
    }
    None
}

/// The column that names a row: the first whose expected values are all
/// different and not empty, else the first.
fn key_column(table: &SnapshotTable) -> usize {
    (0..table.columns.len())
        .find(|&c| {
            let mut seen = std::collections::HashSet::new();
            table
                .rows
                .iter()
                .all(|r| !r[c].is_empty() && seen.insert(&r[c]))
        })
        .unwrap_or(0)
}

/// The first line that differs (trailing spaces ignored):
/// ``snapshot render, line 5: expected `..A..`, got `..B..` ``.
pub fn line_difference(
    name: &str, expected: &str, got: &str,
) -> Option<String> {
    let expected: Vec<&str> = expected.lines().map(str::trim_end).collect();
    let got: Vec<&str> = got.lines().map(str::trim_end).collect();
    let lines = expected.len().max(got.len());
    (0..lines).find_map(|i| match (expected.get(i), got.get(i)) {
        (Some(want), Some(have)) if want == have => None,
        (Some(want), Some(have)) => Some(format!(
            "snapshot {name}, line {}: expected `{want}`, got `{have}`",
            i + 1
        )),
        (Some(want), None) => Some(format!(
            "snapshot {name}, line {}: missing `{want}` (it ends after {} lines)",
            i + 1,
            got.len()
        )),
        (None, Some(have)) => Some(format!(
            "snapshot {name}, line {}: not expected `{have}` (the snapshot has {} lines)",
            i + 1,
            expected.len()
        )),
        (None, None) => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A table as the chapters' snapshots hold it: written by
    /// [`crate::Table`] itself.
    fn table(columns: &[&str], rows: &[&[&str]]) -> String {
        let mut table = crate::Table::new(columns);
        for row in rows {
            table.row(row);
        }
        table.to_string()
    }

    const COLUMNS: [&str; 3] = ["ray", "case", "t"];

    fn rays(t: &str) -> String {
        table(
            &COLUMNS,
            &[
                &["a", "straight down", "4.0000"],
                &["a", "oblique", "5.0000"],
                &["b", "tilted, from below", t],
                &["b", "last", "1.0000"],
            ],
        )
    }

    #[test]
    fn tables_are_read_back_into_cells() {
        let text = rays("1.5000");
        let parsed = SnapshotTable::parse(&text).unwrap();
        assert_eq!(parsed.columns, COLUMNS);
        assert_eq!(parsed.rows[2], ["b", "tilted, from below", "1.5000"]);
        assert_eq!(parsed.rows.len(), 4);
        // A cell holding ` | ` is still read by position, an empty last
        // cell too.
        let empty = table(&["a", "b"], &[&["1", ""], &["2", "x"]]);
        assert_eq!(SnapshotTable::parse(&empty).unwrap().rows[0], ["1", ""]);
        let odd = table(&["a", "b"], &[&["x | y", "z"], &["1", "2"]]);
        assert_eq!(SnapshotTable::parse(&odd).unwrap().rows[0], ["x | y", "z"]);
    }

    #[test]
    fn a_dropped_minus_sign_names_the_row_not_the_rule() {
        // The sign makes column t one wider: the header, the rule and every
        // row of the text change, only one value does.
        let expected = rays("-1.5000");
        let got = rays("1.5000");
        assert_ne!(
            expected.lines().nth(1),
            got.lines().nth(1),
            "the rule line changes"
        );
        assert_eq!(
            first_difference("ray_plane_table", &expected, &got).as_deref(),
            Some(
                "snapshot ray_plane_table, row 3 (case \"tilted, from below\"): \
                 t expected `-1.5000`, got `1.5000`"
            )
        );
    }

    #[test]
    fn a_change_of_width_alone_is_no_difference() {
        let narrow = "a | b\n--|--\n1 | 2\n";
        let wide = "a     | b\n------|-----\n1     | 2\n";
        assert_eq!(first_difference("t", narrow, wide), None);
    }

    #[test]
    fn the_first_wrong_row_is_named_with_every_differing_cell() {
        let columns = ["point", "f1", "f2", "inside"];
        let expected = table(
            &columns,
            &[
                &["centre", "8.0000", "6.0000", "true"],
                &["outside right", "4.0000", "-3.0000", "false"],
                &["on edge", "0.0000", "6.0000", "true"],
            ],
        );
        let got = table(
            &columns,
            &[
                &["centre", "8.0000", "6.0000", "true"],
                &["outside right", "-4.0000", "3.0000", "true"],
                &["on edge", "0.0000", "-6.0000", "false"],
            ],
        );
        assert_eq!(
            first_difference("inside_table", &expected, &got).as_deref(),
            Some(
                "snapshot inside_table, row 2 (point \"outside right\"): \
                 f1 expected `4.0000`, got `-4.0000`; \
                 f2 expected `-3.0000`, got `3.0000`; \
                 inside expected `false`, got `true`"
            )
        );
    }

    #[test]
    fn missing_and_extra_rows_and_other_columns() {
        let two = table(&["k", "v"], &[&["a", "1"], &["b", "2"]]);
        let one = table(&["k", "v"], &[&["a", "1"]]);
        assert_eq!(
            first_difference("t", &two, &one).as_deref(),
            Some(
                "snapshot t, row 2 (k \"b\"): missing (the table ends after 1 rows)"
            )
        );
        assert_eq!(
            first_difference("t", &one, &two).as_deref(),
            Some(
                "snapshot t, row 2: not expected (the table has 1 rows): `b | 2`"
            )
        );
        let renamed = table(&["k", "w"], &[&["a", "1"]]);
        assert_eq!(
            first_difference("t", &one, &renamed).as_deref(),
            Some("snapshot t: columns expected `k | v`, got `k | w`")
        );
    }

    #[test]
    fn rows_without_a_unique_column_are_named_by_the_first() {
        let expected = table(&["plane", "t"], &[&["z", "1"], &["z", "1"]]);
        let got = table(&["plane", "t"], &[&["z", "1"], &["z", "2"]]);
        assert_eq!(
            first_difference("t", &expected, &got).as_deref(),
            Some("snapshot t, row 2 (plane \"z\"): t expected `1`, got `2`")
        );
    }

    #[test]
    fn other_snapshots_are_compared_line_by_line() {
        let expected = "......\n..AA..\n..AA..\n";
        let got = "......\n..AA..\n..AB..\n";
        assert_eq!(SnapshotTable::parse(expected), None);
        assert_eq!(
            first_difference("render", expected, got).as_deref(),
            Some("snapshot render, line 3: expected `..AA..`, got `..AB..`")
        );
        assert_eq!(
            first_difference("render", expected, "......\n").as_deref(),
            Some(
                "snapshot render, line 2: missing `..AA..` (it ends after 1 lines)"
            )
        );
        assert_eq!(first_difference("render", expected, expected), None);
        // a dashed line alone is no table
        assert_eq!(SnapshotTable::parse("a\n---\nb\n"), None);
    }
}
