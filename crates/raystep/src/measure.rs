//! `raystep measure`: the slow timing runs behind the charts. It writes CSV
//! files beside the book's figures; `raystep figures` draws the charts from
//! them, so drawing stays deterministic.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};

use crate::{Error, shown};

/// What `raystep measure` was asked to do.
#[derive(Debug)]
pub struct Options {
    /// Renders timed per data point (the median is kept).
    pub repeats: usize,
    /// The folder holding one folder per chapter [default: book/src/figures].
    pub out: Option<PathBuf>,
}

/// Runs every measurement and writes its CSV.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    if options.repeats == 0 {
        return Err(Error::Usage("--repeats 0: must be at least 1".to_string()));
    }
    let out = match &options.out {
        Some(out) => out.clone(),
        None => crate::figures::default_out(&crate::workspace::root()),
    };
    // Chapter 04: acne and leaks against render time.
    let steps = (ch04::measure::CHART_STRATEGIES.len() * ch04::measure::CHART_SCALES.len()) as u64;
    let bar = progress_bar(steps, "ch04 acne");
    let rows = ch04::measure::measure_acne(options.repeats, || bar.inc(1));
    bar.finish_and_clear();
    let path = out.join("ch04").join("acne.csv");
    write_atomically(&path, ch04::measure::to_csv(&rows).as_bytes())?;
    println!("wrote {} ({} rows)", shown(&path), rows.len());
    Ok(ExitCode::SUCCESS)
}

/// A bar on stderr when it is a terminal; hidden otherwise (CI, pipes).
fn progress_bar(steps: u64, what: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(steps);
    if let Ok(style) = ProgressStyle::with_template("{msg:12} [{bar:40}] {pos}/{len} {elapsed}") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(what.to_string());
    bar
}

/// Writes `bytes` to a temporary file beside `path`, then renames it over
/// `path`: an interrupted run never leaves half a file.
fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let dir = path.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    let temp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let result = std::fs::File::create(&temp)
        .and_then(|mut file| file.write_all(bytes).and_then(|()| file.sync_all()))
        .and_then(|()| std::fs::rename(&temp, path));
    result.map_err(|e| {
        let _ = std::fs::remove_file(&temp);
        Error::io(path, e)
    })
}
