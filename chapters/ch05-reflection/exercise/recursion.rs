//! Exercise 2: the recursive tracer with both stopping rules.
// You will need: crate::{local_light, reflect_direction},
// ch04::offset_scale_aware, raystep_core::Interval.
use crate::{Path, RayKind, RayLog, Stop};
use ch03::World;
use raystep_core::{DVec3, Ray};

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
    // TODO:
    // 1. world.closest_hit(ray, Interval::FORWARD). On a miss, note the ray
    //    with log.traced(kind, path, ray, None) and return world.background;
    //    on a hit note it with Some(hit.t).
    // 2. colour = local_light(world, ray, &hit, object, path, log).
    // 3. kr = the object's material's kr. If it is zero, return colour.
    //    Otherwise the reflected ray starts at
    //    offset_scale_aware(hit.point, normal) with normal = hit.facing(ray.direction),
    //    in the direction reflect_direction(ray.direction, normal).
    // 4. next = path.then(kr). If stop.cut(next) names a rule, note it with
    //    log.cut(RayKind::Reflected, next, &reflected, cut) and Lr = 0;
    //    otherwise add kr * trace(.., RayKind::Reflected, next, ..).
    let _ = (world, ray, kind, path, stop, log);
    todo!("ch05 exercise 2: trace")
}
// ANCHOR_END: trace
