//! What a chapter hands the command line: one description per chapter,
//! which `raystep figures`, `measure`, `render` and `check` all read.
use std::fmt::Display;

use raystep_check::questions::Question;
use raystep_render::{Image, RenderOptions};
use raystep_scene::Scene;
use raystep_world::{Accelerate, World};

use crate::{ChartError, Figure};

/// A chapter's description: who it is, what it draws, what it measures,
/// how it renders a scene file, and which exercises it has.
///
/// Each chapter's figures crate (`chapters/chNN-*/figures`) exports one as
/// `CHAPTER`, built with [`Chapter::new`] and what the chapter has
/// besides; the command line keeps the list of them, in lecture order.
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
    /// Each exercise's difficulty, 1 to 3 stars, in the order of
    /// `exercises`.
    pub stars: &'static [u8],
    /// The questions worked on paper, with the answers the chapter's code
    /// computes (`raystep figures` writes them to `questions.toml` beside
    /// the figures; `raystep check` judges from that file).
    pub questions: fn() -> Vec<Question>,
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

/// What every chapter's [`Renderer`] does around its tracer: the scene's
/// `world` (as the chapter builds it: chapter 3's shapes or chapter 8's),
/// searched as `accelerate` says (built as a stage of its own, shown on a
/// terminal under `options`' progress rule), drawn by `draw`; an error
/// becomes its one line.
pub fn render_world<E: Display, F: Display>(
    world: Result<World, E>, accelerate: Accelerate, options: &RenderOptions,
    draw: impl FnOnce(&World) -> Result<Image, F>,
) -> Result<Image, String> {
    let world = world.map_err(|e| e.to_string())?;
    let what = format!(
        "building the search structure over {} objects",
        world.objects.len()
    );
    let world = raystep_render::stage(options.progress, &what, || {
        world.accelerated(accelerate)
    });
    draw(&world).map_err(|e| e.to_string())
}

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

/// A [`Measurement`] from the progress bar's name, the CSV file's name,
/// the steps function and the function that measures the rows (given the
/// rounds and the step callback, it returns rows of a
/// [`raystep_render::csv::Row`], or them or what is missing):
/// `measurement!("ch04 acne", "acne.csv", steps, measure_acne)`.
#[macro_export]
macro_rules! measurement {
    ($what:expr, $file:expr, $steps:expr, $measure:expr $(,)?) => {
        $crate::Measurement::new($what, $file, $steps, |repeats, step| {
            $crate::csv_text($measure(repeats, step))
        })
    };
}

impl Measurement {
    /// The run `what` writing `file`, with its `steps` and its `run` (see
    /// the fields, and [`measurement!`] for a run that measures rows).
    pub const fn new(
        what: &'static str, file: &'static str, steps: fn(usize) -> u64,
        run: fn(usize, &mut dyn FnMut()) -> Result<String, String>,
    ) -> Measurement {
        Measurement {
            what,
            file,
            steps,
            run,
        }
    }
}

impl Chapter {
    /// The chapter whose lecture crate is `package` (`ch04-shadows`: its
    /// first four letters are the id), with its title and exercises; it
    /// draws, charts, measures and renders nothing until the methods
    /// below say what it does.
    pub const fn new(
        package: &'static str, title: &'static str,
        exercises: &'static [&'static str],
    ) -> Chapter {
        let (id, _) = package.split_at(4);
        Chapter {
            id,
            title,
            package,
            exercises,
            stars: &[],
            questions: Vec::new,
            figures: Vec::new,
            charts: &[],
            measurements: &[],
            renderer: None,
        }
    }

    /// The same chapter with these difficulties (1 to 3 stars), one per
    /// exercise in order.
    pub const fn stars(self, stars: &'static [u8]) -> Chapter {
        Chapter { stars, ..self }
    }

    /// The same chapter asking `questions` on paper.
    pub const fn questions(self, questions: fn() -> Vec<Question>) -> Chapter {
        Chapter { questions, ..self }
    }

    /// The difficulty of `exercise` (a code exercise or a paper question's
    /// id), if it has one: `★★`.
    pub fn difficulty(&self, exercise: &str) -> Option<String> {
        let code = self.exercises.iter().position(|e| *e == exercise);
        let stars = match code {
            Some(i) => self.stars.get(i).copied(),
            None => (self.questions)()
                .iter()
                .find(|q| q.id == exercise)
                .map(|q| q.stars),
        };
        stars.map(raystep_check::questions::stars)
    }

    /// The same chapter drawing `figures`.
    pub const fn figures(self, figures: fn() -> Vec<Figure>) -> Chapter {
        Chapter { figures, ..self }
    }

    /// The same chapter drawing `charts`.
    pub const fn charts(
        self, charts: &'static [fn() -> Result<Figure, ChartError>],
    ) -> Chapter {
        Chapter { charts, ..self }
    }

    /// The same chapter measuring `measurements`.
    pub const fn measurements(
        self, measurements: &'static [Measurement],
    ) -> Chapter {
        Chapter {
            measurements,
            ..self
        }
    }

    /// The same chapter rendering scene files with `renderer`.
    pub const fn renderer(self, renderer: Renderer) -> Chapter {
        Chapter {
            renderer: Some(renderer),
            ..self
        }
    }

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

#[cfg(test)]
mod tests {
    use super::*;

    fn one_figure() -> Vec<Figure> {
        vec![Figure::new("x", "", crate::Page::new(1.0, 1.0))]
    }

    /// A one-column row.
    #[derive(serde::Serialize, serde::Deserialize)]
    struct Count {
        n: u64,
    }
    impl raystep_render::csv::Row for Count {}

    fn measure(rounds: usize, step: &mut dyn FnMut()) -> Vec<Count> {
        step();
        vec![Count { n: rounds as u64 }]
    }

    #[test]
    fn a_chapter_is_its_package_title_and_exercises_until_told_more() {
        const BARE: Chapter = Chapter::new("ch04-shadows", "Shadows", &["a"]);
        assert_eq!((BARE.id, BARE.package), ("ch04", "ch04-shadows"));
        assert_eq!((BARE.title, BARE.exercises), ("Shadows", &["a"][..]));
        assert!((BARE.figures)().is_empty());
        assert!(BARE.charts.is_empty() && BARE.measurements.is_empty());
        assert!(BARE.renderer.is_none());
        const FULL: Chapter = BARE
            .figures(one_figure)
            .measurements(&[crate::measurement!(
                "ch04 count",
                "count.csv",
                |rounds| rounds as u64,
                measure
            )])
            .renderer(|_, _, _, _| Err("no".into()));
        assert_eq!((FULL.figures)().len(), 1);
        let m = FULL.measurements[0];
        assert_eq!(
            (m.what, m.file, (m.steps)(3)),
            ("ch04 count", "count.csv", 3)
        );
        let mut steps = 0;
        assert_eq!((m.run)(7, &mut || steps += 1), Ok("n\n7\n".to_string()));
        assert_eq!(steps, 1);
        assert!(FULL.renderer.is_some());
    }
}
