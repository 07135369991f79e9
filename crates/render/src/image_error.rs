//! How far one image is from another, as the charts report it.
use crate::{Image, srgb8};

/// How far an image is from a reference, in 8-bit sRGB levels (0–255,
/// what the PNG file and the screen show): the root mean square of the
/// differences over every channel of every pixel, and the largest one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageError {
    /// √(mean of the squared level differences), over 3 channels × pixels.
    pub rmse: f64,
    /// The largest level difference of any channel of any pixel.
    pub max: f64,
}

/// The [`ImageError`] of `image` against `reference` (the same size).
///
/// # Panics
/// If the sizes differ.
pub fn image_error(image: &Image, reference: &Image) -> ImageError {
    assert_eq!(
        (image.width(), image.height()),
        (reference.width(), reference.height()),
        "images of the same size"
    );
    let (mut sum, mut max, mut n) = (0.0, 0.0f64, 0.0);
    for (&a, &b) in image.pixels().iter().zip(reference.pixels()) {
        for (x, y) in srgb8(a).into_iter().zip(srgb8(b)) {
            let d = f64::from(x.abs_diff(y));
            sum += d * d;
            max = max.max(d);
            n += 1.0;
        }
    }
    ImageError {
        rmse: (sum / n).sqrt(),
        max,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_core::DVec3;

    #[test]
    fn image_error_is_in_8_bit_levels_over_every_channel() {
        let black = Image::new(2, 1);
        let mut one = Image::new(2, 1);
        // linear 0.5 is sRGB level 188 in one channel of one pixel
        one.set(1, 0, DVec3::new(0.0, 0.5, 0.0));
        let e = image_error(&one, &black);
        assert_eq!(e.max, 188.0);
        assert!((e.rmse - (188.0f64 * 188.0 / 6.0).sqrt()).abs() < 1e-12);
        assert_eq!(
            image_error(&one, &one),
            ImageError {
                rmse: 0.0,
                max: 0.0
            }
        );
    }
}
