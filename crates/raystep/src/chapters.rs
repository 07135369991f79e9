//! The one list of the lecture's chapters: every command finds a chapter
//! here. A new chapter adds its figures crate to the workspace (and as a
//! dependency of this crate) and its line below.
use raystep_figure::Chapter;

/// Every chapter, in lecture order.
pub const CHAPTERS: &[&Chapter] = &[
    &ch01_figures::CHAPTER,
    &ch02_figures::CHAPTER,
    &ch03_figures::CHAPTER,
    &ch04_figures::CHAPTER,
    &ch05_figures::CHAPTER,
    &ch06_figures::CHAPTER,
    &ch07_figures::CHAPTER,
    &ch08_figures::CHAPTER,
    &ch09_figures::CHAPTER,
    &ch10_figures::CHAPTER,
    &ch11_figures::CHAPTER,
];

/// The chapter the user named (`1`, `01`, `ch01`, …), among `chapters`.
pub fn find<'a>(
    arg: &str, chapters: &[&'a Chapter],
) -> Result<&'a Chapter, crate::error::Error> {
    crate::workspace::resolve(arg, chapters, |c| c.id).copied()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// The text of `file` with each `mod x;` it declares followed by the
    /// text of that module's file, recursively: a chapter's source in the
    /// order the compiler meets it (its modules may live in folders).
    fn module_tree(file: &Path) -> String {
        let text = std::fs::read_to_string(file).unwrap();
        let stem = file.file_stem().unwrap();
        let dir = file.parent().unwrap();
        let children = if stem == "lib" || stem == "mod" {
            dir.to_path_buf()
        } else {
            dir.join(stem)
        };
        let mut out = String::new();
        for line in text.lines() {
            out.push_str(line);
            out.push('\n');
            let declared = line
                .trim()
                .trim_start_matches("pub ")
                .strip_prefix("mod ")
                .and_then(|rest| rest.strip_suffix(';'));
            if let Some(name) = declared {
                let flat = children.join(format!("{name}.rs"));
                let nested = children.join(name).join("mod.rs");
                if flat.is_file() {
                    out.push_str(&module_tree(&flat));
                } else if nested.is_file() {
                    out.push_str(&module_tree(&nested));
                }
            }
        }
        out
    }

    /// The list names every chapter folder, in order, with its package
    /// and exactly its exercises (the stems of `exercise/*.rs`), in the
    /// order its modules declare them.
    #[test]
    fn the_list_matches_the_chapter_folders() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let folders = crate::workspace::chapters(&root).unwrap();
        let ids: Vec<&str> = CHAPTERS.iter().map(|c| c.id).collect();
        let folder_ids: Vec<&str> =
            folders.iter().map(|c| c.id.as_str()).collect();
        assert_eq!(ids, folder_ids);
        for (chapter, folder) in CHAPTERS.iter().zip(&folders) {
            assert_eq!(chapter.package, folder.package);
            let mut listed: Vec<String> =
                chapter.exercises.iter().map(|e| e.to_string()).collect();
            listed.sort();
            assert_eq!(listed, folder.exercises().unwrap(), "{}", chapter.id);
            let lib = module_tree(&folder.dir.join("src/lib.rs"));
            let declared: Vec<usize> = chapter
                .exercises
                .iter()
                .map(|e| {
                    lib.find(&format!("exercise/{e}.rs")).expect("declared")
                })
                .collect();
            assert!(declared.is_sorted(), "{}: lecture order", chapter.id);
        }
    }
}
