//! "Collections of stuff → meshes": the Stanford bunny triangle by
//! triangle, and behind one box.
mod common;

use ch08::{
    BoundingSphere, DVec3, Interval, MeshBoxCounts, RandomLines, Ray, Shape,
    TriangleMesh, mesh_behind_box, mesh_triangle,
};
use common::bunny;
use raystep_bench::{TIGHTNESS_SEED, camera_rays, sampling_sphere};
use raystep_check::{Table, num_places};
use raystep_scene::Mesh;

/// The bunny's ray sets: a 64 × 64 camera fitted to its box's
/// circumsphere (the primary rays of `shared/meshes/README.md`, smaller),
/// and 1024 random lines through the sphere of twice that radius (the
/// tightness measurements' rays: most miss the bunny's box). Unoptimised,
/// each ray's 3674 triangle tests take about 0.7 ms here.
fn ray_sets(mesh: &TriangleMesh) -> [(&'static str, Vec<Ray>); 2] {
    let sphere = BoundingSphere::around_box(&mesh.bounds());
    let lines = RandomLines::new(sampling_sphere(mesh), TIGHTNESS_SEED);
    [
        ("camera 64 × 64", camera_rays(sphere, 64)),
        ("random lines", lines.take(1024).collect()),
    ]
}

#[test]
fn every_bunny_triangle_is_a_triangle() {
    let mesh = TriangleMesh::new(&bunny());
    assert_eq!(mesh.triangles().len(), 3674);
    assert_eq!(mesh.skipped(), 0);
    assert!(mesh.triangles().iter().all(|t| t.vertices().len() == 3));
    // a triangle of zero area is refused, and skipped by a mesh
    let line = [DVec3::ZERO, DVec3::X, 2.0 * DVec3::X];
    assert!(mesh_triangle(line).is_none());
    let flat = Mesh {
        vertices: vec![DVec3::ZERO, DVec3::X, 2.0 * DVec3::X, DVec3::Y],
        triangles: vec![[0, 1, 2], [0, 1, 3]],
        normals: Vec::new(),
    };
    let flat = TriangleMesh::new(&flat);
    assert_eq!((flat.triangles().len(), flat.skipped()), (1, 1));
}

/// The bunny whole behind one box against triangle by triangle: the same
/// hits for every ray (0 disagreements), 3674 triangle tests per ray
/// without the box, and 1 + 3674 × P(box hit) with it.
#[test]
fn the_bunny_behind_one_box() {
    let mesh = TriangleMesh::new(&bunny());
    let mut table = Table::new(&[
        "rays",
        "count",
        "hits",
        "box hits",
        "disagreements",
        "tests per ray, no box",
        "tests per ray, box",
        "ratio",
    ]);
    // the two sets on two threads (each ray's 3674 tests are slow here)
    let sets = ray_sets(&mesh);
    let counts: Vec<MeshBoxCounts> = std::thread::scope(|scope| {
        let runs: Vec<_> = sets
            .iter()
            .map(|(_, rays)| scope.spawn(|| mesh_behind_box(&mesh, rays)))
            .collect();
        runs.into_iter().map(|run| run.join().unwrap()).collect()
    });
    for ((name, rays), c) in sets.iter().zip(counts) {
        assert_eq!(c.rays, rays.len() as u64);
        assert_eq!(c.disagreements, 0, "{name}: {c:?}");
        assert!(c.hits > 0 && c.hits <= c.box_hits, "{name}: {c:?}");
        assert_eq!(c.tests_per_ray_without_box(), 3674.0, "{name}");
        let expected = 1.0 + 3674.0 * c.p_box();
        assert!(
            (c.tests_per_ray_with_box() - expected).abs() < 1e-9,
            "{name}: expected 1 + 3674 × {} = {expected} tests per ray, \
             counted {}",
            c.p_box(),
            c.tests_per_ray_with_box()
        );
        table.row(&[
            name.to_string(),
            c.rays.to_string(),
            c.hits.to_string(),
            c.box_hits.to_string(),
            c.disagreements.to_string(),
            num_places(c.tests_per_ray_without_box(), 1),
            num_places(c.tests_per_ray_with_box(), 1),
            num_places(
                c.tests_per_ray_without_box() / c.tests_per_ray_with_box(),
                2,
            ),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// A ray that hits the mesh gets the nearest of its triangles' hits.
#[test]
fn the_mesh_hit_is_the_nearest_triangle_hit() {
    let mesh = TriangleMesh::new(&bunny());
    let sphere = BoundingSphere::around_box(&mesh.bounds());
    let rays = camera_rays(sphere, 8);
    let mut hits = 0;
    for ray in &rays {
        let nearest = mesh
            .triangles()
            .iter()
            .filter_map(|t| t.intersect(ray, Interval::FORWARD))
            .map(|h| h.t)
            .fold(f64::INFINITY, f64::min);
        let hit = mesh.intersect(ray, Interval::FORWARD);
        assert_eq!(hit.map_or(f64::INFINITY, |h| h.t), nearest);
        hits += usize::from(hit.is_some());
    }
    assert!(hits > 10, "only {hits} of 64 rays hit the bunny");
}
