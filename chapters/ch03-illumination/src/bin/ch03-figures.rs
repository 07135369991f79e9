//! Draws chapter 03's lecture figures: `cargo run -p ch03-illumination --bin ch03-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main("ch03", ch03::figures::all)
}
