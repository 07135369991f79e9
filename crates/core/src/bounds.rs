use glam::DVec3;

/// An axis-aligned bounding box: the points with `min ≤ p ≤ max` in every
/// coordinate.
///
/// Every shape answers [`Shape::bounds`](crate::Shape::bounds) with one,
/// and the speed-up chapters test a ray against boxes before they test it
/// against what is inside. A box is *empty* when `min > max` on some axis
/// ([`Aabb::EMPTY`]); an unbounded shape (a plane) has [`Aabb::EVERYTHING`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest coordinates.
    pub min: DVec3,
    /// The corner with the largest coordinates.
    pub max: DVec3,
}

impl Aabb {
    /// Contains nothing; the union with any box is that box.
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::INFINITY,
        max: DVec3::NEG_INFINITY,
    };
    /// Contains every point: the bounds of an unbounded shape.
    pub const EVERYTHING: Aabb = Aabb {
        min: DVec3::NEG_INFINITY,
        max: DVec3::INFINITY,
    };

    /// The box with corners `a` and `b`, in any order.
    pub fn new(a: DVec3, b: DVec3) -> Aabb {
        Aabb {
            min: a.min(b),
            max: a.max(b),
        }
    }

    /// The smallest box around `points` (empty if there are none).
    pub fn around(points: impl IntoIterator<Item = DVec3>) -> Aabb {
        points.into_iter().fold(Aabb::EMPTY, Aabb::grow)
    }

    /// The box grown to contain `p`.
    pub fn grow(self, p: DVec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The smallest box around both.
    pub fn union(self, other: Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Does it contain no point?
    pub fn is_empty(&self) -> bool {
        !(self.min.cmple(self.max).all())
    }

    /// The surface area (0 for an empty or flat box, infinite for an
    /// unbounded one): the surface area heuristic weighs a box by it.
    pub fn surface_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.max - self.min;
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// Is `p` inside or on the boundary?
    pub fn contains(&self, p: DVec3) -> bool {
        self.min.cmple(p).all() && p.cmple(self.max).all()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn around_union_and_contains() {
        let b = Aabb::around([
            DVec3::new(1.0, -2.0, 3.0),
            DVec3::new(-1.0, 2.0, 0.0),
        ]);
        assert_eq!(b.min, DVec3::new(-1.0, -2.0, 0.0));
        assert_eq!(b.max, DVec3::new(1.0, 2.0, 3.0));
        assert!(b.contains(DVec3::ZERO) && !b.contains(DVec3::splat(5.0)));
        assert!(Aabb::EMPTY.is_empty() && Aabb::around([]).is_empty());
        assert_eq!(Aabb::EMPTY.union(b), b);
        assert!(!Aabb::EVERYTHING.is_empty());
        assert!(
            Aabb::new(DVec3::ZERO, DVec3::new(0.0, 1.0, 1.0))
                .contains(DVec3::Y)
        );
    }

    #[test]
    fn surface_area() {
        let b = Aabb::new(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(b.surface_area(), 22.0);
        assert_eq!(Aabb::new(DVec3::ZERO, DVec3::X).surface_area(), 0.0);
        assert_eq!(Aabb::EMPTY.surface_area(), 0.0);
        assert_eq!(Aabb::EVERYTHING.surface_area(), f64::INFINITY);
    }
}
