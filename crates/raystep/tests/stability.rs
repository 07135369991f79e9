//! `raystep stability --group` from the outside: one group run again (a
//! tiny budget) replaces that group's rows in the JSON file and keeps the
//! others', and the Markdown table is written from all of them; a group
//! the catalogue lacks, and --markdown without the JSON it needs, are one
//! clear line each.

use std::fs;

mod common;
use common::{fails_in_one_line, read_json, succeeds};

/// The group the tests run: its cases are cheap at a tiny budget.
const GROUP: &str = "sphere and torus";

/// A row of an earlier run, as `--json` writes it.
fn row(group: &str, case: &str) -> serde_json::Value {
    serde_json::json!({
        "group": group, "case": case, "what": "earlier",
        "method": "m", "failures": 3, "trials": 9, "expect": "Shown",
    })
}

#[test]
fn one_group_run_again_replaces_its_rows_and_keeps_the_others() {
    let dir = common::scratch("raystep-stability", "group");
    let json = dir.join("catalogue.json");
    let markdown = dir.join("catalogue.md");
    // An earlier run: a row of another group (first in the catalogue's
    // order) after a stale row of this one.
    let earlier = [row(GROUP, "stale"), row("triangle tests", "kept")];
    fs::write(&json, serde_json::to_string(&earlier).unwrap()).unwrap();
    let stdout = succeeds(&[
        "stability",
        "--group",
        GROUP,
        "--rays",
        "20",
        "--inputs",
        "5",
        "--json",
        json.to_str().unwrap(),
        "--markdown",
        markdown.to_str().unwrap(),
    ]);
    // The terminal shows only this run's group.
    assert!(stdout.contains(&format!("== {GROUP} ==")), "{stdout}");
    assert!(!stdout.contains("== triangle tests =="), "{stdout}");
    let rows = read_json(&json);
    let rows = rows.as_array().unwrap();
    let cases: Vec<&str> =
        rows.iter().map(|r| r["case"].as_str().unwrap()).collect();
    // The other group's row kept, first; the stale row gone; this group's
    // fresh rows after it, each with the budget's trials.
    assert_eq!(cases[0], "kept");
    assert!(!cases.contains(&"stale"), "{cases:?}");
    assert!(rows.len() > 2, "{cases:?}");
    assert!(rows[1..].iter().all(|r| r["group"] == GROUP));
    assert!(rows[1..].iter().all(|r| r["trials"].as_u64().unwrap() > 0));
    let table = fs::read_to_string(&markdown).unwrap();
    assert!(table.contains("### triangle tests"), "{table}");
    assert!(table.contains(&format!("### {GROUP}")), "{table}");
    assert!(
        table.contains("| **kept**: earlier | m | 3 / 9 |"),
        "{table}"
    );
}

#[test]
fn an_unknown_group_or_a_table_without_its_json_is_refused() {
    let line = fails_in_one_line(&["stability", "--group", "spheres"]);
    assert!(line.contains("--group: no group \"spheres\""), "{line}");
    assert!(line.contains(GROUP), "names the groups: {line}");
    let dir = common::scratch("raystep-stability", "refused");
    let markdown = dir.join("catalogue.md");
    let line = fails_in_one_line(&[
        "stability",
        "--group",
        GROUP,
        "--markdown",
        markdown.to_str().unwrap(),
    ]);
    assert!(
        line.contains("--markdown with --group needs --json"),
        "{line}"
    );
    let missing = dir.join("none.json");
    let line = fails_in_one_line(&[
        "stability",
        "--group",
        GROUP,
        "--json",
        missing.to_str().unwrap(),
    ]);
    assert!(line.contains("none.json"), "{line}");
    assert!(!markdown.exists() && !missing.exists());
}
