use glam::DVec3;

/// A ray: the half-line `P(t) = origin + t·direction` for `t ≥ 0`.
///
/// The direction is not normalised for you. Chapters that want `t` to be a
/// distance build rays with a unit direction (the camera does).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts: the lecture's P₀.
    pub origin: DVec3,
    /// Which way it goes: the lecture's D.
    pub direction: DVec3,
}

impl Ray {
    /// A ray from `origin` along `direction`.
    pub const fn new(origin: DVec3, direction: DVec3) -> Ray {
        Ray { origin, direction }
    }

    /// The point at parameter `t`: `P₀ + t·D`.
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + t * self.direction
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at_walks_along_the_direction() {
        let ray =
            Ray::new(DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.0, 0.0, -2.0));
        assert_eq!(ray.at(0.0), ray.origin);
        assert_eq!(ray.at(1.5), DVec3::new(1.0, 2.0, 0.0));
    }
}
