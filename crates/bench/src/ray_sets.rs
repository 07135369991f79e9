//! The ray sets of `shared/meshes/README.md`, for a mesh: primary rays of
//! a camera fitted to it and incoherent rays at its box. The tests of
//! chapters 8–11, the benchmark, the stability catalogue and the figures
//! all trace these.
use ch08::{BoundingSphere, SplitMix64};
use raystep_core::{Aabb, Camera, DVec3, Ray};

/// The primary rays of a `size × size` pinhole camera fitted to `sphere`
/// (the mesh's bounding sphere): on +z at 3 radii from the centre,
/// looking at it, vertical field of view 29.4°. The primary ray set of
/// `shared/meshes/README.md`, at a smaller size.
pub fn camera_rays(sphere: BoundingSphere, size: u32) -> Vec<Ray> {
    let camera = Camera::look_at(
        sphere.center + 3.0 * sphere.radius * DVec3::Z,
        sphere.center,
        DVec3::Y,
        29.4,
        1.0,
    );
    let mut rays = Vec::with_capacity((size * size) as usize);
    for row in 0..size {
        for column in 0..size {
            rays.push(camera.pixel_ray(column, row, size, size));
        }
    }
    rays
}

/// `count` incoherent rays at a box (the mesh's): origins uniform on the
/// sphere of 1.5× the box's circumsphere radius around its centre,
/// directions aimed at uniform random points inside the box. The
/// incoherent ray set of `shared/meshes/README.md`.
pub fn incoherent_rays(bounds: Aabb, count: usize, seed: u64) -> Vec<Ray> {
    let sphere = BoundingSphere::around_box(&bounds);
    let mut random = SplitMix64::new(seed);
    (0..count)
        .map(|_| {
            let origin =
                sphere.center + 1.5 * sphere.radius * random.unit_vector();
            let along = DVec3::new(
                random.next_f64(),
                random.next_f64(),
                random.next_f64(),
            );
            let target = bounds.min + along * (bounds.max - bounds.min);
            Ray::new(origin, (target - origin).normalize())
        })
        .collect()
}
