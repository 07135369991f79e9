use crate::{Interval, Ray};
use glam::DVec3;

/// γ₃ = 3u / (1 − 3u), u = 2⁻⁵³: a bound on the relative rounding error
/// of three floating-point operations (pbrt-v4, section 6.8.1).
const GAMMA_3: f64 =
    3.0 * (f64::EPSILON / 2.0) / (1.0 - 3.0 * (f64::EPSILON / 2.0));

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

    // ANCHOR: hit
    /// The part of `interval` in which `ray` is inside the box, or None if
    /// the ray misses it there: the slab test, made robust.
    ///
    /// For each axis the ray is between the box's two planes (a *slab*)
    /// from `t_near` to `t_far`; inside the box means inside all three
    /// slabs at once. Two details make the test safe to rely on:
    ///
    /// * A ray parallel to an axis divides by zero: 1/0 = ±∞, and the slab
    ///   gives ±∞ or, for an origin exactly on a face, 0·∞ = NaN. Every
    ///   comparison with NaN is false, so a NaN bound never narrows the
    ///   interval: a ray lying in a face counts as inside that slab.
    /// * Rounding may put `t_far` a little before the true exit, and a
    ///   ray that grazes an edge would then miss a box it hits. Widening
    ///   `t_far` by `1 + 2γ₃` covers the error of the three operations
    ///   behind it (Ize, "Robust BVH Ray Traversal", 2013; pbrt-v4's
    ///   `Bounds3::IntersectP`), so the test never misses a box the ray
    ///   truly meets; at worst it reports a near miss as a hit.
    pub fn hit(&self, ray: &Ray, interval: Interval) -> Option<Interval> {
        if self.is_empty() {
            return None;
        }
        let (mut t0, mut t1) = (interval.min, interval.max);
        for axis in 0..3 {
            // Step 1: where the ray crosses the slab's two planes.
            let inverse = 1.0 / ray.direction[axis];
            let mut t_near = (self.min[axis] - ray.origin[axis]) * inverse;
            let mut t_far = (self.max[axis] - ray.origin[axis]) * inverse;
            // A ray going toward −axis enters through the max plane. The
            // sign bit decides, not t_near > t_far: that is false when one
            // of them is NaN, and a direction of −0 would then keep −∞ as
            // its exit.
            if inverse.is_sign_negative() {
                std::mem::swap(&mut t_near, &mut t_far);
            }
            // Step 2: the exit pushed out by the rounding error it can have.
            t_far *= 1.0 + 2.0 * GAMMA_3;
            // Step 3: narrow the interval (written so NaN leaves it alone).
            t0 = if t_near > t0 { t_near } else { t0 };
            t1 = if t_far < t1 { t_far } else { t1 };
            if t0 > t1 {
                return None;
            }
        }
        Some(Interval::new(t0, t1))
    }
    // ANCHOR_END: hit
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit() -> Aabb {
        Aabb::new(DVec3::ZERO, DVec3::ONE)
    }

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

    #[test]
    fn a_ray_through_the_box_gets_its_entry_and_exit() {
        let ray = Ray::new(DVec3::new(-1.0, 0.5, 0.5), DVec3::X);
        let inside = unit().hit(&ray, Interval::FORWARD).unwrap();
        assert_eq!(inside.min, 1.0);
        assert!((inside.max - 2.0).abs() < 1e-14 && inside.max >= 2.0);
        // the interval clips: a box behind the origin or beyond t_max is missed
        assert!(unit().hit(&ray, Interval::new(0.0, 0.5)).is_none());
        let back = Ray::new(DVec3::new(3.0, 0.5, 0.5), DVec3::X);
        assert!(unit().hit(&back, Interval::FORWARD).is_none());
        // from inside, the entry is the interval's own start
        let from_inside = Ray::new(DVec3::splat(0.5), DVec3::NEG_Y);
        assert_eq!(
            unit().hit(&from_inside, Interval::FORWARD).unwrap().min,
            0.0
        );
    }

    #[test]
    fn axis_parallel_rays_on_a_face_are_inside_not_nan() {
        // 0·∞ = NaN in the x slab: the ray lies in the face x = 0.
        for x in [0.0, 1.0] {
            let ray = Ray::new(DVec3::new(x, -1.0, 0.5), DVec3::Y);
            let inside =
                unit().hit(&ray, Interval::FORWARD).expect("in the face");
            assert!(!inside.min.is_nan() && !inside.max.is_nan());
            assert_eq!(inside.min, 1.0);
        }
        // just outside the face, parallel to it: a miss (±∞, no NaN)
        let outside = Ray::new(DVec3::new(-1e-300, -1.0, 0.5), DVec3::Y);
        assert!(unit().hit(&outside, Interval::FORWARD).is_none());
        // negative zero directions behave like positive ones
        let ray =
            Ray::new(DVec3::new(0.0, -1.0, 0.5), DVec3::new(-0.0, 1.0, 0.0));
        assert!(unit().hit(&ray, Interval::FORWARD).is_some());
    }

    #[test]
    fn empty_and_unbounded_boxes() {
        let ray =
            Ray::new(DVec3::new(0.3, 0.2, 0.1), DVec3::new(1.0, 2.0, 3.0));
        assert!(Aabb::EMPTY.hit(&ray, Interval::UNIVERSE).is_none());
        assert_eq!(
            Aabb::EVERYTHING.hit(&ray, Interval::FORWARD),
            Some(Interval::FORWARD)
        );
        let parallel = Ray::new(DVec3::ZERO, DVec3::X);
        assert!(Aabb::EVERYTHING.hit(&parallel, Interval::FORWARD).is_some());
    }

    /// Rays aimed at points of a box's faces, edges and corners, from far
    /// away, must hit it: the widened exit keeps a ray that only touches
    /// the box from being rounded out of it. Without the widening some of
    /// these rays miss.
    #[test]
    fn rays_aimed_at_the_boundary_never_miss() {
        let boxes = [
            Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0)),
            Aabb::new(
                DVec3::new(1e6, -3.0, 7.0),
                DVec3::new(1e6 + 0.1, 2.0, 7.3),
            ),
            Aabb::new(DVec3::splat(1e-7), DVec3::splat(3e-7)),
        ];
        let mut seed: u64 = 7;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut misses, mut naive_misses) = (0, 0);
        for b in boxes {
            let size = b.max - b.min;
            for k in 0..20_000 {
                // a point on the boundary: one, two or three coordinates
                // pinned to a face
                let mut target =
                    b.min + size * DVec3::new(next(), next(), next());
                for axis in 0..=(k % 3) {
                    let a = (k / 3 + axis) % 3;
                    target[a] = if next() < 0.5 { b.min[a] } else { b.max[a] };
                }
                let from = target
                    + DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5)
                        .normalize()
                        * 1e3
                        * size.max_element().max(1.0);
                let ray = Ray::new(from, target - from);
                misses += usize::from(b.hit(&ray, Interval::FORWARD).is_none());
                naive_misses += usize::from(!naive_hit(&b, &ray));
            }
        }
        assert_eq!(misses, 0);
        assert!(
            naive_misses > 0,
            "the test should catch the naive slab test"
        );
    }

    /// The slab test without the widened exit.
    fn naive_hit(b: &Aabb, ray: &Ray) -> bool {
        let (mut t0, mut t1) = (0.0f64, f64::INFINITY);
        for axis in 0..3 {
            let inverse = 1.0 / ray.direction[axis];
            let a = (b.min[axis] - ray.origin[axis]) * inverse;
            let c = (b.max[axis] - ray.origin[axis]) * inverse;
            t0 = t0.max(a.min(c));
            t1 = t1.min(a.max(c));
        }
        t0 <= t1
    }
}
