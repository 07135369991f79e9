//! Exercise 2: the recursive tracer with both stopping rules.
use crate::{Path, RayKind, RayLog, Stop, local_light, reflect_direction};
use ch03::World;
use ch04::offset_scale_aware;
use raystep_core::{DVec3, Interval, Ray};

// ANCHOR: trace
/// The colour seen along `ray`, a ray at `path` in its pixel's tree:
///
/// L = [ka·Ia + Σᵢ Sᵢ·Iᵢ·(kd·(N·Lᵢ) + ks·(Rᵢ·V)^p)] + kr·Lr
///
/// where Lr is what the reflected ray sees, traced by this same function
/// one level deeper, unless `stop` cuts it. Every ray traced or cut is
/// noted in `log` with its kind (`kind` is this ray's).
pub fn trace(
    world: &World,
    ray: &Ray,
    kind: RayKind,
    path: Path,
    stop: &Stop,
    log: &mut RayLog,
) -> DVec3 {
    // Step 1: the closest hit; a ray that hits nothing sees the background.
    let Some((hit, object)) = world.closest_hit(ray, Interval::FORWARD) else {
        log.traced(kind, path, ray, None);
        return world.background;
    };
    log.traced(kind, path, ray, Some(hit.t));
    // Step 2: the local model with shadows (chapters 03–04).
    let mut colour = local_light(world, ray, &hit, object, path, log);
    // Step 3: a mirror (kr > 0) adds kr·Lr. The reflected ray leaves from
    // the side the ray came from, off the surface (chapter 04's offset).
    let kr = world.materials[object.material].kr;
    if kr == DVec3::ZERO {
        return colour;
    }
    let normal = hit.facing(ray.direction);
    let reflected = Ray::new(
        offset_scale_aware(hit.point, normal),
        reflect_direction(ray.direction, normal),
    );
    // Step 4: the stopping rules: is the reflected ray too deep, or worth
    // too little? Then Lr counts as 0.
    let next = path.then(kr);
    match stop.cut(next) {
        Some(cut) => log.cut(RayKind::Reflected, next, &reflected, cut),
        None => colour += kr * trace(world, &reflected, RayKind::Reflected, next, stop, log),
    }
    colour
}
// ANCHOR_END: trace
