use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use crate::{BoundingSphere, Primitive, slab_test};

/// An axis-aligned box as a solid to render: the points with
/// `min ≤ p ≤ max` in every coordinate, hit by the slab test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisBox {
    min: DVec3,
    max: DVec3,
}

impl AxisBox {
    /// The box from corner `min` to corner `max`; refused unless both are
    /// finite and `min < max` on every axis (a flat box has no inside).
    pub fn new(min: DVec3, max: DVec3) -> Result<AxisBox, String> {
        if !min.is_finite() {
            return Err(format!("min: must be finite, got {min}"));
        }
        if !max.is_finite() {
            return Err(format!("max: must be finite, got {max}"));
        }
        if !min.cmplt(max).all() {
            return Err(format!(
                "max: must exceed min on every axis, got min {min}, max {max}"
            ));
        }
        Ok(AxisBox { min, max })
    }

    /// The corner with the smallest coordinates.
    pub fn min(&self) -> DVec3 {
        self.min
    }

    /// The corner with the largest coordinates.
    pub fn max(&self) -> DVec3 {
        self.max
    }

    // ANCHOR: intersect
    /// The first hit of `ray` with the box's surface in `interval`: where
    /// it enters, or where it leaves if it starts inside.
    pub fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        // Step 1: the slab test along the whole line: entry and exit.
        let b = Aabb::new(self.min, self.max);
        let span = slab_test(&b, ray, Interval::UNIVERSE)?;
        // Step 2: the first of the two in the interval.
        let entering = interval.contains(span.min);
        let t = if entering { span.min } else { span.max };
        if !interval.contains(t) || !t.is_finite() {
            return None;
        }
        // Step 3: the face: the slab that set t (see `face_crossed`).
        let (axis, plane) = self.face_crossed(ray, entering);
        // Step 4: the point, put exactly on that face (rounding moved it a
        // little off); the normal is the face's, pointing out.
        let mut point = ray.at(t).clamp(self.min, self.max);
        point[axis] = plane;
        let mut normal = DVec3::ZERO;
        normal[axis] = if plane == self.max[axis] { 1.0 } else { -1.0 };
        Some(Hit { t, point, normal })
    }
    // ANCHOR_END: intersect

    /// Which face the ray crosses at its entry (`entering`) or its exit:
    /// the axis whose slab it enters last, or leaves first, and that
    /// face's plane coordinate.
    fn face_crossed(&self, ray: &Ray, entering: bool) -> (usize, f64) {
        let mut best: Option<(usize, f64, f64)> = None; // (axis, plane, t)
        for axis in 0..3 {
            let inverse = 1.0 / ray.direction[axis];
            // the plane it enters through comes first along the ray
            let (near, far) = if inverse.is_sign_negative() {
                (self.max[axis], self.min[axis])
            } else {
                (self.min[axis], self.max[axis])
            };
            let plane = if entering { near } else { far };
            let t = (plane - ray.origin[axis]) * inverse;
            // a parallel ray never crosses this slab's planes: ±∞ or NaN
            if !t.is_finite() {
                continue;
            }
            let decides = match best {
                None => true,
                Some((_, _, old)) if entering => t > old,
                Some((_, _, old)) => t < old,
            };
            if decides {
                best = Some((axis, plane, t));
            }
        }
        best.map_or((0, self.min[0]), |(axis, plane, _)| (axis, plane))
    }
}

/// A box as an object of a scene: its hit, and itself as its bounds.
impl Shape for AxisBox {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        AxisBox::intersect(self, ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Aabb::new(self.min, self.max)
    }
}

/// Its bounding sphere is its circumsphere, through its corners.
impl Primitive for AxisBox {
    fn name(&self) -> &'static str {
        "box"
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::around_box(&self.bounds())
    }
}
