//! Measuring acne and leaks: each strategy's Sᵢ against the truth.
use crate::{Offset, shadow_ray};
use ch03::World;
use raystep_core::{DVec3, Interval, Ray};

/// How often a strategy gets a shadow wrong (see [`shadow_errors`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ShadowErrors {
    /// The pixel–light pairs judged: the primary ray hits something and the
    /// light is in front of the surface (N·L > 0). With one light, pixels.
    pub pixels: usize,
    /// Acne: the truth is lit, the strategy's shadow ray is blocked (the
    /// surface shadows itself, or the origin was pushed into a neighbour).
    pub acne: usize,
    /// Leaks: the truth is in shadow, the strategy's shadow ray is not (it
    /// skipped a blocker close to the point).
    pub leaks: usize,
}

impl ShadowErrors {
    /// `acne / pixels` (0 when nothing was judged).
    pub fn acne_fraction(&self) -> f64 {
        fraction(self.acne, self.pixels)
    }

    /// `leaks / pixels` (0 when nothing was judged).
    pub fn leak_fraction(&self) -> f64 {
        fraction(self.leaks, self.pixels)
    }
}

fn fraction(count: usize, of: usize) -> f64 {
    if of == 0 {
        0.0
    } else {
        count as f64 / of as f64
    }
}

/// What a strategy makes of one pixel–light pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The primary ray hits nothing, or the light is behind the surface:
    /// in shadow whatever the strategy does, nothing to judge.
    Unjudged,
    /// The strategy agrees with the truth.
    Right,
    /// The truth is lit, the strategy's shadow ray is blocked.
    Acne,
    /// The truth is in shadow, the strategy's shadow ray is not.
    Leak,
}

// ANCHOR: shadow_errors
/// Judges the strategy `offset` where the primary ray `ray` first hits
/// `world`, for the light at `light`.
///
/// The truth is a shadow ray from the unmoved point that ignores the
/// object it starts on. For spheres and planes that is exact: a convex
/// surface cannot shadow itself where N·L > 0 (the ray leaves it and never
/// comes back), so skipping it removes the acne and nothing else. (A
/// polygon could not be skipped so lightly in a mesh, where its neighbours
/// are the same surface.)
pub fn verdict(
    world: &World, ray: &Ray, light: DVec3, offset: Offset,
) -> Verdict {
    let Some((object, hit)) = world.closest_hit(ray, Interval::FORWARD) else {
        return Verdict::Unjudged;
    };
    // N facing the viewer, as the shader uses it
    let normal = if hit.normal.dot(ray.direction) > 0.0 {
        -hit.normal
    } else {
        hit.normal
    };
    let to_light = light - hit.point;
    if normal.dot(to_light) <= 0.0 {
        return Verdict::Unjudged; // behind the surface: in shadow either way
    }
    // the truth: every object but this one, from the point itself
    let truth_blocked =
        blocked_by_another(world, &Ray::new(hit.point, to_light), object);
    // the strategy: every object, from where it starts the ray
    let (strategy_ray, interval) = shadow_ray(hit.point, normal, light, offset);
    match (
        truth_blocked,
        crate::occluded(world, &strategy_ray, interval),
    ) {
        (false, true) => Verdict::Acne,
        (true, false) => Verdict::Leak,
        _ => Verdict::Right,
    }
}

/// Does an object other than `own` meet `ray` for t in [0, 1]? The closest
/// hits in turn: each one on `own` (its surface a rounding error away from
/// the ray's start) is stepped past, and the first hit on another object
/// answers.
fn blocked_by_another(world: &World, ray: &Ray, own: usize) -> bool {
    let mut interval = Interval::new(0.0, 1.0);
    while let Some((object, hit)) = world.closest_hit(ray, interval) {
        if object != own {
            return true;
        }
        interval.min = hit.t.next_up();
    }
    false
}

/// The [`verdict`] of `offset` at every pixel–light pair of `world`, one
/// primary ray per pixel, counted.
pub fn shadow_errors(world: &World, offset: Offset) -> ShadowErrors {
    let mut errors = ShadowErrors::default();
    for row in 0..world.height {
        for column in 0..world.width {
            let ray =
                world
                    .camera
                    .pixel_ray(column, row, world.width, world.height);
            for light in &world.lights {
                match verdict(world, &ray, light.position, offset) {
                    Verdict::Unjudged => continue,
                    Verdict::Right => {}
                    Verdict::Acne => errors.acne += 1,
                    Verdict::Leak => errors.leaks += 1,
                }
                errors.pixels += 1;
            }
        }
    }
    errors
}
// ANCHOR_END: shadow_errors
