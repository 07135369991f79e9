//! The peers: other Rust BVH libraries, built on the same triangles and
//! handed the same watertight triangle test, so that only the hierarchy
//! and its walk differ. Their own box tests decide what they visit.
use std::time::{Duration, Instant};

use ch08::{Closest, PreparedRay};
use raystep_core::{DVec3, Interval, Ray32};
use raystep_world::{MeshAccelerator, MeshHit, TraceCounts};

use crate::built::Built;

/// obvhs's `Bvh2` over `triangles` (its `medium_build` preset), timed
/// from our triangles to a tracer.
pub fn obvhs_bvh2(triangles: &[[DVec3; 3]]) -> Built {
    timed(|| {
        let (tris, params, mut core) = obvhs_input(triangles);
        let bvh = obvhs::bvh2::builder::build_bvh2_from_tris(
            &tris, params, &mut core,
        );
        Box::new(Obvhs2(bvh, triangles.to_vec()))
    })
}

/// obvhs's compressed 8-wide `CwBvh` (the same preset), timed.
pub fn obvhs_cwbvh(triangles: &[[DVec3; 3]]) -> Built {
    timed(|| {
        let (tris, params, mut core) = obvhs_input(triangles);
        let bvh = obvhs::cwbvh::builder::build_cwbvh_from_tris(
            &tris, params, &mut core,
        );
        Box::new(ObvhsCw(bvh, triangles.to_vec()))
    })
}

/// The `bvh` crate's binned-SAH hierarchy, timed.
pub fn bvh_crate(triangles: &[[DVec3; 3]]) -> Built {
    timed(|| {
        let mut shapes: Vec<Shape> = triangles
            .iter()
            .enumerate()
            .map(|(k, v)| Shape::new(k as u32, v))
            .collect();
        let bvh = bvh::bvh::Bvh::build(&mut shapes);
        Box::new(BvhCrate(bvh, shapes, triangles.to_vec()))
    })
}

/// A peer built by `build`, its time from our triangles to a tracer.
fn timed(build: impl FnOnce() -> Box<dyn MeshAccelerator>) -> Built {
    let start = Instant::now();
    let tracer = build();
    Built {
        tracer,
        build_ms: start.elapsed().as_secs_f64() * 1e3,
        bytes: None,
        tree: None,
    }
}

/// obvhs's triangles, its build preset, and its build-time counter.
fn obvhs_input(
    triangles: &[[DVec3; 3]],
) -> (
    Vec<obvhs::triangle::Triangle>,
    obvhs::BvhBuildParams,
    Duration,
) {
    let tris = triangles
        .iter()
        .map(|v| obvhs::triangle::Triangle {
            v0: v[0].as_vec3a(),
            v1: v[1].as_vec3a(),
            v2: v[2].as_vec3a(),
        })
        .collect();
    (tris, obvhs::BvhBuildParams::medium_build(), Duration::ZERO)
}

/// An obvhs ray over `interval` (infinite ends allowed).
fn obvhs_ray(ray: &Ray32, interval: Interval) -> obvhs::ray::Ray {
    obvhs::ray::Ray::new(
        ray.origin.into(),
        ray.direction.into(),
        interval.min as f32,
        interval.max as f32,
    )
}

/// Our triangle test as a peer's closure wants it: `t`, or +∞ for none.
fn test(
    prepared: &PreparedRay, v: &[DVec3; 3], interval: Interval,
    counts: &mut TraceCounts,
) -> f32 {
    counts.triangles += 1;
    prepared
        .triangle(v, interval)
        .map_or(f32::INFINITY, |t| t as f32)
}

struct Obvhs2(obvhs::bvh2::Bvh2, Vec<[DVec3; 3]>);
struct ObvhsCw(obvhs::cwbvh::CwBvh, Vec<[DVec3; 3]>);

/// obvhs's two hierarchies answer through the same calls.
macro_rules! obvhs_tracer {
    ($type:ty) => {
        impl MeshAccelerator for $type {
            fn closest_hit(
                &self, ray: &Ray32, interval: Interval,
                counts: &mut TraceCounts,
            ) -> Option<MeshHit> {
                let prepared = PreparedRay::traced(ray)?;
                let indices = &self.0.primitive_indices;
                let mut hit = obvhs::ray::RayHit::none();
                let found = self.0.ray_traverse(
                    obvhs_ray(ray, interval),
                    &mut hit,
                    |_, id| {
                        let v = &self.1[indices[id] as usize];
                        test(&prepared, v, interval, counts)
                    },
                );
                found.then(|| MeshHit {
                    triangle: indices[hit.primitive_id as usize],
                    t: f64::from(hit.t),
                })
            }

            fn any_hit(
                &self, ray: &Ray32, interval: Interval,
                counts: &mut TraceCounts,
            ) -> bool {
                let Some(prepared) = PreparedRay::traced(ray) else {
                    return false;
                };
                let indices = &self.0.primitive_indices;
                !self.0.ray_traverse_miss(obvhs_ray(ray, interval), |_, id| {
                    let v = &self.1[indices[id] as usize];
                    test(&prepared, v, interval, counts)
                })
            }
        }
    };
}

obvhs_tracer!(Obvhs2);
obvhs_tracer!(ObvhsCw);

/// A triangle as the `bvh` crate sees it: its box, rounded outward to
/// `f32`, and its index.
struct Shape {
    index: u32,
    node: usize,
    min: nalgebra::Point3<f32>,
    max: nalgebra::Point3<f32>,
}

impl Shape {
    fn new(index: u32, v: &[DVec3; 3]) -> Shape {
        let lo = v[0].min(v[1]).min(v[2]).as_vec3();
        let hi = v[0].max(v[1]).max(v[2]).as_vec3();
        let down = lo.to_array().map(f32::next_down);
        let up = hi.to_array().map(f32::next_up);
        Shape {
            index,
            node: 0,
            min: nalgebra::Point3::from(down),
            max: nalgebra::Point3::from(up),
        }
    }
}

impl bvh::aabb::Bounded<f32, 3> for Shape {
    fn aabb(&self) -> bvh::aabb::Aabb<f32, 3> {
        bvh::aabb::Aabb::with_bounds(self.min, self.max)
    }
}

impl bvh::bounding_hierarchy::BHShape<f32, 3> for Shape {
    fn set_bh_node_index(&mut self, index: usize) {
        self.node = index;
    }

    fn bh_node_index(&self) -> usize {
        self.node
    }
}

struct BvhCrate(bvh::bvh::Bvh<f32, 3>, Vec<Shape>, Vec<[DVec3; 3]>);

impl BvhCrate {
    /// The crate's iterator of every triangle whose box the ray meets.
    fn candidates<'a>(
        &'a self, ray: &'a bvh::ray::Ray<f32, 3>,
    ) -> impl Iterator<Item = &'a Shape> + 'a {
        self.0.traverse_iterator(ray, &self.1)
    }
}

fn bvh_ray(ray: &Ray32) -> bvh::ray::Ray<f32, 3> {
    bvh::ray::Ray::new(
        nalgebra::Point3::from(ray.origin.to_array()),
        nalgebra::Vector3::from(ray.direction.to_array()),
    )
}

impl MeshAccelerator for BvhCrate {
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let prepared = PreparedRay::traced(ray)?;
        let mut closest = Closest::new(interval);
        for shape in self.candidates(&bvh_ray(ray)) {
            let v = &self.2[shape.index as usize];
            closest.test(&prepared, shape.index, v, counts);
        }
        closest.hit
    }

    fn any_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        let Some(prepared) = PreparedRay::traced(ray) else {
            return false;
        };
        let query = bvh_ray(ray);
        let mut found = self.candidates(&query);
        found.any(|shape| {
            let v = &self.2[shape.index as usize];
            prepared.blocked_by(v, interval, counts)
        })
    }
}
