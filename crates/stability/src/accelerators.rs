//! The accelerators behind the seam (chapter 3's `Accelerator`): every
//! BVH builder of chapter 8, chapter 9's grid and chapter 10's kd-trees,
//! each asked what brute force is asked, on the scenes chapters 9 and 10
//! find hard (but the bunny, a mesh case: big triangles over small
//! spheres and a plane,
//! spheres far apart, a flat scene, triangles in split planes, long
//! triangles, a tight cluster) and on the rays each structure fears:
//! made from the kd-tree's own split planes and node corners, and from
//! the grid's own cell lines and planes. A disagreement is another
//! closest `t`, or another any-hit answer over t ≥ 0 or over [0, 1].
//!
//! Two closest `t`s within [`TIE`] of each other are the same answer:
//! where two triangles overlap in one plane (two of the scenes have
//! such), each `t` is rounded its own way, 1 to 3 ulps apart, and a
//! hierarchy that prunes a box by its entry `t` may keep the other one
//! of the two than brute force keeps.
use std::sync::OnceLock;

use ch08::{Builder, Bvh};
use ch10::{KdBuilder, KdCosts, KdTree};
use raystep_core::Ray;
use raystep_world::{Accelerator, Object};

use crate::scenes::bunny;
use crate::{
    Answers, Budget, Case, Count, Expect, adversarial_rays, disagreements_by,
    kd_rays, kd_scenes,
};

/// The group's name in the table.
const GROUP: &str = "accelerators (objects)";

/// How far apart two closest `t`s may be and still be one answer: this
/// times max(1, t) (the largest seen on these rays: 3·10⁻¹² of t, or
/// 2·10⁻¹⁸ at t = 5·10⁻⁷).
pub const TIE: f64 = 1e-11;

/// Do two answers ([`answers`](crate::answers)) agree, closest `t`s
/// within [`TIE`]?
fn agree(a: &Answers, b: &Answers) -> bool {
    let t = match (a.0, b.0) {
        (None, None) => true,
        (Some(x), Some(y)) => (x - y).abs() <= TIE * x.abs().max(1.0),
        _ => false,
    };
    t && a.1 == b.1 && a.2 == b.2
}

/// A case of rays made from the kd-tree's planes.
macro_rules! kd_case {
    ($name:literal, $what:literal) => {
        Case {
            group: GROUP,
            name: concat!("kd planes: ", $name),
            what: $what,
            run: |budget| run(budget, Rays::KdTree($name)),
        }
    };
}

/// A case of rays made from the grid's lattice.
macro_rules! grid_case {
    ($name:literal, $what:literal) => {
        Case {
            group: GROUP,
            name: concat!("grid lines: ", $name),
            what: $what,
            run: |budget| run(budget, Rays::Grid($name)),
        }
    };
}

/// This group's cases: the kd-tree's ray kinds, then the grid's.
pub fn cases() -> Vec<Case> {
    vec![
        kd_case!(
            "lying in a split plane",
            "t_split = t_enter: a walk that drops the ray into one child \
             misses the other"
        ),
        kd_case!(
            "starting on a split plane",
            "origin on the plane, 0·∞ in the slab test; robust walks go on"
        ),
        kd_case!(
            "along two split planes",
            "a ray on the line where two planes meet: both ties at once"
        ),
        kd_case!(
            "axis-parallel in a plane (±0)",
            "1/±0 = ±∞ and the sign of zero decides the near child"
        ),
        kd_case!(
            "axis-parallel anywhere (±0)",
            "infinite reciprocals in every slab test"
        ),
        kd_case!(
            "through a node's corner",
            "entry and exit at one point: an empty interval that is not empty"
        ),
        kd_case!(
            "starting inside",
            "the origin inside the scene's box: no entry point to clip to"
        ),
        kd_case!(
            "from far away",
            "a long ray: rounding of the entry t grows with the distance"
        ),
        grid_case!(
            "along a line between cells",
            "the 3D DDA steps two axes at once: a cell may be skipped"
        ),
        grid_case!(
            "in a plane between cells",
            "t_max equal on two axes all the way: ties at every step"
        ),
        grid_case!(
            "through a cell corner",
            "three axes step at once: the diagonal cell must not be missed"
        ),
        grid_case!("through a cell edge", "two axes step at once at one point"),
        grid_case!(
            "starting on a plane",
            "the first cell is ambiguous: the origin sits on its boundary"
        ),
        grid_case!(
            "starting inside",
            "the walk starts in the origin's cell, not at the box's face"
        ),
        grid_case!(
            "parallel to an axis",
            "t_delta = ∞ on two axes: the walk must never step along them"
        ),
        grid_case!(
            "grazing the box",
            "the ray touches the grid's box in a face, an edge or a corner"
        ),
        grid_case!(
            "from far away",
            "a long way to the box: the entry cell from a rounded point"
        ),
    ]
}

/// Which structure's own planes the rays are made from, and the kind.
#[derive(Clone, Copy)]
enum Rays {
    KdTree(&'static str),
    Grid(&'static str),
}

/// The methods behind the seam, built over `objects`, with their names.
fn methods(objects: &[Object]) -> Vec<(String, Box<dyn Accelerator>)> {
    let mut methods: Vec<(String, Box<dyn Accelerator>)> = Builder::ALL
        .into_iter()
        .map(|builder| {
            let bvh: Box<dyn Accelerator> =
                Box::new(Bvh::for_objects(objects, builder));
            (format!("bvh: {}", builder.name()), bvh)
        })
        .collect();
    methods.push((
        "grid".to_string(),
        Box::new(ch09::Grid::for_objects(objects, ch09::Resolution::Rule)),
    ));
    for (name, builder) in [
        ("kd-tree: SAH", KdBuilder::SahEvents),
        ("kd-tree: median", KdBuilder::Median),
    ] {
        let tree = KdTree::for_objects(objects, builder, KdCosts::CHOSEN);
        methods.push((name.to_string(), Box::new(tree)));
    }
    let mut plain =
        KdTree::for_objects(objects, KdBuilder::SahEvents, KdCosts::CHOSEN);
    plain.mailboxing = false;
    methods.push(("kd-tree: SAH, no mailbox".to_string(), Box::new(plain)));
    methods
}

/// `count` rays of the kind `rays` asks for, made from the scene's own
/// kd-tree and grid.
fn make_rays(built: &Built, rays: Rays, count: usize) -> Vec<Ray> {
    match rays {
        Rays::KdTree(name) => kd_rays(&built.kd, count, 17)
            .into_iter()
            .find(|case| case.name == name)
            .map(|case| case.rays)
            .unwrap_or_default(),
        Rays::Grid(name) => adversarial_rays(&built.grid.lattice, count, 17)
            .into_iter()
            .find(|case| case.name == name)
            .map(|case| case.rays)
            .unwrap_or_default(),
    }
}

/// A scene of chapter 10's catalogue and every method built over it.
struct Built {
    objects: Vec<Object>,
    methods: Vec<(String, Box<dyn Accelerator>)>,
    /// The trees the rays are made from.
    kd: KdTree,
    grid: ch09::Grid,
}

/// The scenes and their methods, built once for all the cases.
fn built() -> &'static [Built] {
    static BUILT: OnceLock<Vec<Built>> = OnceLock::new();
    BUILT.get_or_init(|| {
        kd_scenes(bunny())
            .into_iter()
            // (the bunny is the mesh cases' scene; here its 3 674
            // objects would only slow brute force down)
            .filter(|scene| scene.name != "the bunny")
            .map(|scene| Built {
                methods: methods(&scene.objects),
                kd: KdTree::for_objects(
                    &scene.objects,
                    KdBuilder::SahEvents,
                    KdCosts::CHOSEN,
                ),
                grid: ch09::Grid::for_objects(
                    &scene.objects,
                    ch09::Resolution::Rule,
                ),
                objects: scene.objects,
            })
            .collect()
    })
}

/// Every method against brute force on the rays `rays` over every scene
/// of chapter 10's catalogue: `budget.rays` rays in all, shared out.
fn run(budget: &Budget, rays: Rays) -> Vec<(Count, Expect)> {
    use rayon::prelude::*;
    let built = built();
    let per_scene = budget.rays.div_ceil(built.len());
    let mut counts: Vec<Count> = Vec::new();
    for scene in built {
        let (objects, methods) = (&scene.objects, &scene.methods);
        let asked = make_rays(scene, rays, per_scene);
        let accelerators: Vec<&dyn Accelerator> =
            methods.iter().map(|(_, m)| m.as_ref()).collect();
        let wrong = asked
            .par_chunks(256)
            .map(|chunk| disagreements_by(&accelerators, objects, chunk, agree))
            .reduce(
                || vec![0; accelerators.len()],
                |a, b| a.iter().zip(&b).map(|(x, y)| x + y).collect(),
            );
        for ((name, _), wrong) in methods.iter().zip(wrong) {
            match counts.iter_mut().find(|c| &c.method == name) {
                Some(count) => {
                    count.failures += wrong as u64;
                    count.trials += asked.len() as u64;
                }
                None => counts.push(Count::new(
                    name.clone(),
                    wrong as u64,
                    asked.len() as u64,
                )),
            }
        }
    }
    counts.into_iter().map(|c| (c, Expect::Never)).collect()
}
