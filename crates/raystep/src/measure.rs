//! `raystep measure`: the slow timing runs behind the charts. It writes CSV
//! files beside the book's figures; `raystep figures` draws the charts from
//! them, so drawing stays deterministic.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};

use crate::chapters::{CHAPTERS, find};
use crate::error::Error;
use crate::shown_path::shown;
use raystep_figure::{Chapter, Measurement};

/// What `raystep measure` was asked to do: its command line.
#[derive(Debug, clap::Args)]
pub struct Options {
    /// Timing samples per data point; the median is kept.
    #[arg(long, default_value_t = 11)]
    pub repeats: usize,
    /// Only this chapter: `05`, `5` or `ch05`.
    #[arg(long, value_name = "CHAPTER")]
    pub chapter: Option<String>,
    /// The folder that holds one folder per chapter [default: <workspace>/book/src/figures].
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// Runs every measurement (or one chapter's) and writes its CSV.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    if options.repeats == 0 {
        return Err(Error::Usage(
            "--repeats 0: must be at least 1".to_string(),
        ));
    }
    let out = match &options.out {
        Some(out) => out.clone(),
        None => crate::workspace::figures_dir(&crate::workspace::root()),
    };
    let measured: Vec<&Chapter> = CHAPTERS
        .iter()
        .copied()
        .filter(|c| !c.measurements.is_empty())
        .collect();
    let chosen: Vec<(&Chapter, &Measurement)> = match &options.chapter {
        Some(arg) => {
            let chapter = find(arg, &measured)?;
            chapter.measurements.iter().map(|m| (chapter, m)).collect()
        }
        None => measured
            .iter()
            .flat_map(|c| c.measurements.iter().map(move |m| (*c, m)))
            .collect(),
    };
    for (chapter, measurement) in chosen {
        let bar = progress_bar(
            (measurement.steps)(options.repeats),
            measurement.what,
        );
        let csv = (measurement.run)(options.repeats, &mut || bar.inc(1));
        bar.finish_and_clear();
        let csv =
            csv.map_err(|e| Error::Usage(format!("{}: {e}", chapter.id)))?;
        let path = out.join(chapter.id).join(measurement.file);
        write_atomically(&path, csv.as_bytes())?;
        println!("wrote {} ({} rows)", shown(&path), csv.lines().count() - 1);
    }
    Ok(ExitCode::SUCCESS)
}

/// A bar on stderr when it is a terminal; hidden otherwise (CI, pipes).
fn progress_bar(steps: u64, what: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(steps);
    if let Ok(style) = ProgressStyle::with_template(
        "{msg:12} [{bar:40}] {pos}/{len} {elapsed}",
    ) {
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
        .and_then(|mut file| {
            file.write_all(bytes).and_then(|()| file.sync_all())
        })
        .and_then(|()| std::fs::rename(&temp, path));
    result.map_err(|e| {
        let _ = std::fs::remove_file(&temp);
        Error::io(path, e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The CSV files committed beside the figures are exactly the ones the
    /// measurements write: none is stale, none is missing.
    #[test]
    fn every_committed_csv_has_its_measurement() {
        let figures = crate::workspace::figures_dir(&crate::workspace::root());
        let mut committed = Vec::new();
        for chapter in std::fs::read_dir(&figures).expect("book/src/figures") {
            let chapter = chapter.expect("a folder entry").path();
            for file in std::fs::read_dir(&chapter).into_iter().flatten() {
                let file = file.expect("a folder entry").path();
                if file.extension().is_some_and(|e| e == "csv") {
                    committed.push(format!(
                        "{}/{}",
                        chapter.file_name().unwrap().to_string_lossy(),
                        file.file_name().unwrap().to_string_lossy()
                    ));
                }
            }
        }
        committed.sort();
        let mut measured: Vec<String> = CHAPTERS
            .iter()
            .flat_map(|c| {
                c.measurements
                    .iter()
                    .map(|m| format!("{}/{}", c.id, m.file))
            })
            .collect();
        measured.sort();
        assert_eq!(committed, measured);
    }

    #[test]
    fn a_measurement_is_chosen_by_chapter() {
        let measured: Vec<&Chapter> = CHAPTERS
            .iter()
            .copied()
            .filter(|c| !c.measurements.is_empty())
            .collect();
        let found = find("5", &measured).unwrap();
        assert_eq!(found.measurements[0].file, "stopping.csv");
        let error = find("02", &measured).err().unwrap().to_string();
        assert!(
            error.contains("ch04, ch05, ch06, ch07, ch08, ch09, ch10, ch11"),
            "{error}"
        );
    }
}
