//! Where a grid can go wrong, counted: rays exactly along the lines and
//! in the planes between cells, through their corners and edges, starting
//! on a plane or inside the grid, parallel to an axis (with −0.0 too),
//! grazing the grid's box; scenes with objects much larger than a cell,
//! a plane, one cell, cells nearly all empty, everything flat. Seeded, so
//! every run asks the same rays; the tests ask a few of each, `raystep
//! measure` over a million.
use std::sync::Arc;

use ch03::BruteForce;
use ch08::SplitMix64;
use raystep_core::{DVec3, Interval, Ray};
use raystep_world::{Accelerator, Object};

use crate::{Lattice, Resolution, uniform_spheres, uniform_triangles};

/// A scene of the catalogue: its name, objects and the grid's resolution.
pub struct StabilityScene {
    /// What is special about it, for tables.
    pub name: &'static str,
    /// Its objects.
    pub objects: Vec<Object>,
    /// The grid's cells.
    pub resolution: Resolution,
}

/// The catalogue's scenes, the bunny's triangles given (the tests and
/// `raystep measure` read them from `../shared/meshes`).
pub fn stability_scenes(bunny: &[[DVec3; 3]]) -> Vec<StabilityScene> {
    let object = |spec: raystep_scene::Shape| Object {
        shape: ch08::shape(&spec).expect("a valid shape"),
        material: 0,
    };
    let triangle = |t: &[DVec3; 3]| {
        ch08::mesh_triangle(*t).map(|t| Object {
            shape: Arc::new(t),
            material: 0,
        })
    };
    let spheres = |count, seed| {
        uniform_spheres(count, seed)
            .into_iter()
            .map(|(center, radius)| {
                object(raystep_scene::Shape::Sphere { center, radius })
            })
            .collect::<Vec<_>>()
    };
    // objects much larger than a cell: two big triangles across the whole
    // grid, and a plane outside it
    let mut mixed = spheres(400, 1);
    let corner = |x, y, z| DVec3::new(x, y, z);
    mixed.extend(
        [
            [
                corner(-1., -1., -1.),
                corner(1., -1., 1.),
                corner(1., 1., -1.),
            ],
            [
                corner(-1., 1., 1.),
                corner(1., -1., 1.),
                corner(-1., -1., -1.),
            ],
        ]
        .iter()
        .filter_map(triangle),
    );
    mixed.push(object(raystep_scene::Shape::Plane {
        point: DVec3::new(0.0, -0.9, 0.0),
        normal: DVec3::Y,
    }));
    let flat: Vec<Object> = uniform_triangles(300, 2)
        .iter()
        .map(|t| t.map(|v| DVec3::new(v.x, v.y, 0.0)))
        .filter_map(|t| triangle(&t))
        .collect();
    let scene = |name, objects, resolution| StabilityScene {
        name,
        objects,
        resolution,
    };
    vec![
        scene(
            "the bunny",
            bunny.iter().filter_map(triangle).collect(),
            Resolution::Rule,
        ),
        scene(
            "spheres + big triangles + a plane",
            mixed.clone(),
            Resolution::Rule,
        ),
        scene("the same in one cell", mixed, Resolution::Cells([1, 1, 1])),
        scene(
            "10 spheres in 64 cells a side",
            spheres(10, 3),
            Resolution::Longest(64),
        ),
        scene("flat: triangles in z = 0", flat, Resolution::Rule),
    ]
}

/// How many of `rays` `accelerator` answers differently from brute force:
/// a closest hit at another t (or a hit against a miss), or another
/// any-hit answer (over t ≥ 0, and over 0 ≤ t ≤ 1). Two objects hit at
/// the very same t are a tie, not a disagreement.
pub fn disagreements(
    accelerator: &dyn Accelerator,
    objects: &[Object],
    rays: &[Ray],
) -> usize {
    rays.iter()
        .filter(|ray| {
            let closest = |a: &dyn Accelerator| {
                a.closest_hit(objects, ray, Interval::FORWARD)
                    .map(|(_, hit)| hit.t)
            };
            let any = |a: &dyn Accelerator, interval| {
                a.any_hit(objects, ray, interval)
            };
            let short = Interval::new(0.0, 1.0);
            closest(accelerator) != closest(&BruteForce)
                || any(accelerator, Interval::FORWARD)
                    != any(&BruteForce, Interval::FORWARD)
                || any(accelerator, short) != any(&BruteForce, short)
        })
        .count()
}

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
        let mut d = DVec3::splat(if r.next_u64().is_multiple_of(2) {
            0.0
        } else {
            -0.0
        });
        d[axis] = if r.next_u64().is_multiple_of(2) {
            1.0
        } else {
            -1.0
        };
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
            let face = if r.next_u64().is_multiple_of(2) {
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
