//! Smooth shading: the shading normal blended from a triangle's vertex
//! normals by the watertight test's barycentric coordinates is a unit
//! vector, on the geometric normal's side, and the vertex's own normal at
//! a vertex; the barycentric coordinates put the hit where its t does.
mod common;

use std::path::PathBuf;

use ch08::{
    DVec3, Interval, Ray, Shape, SmoothTriangle, barycentric, placed_triangles,
};
use common::Rng;
use raystep_scene::{Mesh, Placement};

/// A random triangle of edges about 1 near `centre`, and random unit
/// normals at its corners, each within 80° of its geometric normal.
fn random_triangle(rng: &mut Rng, centre: DVec3) -> SmoothTriangle {
    loop {
        let v = [0; 3].map(|_| centre + rng.vec3(1.0));
        let n = (v[1] - v[0]).cross(v[2] - v[0]);
        if n.length() < 0.1 {
            continue;
        }
        let n = n.normalize();
        let normals = [0; 3].map(|_| (n + 1.5 * rng.vec3(1.0)).normalize());
        if normals.iter().all(|m| m.dot(n) > 0.2) {
            return SmoothTriangle::new(v, normals).expect("a triangle");
        }
    }
}

/// A point inside the triangle, and a ray from off its plane through it.
fn ray_through(rng: &mut Rng, v: &[DVec3; 3], normal: DVec3) -> (Ray, DVec3) {
    let (u, w) = (rng.unit(), rng.unit());
    let (u, w) = if u + w > 1.0 {
        (1.0 - u, 1.0 - w)
    } else {
        (u, w)
    };
    let target = v[0] + u * (v[1] - v[0]) + w * (v[2] - v[0]);
    let side = if rng.chance(0.5) { 1.0 } else { -1.0 };
    let origin = target + side * 2.0 * normal + rng.vec3(0.5);
    (
        Ray::new(origin, (target - origin) * rng.uniform(0.2, 5.0)),
        target,
    )
}

#[test]
fn shading_normals_are_unit_and_on_the_geometric_side() {
    let mut rng = Rng::new(0x5300_7E57);
    let mut hits = 0;
    for _ in 0..2000 {
        let centre = rng.vec3(100.0);
        let triangle = random_triangle(&mut rng, centre);
        let flat = triangle.triangle();
        let (v, geometric) = (*flat.vertices(), flat.normal());
        let (ray, target) = ray_through(&mut rng, &v, geometric);
        let interval = Interval::new(0.0, f64::INFINITY);
        let Some(hit) = triangle.intersect(&ray, interval) else {
            continue; // through an edge owned by a neighbour
        };
        hits += 1;
        // the same hit as the flat triangle's
        assert_eq!(Some(hit.t), flat.hit_t(&ray, interval));
        assert!((hit.point - target).length() < 1e-9);
        assert!((hit.normal.length() - 1.0).abs() < 1e-12, "{hit:?}");
        assert!(hit.normal.dot(geometric) > 0.0, "{hit:?}");
        // the barycentric coordinates: in [0, 1], summing to 1, and
        // weighing the corners to the hit point
        let b = barycentric(&v, hit.point);
        assert!(b.min_element() >= 0.0 && b.max_element() <= 1.0, "{b}");
        assert!((b.element_sum() - 1.0).abs() < 1e-12, "{b}");
        let point = b.x * v[0] + b.y * v[1] + b.z * v[2];
        assert!((point - hit.point).length() < 1e-9, "{point} {hit:?}");
        assert_eq!(hit.normal, triangle.shading_normal(b));
    }
    assert!(hits > 1900, "{hits}");
}

#[test]
fn at_a_vertex_the_shading_normal_is_the_vertex_normal() {
    let mut rng = Rng::new(0x7E47_E700);
    for _ in 0..500 {
        let centre = rng.vec3(10.0);
        let triangle = random_triangle(&mut rng, centre);
        let v = *triangle.triangle().vertices();
        for (k, corner) in
            [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate()
        {
            let normal = triangle.normals()[k];
            let shading = triangle.shading_normal(corner);
            assert!((shading - normal).length() < 1e-12, "{shading} {normal}");
            // and the coordinates of the vertex itself
            let b = barycentric(&v, v[k]);
            assert!((b - corner).length() < 1e-12, "{b} at corner {k}");
        }
    }
}

#[test]
fn a_normal_on_the_other_side_gives_way_to_the_geometric_normal() {
    let v = [DVec3::ZERO, DVec3::X, DVec3::Y]; // geometric normal +z
    let triangle =
        SmoothTriangle::new(v, [DVec3::NEG_Z, DVec3::Z, DVec3::Z]).unwrap();
    // near the corner whose normal points down: the blend points down too
    let b = DVec3::new(0.9, 0.05, 0.05);
    assert_eq!(triangle.shading_normal(b), DVec3::Z);
    // no direction at all (the blend cancels out): the geometric normal
    let b = DVec3::new(0.5, 0.25, 0.25);
    assert_eq!(triangle.shading_normal(b), DVec3::Z);
    // near the others: the blend, on the geometric side
    let b = DVec3::new(0.1, 0.45, 0.45);
    assert!((triangle.shading_normal(b) - DVec3::Z).length() < 1e-15);
    let tilted =
        SmoothTriangle::new(v, [DVec3::new(1.0, 0.0, 1.0), DVec3::Z, DVec3::Z])
            .unwrap();
    let n = tilted.shading_normal(DVec3::new(0.5, 0.25, 0.25));
    assert!(
        n.x > 0.0 && n.dot(DVec3::Z) > 0.0 && (n.length() - 1.0).abs() < 1e-12
    );
}

/// Flattened under an uneven scale, a smooth mesh's normals go by the
/// inverse transpose: on a sphere squashed into an ellipsoid, the shading
/// normal at a vertex is the ellipsoid's normal there.
#[test]
fn placed_vertex_normals_go_by_the_inverse_transpose() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/meshes/octasphere-smooth.obj");
    let mesh = Mesh::load_obj(&path).unwrap();
    let radii = DVec3::new(3.0, 1.0, 0.5);
    let placement = Placement {
        scale: radii,
        ..Placement::IDENTITY
    };
    let shapes = placed_triangles(&mesh, &placement.to_world());
    let mut checked = 0;
    for (k, placed) in shapes.iter().enumerate() {
        let [a, b, c] = mesh.triangles[k];
        for i in [a, b, c] {
            // the ellipsoid's normal at p is p / radii², normalised
            let p = mesh.vertices[i] * radii;
            let expected = (p / (radii * radii)).normalize();
            let toward = p * 1.5;
            let ray = Ray::new(toward, p - toward);
            let hit = placed
                .shape
                .intersect(&ray, Interval::new(0.0, f64::INFINITY));
            // a ray at a corner counts for one triangle of its fan
            if let Some(hit) = hit {
                assert!(
                    (hit.normal - expected).length() < 1e-5,
                    "{hit:?} {expected}"
                );
                checked += 1;
            }
        }
    }
    assert!(checked >= 18, "{checked}");
}
