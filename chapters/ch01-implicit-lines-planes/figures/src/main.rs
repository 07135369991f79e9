//! Draws chapter 1's lecture figures: `cargo run -p ch01-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch01_figures::CHAPTER)
}
