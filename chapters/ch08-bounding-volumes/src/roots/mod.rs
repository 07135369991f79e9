//! Part 1, slow primitives: polynomials and their roots (in closed form,
//! and bracketed), then the shapes that need them: the torus (a quartic
//! in t), a saddle (a cubic surface) and blobby objects.

// Polynomials, and their real roots.
mod polynomial;

mod closed_form;

mod bracketed;

// The torus and its quartic.
// Exercise 3: the torus quartic's coefficients.
#[cfg_attr(feature = "exercise", path = "../../exercise/torus_quartic.rs")]
mod torus_quartic;

mod torus;

// A cubic surface, and blobs.
mod saddle;

mod blobby;

pub use blobby::{Ball, Blobby, WYVILL};
pub use bracketed::roots_in;
pub use closed_form::{cubic_roots, quadratic_roots, quartic_roots};
pub use polynomial::{derivative, horner, multiply};
pub use saddle::{Saddle, saddle_cubic};
pub use torus::{Torus, TorusSolver};
pub use torus_quartic::torus_quartic;
