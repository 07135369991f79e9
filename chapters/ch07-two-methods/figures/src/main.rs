//! Draws chapter 7's lecture figures: `cargo run -p ch07-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch07_figures::CHAPTER)
}
