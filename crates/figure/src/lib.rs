//! The raystep figure kit (placeholder until the kit lands).
/// A named lecture figure.
pub struct Figure {
    /// File stem.
    pub name: String,
}
/// Entry point of a chapter's diagram binary.
pub fn diagram_main(_chapter: &str, _figures: fn() -> Vec<Figure>) -> std::process::ExitCode {
    std::process::ExitCode::SUCCESS
}
