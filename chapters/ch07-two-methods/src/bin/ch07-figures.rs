//! Draws chapter 07's lecture figures: `cargo run -p ch07-two-methods --bin ch07-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main("ch07", ch07::figures::all)
}
