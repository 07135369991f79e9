//! `raystep stability`: the stability catalogue (crate
//! `raystep-stability`) over its full count — 10⁶ rays per accelerator
//! case, 10⁴ generated inputs per input case — printed as one table, and
//! written as JSON and as the Markdown table the book's appendix
//! includes. Exits with failure if a method fails a case it is built to
//! survive.
use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};
use raystep_stability::{
    Budget, Case, Expect, Row, catalogue, groups, run_catalogue, run_group,
    table,
};

use crate::atomic_file;
use crate::error::Error;

/// What `raystep stability` was asked: its command line.
#[derive(Debug, clap::Args)]
pub struct Options {
    /// Rays per accelerator case (and per cheap primitive case).
    #[arg(long, value_name = "N", default_value_t = Budget::FULL.rays)]
    pub rays: usize,
    /// Generated inputs per input case.
    #[arg(long, value_name = "N", default_value_t = Budget::FULL.inputs)]
    pub inputs: usize,
    /// Also write the rows as JSON to FILE.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// Also write the book's Markdown table to FILE.
    #[arg(long, value_name = "FILE")]
    pub markdown: Option<PathBuf>,
    /// Run only the cases of GROUP (as the table names it, for example
    /// "accelerators (meshes)"). With --json, FILE's rows of the other
    /// groups are kept (read from it first), so the book's table can be
    /// brought up to date one group at a time; --markdown then needs
    /// --json.
    #[arg(long, value_name = "GROUP")]
    pub group: Option<String>,
}

/// Runs the catalogue, prints the table, writes the files.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    for (count, argument) in
        [(options.rays, "--rays"), (options.inputs, "--inputs")]
    {
        if count == 0 {
            return Err(Error::Usage(format!(
                "{argument}: must be at least 1"
            )));
        }
    }
    for path in options.json.iter().chain(&options.markdown) {
        atomic_file::can_write(path)?;
    }
    let budget = Budget {
        rays: options.rays,
        inputs: options.inputs,
    };
    if let Some(group) = &options.group
        && !groups().contains(&group.as_str())
    {
        return Err(Error::Usage(format!(
            "--group: no group {group:?} in the catalogue; its groups: {}",
            groups().join(", ")
        )));
    }
    // With --group, the other groups' rows come from the JSON file.
    let earlier = match (&options.group, &options.json) {
        (None, _) => None,
        (Some(_), Some(path)) => Some(earlier_rows(path)?),
        (Some(_), None) if options.markdown.is_some() => {
            return Err(Error::Usage(
                "--markdown with --group needs --json: the other groups' \
                 rows are read from it"
                    .into(),
            ));
        }
        (Some(_), None) => None,
    };
    let cases = match &options.group {
        Some(group) => catalogue().iter().filter(|c| c.group == group).count(),
        None => catalogue().len(),
    };
    let bar = progress_bar(cases as u64);
    let mut started = |case: &Case| {
        bar.set_message(case.name);
        bar.inc(1);
    };
    let rows = match &options.group {
        Some(group) => run_group(group, &budget, &mut started),
        None => run_catalogue(&budget, &mut started),
    }
    .map_err(Error::Usage)?;
    bar.finish_and_clear();
    print!("{}", table::text(&rows));
    let bugs = rows
        .iter()
        .filter(|r| r.expect == Expect::Never && r.count.failures > 0)
        .count();
    println!(
        "\n{} cases, {} rows; {bugs} where a method failed a case it is \
         built to survive (marked (!))",
        table::cases(&rows),
        rows.len()
    );
    // What the files hold: this run's rows, or (with --group) the file's
    // rows with this group's replaced.
    let written = match (&options.group, earlier) {
        (Some(group), Some(earlier)) => table::merge(earlier, group, rows),
        _ => rows,
    };
    if let Some(path) = &options.json {
        let mut text = serde_json::to_string_pretty(&written)
            .map_err(|e| Error::Usage(format!("{}: {e}", path.display())))?;
        text.push('\n');
        atomic_file::write(path, text.as_bytes())?;
    }
    if let Some(path) = &options.markdown {
        atomic_file::write(path, table::markdown(&written).as_bytes())?;
    }
    Ok(if bugs == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

/// The rows an earlier run wrote to `path` as JSON.
fn earlier_rows(path: &std::path::Path) -> Result<Vec<Row>, Error> {
    let name = path.display();
    let text = std::fs::read_to_string(path).map_err(|e| {
        Error::Usage(format!(
            "{name}: {e} (with --group, the other groups' rows are read \
             from the --json file)"
        ))
    })?;
    serde_json::from_str(&text).map_err(|e| {
        Error::Usage(format!("{name}:{}:{}: {e}", e.line(), e.column()))
    })
}

/// A bar on stderr when it is a terminal; hidden otherwise (CI, pipes).
fn progress_bar(steps: u64) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(steps);
    if let Ok(style) =
        ProgressStyle::with_template("[{bar:40}] {pos}/{len} {elapsed} {msg}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}
