//! The chapter's scenes, and the acne scene at any scale.
use ch03::World;
use raystep_scene::Scene;

/// `scenes/acne.toml`: spheres resting on a floor, one light, at scale 1.
pub const ACNE_SCENE: &str = include_str!("../scenes/acne.toml");
/// `scenes/two-lights.toml`: spheres on a floor, two lights, two shadows.
pub const TWO_LIGHTS_SCENE: &str = include_str!("../scenes/two-lights.toml");

// ANCHOR: scaled
/// `scene` scaled by `scale` about the origin: every position and size
/// (objects, lights, the eye and the point looked at) times `scale`. The
/// picture stays the same; only the numbers the computer works with grow
/// or shrink.
pub fn scaled(scene: &Scene, scale: f64) -> Scene {
    let mut scene = scene.clone();
    for object in &mut scene.objects {
        object.shape.scale(scale);
    }
    for light in &mut scene.lights {
        light.position *= scale;
    }
    scene.camera.look_from *= scale;
    scene.camera.look_at *= scale;
    scene
}
// ANCHOR_END: scaled

/// The acne scene (`scenes/acne.toml`) scaled by `scale` about the
/// origin, at the file's image size (to render it smaller, set `width` and
/// `height` in the same 16:9 proportion, which the camera was made for).
///
/// The scene's origin is the centre of its middle sphere and its floor is
/// at y = −1, not 0: see [`offset_scale_aware`](crate::offset_scale_aware)
/// for why a floor through the origin defeats the scale-aware offset in a
/// huge scene.
///
/// # Panics
///
/// If `scale` is not positive and finite.
pub fn scaled_scene(scale: f64) -> World {
    assert!(scale.is_finite() && scale > 0.0, "scale {scale}");
    let scene = raystep_scene::parse(ACNE_SCENE, "acne.toml")
        .expect("acne.toml is valid");
    ch03::world(&scaled(&scene, scale), "acne.toml")
        .expect("acne.toml has no polygons")
}
