//! Exercise 2: the recursive tracer with both stopping rules.
use crate::{Path, Tracer, reflect_ray};
use ch04::offset_scale_aware;
use raystep_core::{DVec3, Ray};

impl Tracer<'_> {
    // ANCHOR: trace
    /// The colour seen along `ray`, a ray at `path` in its pixel's tree:
    ///
    /// L = [ka·Ia + Σᵢ Sᵢ·Iᵢ·(kd·(N·Lᵢ) + ks·(Rᵢ·V)^p)] + kr·Lr
    ///
    /// where Lr is what the reflected ray sees, traced by this same method
    /// one level deeper, unless the stopping rules cut it.
    pub fn trace(&self, ray: &Ray, path: Path) -> DVec3 {
        // Step 1: the closest hit; a ray that hits nothing sees the background.
        let Some((object, hit)) = self.closest_hit(ray, path) else {
            return self.world.background;
        };
        // Step 2: the local model with shadows (chapters 3–4).
        let mut colour = self.local_light(ray, &hit, object, path);
        // Step 3: a mirror (kr > 0) adds kr·Lr. The reflected ray leaves
        // from the side the ray came from, off the surface (chapter 4's
        // offset).
        let kr = self.world.material_of(object).kr;
        if kr == DVec3::ZERO {
            return colour;
        }
        let normal = hit.facing(ray.direction);
        let reflected = Ray::new(
            offset_scale_aware(hit.point, normal),
            reflect_ray(ray.direction, normal),
        );
        // Step 4: the stopping rules: is the reflected ray too deep, or
        // worth too little? Then Lr counts as 0.
        let next = path.then(kr);
        if self.allows(&reflected, next) {
            colour += kr * self.trace(&reflected, next);
        }
        colour
    }
    // ANCHOR_END: trace
}
