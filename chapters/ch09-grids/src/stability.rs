//! Rays exactly where a grid walk can go wrong: along the lines and in
//! the planes between cells, through their corners and edges, starting
//! on a plane or inside the grid, parallel to an axis (with −0.0 too),
//! grazing the grid's box. Seeded, so every run asks the same rays.
use ch08::SplitMix64;
use raystep_core::{DVec3, Ray};

use crate::Lattice;

/// One kind of dangerous ray, and a set of them.
#[derive(Clone, Debug)]
pub struct RayCase {
    /// What makes these rays dangerous, for tables.
    pub name: &'static str,
    /// The rays.
    pub rays: Vec<Ray>,
}

/// `per_case` rays of each dangerous kind for the grid `lattice`.
pub fn adversarial_rays(
    lattice: &Lattice,
    per_case: usize,
    seed: u64,
) -> Vec<RayCase> {
    let mut random = SplitMix64::new(seed);
    let b = lattice.bounds;
    let (centre, size) = (0.5 * (b.min + b.max), b.max - b.min);
    let far = 2.0 * size.length().max(1e-300);
    // a plane between cells (or a face of the box) along `axis`
    let plane = |r: &mut SplitMix64, axis: usize| {
        let n = lattice.cells[axis];
        lattice.plane(axis, (r.next_u64() % (n as u64 + 1)) as usize)
    };
    // a point inside the box
    let inside = |r: &mut SplitMix64| {
        b.min + DVec3::new(r.next_f64(), r.next_f64(), r.next_f64()) * size
    };
    // from far outside at `target`
    let aimed = |r: &mut SplitMix64, target: DVec3| {
        let origin = centre + far * r.unit_vector();
        Ray::new(origin, target - origin)
    };
    let axis_of = |r: &mut SplitMix64| (r.next_u64() % 3) as usize;
    let signed_unit = |r: &mut SplitMix64, axis: usize| {
        let mut d =
            DVec3::splat(if r.next_u64() % 2 == 0 { 0.0 } else { -0.0 });
        d[axis] = if r.next_u64() % 2 == 0 { 1.0 } else { -1.0 };
        d
    };
    let mut case =
        |name, make: &mut dyn FnMut(&mut SplitMix64) -> Ray| RayCase {
            name,
            rays: (0..per_case).map(|_| make(&mut random)).collect(),
        };
    vec![
        case("along a line between cells", &mut |r| {
            // two coordinates on planes, the ray along the third axis
            let axis = axis_of(r);
            let mut origin = inside(r);
            for other in [(axis + 1) % 3, (axis + 2) % 3] {
                origin[other] = plane(r, other);
            }
            origin[axis] = centre[axis] - far * 0.5;
            Ray::new(origin, signed_unit(r, axis).abs())
        }),
        case("in a plane between cells", &mut |r| {
            let axis = axis_of(r);
            let mut origin = centre + far * r.unit_vector();
            origin[axis] = plane(r, axis);
            let mut target = inside(r);
            target[axis] = origin[axis];
            Ray::new(origin, target - origin)
        }),
        case("through a cell corner", &mut |r| {
            let corner = DVec3::from_array([0, 1, 2].map(|a| plane(r, a)));
            aimed(r, corner)
        }),
        case("through a cell edge", &mut |r| {
            let axis = axis_of(r);
            let mut target = inside(r);
            for other in [(axis + 1) % 3, (axis + 2) % 3] {
                target[other] = plane(r, other);
            }
            aimed(r, target)
        }),
        case("starting on a plane", &mut |r| {
            let axis = axis_of(r);
            let mut origin = inside(r);
            origin[axis] = plane(r, axis);
            Ray::new(origin, r.unit_vector())
        }),
        case("starting inside", &mut |r| {
            Ray::new(inside(r), r.unit_vector())
        }),
        case("parallel to an axis", &mut |r| {
            let axis = axis_of(r);
            Ray::new(inside(r), signed_unit(r, axis))
        }),
        case("grazing the box", &mut |r| {
            // in the plane of a face, aimed at a point of that face
            let axis = axis_of(r);
            let face = if r.next_u64() % 2 == 0 {
                b.min[axis]
            } else {
                b.max[axis]
            };
            let mut target = inside(r);
            target[axis] = face;
            let mut origin = centre + far * r.unit_vector();
            origin[axis] = face;
            Ray::new(origin, target - origin)
        }),
        case("from far away", &mut |r| {
            let target = inside(r);
            aimed(r, target)
        }),
    ]
}
