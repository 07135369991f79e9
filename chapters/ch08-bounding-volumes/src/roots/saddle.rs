//! The monkey saddle: a cubic surface, clipped to a box.
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use crate::{BoundingSphere, Primitive, roots_in};

/// The monkey saddle y = (x³ − 3xz²)/s² around `center`, clipped to
/// |x| ≤ s and |z| ≤ s, where |y| ≤ 2s: three valleys (for the legs)
/// and three ridges (for the tail) meet at the centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Saddle {
    center: DVec3,
    size: f64,
}

impl Saddle {
    /// The saddle around `center` with half-width `size` (s > 0); an
    /// error names a bad parameter.
    pub fn new(center: DVec3, size: f64) -> Result<Saddle, String> {
        if !center.is_finite() {
            return Err(format!("saddle: center {center} must be finite"));
        }
        if !(size > 0.0 && size.is_finite()) {
            return Err(format!(
                "saddle: size {size} must be a positive number"
            ));
        }
        Ok(Saddle { center, size })
    }

    /// Its centre.
    pub fn center(&self) -> DVec3 {
        self.center
    }

    /// s: the half-width of its square.
    pub fn size(&self) -> f64 {
        self.size
    }

    /// The box it is clipped to: |x|, |z| ≤ s, |y| ≤ 2s around the centre.
    pub fn clip_box(&self) -> Aabb {
        let half = DVec3::new(self.size, 2.0 * self.size, self.size);
        Aabb::new(self.center - half, self.center + half)
    }

    /// The unit normal at a point of the surface, on the side of +y.
    pub fn normal_at(&self, point: DVec3) -> DVec3 {
        saddle_normal(self.size, point - self.center)
    }
}

// ANCHOR: saddle_cubic
/// The cubic g(t) = x³ − 3xz² − s²y along `ray` (lowest degree first),
/// in the saddle's frame (centre at the origin): x = oₓ + t·dₓ, and so on.
pub fn saddle_cubic(size: f64, ray: &Ray) -> [f64; 4] {
    let (o, d, ss) = (ray.origin, ray.direction, size * size);
    // Step 1: x³, a cube of (oₓ + t·dₓ).
    let x3 = [o.x.powi(3), 3.0 * o.x * o.x * d.x, 3.0 * o.x * d.x * d.x];
    // Step 2: x·z², (oₓ + t·dₓ)(o_z + t·d_z)².
    let xz2 = [
        o.x * o.z * o.z,
        2.0 * o.x * o.z * d.z + d.x * o.z * o.z,
        o.x * d.z * d.z + 2.0 * d.x * o.z * d.z,
    ];
    // Step 3: g = x³ − 3xz² − s²y, term by term.
    [
        x3[0] - 3.0 * xz2[0] - ss * o.y,
        x3[1] - 3.0 * xz2[1] - ss * d.y,
        x3[2] - 3.0 * xz2[2],
        d.x.powi(3) - 3.0 * d.x * d.z * d.z,
    ]
}
// ANCHOR_END: saddle_cubic

// ANCHOR: saddle_normal
/// The unit normal at `p` (saddle frame): the graph y = h(x, z) has the
/// normal (−∂h/∂x, 1, −∂h/∂z), with ∂h/∂x = 3(x² − z²)/s² and
/// ∂h/∂z = −6xz/s². Its y part is 1: it never vanishes, so never NaN.
fn saddle_normal(size: f64, p: DVec3) -> DVec3 {
    let ss = size * size;
    let n = DVec3::new(-3.0 * (p.x * p.x - p.z * p.z), ss, 6.0 * p.x * p.z);
    n.try_normalize().unwrap_or(DVec3::Y)
}
// ANCHOR_END: saddle_normal

// ANCHOR: saddle_roots
/// The roots of the cubic in `interval` whose points lie in the clip
/// square, sorted: the bracketed method from the clip box's entry, on
/// the line's whole stretch through the box, then cut to `interval`.
fn saddle_roots(
    size: f64, ray: &Ray, center: DVec3, interval: Interval,
) -> Vec<f64> {
    // Step 1: clip the ray to the box, grown by 1% of s so that no root
    // sits on an end of the interval (where p ≈ 0 has no reliable sign).
    let half = 1.01 * DVec3::new(size, 2.0 * size, size);
    // (The whole line's stretch, not the interval's, so that the roots
    // do not depend on where the interval starts; see the torus.)
    let Some(inside) = crate::slab_test(
        &Aabb::new(-half, half),
        &Ray::new(ray.origin - center, ray.direction),
        Interval::UNIVERSE,
    ) else {
        return Vec::new();
    };
    if !(inside.min.is_finite() && inside.max.is_finite()) {
        return Vec::new();
    }
    // Step 2: the cubic from the entry point, in the saddle's frame.
    let entry = Ray::new(ray.at(inside.min) - center, ray.direction);
    let cubic = saddle_cubic(size, &entry);
    // Step 3: its roots in the box, kept where the point is in the
    // square |x|, |z| ≤ s, and shifted back to the ray's t.
    roots_in(&cubic, 0.0, inside.size())
        .into_iter()
        .filter(|&s| {
            let p = entry.at(s);
            p.x.abs() <= size && p.z.abs() <= size
        })
        .map(|s| inside.min + s)
        .filter(|&t| interval.contains(t))
        .collect()
}
// ANCHOR_END: saddle_roots

/// The saddle as an object of a scene: the first root of its cubic in
/// the clip square.
impl Shape for Saddle {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        let t = saddle_roots(self.size, ray, self.center, interval)
            .into_iter()
            .next()?;
        let point = ray.at(t);
        let normal = saddle_normal(self.size, point - self.center);
        Some(Hit { t, point, normal })
    }

    fn bounds(&self) -> Aabb {
        self.clip_box()
    }
}

impl Primitive for Saddle {
    fn name(&self) -> &'static str {
        "saddle"
    }

    /// The clip box's circumsphere: radius √6·s.
    fn bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere::around_box(&self.clip_box())
    }
}
