//! Helpers for raystep's tests, shared by every chapter.
//!
//! Snapshots hold rounded numbers so that a correct student solution that
//! computes in another order (and so rounds differently in the last bits)
//! still matches the reference's snapshot. For the same reason rendered
//! images are compared with a [`Tolerance`] by [`assert_image_matches`].
//! [`held_out`] holds the protocol of `raystep grade`'s held-out cases, and
//! [`questions`] how it judges the paper questions, and
//! [`verdicts`] how `raystep check` reads what the tests printed into one
//! verdict per exercise.
#![deny(missing_docs)]

pub mod held_out;
mod image_compare;
mod plane_rays;
pub mod questions;
mod round;
mod seeded;
mod table;
pub mod verdicts;

pub use image_compare::{
    Tolerance, assert_image_matches, diff_dir, differing_pixels,
};
pub use plane_rays::ray_in_plane;
pub use round::{num, num_places, vec2, vec3};
pub use seeded::{seeded, unit_vector};
pub use table::Table;
