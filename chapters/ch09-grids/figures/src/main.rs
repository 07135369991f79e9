//! Draws chapter 9's lecture figures: `cargo run -p ch09-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch09_figures::CHAPTER)
}
