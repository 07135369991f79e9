//! Helpers shared by the cross-chapter tests and the browser check.

pub mod rust_in_prose;
