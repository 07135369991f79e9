//! Draws chapter 4's lecture figures: `cargo run -p ch04-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch04_figures::CHAPTER)
}
