//! Where a grid can go wrong, counted: rays exactly along the lines and
//! in the planes between cells, through their corners and edges, starting
//! on a plane or inside the grid, parallel to an axis (with −0.0 too),
//! grazing the grid's box; scenes with objects much larger than a cell,
//! a plane, one cell, cells nearly all empty, everything flat. Seeded, so
//! every run asks the same rays; the tests ask a few of each, `raystep
//! measure` over a million.
use std::sync::Arc;

use ch08::SplitMix64;
use ch09::{Lattice, Resolution};
use raystep_bench::{uniform_spheres, uniform_triangles};
use raystep_core::{DVec3, Ray};
use raystep_world::Object;

use crate::ray_cases::{Around, Cases, RayCase, inside, signed_unit};

/// A triangle as an object (none for a degenerate one).
pub(crate) fn triangle_object(t: &[DVec3; 3]) -> Option<Object> {
    ch08::mesh_triangle(*t).map(|t| Object {
        shape: Arc::new(t),
        material: 0,
    })
}

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
        .filter_map(triangle_object),
    );
    mixed.push(object(raystep_scene::Shape::Plane {
        point: DVec3::new(0.0, -0.9, 0.0),
        normal: DVec3::Y,
    }));
    let flat: Vec<Object> = uniform_triangles(300, 2)
        .iter()
        .map(|t| t.map(|v| DVec3::new(v.x, v.y, 0.0)))
        .filter_map(|t| triangle_object(&t))
        .collect();
    let scene = |name, objects, resolution| StabilityScene {
        name,
        objects,
        resolution,
    };
    vec![
        scene(
            "the bunny",
            bunny.iter().filter_map(triangle_object).collect(),
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

/// `per_case` rays of each dangerous kind for the grid `lattice`.
pub fn adversarial_rays(
    lattice: &Lattice, per_case: usize, seed: u64,
) -> Vec<RayCase> {
    let around = Around::new(lattice.bounds);
    let (b, centre, far) = (around.bounds, around.centre, around.far);
    // a plane between cells (or a face of the box) along `axis`
    let plane = |r: &mut SplitMix64, axis: usize| {
        let n = lattice.cells[axis];
        lattice.plane(axis, (r.next_u64() % (n as u64 + 1)) as usize)
    };
    let axis_of = |r: &mut SplitMix64| (r.next_u64() % 3) as usize;
    let mut cases = Cases::new(per_case, seed);
    vec![
        cases.case("along a line between cells", |r| {
            // two coordinates on planes, the ray along the third axis
            let axis = axis_of(r);
            let mut origin = inside(r, &b);
            for other in [(axis + 1) % 3, (axis + 2) % 3] {
                origin[other] = plane(r, other);
            }
            origin[axis] = centre[axis] - far * 0.5;
            Ray::new(origin, signed_unit(r, axis).abs())
        }),
        cases.case("in a plane between cells", |r| {
            let axis = axis_of(r);
            let mut origin = around.far_point(r);
            origin[axis] = plane(r, axis);
            let mut target = inside(r, &b);
            target[axis] = origin[axis];
            Ray::new(origin, target - origin)
        }),
        cases.case("through a cell corner", |r| {
            let corner = DVec3::from_array([0, 1, 2].map(|a| plane(r, a)));
            around.aimed(r, corner)
        }),
        cases.case("through a cell edge", |r| {
            let axis = axis_of(r);
            let mut target = inside(r, &b);
            for other in [(axis + 1) % 3, (axis + 2) % 3] {
                target[other] = plane(r, other);
            }
            around.aimed(r, target)
        }),
        cases.case("starting on a plane", |r| {
            let axis = axis_of(r);
            let mut origin = inside(r, &b);
            origin[axis] = plane(r, axis);
            Ray::new(origin, r.unit_vector())
        }),
        cases.case("starting inside", |r| {
            Ray::new(inside(r, &b), r.unit_vector())
        }),
        cases.case("parallel to an axis", |r| {
            let axis = axis_of(r);
            Ray::new(inside(r, &b), signed_unit(r, axis))
        }),
        cases.case("grazing the box", |r| {
            // in the plane of a face, aimed at a point of that face
            let axis = axis_of(r);
            let face = if r.next_u64().is_multiple_of(2) {
                b.min[axis]
            } else {
                b.max[axis]
            };
            let mut target = inside(r, &b);
            target[axis] = face;
            let mut origin = around.far_point(r);
            origin[axis] = face;
            Ray::new(origin, target - origin)
        }),
        cases.case("from far away", |r| {
            let target = inside(r, &b);
            around.aimed(r, target)
        }),
    ]
}
