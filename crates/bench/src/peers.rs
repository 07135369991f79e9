//! The peers: other Rust BVH libraries, built on the same triangles and
//! handed the same watertight triangle test, so that only the hierarchy
//! and its walk differ. Their own box tests decide what they visit.
use std::time::{Duration, Instant};

use ch08::{PreparedRay, Ray32, TraceCounts};
use raystep_core::{DVec3, Interval};

use crate::methods::{Built, Method, Tracer, any_among, closest_among};

/// Builds a peer over `triangles`, timed from our triangles to a tracer.
pub fn build(method: Method, triangles: &[[DVec3; 3]]) -> Built {
    let start = Instant::now();
    let tracer: Box<dyn Tracer> = match method {
        Method::ObvhsBvh2 | Method::ObvhsCwBvh => {
            let tris: Vec<obvhs::triangle::Triangle> = triangles
                .iter()
                .map(|v| obvhs::triangle::Triangle {
                    v0: v[0].as_vec3a(),
                    v1: v[1].as_vec3a(),
                    v2: v[2].as_vec3a(),
                })
                .collect();
            let params = obvhs::BvhBuildParams::medium_build();
            let mut core = Duration::ZERO;
            if method == Method::ObvhsBvh2 {
                let bvh = obvhs::bvh2::builder::build_bvh2_from_tris(
                    &tris, params, &mut core,
                );
                Box::new(Obvhs2(bvh, triangles.to_vec()))
            } else {
                let bvh = obvhs::cwbvh::builder::build_cwbvh_from_tris(
                    &tris, params, &mut core,
                );
                Box::new(ObvhsCw(bvh, triangles.to_vec()))
            }
        }
        Method::BvhCrate => {
            let mut shapes: Vec<Shape> = triangles
                .iter()
                .enumerate()
                .map(|(k, v)| Shape::new(k as u32, v))
                .collect();
            let bvh = bvh::bvh::Bvh::build(&mut shapes);
            Box::new(BvhCrate(bvh, shapes, triangles.to_vec()))
        }
        Method::Ours(..)
        | Method::Grid(..)
        | Method::Kd(..)
        | Method::Fast(..) => {
            unreachable!("ours are built in methods.rs")
        }
        Method::Embree { .. } => {
            unreachable!("Embree is built in embree.rs, with its feature")
        }
    };
    Built {
        tracer,
        build_ms: start.elapsed().as_secs_f64() * 1e3,
        bytes: None,
        tree: None,
    }
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
    prepared: &PreparedRay,
    v: &[DVec3; 3],
    interval: Interval,
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
        impl Tracer for $type {
            fn closest(
                &self,
                ray: &Ray32,
                interval: Interval,
                counts: &mut TraceCounts,
            ) -> Option<(u32, f32)> {
                if !ray.is_valid() {
                    return None;
                }
                let prepared = PreparedRay::new(ray);
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
                found.then(|| (indices[hit.primitive_id as usize], hit.t))
            }

            fn any(
                &self,
                ray: &Ray32,
                interval: Interval,
                counts: &mut TraceCounts,
            ) -> bool {
                if !ray.is_valid() {
                    return false;
                }
                let prepared = PreparedRay::new(ray);
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
        &'a self,
        ray: &'a bvh::ray::Ray<f32, 3>,
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

impl Tracer for BvhCrate {
    fn closest(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<(u32, f32)> {
        if !ray.is_valid() {
            return None;
        }
        let query = bvh_ray(ray);
        let found = self
            .candidates(&query)
            .map(|shape| (shape.index, &self.2[shape.index as usize]));
        closest_among(&PreparedRay::new(ray), found, interval, counts)
    }

    fn any(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        if !ray.is_valid() {
            return false;
        }
        let query = bvh_ray(ray);
        let found = self
            .candidates(&query)
            .map(|shape| &self.2[shape.index as usize]);
        any_among(&PreparedRay::new(ray), found, interval, counts)
    }
}
