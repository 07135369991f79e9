//! Chapter 06's lecture figures.
use raystep_figure::Figure;

/// Every figure of chapter 06.
pub fn all() -> Vec<Figure> {
    Vec::new()
}
