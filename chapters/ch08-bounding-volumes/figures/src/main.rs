//! Draws chapter 8's lecture figures: `cargo run -p ch08-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch08_figures::CHAPTER)
}
