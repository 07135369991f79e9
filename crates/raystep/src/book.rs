//! `raystep book`: the lecture as a reader opens it. Draws every figure,
//! then builds the HTML book with mdBook (as a library, so nothing else must
//! be installed) and the book's own preprocessing (crates/book: listings,
//! exercise stubs with folded solutions, LaTeX math as MathML), and ships
//! the fonts the pages ask for.
//!
//! `raystep book-preprocessor` is the same preprocessing behind mdBook's
//! command protocol, so `mdbook build book` and `mdbook serve book` show
//! the same pages (book/book.toml names it).

use std::io::{self, Read};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use mdbook_driver::MDBook;
use mdbook_driver::book::{Book, BookItem};
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

use crate::chapters::CHAPTERS;
use crate::error::Error;
use crate::shown_path::{relative, shown};
use crate::workspace;

/// What `raystep book` was asked to do.
#[derive(Debug)]
pub struct Options {
    /// Where the HTML goes [default: `<workspace>/target/book`].
    pub out: Option<PathBuf>,
    /// Open the first page in the default browser afterwards.
    pub open: bool,
    /// Draw the figures first (else use book/src/figures as it is).
    pub figures: bool,
}

/// The fonts the book's stylesheet (book/raystep.css) loads from the
/// book's `fonts/` folder: New Computer Modern Math for MathML (from the
/// fonts Typst ships), and DejaVu Sans Mono for listings (it has the
/// subscripts P₀, Lᵢ that mdBook's code font lacks).
fn book_fonts() -> Result<Vec<(&'static str, &'static [u8])>, Error> {
    const MATH: &str = "NewCMMath-Book";
    let math = typst_assets::fonts()
        .find(|data| {
            let mut db = usvg::fontdb::Database::new();
            db.load_font_data(data.to_vec());
            db.faces().any(|face| face.post_script_name == MATH)
        })
        .ok_or_else(|| {
            Error::Usage(format!("the math font {MATH} is not in typst-assets"))
        })?;
    Ok(vec![
        ("NewCMMath-Book.otf", math),
        ("DejaVuSansMono.ttf", dejavu::sans_mono::regular()),
    ])
}

/// Runs `raystep book`.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    let root = workspace::root();
    let out = match &options.out {
        Some(out) => std::path::absolute(out).unwrap_or(out.clone()),
        None => root.join("target").join("book"),
    };

    // Step 1: the figures, drawn from the code.
    if options.figures {
        draw_figures(&crate::workspace::figures_dir(&root))?;
    }

    // Step 2: the pages, through mdBook with the book's preprocessing.
    let book_dir = root.join("book");
    let mut book = MDBook::load(&book_dir).map_err(|e| mdbook_error(&e))?;
    book.config.build.build_dir = out.clone();
    book.with_preprocessor(Raystep);
    book.build().map_err(|e| mdbook_error(&e))?;

    // Step 3: the fonts.
    let fonts = out.join("fonts");
    std::fs::create_dir_all(&fonts).map_err(|e| Error::io(&fonts, e))?;
    for (name, bytes) in book_fonts()? {
        let path = fonts.join(name);
        std::fs::write(&path, bytes).map_err(|e| Error::io(&path, e))?;
    }

    let index = out.join("index.html");
    println!("the book is in {}: open {}", shown(&out), shown(&index));
    // The book is built either way: a machine without a browser only
    // gets a note.
    if options.open
        && let Err(error) = opener::open(&index)
    {
        eprintln!(
            "note: no browser opened ({error}); open {} yourself",
            shown(&index)
        );
    }
    Ok(ExitCode::SUCCESS)
}

/// Draws every chapter's figures into `figures`. A chapter whose code stops
/// at a `todo!()` (a student edition, before its exercises are done) keeps
/// the figures it has, with a note: the book still builds.
fn draw_figures(figures: &Path) -> Result<(), Error> {
    let mut count = 0;
    let quiet = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let drawn: Vec<_> = CHAPTERS
        .iter()
        .map(|chapter| {
            std::panic::catch_unwind(|| chapter.all_figures())
                .map_err(|_| chapter.id)
        })
        .collect();
    std::panic::set_hook(quiet);
    for (chapter, drawn) in CHAPTERS.iter().zip(drawn) {
        match drawn {
            Ok(all) => {
                let dir = figures.join(chapter.id);
                let format = raystep_figure::Format::Both;
                count += raystep_figure::write_all(&all, &dir, format)?.len();
            }
            Err(id) => println!(
                "{id}: figures not redrawn (its code stops at a todo!(): \
                 the exercises are not done yet); the book shows the ones \
                 in {}",
                shown(&figures.join(id))
            ),
        }
    }
    println!("drew {count} figure files into {}", shown(figures));
    Ok(())
}

/// mdBook's error with its causes, on one line.
fn mdbook_error(error: &anyhow::Error) -> Error {
    let causes: Vec<String> = error.chain().map(|c| c.to_string()).collect();
    Error::Usage(format!("the book: {}", causes.join(": ")))
}

/// The book's preprocessing as an mdBook preprocessor.
pub struct Raystep;

impl Preprocessor for Raystep {
    fn name(&self) -> &str {
        "raystep"
    }

    fn run(
        &self, ctx: &PreprocessorContext, mut book: Book,
    ) -> anyhow::Result<Book> {
        let src = ctx.root.join(&ctx.config.book.src);
        preprocess_book(&src, &mut book)?;
        Ok(book)
    }

    fn supports_renderer(&self, renderer: &str) -> anyhow::Result<bool> {
        Ok(renderer == "html")
    }
}

/// Runs [`raystep_book::preprocess`] on every page of `book`.
fn preprocess_book(src: &Path, book: &mut Book) -> anyhow::Result<()> {
    let mut first_error = None;
    book.for_each_mut(|item| {
        let BookItem::Chapter(chapter) = item else {
            return;
        };
        let Some(path) = &chapter.source_path else {
            return;
        };
        if first_error.is_some() {
            return;
        }
        let page = relative(&src.join(path));
        match raystep_book::preprocess(&page, &chapter.content) {
            Ok(content) => chapter.content = content,
            Err(error) => first_error = Some(error),
        }
    });
    match first_error {
        Some(error) => Err(error.into()),
        None => Ok(()),
    }
}

/// `raystep book-preprocessor [supports RENDERER]`: mdBook's preprocessor
/// protocol. With `supports`, exits 0 for the renderers it supports;
/// otherwise reads `[context, book]` as JSON on stdin and writes the book.
pub fn preprocessor(args: &[String]) -> Result<ExitCode, Error> {
    if let [supports, renderer] = args
        && supports == "supports"
    {
        return Ok(if renderer == "html" {
            ExitCode::SUCCESS
        } else {
            ExitCode::FAILURE
        });
    }
    if !args.is_empty() {
        return Err(Error::Usage(format!(
            "book-preprocessor: unexpected arguments {args:?} \
             (mdBook runs it as `book-preprocessor [supports RENDERER]`)"
        )));
    }
    let mut input = String::new();
    io::stdin()
        .read_to_string(&mut input)
        .map_err(|e| Error::io(Path::new("<stdin>"), e))?;
    let (ctx, mut book) = mdbook_preprocessor::parse_input(input.as_bytes())
        .map_err(|e| mdbook_error(&e))?;
    let src = ctx.root.join(&ctx.config.book.src);
    preprocess_book(&src, &mut book).map_err(|e| mdbook_error(&e))?;
    serde_json::to_writer(io::stdout(), &book)
        .map_err(|e| Error::Usage(format!("book-preprocessor: {e}")))?;
    Ok(ExitCode::SUCCESS)
}
