/// A closed range of ray parameters `[min, max]`.
///
/// Every intersection query takes one: a hit counts only if its `t` lies in
/// it. Primary rays use `[0, ∞]`; shadow rays stop short of the light;
/// the closest-hit loop shrinks `max` to the best `t` so far.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The smallest accepted value.
    pub min: f64,
    /// The largest accepted value.
    pub max: f64,
}

impl Interval {
    /// Contains nothing: `min > max`.
    pub const EMPTY: Interval = Interval {
        min: f64::INFINITY,
        max: f64::NEG_INFINITY,
    };
    /// Contains every number.
    pub const UNIVERSE: Interval = Interval {
        min: f64::NEG_INFINITY,
        max: f64::INFINITY,
    };
    /// In front of the ray's origin: `[0, ∞]`.
    pub const FORWARD: Interval = Interval {
        min: 0.0,
        max: f64::INFINITY,
    };

    /// The interval `[min, max]`.
    pub const fn new(min: f64, max: f64) -> Interval {
        Interval { min, max }
    }

    /// `max - min` (negative for an empty interval).
    pub fn size(&self) -> f64 {
        self.max - self.min
    }

    /// Is `min ≤ x ≤ max`? (NaN is never contained.)
    pub fn contains(&self, x: f64) -> bool {
        self.min <= x && x <= self.max
    }

    /// Is `min < x < max`, strictly inside?
    pub fn surrounds(&self, x: f64) -> bool {
        self.min < x && x < self.max
    }

    /// Does it contain nothing?
    pub fn is_empty(&self) -> bool {
        self.min.is_nan() || self.max.is_nan() || self.min > self.max
    }

    /// The same interval with `max` lowered to `t` (the closest-hit loop).
    pub fn with_max(self, t: f64) -> Interval {
        Interval { max: t, ..self }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contains_is_closed_and_surrounds_is_open() {
        let i = Interval::new(0.0, 1.0);
        assert!(i.contains(0.0) && i.contains(1.0) && i.contains(0.5));
        assert!(!i.surrounds(0.0) && !i.surrounds(1.0) && i.surrounds(0.5));
        assert!(!i.contains(f64::NAN) && !i.surrounds(f64::NAN));
    }

    #[test]
    fn empty_and_universe() {
        assert!(Interval::EMPTY.is_empty());
        assert!(!Interval::EMPTY.contains(0.0));
        assert!(
            Interval::UNIVERSE.contains(-1e300)
                && Interval::UNIVERSE.contains(f64::INFINITY)
        );
        assert!(!Interval::FORWARD.contains(-1e-300));
        assert_eq!(Interval::FORWARD.with_max(2.0), Interval::new(0.0, 2.0));
    }
}
