//! [`render`]: the pixel loop, rows in parallel.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

use crate::image::pixel_count;
use crate::{Image, RenderError, Rgb};

/// When [`render`] shows a progress bar.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Progress {
    /// A bar on stderr, counting rows, if stderr is a terminal; nothing
    /// otherwise, so CI logs, tests and redirected output stay quiet.
    #[default]
    Auto,
    /// Never a bar.
    Never,
}

/// How [`render`] runs. `RenderOptions::default()` uses every core and
/// shows a bar when run in a terminal.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderOptions {
    /// `Some(n)`: render on a pool of its own of `n ≥ 1` threads
    /// (`Some(1)` is handy for debugging with prints). `None`: rayon's
    /// global pool, one thread per core (or `RAYON_NUM_THREADS`).
    pub threads: Option<usize>,
    /// Whether to show a progress bar.
    pub progress: Progress,
}

impl RenderOptions {
    /// Every core, never a progress bar: for figures and measurements,
    /// whose images are the same for any number of threads.
    pub const QUIET: RenderOptions = RenderOptions {
        threads: None,
        progress: Progress::Never,
    };
}

/// Renders a `width × height` image: pixel `(x, y)` (column `x` from the
/// left, row `y` from the top) is `pixel(x, y)`.
///
/// Rows are computed in parallel, but every pixel by one call of `pixel`
/// and nothing else, so the image is bit-for-bit the same for any number
/// of threads: a test rendered on 1 thread matches a render on 16. (Keep
/// it that way in `pixel`: no shared random-number generator or counter.)
///
/// # Errors
///
/// [`RenderError::InvalidSize`] if `width` or `height` is 0,
/// [`RenderError::ZeroThreads`] for `threads: Some(0)`, and
/// [`RenderError::ThreadPool`] if the threads cannot be started. A panic in
/// `pixel` is not caught: it reaches the caller.
pub fn render(
    width: u32, height: u32, options: &RenderOptions,
    pixel: impl Fn(u32, u32) -> Rgb + Sync,
) -> Result<Image, RenderError> {
    let count = pixel_count(width, height)?;
    let pool = match options.threads {
        None => None,
        Some(0) => return Err(RenderError::ZeroThreads),
        Some(threads) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .thread_name(|i| format!("raystep-render-{i}"))
                .build()
                .map_err(|source| RenderError::ThreadPool {
                    threads,
                    source,
                })?,
        ),
    };
    let bar = progress_bar(options.progress, height);
    let mut pixels = vec![Rgb::ZERO; count];
    let mut fill = || {
        pixels.par_chunks_mut(width as usize).enumerate().for_each(
            |(y, row)| {
                let y = y as u32; // y < height, a u32
                for (x, p) in (0..width).zip(row.iter_mut()) {
                    *p = pixel(x, y);
                }
                bar.inc(1);
            },
        );
    };
    match &pool {
        Some(pool) => pool.install(fill),
        None => fill(),
    }
    bar.finish();
    Ok(Image::from_pixels(width, height, pixels))
}

/// Runs `work`, a stage before the render (reading a mesh, building a
/// search structure), shown on stderr as `what` with a spinner while it
/// runs and its time when done, under the same rule as the bar (only on
/// a terminal, unless `progress` says never).
pub fn stage<T>(progress: Progress, what: &str, work: impl FnOnce() -> T) -> T {
    let show = match progress {
        Progress::Auto => std::io::stderr().is_terminal(),
        Progress::Never => false,
    };
    if !show {
        return work();
    }
    let spinner =
        ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    // The template is a constant: it parses, or a test fails.
    if let Ok(style) = ProgressStyle::with_template(STAGE_TEMPLATE) {
        spinner.set_style(style);
    }
    spinner.set_message(what.to_string());
    spinner.enable_steady_tick(std::time::Duration::from_millis(100));
    let started = std::time::Instant::now();
    let done = work();
    spinner.finish_with_message(format!(
        "{what}: {:.2} s",
        started.elapsed().as_secs_f64()
    ));
    done
}

/// What a stage shows while it runs: a spinner and its name.
const STAGE_TEMPLATE: &str = "{spinner} {msg}";

/// What the bar shows: time so far, the bar, rows done, time left.
const BAR_TEMPLATE: &str =
    "{elapsed_precise} [{wide_bar}] {pos}/{len} rows, {eta} left";

/// A bar counting `rows`, drawn on stderr, or a hidden one.
fn progress_bar(progress: Progress, rows: u32) -> ProgressBar {
    let show = match progress {
        Progress::Auto => std::io::stderr().is_terminal(),
        Progress::Never => false,
    };
    if !show {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(
        Some(u64::from(rows)),
        ProgressDrawTarget::stderr(),
    );
    // The template is a constant: it parses, or a test fails.
    if let Ok(style) = ProgressStyle::with_template(BAR_TEMPLATE) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stage_returns_its_work_and_its_template_parses() {
        assert!(ProgressStyle::with_template(STAGE_TEMPLATE).is_ok());
        assert_eq!(stage(Progress::Never, "building", || 42), 42);
        assert_eq!(stage(Progress::Auto, "building", || "done"), "done");
    }

    /// Enough floating-point work that a different evaluation order would
    /// show: a little chaotic iteration per pixel.
    fn busy_pixel(x: u32, y: u32) -> Rgb {
        let (mut a, mut b) =
            (f64::from(x) * 0.0137 + 0.1, f64::from(y) * 0.0291 + 0.2);
        for _ in 0..200 {
            let t = a * a - b * b + 0.3 * a.sin();
            b = 2.0 * a * b + 0.1 * b.cos() + 0.01;
            a = t.tanh() + 0.001 * f64::from(x);
            b = b.tanh();
        }
        Rgb::new(a.abs(), b.abs(), (a * b).sqrt().fract())
    }

    fn quiet(threads: Option<usize>) -> RenderOptions {
        RenderOptions {
            threads,
            progress: Progress::Never,
        }
    }

    #[test]
    fn any_thread_count_gives_the_same_pixels() {
        let (w, h) = (61, 47);
        let reference = Image::from_fn(w, h, busy_pixel);
        for threads in [Some(1), Some(2), Some(4), None] {
            let image = render(w, h, &quiet(threads), busy_pixel).unwrap();
            // compare bits, so that even NaN payloads and -0.0 must agree
            let bits = |i: &Image| -> Vec<[u64; 3]> {
                i.pixels()
                    .iter()
                    .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
                    .collect()
            };
            assert_eq!(bits(&image), bits(&reference), "threads = {threads:?}");
        }
    }

    #[test]
    fn pixels_are_addressed_by_column_and_row() {
        let image = render(3, 2, &quiet(Some(2)), |x, y| {
            Rgb::new(f64::from(x), f64::from(y), 0.0)
        })
        .unwrap();
        assert_eq!(image.get(2, 1), Rgb::new(2.0, 1.0, 0.0));
        assert_eq!(image.get(1, 0), Rgb::new(1.0, 0.0, 0.0));
    }

    #[test]
    fn bad_arguments_are_errors_not_panics() {
        let err = render(4, 4, &quiet(Some(0)), busy_pixel).unwrap_err();
        assert!(matches!(err, RenderError::ZeroThreads));
        assert!(err.to_string().contains("`threads` is 0"), "{err}");
        let err = render(0, 4, &quiet(None), busy_pixel).unwrap_err();
        assert!(matches!(
            err,
            RenderError::InvalidSize {
                width: 0,
                height: 4
            }
        ));
        assert!(err.to_string().contains("0×4"), "{err}");
        assert!(render(4, 0, &quiet(Some(1)), busy_pixel).is_err());
    }

    #[test]
    fn the_progress_template_parses() {
        assert!(ProgressStyle::with_template(BAR_TEMPLATE).is_ok());
        // Auto in a test run: stderr is captured or a pipe, so no bar
        let image =
            render(2, 2, &RenderOptions::default(), |_, _| Rgb::ONE).unwrap();
        assert_eq!(image, Image::from_fn(2, 2, |_, _| Rgb::ONE));
    }
}
