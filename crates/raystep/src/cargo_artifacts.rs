//! Cargo's JSON messages read back (`--message-format=json…`, one per line
//! on its stdout): the test executables a build made, each with the target
//! it belongs to, in the order `raystep check` runs them; and the examples.

use std::path::{Path, PathBuf};

use raystep_check::verdicts::Target;
use serde::Deserialize;

/// A test executable cargo built.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Executable {
    /// Which target it was built from.
    pub target: Target,
    /// The executable.
    pub path: PathBuf,
    /// Its package's `Cargo.toml`.
    pub manifest_path: PathBuf,
}

impl Executable {
    /// The package folder: where cargo runs a test binary, its `CARGO_MANIFEST_DIR`.
    pub fn package_dir(&self) -> &Path {
        self.manifest_path.parent().unwrap_or(Path::new("."))
    }
}

/// The fields of one of cargo's JSON messages that name a built target
/// (`"reason": "compiler-artifact"`); the rest are ignored.
#[derive(Deserialize)]
struct Artifact {
    reason: String,
    profile: Option<ArtifactProfile>,
    executable: Option<PathBuf>,
    manifest_path: Option<PathBuf>,
    target: Option<ArtifactTarget>,
}

/// Was the artifact built with the test profile?
#[derive(Deserialize)]
struct ArtifactProfile {
    test: bool,
}

/// Which target an artifact was built from.
#[derive(Deserialize)]
struct ArtifactTarget {
    kind: Vec<String>,
    name: String,
    src_path: PathBuf,
}

/// The test executables named in the JSON messages of `cargo test --no-run
/// --message-format=json…` (one per line on its stdout), in the order
/// `raystep check` runs them: the library's unit tests, the binaries' unit
/// tests by name, the integration tests by name, anything else last.
///
/// A test executable is a `compiler-artifact` built with the test profile
/// (`"profile": {"test": true}`) that has an `executable`; the other
/// artifacts are the dependencies and the plain library and binaries.
pub fn test_executables(messages: &str) -> Vec<Executable> {
    let mut found: Vec<(u8, String, Executable)> = Vec::new();
    for line in messages.lines() {
        // other messages (build scripts, diagnostics) lack these fields
        let Ok(artifact) = serde_json::from_str::<Artifact>(line) else {
            continue;
        };
        let (Some(path), Some(manifest_path), Some(target)) =
            (artifact.executable, artifact.manifest_path, artifact.target)
        else {
            continue;
        };
        if artifact.reason != "compiler-artifact"
            || !artifact.profile.is_some_and(|p| p.test)
        {
            continue;
        }
        let kinds: Vec<&str> = target.kind.iter().map(String::as_str).collect();
        let name = target.name;
        let source = target.src_path;
        let package_dir = manifest_path.parent().unwrap_or(Path::new(""));
        let relative = source.strip_prefix(package_dir).unwrap_or(&source);
        let relative = relative.to_string_lossy().replace('\\', "/");
        let (rank, target) = if kinds.contains(&"test") {
            (2, Target::Test(test_stem(&relative)))
        } else if kinds.contains(&"bin") {
            (1, Target::Unit(relative))
        } else if kinds.contains(&"bench") || kinds.contains(&"example") {
            (3, Target::Unit(relative))
        } else {
            (0, Target::Unit(relative))
        };
        if found.iter().all(|(_, _, e)| e.path != path) {
            found.push((
                rank,
                name,
                Executable {
                    target,
                    path,
                    manifest_path,
                },
            ));
        }
    }
    found.sort_by(|(rank_a, name_a, _), (rank_b, name_b, _)| {
        (rank_a, name_a).cmp(&(rank_b, name_b))
    });
    found.into_iter().map(|(_, _, e)| e).collect()
}

/// The examples named in cargo's JSON messages (a test build builds
/// them too): (name, executable).
pub fn examples(messages: &str) -> Vec<(String, PathBuf)> {
    messages
        .lines()
        .filter_map(|line| serde_json::from_str::<Artifact>(line).ok())
        .filter(|a| a.reason == "compiler-artifact")
        .filter_map(|a| {
            let target = a.target?;
            target
                .kind
                .iter()
                .any(|k| k == "example")
                .then_some((target.name, a.executable?))
        })
        .collect()
}

/// `tests/line.rs` → `line`; `tests/line/main.rs` → `line`.
fn test_stem(source: &str) -> String {
    let path = Path::new(source);
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or(source);
    if stem == "main"
        && let Some(dir) = path
            .parent()
            .and_then(|p| p.file_name())
            .and_then(|s| s.to_str())
    {
        return dir.to_string();
    }
    stem.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_executables_are_read_from_cargos_messages() {
        let executables =
            test_executables(include_str!("../testdata/artifacts.jsonl"));
        let manifest = PathBuf::from(
            "/work/check-wt/chapters/ch01-implicit-lines-planes/Cargo.toml",
        );
        let deps = Path::new("/work/main/target/debug/deps");
        let built = |target, file: &str| Executable {
            target,
            path: deps.join(file),
            manifest_path: manifest.clone(),
        };
        let unit = |source: &str| Target::Unit(source.into());
        let test = |stem: &str| Target::Test(stem.into());
        assert_eq!(
            executables,
            [
                built(unit("src/lib.rs"), "ch01-754aa3f610206f77"),
                built(
                    unit("src/bin/ch01-figures.rs"),
                    "ch01_figures-f9cb07e01a0e3669"
                ),
                built(
                    test("line_through_points"),
                    "line_through_points-94ea8b96c78fea7c"
                ),
                built(
                    test("plane_through_points"),
                    "plane_through_points-b61bbc251acfa3bc"
                ),
            ]
        );
        assert_eq!(
            executables[0].package_dir(),
            Path::new("/work/check-wt/chapters/ch01-implicit-lines-planes")
        );
        assert_eq!(executables[0].target.to_string(), "unittests src/lib.rs");
        assert_eq!(
            executables[2].target.to_string(),
            "tests/line_through_points.rs"
        );
    }

    #[test]
    fn lines_that_are_not_test_artifacts_are_skipped() {
        let messages = "   Compiling ch01 v0.1.0\n\
            {\"reason\":\"compiler-artifact\",\"profile\":{\"test\":true},\"executable\":null,\
             \"manifest_path\":\"/p/Cargo.toml\",\"target\":{\"kind\":[\"lib\"],\"name\":\"p\",\"src_path\":\"/p/src/lib.rs\"}}\n\
            {\"reason\":\"compiler-message\",\"profile\":{\"test\":true},\"executable\":\"/t/x\",\
             \"manifest_path\":\"/p/Cargo.toml\",\"target\":{\"kind\":[\"test\"],\"name\":\"x\",\"src_path\":\"/p/tests/x.rs\"}}\n\
            {\"reason\":\"compiler-artifact\",\"profile\":{\"test\":true},\"executable\":\"/t/y\",\
             \"manifest_path\":\"/p/Cargo.toml\",\"target\":{\"kind\":[\"test\"],\"name\":\"y\",\"src_path\":\"/p/tests/y/main.rs\"}}\n\
            {\"reason\":\"build-finished\",\"success\":true}\n";
        let executables = test_executables(messages);
        assert_eq!(executables.len(), 1);
        assert_eq!(executables[0].target, Target::Test("y".into()));
        assert_eq!(executables[0].path, Path::new("/t/y"));
    }

    #[test]
    fn nested_test_folders_are_named_by_folder() {
        assert_eq!(test_stem("tests/line.rs"), "line");
        assert_eq!(test_stem("tests/line/main.rs"), "line");
    }
}
