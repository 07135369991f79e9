//! The measured CSV files behind the charts, as the repository keeps them
//! in `book/src/figures/<chapter>/`: `raystep measure` writes them,
//! the charts read them; and the boxed jobs the measurements time.
use std::path::PathBuf;

use raystep_render::csv::{Row, from_csv, to_csv};

use crate::ChartError;

/// The folder of the book's figures, `<workspace>/book/src/figures`, where
/// `raystep figures` draws and `raystep measure` writes its CSV files.
pub fn book_figures() -> PathBuf {
    let kit = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let workspace = kit.ancestors().nth(2).unwrap_or(kit);
    workspace.join("book").join("src").join("figures")
}

/// The rows of the measured CSV file `file` of chapter `chapter`, as the
/// repository keeps it; an error names the file and says how to make it.
pub fn measured<R: Row>(
    chapter: &str, file: &str,
) -> Result<Vec<R>, ChartError> {
    let text = measured_text(chapter, file)?;
    let path = book_figures().join(chapter).join(file);
    Ok(from_csv(&text).map_err(|e| format!("{}: {e}", path.display()))?)
}

/// The text of the measured CSV file `file` of chapter `chapter` (see
/// [`measured`]).
fn measured_text(chapter: &str, file: &str) -> Result<String, ChartError> {
    let path = book_figures().join(chapter).join(file);
    Ok(std::fs::read_to_string(&path).map_err(|e| {
        format!("{}: {e} (run `raystep measure` first)", path.display())
    })?)
}

/// What a measuring function returns: its rows, or its rows or what is
/// missing (a message naming the file).
pub trait MeasuredRows {
    /// The CSV row.
    type Row: Row;
    /// The rows, or what is missing.
    fn rows(self) -> Result<Vec<Self::Row>, String>;
}

impl<R: Row> MeasuredRows for Vec<R> {
    type Row = R;
    fn rows(self) -> Result<Vec<R>, String> {
        Ok(self)
    }
}

impl<R: Row> MeasuredRows for Result<Vec<R>, String> {
    type Row = R;
    fn rows(self) -> Result<Vec<R>, String> {
        self
    }
}

/// A measurement's rows as the CSV text its [`crate::Measurement::run`]
/// returns.
pub fn csv_text(rows: impl MeasuredRows) -> Result<String, String> {
    rows.rows().map(|rows| to_csv(&rows))
}

/// Checks that the measured CSV file `file` of chapter `chapter` reads and
/// writes back byte for byte, so that a new measurement writes the
/// committed format; an error names the file and the first line that
/// differs.
pub fn writes_back<R: Row>(
    chapter: &str, file: &str,
) -> Result<(), ChartError> {
    let text = measured_text(chapter, file)?;
    let written = to_csv(&measured::<R>(chapter, file)?);
    let mut lines = written.lines().zip(text.lines()).enumerate();
    if let Some((k, (now, was))) = lines.find(|(_, (now, was))| now != was) {
        let line = k + 1;
        return Err(format!(
            "{chapter}/{file}, line {line}: `{was}` is written back as `{now}`"
        )
        .into());
    }
    if written != text {
        return Err(format!(
            "{chapter}/{file}: written back, its length differs"
        )
        .into());
    }
    Ok(())
}

/// Boxed jobs as [`raystep_render::timing::Timing::median_ms`] takes
/// them: the jobs a measurement builds in a loop, one per method.
pub fn as_jobs<'a>(
    jobs: &'a mut [Box<dyn FnMut() + '_>],
) -> Vec<&'a mut dyn FnMut()> {
    jobs.iter_mut().map(|job| &mut **job as _).collect()
}
