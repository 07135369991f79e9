//! What the structures' dangerous rays are made of: a set of rays per
//! kind, drawn one kind after the other from one seeded generator, and
//! the points and directions the kinds share (a point inside a box, a
//! ray from far outside aimed at a point, an axis direction with a
//! signed zero).
use ch08::SplitMix64;
use raystep_core::{Aabb, DVec3, Ray};

/// One kind of dangerous ray, and a set of them.
#[derive(Clone, Debug)]
pub struct RayCase {
    /// What makes these rays dangerous, for tables.
    pub name: &'static str,
    /// The rays.
    pub rays: Vec<Ray>,
}

/// Makes the kinds one after the other, `per_case` rays each, from one
/// generator: every run asks the same rays.
pub(crate) struct Cases {
    random: SplitMix64,
    per_case: usize,
}

impl Cases {
    /// A maker of `per_case` rays a kind, seeded `seed`.
    pub fn new(per_case: usize, seed: u64) -> Cases {
        Cases {
            random: SplitMix64::new(seed),
            per_case,
        }
    }

    /// The kind `name`: `make` called for each of its rays.
    pub fn case(
        &mut self, name: &'static str,
        mut make: impl FnMut(&mut SplitMix64) -> Ray,
    ) -> RayCase {
        RayCase {
            name,
            rays: (0..self.per_case).map(|_| make(&mut self.random)).collect(),
        }
    }
}

/// The box the rays are made around: its centre, and how far outside
/// it a ray from far away starts.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Around {
    /// The box.
    pub bounds: Aabb,
    /// Its centre.
    pub centre: DVec3,
    /// Twice its diagonal (at least 1e-300).
    pub far: f64,
}

impl Around {
    /// The rays' frame for box `b`.
    pub fn new(b: Aabb) -> Around {
        Around {
            bounds: b,
            centre: 0.5 * (b.min + b.max),
            far: 2.0 * (b.max - b.min).length().max(1e-300),
        }
    }

    /// A point far outside the box, in a random direction.
    pub fn far_point(&self, r: &mut SplitMix64) -> DVec3 {
        self.centre + self.far * r.unit_vector()
    }

    /// A ray from far outside at `target`.
    pub fn aimed(&self, r: &mut SplitMix64, target: DVec3) -> Ray {
        let origin = self.far_point(r);
        Ray::new(origin, target - origin)
    }
}

/// A point inside `b`, uniform at random.
pub(crate) fn inside(r: &mut SplitMix64, b: &Aabb) -> DVec3 {
    b.min
        + DVec3::new(r.next_f64(), r.next_f64(), r.next_f64()) * (b.max - b.min)
}

/// ±1 along `axis`, ±0 along the others: the sign of the zeros, then
/// the direction, at random.
pub(crate) fn signed_unit(r: &mut SplitMix64, axis: usize) -> DVec3 {
    let zero = if r.next_u64().is_multiple_of(2) {
        0.0
    } else {
        -0.0
    };
    let mut d = DVec3::splat(zero);
    d[axis] = if r.next_u64().is_multiple_of(2) {
        1.0
    } else {
        -1.0
    };
    d
}
