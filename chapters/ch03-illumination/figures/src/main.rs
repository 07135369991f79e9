//! Draws chapter 3's lecture figures: `cargo run -p ch03-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch03_figures::CHAPTER)
}
