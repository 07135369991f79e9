//! The whole recursive tracer: local light, kr·Lr and kt·Lt.
use crate::{Fresnel, Media, refract};
use ch03::World;
use ch04::offset_scale_aware;
use ch05::{Path, RayKind, RayLog, Stop, local_light, reflect_direction};
use raystep_core::{DVec3, Interval, Ray};

/// The index of refraction of the medium the camera is in (vacuum).
pub const CAMERA_MEDIUM: f64 = 1.0;

// ANCHOR: split
/// How a surface with reflectance `kr` and transmittance `kt` splits a ray:
/// the weights (wr, wt) of the reflected and transmitted rays, given the
/// Fresnel reflectance `r` of its transparent part, and whether a
/// transmitted ray exists at all (not past the critical angle).
///
/// wr = kr + kt·R and wt = kt·(1 − R); on total internal reflection the
/// transmitted share turns into reflection: wr = kr + kt, wt = 0. Either
/// way wr + wt = kr + kt: splitting a ray creates no light.
pub fn split(kr: DVec3, kt: DVec3, r: f64, transmits: bool) -> (DVec3, DVec3) {
    if transmits {
        (kr + kt * r, kt * (1.0 - r))
    } else {
        (kr + kt, DVec3::ZERO)
    }
}
// ANCHOR_END: split

// ANCHOR: trace
/// The colour seen along `ray`, a ray of `kind` at `path` in its pixel's
/// tree, travelling through `media`:
///
/// L = local + kr·Lr + kt·Lt
///
/// (with the Fresnel split of `fresnel`), Lr and Lt traced by this same
/// function unless `stop` cuts them.
#[allow(clippy::too_many_arguments)] // the tree's state, spelled out
pub fn trace(
    world: &World,
    ray: &Ray,
    kind: RayKind,
    path: Path,
    media: &Media,
    stop: &Stop,
    fresnel: Fresnel,
    log: &mut RayLog,
) -> DVec3 {
    // Step 1: the closest hit; a miss sees the background.
    let Some((hit, object)) = world.closest_hit(ray, Interval::FORWARD) else {
        log.traced(kind, path, ray, None);
        return world.background;
    };
    log.traced(kind, path, ray, Some(hit.t));
    // Step 2: the local model with shadows (chapters 03–04).
    let mut colour = local_light(world, ray, &hit, object, path, log);
    let material = &world.materials[object.material];
    let (kr, kt) = (material.kr, material.kt);
    if kr == DVec3::ZERO && kt == DVec3::ZERO {
        return colour;
    }
    // Step 3: entering or leaving? The surface's own normal points out of
    // the object: against it, the ray enters. `normal` is on the ray's
    // side either way (the lecture's "flip the normal").
    let direction = ray.direction.normalize();
    let normal = hit.facing(direction);
    let entering = hit.normal.dot(direction) < 0.0;
    let crossing = if kt == DVec3::ZERO {
        None // an opaque mirror: nothing crosses
    } else {
        let index = world
            .objects
            .iter()
            .position(|o| std::ptr::eq(o, object))
            .expect("closest_hit returns one of the world's objects");
        let crossing = media.cross(index, material.ior, entering);
        if !crossing.consistent {
            log.counts.medium_mismatches += 1;
        }
        Some(crossing)
    };
    // Step 4: Snell's law for the transmitted direction (None: total
    // internal reflection), and the split of the light between the rays.
    let transmitted = crossing.and_then(|c| {
        let t = refract(direction, normal, c.n_theta, c.n_phi);
        if t.is_none() {
            log.counts.total_internal_reflections += 1;
        }
        t.map(|t| (t, c))
    });
    let r = match (transmitted, crossing) {
        (Some(_), Some(c)) => fresnel.reflectance(-direction.dot(normal), c.n_theta, c.n_phi),
        _ => 0.0,
    };
    let (wr, wt) = split(kr, kt, r, transmitted.is_some() || kt == DVec3::ZERO);
    // Step 5: kr·Lr, the reflected ray, on the ray's side of the surface,
    // in the same media.
    if wr != DVec3::ZERO {
        let reflected = Ray::new(
            offset_scale_aware(hit.point, normal),
            reflect_direction(direction, normal),
        );
        let next = path.then(wr);
        match stop.cut(next) {
            Some(cut) => log.cut(RayKind::Reflected, next, &reflected, cut),
            None => {
                colour += wr
                    * trace(
                        world,
                        &reflected,
                        RayKind::Reflected,
                        next,
                        media,
                        stop,
                        fresnel,
                        log,
                    );
            }
        }
    }
    // Step 6: kt·Lt, the transmitted ray, on the far side, in the media
    // beyond the surface.
    if let Some((t, c)) = transmitted {
        let transmitted = Ray::new(offset_scale_aware(hit.point, -normal), t);
        let next = path.then(wt);
        match stop.cut(next) {
            Some(cut) => log.cut(RayKind::Transmitted, next, &transmitted, cut),
            None => {
                colour += wt
                    * trace(
                        world,
                        &transmitted,
                        RayKind::Transmitted,
                        next,
                        &c.beyond,
                        stop,
                        fresnel,
                        log,
                    );
            }
        }
    }
    colour
}
// ANCHOR_END: trace
