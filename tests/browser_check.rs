//! `browser-check BOOK_DIR`: opens every page of the built book in headless
//! Chromium, as a reader at a 1280 px wide window would, and fails on what
//! a reader would see go wrong:
//!
//! - a console error (a failed load, a script error);
//! - an image that did not load;
//! - an include that was not expanded (`{{#include` in the text);
//! - math that did not typeset (a `merror` element, a `$` left in the
//!   text, a formula of zero width, or the math font not loaded);
//! - a figure whose smallest text is under 11 CSS px as displayed (the
//!   figure's SVG notes its smallest text, the page gives its displayed
//!   width);
//! - a listing wider than its box (a horizontal scrollbar);
//! - a line of Rust in the prose (a paragraph, list item, table cell or
//!   heading, its inline `code` left out): a listing that lost its fence
//!   (the shapes judged are in [`raystep_tests::rust_in_prose`]);
//! - an exercise's solution fold that is open.
//!
//! CI runs it after `raystep book` (see `.ci/run`):
//!
//! ```text
//! cargo run -p raystep-tests --features browser --bin browser-check -- target/book
//! ```
//!
//! `--screenshots DIR` also saves each page as a full-page PNG.
//! Chromium is `$CHROME`, else `/usr/bin/chromium` (Debian's package).

mod devtools;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use devtools::{Chromium, Tab};
use raystep_tests::rust_in_prose;
use serde::Deserialize;
use serde_json::{Value, json};

/// The window a reader has: wide enough for the sidebar and a full column.
const WINDOW: (u32, u32) = (1280, 900);
/// The smallest text a figure may show, in CSS px.
const MIN_TEXT_PX: f64 = 11.0;

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(message) => {
            eprintln!("browser-check: {message}");
            ExitCode::from(2)
        }
    }
}

/// The command line: the book folder and `--screenshots DIR`.
struct Args {
    book: PathBuf,
    screenshots: Option<PathBuf>,
}

fn args() -> Result<Args, String> {
    let mut book = None;
    let mut screenshots = None;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--screenshots" => {
                let dir = args.next().ok_or("--screenshots needs a folder")?;
                screenshots = Some(PathBuf::from(dir));
            }
            flag if flag.starts_with('-') => {
                return Err(format!(
                    "unknown option {flag} (usage: browser-check BOOK_DIR \
                     [--screenshots DIR])"
                ));
            }
            _ if book.is_some() => {
                return Err(format!("unexpected argument {arg}"));
            }
            _ => book = Some(PathBuf::from(arg)),
        }
    }
    let book =
        book.ok_or("usage: browser-check BOOK_DIR [--screenshots DIR]")?;
    Ok(Args { book, screenshots })
}

fn run() -> Result<bool, String> {
    let args = args()?;
    let book = std::path::absolute(&args.book)
        .map_err(|e| format!("{}: {e}", args.book.display()))?;
    let pages = pages(&book)?;
    if let Some(dir) = &args.screenshots {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("{}: {e}", dir.display()))?;
    }

    let chrome = std::env::var_os("CHROME")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/bin/chromium"));
    if !chrome.is_file() {
        return Err(format!(
            "no Chromium at {} (install Debian's `chromium`, or set CHROME)",
            chrome.display()
        ));
    }
    // No connections out of this machine: the book must need none.
    let flags = [
        "--disable-background-networking",
        "--disable-component-update",
        "--disable-sync",
        "--disable-quic",
        "--no-first-run",
        "--hide-scrollbars",
    ];
    let mut browser = Chromium::start(&chrome, WINDOW, &flags)?;

    let mut failures = 0;
    println!(
        "{:<32} {:>6} {:>5} {:>9} {:>8}  problems",
        "page", "images", "math", "solutions", "min text"
    );
    for page in &pages {
        let tab = browser.open_tab()?;
        let seen = visit(&mut browser, &tab, &book, page)?;
        if let Some(dir) = &args.screenshots {
            let path = dir.join(page.with_extension("png"));
            screenshot(&mut browser, &tab, &seen, &path)?;
        }
        browser.close_tab(tab)?;
        let problems = problems(&book, &seen);
        let min_text = seen
            .figures(&book)
            .iter()
            .map(|f| f.shown_text_px)
            .fold(f64::INFINITY, f64::min);
        println!(
            "{:<32} {:>6} {:>5} {:>9} {:>8}  {}",
            page.display(),
            seen.images.len(),
            seen.math,
            seen.solutions,
            if min_text.is_finite() {
                format!("{min_text:.1} px")
            } else {
                "-".into()
            },
            if problems.is_empty() { "none" } else { "" }
        );
        for problem in &problems {
            println!("    {problem}");
        }
        failures += problems.len();
    }
    println!(
        "{} pages at {}×{} px: {failures} problems",
        pages.len(),
        WINDOW.0,
        WINDOW.1
    );
    Ok(failures == 0)
}

/// The pages a reader opens: every HTML file of the book but the print
/// version (the same pages again), the 404 page and the sidebar frame.
fn pages(book: &Path) -> Result<Vec<PathBuf>, String> {
    let entries = std::fs::read_dir(book).map_err(|e| {
        format!(
            "{}: {e} (build the book first: raystep book)",
            book.display()
        )
    })?;
    let mut pages: Vec<PathBuf> = entries
        .filter_map(|e| e.ok())
        .map(|e| PathBuf::from(e.file_name()))
        .filter(|p| p.extension().is_some_and(|x| x == "html"))
        .filter(|p| {
            !matches!(p.to_str(), Some("print.html" | "404.html" | "toc.html"))
        })
        .collect();
    pages.sort();
    if pages.is_empty() {
        return Err(format!("{}: no pages", book.display()));
    }
    Ok(pages)
}

/// What the browser saw on one page.
#[derive(Debug, Default, Deserialize)]
#[serde(rename_all = "camelCase")]
struct Seen {
    #[serde(skip)]
    page: PathBuf,
    #[serde(skip)]
    console: Vec<String>,
    images: Vec<Image>,
    math: usize,
    math_errors: usize,
    empty_math: usize,
    dollars: Vec<String>,
    includes: usize,
    fonts: Vec<FontFace>,
    wide_listings: Vec<String>,
    /// The text of each block of prose, without its code and math.
    prose: Vec<String>,
    solutions: usize,
    open_solutions: usize,
    code_blocks: usize,
    height: f64,
    width: f64,
}

#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
struct Image {
    src: String,
    loaded: bool,
    natural_width: f64,
    shown_width: f64,
}

#[derive(Debug, Deserialize)]
struct FontFace {
    family: String,
    status: String,
}

/// A figure as displayed: its file, and its smallest text in CSS px.
struct Shown {
    src: String,
    shown_text_px: f64,
}

impl Seen {
    /// The SVG figures of the page and their smallest text as displayed.
    fn figures(&self, book: &Path) -> Vec<Shown> {
        self.images
            .iter()
            .filter(|i| i.src.ends_with(".svg") && i.natural_width > 0.0)
            .filter_map(|image| {
                let drawn = smallest_text(&book.join(&image.src))?;
                Some(Shown {
                    src: image.src.clone(),
                    shown_text_px: drawn * image.shown_width
                        / image.natural_width,
                })
            })
            .collect()
    }
}

/// The figure kit notes each figure's smallest text in its SVG:
/// `<!-- raystep: smallest text 11.2 px -->`.
fn smallest_text(svg: &Path) -> Option<f64> {
    let text = std::fs::read_to_string(svg).ok()?;
    let rest = &text[text.find("<!-- raystep: smallest text ")? + 28..];
    rest[..rest.find(" px")?].trim().parse().ok()
}

/// What a page must not show (see the module documentation).
fn problems(book: &Path, seen: &Seen) -> Vec<String> {
    let mut found: Vec<String> = seen.console.clone();
    if seen.width != f64::from(WINDOW.0) {
        found.push(format!(
            "the window is {} px wide, not {} (are the sizes measured at \
             another width?)",
            seen.width, WINDOW.0
        ));
    }
    for image in &seen.images {
        if !image.loaded {
            found.push(format!("image did not load: {}", image.src));
        }
    }
    for image in seen.images.iter().filter(|i| i.src.ends_with(".svg")) {
        if image.loaded && smallest_text(&book.join(&image.src)).is_none() {
            found.push(format!(
                "figure {} does not note its smallest text (redraw it: \
                 raystep figures)",
                image.src
            ));
        }
    }
    for figure in seen.figures(book) {
        if figure.shown_text_px < MIN_TEXT_PX {
            found.push(format!(
                "figure {}: smallest text {:.1} px as shown (under {MIN_TEXT_PX} px)",
                figure.src, figure.shown_text_px
            ));
        }
    }
    if seen.includes > 0 {
        found.push(format!("{} unexpanded {{{{#include}}}}", seen.includes));
    }
    if seen.math_errors > 0 {
        found.push(format!("{} math errors (merror)", seen.math_errors));
    }
    if seen.empty_math > 0 {
        found.push(format!("{} formulas drawn with no width", seen.empty_math));
    }
    for text in &seen.dollars {
        found.push(format!("a `$` outside code (untypeset math?): …{text}…"));
    }
    let needs = |family: &str, used: bool, found: &mut Vec<String>| {
        if !used {
            return;
        }
        match seen
            .fonts
            .iter()
            .find(|f| f.family.trim_matches('"') == family)
        {
            Some(face) if face.status == "loaded" => {}
            Some(face) => found.push(format!("font {family}: {}", face.status)),
            None => found.push(format!("font {family}: not declared")),
        }
    };
    needs("NewCM Math", seen.math > 0, &mut found);
    needs("DejaVu Sans Mono", seen.code_blocks > 0, &mut found);
    for first_line in &seen.wide_listings {
        found.push(format!("listing wider than the column: {first_line}"));
    }
    let mut rust: Vec<&str> = seen
        .prose
        .iter()
        .filter_map(|text| rust_in_prose::rust_line(text))
        .collect();
    rust.dedup();
    for line in rust {
        let line: String = line.chars().take(72).collect();
        found.push(format!(
            "Rust in the prose (a listing outside a code block?): {line}"
        ));
    }
    if seen.open_solutions > 0 {
        found.push(format!("{} solution folds open", seen.open_solutions));
    }
    found
}

/// What the page reports of itself once it and its fonts have loaded.
const INSPECT: &str = r#"
(async () => {
  await document.fonts.ready;
  await Promise.all([...document.images].map(i => i.decode().catch(() => {})));
  const main = document.querySelector('main');
  const prose = main.cloneNode(true);
  prose.querySelectorAll('pre, code, math, script').forEach(e => e.remove());
  const text = prose.textContent;
  const dollars = [];
  for (let i = text.indexOf('$'); i >= 0 && dollars.length < 5; i = text.indexOf('$', i + 1)) {
    dollars.push(text.slice(Math.max(0, i - 30), i + 30).replace(/\s+/g, ' '));
  }
  const maths = [...main.querySelectorAll('math')];
  // The text of each block of prose (a paragraph, list item, table cell,
  // heading…), without its inline code, math and listings.
  const blocks = new Map();
  const walk = document.createTreeWalker(main, NodeFilter.SHOW_TEXT);
  for (let node = walk.nextNode(); node; node = walk.nextNode()) {
    const parent = node.parentElement;
    if (parent.closest('pre, code, kbd, samp, math, script, style')) continue;
    const block = parent.closest('p, li, td, th, dt, dd, h1, h2, h3, h4, '
      + 'h5, h6, figcaption, summary, blockquote, details, div, main');
    blocks.set(block, (blocks.get(block) || '') + node.data);
  }
  return JSON.stringify({
    images: [...main.querySelectorAll('img:not(.img-wrapper img)')].map(i => ({
      src: i.getAttribute('src'),
      loaded: i.complete && i.naturalWidth > 0,
      naturalWidth: i.naturalWidth,
      shownWidth: i.getBoundingClientRect().width,
    })),
    math: maths.length,
    mathErrors: main.querySelectorAll('merror').length,
    emptyMath: maths.filter(m => m.getBoundingClientRect().width === 0).length,
    dollars,
    includes: (main.textContent.match(/\{\{#(include|rustdoc_include)/g) || []).length,
    fonts: [...document.fonts].map(f => ({ family: f.family, status: f.status })),
    wideListings: [...main.querySelectorAll('pre')]
      .filter(p => p.scrollWidth > p.clientWidth + 1)
      .map(p => p.textContent.trim().split('\n')[0].slice(0, 60)),
    prose: [...blocks.values()].filter(text => text.trim()),
    solutions: main.querySelectorAll('details.solution').length,
    openSolutions: main.querySelectorAll('details.solution[open]').length,
    codeBlocks: main.querySelectorAll('pre code').length,
    height: document.documentElement.scrollHeight,
    width: window.innerWidth,
  });
})()
"#;

/// Opens one page and collects what it shows and what its console says.
fn visit(
    browser: &mut Chromium, tab: &Tab, book: &Path, page: &Path,
) -> Result<Seen, String> {
    let at = |e: String| format!("{}: {e}", page.display());
    for domain in ["Log", "Runtime", "Page"] {
        browser.call(Some(tab), &format!("{domain}.enable"), json!({}))?;
    }
    let url = format!("file://{}", book.join(page).display());
    let navigated =
        browser.call(Some(tab), "Page.navigate", json!({ "url": url }))?;
    if let Some(error) = navigated["errorText"].as_str() {
        return Err(at(format!("cannot open: {error}")));
    }
    browser.wait_for(tab, "Page.loadEventFired").map_err(at)?;
    let answer = browser.evaluate(tab, INSPECT).map_err(at)?;
    let json = answer
        .as_str()
        .ok_or_else(|| at("the page did not answer".into()))?;
    let mut seen: Seen =
        serde_json::from_str(json).map_err(|e| at(e.to_string()))?;
    // A round trip, so that events sent before it have arrived.
    browser.call(
        Some(tab),
        "Runtime.evaluate",
        json!({ "expression": "0" }),
    )?;
    seen.page = page.to_path_buf();
    for event in browser.take_events(tab) {
        if let Some(message) = console_error(&event)
            && !seen.console.contains(&message)
        {
            seen.console.push(message);
        }
    }
    Ok(seen)
}

/// What a console event says, if it is an error.
fn console_error(event: &Value) -> Option<String> {
    let params = &event["params"];
    match event["method"].as_str()? {
        "Log.entryAdded" if params["entry"]["level"] == "error" => {
            let entry = &params["entry"];
            let url = entry["url"]
                .as_str()
                .map(|u| format!(" ({u})"))
                .unwrap_or_default();
            Some(format!("console: {}{url}", entry["text"].as_str()?))
        }
        "Runtime.exceptionThrown" => {
            let details = &params["exceptionDetails"];
            let text = details["exception"]["description"]
                .as_str()
                .or(details["text"].as_str())?;
            let first_line = text.lines().next().unwrap_or(text);
            Some(format!("script error: {first_line}"))
        }
        "Runtime.consoleAPICalled"
            if matches!(params["type"].as_str(), Some("error" | "assert")) =>
        {
            let first = &params["args"][0];
            let text = first["value"]
                .as_str()
                .map(str::to_string)
                .unwrap_or_else(|| first["description"].to_string());
            Some(format!("console.error: {text}"))
        }
        _ => None,
    }
}

/// The whole page as a PNG.
fn screenshot(
    browser: &mut Chromium, tab: &Tab, seen: &Seen, path: &Path,
) -> Result<(), String> {
    let shot = browser.call(
        Some(tab),
        "Page.captureScreenshot",
        json!({
            "format": "png",
            "clip": {
                "x": 0, "y": 0, "width": WINDOW.0, "height": seen.height,
                "scale": 1,
            },
            "fromSurface": true,
            "captureBeyondViewport": true,
        }),
    )?;
    use base64::Engine as _;
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(shot["data"].as_str().unwrap_or_default())
        .map_err(|e| format!("{}: screenshot: {e}", seen.page.display()))?;
    std::fs::write(path, bytes).map_err(|e| format!("{}: {e}", path.display()))
}
