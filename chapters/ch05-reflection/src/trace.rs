//! The recursive tracer's state, and the tracer over a whole image.
use std::cell::RefCell;
use std::sync::Mutex;

use ch03::{World, render_with, shade_hit};
use ch04::{Offset, occluded, shadow_ray};
use raystep_core::{DVec3, Hit, Interval, Ray};
use raystep_render::{Image, RenderError, RenderOptions};

use crate::{LoggedRay, Path, RayCounts, RayLog, Stop};

// ANCHOR: tracer
/// One pixel's recursive trace: the world its rays are traced in, the
/// rules that stop the recursion, and a notebook of every ray it shoots.
///
/// The recursion itself is [`Tracer::trace`] (exercise 2). It asks the
/// tracer for each step (the closest hit, the local light, whether the
/// rules allow a ray), and the tracer notes each ray on the way, so the
/// counts and ray trees of the tests and figures stay out of the lecture's
/// code.
pub struct Tracer<'a> {
    /// The world the rays are traced in.
    pub world: &'a World,
    /// The rules that stop the recursion.
    pub stop: Stop,
    notebook: RefCell<RayLog>,
}
// ANCHOR_END: tracer

impl<'a> Tracer<'a> {
    /// A tracer in `world` under `stop` that counts its rays.
    pub fn new(world: &'a World, stop: Stop) -> Tracer<'a> {
        Tracer {
            world,
            stop,
            notebook: RefCell::new(RayLog::new()),
        }
    }

    /// A tracer that counts its rays and keeps each one (the ray tree).
    pub fn recording(world: &'a World, stop: Stop) -> Tracer<'a> {
        Tracer {
            world,
            stop,
            notebook: RefCell::new(RayLog::recording()),
        }
    }

    /// The rays traced so far, counted.
    pub fn counts(&self) -> RayCounts {
        self.notebook.borrow().counts
    }

    /// Every ray traced or cut, in order (empty unless recording).
    pub fn rays(self) -> Vec<LoggedRay> {
        self.notebook.into_inner().rays.unwrap_or_default()
    }

    // ANCHOR: steps
    /// Step 1 of every ray: the closest hit of `ray`, the ray at `path` in
    /// the tree, and the object hit.
    pub fn closest_hit(&self, ray: &Ray, path: Path) -> Option<(usize, Hit)> {
        let hit = self.world.closest_hit(ray, Interval::FORWARD);
        self.notebook
            .borrow_mut()
            .traced(path, ray, hit.map(|(_, h)| h.t));
        hit
    }

    /// Step 2: ka·Ia + Σᵢ Sᵢ·Iᵢ·[kd·(N·Lᵢ) + ks·(Rᵢ·V)^p] at `hit` on
    /// `object`, seen along `ray`: chapter 4's shading, with Sᵢ from a
    /// shadow ray that starts off the surface by the scale-aware offset.
    pub fn local_light(
        &self, ray: &Ray, hit: &Hit, object: usize, path: Path,
    ) -> DVec3 {
        let world = self.world;
        let terms = shade_hit(world, ray, hit, object, |hit, normal, light| {
            // A light behind the surface needs no ray (chapter 4, step 1).
            if normal.dot(light.position - hit.point) <= 0.0 {
                return 0.0;
            }
            let (shadow, interval) = shadow_ray(
                hit.point,
                normal,
                light.position,
                Offset::ScaleAware,
            );
            let blocked = occluded(world, &shadow, interval);
            self.notebook.borrow_mut().shadow(
                path,
                &shadow,
                interval.max,
                blocked,
            );
            if blocked { 0.0 } else { 1.0 }
        });
        terms.sum()
    }

    /// Step 4: do the stopping rules let `ray`, at `path` in the tree, be
    /// shot? If not, the rule that cut it is noted.
    pub fn allows(&self, ray: &Ray, path: Path) -> bool {
        match self.stop.cut(path) {
            Some(cut) => {
                self.notebook.borrow_mut().cut(path, ray, cut);
                false
            }
            None => true,
        }
    }
    // ANCHOR_END: steps
}

// ANCHOR: render
/// For each pixel on screen: trace the primary ray recursively under
/// `stop`. Returns the image and every ray it took. Rows run in parallel;
/// image and counts are the same for any number of threads.
pub fn render(
    world: &World, stop: &Stop, options: &RenderOptions,
) -> Result<(Image, RayCounts), RenderError> {
    let total = Mutex::new(RayCounts::default());
    let image = render_with(world, options, |ray| {
        let tracer = Tracer::new(world, *stop);
        let colour = tracer.trace(ray, Path::PRIMARY);
        *total.lock().unwrap_or_else(|e| e.into_inner()) += tracer.counts();
        colour
    })?;
    Ok((image, total.into_inner().unwrap_or_else(|e| e.into_inner())))
}
// ANCHOR_END: render

/// The colour of one primary `ray` under `stop`, and the rays it took.
pub fn trace_counted(
    world: &World, ray: &Ray, stop: &Stop,
) -> (DVec3, RayCounts) {
    let tracer = Tracer::new(world, *stop);
    let colour = tracer.trace(ray, Path::PRIMARY);
    (colour, tracer.counts())
}

/// The ray tree of one primary `ray`: every ray its trace shot or cut, in
/// order.
pub fn ray_tree(world: &World, ray: &Ray, stop: &Stop) -> Vec<LoggedRay> {
    let tracer = Tracer::recording(world, *stop);
    tracer.trace(ray, Path::PRIMARY);
    tracer.rays()
}

/// The ray tree of one pixel (see [`ray_tree`]).
pub fn pixel_tree(
    world: &World, column: u32, row: u32, stop: &Stop,
) -> Vec<LoggedRay> {
    let ray = world
        .camera
        .pixel_ray(column, row, world.width, world.height);
    ray_tree(world, &ray, stop)
}
