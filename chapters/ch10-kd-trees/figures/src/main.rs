//! Draws chapter 10's lecture figures: `cargo run -p ch10-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main(&ch10_figures::CHAPTER)
}
