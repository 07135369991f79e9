//! Draws chapter 2's lecture figures: `cargo run -p ch02-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch02_figures::CHAPTER)
}
