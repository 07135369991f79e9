//! `{{#question q1}}`: a paper question, stated where its idea is taught.
//!
//! The question comes from the chapter's `figures/chNN/questions.toml`
//! (written by `raystep figures` from the chapter's code; the page
//! `chNN-….md` names the chapter). The page shows its number, difficulty,
//! prompt and the form of the answer; the worked answer follows in a
//! closed fold, as an exercise's solution does. The student edition's
//! file has no worked answers: there the fold is left out.

use std::path::Path;

use raystep_check::questions::{Question, Questions};

/// The question id of a `{{#question ID}}` line, if the line is one.
pub fn directive(trimmed: &str) -> Option<&str> {
    let id = trimmed
        .trim_end()
        .strip_prefix("{{#question ")?
        .strip_suffix("}}")?
        .trim();
    (!id.is_empty()).then_some(id)
}

/// The Markdown (with `$…$` math still to typeset) of question `id` of the
/// page `page` (in `dir`, the book's source folder).
pub fn render(dir: &Path, page: &Path, id: &str) -> Result<String, String> {
    let name = page
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let chapter = name
        .get(..4)
        .filter(|c| c.starts_with("ch") && c[2..].bytes().all(|b| b.is_ascii_digit()))
        .ok_or_else(|| {
            format!("{{{{#question {id}}}}}: only a chapter's page (chNN-….md) asks questions")
        })?;
    let file = Path::new("figures").join(chapter).join("questions.toml");
    let text = std::fs::read_to_string(dir.join(&file)).map_err(|e| {
        format!(
            "{{{{#question {id}}}}}: {}: {e} (draw it with `raystep figures`)",
            file.display()
        )
    })?;
    let questions = Questions::parse(&file.display().to_string(), &text)?;
    let question =
        questions
            .questions
            .iter()
            .find(|q| q.id == id)
            .ok_or_else(|| {
                let ids: Vec<&str> =
                    questions.questions.iter().map(|q| q.id.as_str()).collect();
                format!(
                    "{{{{#question {id}}}}}: no such question in {}; it has {}",
                    file.display(),
                    ids.join(", ")
                )
            })?;
    Ok(block(chapter, question))
}

/// The question as a block of Markdown.
fn block(chapter: &str, q: &Question) -> String {
    let number = q.id.trim_start_matches('q');
    let mut text = format!(
        "<div class=\"question\">\n\n**Question {number}** ({}, on paper): \
         *{}.* {}\n\n*Answer* in `exercise/answers.toml` as `{} = …`: {}; \
         `raystep check {chapter}` judges it.\n",
        q.difficulty(),
        q.title,
        one_line(&q.prompt),
        q.id,
        q.form(),
    );
    if let Some(worked) = &q.worked {
        text.push_str(&format!(
            "\n<details class=\"solution\">\n<summary>Worked answer (try it \
             on paper first)</summary>\n\n{}\n\n</details>\n",
            one_line(worked)
        ));
    }
    text.push_str("\n</div>");
    text
}

/// Text on one line (a paragraph of Markdown).
fn one_line(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = r#"
[[question]]
id = "q1"
stars = 2
title = "t where a ray meets a plane"
prompt = "The ray meets the plane $z = 4$: what is $t$?"
kind = "number"
quantity = "t"
step = 0.01
answer = 4.0
worked = "$t = 4$."
"#;

    fn book() -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        let figures = dir.path().join("figures/ch02");
        std::fs::create_dir_all(&figures).unwrap();
        std::fs::write(figures.join("questions.toml"), FILE).unwrap();
        dir
    }

    #[test]
    fn a_directive_is_a_line_of_its_own() {
        assert_eq!(directive("{{#question q1}}"), Some("q1"));
        assert_eq!(directive("{{#question q1}}  "), Some("q1"));
        assert_eq!(directive("{{#question }}"), None);
        assert_eq!(directive("see {{#question q1}}"), None);
    }

    #[test]
    fn the_question_is_stated_with_its_answer_folded() {
        let dir = book();
        let page = dir.path().join("ch02-plane-polygon-hits.md");
        let text = render(dir.path(), &page, "q1").unwrap();
        assert!(text.contains(
            "**Question 1** (★★, on paper): *t where a ray meets a plane.* \
             The ray meets the plane $z = 4$: what is $t$?"
        ));
        assert!(text.contains(
            "as `q1 = …`: a number, to within 0.01; `raystep check ch02`"
        ));
        assert!(text.contains("<details class=\"solution\">"));
        assert!(text.contains("\n$t = 4$.\n"));
    }

    #[test]
    fn the_student_edition_has_no_fold() {
        let dir = book();
        let file = dir.path().join("figures/ch02/questions.toml");
        let hidden =
            Questions::parse("q", FILE).unwrap().without_answers("ch02");
        std::fs::write(&file, hidden.to_toml("hidden")).unwrap();
        let page = dir.path().join("ch02-x.md");
        let text = render(dir.path(), &page, "q1").unwrap();
        assert!(!text.contains("<details") && !text.contains("t = 4"));
    }

    #[test]
    fn an_unknown_question_or_page_is_named() {
        let dir = book();
        let page = dir.path().join("ch02-x.md");
        assert_eq!(
            render(dir.path(), &page, "q7").unwrap_err(),
            "{{#question q7}}: no such question in figures/ch02/questions.toml; it has q1"
        );
        let intro = dir.path().join("introduction.md");
        assert!(
            render(dir.path(), &intro, "q1")
                .unwrap_err()
                .contains("only a chapter's page")
        );
        let other = dir.path().join("ch03-y.md");
        assert!(
            render(dir.path(), &other, "q1")
                .unwrap_err()
                .contains("figures/ch03/questions.toml")
        );
    }
}
