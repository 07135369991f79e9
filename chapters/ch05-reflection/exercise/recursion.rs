//! Exercise 2 (★★): the recursive tracer with both stopping rules.
// You will need: crate::reflect_ray, ch04::offset_scale_aware.
use crate::{Path, Tracer};
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
        // TODO:
        // 1. The closest hit: self.closest_hit(ray, path). A ray that hits
        //    nothing sees self.world.background.
        // 2. The local model with shadows:
        //    colour = self.local_light(ray, &hit, object, path).
        // 3. kr = self.world.material_of(object).kr. If it is zero, return
        //    the colour. Otherwise the reflected ray starts off the surface
        //    on the side the ray came from,
        //    offset_scale_aware(hit.point, normal) with
        //    normal = hit.facing(ray.direction), and goes
        //    reflect_ray(ray.direction, normal).
        // 4. Its path is next = path.then(kr). If self.allows(&reflected,
        //    next) (not too deep, not worth too little), add
        //    kr * self.trace(&reflected, next): the recursion.
        let _ = (ray, path);
        todo!("ch05 exercise 2: trace")
    }
    // ANCHOR_END: trace
}
