//! The chapter's lecture figures, drawn from the reference code.
use raystep_figure::Figure;

/// Every figure of this chapter, in the order the lecture shows them.
pub fn all() -> Vec<Figure> {
    Vec::new()
}
