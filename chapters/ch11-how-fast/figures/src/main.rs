//! Draws the appendix's figures: `cargo run -p ch11-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch11_figures::CHAPTER)
}
