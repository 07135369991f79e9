//! The local model with shadows at one hit (chapters 03–04), its shadow
//! rays counted.
use crate::{Path, RayLog};
use ch03::{Object, World, shade_hit};
use ch04::{Offset, occluded, shadow_ray};
use raystep_core::{DVec3, Hit, Ray};
use std::cell::RefCell;

// ANCHOR: local_light
/// ka·Ia + Σᵢ Sᵢ·Iᵢ·[kd·(N·Lᵢ) + ks·(Rᵢ·V)^p] at `hit` on `object`, seen
/// along `ray`: chapter 04's shading, with Sᵢ from a shadow ray that
/// starts off the surface by the scale-aware offset. Every shadow ray shot
/// is noted in `log` at `path`.
pub fn local_light(
    world: &World,
    ray: &Ray,
    hit: &Hit,
    object: &Object,
    path: Path,
    log: &mut RayLog,
) -> DVec3 {
    let log = RefCell::new(log);
    let terms = shade_hit(world, ray, hit, object, |hit, normal, light| {
        // A light behind the surface needs no ray (chapter 04, step 1).
        if normal.dot(light.position - hit.point) <= 0.0 {
            return 0.0;
        }
        let (shadow, interval) = shadow_ray(hit.point, normal, light.position, Offset::ScaleAware);
        let blocked = occluded(world, &shadow, interval);
        log.borrow_mut()
            .shadow(path, &shadow, interval.max, blocked);
        if blocked { 0.0 } else { 1.0 }
    });
    terms.sum()
}
// ANCHOR_END: local_light
