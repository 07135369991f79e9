//! Charts: plotters draws into an SVG string with its SVG backend, and that
//! SVG becomes a page like any other figure's, so its text is outlined in
//! the embedded font and its PNG comes from the same tree. Chart text takes
//! the same label markup as [`Page::label`] (`"10^{−2}"`, `"t_{min}"`).

use plotters::coord::Shift;
use plotters::prelude::{
    DrawingArea, FontDesc, FontFamily, FontStyle, IntoDrawingArea, SVGBackend,
    WHITE,
};

use crate::text::{markup_spans, unescape_xml};
use crate::{Figure, Page};

/// plotters' SVG backend writes a font of size s as `font-size` s / 1.24.
const PLOTTERS_FONT_SCALE: f64 = 1.24;

/// The sans-serif font whose text plotters draws `px` page px tall (its
/// `font-size`), for every chart text: `label_style(font(15.0))`.
pub fn font(px: f64) -> FontDesc<'static> {
    FontDesc::new(
        FontFamily::SansSerif,
        px * PLOTTERS_FONT_SCALE,
        FontStyle::Normal,
    )
}

/// The drawing area a chart function draws on.
pub type ChartArea<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// Why a chart could not be drawn.
pub type ChartError = Box<dyn std::error::Error>;

/// A figure `width × height` px drawn by `draw` with plotters, e.g. a
/// `ChartBuilder::on(area)` chart. Errors from plotters come back as the
/// message of the returned error.
pub fn chart(
    name: &str, caption: &str, width: u32, height: u32,
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
    page.raw_svg(&with_markup(&svg[start..]));
    Ok(Figure::new(name, caption, page))
}

/// plotters' SVG with the contents of every `<text>` element read as label
/// markup: sub- and superscripts become `<tspan>`s of the element's size.
fn with_markup(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len());
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        let Some(open) = rest[start..].find('>').map(|i| start + i + 1) else {
            break;
        };
        let Some(close) = rest[open..].find("</text>").map(|i| open + i) else {
            break;
        };
        let tag = &rest[start..open];
        let size = tag
            .split_once(r#"font-size=""#)
            .and_then(|(_, v)| v.split('"').next())
            .and_then(|v| v.parse::<f64>().ok())
            .unwrap_or(16.0);
        out.push_str(&rest[..open]);
        out.push_str(&markup_spans(
            unescape_xml(&rest[open..close]).trim(),
            size,
        ));
        rest = &rest[close..];
    }
    out.push_str(rest);
    out
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

    #[test]
    fn chart_text_takes_label_markup_at_the_font_size_asked() {
        let figure = chart("markup", "", 200, 100, |area| {
            area.draw(&Text::new("10^{−2} & t_{min}", (10, 50), font(20.0)))?;
            Ok(())
        })
        .unwrap();
        let source = figure.page.to_svg_source();
        assert!(
            source.contains(
                r#"10<tspan font-size="14.00" baseline-shift="7.60">−2</tspan> &amp; t<tspan font-size="14.00" baseline-shift="-4.00">min</tspan></text>"#
            ),
            "{source}"
        );
        let rendered = crate::render(&figure).unwrap();
        let size = rendered.smallest_text.unwrap();
        assert!((size - 14.0).abs() < 1e-3, "{size}");
    }
}
