//! What a chapter hands the command line: one description per chapter,
//! which `raystep figures`, `measure`, `render` and `check` all read.
use std::path::PathBuf;

use raystep_render::csv::{CsvRow, from_csv};
use raystep_render::{Image, RenderOptions};
use raystep_scene::Scene;
use raystep_world::Accelerate;

use crate::{ChartError, Figure};

/// A chapter's description: who it is, what it draws, what it measures,
/// how it renders a scene file, and which exercises it has.
///
/// Each chapter's figures crate (`chapters/chNN-*/figures`) exports one as
/// `CHAPTER`; the command line keeps the list of them, in lecture order.
#[derive(Clone, Copy, Debug)]
pub struct Chapter {
    /// `ch04`: the id the command line takes, and the name of the
    /// chapter's folder under `book/src/figures/`.
    pub id: &'static str,
    /// `Shadows`.
    pub title: &'static str,
    /// `ch04-shadows`: the lecture crate's package name, which is also its
    /// folder under `chapters/`.
    pub package: &'static str,
    /// The exercises, in lecture order: the file stems of `exercise/*.rs`,
    /// each judged by `tests/<stem>.rs`.
    pub exercises: &'static [&'static str],
    /// The lecture figures, drawn from the chapter's code.
    pub figures: fn() -> Vec<Figure>,
    /// The charts, each drawn from a CSV file a measurement wrote.
    pub charts: &'static [fn() -> Result<Figure, ChartError>],
    /// The slow timing runs behind the charts.
    pub measurements: &'static [Measurement],
    /// How `raystep render` renders a scene file with this chapter's
    /// tracer, for chapters that have one.
    pub renderer: Option<Renderer>,
}

/// A chapter's renderer: the scene (its size already chosen), the file's
/// name for messages, how to run, and what searches the objects (the
/// lecture's loop or chapter 8's hierarchy: `raystep render --accel`); an
/// error is one line naming the file.
pub type Renderer =
    fn(&Scene, &str, &RenderOptions, Accelerate) -> Result<Image, String>;

/// One timing run behind a chart.
#[derive(Clone, Copy, Debug)]
pub struct Measurement {
    /// The progress bar's name, `ch04 acne`.
    pub what: &'static str,
    /// The CSV file's name in the chapter's folder of `book/src/figures/`.
    pub file: &'static str,
    /// How many steps the run reports, given the rounds per data point.
    pub steps: fn(usize) -> u64,
    /// Runs with this many rounds per data point, calling back once per
    /// step, and returns the CSV text, or what is missing (a message
    /// naming the file).
    pub run: fn(usize, &mut dyn FnMut()) -> Result<String, String>,
}

impl Chapter {
    /// Every figure: the lecture figures, then the charts. A chart whose
    /// CSV is missing or bad is left out with a warning on stderr (and
    /// `raystep figures --check` then names its committed files as extra).
    pub fn all_figures(&self) -> Vec<Figure> {
        let mut figures = (self.figures)();
        for chart in self.charts {
            match chart() {
                Ok(figure) => figures.push(figure),
                Err(error) => {
                    eprintln!("warning: {} chart not drawn: {error}", self.id)
                }
            }
        }
        figures
    }
}

/// The folder of the book's figures, `<workspace>/book/src/figures`, where
/// `raystep figures` draws and `raystep measure` writes its CSV files.
pub fn book_figures() -> PathBuf {
    let kit = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let workspace = kit.ancestors().nth(2).unwrap_or(kit);
    workspace.join("book").join("src").join("figures")
}

/// The rows of the measured CSV file `file` of chapter `chapter`, as the
/// repository keeps it; an error names the file and says how to make it.
pub fn measured<R: CsvRow>(
    chapter: &str,
    file: &str,
) -> Result<Vec<R>, ChartError> {
    let path = book_figures().join(chapter).join(file);
    let text = std::fs::read_to_string(&path).map_err(|e| {
        format!("{}: {e} (run `raystep measure` first)", path.display())
    })?;
    Ok(from_csv(&text).map_err(|e| format!("{}: {e}", path.display()))?)
}
