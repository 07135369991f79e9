//! Charts: plotters draws into an SVG string with its SVG backend, and that
//! SVG becomes a page like any other figure's, so its text is outlined in
//! the embedded font and its PNG comes from the same tree.

use plotters::coord::Shift;
use plotters::prelude::{DrawingArea, IntoDrawingArea, SVGBackend, WHITE};

use crate::{Figure, Page};

/// The drawing area a chart function draws on.
pub type ChartArea<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// Why a chart could not be drawn.
pub type ChartError = Box<dyn std::error::Error>;

/// A figure `width × height` px drawn by `draw` with plotters, e.g. a
/// `ChartBuilder::on(area)` chart. Errors from plotters come back as the
/// message of the returned error.
pub fn chart(
    name: &str,
    caption: &str,
    width: u32,
    height: u32,
    draw: impl FnOnce(&ChartArea) -> Result<(), ChartError>,
) -> Result<Figure, ChartError> {
    let mut svg = String::new();
    {
        let area = SVGBackend::with_string(&mut svg, (width, height))
            .into_drawing_area();
        area.fill(&WHITE).map_err(|e| e.to_string())?;
        draw(&area)?;
        area.present().map_err(|e| e.to_string())?;
    }
    let mut page = Page::new(f64::from(width), f64::from(height));
    // plotters writes a whole <svg> element: nested inside the page's own
    // it keeps its coordinates (the sizes match).
    let start = svg.find("<svg").unwrap_or(0);
    page.raw_svg(&svg[start..]);
    Ok(Figure::new(name, caption, page))
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::prelude::*;

    #[test]
    fn a_chart_renders_with_outlined_text_and_is_deterministic() {
        let make = || {
            chart("demo-chart", "a line", 320, 200, |area| {
                let mut c = ChartBuilder::on(area)
                    .caption("y = x²", ("sans-serif", 16))
                    .margin(8)
                    .x_label_area_size(24)
                    .y_label_area_size(32)
                    .build_cartesian_2d(0f64..1f64, 0f64..1f64)?;
                c.configure_mesh().draw()?;
                c.draw_series(LineSeries::new(
                    (0..=10).map(|i| {
                        (f64::from(i) / 10.0, (f64::from(i) / 10.0).powi(2))
                    }),
                    &BLUE,
                ))?;
                Ok(())
            })
            .unwrap()
        };
        let (a, b) = (
            crate::render(&make()).unwrap(),
            crate::render(&make()).unwrap(),
        );
        assert_eq!(a.svg, b.svg);
        assert_eq!(a.png, b.png);
        let svg = String::from_utf8(a.svg).unwrap();
        assert!(!svg.contains("<text"), "text is outlined");
        assert!(svg.contains("<path"));
    }
}
