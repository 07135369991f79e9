//! How tight a bound is: the random lines it is measured with meet a
//! sphere as integral geometry says, and the expected cost's arithmetic.
//! (The measurement itself, and its table, are tested with the figures
//! crate that makes it: `figures/tests/tightness.rs`.)
mod common;

use ch08::{BoundingSphere, DVec3, Interval, RandomLines, Tightness};
use common::assert_near;

/// Every ray of the distribution meets the sphere it is drawn for, and
/// starts outside it; a sphere of half the radius, anywhere inside,
/// is met by 1/4 of them, as the uniform measure on lines says (the
/// chance is the ratio of the two surface areas).
#[test]
fn random_lines_meet_the_sphere_uniformly() {
    let sphere = BoundingSphere {
        center: DVec3::new(3.0, -2.0, 1.0),
        radius: 4.0,
    };
    let rays: Vec<_> = RandomLines::new(sphere, 7).take(40_000).collect();
    assert!(rays.iter().all(|r| !sphere.contains(r.origin)));
    assert!(
        rays.iter()
            .all(|r| sphere.hit(r, Interval::FORWARD).is_some()),
        "a ray that misses the sphere it was drawn through"
    );
    assert!(
        rays.iter()
            .all(|r| (r.direction.length() - 1.0).abs() < 1e-12)
    );
    for offset in [
        DVec3::ZERO,
        DVec3::new(1.9, 0.0, 0.0),
        DVec3::new(0.0, -1.0, 1.5),
    ] {
        let small = BoundingSphere {
            center: sphere.center + offset,
            radius: 2.0,
        };
        let hits = rays
            .iter()
            .filter(|r| small.hit(r, Interval::FORWARD).is_some())
            .count();
        assert_near(
            &format!("a sphere of half the radius, moved by {offset}"),
            hits as f64 / rays.len() as f64,
            0.25,
            rays.len() as u64,
        );
    }
    // the same seed draws the same rays; another seed others
    let again: Vec<_> = RandomLines::new(sphere, 7).take(10).collect();
    assert_eq!(again, rays[..10]);
    let other: Vec<_> = RandomLines::new(sphere, 8).take(10).collect();
    assert_ne!(other, rays[..10]);
}

/// The arithmetic of the expected cost, on counts made up by hand.
#[test]
fn expected_cost_and_speed_up() {
    let t = Tightness {
        rays: 1000,
        bound_hits: 250,
        object_hits: 100,
        wasted: 150,
        lost: 0,
    };
    assert_eq!(t.p_bound(), 0.25);
    assert_eq!(t.p_object(), 0.1);
    assert_eq!(t.p_object_given_bound(), 0.4);
    assert_eq!(t.wasted_fraction(), 0.6);
    // C_bound + P(bound) · C_object
    assert_eq!(t.expected_cost(1.0, 20.0), 6.0);
    assert_eq!(t.speed_up(1.0, 20.0), 20.0 / 6.0);
    // a bound as costly as the object never pays
    assert!(t.speed_up(1.0, 1.0) < 1.0);
    let none = Tightness {
        rays: 10,
        ..Tightness::default()
    };
    assert!(none.p_object_given_bound().is_nan());
}
