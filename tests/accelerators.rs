//! The seam between the objects and the tracers: a second collection, the
//! brute-force list behind a bounding-box test, must give every tracer of
//! chapters 3–7 exactly what the plain list gives it, on every chapter
//! scene, without a line of those tracers changed. Chapter 8's bounding
//! volume hierarchy, chapter 9's grid and chapter 10's kd-tree (and its
//! rule for choosing a structure) are handed to them the same way.
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use raystep_core::{Aabb, DVec3, Hit, Interval, Ray};
use raystep_render::{Image, Progress, RenderOptions};
use raystep_world::{Accelerate, Accelerator, Object, World};

/// The brute-force loop with a box test in front of every object: an
/// object whose bounds the ray misses within the interval is not asked.
/// It counts the questions it is asked and the objects it skips, so the
/// test can tell that every ray of a tracer went through it.
#[derive(Debug)]
struct BoxedList {
    boxes: Vec<Aabb>,
    skipped: AtomicU64,
    closest_asked: AtomicU64,
    any_asked: AtomicU64,
}

impl BoxedList {
    fn new(objects: &[Object]) -> BoxedList {
        BoxedList {
            boxes: objects.iter().map(|o| o.shape.bounds()).collect(),
            skipped: AtomicU64::new(0),
            closest_asked: AtomicU64::new(0),
            any_asked: AtomicU64::new(0),
        }
    }

    /// (closest-hit questions, any-hit questions) since the last call.
    fn asked(&self) -> (u64, u64) {
        (
            self.closest_asked.swap(0, Ordering::Relaxed),
            self.any_asked.swap(0, Ordering::Relaxed),
        )
    }

    fn misses(&self, index: usize, ray: &Ray, interval: Interval) -> bool {
        let miss = ch08::slab_test(&self.boxes[index], ray, interval).is_none();
        if miss {
            self.skipped.fetch_add(1, Ordering::Relaxed);
        }
        miss
    }
}

impl Accelerator for BoxedList {
    fn closest_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> Option<(usize, Hit)> {
        self.closest_asked.fetch_add(1, Ordering::Relaxed);
        let mut closest = None;
        let mut interval = interval;
        for (index, object) in objects.iter().enumerate() {
            if self.misses(index, ray, interval) {
                continue;
            }
            if let Some(hit) = object.shape.intersect(ray, interval) {
                interval = interval.with_max(hit.t);
                closest = Some((index, hit));
            }
        }
        closest
    }

    fn any_hit(
        &self, objects: &[Object], ray: &Ray, interval: Interval,
    ) -> bool {
        self.any_asked.fetch_add(1, Ordering::Relaxed);
        (0..objects.len()).any(|index| {
            !self.misses(index, ray, interval)
                && objects[index].shape.intersect(ray, interval).is_some()
        })
    }
}

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every `chapters/*/scenes/*.toml` but those of meshes, in order. The
/// scenes of the bunny (3 674 triangles, or a thousand instances of it)
/// would take minutes on every tracer through every structure here; the
/// same questions are asked of small meshes, flattened and instanced, in
/// [`mesh_scenes_give_the_same_bytes_on_every_accelerator`].
fn chapter_scenes() -> Vec<PathBuf> {
    let mut scenes = Vec::new();
    for chapter in std::fs::read_dir(workspace().join("chapters")).unwrap() {
        let dir = chapter.unwrap().path().join("scenes");
        for file in std::fs::read_dir(&dir).into_iter().flatten() {
            let file = file.unwrap().path();
            let meshes = std::fs::read_to_string(&file)
                .is_ok_and(|text| text.contains("obj = "));
            if file.extension().is_some_and(|e| e == "toml") && !meshes {
                scenes.push(file);
            }
        }
    }
    scenes.sort();
    scenes
}

/// The world of `path` at a test size, with the plain list, and the same
/// world with the boxed list.
fn worlds(path: &Path) -> (World, World, Arc<BoxedList>) {
    let mut scene = raystep_scene::load(path).unwrap();
    // a test size in the scene's own proportion
    let aspect = f64::from(scene.width) / f64::from(scene.height);
    (scene.width, scene.height) = (64, (64.0 / aspect).round() as u32);
    // chapter 8's shapes: chapter 3's sphere, plane and polygon, and every
    // primitive chapter 8 adds, so its scenes run on every tracer too
    let list = ch08::world(&scene, &path.display().to_string()).unwrap();
    let boxed = Arc::new(BoxedList::new(&list.objects));
    let other = list.clone().with_accelerator(boxed.clone());
    (list, other, boxed)
}

const QUIET: RenderOptions = RenderOptions {
    threads: Some(2),
    progress: Progress::Never,
};

/// Every tracer of chapters 3–6, as the command line runs it, and the
/// counts it keeps (rays, wrong shadows) as text.
fn every_tracer(world: &World) -> Vec<(&'static str, Image, String)> {
    let (ch05_image, ch05_counts) =
        ch05::render(world, &ch05::DEFAULT_STOP, &QUIET).unwrap();
    let (ch06_image, ch06_counts) =
        ch06::render(world, &ch05::DEFAULT_STOP, ch06::Fresnel::Exact, &QUIET)
            .unwrap();
    vec![
        (
            "ch03",
            ch03::render(world, ch03::Terms::All, &QUIET).unwrap(),
            String::new(),
        ),
        (
            "ch04",
            ch04::render(world, ch04::Offset::ScaleAware, &QUIET).unwrap(),
            format!(
                "{:?}",
                ch04::shadow_errors(world, ch04::Offset::TMin(0.0))
            ),
        ),
        ("ch05", ch05_image, format!("{ch05_counts:?}")),
        ("ch06", ch06_image, format!("{ch06_counts:?}")),
    ]
}

/// Every tracer on `world` gives the same image bytes and the same counts
/// as `expected` (every tracer on the plain list), asked `through` an
/// accelerator named in the messages; how many tracers were compared.
fn assert_same(
    expected: &[(&'static str, Image, String)], world: &World, through: &str,
    path: &Path,
) -> usize {
    let actual = every_tracer(world);
    for ((name, a, a_counts), (_, b, b_counts)) in expected.iter().zip(&actual)
    {
        assert_eq!(
            a.to_srgb8(),
            b.to_srgb8(),
            "{name} through {through} on {}: the images differ",
            path.display()
        );
        assert_eq!(a_counts, b_counts, "{name} on {}", path.display());
    }
    actual.len()
}

#[test]
fn every_tracer_gives_the_same_bytes_on_a_second_collection() {
    let scenes = chapter_scenes();
    assert!(scenes.len() >= 8, "{scenes:?}");
    let mut compared = 0;
    for path in &scenes {
        let (list, boxed_world, boxed) = worlds(path);
        let expected = every_tracer(&list);
        let before = boxed.skipped.load(Ordering::Relaxed);
        compared += assert_same(&expected, &boxed_world, "a boxed list", path);
        // the tracers really asked the boxed list (it skipped objects)
        assert!(
            boxed.skipped.load(Ordering::Relaxed) > before,
            "{}: the boxed list was never asked",
            path.display()
        );
        every_ray_goes_through_the_seam(&boxed_world, &boxed, path);
    }
    assert_eq!(compared, 4 * scenes.len());
}

/// Chapter 8's hierarchy behind the same seam: on every chapter scene,
/// every tracer gives the same image bytes and the same counts with the
/// BVH of each builder as with the plain list.
#[test]
fn every_tracer_gives_the_same_bytes_on_a_bvh() {
    let builders = [
        ch08::Builder::Midpoint,
        ch08::Builder::Median,
        ch08::Builder::BinnedSah { bins: 8 },
        ch08::Builder::SweepSah,
        ch08::Builder::Ploc { radius: 8 },
    ];
    let mut compared = 0;
    for path in &chapter_scenes() {
        let (list, _, _) = worlds(path);
        let expected = every_tracer(&list);
        for builder in builders {
            let bvh = Arc::new(ch08::Bvh::for_objects(&list.objects, builder));
            let world = list.clone().with_accelerator(bvh);
            let through = format!("a {} BVH", builder.name());
            compared += assert_same(&expected, &world, &through, path);
        }
    }
    assert!(compared >= 4 * 5 * 8);
}

/// Chapter 9's grid behind the same seam: on every chapter scene, every
/// tracer gives the same image bytes and the same counts through the grid
/// (the rule's resolution with the mailbox on and off, one cell, and 64
/// cells along the longest axis) as through the plain list.
#[test]
fn every_tracer_gives_the_same_bytes_on_a_grid() {
    let mut compared = 0;
    for path in &chapter_scenes() {
        let (list, _, _) = worlds(path);
        let expected = every_tracer(&list);
        let resolutions = [
            (ch09::Resolution::Rule, true),
            (ch09::Resolution::Rule, false),
            (ch09::Resolution::Cells([1, 1, 1]), true),
            (ch09::Resolution::Longest(64), true),
        ];
        for (resolution, mailboxing) in resolutions {
            let mut grid = ch09::Grid::for_objects(&list.objects, resolution);
            grid.mailboxing = mailboxing;
            let world = list.clone().with_accelerator(Arc::new(grid));
            let through =
                format!("a grid ({resolution:?}, mailbox {mailboxing})");
            compared += assert_same(&expected, &world, &through, path);
        }
    }
    assert!(compared >= 4 * 4 * 10);
}

/// Chapter 10's kd-tree behind the same seam: on every chapter scene,
/// every tracer gives the same image bytes and the same counts through
/// the tree (SAH from events with the mailbox on and off, the median
/// split, SAH by sorting under pbrt's costs) and through the rule's
/// choice as through the plain list.
#[test]
fn every_tracer_gives_the_same_bytes_on_a_kd_tree() {
    use ch10::{KdBuilder, KdCosts, KdTree};
    let trees = [
        (KdBuilder::SahEvents, KdCosts::CHOSEN, true),
        (KdBuilder::SahEvents, KdCosts::CHOSEN, false),
        (KdBuilder::Median, KdCosts::CHOSEN, true),
        (KdBuilder::SahSorting, KdCosts::PBRT_V3, true),
    ];
    let mut compared = 0;
    for path in &chapter_scenes() {
        let (list, _, _) = worlds(path);
        let expected = every_tracer(&list);
        let mut accelerators: Vec<(String, Arc<dyn Accelerator>)> = trees
            .iter()
            .map(|&(builder, costs, mailboxing)| {
                let mut tree =
                    KdTree::for_objects(&list.objects, builder, costs);
                tree.mailboxing = mailboxing;
                let name = format!(
                    "a kd-tree ({}, {}, mailbox {mailboxing})",
                    builder.name(),
                    costs.name()
                );
                (name, Arc::new(tree) as Arc<dyn Accelerator>)
            })
            .collect();
        let boxes: Vec<Aabb> =
            list.objects.iter().map(|o| o.shape.bounds()).collect();
        let rule = format!("the rule's {}", ch10::choose(&boxes).name());
        accelerators.push((rule, ch10::auto(&list.objects)));
        for (accelerator, built) in accelerators {
            let world = list.clone().with_accelerator(built);
            compared += assert_same(&expected, &world, &accelerator, path);
        }
    }
    assert!(compared >= 4 * 5 * 10);
}

/// What `raystep render --accel` builds for a list of objects: the
/// lecture's loop, chapter 8's BVH (binned SAH), chapter 9's grid (the
/// rule's resolution), chapter 10's kd-tree (SAH from events) and chapter
/// 10's rule.
const EVERY_ACCEL: [(&str, Accelerate); 5] = [
    ("brute", |_| Arc::new(ch03::BruteForce)),
    ("bvh", |objects| {
        Arc::new(ch08::Bvh::for_objects(
            objects,
            ch08::Builder::BinnedSah { bins: 16 },
        ))
    }),
    ("grid", |objects| {
        Arc::new(ch09::Grid::for_objects(objects, ch09::Resolution::Rule))
    }),
    ("kdtree", |objects| {
        Arc::new(ch10::KdTree::for_objects(
            objects,
            ch10::KdBuilder::SahEvents,
            ch10::KdCosts::CHOSEN,
        ))
    }),
    ("auto", ch10::auto),
];

/// Scenes of meshes (chapter 8's test scenes: small meshes flattened, and
/// instanced beside a flattened one): every tracer gives the same image
/// bytes and counts with every accelerator of `raystep render --accel`,
/// which builds both levels of an instanced scene (each mesh's own
/// structure, and the world's over the instances and other objects), as
/// with the lecture's loop at both levels.
#[test]
fn mesh_scenes_give_the_same_bytes_on_every_accelerator() {
    let folder =
        workspace().join("chapters/ch08-bounding-volumes/tests/meshes");
    let mut compared = 0;
    for name in ["flattened.toml", "instanced.toml"] {
        let path = folder.join(name);
        let scene = raystep_scene::load(&path).unwrap();
        let file = path.display().to_string();
        let (_, brute) = EVERY_ACCEL[0];
        let list = ch08::world_with(&scene, &file, brute).unwrap();
        let expected = every_tracer(&list);
        // the meshes are in the picture: without them it differs
        let mut bare = list.clone();
        bare.objects.truncate(1);
        let (_, bare_image, _) = &every_tracer(&bare)[3];
        assert_ne!(bare_image.to_srgb8(), expected[3].1.to_srgb8(), "{name}");
        for (accel, accelerate) in &EVERY_ACCEL[1..] {
            let world = ch08::world_with(&scene, &file, *accelerate)
                .unwrap()
                .accelerated(*accelerate);
            let through = format!("--accel {accel} (both levels)");
            compared += assert_same(&expected, &world, &through, &path);
        }
    }
    assert_eq!(compared, 2 * 4 * 4);
}

/// The chapters' own scenes of meshes (the bunny on its floor, a thousand
/// instances of it, the bunny in its stadium; they read
/// `../shared/meshes/bunny.obj`) at 24 pixels wide, through chapter 6's
/// tracer as `raystep render` runs it: the same image bytes with every
/// `--accel`, both levels built by it. (The thousand bunnies by brute
/// force at both levels would take a minute here: they are compared from
/// the BVH on; the small instanced scene above has brute force.)
#[test]
fn the_chapters_mesh_scenes_give_the_same_bytes_on_every_accelerator() {
    let mut compared = 0;
    for (name, first) in [
        ("ch08-bounding-volumes/scenes/bunny.toml", 0),
        ("ch08-bounding-volumes/scenes/bunnies.toml", 1),
        ("ch09-grids/scenes/teapot-in-stadium.toml", 0),
    ] {
        let path = workspace().join("chapters").join(name);
        let mut scene = raystep_scene::load(&path).unwrap();
        let aspect = f64::from(scene.width) / f64::from(scene.height);
        (scene.width, scene.height) = (24, (24.0 / aspect).round() as u32);
        let file = path.display().to_string();
        let render = |accelerate: Accelerate| {
            let world = ch08::world_with(&scene, &file, accelerate)
                .unwrap()
                .accelerated(accelerate);
            let stop = &ch05::DEFAULT_STOP;
            ch06::render(&world, stop, ch06::Fresnel::Exact, &QUIET)
                .unwrap()
                .0
                .to_srgb8()
        };
        let expected = render(EVERY_ACCEL[first].1);
        for (accel, accelerate) in &EVERY_ACCEL[first + 1..] {
            assert!(render(*accelerate) == expected, "{name}: --accel {accel}");
            compared += 1;
        }
    }
    assert_eq!(compared, 4 + 3 + 4);
}

/// Each ray a tracer counts is one question to the collection: a primary
/// or secondary ray one closest-hit question, a shadow ray one any-hit
/// question. A tracer that kept a loop of its own would ask fewer.
fn every_ray_goes_through_the_seam(
    world: &World, boxed: &BoxedList, path: &Path,
) {
    let pixels = u64::from(world.width * world.height);
    let _ = boxed.asked();
    ch03::render(world, ch03::Terms::All, &QUIET).unwrap();
    assert_eq!(boxed.asked(), (pixels, 0), "ch03 on {}", path.display());
    ch04::render(world, ch04::Offset::ScaleAware, &QUIET).unwrap();
    let (closest, any) = boxed.asked();
    assert_eq!(closest, pixels, "ch04 on {}", path.display());
    assert!(any > 0, "ch04 on {}: no shadow ray asked", path.display());
    let (_, c) = ch05::render(world, &ch05::DEFAULT_STOP, &QUIET).unwrap();
    let asked = boxed.asked();
    assert_eq!(
        asked,
        (c.primary + c.secondary, c.shadow),
        "ch05 on {}",
        path.display()
    );
    let (_, c) =
        ch06::render(world, &ch05::DEFAULT_STOP, ch06::Fresnel::Exact, &QUIET)
            .unwrap();
    let asked = boxed.asked();
    let traced = c.primary + c.reflected + c.transmitted;
    assert_eq!(asked, (traced, c.shadow), "ch06 on {}", path.display());
}

#[test]
fn the_ray_caster_of_chapter_07_gives_the_same_buffers() {
    let path = workspace().join("chapters/ch07-two-methods/scenes/shapes.toml");
    let mut scene = raystep_scene::load(&path).unwrap();
    (scene.width, scene.height) = (64, 36);
    let mut stage = ch07::Stage::from_scene(&scene, "shapes.toml").unwrap();
    let expected = ch07::raycast(&stage);
    let boxed = Arc::new(BoxedList::new(&stage.world.objects));
    stage.world = stage.world.with_accelerator(boxed.clone());
    let actual = ch07::raycast(&stage);
    assert_eq!(expected, actual);
    assert!(boxed.skipped.load(Ordering::Relaxed) > 0);
}

/// Seeded rays from inside and around every chapter scene: the two
/// collections agree on the closest hit (object and t, to the bit) and on
/// any hit. Disagreements are counted, and there must be none.
#[test]
fn closest_and_any_hit_agree_on_seeded_rays() {
    let mut seed: u64 = 0x5EED;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let (mut rays, mut disagreements) = (0, 0);
    for path in chapter_scenes() {
        let (list, boxed, _) = worlds(&path);
        for _ in 0..2000 {
            let origin = DVec3::new(next(), next(), next()) * 8.0;
            let direction = DVec3::new(next(), next(), next());
            let ray = Ray::new(origin, direction);
            let interval = Interval::new(0.0, 4.0 + 8.0 * next().abs());
            let (a, b) = (
                list.closest_hit(&ray, interval),
                boxed.closest_hit(&ray, interval),
            );
            let same_closest = match (a, b) {
                (None, None) => true,
                (Some((i, h)), Some((j, k))) => {
                    i == j && h.t.to_bits() == k.t.to_bits()
                }
                _ => false,
            };
            let same_any =
                list.any_hit(&ray, interval) == boxed.any_hit(&ray, interval);
            disagreements +=
                usize::from(!same_closest) + usize::from(!same_any);
            rays += 1;
        }
    }
    assert_eq!(disagreements, 0, "of {rays} rays");
}
