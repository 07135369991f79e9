//! What the chapter's test files (and its held-out cases,
//! `examples/ch08_held_out.rs`, and the figures crate's tightness tests)
//! share: seeded random numbers (raystep-check's SplitMix64, and unit
//! vectors drawn from it), the Stanford bunny, a test-only primitive
//! (chapter 2's polygon in a sphere of its own, so that the
//! bounding-volume code can be tested independently of the chapter's own
//! bounding spheres), a measured fraction judged against its probability,
//! and the plain answers the exercises are judged against.
#![allow(dead_code)]
use std::path::PathBuf;

use ch02::Polygon;
use ch08::{Aabb, BoundingSphere, DVec3, Hit, Interval, Primitive, Ray, Shape};
pub use raystep_check::held_out::Rng;
use raystep_scene::Mesh;

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

/// A unit vector, by rejection from the cube [−1, 1]³, normalised as glam
/// does (the draws every test of the chapter has always made).
pub fn unit_vector(rng: &mut Rng) -> DVec3 {
    loop {
        let v = rng.vec3(1.0);
        if (0.01..=1.0).contains(&v.length_squared()) {
            return v.normalize();
        }
    }
}

/// `measured` within 4 standard deviations of `p`, for a fraction of `n`
/// independent trials (a deterministic test: the seed is fixed, and the
/// 4σ leave room for another seed or ray order).
pub fn assert_near(what: &str, measured: f64, p: f64, n: u64) {
    let sigma = (p * (1.0 - p) / n as f64).sqrt();
    assert!(
        (measured - p).abs() <= 4.0 * sigma.max(1e-4),
        "{what}: expected {p:.4} ± {:.4} (4σ of {n} trials), measured \
         {measured:.4}",
        4.0 * sigma
    );
}

/// The Stanford bunny beside the workspace: `../shared/meshes/bunny.obj`
/// from the workspace root (this crate is two folders below it).
pub fn bunny() -> Mesh {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/meshes/bunny.obj");
    assert!(
        path.exists(),
        "the Stanford bunny is missing: expected {} (the folder shared/ \
         beside the workspace, see shared/meshes/README.md)",
        path.display()
    );
    Mesh::load_obj(&path).expect("bunny.obj should be a valid OBJ file")
}

/// The bunny's triangles, by their corners.
pub fn bunny_triangles() -> Vec<[DVec3; 3]> {
    let mesh = bunny();
    (0..mesh.triangles.len())
        .map(|k| mesh.triangle(k))
        .collect()
}

/// The slab test as it is often written: each slab's two crossings
/// ordered by min/max, no widened exit, no care for NaN. What the robust
/// test (exercise 1) is compared with, and a check independent of it.
pub fn plain_slab(b: &Aabb, ray: &Ray, interval: Interval) -> Option<Interval> {
    let (mut t0, mut t1) = (interval.min, interval.max);
    for axis in 0..3 {
        let inverse = 1.0 / ray.direction[axis];
        let a = (b.min[axis] - ray.origin[axis]) * inverse;
        let c = (b.max[axis] - ray.origin[axis]) * inverse;
        t0 = t0.max(a.min(c));
        t1 = t1.min(a.max(c));
    }
    (t0 <= t1).then_some(Interval::new(t0, t1))
}

/// Half the largest distance between two points: no sphere around them is
/// smaller (it must hold the two farthest apart), and the smallest is at
/// most √(3/2) times larger (Jung's theorem).
pub fn half_diameter(points: &[DVec3]) -> f64 {
    let mut largest: f64 = 0.0;
    for (i, &a) in points.iter().enumerate() {
        for &b in &points[i + 1..] {
            largest = largest.max(a.distance_squared(b));
        }
    }
    0.5 * largest.sqrt()
}
