//! [`Image`]: a grid of linear-RGB pixels, stored as sRGB PNG.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use ::image::codecs::png::{CompressionType, FilterType, PngEncoder};
use ::image::{ExtendedColorType, ImageEncoder, ImageFormat};

use crate::RenderError;
use crate::color::{Rgb, linear_from_srgb8, linear_to_srgb, srgb8};

/// The characters of [`Image::to_ascii`], darkest to brightest.
const RAMP: &[u8; 10] = b" .:-=+*#%@";

/// A `width × height` image of linear-RGB pixels, stored row by row from the
/// top-left corner: pixel `(x, y)` is column `x` (from the left) of row `y`
/// (from the top), the same convention as `Camera::pixel_ray`.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    width: u32,
    height: u32,
    pixels: Vec<Rgb>,
}

/// The number of pixels of a `width × height` image, if it is a valid size.
pub(crate) fn pixel_count(
    width: u32, height: u32,
) -> Result<usize, RenderError> {
    if width == 0 || height == 0 {
        return Err(RenderError::InvalidSize { width, height });
    }
    usize::try_from(u64::from(width) * u64::from(height))
        .ok()
        .filter(|n| n.checked_mul(size_of::<Rgb>()).is_some())
        .ok_or(RenderError::InvalidSize { width, height })
}

impl Image {
    /// A black image.
    ///
    /// # Panics
    ///
    /// If `width` or `height` is 0 (a PNG cannot hold an empty image); use
    /// [`render`](crate::render) for a size that comes from user input, it
    /// reports that as an error.
    pub fn new(width: u32, height: u32) -> Image {
        Image::from_fn(width, height, |_, _| Rgb::ZERO)
    }

    /// An image with pixel `(x, y)` set to `f(x, y)`, computed row by row
    /// from the top (for a parallel loop see [`render`](crate::render)).
    ///
    /// # Panics
    ///
    /// If `width` or `height` is 0, like [`Image::new`].
    pub fn from_fn(
        width: u32, height: u32, mut f: impl FnMut(u32, u32) -> Rgb,
    ) -> Image {
        if let Err(e) = pixel_count(width, height) {
            panic!("{e}");
        }
        let pixels = (0..height)
            .flat_map(|y| (0..width).map(move |x| (x, y)))
            .map(|(x, y)| f(x, y))
            .collect();
        Image {
            width,
            height,
            pixels,
        }
    }

    /// An image from its pixels, row-major from the top. The caller has
    /// checked the size (`pixels.len() == width * height`, both ≥ 1).
    pub(crate) fn from_pixels(
        width: u32, height: u32, pixels: Vec<Rgb>,
    ) -> Image {
        debug_assert_eq!(
            pixels.len() as u64,
            u64::from(width) * u64::from(height)
        );
        Image {
            width,
            height,
            pixels,
        }
    }

    /// The number of columns.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The number of rows.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// All pixels, row-major from the top-left: pixel `(x, y)` is at index
    /// `y * width + x`.
    pub fn pixels(&self) -> &[Rgb] {
        &self.pixels
    }

    fn index(&self, x: u32, y: u32) -> usize {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) is outside the {}×{} image",
            self.width,
            self.height
        );
        y as usize * self.width as usize + x as usize
    }

    /// The colour of pixel `(x, y)`.
    ///
    /// # Panics
    ///
    /// If the pixel is outside the image.
    pub fn get(&self, x: u32, y: u32) -> Rgb {
        self.pixels[self.index(x, y)]
    }

    /// Sets pixel `(x, y)` to `c`.
    ///
    /// # Panics
    ///
    /// If the pixel is outside the image.
    pub fn set(&mut self, x: u32, y: u32, c: Rgb) {
        let i = self.index(x, y);
        self.pixels[i] = c;
    }

    /// The pixels as 8-bit sRGB, three bytes `r, g, b` per pixel, row-major
    /// from the top: what a PNG file holds (see [`srgb8`]).
    pub fn to_srgb8(&self) -> Vec<u8> {
        self.pixels.iter().flat_map(|&c| srgb8(c)).collect()
    }

    /// An image from 8-bit sRGB bytes (three per pixel, row-major from the
    /// top), decoded to linear RGB; `None` if the length or size is wrong.
    /// Exact inverse of [`Image::to_srgb8`]: every level survives.
    pub fn from_srgb8(width: u32, height: u32, bytes: &[u8]) -> Option<Image> {
        let n = pixel_count(width, height).ok()?;
        if bytes.len() != n.checked_mul(3)? {
            return None;
        }
        let pixels = bytes
            .chunks_exact(3)
            .map(|p| linear_from_srgb8([p[0], p[1], p[2]]))
            .collect();
        Some(Image::from_pixels(width, height, pixels))
    }

    /// The image as the bytes of an 8-bit RGB PNG file (sRGB).
    ///
    /// The bytes depend on the pixels only: no time stamp or other metadata,
    /// so the same image always encodes to the same file and a re-rendered
    /// figure shows no spurious change in version control.
    pub fn encode_png(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        let encoder = PngEncoder::new_with_quality(
            &mut bytes,
            CompressionType::Best,
            FilterType::Adaptive,
        );
        encoder
            .write_image(
                &self.to_srgb8(),
                self.width,
                self.height,
                ExtendedColorType::Rgb8,
            )
            // Writing to memory cannot fail, and the size is valid (≥ 1×1,
            // buffer length w·h·3): an error here is a bug in this crate.
            .expect("encoding a valid image into memory as PNG");
        bytes
    }

    /// Writes the image to `path` as a PNG file (see [`Image::encode_png`]).
    ///
    /// The bytes go to a temporary file next to `path` that is then renamed
    /// over it, so an interrupted run (Ctrl-C, a crash, a full disk) leaves
    /// either the old file or the new one, never half of a PNG. The folder
    /// must exist. An error names `path`.
    pub fn write_png(&self, path: impl AsRef<Path>) -> Result<(), RenderError> {
        let path = path.as_ref();
        let error = |source| RenderError::Write {
            path: path.to_path_buf(),
            source,
        };
        let temp = temp_path(path).map_err(error)?;
        let result = (|| {
            let mut file = fs::File::create(&temp)?;
            file.write_all(&self.encode_png())?;
            file.sync_all()?;
            drop(file);
            fs::rename(&temp, path)
        })();
        if result.is_err() {
            // Best effort: the original error is the one worth reporting.
            let _ = fs::remove_file(&temp);
        }
        result.map_err(error)
    }

    /// Reads a PNG file, decoding its 8-bit sRGB values back to linear RGB
    /// (exactly: `read_png` of `write_png(image)` gives back
    /// `image.to_srgb8()` to the level). An alpha channel is ignored and
    /// 16-bit or grey images are converted to 8-bit RGB. An error names `path`.
    pub fn read_png(path: impl AsRef<Path>) -> Result<Image, RenderError> {
        let path = path.as_ref();
        let bytes = fs::read(path).map_err(|source| RenderError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        let decoded =
            ::image::load_from_memory_with_format(&bytes, ImageFormat::Png)
                .map_err(|source| RenderError::Decode {
                    path: path.to_path_buf(),
                    source,
                })?
                .to_rgb8();
        let (width, height) = decoded.dimensions();
        Image::from_srgb8(width, height, decoded.as_raw())
            .ok_or_else(|| RenderError::InvalidSize { width, height })
    }

    /// A small text rendering for snapshot tests: `columns` characters wide,
    /// one line per text row, each line ending in `\n`.
    ///
    /// The image is divided into `columns` × `rows` cells, `rows` chosen so
    /// the picture keeps its proportions with characters about twice as
    /// tall as wide (`rows ≈ height · columns / width / 2`, at least 1).
    /// Each cell shows the average luminance of its pixels (averaged in
    /// linear light, then sRGB-encoded so equal steps look equally bright)
    /// as one of the ten characters `" .:-=+*#%@"`, darkest to brightest.
    /// `columns` = 0 gives an empty string.
    pub fn to_ascii(&self, columns: u32) -> String {
        if columns == 0 {
            return String::new();
        }
        let (w, h) = (u64::from(self.width), u64::from(self.height));
        let cols = u64::from(columns);
        let rows = ((h * cols + w) / (2 * w)).max(1); // round(h·cols / (2w))
        // cell i of n covers pixels [i·len/n, (i+1)·len/n), at least one
        let span = |i: u64, n: u64, len: u64| {
            let start = (i * len / n).min(len - 1);
            let end = ((i + 1) * len / n).max(start + 1);
            start as u32..end as u32
        };
        let mut out = String::with_capacity(((cols + 1) * rows) as usize);
        for row in 0..rows {
            for col in 0..cols {
                let (mut sum, mut n) = (0.0, 0.0);
                for y in span(row, rows, h) {
                    for x in span(col, cols, w) {
                        let c = self.get(x, y);
                        sum += 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
                        n += 1.0;
                    }
                }
                let level =
                    (linear_to_srgb(sum / n) * RAMP.len() as f64) as usize;
                out.push(RAMP[level.min(RAMP.len() - 1)] as char);
            }
            out.push('\n');
        }
        out
    }
}

/// A file name for the temporary copy of `path`, in the same folder (so the
/// rename stays on one file system) and hidden: `.<name>.<pid>.tmp`.
fn temp_path(path: &Path) -> std::io::Result<PathBuf> {
    let name = path.file_name().ok_or_else(|| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "the path names no file",
        )
    })?;
    let mut temp_name = std::ffi::OsString::from(".");
    temp_name.push(name);
    temp_name.push(format!(".{}.tmp", std::process::id()));
    Ok(path.with_file_name(temp_name))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A folder of its own for one test, emptied first.
    fn scratch(test: &str) -> PathBuf {
        let dir = std::env::temp_dir()
            .join(format!("raystep-render-{}-{test}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn colourful(w: u32, h: u32) -> Image {
        Image::from_fn(w, h, |x, y| {
            let (u, v) =
                (f64::from(x) / f64::from(w), f64::from(y) / f64::from(h));
            Rgb::new(u, v, (u * 7.0 + v * 3.0).sin().abs())
        })
    }

    #[test]
    fn pixels_are_row_major_from_the_top() {
        let mut image = Image::new(3, 2);
        image.set(2, 1, Rgb::ONE);
        assert_eq!(image.pixels()[5], Rgb::ONE);
        assert_eq!(image.get(2, 1), Rgb::ONE);
        assert_eq!(image.get(0, 0), Rgb::ZERO);
        assert_eq!(
            (image.width(), image.height(), image.pixels().len()),
            (3, 2, 6)
        );
        let f = Image::from_fn(3, 2, |x, y| {
            Rgb::new(f64::from(x), f64::from(y), 0.0)
        });
        assert_eq!(f.pixels()[4], Rgb::new(1.0, 1.0, 0.0));
        assert_eq!(&f.to_srgb8()[12..15], &[255, 255, 0]);
    }

    #[test]
    #[should_panic(expected = "outside the 3×2 image")]
    fn get_outside_panics() {
        Image::new(3, 2).get(3, 0);
    }

    #[test]
    #[should_panic(expected = "0×5")]
    fn empty_image_panics() {
        Image::new(0, 5);
    }

    #[test]
    fn png_encoding_is_deterministic_and_decodes_to_the_same_levels() {
        let image = colourful(37, 23);
        let bytes = image.encode_png();
        assert_eq!(bytes, colourful(37, 23).encode_png());
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        let dir = scratch("decode");
        let path = dir.join("colourful.png");
        image.write_png(&path).unwrap();
        assert_eq!(fs::read(&path).unwrap(), bytes);
        let back = Image::read_png(&path).unwrap();
        assert_eq!((back.width(), back.height()), (37, 23));
        assert_eq!(back.to_srgb8(), image.to_srgb8());
        // and a second round trip changes nothing at all
        assert_eq!(back.encode_png(), bytes);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn write_png_replaces_the_file_and_leaves_no_temporary_file() {
        let dir = scratch("write");
        let path = dir.join("out.png");
        fs::write(&path, b"old contents").unwrap();
        Image::new(2, 2).write_png(&path).unwrap();
        let names: Vec<_> = fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, ["out.png"]);
        assert_eq!(Image::read_png(&path).unwrap(), Image::new(2, 2));
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn errors_name_the_path() {
        let dir = scratch("errors");
        let missing_folder = dir.join("no-such-folder").join("out.png");
        let err = Image::new(1, 1).write_png(&missing_folder).unwrap_err();
        assert!(matches!(err, RenderError::Write { .. }));
        let message = err.to_string();
        assert!(
            message.contains(&missing_folder.display().to_string()),
            "{message}"
        );
        assert!(
            fs::read_dir(&dir).unwrap().next().is_none(),
            "nothing left behind"
        );

        let err = Image::read_png(&missing_folder).unwrap_err();
        assert!(matches!(err, RenderError::Read { .. }));
        assert!(err.to_string().contains("no-such-folder"), "{err}");

        let not_png = dir.join("not.png");
        fs::write(&not_png, b"hello").unwrap();
        let err = Image::read_png(&not_png).unwrap_err();
        assert!(matches!(err, RenderError::Decode { .. }));
        assert!(err.to_string().contains("not.png"), "{err}");
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn from_srgb8_checks_the_length() {
        assert!(Image::from_srgb8(2, 1, &[0; 5]).is_none());
        assert!(Image::from_srgb8(0, 1, &[]).is_none());
        let image =
            Image::from_srgb8(2, 1, &[0, 128, 255, 188, 188, 188]).unwrap();
        assert_eq!(image.to_srgb8(), [0, 128, 255, 188, 188, 188]);
        assert!((image.get(1, 0).x - 0.5).abs() < 0.003);
    }

    /// Each line between bars, so a snapshot keeps its trailing spaces.
    fn framed(ascii: &str) -> String {
        ascii.lines().map(|l| format!("|{l}|\n")).collect()
    }

    #[test]
    fn ascii_of_a_horizontal_gradient_is_the_ramp() {
        // sRGB-even steps from black to white, 40 × 8 pixels
        let image = Image::from_fn(40, 8, |x, _| {
            Rgb::splat(crate::srgb_to_linear(f64::from(x) / 39.0))
        });
        let ascii = image.to_ascii(20);
        assert_eq!(ascii.lines().count(), 2);
        insta::assert_snapshot!(framed(&ascii));
    }

    #[test]
    fn ascii_keeps_shapes_and_handles_odd_sizes() {
        // a white disc on black, and sizes that do not divide evenly
        let disc = Image::from_fn(30, 30, |x, y| {
            let (dx, dy) = (f64::from(x) - 14.5, f64::from(y) - 14.5);
            Rgb::splat(if dx * dx + dy * dy < 100.0 { 1.0 } else { 0.0 })
        });
        insta::assert_snapshot!(framed(&disc.to_ascii(15)));
        assert_eq!(Image::new(1, 1).to_ascii(2), "  \n");
        assert_eq!(Image::new(5, 100).to_ascii(1).lines().count(), 10);
        assert_eq!(Image::new(5, 5).to_ascii(0), "");
    }
}
