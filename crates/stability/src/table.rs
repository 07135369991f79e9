//! The catalogue's table, as text for the terminal and as Markdown for
//! the book: case by case, every method's failures out of its trials (0
//! shown as 0), the failures a method is not built to survive marked.
use std::fmt::Write;

use crate::{Expect, Row, groups};

/// The table for a terminal: one block per case, one line per method.
pub fn text(rows: &[Row]) -> String {
    let mut out = String::new();
    for (new_group, new_case, row) in with_starts(rows) {
        if new_group {
            writeln!(out, "\n== {} ==", row.group).unwrap();
        }
        if new_case {
            writeln!(out, "{}: {}", row.case, row.what).unwrap();
        }
        let tally = tally(row, 9);
        writeln!(out, "    {:<36} {tally}", row.count.method).unwrap();
    }
    out
}

/// The table for the book: one Markdown table per group, a row per
/// (case, method), the case named on its first row.
pub fn markdown(rows: &[Row]) -> String {
    let mut out = String::new();
    for (new_group, new_case, row) in with_starts(rows) {
        if new_group {
            writeln!(out, "\n### {}\n", row.group).unwrap();
            writeln!(out, "| case | method | failures / trials |").unwrap();
            writeln!(out, "|---|---|---:|").unwrap();
        }
        let case = if new_case {
            format!("**{}**: {}", row.case, row.what)
        } else {
            String::new()
        };
        let tally = tally(row, 0);
        writeln!(out, "| {case} | {} | {tally} |", row.count.method).unwrap();
    }
    out
}

/// Each row with whether it starts a group and whether it starts a case
/// (the row before it had another).
fn with_starts(rows: &[Row]) -> impl Iterator<Item = (bool, bool, &Row)> {
    let mut last: Option<(&str, &str)> = None;
    rows.iter().map(move |row| {
        let new_group = last.map(|(g, _)| g) != Some(&row.group);
        let new_case = last.map(|(_, c)| c) != Some(&row.case);
        last = Some((&row.group, &row.case));
        (new_group, new_case, row)
    })
}

/// `failures / trials`, the failures right-aligned in `width`, marked.
fn tally(row: &Row, width: usize) -> String {
    let count = &row.count;
    format!("{:>width$} / {}{}", count.failures, count.trials, mark(row))
}

/// ` (!)` after a failure the method is built to survive: a bug.
fn mark(row: &Row) -> &'static str {
    if row.expect == Expect::Never && row.count.failures > 0 {
        " (!)"
    } else {
        ""
    }
}

/// How many cases the rows hold.
pub fn cases(rows: &[Row]) -> usize {
    let mut names: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r.group.as_str(), r.case.as_str()))
        .collect();
    names.dedup();
    names.len()
}

/// The rows of a whole run with one group's rows run again: `fresh`
/// (the rows of `group`) in place of `earlier`'s rows of that group, the
/// other groups' rows kept, every group in the catalogue's order (rows of
/// a group the catalogue no longer has are dropped).
pub fn merge(earlier: Vec<Row>, group: &str, fresh: Vec<Row>) -> Vec<Row> {
    let mut rows = Vec::with_capacity(earlier.len() + fresh.len());
    for name in groups() {
        if name == group {
            rows.extend(fresh.iter().cloned());
        } else {
            rows.extend(earlier.iter().filter(|r| r.group == name).cloned());
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Count;

    fn row(group: &str, case: &str, failures: u64) -> Row {
        Row {
            group: group.to_string(),
            case: case.to_string(),
            what: String::new(),
            count: Count::new("m", failures, 10),
            expect: Expect::Never,
        }
    }

    #[test]
    fn merging_replaces_one_group_and_keeps_the_others_in_order() {
        let all = groups();
        let (first, middle, last) =
            (all[0], all[all.len() / 2], all[all.len() - 1]);
        // The earlier file in another order, with a group since removed.
        let earlier = vec![
            row(last, "l", 0),
            row(middle, "old", 7),
            row("gone", "g", 0),
            row(first, "f", 0),
            row(middle, "old too", 7),
        ];
        let fresh = vec![row(middle, "new", 0)];
        let merged = merge(earlier, middle, fresh);
        let names: Vec<&str> = merged.iter().map(|r| r.case.as_str()).collect();
        assert_eq!(names, ["f", "new", "l"]);
        // A group the file did not have yet is added in its place.
        let merged =
            merge(vec![row(last, "l", 0)], first, vec![row(first, "f", 1)]);
        let names: Vec<&str> = merged.iter().map(|r| r.case.as_str()).collect();
        assert_eq!(names, ["f", "l"]);
    }
}
