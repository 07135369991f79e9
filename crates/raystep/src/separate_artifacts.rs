//! Copies of one workspace that build into one target folder keep their
//! own crates' artifacts apart (a setting of their own), so that cargo
//! never takes one copy's build for another's.

use std::path::{Path, PathBuf};

use raystep_check::verdicts::lexically_normal;

/// Cargo's arguments that keep this workspace's own artifacts apart in a
/// target folder that is not its own (`--target-dir`, `CARGO_TARGET_DIR`).
///
/// Cargo names the artifacts of a workspace's crates by their paths
/// *inside* the workspace, so copies of one workspace (`raystep grade`'s
/// scratch copy, a student edition) that build into one target folder
/// share artifacts, and cargo judges them fresh by file times alone: one
/// copy could run another's build of a student's code, or a test binary
/// with another copy's folder baked in (`env!("CARGO_MANIFEST_DIR")`, which
/// insta uses to find the snapshots). Built with a setting of their own
/// (`codegen-units = 256`, which changes how rustc splits the work, not
/// what the code does), the workspace's crates get artifacts of their own;
/// dependencies from crates.io are still shared. Copies that build into
/// the same folder at once (`raystep grade --jobs`) are told apart by
/// `copy` (0, 1, …): each has a count of its own (256, 254, …), and the
/// odd counts below each are left for [`own_package`]. Nothing is added
/// when the target folder is the workspace's `target/` (the usual case), or
/// when the members cannot be read.
pub fn separate_artifacts(
    root: &Path, target_dir: Option<&Path>, copy: u32,
) -> Vec<String> {
    let target = target_dir
        .map(Path::to_path_buf)
        .or_else(|| std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from))
        .map(|dir| {
            if dir.is_absolute() {
                dir
            } else {
                root.join(dir)
            }
        });
    let own = root.join("target");
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => lexically_normal(a) == lexically_normal(b),
    };
    match target {
        Some(target) if !same(&target, &own) => workspace_members(root)
            .iter()
            .flat_map(|name| {
                [
                    "--config".to_string(),
                    format!(
                        "profile.dev.package.\"{name}\".codegen-units={}",
                        codegen_units(copy)
                    ),
                ]
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// The codegen units of copy `copy`'s own crates: 256, 254, …
fn codegen_units(copy: u32) -> u32 {
    256 - 2 * copy.min(100)
}

/// The setting that gives `package` of copy `copy` artifacts apart from
/// every copy's other crates (`crate::test_build::Artifacts::OwnPackage`):
/// one codegen unit fewer than the copy's.
pub fn own_package(package: &str, copy: u32) -> [String; 2] {
    [
        "--config".to_string(),
        format!(
            "profile.dev.package.\"{package}\".codegen-units={}",
            codegen_units(copy) - 1
        ),
    ]
}

/// The package names of the workspace's members (its root `Cargo.toml`
/// lists them by folder); empty if a manifest cannot be read.
fn workspace_members(root: &Path) -> Vec<String> {
    let read = |path: PathBuf| -> Option<toml::Table> {
        std::fs::read_to_string(path).ok()?.parse().ok()
    };
    let Some(manifest) = read(root.join("Cargo.toml")) else {
        return Vec::new();
    };
    let members = manifest
        .get("workspace")
        .and_then(|w| w.get("members"))
        .and_then(|m| m.as_array())
        .cloned()
        .unwrap_or_default();
    members
        .iter()
        .filter_map(|member| {
            let package = read(root.join(member.as_str()?).join("Cargo.toml"))?;
            Some(package.get("package")?.get("name")?.as_str()?.to_string())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_files::write;

    /// A target folder of another workspace: this workspace's crates get
    /// a setting of their own; in its own `target/`, nothing changes.
    #[test]
    fn own_artifacts_apart_in_a_foreign_target_folder() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        let write = |path: &str, text: &str| write(&root.join(path), text);
        write(
            "Cargo.toml",
            "[workspace]\nmembers = [\"crates/a\", \"chapters/b\"]\n",
        );
        write("crates/a/Cargo.toml", "[package]\nname = \"a-core\"\n");
        write("chapters/b/Cargo.toml", "[package]\nname = \"ch09-b\"\n");
        assert!(
            separate_artifacts(root, Some(&root.join("target")), 0).is_empty()
        );
        assert_eq!(
            separate_artifacts(root, Some(Path::new("/elsewhere/target")), 0),
            [
                "--config",
                "profile.dev.package.\"a-core\".codegen-units=256",
                "--config",
                "profile.dev.package.\"ch09-b\".codegen-units=256",
            ]
        );
        // A second copy building at once: counts of its own, for the
        // workspace and for the package compiled apart.
        assert_eq!(
            separate_artifacts(root, Some(Path::new("/elsewhere/target")), 1)
                [1],
            "profile.dev.package.\"a-core\".codegen-units=254"
        );
        assert_eq!(
            own_package("ch09-b", 1)[1],
            "profile.dev.package.\"ch09-b\".codegen-units=253"
        );
        assert_eq!(
            own_package("ch09-b", 0)[1],
            "profile.dev.package.\"ch09-b\".codegen-units=255"
        );
        // Unreadable members: nothing to add.
        write("Cargo.toml", "[workspace\n");
        assert!(separate_artifacts(root, Some(Path::new("/x")), 0).is_empty());
    }
}
