//! Draws chapter 04's lecture figures: `cargo run -p ch04-shadows --bin ch04-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main("ch04", ch04::figures::all)
}
