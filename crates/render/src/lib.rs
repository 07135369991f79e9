//! What every raystep renderer shares: a linear-RGB image, written as an
//! sRGB PNG, and a deterministic parallel pixel loop.
//!
//! * [`Rgb`] and [`color`] functions: colours are linear RGB (light adds up
//!   linearly there); they become 8-bit sRGB only when an image is stored.
//! * [`Image`]: a `width × height` grid of [`Rgb`], row-major from the top,
//!   with PNG reading and writing and a small text rendering for snapshots.
//! * [`render`]: calls a pixel function for every pixel, rows in parallel,
//!   with an optional progress bar; the result does not depend on the
//!   number of threads.
//! * [`timing::Timing`]: how the charts' render times are measured.
//! * [`RenderError`]: everything that can go wrong, with messages that name
//!   the path or argument at fault.
//!
//! ```
//! use raystep_render::{render, Progress, RenderOptions, Rgb};
//!
//! let options = RenderOptions { threads: Some(2), progress: Progress::Never };
//! let image = render(4, 3, &options, |x, y| Rgb::new(x as f64 / 3.0, y as f64 / 2.0, 0.5))?;
//! assert_eq!(image.get(3, 0), Rgb::new(1.0, 0.0, 0.5));
//! # Ok::<(), raystep_render::RenderError>(())
//! ```
#![deny(missing_docs)]

pub mod color;
pub mod csv;
mod error;
mod image;
mod image_error;
mod parallel;
pub mod timing;

pub use self::image::Image;
pub use color::{
    Rgb, linear_from_srgb8, linear_to_srgb, srgb_to_linear, srgb8,
};
pub use error::RenderError;
pub use image_error::{ImageError, image_error};
pub use parallel::{Progress, RenderOptions, render, stage};
