//! The data behind the instances chart: fields of 1, 10, 100 and 1 000
//! bunnies (`bunnies_toml`'s placement, the floor left out: the structures
//! hold the bunnies alone), each built two ways with the 16-bin SAH
//! hierarchy, as `raystep render --accel bvh` builds it:
//!
//! - **flattened**: every bunny's triangles placed in the world, one
//!   object each, one hierarchy over them all;
//! - **instanced**: one [`Blas`] over the bunny's triangles, shared, one
//!   [`MeshInstance`](ch08::MeshInstance) per bunny, and the top hierarchy over the instances.
//!
//! The build and trace times are measured on one thread, medians of the
//! rounds, the two ways taking turns. The bytes are counted from the
//! structures' sizes (the same on every machine, see [`footprint`]).
use std::hint::black_box;
use std::sync::Arc;
use std::time::Instant;

use ch08::{Blas, Builder, Bvh, Interval, Object, Ray, World};
use raystep_render::timing::Timing;
use raystep_scene::{Scene, Shape as ShapeSpec};

use crate::bunnies_toml;
use crate::instance_rows::{FLATTENED, INSTANCED, InstanceRow};

/// The fields measured: bunnies in each.
pub const FIELDS: [usize; 4] = [1, 10, 100, 1000];

/// The camera rays traced: the scene's camera at 256 × 144 pixels.
pub const RAYS: (u32, u32) = (256, 144);

/// The hierarchy of both levels: binned SAH, 16 bins (`--accel bvh`).
const BUILDER: Builder = Builder::BinnedSah { bins: 16 };

/// What `--accel bvh` builds for a list of objects.
pub(crate) fn bvh(objects: &[Object]) -> Arc<dyn ch08::Accelerator> {
    Arc::new(Bvh::for_objects(objects, BUILDER))
}

/// The field of `count` bunnies as `bunnies_toml` places them, without
/// its floor: the instanced scene, and the same bunnies as `mesh = { … }`
/// objects (flattened). The OBJ is read once, from ../shared.
pub fn fields(count: usize) -> Result<(Scene, Scene), String> {
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../scenes/bunnies-{count}.toml"));
    let mut instanced =
        raystep_scene::parse(&bunnies_toml(count), &file.to_string_lossy())
            .map_err(|e| {
                format!("{e} (the meshes live in ../shared/meshes)")
            })?;
    instanced.objects.clear();
    let mut flattened = instanced.clone();
    flattened.instances.clear();
    for instance in &instanced.instances {
        flattened.objects.push(raystep_scene::Object {
            shape: ShapeSpec::Mesh {
                mesh: instanced.meshes[&instance.mesh].clone(),
                placement: instance.placement,
            },
            material: instance.material,
            line: instance.line,
        });
    }
    Ok((flattened, instanced))
}

/// The world of `scene` ready to trace, as `raystep render --accel bvh`
/// builds it (each mesh's own hierarchy, and the top one over the
/// world's objects), and its top hierarchy.
pub fn build(scene: &Scene) -> (World, Arc<Bvh>) {
    let world =
        ch08::world_with(scene, "field", bvh).expect("the field builds");
    let top = Arc::new(Bvh::for_objects(&world.objects, BUILDER));
    (world.with_accelerator(top.clone()), top)
}

/// The bytes an `Arc` adds to what it holds: its two counts.
const ARC_COUNTS: usize = 2 * size_of::<usize>();

/// A hierarchy's bytes: the struct in its `Arc`, its nodes, and its
/// object indices (in leaf order, and the unbounded ones).
fn tree_bytes(tree: &Bvh) -> usize {
    ARC_COUNTS
        + size_of::<Bvh>()
        + tree.nodes.len() * size_of::<ch08::BvhNode>()
        + (tree.order.len() + tree.unbounded.len()) * size_of::<u32>()
}

/// The objects' bytes: each `Object` in the world's list, and the shape
/// it points to in its `Arc` (a triangle, or an instance).
fn object_bytes(objects: &[Object]) -> usize {
    objects
        .iter()
        .map(|o| size_of::<Object>() + ARC_COUNTS + size_of_val(&*o.shape))
        .sum()
}

/// What a built field holds, counted from the structures' sizes
/// (`size_of`: the same on every 64-bit machine), not asked of the
/// allocator: the lengths of the vectors, not their spare capacity.
///
/// - flattened: the world's objects (one per triangle, each pointing to
///   its placed triangle), and the hierarchy over them;
/// - instanced: the world's objects (one per bunny, each pointing to its
///   [`MeshInstance`](ch08::MeshInstance): the shared `Arc` and three matrices) and the top
///   hierarchy; once, the [`Blas`]: the bunny's triangles as objects, their
///   normals, and its own hierarchy (built again here, by the same
///   deterministic builder, to be counted: the `Blas` keeps it behind
///   `dyn Accelerator`).
///
/// The OBJ's mesh itself, which the scene holds either way, is not
/// counted. Returns (nodes, object bytes, node bytes).
pub fn footprint(
    scene: &Scene, world: &World, top: &Bvh,
) -> (usize, usize, usize) {
    let (mut nodes, mut objects, mut trees) = (
        top.nodes.len(),
        object_bytes(&world.objects),
        tree_bytes(top),
    );
    if let Some(instance) = scene.instances.first() {
        let blas = Blas::new(&scene.meshes[&instance.mesh], bvh);
        let own = Bvh::for_objects(blas.objects(), BUILDER);
        nodes += own.nodes.len();
        objects += ARC_COUNTS
            + size_of::<Blas>()
            + object_bytes(blas.objects())
            + blas.objects().len() * size_of::<ch08::DVec3>();
        trees += tree_bytes(&own);
    }
    (nodes, objects, trees)
}

/// The camera rays of `world` at [`RAYS`]' size.
fn camera_rays(world: &World) -> Vec<Ray> {
    let (width, height) = RAYS;
    world
        .camera
        .pixel_rays(width, height)
        .map(|(_, _, ray)| ray)
        .collect()
}

/// How many of `rays` hit something in `world`.
fn trace(world: &World, rays: &[Ray]) -> usize {
    rays.iter()
        .filter(|ray| world.closest_hit(ray, Interval::FORWARD).is_some())
        .count()
}

/// The middle value (the upper one of an even count).
fn median(mut samples: Vec<f64>) -> f64 {
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

/// The steps [`measure_instances`] reports: per field, one per round of
/// builds and one per round of traces.
pub fn instance_steps(repeats: usize) -> u64 {
    (FIELDS.len() * 2 * repeats.max(1)) as u64
}

/// Each field built flattened and instanced: build time, structure
/// (counted), trace time of the camera rays (one thread).
///
/// The builds take turns (flattened then instanced, then the other way
/// round), each timed from the scene in memory to the world ready, the
/// world it replaces dropped before the clock starts; the traces take
/// turns as [`Timing`] orders them.
pub fn measure_instances(
    repeats: usize, step: &mut dyn FnMut(),
) -> Result<Vec<InstanceRow>, String> {
    let rounds = repeats.max(1);
    let mut rows = Vec::new();
    for count in FIELDS {
        let scenes = fields(count)?;
        let scenes = [&scenes.0, &scenes.1];
        // Step 1: the builds, timed; one untimed build of each first.
        let mut built = scenes.map(|scene| Some(build(scene)));
        let mut samples = [Vec::new(), Vec::new()];
        for round in 0..rounds {
            for k in [round % 2, 1 - round % 2] {
                built[k] = None; // the last world dropped, untimed
                let start = Instant::now();
                let world = build(scenes[k]);
                samples[k].push(start.elapsed().as_secs_f64() * 1e3);
                built[k] = Some(world);
            }
            step();
        }
        let [flat_ms, inst_ms] = samples.map(median);
        let [Some(flat), Some(inst)] = built else {
            unreachable!("both ways are built");
        };
        // Step 2: the traces, timed, the same rays both ways.
        let rays = camera_rays(&flat.0);
        let timing = Timing { rounds, batch: 1 };
        let trace_ms = timing.median_ms(
            &mut [
                &mut || {
                    black_box(trace(&flat.0, &rays));
                },
                &mut || {
                    black_box(trace(&inst.0, &rays));
                },
            ],
            &mut *step,
        );
        // Step 3: the counts.
        let ways = [(FLATTENED, flat_ms, &flat), (INSTANCED, inst_ms, &inst)];
        for (k, (way, build_ms, (world, top))) in ways.into_iter().enumerate() {
            let (nodes, object_bytes, node_bytes) =
                footprint(scenes[k], world, top);
            rows.push(InstanceRow {
                bunnies: count as u64,
                way: way.to_string(),
                objects: world.objects.len() as u64,
                nodes: nodes as u64,
                object_bytes: object_bytes as u64,
                node_bytes: node_bytes as u64,
                build_ms,
                rays: rays.len() as u64,
                hits: trace(world, &rays) as u64,
                trace_ns: trace_ms[k] * 1e6 / rays.len() as f64,
            });
        }
    }
    Ok(rows)
}
