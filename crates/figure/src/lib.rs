//! The raystep figure kit: lecture diagrams drawn in code and written as SVG and PNG files that
//! look the same on every machine and are byte-identical from run to run.
//!
//! A chapter builds [`Figure`]s — a name, a caption and a [`Page`] drawn with world-coordinate
//! primitives — and its diagram binary hands them to [`diagram_main`]. [`render`] turns a figure
//! into bytes: the page's SVG source is parsed by usvg with only the embedded DejaVu Sans font,
//! so labels become outlines; the SVG file is written back from that tree and the PNG is the
//! same tree rasterised at 2× on white. Renders shown in a figure ([`Page::image`]) are
//! embedded in the SVG as PNG data.
//!
//! # Sizes for the book
//! The book shows a figure at most [`BOOK_COLUMN_PX`] wide at 1:1; its smallest text,
//! sub- and superscripts included, should be at least [`MIN_TEXT_PX`]. [`render`] measures
//! the smallest text of every figure ([`Rendered::smallest_text`]) and the SVG file records
//! it in a comment, `<!-- raystep: smallest text 11.2 px -->`.
//!
//! # Label markup
//! Labels ([`Page::label`] and friends) take a little markup: `_` makes the next character, or
//! the `{...}` group after it, a subscript (`"P_0"`, `"E_{12}"`); `^` likewise a superscript
//! (`"x^2"`); `\` makes the next character literal (`"a\_b"`). Greek letters are typed directly
//! (`"θ"`, `"φ"`), and `<`, `>`, `&` are fine (`"f(x, y) > 0"`). Chart text ([`chart`])
//! takes the same markup.
//!
//! # Charts
//! [`chart`] draws with plotters; [`font`] gives a plotters font by its size on the page.
//! [`LogAxis`] is a log axis labelled in powers of ten that shows zero on a row of its own,
//! behind an [`AxisBreak`]; [`Labels`] puts point labels where they cover nothing.
//!
//! # Example
//! ```
//! use raystep_figure::{Anchor, DVec2, Figure, Page, Stroke, palette, render};
//!
//! let mut page = Page::new(320.0, 200.0).view(DVec2::new(-2.0, -1.0), DVec2::new(2.0, 1.5));
//! page.axes(palette::GREY);
//! page.arrow(DVec2::ZERO, DVec2::new(1.0, 1.0), &Stroke::new(palette::BLUE));
//! page.label(DVec2::new(1.0, 1.0), "v_1", Anchor::NE);
//! let rendered = render(&Figure::new("demo", "A vector.", page)).unwrap();
//! assert!(rendered.png.starts_with(b"\x89PNG"));
//! ```

mod chapter;
mod chart;
mod chart_labels;
mod cli;
mod dot_rows;
mod error;
mod field;
mod glyphs;
mod image;
mod log_axis;
mod measured;
pub mod numbers;
mod output;
mod page;
pub mod plots;
mod projection;
mod side_view;
mod style;
mod text;

pub use chapter::{Chapter, Measurement, Renderer, render_world};
pub use chart::{ChartArea, ChartError, chart, font};
pub use chart_labels::{Labels, Spot};
pub use dot_rows::DotRows;
pub use log_axis::{AxisBreak, LogAxis, Ticked, decade};
pub use measured::{
    MeasuredRows, as_jobs, book_figures, csv_text, measured, writes_back,
};
/// plotters, re-exported so chapters draw charts with the kit's version.
pub use plotters;
pub use raystep_check::questions::{ChoiceQuestion, NumberQuestion, Question};
pub use raystep_core::{DVec2, DVec3};

pub use cli::diagram_main;
pub use error::FigureError;
pub use output::{
    BOOK_COLUMN_PX, Format, MIN_TEXT_PX, Mismatch, Rendered, check_all, render,
    smallest_text_comment, write_all,
};
pub use page::{Anchor, Page, clip_line};
pub use projection::Projection;
pub use side_view::{SideView, camera_pixel};
pub use style::{Color, Fill, Stroke, palette};

/// The licence of the DejaVu fonts (Bitstream Vera licence, DejaVu changes public domain),
/// whose glyph outlines end up in every figure. Copied from the `dejavu` crate's
/// `assets/dejavu-fonts-ttf-2.37/LICENSE`.
pub const FONT_LICENSE: &str = include_str!("../assets/DejaVu-LICENSE.txt");

/// A named lecture figure.
#[derive(Clone, Debug)]
pub struct Figure {
    /// File stem: `"line-sign"` is written as `line-sign.svg` and `line-sign.png`.
    pub name: String,
    /// The caption the lecture shows under the figure (not drawn on the page).
    pub caption: String,
    /// The drawing.
    pub page: Page,
}

impl Figure {
    /// A figure named `name` (the file stem) with its caption and drawing.
    pub fn new(name: &str, caption: &str, page: Page) -> Figure {
        Figure {
            name: name.to_string(),
            caption: caption.to_string(),
            page,
        }
    }
}
