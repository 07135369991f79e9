//! Meshes in scenes, two ways: flattened into the world (one object per
//! triangle, moved by the placement) and instanced (the ray moved into the
//! mesh's frame, the mesh's own structure walked there). On seeded rays an
//! instance hits exactly where its flattened copy does: to the bit at the
//! identity placement (t and normal within 1e-12), and at a rotated,
//! scaled, moved or mirrored placement within a relative 1e-9.
mod common;

use std::path::PathBuf;
use std::sync::Arc;

use ch03::BruteForce;
use ch08::{
    Accelerate, Accelerator, Blas, Builder, Bvh, DVec3, Hit, Interval,
    MeshInstance, Object, Ray, Shape, placed_triangles,
};
use common::Rng;
use raystep_core::glam::DAffine3;
use raystep_scene::{Mesh, Placement};

fn octasphere(file: &str) -> Mesh {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/meshes")
        .join(file);
    Mesh::load_obj(&path).expect("a test mesh")
}

/// Both test meshes: flat (no normals) and smooth.
fn meshes() -> [(&'static str, Mesh); 2] {
    [
        ("flat", octasphere("octasphere.obj")),
        ("smooth", octasphere("octasphere-smooth.obj")),
    ]
}

const BRUTE: Accelerate = |_| Arc::new(BruteForce);
const BVH: Accelerate = |objects| {
    Arc::new(Bvh::for_objects(objects, Builder::BinnedSah { bins: 16 }))
};

/// The mesh flattened by `to_world`: its triangles as world objects.
fn flattened(mesh: &Mesh, to_world: &DAffine3) -> Vec<Object> {
    placed_triangles(mesh, to_world)
        .into_iter()
        .map(|placed| Object {
            shape: placed.shape,
            material: 0,
        })
        .collect()
}

fn closest(objects: &[Object], ray: &Ray) -> Option<Hit> {
    let interval = Interval::new(0.0, f64::INFINITY);
    BruteForce
        .closest_hit(objects, ray, interval)
        .map(|(_, hit)| hit)
}

fn instance(
    mesh: &Mesh, to_world: DAffine3, accelerate: Accelerate,
) -> MeshInstance {
    MeshInstance::new(Arc::new(Blas::new(mesh, accelerate)), to_world)
}

#[test]
fn flattening_keeps_every_triangle_in_the_world() {
    for (name, mesh) in meshes() {
        let objects = flattened(&mesh, &DAffine3::IDENTITY);
        assert_eq!(objects.len(), 32, "{name}");
        assert_eq!(mesh.normals.is_empty(), name == "flat");
    }
}

#[test]
fn an_instance_at_the_identity_hits_as_the_flattened_mesh() {
    let mut rng = Rng::new(0x1DE4_7100);
    for (name, mesh) in meshes() {
        let objects = flattened(&mesh, &DAffine3::IDENTITY);
        for (accel, accelerate) in [("brute", BRUTE), ("bvh", BVH)] {
            let placed = instance(&mesh, DAffine3::IDENTITY, accelerate);
            let mut hits = 0;
            for _ in 0..4000 {
                // from around the mesh (some from inside it) toward a
                // point near its centre, or anywhere
                let origin = rng.vec3(3.0);
                let direction = if rng.chance(0.8) {
                    rng.vec3(0.8) - origin
                } else {
                    rng.unit_vec3()
                };
                let ray = Ray::new(origin, direction);
                let interval = Interval::new(0.0, f64::INFINITY);
                let (a, b) =
                    (closest(&objects, &ray), placed.intersect(&ray, interval));
                match (a, b) {
                    (None, None) => {}
                    (Some(a), Some(b)) => {
                        hits += 1;
                        assert!(
                            (a.t - b.t).abs() <= 1e-12,
                            "{name} {accel} {ray:?}"
                        );
                        assert!(
                            (a.normal - b.normal).length() <= 1e-12,
                            "{name} {accel} {ray:?}: {} against {}",
                            a.normal,
                            b.normal
                        );
                        assert!((a.point - b.point).length() <= 1e-12);
                    }
                    _ => panic!("{name} {accel} {ray:?}: {a:?} against {b:?}"),
                }
            }
            assert!(hits > 2000, "{name} {accel}: only {hits} hits");
        }
    }
}

/// Placements that rotate about every axis, scale unevenly, move, and
/// one that mirrors (a negative scale).
fn placements() -> [Placement; 3] {
    [
        Placement {
            scale: DVec3::new(2.0, 0.5, 1.5),
            rotate: DVec3::new(30.0, -50.0, 110.0),
            translate: DVec3::new(1.0, -2.0, 3.0),
        },
        Placement {
            scale: DVec3::splat(0.01),
            rotate: DVec3::new(0.0, 90.0, 0.0),
            translate: DVec3::new(100.0, 0.0, 0.0),
        },
        Placement {
            scale: DVec3::new(-1.0, 3.0, 1.0),
            rotate: DVec3::new(12.0, 0.0, -77.0),
            translate: DVec3::new(0.0, 0.5, 0.0),
        },
    ]
}

/// A point well inside a random triangle of `objects`' shapes (each
/// barycentric coordinate at least 0.1), found through its hit: a ray
/// from far away aimed at it hits the mesh, near no edge of that
/// triangle.
fn aim(rng: &mut Rng, mesh: &Mesh, to_world: &DAffine3) -> DVec3 {
    let [a, b, c] = mesh.triangle(rng.below(mesh.triangles.len()));
    let (u, v) = (rng.uniform(0.1, 0.8), rng.uniform(0.1, 0.8));
    let (u, v) = if u + v > 0.9 {
        (0.9 - v, 0.9 - u)
    } else {
        (u, v)
    };
    to_world.transform_point3(a + u * (b - a) + v * (c - a))
}

#[test]
fn a_placed_instance_hits_where_its_flattened_copy_does() {
    let mut rng = Rng::new(0x91AC_E000);
    for (name, mesh) in meshes() {
        for placement in placements() {
            let to_world = placement.to_world();
            let objects = flattened(&mesh, &to_world);
            let size = placement.scale.abs().max_element();
            for accelerate in [BRUTE, BVH] {
                let placed = instance(&mesh, to_world, accelerate);
                let bounds = placed.bounds();
                for _ in 0..2000 {
                    let target = aim(&mut rng, &mesh, &to_world);
                    let origin =
                        placement.translate + rng.unit_vec3() * 10.0 * size;
                    // an unnormalised direction, as a mesh's frame sees it
                    let ray = Ray::new(
                        origin,
                        (target - origin) * rng.uniform(0.1, 3.0),
                    );
                    let interval = Interval::new(0.0, f64::INFINITY);
                    let a = closest(&objects, &ray).expect("aimed at the mesh");
                    let b =
                        placed.intersect(&ray, interval).unwrap_or_else(|| {
                            panic!("{name} {placement:?} {ray:?}: missed")
                        });
                    assert!(
                        (a.t - b.t).abs() <= 1e-9 * a.t,
                        "{name} {placement:?}: t {} against {}",
                        a.t,
                        b.t
                    );
                    if name == "flat" {
                        assert!(
                            (a.normal - b.normal).length() <= 1e-9,
                            "{name} {placement:?}: {} against {}",
                            a.normal,
                            b.normal
                        );
                    }
                    assert!(bounds.contains(b.point), "{name} {placement:?}");
                }
            }
        }
    }
}

/// A mirror keeps the normals pointing out of the mesh, flattened or
/// instanced: on a sphere the normal at a hit points away from its
/// centre.
#[test]
fn a_mirrored_mesh_keeps_its_normals_outside() {
    let mut rng = Rng::new(0x3112_2000);
    let placement = placements()[2];
    let to_world = placement.to_world();
    for (name, mesh) in meshes() {
        let objects = flattened(&mesh, &to_world);
        let placed = instance(&mesh, to_world, BRUTE);
        for _ in 0..500 {
            let target = aim(&mut rng, &mesh, &to_world);
            let origin = placement.translate + rng.unit_vec3() * 20.0;
            let ray = Ray::new(origin, target - origin);
            let interval = Interval::new(0.0, f64::INFINITY);
            let hits = [
                closest(&objects, &ray).expect("flattened"),
                placed.intersect(&ray, interval).expect("instanced"),
            ];
            for hit in hits {
                let out = hit.point - placement.translate;
                assert!(hit.normal.dot(out) > 0.0, "{name}: {hit:?}");
            }
        }
    }
}

/// Instances share their mesh's structure: ten placements of one mesh
/// hold one copy of its triangles.
#[test]
fn instances_share_one_structure() {
    let mesh = octasphere("octasphere.obj");
    let blas = Arc::new(Blas::new(&mesh, BVH));
    let instances: Vec<MeshInstance> = (0..10)
        .map(|k| {
            let placement = Placement {
                translate: DVec3::new(f64::from(k) * 3.0, 0.0, 0.0),
                ..Placement::IDENTITY
            };
            MeshInstance::new(blas.clone(), placement.to_world())
        })
        .collect();
    assert_eq!(Arc::strong_count(&blas), 11);
    assert_eq!(blas.objects().len(), 32);
    assert!(instances.iter().all(|i| Arc::ptr_eq(i.blas(), &blas)));
}

/// A smooth triangle stretched: its corners' normal (1, −½, 0) is on its
/// facet's side, normal ∝ (1, 1, 0); squashing y by 10 turns the normals
/// into (1, −5, 0) and (1, 10, 0), on opposite sides. Instanced (blended
/// in the mesh's frame) or flattened (blended in the world), the hit
/// keeps the facet's normal.
#[test]
fn a_stretched_smooth_normal_gives_way_to_its_facet() {
    let corner = DVec3::new(1.0, -0.5, 0.0).normalize();
    let mesh = Mesh {
        vertices: vec![DVec3::ZERO, DVec3::Z, DVec3::new(1.0, -1.0, 0.0)],
        triangles: vec![[0, 1, 2]],
        normals: vec![corner; 3],
    };
    let placement = Placement {
        scale: DVec3::new(1.0, 0.1, 1.0),
        ..Placement::IDENTITY
    };
    let to_world = placement.to_world();
    let facet = DVec3::new(0.1, 1.0, 0.0).normalize();
    let objects = flattened(&mesh, &to_world);
    let placed = instance(&mesh, to_world, BRUTE);
    let mut rng = Rng::new(0x57E7_C400);
    for _ in 0..200 {
        let target = aim(&mut rng, &mesh, &to_world);
        let origin = target + facet * 3.0 + rng.vec3(1.0);
        let ray = Ray::new(origin, target - origin);
        let interval = Interval::new(0.0, f64::INFINITY);
        let flat = closest(&objects, &ray).expect("flattened");
        let hit = placed.intersect(&ray, interval).expect("instanced");
        assert!((flat.normal - facet).length() < 1e-12, "{flat:?}");
        assert!((hit.normal - facet).length() < 1e-12, "{hit:?}");
    }
}
