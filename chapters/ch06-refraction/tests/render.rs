//! The whole tracer: local light, kr·Lr and kt·Lt through nested media.
//! These use both exercises (Snell's law everywhere, Schlick where asked).
use ch06::{
    DEFAULT_STOP, DVec3, Fresnel, Image, LoggedRay, Media, Path as RayPath,
    Ray, RayCounts, RenderOptions, Stop, Tracer, World, pixel_tree, render,
};
use raystep_check::{Tolerance, assert_image_matches, differing_pixels};
use raystep_render::Progress;
use std::path::Path;

/// A scene of the chapter's `scenes/` folder at `width × height`.
fn scene(file: &str, width: u32, height: u32) -> World {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(file);
    let mut world = ch03::load(&path).expect("the chapter's scene loads");
    (world.width, world.height) = (width, height);
    world
}

/// A world from scene-file text.
fn world(toml: &str) -> World {
    ch03::parse(toml, "test.toml").expect("the test scene builds")
}

/// Render options for tests: no progress bar, and a pool of `threads`
/// threads of its own (`Some`), started from the test's thread: a panic in
/// a row (a `todo!()` in student mode) is then reported with the test that
/// made it, not with whichever test started rayon's global pool.
fn quiet(threads: Option<usize>) -> RenderOptions {
    RenderOptions {
        threads,
        progress: Progress::Never,
    }
}

fn draw(world: &World, fresnel: Fresnel) -> (Image, RayCounts) {
    render(world, &DEFAULT_STOP, fresnel, &quiet(Some(2))).unwrap()
}

/// The air bubble in the water ball: the checks through the water, and
/// in the bubble's middle the checks shrunk and upright again, its rim a
/// ring of total internal reflection.
#[test]
fn bubble_ascii() {
    let (image, _) = draw(&scene("bubble.toml", 64, 36), Fresnel::Exact);
    insta::assert_snapshot!(image.to_ascii(64));
}

/// Every ray the bubble scene takes at 64 × 36, by kind. Inside the water
/// rays meet the bubble past the critical angle of water to air (48.8°):
/// total internal reflections happen (506 of them); every crossing agrees
/// with the stack of media; and rule 2 alone ends every tree (no cut by
/// the safety depth).
#[test]
fn bubble_counts() {
    let (_, counts) = draw(&scene("bubble.toml", 64, 36), Fresnel::Exact);
    assert!(
        counts.total_internal_reflections > 0,
        "the bubble at 64×36: total internal reflections: expected some \
         (rays in the water meet the bubble past 48.8°), got none"
    );
    assert!(
        counts.medium_mismatches == 0,
        "the bubble at 64×36: crossings that contradict the stack of media: \
         expected 0, got {}",
        counts.medium_mismatches
    );
    insta::assert_snapshot!(format!("{counts:#?}"));
}

/// The materials scene at its own 224 × 72 pixels with the exact Fresnel
/// split, against tests/images/materials.png within the default tolerance
/// (2 levels of 8-bit sRGB on at most 0.1 % of the pixels).
/// RAYSTEP_BLESS=1 rewrites the reference; look at it before committing.
#[test]
fn materials_image() {
    let (image, _) = draw(&scene("materials.toml", 224, 72), Fresnel::Exact);
    let expected = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/images/materials.png");
    assert_image_matches(&image, &expected, Tolerance::default());
}

/// One ball of radius 1 at the origin, clear (kt = 1, no diffuse, no
/// highlight) with index `ior`, in front of a grey background; no lights.
fn clear_ball(ior: f64) -> World {
    world(&format!(
        r#"
[camera]
look_from = [0, 0, 5]
look_at = [0, 0, 0]
[background]
intensity = 0.5
[materials.clear]
kd = 0
kt = 1
ior = {ior}
[[objects]]
sphere = {{ center = [0, 0, 0], radius = 1 }}
material = "clear"
"#
    ))
}

/// What happens to rays that hit a clear ball ever closer to its rim.
#[derive(Debug, Default)]
struct Tangent {
    /// Impact parameters whose ray hit the ball.
    hits: usize,
    /// Rays inside the ball whose next hit was not the far end of their
    /// chord: a self-hit near t = 0, or a miss.
    wrong_exits: usize,
    /// The largest |t/chord − 1| of the rays inside, chord computed from b.
    worst_chord_error: f64,
    /// The tracer's counts over the whole sweep.
    counts: RayCounts,
}

/// Shoots 1000 rays at the unit ball at impact parameters b = 1 − gap,
/// gap from 1e-1 down to 1e-13, and follows each ray tree three bounces
/// deep (rule 1 only: near the rim the Fresnel reflection takes nearly
/// everything and rule 2 would cut the transmitted rays we look at).
///
/// A ray inside (it starts inside: the transmitted ray at depth 1, and
/// every ray reflected off the inside) must next hit the far end of its
/// chord. Its line passes the centre closest at t_mid = −O·D, halfway
/// along the chord; a self-hit where it started would come at t ≈ 0, far
/// before t_mid; the far end is at t_mid + √(t_mid² + 1 − |O|²), about
/// 2·t_mid.
fn sweep_the_rim(ior: f64) -> Tangent {
    let world = clear_ball(ior);
    let stop = Stop::depth(3);
    let mut out = Tangent::default();
    for i in 0..1000 {
        let gap = 10f64.powf(-1.0 - 12.0 * f64::from(i) / 999.0);
        let b = 1.0 - gap;
        let ray = Ray::new(DVec3::new(b, 0.0, 5.0), DVec3::new(0.0, 0.0, -1.0));
        let tracer = Tracer::recording(&world, stop, Fresnel::Exact);
        tracer.trace(&ray, RayPath::PRIMARY, &Media::new(1.0));
        let counts = tracer.counts();
        let rays = tracer.ray_tree();
        if rays[0].t.is_none() {
            continue;
        }
        out.hits += 1;
        // every chord inside a sphere has the same length: the refracted
        // ray passes the centre at b/n (Snell's law at the rim)
        let chord = 2.0 * (1.0 - (b / ior).powi(2)).sqrt();
        let inside = rays.iter().filter(|r| {
            r.cut.is_none() && !r.shadow && r.origin.length() < 1.0
        });
        for ray in inside {
            let d = ray.direction.normalize();
            let t_mid = -ray.origin.dot(d);
            // the far end, from an origin a little inside the surface
            let depth = (1.0 - ray.origin.length_squared()).abs();
            let t_far = t_mid + (t_mid * t_mid + depth).sqrt();
            match ray.t {
                Some(t) if t > t_mid && t < t_far * (1.0 + 1e-3) => {
                    let error = (t / chord - 1.0).abs();
                    out.worst_chord_error = out.worst_chord_error.max(error);
                }
                _ => out.wrong_exits += 1,
            }
        }
        out.counts += counts;
    }
    out
}

/// A ray that enters a ball near its rim leaves it again through the far
/// side, however close to tangent: never a self-hit at t ≈ 0 where it
/// entered, never a medium mismatch.
///
/// Glass bends the ray toward the normal, so its chord stays long
/// (2·cos θc = 1.49 at the rim); in vacuum (n = 1) the ray goes straight
/// on and the chord shrinks to 2·√(2·gap), 9e-7 at gap = 1e-13: entry and
/// exit nearly coincide. Still every ray finds the far side. The chord
/// comes out up to 30 % longer than 2·√(2·gap), and that is the offset at
/// work, not an error: the transmitted ray starts 256 ulps (5.7e-14)
/// inside the surface, so its line passes the centre at 1 − gap − 5.7e-14,
/// a chord of 2·√(2·(gap + 5.7e-14)). Inside a ball no ray meets the
/// surface past the critical angle: no total internal reflection either.
#[test]
fn a_ray_near_the_rim_leaves_through_the_far_side() {
    for ior in [1.5, 1.33, 1.0003, 1.0] {
        let sweep = sweep_the_rim(ior);
        println!("n = {ior}: {sweep:?}");
        let ball =
            format!("a clear ball of n = {ior}, rays ever closer to its rim");
        assert!(
            sweep.hits == 1000,
            "{ball}: rays that hit it: expected all 1000, got {}",
            sweep.hits
        );
        assert!(
            sweep.wrong_exits == 0,
            "{ball}: rays inside whose next hit is not the far end of their \
             chord (a hit at t ≈ 0 where they start, or none): expected 0, \
             got {}",
            sweep.wrong_exits
        );
        assert!(
            sweep.counts.medium_mismatches == 0,
            "{ball}: crossings that contradict the stack of media: expected \
             0, got {}",
            sweep.counts.medium_mismatches
        );
        assert!(
            sweep.counts.total_internal_reflections == 0,
            "{ball}: total internal reflections: expected 0 (inside a ball no \
             ray meets the surface past the critical angle), got {}",
            sweep.counts.total_internal_reflections
        );
        let allowed = if ior == 1.0 { 0.3 } else { 1e-9 };
        assert!(
            sweep.worst_chord_error < allowed,
            "{ball}: the largest relative error of a chord: expected below \
             {allowed}, got {}",
            sweep.worst_chord_error
        );
    }
}

/// A room (checkered floor and wall, one light) with these balls in it,
/// each `(centre, radius, material)` with materials water (kt = 1,
/// n = 1.33), glass (kt = 1, n = 1.5) and air (kt = 1, n = 1.0003), all
/// with a highlight and no diffuse light.
fn room(balls: &[([f64; 3], f64, &str)]) -> World {
    let mut toml = String::from(
        r#"
[image]
width = 64
height = 36
[camera]
look_from = [0, 0.6, 6]
look_at = [0, 0.1, 0]
vfov = 32
[background]
intensity = [0.45, 0.6, 0.85]
[[lights]]
position = [-3, 6, 6]
intensity = 0.9
[materials.floor]
kd = 0.8
checker = { size = 0.5, kd = 0.15 }
[materials.water]
kd = 0
ks = 0.5
p = 300
kt = 1
ior = "water"
[materials.glass]
kd = 0
ks = 0.5
p = 300
kt = 1
ior = "glass"
[materials.air]
kd = 0
ks = 0.5
p = 300
kt = 1
ior = "air"
[[objects]]
plane = { point = [0, -1, 0], normal = [0, 1, 0] }
material = "floor"
[[objects]]
plane = { point = [0, 0, -3], normal = [0, 0, 1] }
material = "floor"
"#,
    );
    for ([x, y, z], radius, material) in balls {
        toml += &format!(
            "[[objects]]\nsphere = {{ center = [{x}, {y}, {z}], radius = {radius} }}\n\
             material = \"{material}\"\n"
        );
    }
    world(&toml)
}

/// Objects inside objects, properly nested: a glass ball in a water ball,
/// an air bubble in water (off centre, as in scenes/bubble.toml, so rays
/// cross the bubble at every angle, total internal reflection included).
/// Every surface any ray crosses agrees with its stack of media.
#[test]
fn nested_objects_have_no_medium_mismatches() {
    let centre = [0.0, 0.2, 0.0];
    let inner = [0.15, 0.3, 0.4];
    for (name, world) in [
        (
            "glass in water",
            room(&[(centre, 1.2, "water"), (inner, 0.6, "glass")]),
        ),
        (
            "air in water",
            room(&[(centre, 1.2, "water"), (inner, 0.6, "air")]),
        ),
        ("bubble.toml", scene("bubble.toml", 64, 36)),
    ] {
        let (_, counts) = draw(&world, Fresnel::Exact);
        println!("{name}: {counts:?}");
        assert!(
            counts.medium_mismatches == 0,
            "{name}: crossings that contradict the stack of media: expected \
             0, got {}",
            counts.medium_mismatches
        );
        assert!(
            counts.transmitted > 2000,
            "{name}: transmitted rays: expected more than 2000, got {}",
            counts.transmitted
        );
    }
}

/// Two balls with the same centre and radius, one water, one glass: every
/// ray meets both surfaces at the same t, bit for bit (the same numbers go
/// through the same sum). The closest-hit loop keeps a hit at equal t from
/// a later object (its interval is closed: t ≤ t_max), so the object
/// listed last is the only one ever hit, entering and leaving alike. The
/// stack never hears of the other: no mismatches, and the picture is the
/// one with the last ball alone, to the bit.
#[test]
fn coincident_surfaces_show_the_last_object() {
    let (c, r) = ([0.0, 0.2, 0.0], 1.2);
    let pixels = |world: &World| draw(world, Fresnel::Exact);
    for (both, alone) in [
        (
            room(&[(c, r, "water"), (c, r, "glass")]),
            room(&[(c, r, "glass")]),
        ),
        (
            room(&[(c, r, "glass"), (c, r, "water")]),
            room(&[(c, r, "water")]),
        ),
    ] {
        let ((both, counts), (alone, _)) = (pixels(&both), pixels(&alone));
        let differing = both
            .pixels()
            .iter()
            .zip(alone.pixels())
            .filter(|(a, b)| a != b)
            .count();
        println!("{counts:?}, {differing} differing");
        assert!(
            counts.medium_mismatches == 0,
            "two coincident balls: crossings that contradict the stack of \
             media: expected 0, got {}",
            counts.medium_mismatches
        );
        assert!(
            differing == 0,
            "two coincident balls: pixels that differ from the last ball \
             alone: expected 0 (the object listed last is the only one hit), \
             got {differing}"
        );
    }
}

/// With kr + kt ≤ 1 in every material, no ray of a pixel's tree carries
/// more than the pixel's own light: every ray's weight is at most 1 in
/// every channel, and so is the sum over all rays at the same depth (a
/// split hands on kr + kt ≤ 1 of its weight, so each generation of rays
/// together carries no more than the one before).
#[test]
fn no_energy_is_created() {
    // a glass ball that also mirrors (kr + kt = 1), beside a water ball
    // with an air bubble, lit and over the checkered floor
    let mut mirror_glass = room(&[
        ([-0.8, 0.0, 0.0], 0.7, "glass"),
        ([0.8, 0.0, 0.0], 0.7, "water"),
        ([0.8, 0.0, 0.3], 0.3, "air"),
    ]);
    let glass = mirror_glass
        .materials
        .iter_mut()
        .find(|m| m.name == "glass")
        .unwrap();
    (glass.kr, glass.kt) = (DVec3::splat(0.3), DVec3::new(0.7, 0.6, 0.5));
    let worlds = [
        ("room", mirror_glass),
        ("bubble.toml", scene("bubble.toml", 64, 36)),
        ("materials.toml", scene("materials.toml", 112, 36)),
    ];
    for (name, world) in &worlds {
        for m in &world.materials {
            assert!((m.kr + m.kt).max_element() <= 1.0, "{name}: {}", m.name);
        }
        let mut checked = 0;
        for row in (0..world.height).step_by(3) {
            for column in (0..world.width).step_by(3) {
                for fresnel in [Fresnel::Off, Fresnel::Exact, Fresnel::Schlick]
                {
                    let tree =
                        pixel_tree(world, column, row, &DEFAULT_STOP, fresnel);
                    check_weights(&tree, name);
                    checked += tree.len();
                }
            }
        }
        println!("{name}: {checked} rays");
    }
}

fn check_weights(tree: &[LoggedRay], name: &str) {
    let mut per_depth = Vec::<DVec3>::new();
    for ray in tree.iter().filter(|r| !r.shadow) {
        let w = ray.path.weight;
        assert!(
            w.min_element() >= 0.0 && w.max_element() <= 1.0,
            "{name}: a ray at depth {}: expected a weight between 0 and 1 in \
             every channel, got {w}",
            ray.path.depth
        );
        let depth = ray.path.depth as usize;
        if per_depth.len() <= depth {
            per_depth.resize(depth + 1, DVec3::ZERO);
        }
        per_depth[depth] += w;
    }
    for (depth, sum) in per_depth.iter().enumerate() {
        assert!(
            sum.max_element() <= 1.0 + 1e-12,
            "{name}: the rays at depth {depth} together: expected a weight of \
             at most 1 (a split hands on kr + kt ≤ 1), got {sum}"
        );
    }
}

/// Rows run in parallel, but each pixel is traced on its own: one thread
/// or two give the same image, bit for bit, and the same counts.
#[test]
fn same_render_for_one_and_two_threads() {
    let world = scene("bubble.toml", 48, 27);
    let one =
        render(&world, &DEFAULT_STOP, Fresnel::Exact, &quiet(Some(1))).unwrap();
    let two =
        render(&world, &DEFAULT_STOP, Fresnel::Exact, &quiet(Some(2))).unwrap();
    let differing = differing_pixels(&one.0, &two.0);
    assert!(
        differing == 0,
        "pixels that differ between one thread and two: expected 0 (every \
         pixel is traced on its own), got {differing}"
    );
    assert!(
        one.1 == two.1,
        "ray counts: expected the same on one thread and on two, got {:?} \
         and {:?}",
        one.1,
        two.1
    );
}

/// The root mean square difference of two images, in linear light.
fn rmse(a: &Image, b: &Image) -> f64 {
    let sum: f64 = a
        .pixels()
        .iter()
        .zip(b.pixels())
        .map(|(p, q)| (*p - *q).length_squared())
        .sum();
    (sum / (3.0 * a.pixels().len() as f64)).sqrt()
}

/// The three ways to split light at a transparent surface give three
/// different pictures of the materials scene, and Schlick's is much closer
/// to the exact one than the lecture's constant split (Fresnel off: no
/// reflection at all off the balls but total internal reflection).
#[test]
fn schlick_is_closer_to_exact_than_no_fresnel() {
    let world = scene("materials.toml", 224, 72);
    let [off, exact, schlick] =
        [Fresnel::Off, Fresnel::Exact, Fresnel::Schlick]
            .map(|f| draw(&world, f).0);
    let (off_error, schlick_error) =
        (rmse(&off, &exact), rmse(&schlick, &exact));
    // the reference: 0.0337 without Fresnel, 0.0109 with Schlick
    println!("RMSE to exact: off {off_error:.4}, Schlick {schlick_error:.4}");
    assert!(
        schlick_error > 0.0 && off_error > 0.0 && rmse(&off, &schlick) > 0.0,
        "the materials scene: expected three different pictures with Fresnel \
         off, exact and by Schlick, got RMSE {off_error} (off to exact), \
         {schlick_error} (Schlick to exact), {} (off to Schlick)",
        rmse(&off, &schlick)
    );
    assert!(
        schlick_error < 0.5 * off_error,
        "the materials scene: expected Schlick's picture at most half as far \
         from the exact one as the picture without Fresnel ({off_error}), got \
         {schlick_error}"
    );
}
