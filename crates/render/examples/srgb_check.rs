//! Renders a test picture for checking the sRGB output by eye:
//! `cargo run -p raystep-render --example srgb_check -- out.png`
//!
//! * Top: a black/white checkerboard (half the light, on average) between
//!   two patches of linear 0.5. Seen from a distance the three should look
//!   the same grey, sRGB level 188. (A renderer that forgot the sRGB
//!   encoding would show level 128 there: visibly darker than the checks.)
//! * Middle: linear ramps of grey, red, green and blue.
//! * Bottom: a hue wheel on a dark blue background.

use std::f64::consts::TAU;

use raystep_render::{Progress, RenderOptions, Rgb, render};

/// A fully saturated colour of hue `h` (turns, 0..1), linear RGB.
fn hue(h: f64) -> Rgb {
    let channel =
        |offset: f64| (0.5 + 0.5 * (TAU * (h - offset)).cos()).powi(2);
    Rgb::new(channel(0.0), channel(1.0 / 3.0), channel(2.0 / 3.0))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "srgb_check.png".to_string());
    let (width, height) = (480, 360);
    let options = RenderOptions {
        threads: None,
        progress: Progress::Auto,
    };
    let image = render(width, height, &options, |x, y| {
        let u = f64::from(x) / f64::from(width - 1);
        match y {
            0..90 => {
                if (160..320).contains(&x) {
                    Rgb::splat(f64::from((x + y) % 2))
                } else {
                    Rgb::splat(0.5)
                }
            }
            90..130 => Rgb::splat(u),
            130..150 => Rgb::new(u, 0.0, 0.0),
            150..170 => Rgb::new(0.0, u, 0.0),
            170..190 => Rgb::new(0.0, 0.0, u),
            _ => {
                let (dx, dy) = (f64::from(x) - 240.0, f64::from(y) - 275.0);
                let r = (dx * dx + dy * dy).sqrt();
                if r < 80.0 {
                    let h = dy.atan2(dx) / TAU + 0.5;
                    hue(h) * (r / 80.0) + Rgb::splat(1.0 - r / 80.0)
                } else {
                    Rgb::new(0.01, 0.02, 0.08)
                }
            }
        }
    })?;
    image.write_png(&path)?;
    let srgb = image.to_srgb8();
    println!(
        "wrote {path}: linear 0.5 is sRGB level {} (expected 188)",
        srgb[3 * (10 * width as usize + 10)]
    );
    Ok(())
}
