//! Raster images embedded in the SVG as PNG data URLs: renders shown inside a figure.
//!
//! The pixels are encoded as PNG by tiny-skia (the same encoder as the figure PNGs, so the
//! bytes are the same on every run) and written into the SVG as
//! `<image href="data:image/png;base64,…">`. usvg keeps the image in the SVG it writes back, and
//! resvg draws it into the PNG (its `raster-images` feature decodes it).

use base64::Engine;
use base64::engine::general_purpose::STANDARD;
use raystep_core::DVec2;
use resvg::tiny_skia;

use crate::page::Page;
use crate::style::num;

/// The PNG file of a `width × height` RGB 8-bit image, rows from the top.
fn encode_png(width: u32, height: u32, rgb8: &[u8]) -> Vec<u8> {
    let mut pixmap =
        tiny_skia::Pixmap::new(width, height).expect("a non-empty image size");
    for (out, rgb) in pixmap
        .data_mut()
        .chunks_exact_mut(4)
        .zip(rgb8.chunks_exact(3))
    {
        out.copy_from_slice(&[rgb[0], rgb[1], rgb[2], 255]);
    }
    pixmap
        .encode_png()
        .expect("an in-memory PNG of a valid pixmap encodes")
}

impl Page {
    /// An RGB 8-bit image, `width × height` pixels given row by row from the top (3 bytes a
    /// pixel, as `raystep_render::Image::to_srgb8` makes them), stretched over the world
    /// rectangle [`min`, `max`].
    ///
    /// Embedded in the SVG as a PNG. Shown larger than its pixel size (as in the 2× PNG, or
    /// when the rectangle is larger than the image) it is upscaled pixelated, not blurred:
    /// give the rectangle a whole multiple of the image's size in page px for even pixels.
    /// Draws nothing for an empty image or a rectangle that is not finite.
    ///
    /// # Panics
    /// If `rgb8` does not hold exactly `width · height · 3` bytes.
    pub fn image(
        &mut self, min: DVec2, max: DVec2, width: u32, height: u32, rgb8: &[u8],
    ) {
        let expected = u64::from(width) * u64::from(height) * 3;
        assert_eq!(
            rgb8.len() as u64,
            expected,
            "a {width} × {height} RGB image has {expected} bytes"
        );
        let (a, b) = (
            self.to_page(DVec2::new(min.x, max.y)),
            self.to_page(DVec2::new(max.x, min.y)),
        );
        let size = b - a;
        if width == 0
            || height == 0
            || !a.is_finite()
            || !b.is_finite()
            || size.min_element() <= 0.0
        {
            return;
        }
        // the PNG doubles the page: every image at least as large as its pixels is upscaled
        let upscaled = size.x >= f64::from(width) / 2.0
            && size.y >= f64::from(height) / 2.0;
        let rendering = if upscaled {
            r#" image-rendering="optimizeSpeed""#
        } else {
            ""
        };
        let png = encode_png(width, height, rgb8);
        let el = format!(
            r#"<image x="{}" y="{}" width="{}" height="{}" preserveAspectRatio="none"{rendering} href="data:image/png;base64,{}"/>"#,
            num(a.x),
            num(a.y),
            num(size.x),
            num(size.y),
            STANDARD.encode(png)
        );
        self.push(&[a, b], el);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Figure, render};

    /// A 4 × 2 image: top row red, green, blue, white; bottom row black.
    fn pixels() -> Vec<u8> {
        let mut rgb = vec![255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
        rgb.extend([0; 12]);
        rgb
    }

    fn figure() -> Figure {
        let mut page = Page::new(200.0, 100.0)
            .margin(0.0)
            .view(DVec2::ZERO, DVec2::new(200.0, 100.0));
        page.image(
            DVec2::new(20.0, 20.0),
            DVec2::new(180.0, 100.0),
            4,
            2,
            &pixels(),
        );
        Figure::new("image", "An embedded image.", page)
    }

    /// The colour of PNG pixel (`x`, `y`).
    fn pixel(png: &[u8], x: u32, y: u32) -> [u8; 4] {
        let pixmap = tiny_skia::Pixmap::decode_png(png).unwrap();
        let c = pixmap.pixel(x, y).unwrap();
        [c.red(), c.green(), c.blue(), c.alpha()]
    }

    #[test]
    fn source_embeds_a_png_data_url() {
        let svg = figure().page.to_svg_source();
        assert!(
            svg.contains(r#"preserveAspectRatio="none" image-rendering="optimizeSpeed" href="data:image/png;base64,iVBORw0KGgo"#),
            "{svg}"
        );
        // shown smaller than its pixels: smooth
        let mut page = Page::new(100.0, 100.0);
        page.image(DVec2::ZERO, DVec2::splat(1.0), 4, 2, &pixels());
        assert!(!page.to_svg_source().contains("optimizeSpeed"));
    }

    #[test]
    fn image_survives_into_the_svg_and_the_png() {
        let rendered = render(&figure()).unwrap();
        let svg = String::from_utf8(rendered.svg.clone()).unwrap();
        assert!(svg.contains("<image"), "{svg}");
        assert!(svg.contains("data:image/png;base64"), "{svg}");
        assert!(svg.contains(r#"image-rendering="optimizeSpeed""#), "{svg}");
        // the PNG is 400 × 200; the image covers x 40..360, y 0..160, 80 × 80 px a pixel
        assert_eq!(pixel(&rendered.png, 60, 20), [255, 0, 0, 255]);
        assert_eq!(pixel(&rendered.png, 140, 20), [0, 255, 0, 255]);
        assert_eq!(pixel(&rendered.png, 240, 60), [0, 0, 255, 255]);
        assert_eq!(pixel(&rendered.png, 300, 60), [255, 255, 255, 255]);
        assert_eq!(pixel(&rendered.png, 100, 120), [0, 0, 0, 255]);
        // pixelated: sharp edges between image pixels
        assert_eq!(pixel(&rendered.png, 119, 20), [255, 0, 0, 255]);
        assert_eq!(pixel(&rendered.png, 120, 20), [0, 255, 0, 255]);
        // outside the image: the white page
        assert_eq!(pixel(&rendered.png, 20, 100), [255, 255, 255, 255]);
        assert_eq!(pixel(&rendered.png, 200, 190), [255, 255, 255, 255]);
    }

    #[test]
    fn renders_are_byte_identical() {
        assert_eq!(render(&figure()).unwrap(), render(&figure()).unwrap());
    }

    #[test]
    #[should_panic(expected = "RGB image has 24 bytes")]
    fn wrong_pixel_count_panics() {
        Page::new(10.0, 10.0).image(DVec2::ZERO, DVec2::ONE, 4, 2, &[0; 23]);
    }
}
