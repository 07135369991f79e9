//! Colours: linear RGB while computing, 8-bit sRGB when stored.
//!
//! Light adds and scales linearly, so every renderer computes in linear RGB
//! (`0.0` black, `1.0` the brightest a pixel shows; larger values are
//! allowed while computing and clip when stored). A screen and a PNG file
//! expect sRGB, a non-linear encoding that spends more of its 256 levels on
//! dark tones: linear `0.5` (half the light) is stored as level 188, not 128.

use raystep_core::DVec3;

/// A linear-RGB colour: `x` red, `y` green, `z` blue, `0.0..=1.0` on screen.
pub type Rgb = DVec3;

/// The sRGB transfer function (IEC 61966-2-1): a linear intensity in
/// `[0, 1]` to its sRGB-encoded value in `[0, 1]`.
///
/// Values outside `[0, 1]` are clamped first, and NaN gives `0.0`, so a
/// stray NaN from a degenerate computation shows as a black pixel.
pub fn linear_to_srgb(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        0.0
    } else if x >= 1.0 {
        1.0
    } else if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// The inverse of [`linear_to_srgb`]: an sRGB-encoded value in `[0, 1]` to
/// its linear intensity (clamped to `[0, 1]`; NaN gives `0.0`).
pub fn srgb_to_linear(v: f64) -> f64 {
    if v.is_nan() || v <= 0.0 {
        0.0
    } else if v >= 1.0 {
        1.0
    } else if v <= 0.040_45 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// A linear colour as 8-bit sRGB `[r, g, b]`: each channel encoded by
/// [`linear_to_srgb`], scaled to `0..=255` and rounded to the nearest level.
pub fn srgb8(c: Rgb) -> [u8; 3] {
    // The encoded value is in [0, 1], so the cast cannot saturate.
    let level = |x: f64| (linear_to_srgb(x) * 255.0).round() as u8;
    [level(c.x), level(c.y), level(c.z)]
}

/// An 8-bit sRGB colour back to linear RGB: the inverse of [`srgb8`], exact
/// for every level (`srgb8(linear_from_srgb8(c)) == c`).
pub fn linear_from_srgb8(c: [u8; 3]) -> Rgb {
    let linear = |level: u8| srgb_to_linear(f64::from(level) / 255.0);
    Rgb::new(linear(c[0]), linear(c[1]), linear(c[2]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_8_bit_level_survives_a_round_trip_through_linear() {
        for v in 0..=255u8 {
            let c = [v, 255 - v, v / 2];
            assert_eq!(srgb8(linear_from_srgb8(c)), c, "level {v}");
        }
    }

    #[test]
    fn transfer_function_landmarks() {
        assert_eq!(srgb8(Rgb::splat(0.5)), [188; 3]);
        assert_eq!(srgb8(Rgb::new(0.0, 1.0, 0.2159)), [0, 255, 128]);
        assert!((linear_from_srgb8([128; 3]).x - 0.215_861).abs() < 1e-6);
        // clamped, NaN black
        assert_eq!(srgb8(Rgb::new(-1.0, 7.0, f64::NAN)), [0, 255, 0]);
        assert_eq!(linear_to_srgb(f64::INFINITY), 1.0);
        assert_eq!(linear_to_srgb(f64::NEG_INFINITY), 0.0);
        // the two pieces meet: continuous at the break point
        let b: f64 = 0.003_130_8;
        assert!((12.92 * b - (1.055 * b.powf(1.0 / 2.4) - 0.055)).abs() < 1e-7);
        for i in 0..=100 {
            let x = f64::from(i) / 100.0;
            assert!((srgb_to_linear(linear_to_srgb(x)) - x).abs() < 1e-12);
        }
    }
}
