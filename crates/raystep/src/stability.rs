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
use raystep_stability::{Budget, Expect, catalogue, run_catalogue, table};

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
    let bar = progress_bar(catalogue().len() as u64);
    let rows = run_catalogue(&budget, &mut |case| {
        bar.set_message(case.name);
        bar.inc(1);
    })
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
    if let Some(path) = &options.json {
        let mut text = serde_json::to_string_pretty(&rows)
            .map_err(|e| Error::Usage(format!("{}: {e}", path.display())))?;
        text.push('\n');
        atomic_file::write(path, text.as_bytes())?;
    }
    if let Some(path) = &options.markdown {
        atomic_file::write(path, table::markdown(&rows).as_bytes())?;
    }
    Ok(if bugs == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
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
