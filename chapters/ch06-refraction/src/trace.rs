//! The whole recursive tracer: local light, kr·Lr and kt·Lt.
use std::cell::Cell;
use std::sync::Mutex;

use ch03::{World, render_with};
use ch04::offset_scale_aware;
use ch05::{LoggedRay, Path, Stop, reflect_ray};
use raystep_core::{DVec3, Ray};
use raystep_render::{Image, RenderError, RenderOptions};

use crate::{Fresnel, Media, refract};

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

/// The rays of a trace with refraction, counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts {
    /// Primary rays.
    pub primary: u64,
    /// Shadow rays.
    pub shadow: u64,
    /// Reflected rays.
    pub reflected: u64,
    /// Transmitted (refracted) rays.
    pub transmitted: u64,
    /// Rays not shot because of rule 1 (the maximum depth).
    pub cut_by_depth: u64,
    /// Rays not shot because of rule 2 (contribution below threshold).
    pub cut_by_contribution: u64,
    /// Refractions that found total internal reflection.
    pub total_internal_reflections: u64,
    /// Surfaces crossed against the medium bookkeeping: a ray leaving an
    /// object it was not inside, or entering one it was.
    pub medium_mismatches: u64,
}

impl RayCounts {
    /// Every ray shot, of every kind.
    pub fn total(&self) -> u64 {
        self.primary + self.shadow + self.reflected + self.transmitted
    }
}

impl std::ops::AddAssign for RayCounts {
    fn add_assign(&mut self, other: RayCounts) {
        self.primary += other.primary;
        self.shadow += other.shadow;
        self.reflected += other.reflected;
        self.transmitted += other.transmitted;
        self.cut_by_depth += other.cut_by_depth;
        self.cut_by_contribution += other.cut_by_contribution;
        self.total_internal_reflections += other.total_internal_reflections;
        self.medium_mismatches += other.medium_mismatches;
    }
}

/// One pixel's trace with refraction: chapter 5's [`ch05::Tracer`] (the
/// world, the stopping rules, the notebook of rays), the Fresnel split,
/// and the counts only refraction has.
pub struct Tracer<'a> {
    /// Chapter 5's tracer: the closest hit, the local light and the
    /// stopping rules, each ray noted.
    pub rays: ch05::Tracer<'a>,
    /// How light splits between the reflected and the transmitted ray.
    pub fresnel: Fresnel,
    transmitted: Cell<u64>,
    total_internal_reflections: Cell<u64>,
    medium_mismatches: Cell<u64>,
}

impl<'a> Tracer<'a> {
    /// A tracer that counts its rays.
    pub fn new(world: &'a World, stop: Stop, fresnel: Fresnel) -> Tracer<'a> {
        Tracer::with(ch05::Tracer::new(world, stop), fresnel)
    }

    /// A tracer that counts its rays and keeps each one (the ray tree).
    pub fn recording(
        world: &'a World, stop: Stop, fresnel: Fresnel,
    ) -> Tracer<'a> {
        Tracer::with(ch05::Tracer::recording(world, stop), fresnel)
    }

    fn with(rays: ch05::Tracer<'a>, fresnel: Fresnel) -> Tracer<'a> {
        Tracer {
            rays,
            fresnel,
            transmitted: Cell::new(0),
            total_internal_reflections: Cell::new(0),
            medium_mismatches: Cell::new(0),
        }
    }

    /// The rays traced so far, counted.
    pub fn counts(&self) -> RayCounts {
        let rays = self.rays.counts();
        let transmitted = self.transmitted.get();
        RayCounts {
            primary: rays.primary,
            shadow: rays.shadow,
            // chapter 5 counts every secondary ray; these were not reflected
            reflected: rays.secondary - transmitted,
            transmitted,
            cut_by_depth: rays.cut_by_depth,
            cut_by_contribution: rays.cut_by_contribution,
            total_internal_reflections: self.total_internal_reflections.get(),
            medium_mismatches: self.medium_mismatches.get(),
        }
    }

    /// Every ray traced or cut, in order (empty unless recording).
    pub fn ray_tree(self) -> Vec<LoggedRay> {
        self.rays.rays()
    }

    fn add(counter: &Cell<u64>) {
        counter.set(counter.get() + 1);
    }

    // ANCHOR: trace
    /// The colour seen along `ray`, a ray at `path` in its pixel's tree,
    /// travelling through `media`:
    ///
    /// L = local + kr·Lr + kt·Lt
    ///
    /// (with the Fresnel split of `self.fresnel`), Lr and Lt traced by this
    /// same method unless the stopping rules cut them.
    pub fn trace(&self, ray: &Ray, path: Path, media: &Media) -> DVec3 {
        let world = self.rays.world;
        // Step 1: the closest hit; a miss sees the background.
        let Some((object, hit)) = self.rays.closest_hit(ray, path) else {
            return world.background;
        };
        // Step 2: the local model with shadows (chapters 3–4).
        let mut colour = self.rays.local_light(ray, &hit, object, path);
        let material = world.material_of(object);
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
            let crossing = media.cross(object, material.ior, entering);
            if !crossing.consistent {
                Tracer::add(&self.medium_mismatches);
            }
            Some(crossing)
        };
        // Step 4: Snell's law for the transmitted direction (None: total
        // internal reflection), and the split of the light between the rays.
        let transmitted = crossing.and_then(|c| {
            let t = refract(direction, normal, c.n_theta, c.n_phi);
            if t.is_none() {
                Tracer::add(&self.total_internal_reflections);
            }
            t.map(|t| (t, c))
        });
        let r = match (transmitted, crossing) {
            (Some(_), Some(c)) => self.fresnel.reflectance(
                -direction.dot(normal),
                c.n_theta,
                c.n_phi,
            ),
            _ => 0.0,
        };
        let (wr, wt) =
            split(kr, kt, r, transmitted.is_some() || kt == DVec3::ZERO);
        // Step 5: kr·Lr, the reflected ray, on the ray's side of the surface,
        // in the same media.
        if wr != DVec3::ZERO {
            let reflected = Ray::new(
                offset_scale_aware(hit.point, normal),
                reflect_ray(direction, normal),
            );
            let next = path.then(wr);
            if self.rays.allows(&reflected, next) {
                colour += wr * self.trace(&reflected, next, media);
            }
        }
        // Step 6: kt·Lt, the transmitted ray, on the far side, in the media
        // beyond the surface.
        if let Some((t, c)) = transmitted {
            let transmitted =
                Ray::new(offset_scale_aware(hit.point, -normal), t);
            let next = path.then(wt);
            if self.rays.allows(&transmitted, next) {
                Tracer::add(&self.transmitted);
                colour += wt * self.trace(&transmitted, next, &c.beyond);
            }
        }
        colour
    }
    // ANCHOR_END: trace
}

// ANCHOR: render
/// For each pixel on screen: trace the primary ray with reflection and
/// refraction under `stop`, splitting light by `fresnel`. Returns the
/// image and every ray it took; both are the same for any number of
/// threads.
pub fn render(
    world: &World, stop: &Stop, fresnel: Fresnel, options: &RenderOptions,
) -> Result<(Image, RayCounts), RenderError> {
    let total = Mutex::new(RayCounts::default());
    let media = Media::new(CAMERA_MEDIUM);
    let image = render_with(world, options, |ray| {
        let tracer = Tracer::new(world, *stop, fresnel);
        let colour = tracer.trace(ray, Path::PRIMARY, &media);
        *total.lock().unwrap_or_else(|e| e.into_inner()) += tracer.counts();
        colour
    })?;
    Ok((image, total.into_inner().unwrap_or_else(|e| e.into_inner())))
}
// ANCHOR_END: render

/// The ray tree of one pixel: every ray its trace shot or cut, in order.
pub fn pixel_tree(
    world: &World, column: u32, row: u32, stop: &Stop, fresnel: Fresnel,
) -> Vec<LoggedRay> {
    let ray = world
        .camera
        .pixel_ray(column, row, world.width, world.height);
    let tracer = Tracer::recording(world, *stop, fresnel);
    tracer.trace(&ray, Path::PRIMARY, &Media::new(CAMERA_MEDIUM));
    tracer.ray_tree()
}
