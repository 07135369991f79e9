//! # Chapter 04 — shadows (work in progress)
pub mod figures;
