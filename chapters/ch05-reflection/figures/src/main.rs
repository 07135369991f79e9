//! Draws chapter 5's lecture figures: `cargo run -p ch05-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch05_figures::CHAPTER)
}
