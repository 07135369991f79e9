//! Chapter 05's lecture figures.
use raystep_figure::Figure;

/// Every figure of chapter 05.
pub fn all() -> Vec<Figure> {
    Vec::new()
}
