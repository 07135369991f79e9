//! A throwaway workspace for the tests of `check` and of the student
//! loop (`watch`, `progress`): shaped like the real one as far as `raystep check` looks
//! (chapter 1's package and exercise names), with one chapter that
//! compiles in seconds, so that no test writes into the real workspace.
#![allow(dead_code)]

use std::fs;
use std::path::{Path, PathBuf};

/// `line_through_points`, wrong: the rise without the run.
pub const WRONG_SLOPE: &str = "pub fn slope(p0: (f64, f64), p1: (f64, f64)) \
    -> f64 {\n\
    \x20   p1.1 - p0.1\n\
    }\n";

/// `line_through_points`, right.
pub const RIGHT_SLOPE: &str = "pub fn slope(p0: (f64, f64), p1: (f64, f64)) \
    -> f64 {\n\
    \x20   (p1.1 - p0.1) / (p1.0 - p0.0)\n\
    }\n";

/// `line_through_points`, never ending.
pub const LOOPING_SLOPE: &str = "pub fn slope(p0: (f64, f64), p1: (f64, f64)) \
    -> f64 {\n\
    \x20   let _ = (p0, p1);\n\
    \x20   loop {\n\
    \x20       std::thread::sleep(std::time::Duration::from_millis(10));\n\
    \x20   }\n\
    }\n";

/// `plane_through_points`, right.
pub const RIGHT_NORMAL: &str = "pub fn normal_z(a: (f64, f64), b: (f64, f64)) \
    -> f64 {\n\
    \x20   a.0 * b.1 - a.1 * b.0\n\
    }\n";

/// Writes `text` to `path` unless it holds it already (cargo rebuilds what
/// has a newer modification time).
fn write(path: &Path, text: &str) {
    if fs::read_to_string(path).ok().as_deref() != Some(text) {
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, text).unwrap();
    }
}

/// The chapter's folder in the workspace at `root`.
pub fn chapter(root: &Path) -> PathBuf {
    root.join("chapters/ch01-implicit-lines-planes")
}

/// The workspace `<tmp>/<name>`: chapter 1 whose `line_through_points`
/// is `slope` (one of the constants above) and whose
/// `plane_through_points` is right; nothing recorded yet (no
/// `.raystep/`). Its target folder, `<root>/target`, is kept between
/// runs.
pub fn workspace(name: &str, slope: &str) -> PathBuf {
    with_stubs(name, slope, RIGHT_NORMAL)
}

/// [`workspace`] with the stubs `line` (of `slope`) and `plane` (of
/// `normal_z`); the reference bodies are right, and the library has one
/// unit test of its own.
pub fn with_stubs(name: &str, line: &str, plane: &str) -> PathBuf {
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let chapter = chapter(&root);
    let _ = fs::remove_dir_all(root.join(".raystep"));
    write(
        &root.join("Cargo.toml"),
        "[workspace]\nresolver = \"3\"\nmembers = [\"chapters/ch01-implicit-lines-planes\"]\n",
    );
    write(
        &chapter.join("Cargo.toml"),
        "[package]\n\
         name = \"ch01-implicit-lines-planes\"\n\
         version = \"0.1.0\"\n\
         edition = \"2024\"\n\
         publish = false\n\n\
         [lib]\n\
         name = \"ch01\"\n\n\
         [features]\n\
         exercise = []\n",
    );
    write(
        &chapter.join("src/lib.rs"),
        "#[cfg_attr(feature = \"exercise\", path = \"../exercise/line_through_points.rs\")]\n\
         mod line_through_points;\n\
         #[cfg_attr(feature = \"exercise\", path = \"../exercise/plane_through_points.rs\")]\n\
         mod plane_through_points;\n\n\
         pub use line_through_points::slope;\n\
         pub use plane_through_points::normal_z;\n\n\
         #[cfg(test)]\n\
         mod tests {\n\
         \x20   #[test]\n\
         \x20   fn a_unit_test() {}\n\
         }\n",
    );
    write(&chapter.join("src/line_through_points.rs"), RIGHT_SLOPE);
    write(&chapter.join("exercise/line_through_points.rs"), line);
    write(&chapter.join("src/plane_through_points.rs"), RIGHT_NORMAL);
    write(&chapter.join("exercise/plane_through_points.rs"), plane);
    write(
        &chapter.join("tests/line_through_points.rs"),
        "#[test]\n\
         fn slope_of_a_diagonal() {\n\
         \x20   assert_eq!(ch01::slope((0.0, 0.0), (2.0, 2.0)), 1.0);\n\
         }\n",
    );
    write(
        &chapter.join("tests/plane_through_points.rs"),
        "#[test]\n\
         fn normal_of_the_xy_plane() {\n\
         \x20   assert_eq!(ch01::normal_z((1.0, 0.0), (0.0, 1.0)), 1.0);\n\
         }\n",
    );
    root
}
