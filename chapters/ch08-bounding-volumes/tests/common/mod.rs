//! What the chapter's test files share: seeded random numbers, and
//! test-only primitives (chapter 3's sphere and chapter 2's polygon seen
//! as [`Primitive`]s, so that the bounding-volume code can be tested
//! independently of the chapter's own primitives).
#![allow(dead_code)]
use ch02::Polygon;
use ch03::Sphere;
use ch08::{Aabb, BoundingSphere, DVec3, Hit, Interval, Primitive, Ray, Shape};

/// Chapter 3's sphere, its own bounding sphere.
#[derive(Debug)]
pub struct TestSphere(pub Sphere);

impl Shape for TestSphere {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        self.0.intersect(ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Shape::bounds(&self.0)
    }
}

impl Primitive for TestSphere {
    fn name(&self) -> &'static str {
        "sphere"
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        BoundingSphere {
            center: self.0.center,
            radius: self.0.radius,
        }
    }
}

/// Chapter 2's polygon in the sphere around its vertices' centroid,
/// through the farthest vertex (the smallest sphere for an equilateral
/// triangle).
#[derive(Debug)]
pub struct TestPolygon(pub Polygon);

impl TestPolygon {
    /// The polygon with these corners.
    pub fn new(corners: &[DVec3]) -> TestPolygon {
        TestPolygon(Polygon::new(corners.to_vec()).expect("a valid polygon"))
    }
}

impl Shape for TestPolygon {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        self.0.intersect(ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Shape::bounds(&self.0)
    }
}

impl Primitive for TestPolygon {
    fn name(&self) -> &'static str {
        "polygon"
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        let vertices = self.0.vertices();
        let center = vertices.iter().sum::<DVec3>() / vertices.len() as f64;
        let radius = vertices
            .iter()
            .map(|v| v.distance(center))
            .fold(0.0, f64::max);
        BoundingSphere { center, radius }
    }
}

/// An equilateral triangle of side `side` in the plane z = 0, one side
/// along x, centred on the origin.
pub fn equilateral(side: f64) -> [DVec3; 3] {
    let h = side * 3f64.sqrt() / 2.0;
    [
        DVec3::new(-side / 2.0, -h / 3.0, 0.0),
        DVec3::new(side / 2.0, -h / 3.0, 0.0),
        DVec3::new(0.0, 2.0 * h / 3.0, 0.0),
    ]
}

/// SplitMix64: deterministic random numbers, the same on every machine.
pub struct Rng(pub u64);

impl Rng {
    /// A number in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A number in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    /// A unit vector, by rejection from the cube.
    pub fn unit_vector(&mut self) -> DVec3 {
        loop {
            let v = DVec3::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            if (0.01..=1.0).contains(&v.length_squared()) {
                return v.normalize();
            }
        }
    }
}
