use crate::{LightSample, ShadingTerms, World, shading_terms};
use raystep_core::{DVec3, Hit, Interval, Ray};
use raystep_render::{Image, RenderError, RenderOptions};
use raystep_scene::{Light, Material};

// ANCHOR: shade
/// The local model's terms where `ray` first hits the world, or None if it
/// hits nothing. Every light counts as visible (Sᵢ = 1): shadows are
/// chapter 4.
pub fn shade(world: &World, ray: &Ray) -> Option<ShadingTerms> {
    shade_with(world, ray, |_, _, _| 1.0)
}

/// [`shade`] with Sᵢ from `visibility(hit, normal, light)`, where `normal`
/// is the hit's normal turned toward the viewer. Chapter 4 passes its
/// shadow rays here.
pub fn shade_with(
    world: &World, ray: &Ray, visibility: impl Fn(&Hit, DVec3, &Light) -> f64,
) -> Option<ShadingTerms> {
    // Step 1: the closest hit, and which object it is on.
    let (object, hit) = world.closest_hit(ray, Interval::FORWARD)?;
    Some(shade_hit(world, ray, &hit, object, visibility))
}

/// Steps 2–4 of [`shade_with`] for a hit already found: the local model's
/// terms at `hit` on object `object` (its index in `world.objects`), seen
/// along `ray`. Chapters 5–6 call it
/// at every bounce of a recursive ray.
pub fn shade_hit(
    world: &World, ray: &Ray, hit: &Hit, object: usize,
    visibility: impl Fn(&Hit, DVec3, &Light) -> f64,
) -> ShadingTerms {
    let material = world.material_of(object);
    // (A checkered material swaps its ka and kd on every other cube.)
    let patterned;
    let material = match material.checker {
        None => material,
        Some(_) => {
            let (ka, kd) = material.ka_kd_at(hit.point);
            patterned = Material {
                ka,
                kd,
                ..material.clone()
            };
            &patterned
        }
    };
    // Step 2: N facing the viewer (planes and polygons have two sides), and
    // V, the unit direction back to the eye.
    let to_eye = -ray.direction.normalize();
    let normal = hit.facing(ray.direction);
    // Step 3: Lᵢ, Iᵢ and Sᵢ for every light.
    let lights: Vec<LightSample> = world
        .lights
        .iter()
        .map(|light| LightSample {
            direction: (light.position - hit.point).normalize(),
            intensity: light.intensity,
            visibility: visibility(hit, normal, light),
        })
        .collect();
    // Step 4: the local model.
    shading_terms(material, normal, to_eye, world.ambient, &lights)
}
// ANCHOR_END: shade

/// The colour seen along `ray`: the local model's sum, the background for
/// a miss.
pub fn trace(world: &World, ray: &Ray) -> DVec3 {
    shade(world, ray).map_or(world.background, |terms| terms.sum())
}

/// Which of the model's terms a render shows (the figures' panels).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Terms {
    /// ka·Ia only.
    Ambient,
    /// Ambient and diffuse.
    AmbientDiffuse,
    /// The whole local model.
    All,
}

impl Terms {
    /// The chosen terms' sum.
    pub fn pick(self, t: &ShadingTerms) -> DVec3 {
        match self {
            Terms::Ambient => t.ambient,
            Terms::AmbientDiffuse => t.ambient + t.diffuse,
            Terms::All => t.sum(),
        }
    }
}

// ANCHOR: render
/// For each pixel on screen: shoot a ray through its centre and shade what
/// it hits first. Rows run in parallel; the image is the same for any
/// number of threads.
pub fn render(
    world: &World, terms: Terms, options: &RenderOptions,
) -> Result<Image, RenderError> {
    render_with(world, options, |ray| {
        shade(world, ray).map_or(world.background, |t| terms.pick(&t))
    })
}
// ANCHOR_END: render

/// The pixel loop of [`render`] with any colour function of the primary
/// ray (later chapters pass their own tracers).
pub fn render_with(
    world: &World, options: &RenderOptions,
    colour: impl Fn(&Ray) -> DVec3 + Sync,
) -> Result<Image, RenderError> {
    raystep_render::render(world.width, world.height, options, |column, row| {
        colour(
            &world
                .camera
                .pixel_ray(column, row, world.width, world.height),
        )
    })
}
