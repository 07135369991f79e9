//! Draws chapter 02's lecture figures: `cargo run -p ch02-plane-polygon-hits --bin ch02-figures -- --out DIR`.
fn main() -> std::process::ExitCode {
    raystep_figure::diagram_main("ch02", ch02::figures::all)
}
