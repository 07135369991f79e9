//! chapter placeholder
pub mod figures;
