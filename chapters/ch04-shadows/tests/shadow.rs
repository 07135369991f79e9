//! Exercise 1: Sᵢ from a shadow ray.
use ch04::{DVec3, Hit, Light, Offset, World, render, shadow};
use proptest::prelude::*;
use raystep_check::{
    Table, Tolerance, assert_image_matches, differing_pixels, seeded, vec3,
};
use raystep_render::{Progress, RenderOptions};
use raystep_scene::Shape;
use std::path::Path;

mod common;
use common::world;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn light(position: DVec3) -> Light {
    Light {
        position,
        intensity: DVec3::ONE,
    }
}

/// Sᵢ with the scale-aware offset (this exercise's code does not depend on
/// which strategy builds the ray).
fn si(
    world: &World, point: DVec3, normal: DVec3, light_position: DVec3,
) -> f64 {
    let hit = Hit {
        t: 1.0,
        point,
        normal,
    };
    shadow(
        world,
        &hit,
        normal,
        &light(light_position),
        Offset::ScaleAware,
    )
}

/// A floor at y = 0 and a ball of radius 0.5 hovering at (0, 2, 0).
fn floor_and_ball() -> World {
    world(vec![
        Shape::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        },
        Shape::Sphere {
            center: v(0.0, 2.0, 0.0),
            radius: 0.5,
        },
    ])
}

#[test]
fn shadow_table() {
    let w = floor_and_ball();
    let up = DVec3::Y;
    #[rustfmt::skip]
    let cases = [
        ("under the ball, light above", v(0.0, 0.0, 0.0), up, v(0.0, 5.0, 0.0)),
        ("beside the ball, light above", v(3.0, 0.0, 0.0), up, v(3.0, 5.0, 0.0)),
        ("ball beyond the light", v(0.0, 0.0, 0.0), up, v(0.0, 1.0, 0.0)),
        ("light just before the ball", v(0.0, 0.0, 0.0), up, v(0.0, 1.49, 0.0)),
        ("light just inside the ball", v(0.0, 0.0, 0.0), up, v(0.0, 1.51, 0.0)),
        ("slanted ray through the centre", v(-2.0, 0.0, 0.0), up, v(2.0, 4.0, 0.0)),
        ("slanted ray passing 0.55 away", v(-2.0, 0.0, 0.0), up, v(4.0, 4.0, 0.0)),
        ("light behind the surface", v(3.0, 0.0, 0.0), up, v(3.0, -2.0, 0.0)),
        ("light in the surface's plane", v(3.0, 0.0, 0.0), up, v(8.0, 0.0, 0.0)),
        ("top of the ball, light above", v(0.0, 2.5, 0.0), up, v(0.0, 5.0, 0.0)),
        ("underside of the ball, light above", v(0.0, 1.5, 0.0), -up, v(0.0, 5.0, 0.0)),
        ("underside of the ball, light below", v(0.0, 1.5, 0.0), -up, v(0.0, 0.5, 0.0)),
        ("side of the ball, light to that side", v(0.5, 2.0, 0.0), DVec3::X, v(5.0, 2.0, 0.0)),
    ];
    let mut table = Table::new(&["case", "point", "normal", "light", "S"]);
    for (name, point, normal, light) in cases {
        table.row(&[
            name.to_string(),
            vec3(point),
            vec3(normal),
            vec3(light),
            si(&w, point, normal, light).to_string(),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}

/// A light exactly in the tangent plane of the point (N·(light − P) = 0)
/// counts as behind it: S = 0, like the floor's "light in the surface's
/// plane" above. The floor would also block its own shadow ray; the ball,
/// curving away below the tangent plane, does not, so only the rule
/// "N·L ≤ 0: the surface blocks it" gives 0 here.
#[test]
fn a_light_in_the_tangent_plane_is_behind_the_surface() {
    let w = floor_and_ball();
    #[rustfmt::skip]
    let cases = [
        ("side of the ball, light straight above it",
            v(0.5, 2.0, 0.0), DVec3::X, v(0.5, 5.0, 0.0)),
        ("top of the ball, light level with it",
            v(0.0, 2.5, 0.0), DVec3::Y, v(4.0, 2.5, -3.0)),
    ];
    for (name, point, normal, light) in cases {
        let got = si(&w, point, normal, light);
        assert!(
            got == 0.0,
            "{name}: point {point}, normal {normal}, light {light}, N·(light \
             − point) = {}: expected S = 0 (a light in the surface's tangent \
             plane is not in front of it: N·L ≤ 0), got S = {got}",
            normal.dot(light - point)
        );
    }
}

/// `normal` is the normal turned toward the viewer; the hit's own normal
/// may point the other way (a plane whose normal points down, seen from
/// above; a ball seen from inside). The shadow ray leaves on the viewer's
/// side, so S follows `normal`, not `hit.normal`.
#[test]
fn the_normal_toward_the_viewer_decides() {
    let w = floor_and_ball();
    #[rustfmt::skip]
    let cases = [
        ("the floor seen from above, its plane's normal pointing down",
            v(3.0, 0.0, 0.0), v(0.0, -1.0, 0.0), DVec3::Y, v(3.0, 5.0, 0.0), 1.0),
        ("the top of the ball seen from inside, the light at its centre",
            v(0.0, 2.5, 0.0), DVec3::Y, v(0.0, -1.0, 0.0), v(0.0, 2.0, 0.0), 1.0),
        ("the top of the ball seen from inside, the light above it",
            v(0.0, 2.5, 0.0), DVec3::Y, v(0.0, -1.0, 0.0), v(0.0, 5.0, 0.0), 0.0),
    ];
    for (name, point, hit_normal, normal, light_position, expected) in cases {
        let hit = Hit {
            t: 1.0,
            point,
            normal: hit_normal,
        };
        let got = shadow(
            &w,
            &hit,
            normal,
            &light(light_position),
            Offset::ScaleAware,
        );
        assert!(
            got == expected,
            "{name}: point {point}, hit.normal {hit_normal}, normal toward \
             the viewer {normal}, light {light_position}: expected S = \
             {expected} (judged on the viewer's side, by `normal`), got S = \
             {got}"
        );
    }
}

proptest! {
    #![proptest_config(seeded(256))]

    /// A sphere centred anywhere on the segment from a floor point to a
    /// light above it, small enough to hold neither, always casts its
    /// shadow there: S = 0. Without it the floor point is lit: S = 1.
    #[test]
    fn a_sphere_between_point_and_light_shadows_it(
        px in -10.0..10.0f64, pz in -10.0..10.0f64,
        lx in -10.0..10.0f64, ly in 0.5..10.0f64, lz in -10.0..10.0f64,
        along in 0.05..0.95f64, size in 0.01..0.99f64,
    ) {
        let floor = Shape::Plane { point: DVec3::ZERO, normal: DVec3::Y };
        let (point, light) = (v(px, 0.0, pz), v(lx, ly, lz));
        let center = point + along * (light - point);
        // at most `size` of the way to whichever end is nearer, and never
        // below the floor
        let radius = size * (light - point).length() * along.min(1.0 - along);
        let radius = radius.min(size * center.y);
        let blocked = world(vec![floor.clone(), Shape::Sphere { center, radius }]);
        let what = format!("the floor point {point}, the light {light}");
        let s_blocked = si(&blocked, point, DVec3::Y, light);
        prop_assert!(s_blocked == 0.0, "{what}, a ball of radius {radius} at {center} between them: expected S = 0 (in its shadow), got S = {s_blocked}");
        let s_open = si(&world(vec![floor]), point, DVec3::Y, light);
        prop_assert!(s_open == 1.0, "{what}, nothing between them: expected S = 1 (lit), got S = {s_open}");
    }
}

/// `scenes/two-lights.toml` at `width × height` (16:9, the file's own
/// proportion, which its camera was made for).
fn two_lights(width: u32, height: u32) -> World {
    let mut scene =
        raystep_scene::parse(ch04::TWO_LIGHTS_SCENE, "two-lights.toml")
            .unwrap();
    (scene.width, scene.height) = (width, height);
    ch03::world(&scene, "two-lights.toml").unwrap()
}

fn options(threads: usize) -> RenderOptions {
    RenderOptions {
        threads: Some(threads),
        progress: Progress::Never,
    }
}

/// Two lights, two shadows: the big sphere's shadows fall to its left
/// and right, each lit by the other light.
#[test]
fn two_lights_ascii() {
    let image =
        render(&two_lights(64, 36), Offset::ScaleAware, &options(2)).unwrap();
    insta::assert_snapshot!(image.to_ascii(64));
}

/// The rows run in parallel, but every pixel is computed the same way:
/// one thread or two, the same image bit for bit.
#[test]
fn renders_are_the_same_for_any_number_of_threads() {
    let w = two_lights(48, 27);
    let one = render(&w, Offset::ScaleAware, &options(1)).unwrap();
    let two = render(&w, Offset::ScaleAware, &options(2)).unwrap();
    let differing = differing_pixels(&one, &two);
    assert!(
        differing == 0,
        "pixels that differ between one thread and two: expected 0 (every \
         pixel is computed on its own), got {differing}"
    );
}

/// The render against its reference image (tests/images/two-lights.png),
/// within the default tolerance. RAYSTEP_BLESS=1 rewrites the reference.
#[test]
fn two_lights_image() {
    let image =
        render(&two_lights(160, 90), Offset::ScaleAware, &options(2)).unwrap();
    let expected = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/images/two-lights.png");
    assert_image_matches(&image, &expected, Tolerance::default());
}
