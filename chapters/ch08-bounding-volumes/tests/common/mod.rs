//! Test-only primitives: chapter 3's sphere and chapter 2's polygon seen
//! as [`Primitive`]s, so that the bounding-volume code can be tested
//! before (and independently of) the chapter's own primitives.
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
