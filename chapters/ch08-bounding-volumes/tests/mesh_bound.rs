//! "Collections of stuff → meshes": the Stanford bunny triangle by
//! triangle, and behind one box.
use std::path::PathBuf;

use ch08::{
    BoundingSphere, DVec3, Interval, MeshBoxCounts, RandomLines, Ray, Shape,
    TIGHTNESS_SEED, TriangleMesh, camera_rays, incoherent_rays,
    mesh_behind_box, mesh_triangle, sampling_sphere,
};
use raystep_check::{Table, num_places};
use raystep_scene::Mesh;

/// The Stanford bunny beside the workspace: `../shared/meshes/bunny.obj`
/// from the workspace root (this crate is two folders below it).
fn bunny() -> Mesh {
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

/// The incoherent rays of `shared/meshes/README.md` (for part 2): from
/// the sphere of 1.5 × the box's circumsphere radius, each aimed at a
/// point inside the box, so every one of them hits the box.
#[test]
fn incoherent_rays_start_on_their_sphere_and_hit_the_box() {
    let b =
        ch08::Aabb::new(DVec3::new(-5.0, 0.0, -4.0), DVec3::new(5.0, 9.7, 3.8));
    let sphere = BoundingSphere::around_box(&b);
    let rays = incoherent_rays(b, 2000, 1);
    assert_eq!(rays.len(), 2000);
    for ray in &rays {
        let r = ray.origin.distance(sphere.center);
        assert!((r - 1.5 * sphere.radius).abs() < 1e-9 * r);
        assert!((ray.direction.length() - 1.0).abs() < 1e-12);
        assert!(ch08::slab_test(&b, ray, Interval::FORWARD).is_some());
    }
    assert_eq!(incoherent_rays(b, 10, 1), rays[..10]);
    // the origins cover the sphere: each octant gets its share
    for octant in 0..8 {
        let side =
            |axis: usize| if octant >> axis & 1 == 0 { 1.0 } else { -1.0 };
        let count = rays
            .iter()
            .filter(|r| {
                let d = r.origin - sphere.center;
                (0..3).all(|a| d[a] * side(a) > 0.0)
            })
            .count();
        assert!(
            (150..350).contains(&count),
            "octant {octant}: {count} of 2000"
        );
    }
}
