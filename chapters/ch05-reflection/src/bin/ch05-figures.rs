//! Draws chapter 05's lecture figures: `cargo run -p ch05-reflection --bin ch05-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main("ch05", ch05::figures::all)
}
