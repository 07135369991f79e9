//! Comparing a rendered image with a reference PNG, with a tolerance.

use std::fs;
use std::path::{Path, PathBuf};

use raystep_render::Image;

/// How many pixels of `a` and `b` differ in any bit: 0 only for the same
/// image bit for bit (a render that must not depend on the number of
/// threads, say). Images of different sizes differ in every pixel.
pub fn differing_pixels(a: &Image, b: &Image) -> usize {
    if (a.width(), a.height()) != (b.width(), b.height()) {
        return a.pixels().len().max(b.pixels().len());
    }
    let bits = |c: &raystep_render::Rgb| c.to_array().map(f64::to_bits);
    a.pixels()
        .iter()
        .zip(b.pixels())
        .filter(|(a, b)| bits(a) != bits(b))
        .count()
}

/// How far a render may be from its reference image and still pass.
///
/// Images are compared in 8-bit sRGB, the levels stored in the PNG. A pixel
/// *differs* if one of its channels is more than `per_channel` levels away
/// from the reference; the test passes if at most `max_differing_fraction`
/// of all pixels differ (and the sizes agree).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// How many 8-bit levels a channel may be off without the pixel counting
    /// as different.
    pub per_channel: u8,
    /// The fraction of pixels (`0.0..=1.0`) that may differ by more than
    /// `per_channel`.
    pub max_differing_fraction: f64,
}

impl Default for Tolerance {
    /// `per_channel: 2`, `max_differing_fraction: 0.001`.
    ///
    /// A correct student render that computes in another order (another
    /// but equivalent formula, another order of a sum) differs by at most a
    /// level here and there: rounding in the last bits of an `f64` moves a
    /// channel across a level boundary now and then, and a ray that grazes
    /// an edge may land on the other side of it in one pixel in a thousand.
    /// A real mistake (a wrong normal, a missing shadow, a flipped sign)
    /// changes whole regions and fails.
    fn default() -> Tolerance {
        Tolerance {
            per_channel: 2,
            max_differing_fraction: 0.001,
        }
    }
}

/// The folder where [`assert_image_matches`] puts the images of a failed
/// comparison: `target/image-diffs/` in the workspace.
///
/// It is found from `CARGO_MANIFEST_DIR` of this crate, fixed when
/// `raystep-check` is compiled (`<workspace>/crates/check`, two levels
/// below the workspace root), so every chapter's tests write to the same
/// place whatever their working directory. It is deliberately the
/// workspace's `target/` folder even when `CARGO_TARGET_DIR` points
/// elsewhere: the failure message says where to look, and the folder is
/// easy to find next to the sources. (`CARGO_TARGET_TMPDIR` was not used:
/// cargo defines it only while compiling integration tests and
/// benchmarks, not for a library like this one, so every caller would
/// have to pass it in.)
pub fn diff_dir() -> PathBuf {
    let check_crate = Path::new(env!("CARGO_MANIFEST_DIR"));
    let workspace = check_crate.ancestors().nth(2).unwrap_or(check_crate);
    workspace.join("target").join("image-diffs")
}

/// Is `RAYSTEP_BLESS=1` set?
fn bless_requested() -> bool {
    std::env::var_os("RAYSTEP_BLESS").is_some_and(|v| v == "1")
}

/// Asserts that `actual` looks like the PNG file `expected_png`, within
/// `tolerance` (see [`Tolerance`]; `Tolerance::default()` suits renders).
///
/// # Panics
///
/// If the images differ by more than the tolerance, have different sizes,
/// or `expected_png` is missing or unreadable. Before panicking it writes,
/// into [`diff_dir`] (`target/image-diffs/`), with `<name>` the file stem
/// of `expected_png`:
///
/// * `<name>.actual.png`: the render;
/// * `<name>.expected.png`: a copy of the reference, if there is one;
/// * `<name>.diff.png`: the reference in faded grey, with every pixel that
///   differs by more than `tolerance.per_channel` in red (for a size
///   mismatch, the larger of the two sizes, pixels outside either image
///   red).
///
/// The panic message gives the number of differing pixels, the largest
/// difference and the paths of these files. After a passing comparison,
/// stale files of an earlier failure with the same `<name>` are removed.
///
/// # Creating and updating reference images
///
/// With the environment variable `RAYSTEP_BLESS=1` the comparison does not
/// fail: it writes `actual` to `expected_png` (creating its folder) unless
/// the existing file already matches within the tolerance, in which case
/// the file is left alone so re-blessing does not churn images in version
/// control. **A blessed image is only as right as the code that rendered
/// it: open it and look at it before committing it.**
pub fn assert_image_matches(
    actual: &Image, expected_png: &Path, tolerance: Tolerance,
) {
    if let Err(message) = compare(
        actual,
        expected_png,
        tolerance,
        bless_requested(),
        &diff_dir(),
    ) {
        panic!("{message}");
    }
}

/// What [`compare`] found.
enum Outcome {
    /// Within the tolerance.
    Matches,
    /// The sizes differ.
    SizeMismatch { expected: (u32, u32) },
    /// Too many pixels differ.
    TooManyDiffer {
        /// Pixels differing by more than the tolerance.
        differing: usize,
        /// The largest channel difference, in levels, and where.
        largest: (u8, u32, u32),
    },
}

/// [`assert_image_matches`] with the bless switch and the diff folder
/// passed in (so the tests do not depend on the environment); `Err` holds
/// the panic message.
fn compare(
    actual: &Image, expected_png: &Path, tolerance: Tolerance, bless: bool,
    diff_dir: &Path,
) -> Result<(), String> {
    let expected = match expected_png.try_exists() {
        Ok(true) => {
            Some(Image::read_png(expected_png).map_err(|e| e.to_string()))
        }
        Ok(false) => None,
        Err(e) => Some(Err(format!(
            "cannot tell whether {} exists: {e}",
            expected_png.display()
        ))),
    };
    let outcome = match &expected {
        Some(Ok(expected)) => Some(judge(actual, expected, tolerance)),
        _ => None,
    };
    if bless {
        if matches!(outcome, Some(Outcome::Matches)) {
            eprintln!(
                "RAYSTEP_BLESS: {} already matches, left unchanged",
                expected_png.display()
            );
            return Ok(());
        }
        if let Some(parent) =
            expected_png.parent().filter(|p| !p.as_os_str().is_empty())
        {
            fs::create_dir_all(parent).map_err(|e| {
                format!(
                    "RAYSTEP_BLESS: cannot create {}: {e}",
                    parent.display()
                )
            })?;
        }
        actual
            .write_png(expected_png)
            .map_err(|e| format!("RAYSTEP_BLESS: {e}"))?;
        eprintln!(
            "RAYSTEP_BLESS: wrote {}; look at it before you commit it",
            expected_png.display()
        );
        return Ok(());
    }

    let name = expected_png
        .file_stem()
        .map_or("image".into(), |s| s.to_string_lossy());
    let out = |kind: &str| diff_dir.join(format!("{name}.{kind}.png"));
    let (actual_out, expected_out, diff_out) =
        (out("actual"), out("expected"), out("diff"));
    let bless_hint = "If the new render is right, run the test again with RAYSTEP_BLESS=1 to \
        make it the reference, and look at the image before you commit it.";

    let expected = match expected {
        Some(Ok(expected)) => expected,
        missing_or_unreadable => {
            let problem = match missing_or_unreadable {
                Some(Err(e)) => {
                    format!("the expected image cannot be used: {e}")
                }
                _ => format!(
                    "the expected image {} does not exist",
                    expected_png.display()
                ),
            };
            let written =
                write_files(diff_dir, (&actual_out, actual), None, None);
            return Err(format!(
                "{problem}. The render ({}×{}) was {written}. {bless_hint}",
                actual.width(),
                actual.height()
            ));
        }
    };
    let what = match outcome {
        Some(Outcome::Matches) | None => {
            for stale in [&actual_out, &expected_out, &diff_out] {
                let _ = fs::remove_file(stale);
            }
            return Ok(());
        }
        Some(Outcome::SizeMismatch { expected: (w, h) }) => format!(
            "the render is {}×{} pixels but the expected image is {w}×{h}",
            actual.width(),
            actual.height()
        ),
        Some(Outcome::TooManyDiffer {
            differing,
            largest: (largest, x, y),
        }) => {
            let total = actual.pixels().len();
            format!(
                "{differing} of {total} pixels ({:.3}%) differ by more than {} levels in a channel, \
                 more than the {:.3}% allowed; the largest difference is {largest} levels, at pixel \
                 ({x}, {y}) (column, row from the top-left)",
                100.0 * differing as f64 / total as f64,
                tolerance.per_channel,
                100.0 * tolerance.max_differing_fraction,
            )
        }
    };
    let diff = diff_image(actual, &expected, tolerance.per_channel);
    let written = write_files(
        diff_dir,
        (&actual_out, actual),
        Some((expected_png, &expected_out)),
        Some((&diff_out, &diff)),
    );
    Err(format!(
        "the render does not match {}: {what}. The images were {written} \
         (the diff shows differing pixels in red over the faded expected image). {bless_hint}",
        expected_png.display()
    ))
}

/// Compares two images in 8-bit sRGB.
fn judge(actual: &Image, expected: &Image, tolerance: Tolerance) -> Outcome {
    if (actual.width(), actual.height())
        != (expected.width(), expected.height())
    {
        return Outcome::SizeMismatch {
            expected: (expected.width(), expected.height()),
        };
    }
    let (a, e) = (actual.to_srgb8(), expected.to_srgb8());
    let mut differing = 0;
    let mut largest = (0, 0, 0);
    for (i, (pa, pe)) in a.chunks_exact(3).zip(e.chunks_exact(3)).enumerate() {
        let d = channel_difference(pa, pe);
        if d > tolerance.per_channel {
            differing += 1;
        }
        if d > largest.0 {
            let width = actual.width() as usize;
            largest = (d, (i % width) as u32, (i / width) as u32);
        }
    }
    let allowed =
        tolerance.max_differing_fraction * actual.pixels().len() as f64;
    if differing as f64 <= allowed {
        Outcome::Matches
    } else {
        Outcome::TooManyDiffer { differing, largest }
    }
}

/// The largest difference between two 8-bit RGB pixels, over the channels.
fn channel_difference(a: &[u8], b: &[u8]) -> u8 {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap_or(0)
}

/// The expected image in faded grey with differing pixels in red, as large
/// as the larger of the two images (outside one of them: red).
fn diff_image(actual: &Image, expected: &Image, per_channel: u8) -> Image {
    let width = actual.width().max(expected.width());
    let height = actual.height().max(expected.height());
    let (a, e) = (actual.to_srgb8(), expected.to_srgb8());
    let at = |bytes: &[u8], image: &Image, x: u32, y: u32| -> Option<[u8; 3]> {
        (x < image.width() && y < image.height()).then(|| {
            let i = 3 * (y as usize * image.width() as usize + x as usize);
            [bytes[i], bytes[i + 1], bytes[i + 2]]
        })
    };
    let mut bytes = Vec::with_capacity(3 * width as usize * height as usize);
    for y in 0..height {
        for x in 0..width {
            let pixel = match (at(&a, actual, x, y), at(&e, expected, x, y)) {
                (Some(pa), Some(pe))
                    if channel_difference(&pa, &pe) <= per_channel =>
                {
                    // faded grey: sRGB luma squeezed into levels 96..=181
                    let luma = (299 * u32::from(pe[0])
                        + 587 * u32::from(pe[1])
                        + 114 * u32::from(pe[2]))
                        / 1000;
                    let grey = (96 + luma / 3) as u8;
                    [grey; 3]
                }
                (None, None) => [0; 3],
                _ => [255, 0, 0],
            };
            bytes.extend(pixel);
        }
    }
    // width, height ≥ 1 and the length is 3·w·h, so this cannot fail.
    Image::from_srgb8(width, height, &bytes)
        .expect("a diff image of a valid size")
}

/// Writes the render, a copy of the expected file and the diff image into
/// `dir`, each if given; returns "written to A, B and C" (or what went
/// wrong) for the panic message.
fn write_files(
    dir: &Path, actual: (&Path, &Image), expected_copy: Option<(&Path, &Path)>,
    diff: Option<(&Path, &Image)>,
) -> String {
    if let Err(e) = fs::create_dir_all(dir) {
        return format!("not written: cannot create {}: {e}", dir.display());
    }
    let write = |(path, image): (&Path, &Image)| {
        (
            path.display().to_string(),
            image.write_png(path).map_err(|e| e.to_string()),
        )
    };
    let copy = |(from, to): (&Path, &Path)| {
        let result = fs::copy(from, to).map(|_| ()).map_err(|e| {
            format!(
                "could not copy {} to {}: {e}",
                from.display(),
                to.display()
            )
        });
        (to.display().to_string(), result)
    };
    let results = [
        Some(write(actual)),
        expected_copy.map(copy),
        diff.map(write),
    ];
    let (mut written, mut failed) = (Vec::new(), Vec::new());
    for (path, result) in results.into_iter().flatten() {
        match result {
            Ok(()) => written.push(path),
            Err(e) => failed.push(e),
        }
    }
    let mut text = match written.as_slice() {
        [] => "not written".to_string(),
        [one] => format!("written to {one}"),
        [init @ .., last] => {
            format!("written to {} and {last}", init.join(", "))
        }
    };
    if !failed.is_empty() {
        text.push_str(&format!(" (but {})", failed.join("; ")));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_render::Rgb;
    use std::panic::{AssertUnwindSafe, catch_unwind};

    /// A folder of its own for one test, emptied first.
    fn scratch(test: &str) -> PathBuf {
        let dir = std::env::temp_dir()
            .join(format!("raystep-check-{}-{test}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// 40 × 30 = 1200 pixels: one differing pixel is below 0.1 %, two are not.
    fn picture() -> Image {
        Image::from_fn(40, 30, |x, y| {
            let (u, v) = (f64::from(x) / 39.0, f64::from(y) / 29.0);
            let inside = (u - 0.5).powi(2) + (v - 0.5).powi(2) < 0.1;
            Rgb::new(u, v, if inside { 0.8 } else { 0.1 })
        })
    }

    /// `image` with pixel `(x, y)` moved by `levels` sRGB levels in red.
    fn nudged(image: &Image, pixels: &[(u32, u32)], levels: i16) -> Image {
        let mut bytes = image.to_srgb8();
        for &(x, y) in pixels {
            let i = 3 * (y * image.width() + x) as usize;
            bytes[i] = (i16::from(bytes[i]) + levels).clamp(0, 255) as u8;
        }
        Image::from_srgb8(image.width(), image.height(), &bytes).unwrap()
    }

    /// Runs `compare` (never blessing) and turns a failure into its message.
    fn panic_message(f: impl FnOnce()) -> Option<String> {
        let payload = catch_unwind(AssertUnwindSafe(f)).err()?;
        Some(match payload.downcast::<String>() {
            Ok(s) => *s,
            Err(p) => p.downcast_ref::<&str>().unwrap_or(&"?").to_string(),
        })
    }

    fn assert_matches_in(dir: &Path, actual: &Image, expected: &Path) {
        if let Err(m) =
            compare(actual, expected, Tolerance::default(), false, dir)
        {
            panic!("{m}");
        }
    }

    #[test]
    fn identical_images_pass() {
        let dir = scratch("identical");
        let reference = dir.join("picture.png");
        picture().write_png(&reference).unwrap();
        assert_image_matches(&picture(), &reference, Tolerance::default());
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn small_differences_within_the_tolerance_pass() {
        let dir = scratch("within");
        let reference = dir.join("picture.png");
        picture().write_png(&reference).unwrap();
        // one pixel far off: 1 of 1200 ≤ 0.1 %
        assert_matches_in(
            &dir,
            &nudged(&picture(), &[(7, 3)], 100),
            &reference,
        );
        // every pixel off by 2 levels (where not clipped)
        let all: Vec<_> =
            (0..30).flat_map(|y| (0..40).map(move |x| (x, y))).collect();
        assert_matches_in(&dir, &nudged(&picture(), &all, -2), &reference);
        assert!(
            fs::read_dir(&dir).unwrap().count() == 1,
            "nothing written on success"
        );
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_larger_difference_panics_and_leaves_the_three_images() {
        let dir = scratch("larger");
        let reference = dir.join("raystep-check-selftest.png");
        picture().write_png(&reference).unwrap();
        let diffs = diff_dir();
        let out = |kind: &str| {
            diffs.join(format!("raystep-check-selftest.{kind}.png"))
        };
        for kind in ["actual", "expected", "diff"] {
            let _ = fs::remove_file(out(kind));
        }
        let actual = nudged(&picture(), &[(1, 1), (2, 1), (3, 2)], 60);
        let message =
            panic_message(|| assert_matches_in(&diffs, &actual, &reference))
                .expect("three differing pixels must fail");
        assert!(message.contains("3 of 1200 pixels"), "{message}");
        assert!(
            message.contains(
                "the largest difference is 60 levels, at pixel (1, 1)"
            ),
            "{message}"
        );
        assert!(!message.contains('\n'), "one paragraph: {message}");
        for kind in ["actual", "expected", "diff"] {
            let path = out(kind);
            assert!(path.exists(), "{} missing", path.display());
            assert!(message.contains(&path.display().to_string()), "{message}");
        }
        // the copies are exact, and the diff marks exactly the three pixels
        assert_eq!(
            Image::read_png(out("actual")).unwrap().to_srgb8(),
            actual.to_srgb8()
        );
        assert_eq!(
            fs::read(out("expected")).unwrap(),
            fs::read(&reference).unwrap()
        );
        let diff = Image::read_png(out("diff")).unwrap();
        let red = Rgb::new(1.0, 0.0, 0.0);
        let reds: Vec<_> = (0..30)
            .flat_map(|y| (0..40).map(move |x| (x, y)))
            .filter(|&(x, y)| diff.get(x, y) == red)
            .collect();
        assert_eq!(reds, [(1, 1), (2, 1), (3, 2)]);
        // a passing comparison afterwards clears them away
        assert_matches_in(&diffs, &picture(), &reference);
        assert!(!out("diff").exists());
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_missing_expected_file_panics_naming_it() {
        let dir = scratch("missing");
        let reference = dir.join("nowhere.png");
        let message =
            panic_message(|| assert_matches_in(&dir, &picture(), &reference))
                .expect("a missing reference must fail");
        assert!(
            message.contains(&reference.display().to_string()),
            "{message}"
        );
        assert!(message.contains("does not exist"), "{message}");
        assert!(message.contains("RAYSTEP_BLESS=1"), "{message}");
        assert!(dir.join("nowhere.actual.png").exists());
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_size_mismatch_panics() {
        let dir = scratch("size");
        let reference = dir.join("small.png");
        Image::new(4, 3).write_png(&reference).unwrap();
        let message =
            panic_message(|| assert_matches_in(&dir, &picture(), &reference))
                .unwrap();
        assert!(
            message.contains("40×30 pixels but the expected image is 4×3"),
            "{message}"
        );
        let diff = Image::read_png(dir.join("small.diff.png")).unwrap();
        assert_eq!((diff.width(), diff.height()), (40, 30));
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn blessing_writes_the_reference_but_keeps_a_matching_one() {
        let dir = scratch("bless");
        let reference = dir.join("new").join("blessed.png");
        compare(&picture(), &reference, Tolerance::default(), true, &dir)
            .unwrap();
        assert_eq!(
            Image::read_png(&reference).unwrap().to_srgb8(),
            picture().to_srgb8()
        );
        // within the tolerance: the committed file is left as it is
        let before = fs::read(&reference).unwrap();
        let close = nudged(&picture(), &[(0, 0)], 1);
        compare(&close, &reference, Tolerance::default(), true, &dir).unwrap();
        assert_eq!(fs::read(&reference).unwrap(), before);
        // a real change is written
        let changed = nudged(&picture(), &[(0, 0), (1, 0), (2, 0)], 50);
        compare(&changed, &reference, Tolerance::default(), true, &dir)
            .unwrap();
        assert_eq!(
            Image::read_png(&reference).unwrap().to_srgb8(),
            changed.to_srgb8()
        );
        fs::remove_dir_all(dir).unwrap();
    }
}
