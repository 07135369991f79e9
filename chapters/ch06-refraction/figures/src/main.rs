//! Draws chapter 6's lecture figures: `cargo run -p ch06-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch06_figures::CHAPTER)
}
