//! Where an exercise's reference module lives: the one file
//! `src/**/<exercise>.rs` of its chapter. A chapter keeps each exercise's
//! module in the folder of its part of the lecture (chapter 8's slab test
//! is `src/primitives/slab.rs`), so the tools look it up, never assume
//! `src/<exercise>.rs`.
use std::path::{Path, PathBuf};

use walkdir::WalkDir;

use crate::error::Error;

/// The reference module of `exercise` in the chapter folder `chapter`:
/// the one file named `<exercise>.rs` below its `src/`.
pub fn reference_module(
    chapter: &Path, exercise: &str,
) -> Result<PathBuf, Error> {
    let src = chapter.join("src");
    let name = format!("{exercise}.rs");
    let mut found: Vec<PathBuf> = WalkDir::new(&src)
        .sort_by_file_name()
        .into_iter()
        .filter_map(Result::ok)
        .filter(|entry| {
            entry.file_type().is_file() && entry.file_name() == name.as_str()
        })
        .map(|entry| entry.into_path())
        .collect();
    match found.len() {
        1 => Ok(found.remove(0)),
        0 => Err(Error::Usage(format!(
            "{}: no module {name} (the reference of exercise/{name})",
            src.display()
        ))),
        _ => Err(Error::Usage(format!(
            "{}: {} files named {name}; an exercise's module must have a name \
             of its own in its chapter",
            src.display(),
            found.len()
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_a_module_in_a_part_s_folder_and_refuses_ambiguity() {
        let dir = tempfile::tempdir().unwrap();
        let write = |path: &str| {
            let path = dir.path().join(path);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, "").unwrap();
        };
        write("src/lib.rs");
        write("src/a.rs");
        write("src/part/b.rs");
        assert_eq!(
            reference_module(dir.path(), "a").unwrap(),
            dir.path().join("src/a.rs")
        );
        assert_eq!(
            reference_module(dir.path(), "b").unwrap(),
            dir.path().join("src/part/b.rs")
        );
        let missing = reference_module(dir.path(), "c").unwrap_err();
        assert!(missing.to_string().contains("no module c.rs"), "{missing}");
        write("src/other/b.rs");
        let twice = reference_module(dir.path(), "b").unwrap_err();
        assert!(twice.to_string().contains("2 files named b.rs"), "{twice}");
    }
}
