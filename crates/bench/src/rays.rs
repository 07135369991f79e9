//! The ray sets a benchmark traces: generated (primary, shadow,
//! incoherent; seeded; in `f32`) or read from a file of little-endian
//! `f32`s.
use std::path::Path;

use ch08::{BoundingSphere, MeshAccelerator, MeshBvh, Ray32, TraceCounts};
use raystep_core::glam::Vec3;
use raystep_core::{Aabb, DVec3, Interval};

use crate::{BenchError, camera_rays, incoherent_rays};

/// What a ray set asks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Question {
    /// The closest hit over t ∈ [0, ∞).
    Closest,
    /// Is anything hit over t ∈ [0, 1 − 10⁻⁴]? (A shadow ray runs from
    /// the light to a point, its direction the whole way.)
    Any,
}

/// The `t` interval a question searches.
pub fn interval(question: Question) -> Interval {
    match question {
        Question::Closest => Interval::new(0.0, f64::INFINITY),
        Question::Any => Interval::new(0.0, 1.0 - 1e-4),
    }
}

/// A named set of rays and its question.
#[derive(Clone, Debug)]
pub struct RaySet {
    /// `primary`, `shadow`, `incoherent`, or the file's name.
    pub name: String,
    /// What each ray asks.
    pub question: Question,
    /// The rays.
    pub rays: Vec<Ray32>,
}

/// The bytes of one ray in a ray file: origin xyz, direction xyz.
pub const RAY_BYTES: usize = 24;

/// Reads a ray file: records of six little-endian `f32`s.
pub fn read_rays(file: &Path) -> Result<RaySet, BenchError> {
    let error = |message: String| BenchError::RayFile {
        file: file.to_path_buf(),
        message,
    };
    let bytes = std::fs::read(file).map_err(|e| error(e.to_string()))?;
    if bytes.is_empty() || bytes.len() % RAY_BYTES != 0 {
        return Err(error(format!(
            "{} bytes is not a whole number of rays ({RAY_BYTES} bytes \
             each: origin xyz, direction xyz as little-endian f32)",
            bytes.len()
        )));
    }
    let rays = bytes
        .chunks_exact(RAY_BYTES)
        .map(|record| {
            let f = |k: usize| {
                f32::from_le_bytes(record[4 * k..4 * k + 4].try_into().unwrap())
            };
            Ray32 {
                origin: Vec3::new(f(0), f(1), f(2)),
                direction: Vec3::new(f(3), f(4), f(5)),
            }
        })
        .collect();
    Ok(RaySet {
        name: file
            .file_name()
            .map_or("rays".into(), |n| n.to_string_lossy().into_owned()),
        question: Question::Closest,
        rays,
    })
}

/// Rays as a ray file's bytes.
pub fn ray_bytes(rays: &[Ray32]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(rays.len() * RAY_BYTES);
    for ray in rays {
        for x in ray
            .origin
            .to_array()
            .iter()
            .chain(&ray.direction.to_array())
        {
            bytes.extend_from_slice(&x.to_le_bytes());
        }
    }
    bytes
}

/// The primary rays of `shared/meshes/README.md`: a `size × size`
/// pinhole camera on +z at 3 bounding radii from the box's centre,
/// vertical field of view 29.4°.
pub fn primary(bounds: &Aabb, size: u32) -> RaySet {
    let sphere = BoundingSphere::around_box(bounds);
    RaySet {
        name: "primary".into(),
        question: Question::Closest,
        rays: camera_rays(sphere, size)
            .iter()
            .map(Ray32::rounded)
            .collect(),
    }
}

/// The incoherent rays of `shared/meshes/README.md`: origins on a sphere
/// of 1.5 bounding radii, aimed at uniform points in the box.
pub fn incoherent(bounds: &Aabb, count: usize, seed: u64) -> RaySet {
    RaySet {
        name: "incoherent".into(),
        question: Question::Closest,
        rays: incoherent_rays(*bounds, count, seed)
            .iter()
            .map(Ray32::rounded)
            .collect(),
    }
}

/// Shadow rays: from a point light above and to the right of the camera
/// to every point the primary rays hit (found with `bvh`).
pub fn shadow(bounds: &Aabb, primary: &RaySet, bvh: &MeshBvh) -> RaySet {
    let sphere = BoundingSphere::around_box(bounds);
    let light = sphere.center + sphere.radius * DVec3::new(2.0, 3.0, 2.5);
    let mut counts = TraceCounts::default();
    let rays = primary
        .rays
        .iter()
        .filter_map(|ray| {
            let hit =
                bvh.closest_hit(ray, interval(Question::Closest), &mut counts)?;
            let point = ray.to_ray().at(hit.t);
            Some(Ray32 {
                origin: light.as_vec3(),
                direction: (point - light.as_vec3().as_dvec3()).as_vec3(),
            })
        })
        .collect();
    RaySet {
        name: "shadow".into(),
        question: Question::Any,
        rays,
    }
}
