//! The kd-tree's cost model: what a split must save to be worth making,
//! and how deep a tree may go.

/// The deepest any tree goes, whatever the rule gives (the traversal's
/// stack holds one entry per level).
pub const MAX_DEPTH: usize = 60;

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
    /// The termination rule's depth: at most 8 + `depth_factor`·log₂ N
    /// levels for N objects ([`KdCosts::max_depth`]).
    pub depth_factor: f64,
}

/// The depth factor this chapter builds with: 8 + 2·log₂ N levels. pbrt's
/// 1.3 stops the 235 000-triangle bunny's tree at depth 31, before the
/// SAH is done: a camera ray then tests 10.6 triangles; with 2 it tests
/// 2.4 (`figures/ch10/kd-variants.csv`).
pub const DEPTH_FACTOR: f64 = 2.0;

impl KdCosts {
    /// pbrt 3rd edition: traversal 1, intersection 80, bonus 0.5 (tuned
    /// for pbrt's own, costly, general shape tests).
    /// Its depth rule, 8 + 1.3·log₂ N.
    pub const PBRT_V3: KdCosts = KdCosts {
        traversal: 1.0,
        intersection: 80.0,
        empty_bonus: 0.5,
        depth_factor: 1.3,
    };

    /// Wald and Havran's (2006) traversal and intersection costs, 15 and
    /// 20, and their 0.8 taken as the bonus b of this formula, (1 − b):
    /// an 80 % discount of the tests, where their own λ = 0.8 multiplies
    /// the whole cost, a 20 % discount. With this chapter's depth rule
    /// ([`DEPTH_FACTOR`]).
    pub const WALD_HAVRAN: KdCosts = KdCosts {
        traversal: 15.0,
        intersection: 20.0,
        empty_bonus: 0.8,
        depth_factor: DEPTH_FACTOR,
    };

    /// The constants this chapter builds with: [`KdCosts::WALD_HAVRAN`].
    /// Measured on both bunnies and 10⁴ small triangles, pbrt's constants
    /// (at the same depth rule) test about half as many triangles per
    /// ray but make trees 1.6–2.5 times as large, built 1.5–1.6 times as
    /// slowly, and trace 0.94–1.20 times as long
    /// (`figures/ch10/kd-variants.csv`).
    pub const CHOSEN: KdCosts = KdCosts::WALD_HAVRAN;

    /// `1/80/0.5, depth 8 + 1.3·log₂ N`: the name tables show.
    pub fn name(&self) -> String {
        format!(
            "{}/{}/{}, depth 8 + {}·log₂ N",
            self.traversal,
            self.intersection,
            self.empty_bonus,
            self.depth_factor
        )
    }

    /// The deepest a tree over `objects` objects may go:
    /// 8 + `depth_factor`·log₂ N, rounded, at most [`MAX_DEPTH`].
    pub fn max_depth(&self, objects: usize) -> usize {
        let n = objects.max(1) as f64;
        ((8.0 + self.depth_factor * n.log2()).round() as usize).min(MAX_DEPTH)
    }
}

impl Default for KdCosts {
    /// [`KdCosts::CHOSEN`].
    fn default() -> KdCosts {
        KdCosts::CHOSEN
    }
}
