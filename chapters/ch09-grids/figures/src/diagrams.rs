//! Chapter 9's lecture figures.
use raystep_figure::Figure;

/// Every lecture figure of the chapter.
pub fn all() -> Vec<Figure> {
    vec![]
}
