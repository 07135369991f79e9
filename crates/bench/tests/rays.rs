//! The generated ray sets that every measurement and test of chapters
//! 8–11 shares.
use ch08::{BoundingSphere, DVec3, Interval};
use raystep_bench::incoherent_rays;

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
