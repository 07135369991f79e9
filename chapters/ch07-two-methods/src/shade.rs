//! Both methods shade a pixel the same way: chapter 3's local model,
//! every light visible.
use ch03::World;
use raystep_core::{DVec3, Hit, Ray};
use raystep_render::Rgb;

// ANCHOR: shade_pixel
/// The colour of object `object` of `world`, whose unit normal there is
/// `normal`, where the pixel's ray `ray` meets it at distance `t`:
/// chapter 3's local model with every light
/// visible (Sᵢ = 1). Rasterization alone knows nothing of other objects
/// when it shades a pixel, so it has no shadow rays, and no reflected or
/// refracted rays either; the ray caster is held to the same rule here.
pub fn shade_pixel(
    world: &World, ray: &Ray, t: f64, object: usize, normal: DVec3,
) -> Rgb {
    let hit = Hit {
        t,
        point: ray.at(t),
        normal,
    };
    ch03::shade_hit(world, ray, &hit, object, |_, _, _| 1.0).sum()
}
// ANCHOR_END: shade_pixel
