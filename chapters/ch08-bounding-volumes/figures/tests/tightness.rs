//! Tightness, measured: how many rays a bound lets through to an object
//! they then miss, against what integral geometry predicts.
#[path = "../../tests/common/mod.rs"]
mod common;

use std::f64::consts::PI;

use ch03::Sphere;
use ch08::{Bound, BoundKind, BoundingSphere, DVec3, Primitive, Shape};
use ch08_figures::{measure_tightness, tightness};
use common::{TestPolygon, assert_near, equilateral};
use raystep_bench::{TIGHTNESS_SEED, sampling_sphere};
use raystep_check::{Table, num_places};

/// Rays per (object, bound) pair. The fractions below then have a
/// standard deviation of at most 0.5/√(rays hitting the bound), about
/// 0.003 for a bound hit by 1 ray in 6.
const RAYS: u64 = 100_000;

fn unit_sphere() -> Sphere {
    Sphere::new(DVec3::new(0.5, -1.0, 2.0), 1.5)
}

/// A sphere in its own bounding sphere: no ray hits the bound and misses
/// the sphere (the two tests are the same quadratic), none is lost.
#[test]
fn a_sphere_in_its_own_sphere_wastes_nothing() {
    let s = tightness(&unit_sphere(), BoundKind::Sphere, RAYS, TIGHTNESS_SEED);
    assert_eq!((s.wasted, s.lost), (0, 0), "{s:?}");
    assert_eq!(s.bound_hits, s.object_hits);
    // the sampling sphere is 2√3 × the radius: P = 1/12
    assert_near("P(sphere)", s.p_bound(), 1.0 / 12.0, RAYS);
}

/// A sphere in its box: of the rays that hit the box, a fraction π/6
/// hits the sphere (the ratio of the surface areas, 4πr² / 24r²), and
/// 1 − π/6 = 47.6 % is wasted. (Along one axis it would be the
/// cross-sections' ratio π/4; averaged over all directions it is π/6.)
/// In the box's circumsphere (radius √3·r) 1/3 hits the sphere.
#[test]
fn a_sphere_in_its_box_and_in_the_box_sphere() {
    let object = unit_sphere();
    let boxed = tightness(&object, BoundKind::Box, RAYS, TIGHTNESS_SEED);
    assert_eq!(boxed.lost, 0);
    assert_near("P(box)", boxed.p_bound(), 1.0 / (2.0 * PI), RAYS);
    assert_near(
        "P(sphere | box)",
        boxed.p_object_given_bound(),
        PI / 6.0,
        boxed.bound_hits,
    );
    let around = tightness(&object, BoundKind::BoxSphere, RAYS, TIGHTNESS_SEED);
    assert_eq!(around.lost, 0);
    assert_near("P(box's sphere)", around.p_bound(), 0.25, RAYS);
    assert_near(
        "P(sphere | box's sphere)",
        around.p_object_given_bound(),
        1.0 / 3.0,
        around.bound_hits,
    );
    // the same rays for every bound: the object is hit as often
    let own = tightness(&object, BoundKind::Sphere, RAYS, TIGHTNESS_SEED);
    assert_eq!(boxed.object_hits, own.object_hits);
    assert_eq!(around.object_hits, own.object_hits);
}

/// A flat equilateral triangle (side s, in z = 0): a line meets it with
/// a chance 2A / area(S), A its area (a flat object has two sides). So
/// P(triangle | its circumsphere) = 3√3/(8π) ≈ 0.207 (79 % wasted),
/// P(triangle | its box) = 1/2 (the box is a flat s × (√3/2)s rectangle,
/// twice the triangle's area) and P(triangle | the box's circumsphere) =
/// 2√3/(7π) ≈ 0.158.
#[test]
fn a_flat_triangle_in_a_sphere_wastes_most_rays() {
    let object = TestPolygon::new(&equilateral(2.0));
    let expected = [
        (BoundKind::Sphere, 3.0 * 3f64.sqrt() / (8.0 * PI)),
        (BoundKind::Box, 0.5),
        (BoundKind::BoxSphere, 2.0 * 3f64.sqrt() / (7.0 * PI)),
    ];
    for (kind, p) in expected {
        let t = tightness(&object, kind, RAYS, TIGHTNESS_SEED);
        assert_eq!(t.lost, 0, "{}: {t:?}", kind.name());
        assert_near(
            &format!("P(triangle | {})", kind.name()),
            t.p_object_given_bound(),
            p,
            t.bound_hits,
        );
    }
    let sphere = tightness(&object, BoundKind::Sphere, RAYS, TIGHTNESS_SEED);
    assert!(sphere.wasted_fraction() > 0.75, "{sphere:?}");
}

/// A bound that does not hold its object loses hits, and the count says
/// so (the measurement would catch a wrong bound).
#[test]
fn a_bound_too_small_loses_hits() {
    let object = unit_sphere();
    let small = Bound::Sphere(BoundingSphere {
        center: object.center,
        radius: 0.5 * object.radius,
    });
    let t = measure_tightness(&object, &small, 20_000, TIGHTNESS_SEED);
    assert_eq!(t.wasted, 0);
    // (1.5² − 0.75²) / 1.5² = 3/4 of the sphere's hits are lost
    assert_near(
        "lost / hits",
        t.lost as f64 / t.object_hits as f64,
        0.75,
        t.object_hits,
    );
}

/// The sampling sphere: around the object's box, twice its circumsphere.
#[test]
fn the_sampling_sphere_holds_every_bound() {
    let object = TestPolygon::new(&[
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(4.0, 1.0, -1.0),
        DVec3::new(1.0, 3.0, 2.0),
    ]);
    let s = sampling_sphere(&object);
    let b = object.bounds();
    assert_eq!(s.center, 0.5 * (b.min + b.max));
    assert_eq!(s.radius, (b.max - b.min).length());
    let own = object.bounding_sphere();
    assert!(s.radius >= own.radius + own.center.distance(s.center));
}

/// The table for the book: each object in each bound, the fractions of
/// rays, and the speed-up for two cost ratios (a bound as costly as the
/// object: it never pays; an object 10× the bound's cost).
#[test]
fn tightness_table() {
    let s = 2.0;
    let objects: [(&str, Box<dyn Primitive>); 4] = [
        ("sphere", Box::new(unit_sphere())),
        (
            "triangle, flat in z = 0",
            Box::new(TestPolygon::new(&equilateral(s))),
        ),
        (
            "triangle, tilted",
            Box::new(TestPolygon::new(&[
                DVec3::new(0.0, 0.0, 0.0),
                DVec3::new(2.0, 0.5, -0.5),
                DVec3::new(0.5, 1.5, 1.0),
            ])),
        ),
        (
            "thin rectangle, diagonal",
            Box::new(TestPolygon::new(&[
                DVec3::new(0.0, 0.0, 0.0),
                DVec3::new(3.0, 3.0, 3.0),
                DVec3::new(3.1, 2.9, 3.0),
                DVec3::new(0.1, -0.1, 0.0),
            ])),
        ),
    ];
    let mut table = Table::new(&[
        "object",
        "bound",
        "P(bound)",
        "P(object)",
        "P(object | bound)",
        "wasted",
        "lost",
        "speed-up, C_o = C_b",
        "speed-up, C_o = 10 C_b",
    ]);
    for (name, object) in &objects {
        for kind in BoundKind::ALL {
            let t = tightness(object.as_ref(), kind, RAYS, TIGHTNESS_SEED);
            assert_eq!(t.lost, 0, "{name} in its {}: {t:?}", kind.name());
            table.row(&[
                name.to_string(),
                kind.name().to_string(),
                num_places(t.p_bound(), 3),
                num_places(t.p_object(), 3),
                num_places(t.p_object_given_bound(), 3),
                num_places(t.wasted_fraction(), 3),
                t.lost.to_string(),
                num_places(t.speed_up(1.0, 1.0), 2),
                num_places(t.speed_up(1.0, 10.0), 2),
            ]);
        }
    }
    insta::assert_snapshot!(table.to_string());
}
