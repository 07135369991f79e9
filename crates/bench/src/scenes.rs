//! The scenes that make chapter 9's point, generated from a seed: many
//! small objects spread evenly (where a grid shines) and a detailed mesh
//! in a huge sparse stadium (where it fails). The tests of chapters 9 and
//! 10, their figures and the stability catalogue all build these.
use std::sync::Arc;

use ch08::SplitMix64;
use raystep_core::{Aabb, DVec3};
use raystep_world::Object;

/// The seed of every generated scene.
pub const SCENE_SEED: u64 = 9;

/// `count` small triangles spread evenly through the cube [−1, 1]³: each
/// around a uniform random centre, its corners at a random direction and
/// about the spacing of the centres from it (so neighbours barely meet).
pub fn uniform_triangles(count: usize, seed: u64) -> Vec<[DVec3; 3]> {
    let mut random = SplitMix64::new(seed);
    let reach = spacing(count) * 0.5;
    (0..count)
        .map(|_| {
            let centre = uniform_point(&mut random);
            [0, 1, 2].map(|_| centre + reach * random.unit_vector())
        })
        .collect()
}

/// `count` small spheres spread evenly through the cube [−1, 1]³: centres
/// uniform at random, radii a quarter of the centres' spacing.
pub fn uniform_spheres(count: usize, seed: u64) -> Vec<(DVec3, f64)> {
    let mut random = SplitMix64::new(seed);
    let radius = spacing(count) * 0.25;
    (0..count)
        .map(|_| (uniform_point(&mut random), radius))
        .collect()
}

/// The mean distance between `count` points spread through a cube of
/// side 2: the side of the cube each one has to itself.
fn spacing(count: usize) -> f64 {
    2.0 / (count.max(1) as f64).cbrt()
}

fn uniform_point(random: &mut SplitMix64) -> DVec3 {
    DVec3::new(random.next_f64(), random.next_f64(), random.next_f64()) * 2.0
        - DVec3::ONE
}

/// How much larger than the mesh the stadium is: its floor is
/// `2·STADIUM` wide, its walls `STADIUM / 2` high, for a mesh of size 1.
pub const STADIUM: f64 = 100.0;

/// The "teapot in a stadium" (Haines): `mesh`, scaled to size 1 and
/// standing at the centre of a floor `2·STADIUM` wide, walled on four
/// sides; ten big triangles and the mesh's many small ones.
pub fn stadium(mesh: &[[DVec3; 3]]) -> Vec<[DVec3; 3]> {
    let bounds = Aabb::around(mesh.iter().flatten().copied());
    let scale = 1.0 / (bounds.max - bounds.min).max_element();
    let base = DVec3::new(
        0.5 * (bounds.min.x + bounds.max.x),
        bounds.min.y,
        0.5 * (bounds.min.z + bounds.max.z),
    );
    let mut triangles: Vec<[DVec3; 3]> =
        mesh.iter().map(|t| t.map(|v| (v - base) * scale)).collect();
    let (s, h) = (STADIUM, STADIUM / 2.0);
    let corner = |x: f64, y: f64, z: f64| DVec3::new(x * s, y * h, z * s);
    let quad = |a: DVec3, b: DVec3, c: DVec3, d: DVec3| [[a, b, c], [a, c, d]];
    let (floor, walls) = (
        [
            corner(-1.0, 0.0, -1.0),
            corner(1.0, 0.0, -1.0),
            corner(1.0, 0.0, 1.0),
            corner(-1.0, 0.0, 1.0),
        ],
        [(-1.0, -1.0, 1.0, -1.0), (1.0, -1.0, 1.0, 1.0)],
    );
    triangles.extend(quad(floor[0], floor[3], floor[2], floor[1]));
    for (x0, z0, x1, z1) in walls {
        for sign in [1.0, -1.0] {
            let (a, b) = (
                corner(sign * x0, 0.0, sign * z0),
                corner(sign * x1, 0.0, sign * z1),
            );
            let up = DVec3::new(0.0, h, 0.0);
            triangles.extend(quad(a, b, b + up, a + up));
        }
    }
    triangles
}

/// Triangles as objects for the object seam (chapter 8's mesh triangles;
/// those of zero area left out).
pub fn triangle_objects(triangles: &[[DVec3; 3]]) -> Vec<Object> {
    triangles
        .iter()
        .filter_map(|t| ch08::mesh_triangle(*t))
        .map(|t| Object {
            shape: Arc::new(t),
            material: 0,
        })
        .collect()
}
