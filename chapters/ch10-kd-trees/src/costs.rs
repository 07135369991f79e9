//! The kd-tree's cost model: what a split must save to be worth making.

/// The surface area heuristic's constants for a kd-tree: the cost of one
/// node step against one object test, and the bonus for cutting off
/// empty space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KdCosts {
    /// One traversal step (an interior node: one plane, one compare).
    pub traversal: f64,
    /// One ray–object test.
    pub intersection: f64,
    /// How much cheaper a split with an empty child counts (0 ≤ b < 1):
    /// a ray that finds an empty child skips it for free.
    pub empty_bonus: f64,
}

impl KdCosts {
    /// pbrt 3rd edition: traversal 1, intersection 80, bonus 0.5 (tuned
    /// for pbrt's own, costly, general shape tests).
    pub const PBRT_V3: KdCosts = KdCosts {
        traversal: 1.0,
        intersection: 80.0,
        empty_bonus: 0.5,
    };

    /// Wald and Havran 2006: traversal 15, intersection 20, bonus 0.8.
    pub const WALD_HAVRAN: KdCosts = KdCosts {
        traversal: 15.0,
        intersection: 20.0,
        empty_bonus: 0.8,
    };

    /// The constants this chapter builds with: Wald and Havran's. Measured
    /// on the bunnies and 10⁵ uniform triangles, both sets give trees
    /// whose rays visit the same nodes and test the same triangles within
    /// a few per cent; Wald and Havran's trees are smaller (fewer nodes
    /// and list entries), so they are the default.
    pub const CHOSEN: KdCosts = KdCosts::WALD_HAVRAN;

    /// `1/80/0.5`: the name tables show.
    pub fn name(&self) -> String {
        format!(
            "{}/{}/{}",
            self.traversal, self.intersection, self.empty_bonus
        )
    }
}

impl Default for KdCosts {
    /// [`KdCosts::CHOSEN`].
    fn default() -> KdCosts {
        KdCosts::CHOSEN
    }
}
