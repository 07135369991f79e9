//! What both methods write: a colour, a depth and an object id per pixel.
use raystep_render::{Image, Rgb};

/// The three buffers of one image.
#[derive(Clone, Debug, PartialEq)]
pub struct Buffers {
    /// The shaded image.
    pub color: Image,
    /// The view depth of what each pixel shows (distance along the view
    /// direction), +∞ where it shows the background.
    pub depth: Vec<f64>,
    /// The index of the object each pixel shows, None for the background.
    pub id: Vec<Option<usize>>,
}

impl Buffers {
    /// Buffers of `width × height` pixels that show the background.
    pub fn new(width: u32, height: u32, background: Rgb) -> Buffers {
        let n = width as usize * height as usize;
        Buffers {
            color: Image::from_fn(width, height, |_, _| background),
            depth: vec![f64::INFINITY; n],
            id: vec![None; n],
        }
    }

    /// Image width.
    pub fn width(&self) -> u32 {
        self.color.width()
    }

    /// Image height.
    pub fn height(&self) -> u32 {
        self.color.height()
    }

    /// The id at pixel (column, row).
    pub fn id_at(&self, column: u32, row: u32) -> Option<usize> {
        self.id[row as usize * self.width() as usize + column as usize]
    }

    /// The depth at pixel (column, row).
    pub fn depth_at(&self, column: u32, row: u32) -> f64 {
        self.depth[row as usize * self.width() as usize + column as usize]
    }

    /// The id buffer as text, one character per pixel: `.` for the
    /// background, then `0`–`9`, `a`–`z`, `A`–`Z` by object index (`#`
    /// beyond).
    pub fn ids_to_ascii(&self) -> String {
        const DIGITS: &[u8] =
            b"0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
        let mut text = String::new();
        for row in 0..self.height() {
            for column in 0..self.width() {
                text.push(match self.id_at(column, row) {
                    None => '.',
                    Some(i) => DIGITS.get(i).map_or('#', |&d| char::from(d)),
                });
            }
            text.push('\n');
        }
        text
    }
}
