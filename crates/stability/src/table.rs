//! The catalogue's table, as text for the terminal and as Markdown for
//! the book: case by case, every method's failures out of its trials (0
//! shown as 0), the failures a method is not built to survive marked.
use std::fmt::Write;

use crate::{Expect, Row};

/// The table for a terminal: one block per case, one line per method.
pub fn text(rows: &[Row]) -> String {
    let mut out = String::new();
    let mut last: Option<(&str, &str)> = None;
    for row in rows {
        if last.map(|(g, _)| g) != Some(&row.group) {
            writeln!(out, "\n== {} ==", row.group).unwrap();
        }
        if last.map(|(_, c)| c) != Some(&row.case) {
            writeln!(out, "{}: {}", row.case, row.what).unwrap();
        }
        last = Some((&row.group, &row.case));
        writeln!(
            out,
            "    {:<36} {:>9} / {}{}",
            row.count.method,
            row.count.failures,
            row.count.trials,
            mark(row)
        )
        .unwrap();
    }
    out
}

/// The table for the book: one Markdown table per group, a row per
/// (case, method), the case named on its first row.
pub fn markdown(rows: &[Row]) -> String {
    let mut out = String::new();
    let mut last: Option<(&str, &str)> = None;
    for row in rows {
        if last.map(|(g, _)| g) != Some(&row.group) {
            writeln!(out, "\n### {}\n", row.group).unwrap();
            writeln!(out, "| case | method | failures / trials |").unwrap();
            writeln!(out, "|---|---|---:|").unwrap();
        }
        let case = if last.map(|(_, c)| c) != Some(&row.case) {
            format!("**{}**: {}", row.case, row.what)
        } else {
            String::new()
        };
        last = Some((&row.group, &row.case));
        writeln!(
            out,
            "| {case} | {} | {} / {}{} |",
            row.count.method,
            row.count.failures,
            row.count.trials,
            mark(row)
        )
        .unwrap();
    }
    out
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
