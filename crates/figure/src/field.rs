//! Area fills made of many small rectangles: a shaded scalar field and a pixelated raster.
//!
//! Both merge horizontal runs of equal colour into one `<rect>` and draw with
//! `shape-rendering="crispEdges"`, so neighbouring rectangles meet without hairline seams.

use raystep_core::DVec2;

use crate::page::Page;
use crate::style::{Color, num, palette};

/// The colour of the band `level` (0 = nearest zero) on the negative or positive side.
fn band_color(positive: bool, level: usize) -> Color {
    const STRENGTH: [f64; 4] = [0.12, 0.24, 0.38, 0.54];
    let base = if positive {
        palette::ORANGE
    } else {
        palette::BLUE
    };
    palette::WHITE.mix(base, STRENGTH[level.min(STRENGTH.len() - 1)])
}

/// The shading of value `f` for scale `f_scale`: four bands per sign by |f| / f_scale, split at
/// 0.25, 0.5 and 1. `None` (left white) for NaN.
fn field_color(f: f64, f_scale: f64) -> Option<Color> {
    if f.is_nan() {
        return None;
    }
    let v = (f / f_scale).abs();
    let level = [0.25, 0.5, 1.0].iter().filter(|&&t| v >= t).count();
    Some(band_color(f >= 0.0, level))
}

/// One row of cells as `<rect>`s, merging runs of equal colour. `cells` gives each cell's left
/// edge, right edge and colour, left to right.
fn row_rects(
    out: &mut String, y: f64, h: f64,
    cells: impl Iterator<Item = (f64, f64, Option<Color>)>,
) {
    let mut run: Option<(f64, f64, Color)> = None;
    let flush = |run: Option<(f64, f64, Color)>, out: &mut String| {
        if let Some((x0, x1, c)) = run {
            out.push_str(&format!(
                r#"<rect x="{}" y="{}" width="{}" height="{}" fill="{}"/>"#,
                num(x0),
                num(y),
                num(x1 - x0),
                num(h),
                c.hex()
            ));
            out.push('\n');
        }
    };
    for (x0, x1, color) in cells {
        run = match (run, color) {
            (Some((r0, _, rc)), Some(c)) if rc == c => Some((r0, x1, c)),
            (prev, color) => {
                flush(prev, out);
                color.map(|c| (x0, x1, c))
            }
        };
    }
    flush(run, out);
}

/// Wraps rectangles in a crisp-edged group.
fn crisp_group(rects: &str) -> String {
    format!("<g shape-rendering=\"crispEdges\">\n{rects}</g>")
}

impl Page {
    /// Shades the sign and size of `f` over the whole page: negative values blue, positive
    /// orange, each in four bands by |f| / `f_scale` (split at 0.25, 0.5 and 1), so the sign and
    /// size read at a glance. `f` is sampled at the centre of square cells of `cell_px` page px.
    /// The zero contour is not drawn: draw the line or curve on top.
    pub fn scalar_field(
        &mut self, f: impl Fn(DVec2) -> f64, f_scale: f64, cell_px: f64,
    ) {
        if !(cell_px.is_finite() && cell_px >= 0.5) {
            return;
        }
        let (w, h) = (self.width(), self.height());
        let mut rects = String::new();
        let mut y = 0.0;
        while y < h {
            let ch = cell_px.min(h - y);
            let xs =
                (0..).map(|i| f64::from(i) * cell_px).take_while(|&x| x < w);
            let cells = xs.map(|x| {
                let x1 = (x + cell_px).min(w);
                let centre =
                    self.to_world(DVec2::new((x + x1) / 2.0, y + ch / 2.0));
                (x, x1, field_color(f(centre), f_scale))
            });
            row_rects(&mut rects, y, ch, cells);
            y += cell_px;
        }
        self.raw_svg(&crisp_group(&rects));
    }

    /// A small raster image shown pixelated: `width × height` pixels filling the world
    /// rectangle [`min`, `max`], pixel (0, 0) at the top-left, `pixel(x, y)` giving each colour.
    pub fn raster(
        &mut self, min: DVec2, max: DVec2, width: u32, height: u32,
        pixel: impl Fn(u32, u32) -> Color,
    ) {
        let (a, b) = (
            self.to_page(DVec2::new(min.x, max.y)),
            self.to_page(DVec2::new(max.x, min.y)),
        );
        if width == 0 || height == 0 || !a.is_finite() || !b.is_finite() {
            return;
        }
        let step = (b - a) / DVec2::new(f64::from(width), f64::from(height));
        let mut rects = String::new();
        for j in 0..height {
            let y0 = a.y + f64::from(j) * step.y;
            let y1 = a.y + f64::from(j + 1) * step.y;
            let cells = (0..width).map(|i| {
                let x0 = a.x + f64::from(i) * step.x;
                (x0, x0 + step.x, Some(pixel(i, j)))
            });
            row_rects(&mut rects, y0, y1 - y0, cells);
        }
        self.raw_svg(&crisp_group(&rects));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_raster_merges_each_row_into_one_rect() {
        let mut page =
            Page::new(200.0, 200.0).view(DVec2::ZERO, DVec2::splat(1.0));
        page.raster(DVec2::ZERO, DVec2::splat(1.0), 16, 16, |_, _| {
            palette::SKY_BLUE
        });
        let rects = page.to_svg_source().matches("<rect").count() - 1; // minus the background
        assert!(rects <= 16, "{rects} rects");
    }

    #[test]
    fn scalar_field_merges_runs() {
        let mut page =
            Page::new(200.0, 100.0).view(DVec2::splat(-1.0), DVec2::splat(1.0));
        page.scalar_field(|p| p.y, 1.0, 4.0);
        let rects = page.to_svg_source().matches("<rect").count() - 1;
        assert_eq!(rects, 25); // one per row of cells: f depends on y only
    }

    #[test]
    fn field_bands_by_sign_and_size() {
        assert_eq!(field_color(0.1, 1.0), Some(band_color(true, 0)));
        assert_eq!(field_color(-0.3, 1.0), Some(band_color(false, 1)));
        assert_eq!(field_color(5.0, 1.0), Some(band_color(true, 3)));
        assert_eq!(field_color(f64::NAN, 1.0), None);
        assert_ne!(band_color(true, 0), band_color(false, 0));
    }
}
