//! Rays where a mesh is most fragile: aimed from one eye exactly at the
//! edges two triangles share. A robust walk with a watertight test lets
//! none of them through; the tests, the catalogue and chapter 8's charts
//! count the ones that leak.
use std::collections::HashMap;

use raystep_core::{Aabb, DVec3, Interval, Ray32};
use raystep_world::{MeshAccelerator, TraceCounts};

/// The t interval of an edge ray: its target is (to rounding) on the
/// surface at t = 1; the slack allows for rounding the ray to `f32`.
pub const EDGE_REACH: Interval = Interval {
    min: 0.0,
    max: 1.0 + 1e-4,
};

/// Rays from an eye beside the mesh's box through the points at fractions
/// `points` along every edge exactly two triangles share — but not at a
/// silhouette: the ray must see both triangles from the same side, and
/// neither nearly edge-on. Each ray reaches its target at t = 1.
pub fn shared_edge_rays(
    triangles: &[[DVec3; 3]], points: &[f64],
) -> Vec<Ray32> {
    // Step 1: the triangles on each edge (corners compared bit for bit).
    let mut edges: HashMap<[[u64; 3]; 2], Vec<usize>> = HashMap::new();
    let key = |p: DVec3| p.to_array().map(f64::to_bits);
    for (k, v) in triangles.iter().enumerate() {
        for i in 0..3 {
            let (a, b) = (key(v[i]), key(v[(i + 1) % 3]));
            let edge = if a < b { [a, b] } else { [b, a] };
            edges.entry(edge).or_default().push(k);
        }
    }
    // Step 2: an eye up and to the side of the box.
    let bounds = Aabb::around(triangles.iter().flatten().copied());
    let (centre, size) =
        (0.5 * (bounds.min + bounds.max), bounds.max - bounds.min);
    let eye = (centre + DVec3::new(0.3, 0.2, 3.0) * size.length()).as_vec3();
    let normal = |v: &[DVec3; 3]| (v[1] - v[0]).cross(v[2] - v[0]).normalize();
    let from = |k: [u64; 3]| DVec3::from_array(k.map(f64::from_bits));
    // Step 3: a ray through each point of each shared edge, in a fixed
    // order (the edges sorted), away from silhouettes.
    let mut shared: Vec<_> = edges
        .into_iter()
        .filter_map(|(edge, sharing)| match sharing.as_slice() {
            &[i, j] => Some((edge, i, j)),
            _ => None, // a border edge, or more than two triangles
        })
        .collect();
    shared.sort_unstable();
    let mut rays = Vec::new();
    for ([a, b], i, j) in shared {
        for &s in points {
            let target = from(a).lerp(from(b), s);
            let ray = Ray32 {
                origin: eye,
                direction: (target - eye.as_dvec3()).as_vec3(),
            };
            let d = ray.direction.as_dvec3().normalize();
            let (ci, cj) =
                (normal(&triangles[i]).dot(d), normal(&triangles[j]).dot(d));
            if ci * cj > 0.0 && ci.abs() >= 0.05 && cj.abs() >= 0.05 {
                rays.push(ray);
            }
        }
    }
    rays
}

/// How many of `rays` (from [`shared_edge_rays`]) hit nothing within
/// [`EDGE_REACH`] through `mesh` (any mesh structure): leaks through the
/// surface.
pub fn leaks(mesh: &dyn MeshAccelerator, rays: &[Ray32]) -> usize {
    rays.iter()
        .filter(|ray| {
            let mut counts = TraceCounts::default();
            mesh.closest_hit(ray, EDGE_REACH, &mut counts).is_none()
        })
        .count()
}

/// A surface the leak counts aim at.
pub struct LeakSurface {
    /// `mesh`, `mesh moved`, `tiled floor`.
    pub name: &'static str,
    /// Its triangles.
    pub triangles: Vec<[DVec3; 3]>,
    /// The fractions along each shared edge aimed at.
    pub points: &'static [f64],
}

/// The surfaces the leak counts use: the mesh as given, the same mesh
/// moved 1000 away and shrunk by 3 (corners no `f32` can hold, so node
/// boxes are rounded), and a floor of 24 × 24 square tiles 0.1 wide (no
/// `f32` holds 0.1; its edges lie on the faces of the leaves' boxes).
pub fn leak_surfaces(mesh: &[[DVec3; 3]]) -> Vec<LeakSurface> {
    let moved: Vec<_> = mesh
        .iter()
        .map(|v| v.map(|p| p / 3.0 + DVec3::new(1000.0, -700.0, 300.0)))
        .collect();
    let mut floor = Vec::new();
    for i in 0..24 {
        for j in 0..24 {
            let corner = |a: i32, b: i32| {
                DVec3::new(0.1 * f64::from(a), 0.3, 0.1 * f64::from(b))
            };
            let [p, q, r, s] = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                .map(|(a, b)| corner(a, b));
            floor.extend([[p, s, q], [q, s, r]]);
        }
    }
    let surface = |name, triangles, points| LeakSurface {
        name,
        triangles,
        points,
    };
    vec![
        surface("mesh", mesh.to_vec(), &[0.5]),
        surface("mesh moved", moved, &[0.5]),
        surface("tiled floor", floor, &[0.1, 0.3, 0.5, 0.7, 0.9]),
    ]
}
