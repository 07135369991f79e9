//! Where the workspace is and which chapters it has.

use std::fs;
use std::path::{Path, PathBuf};

use crate::error::Error;

/// The workspace root: the nearest directory, from the current one upwards,
/// whose `Cargo.toml` has a `[workspace]` table; otherwise the workspace this
/// program was compiled in.
pub fn root() -> PathBuf {
    std::env::current_dir()
        .ok()
        .and_then(|dir| find_root(&dir))
        .unwrap_or_else(compiled_root)
}

/// The workspace this program was compiled in (`crates/raystep/../..`).
fn compiled_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join("..")
}

/// The figure folder of the book: `<workspace>/book/src/figures`.
pub fn figures_dir(root: &Path) -> PathBuf {
    root.join("book").join("src").join("figures")
}

/// Walks up from `start` to the first `Cargo.toml` that declares `[workspace]`.
pub fn find_root(start: &Path) -> Option<PathBuf> {
    start.ancestors().find_map(|dir| {
        let text = fs::read_to_string(dir.join("Cargo.toml")).ok()?;
        text.lines()
            .any(|line| line.trim() == "[workspace]")
            .then(|| dir.to_path_buf())
    })
}

/// One chapter crate found under `chapters/` (the tests check the list of
/// chapters, `crate::chapters::CHAPTERS`, against the folders).
#[cfg(test)]
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Chapter {
    /// `ch01`.
    pub id: String,
    /// `ch01-implicit-lines-planes`: the folder name, which is also the package name.
    pub package: String,
    /// `<root>/chapters/ch01-implicit-lines-planes`.
    pub dir: PathBuf,
}

#[cfg(test)]
impl Chapter {
    /// The chapter's exercises: the file stems of `exercise/*.rs`, sorted.
    pub fn exercises(&self) -> Result<Vec<String>, Error> {
        let dir = self.dir.join("exercise");
        if !dir.is_dir() {
            return Ok(Vec::new());
        }
        let entries = fs::read_dir(&dir).map_err(|e| Error::io(&dir, e))?;
        let mut stems = Vec::new();
        for entry in entries {
            let path = entry.map_err(|e| Error::io(&dir, e))?.path();
            if path.extension().is_some_and(|ext| ext == "rs")
                && let Some(stem) = path.file_stem().and_then(|s| s.to_str())
            {
                stems.push(stem.to_string());
            }
        }
        stems.sort();
        Ok(stems)
    }
}

/// Every `chapters/chNN-*` folder with a `Cargo.toml`, in chapter order.
#[cfg(test)]
pub fn chapters(root: &Path) -> Result<Vec<Chapter>, Error> {
    let dir = root.join("chapters");
    let entries = fs::read_dir(&dir).map_err(|e| Error::io(&dir, e))?;
    let mut chapters = Vec::new();
    for entry in entries {
        let path = entry.map_err(|e| Error::io(&dir, e))?.path();
        let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
            continue;
        };
        let Some(id) = chapter_id_of_folder(name) else {
            continue;
        };
        if path.join("Cargo.toml").is_file() {
            chapters.push(Chapter {
                id,
                package: name.to_string(),
                dir: path.clone(),
            });
        }
    }
    chapters.sort_by(|a, b| a.id.cmp(&b.id));
    Ok(chapters)
}

/// `ch01-implicit-lines-planes` → `ch01`; anything else → `None`.
#[cfg(test)]
fn chapter_id_of_folder(name: &str) -> Option<String> {
    let (id, rest) = name.split_once('-')?;
    (is_chapter_id(id) && !rest.is_empty()).then(|| id.to_string())
}

/// `ch` followed by two or more digits.
#[cfg(test)]
fn is_chapter_id(id: &str) -> bool {
    id.strip_prefix("ch")
        .is_some_and(|n| n.len() >= 2 && n.bytes().all(|b| b.is_ascii_digit()))
}

/// What the user typed for a chapter, as a chapter id: `1`, `01`, `ch1`, `ch01`
/// and `ch01-implicit-lines-planes` all mean `ch01`. Unrecognisable input is
/// returned unchanged, so error messages quote it.
pub fn normalise_chapter(arg: &str) -> String {
    let arg = arg.trim();
    let lower = arg.to_ascii_lowercase();
    let digits_and_rest = lower.strip_prefix("ch").unwrap_or(&lower);
    let (digits, _name) = digits_and_rest
        .split_once('-')
        .unwrap_or((digits_and_rest, ""));
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return arg.to_string();
    }
    match digits.parse::<u32>() {
        Ok(n) => format!("ch{n:02}"),
        Err(_) => arg.to_string(),
    }
}

/// Picks the chapter the user named out of `known` (ids in lecture order).
pub fn resolve<'a, T>(
    arg: &str, known: &'a [T], id: impl Fn(&T) -> &str,
) -> Result<&'a T, Error> {
    let wanted = normalise_chapter(arg);
    known.iter().find(|c| id(c) == wanted).ok_or_else(|| {
        let ids: Vec<&str> = known.iter().map(&id).collect();
        Error::NoSuchChapter {
            wanted,
            known: ids.join(", "),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chapter_arguments_are_normalised() {
        for arg in [
            "1",
            "01",
            "ch1",
            "ch01",
            "CH01",
            "ch01-implicit-lines-planes",
            " 01 ",
        ] {
            assert_eq!(normalise_chapter(arg), "ch01", "{arg:?}");
        }
        assert_eq!(normalise_chapter("12"), "ch12");
        assert_eq!(normalise_chapter("ch99"), "ch99");
        assert_eq!(normalise_chapter("lines"), "lines");
        assert_eq!(normalise_chapter(""), "");
    }

    #[test]
    fn folder_names_give_chapter_ids() {
        assert_eq!(
            chapter_id_of_folder("ch01-implicit-lines-planes").as_deref(),
            Some("ch01")
        );
        assert_eq!(chapter_id_of_folder("ch01"), None);
        assert_eq!(chapter_id_of_folder("ch1-x"), None);
        assert_eq!(chapter_id_of_folder("notes-ch01"), None);
    }

    #[test]
    fn unknown_chapters_name_the_known_ones() {
        let known = ["ch01", "ch02"];
        assert_eq!(resolve("2", &known, |c| c).unwrap(), &"ch02");
        let err = resolve("ch99", &known, |c| c).unwrap_err();
        assert_eq!(
            err.to_string(),
            "ch99: no such chapter; chapters are ch01, ch02"
        );
    }

    #[test]
    fn the_root_is_found_from_inside_the_workspace() {
        let here = Path::new(env!("CARGO_MANIFEST_DIR"));
        let root = find_root(&here.join("src")).expect("workspace root");
        assert!(root.join("chapters").is_dir());
        assert_eq!(
            root.canonicalize().unwrap(),
            compiled_root().canonicalize().unwrap()
        );
    }

    #[test]
    fn chapters_are_found_in_order() {
        let chapters = chapters(&compiled_root()).unwrap();
        assert!(chapters.len() >= 2);
        assert_eq!(chapters[0].id, "ch01");
        assert_eq!(chapters[0].package, "ch01-implicit-lines-planes");
        assert!(chapters.windows(2).all(|w| w[0].id < w[1].id));
    }
}
