//! How many cells: the resolution rule, stated so it can be charted.
use raystep_core::Aabb;

/// The rule's factor: `RULE_FACTOR · ∛N` cells along the longest axis
/// for `N` objects (pbrt's uniform grid, 1st and 2nd editions). About
/// `RULE_FACTOR³ = 27` cells per object in a cube-shaped scene: with
/// small objects spread evenly, each cell then holds a few of them.
pub const RULE_FACTOR: f64 = 3.0;

/// The most cells along one axis (pbrt stops at 64; 512 lets the rule
/// serve a quarter-million triangles, and caps a grid at 2²⁷ cells).
pub const MAX_CELLS: usize = 512;

/// How a grid chooses its cells.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Resolution {
    /// The rule: `RULE_FACTOR · ∛N` along the longest axis.
    Rule,
    /// This many cells along the longest axis, the others in proportion.
    Longest(usize),
    /// Exactly these cells along x, y and z.
    Cells([usize; 3]),
}

impl Resolution {
    /// The cells along x, y and z for `objects` objects in `bounds`.
    pub fn cells(self, bounds: &Aabb, objects: usize) -> [usize; 3] {
        match self {
            Resolution::Rule => cells_for(bounds, rule_cells(objects)),
            Resolution::Longest(n) => cells_for(bounds, n),
            Resolution::Cells(cells) => cells.map(|n| n.clamp(1, MAX_CELLS)),
        }
    }
}

// ANCHOR: rule
/// The rule's cells along the longest axis for `objects` objects:
/// `RULE_FACTOR · ∛N`, rounded, from 1 to [`MAX_CELLS`].
pub fn rule_cells(objects: usize) -> usize {
    let n = RULE_FACTOR * (objects as f64).cbrt();
    (n.round() as usize).clamp(1, MAX_CELLS)
}

/// `longest` cells along the box's longest axis, and along the others as
/// many cells of about the same width (at least 1): cells close to cubes.
pub fn cells_for(bounds: &Aabb, longest: usize) -> [usize; 3] {
    let extent = bounds.max - bounds.min;
    let widest = extent.max_element();
    if widest.is_nan() || widest <= 0.0 || widest.is_infinite() {
        return [1, 1, 1];
    }
    let per_unit = longest.clamp(1, MAX_CELLS) as f64 / widest;
    extent
        .to_array()
        .map(|e| ((e * per_unit).round() as usize).clamp(1, MAX_CELLS))
}
// ANCHOR_END: rule

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_core::DVec3;

    #[test]
    fn the_rule_grows_as_the_cube_root() {
        assert_eq!(rule_cells(0), 1);
        assert_eq!(rule_cells(1), 3);
        assert_eq!(rule_cells(1000), 30);
        assert_eq!(rule_cells(3674), 46);
        assert_eq!(rule_cells(usize::MAX), MAX_CELLS);
    }

    #[test]
    fn cells_are_close_to_cubes() {
        let b = Aabb::new(DVec3::ZERO, DVec3::new(10.0, 5.0, 0.0));
        assert_eq!(cells_for(&b, 20), [20, 10, 1]);
        let point = Aabb::new(DVec3::ONE, DVec3::ONE);
        assert_eq!(cells_for(&point, 20), [1, 1, 1]);
    }
}
