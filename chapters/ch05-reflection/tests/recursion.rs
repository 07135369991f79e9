//! Exercise 2: the recursive tracer L = local + kr·Lr, and the two rules
//! that stop it (a maximum depth; a contribution below a threshold).
use ch04::{Offset, offset_scale_aware};
use ch05::{
    Cut, DEFAULT_STOP, DVec3, Interval, LoggedRay, Ray, RayCounts,
    SAFETY_DEPTH, Stop, World, pixel_tree, ray_tree, reflect_ray, render,
    trace_counted,
};
use raystep_check::{Table, num, vec3};

mod common;
use common::{chapter_scene, quiet, world_from};

/// Every pixel's primary ray of `world`, with its column and row.
fn primary_rays(world: &World) -> impl Iterator<Item = (u32, u32, Ray)> {
    world.camera.pixel_rays(world.width, world.height)
}

/// The largest kr of any material of `world`, in any channel: the best
/// mirror.
fn best_kr(world: &World) -> f64 {
    world
        .materials
        .iter()
        .map(|m| m.kr.max_element())
        .fold(0.0, f64::max)
}

/// The largest channel difference of two colours.
fn distance(a: DVec3, b: DVec3) -> f64 {
    (a - b).abs().max_element()
}

/// A colour to 6 decimals, for messages: `(0.168590, 0.258590, 0.438590)`.
fn rgb(c: DVec3) -> String {
    format!("({:.6}, {:.6}, {:.6})", c.x, c.y, c.z)
}

/// The counts that differ, by name: `reflected rays expected 3, got 0;
/// shadow rays expected 4, got 1`.
fn count_differences(got: &RayCounts, expected: &RayCounts) -> String {
    let fields = |c: &RayCounts| {
        [
            ("primary rays", c.primary),
            ("reflected rays", c.secondary),
            ("shadow rays", c.shadow),
            ("rays cut by depth", c.cut_by_depth),
            ("rays cut by contribution", c.cut_by_contribution),
        ]
    };
    fields(expected)
        .iter()
        .zip(fields(got))
        .filter(|((_, e), (_, g))| e != g)
        .map(|((name, e), (_, g))| format!("{name} expected {e}, got {g}"))
        .collect::<Vec<_>>()
        .join("; ")
}

/// One mirror: a mirror floor (kr coloured, so each channel is scaled on
/// its own) under a red ball that is no mirror. What the floor reflects
/// is the ball or the sky, neither of which reflects again.
const MIRROR_FLOOR: &str = r#"
[camera]
look_from = [0, 2.5, 6]
look_at = [0, -0.3, 0]
vfov = 45

[ambient]
intensity = 0.1

[background]
intensity = [0.3, 0.4, 0.6]

[[lights]]
position = [-3, 5, 4]
intensity = 0.9

[materials.mirror]
kd = 0.1
ks = 0.3
p = 50
kr = [0.5, 0.6, 0.7]

[materials.red]
kd = [0.8, 0.2, 0.15]
ks = 0.3
p = 40

[[objects]]
plane = { point = [0, -1, 0], normal = [0, 1, 0] }
material = "mirror"

[[objects]]
sphere = { center = [0, 0, 0], radius = 1 }
material = "red"
"#;

fn mirror_floor() -> World {
    world_from(MIRROR_FLOOR, "mirror-floor.toml", 32, 18)
}

/// Depth 0 shoots no reflected ray: every pixel is chapter 4's local
/// colour with shadows (scale-aware offset), and every primary ray that
/// hits a mirror is counted as cut by depth.
#[test]
fn depth_zero_is_the_chapter_04_colour() {
    for (name, world) in [
        ("the mirror floor", mirror_floor()),
        ("scenes/mirrors.toml", chapter_scene("mirrors", 48, 27)),
    ] {
        let mut on_mirrors = 0;
        let mut total = RayCounts::default();
        for (column, row, ray) in primary_rays(&world) {
            let (colour, counts) = trace_counted(&world, &ray, &Stop::depth(0));
            let local = ch04::trace(&world, &ray, Offset::ScaleAware);
            assert!(
                distance(colour, local) <= 1e-12,
                "{name}, pixel ({column}, {row}), depth ≤ 0: expected chapter \
                 04's colour {} (the local model with shadows, no reflected \
                 ray), got {} (off by {:.1e})",
                rgb(local),
                rgb(colour),
                distance(colour, local)
            );
            total += counts;
            if let Some((object, _)) =
                world.closest_hit(&ray, Interval::FORWARD)
            {
                on_mirrors +=
                    u64::from(world.material_of(object).kr != DVec3::ZERO);
            }
        }
        let pixels = u64::from(world.width * world.height);
        assert!(
            total.primary == pixels,
            "{name}, depth ≤ 0: primary rays: expected {pixels} (one per \
             pixel), got {}",
            total.primary
        );
        assert!(
            total.secondary == 0,
            "{name}, depth ≤ 0: reflected rays: expected 0 (depth 0 allows \
             none), got {}",
            total.secondary
        );
        assert!(on_mirrors > 0, "{name}: the test sees no mirror");
        assert!(
            total.cut_by_depth == on_mirrors,
            "{name}, depth ≤ 0: rays cut by the depth rule: expected \
             {on_mirrors} (one for every primary ray that hits a mirror: \
             its reflected ray would be at depth 1), got {}",
            total.cut_by_depth
        );
    }
}

/// Depth 1 adds kr·Lr where a primary ray hits the mirror, Lr being what
/// the reflected ray sees by chapter 4's local model. The reflected ray is
/// built here from exercise 1's `reflect_ray` (judged by
/// `tests/reflection.rs`), starting off the surface on the side the ray
/// came from.
#[test]
fn depth_one_adds_kr_times_what_the_reflected_ray_sees() {
    let world = mirror_floor();
    let (mut mirror_pixels, mut ball_in_mirror) = (0, 0);
    for (column, row, ray) in primary_rays(&world) {
        let pixel = format!("the mirror floor, pixel ({column}, {row})");
        let (colour, counts) = trace_counted(&world, &ray, &Stop::depth(1));
        let local = ch04::trace(&world, &ray, Offset::ScaleAware);
        let mut expected = local;
        if let Some((object, hit)) = world.closest_hit(&ray, Interval::FORWARD)
        {
            let kr = world.material_of(object).kr;
            if kr != DVec3::ZERO {
                let facing = hit.facing(ray.direction);
                let reflected = Ray::new(
                    offset_scale_aware(hit.point, facing),
                    reflect_ray(ray.direction, facing),
                );
                let seen = ch04::trace(&world, &reflected, Offset::ScaleAware);
                expected += kr * seen;
                mirror_pixels += 1;
                ball_in_mirror += usize::from(
                    world.closest_hit(&reflected, Interval::FORWARD).is_some(),
                );
                assert!(
                    counts.secondary == 1,
                    "{pixel}, on the mirror, depth ≤ 1: reflected rays: \
                     expected 1, got {}",
                    counts.secondary
                );
            }
        }
        assert!(
            distance(colour, expected) <= 1e-12,
            "{pixel}, depth ≤ 1: expected the local colour {} plus kr·Lr, {} \
             in all (Lr: what the reflected ray sees), got {} (off by {:.1e})",
            rgb(local),
            rgb(expected),
            rgb(colour),
            distance(colour, expected)
        );
        // Nothing the floor shows is a mirror: no ray was cut.
        assert!(
            counts.cut_by_depth == 0,
            "{pixel}, depth ≤ 1: rays cut by the depth rule: expected 0 (the \
             ball and the sky the floor reflects are no mirrors), got {}",
            counts.cut_by_depth
        );
        // So depth 2 changes nothing.
        let (deeper, _) = trace_counted(&world, &ray, &Stop::depth(2));
        assert!(
            distance(deeper, colour) <= 1e-12,
            "{pixel}: expected the same colour at depth ≤ 2 as at depth ≤ 1, \
             {} (nothing deeper to see), got {}",
            rgb(colour),
            rgb(deeper)
        );
    }
    // the test saw the mirror, and the ball in it
    assert!(
        mirror_pixels > 100 && ball_in_mirror > 20,
        "the test sees {mirror_pixels} mirror pixels and the ball in \
         {ball_in_mirror} of them"
    );
}

fn counts_row(table: &mut Table, rule: String, c: &RayCounts) {
    table.row(&[
        rule,
        c.primary.to_string(),
        c.secondary.to_string(),
        c.shadow.to_string(),
        c.cut_by_depth.to_string(),
        c.cut_by_contribution.to_string(),
        c.total().to_string(),
    ]);
}

const COUNT_COLUMNS: [&str; 7] = [
    "rule",
    "primary",
    "reflected",
    "shadow",
    "cut by depth",
    "cut by contribution",
    "total",
];

/// The rays the depth rule spends on the chapter's scenes (48×27 pixels).
/// One level deeper shoots exactly the rays the level above cut; and fewer
/// rays reach each level, since only those that hit a mirror go on. In
/// the mirrors scene no path is longer than two reflections at this size;
/// between the facing mirrors rays go on as deep as they are allowed.
#[test]
fn depth_rule_counts() {
    let mut table = Table::new(&COUNT_COLUMNS);
    for name in ["mirrors", "facing-mirrors"] {
        let world = chapter_scene(name, 48, 27);
        let counts: Vec<RayCounts> = (0..=5)
            .map(|depth| {
                render(&world, &Stop::depth(depth), &quiet(Some(2)))
                    .unwrap()
                    .1
            })
            .collect();
        for (depth, c) in counts.iter().enumerate() {
            counts_row(&mut table, format!("{name}, depth ≤ {depth}"), c);
            assert!(
                c.primary == 48 * 27,
                "{name}, depth ≤ {depth}: primary rays: expected 1296 (one \
                 per pixel of 48×27), got {}",
                c.primary
            );
            assert!(
                c.cut_by_contribution == 0,
                "{name}, depth ≤ {depth}: rays cut by contribution: expected \
                 0 (only the depth rule is on), got {}",
                c.cut_by_contribution
            );
        }
        for (depth, pair) in counts.windows(2).enumerate() {
            assert!(
                pair[1].secondary == pair[0].secondary + pair[0].cut_by_depth,
                "{name}: reflected rays at depth ≤ {}: expected {} + {} = {} \
                 (those at depth ≤ {depth}, and the ones depth ≤ {depth} \
                 cut), got {}",
                depth + 1,
                pair[0].secondary,
                pair[0].cut_by_depth,
                pair[0].secondary + pair[0].cut_by_depth,
                pair[1].secondary
            );
            assert!(
                pair[1].cut_by_depth <= pair[0].cut_by_depth,
                "{name}: rays cut by depth: expected at most {} at depth ≤ \
                 {} (as many as at depth ≤ {depth} or fewer), got {}",
                pair[0].cut_by_depth,
                depth + 1,
                pair[1].cut_by_depth
            );
        }
    }
    insta::assert_snapshot!(table.to_string());
}

/// The rays the contribution rule spends on the chapter's scenes (48×27).
/// Each tenfold lower threshold lets at least as many rays through. The
/// safety depth can only cut a ray whose parent, at depth 64, still
/// weighed at least the threshold, so at most best_kr⁶⁴: never in the
/// mirrors scene (0.8⁶⁴ ≈ 6·10⁻⁷), and between the facing mirrors (0.88
/// in green, 0.88⁶⁴ ≈ 2.8·10⁻⁴) only at 10⁻⁴.
#[test]
fn contribution_rule_counts() {
    let mut table = Table::new(&COUNT_COLUMNS);
    for name in ["mirrors", "facing-mirrors"] {
        let world = chapter_scene(name, 48, 27);
        let best_kr = best_kr(&world);
        let mut previous: Option<RayCounts> = None;
        for threshold in [1e-1, 1e-2, 1e-3, 1e-4] {
            let (_, c) =
                render(&world, &Stop::contribution(threshold), &quiet(Some(2)))
                    .unwrap();
            counts_row(
                &mut table,
                format!("{name}, contribution ≥ {threshold:e}"),
                &c,
            );
            let rule = format!("{name}, contribution ≥ {threshold:e}");
            assert!(
                c.primary == 48 * 27,
                "{rule}: primary rays: expected 1296 (one per pixel of \
                 48×27), got {}",
                c.primary
            );
            if best_kr.powi(SAFETY_DEPTH as i32) < threshold {
                assert!(
                    c.cut_by_depth == 0,
                    "{rule}: rays cut by the safety depth: expected 0 (no ray \
                     at depth {SAFETY_DEPTH} still weighs {threshold:e}), \
                     got {}",
                    c.cut_by_depth
                );
            }
            if let Some(p) = previous {
                assert!(
                    c.secondary >= p.secondary,
                    "{rule}: reflected rays: expected at least {} (a lower \
                     threshold lets at least as many through), got {}",
                    p.secondary,
                    c.secondary
                );
            }
            previous = Some(c);
        }
    }
    insta::assert_snapshot!(table.to_string());
}

/// Two parallel mirrors x = ±1 facing each other, both of reflectance
/// `kr` (and a little diffuse, kd = 0.1), lit from above.
fn facing_mirrors(kr: &str) -> World {
    let text = format!(
        r#"
[camera]
look_from = [0, 0, 5]
look_at = [0, 0, 0]

[ambient]
intensity = 0.1

[[lights]]
position = [0, 5, 0]
intensity = 1

[materials.mirror]
kd = 0.1
kr = {kr}

[[objects]]
plane = {{ point = [1, 0, 0], normal = [-1, 0, 0] }}
material = "mirror"

[[objects]]
plane = {{ point = [-1, 0, 0], normal = [1, 0, 0] }}
material = "mirror"
"#
    );
    world_from(&text, "facing.toml", 16, 9)
}

/// The ray between the two mirrors, perpendicular to both: it comes back
/// along itself at every bounce, forever unless a rule stops it.
const BETWEEN: Ray = Ray::new(DVec3::ZERO, DVec3::X);

/// Every hit of the ray is lit (the light is above, in front of both
/// mirrors), so each hit shoots one shadow ray. `what` says which mirrors
/// and which rule, for the message.
fn assert_one_chain(
    what: &str, c: &RayCounts, reflected: u64, cut_by_depth: u64,
    cut_by_contribution: u64,
) {
    let expected = RayCounts {
        primary: 1,
        secondary: reflected,
        shadow: reflected + 1,
        cut_by_depth,
        cut_by_contribution,
    };
    assert!(
        *c == expected,
        "the ray between {what}: expected {reflected} reflected rays, {} \
         shadow rays (one per hit) and the next reflected ray cut by {}: {}",
        reflected + 1,
        if cut_by_depth == 1 {
            "depth"
        } else {
            "contribution"
        },
        count_differences(c, &expected)
    );
}

/// The smallest n with kⁿ < threshold, the weight multiplied up one
/// bounce at a time.
fn first_weight_below(k: f64, threshold: f64) -> u64 {
    let (mut weight, mut n) = (1.0, 0);
    while weight >= threshold {
        weight *= k;
        n += 1;
    }
    n
}

/// Between facing mirrors both rules end the recursion. The depth rule
/// shoots exactly max_depth reflected rays and cuts the next. The
/// contribution rule cuts the first ray whose weight kⁿ falls below the
/// threshold; with perfect mirrors (k = 1) the weight never falls and the
/// safety depth ends it.
#[test]
fn facing_mirrors_terminate() {
    for kr in ["1", "0.85"] {
        let world = facing_mirrors(kr);
        for max_depth in [0, 1, 2, 7, 20] {
            let (_, c) =
                trace_counted(&world, &BETWEEN, &Stop::depth(max_depth));
            let what =
                format!("facing mirrors of kr {kr}, depth ≤ {max_depth}");
            assert_one_chain(&what, &c, u64::from(max_depth), 1, 0);
        }
    }
    let perfect = facing_mirrors("1");
    for threshold in [1e-1, 1e-3] {
        let (_, c) =
            trace_counted(&perfect, &BETWEEN, &Stop::contribution(threshold));
        let what = format!(
            "perfect facing mirrors (kr 1), contribution ≥ {threshold} (the \
             weight stays 1: the safety depth {SAFETY_DEPTH} ends it)"
        );
        assert_one_chain(&what, &c, u64::from(SAFETY_DEPTH), 1, 0);
    }
    let tarnished = facing_mirrors("0.85");
    let mut shot = Vec::new();
    for threshold in [1e-1, 1e-2, 1e-3, 1e-4] {
        let n = first_weight_below(0.85, threshold);
        let (_, c) =
            trace_counted(&tarnished, &BETWEEN, &Stop::contribution(threshold));
        // rays 1..n−1 are shot, ray n is cut
        let what = format!(
            "facing mirrors of kr 0.85, contribution ≥ {threshold} (ray {n} \
             is the first to weigh less, 0.85^{n})"
        );
        assert_one_chain(&what, &c, n - 1, 0, 1);
        shot.push(c.secondary);
    }
    // ln(threshold)/ln(0.85) rounded up, less one
    assert_eq!(shot, [14, 28, 42, 56], "reflected rays per threshold");
}

/// A cut by contribution happens exactly when the weight's largest channel
/// is below the threshold, worked by hand for kr = 0.5: the reflected
/// rays' weights are 0.5, 0.25, 0.125, 0.0625, …
#[test]
fn contribution_cut_by_hand() {
    #[rustfmt::skip]
    let cases = [
        // (kr, threshold, reflected rays shot)
        ("0.5", 0.1, 3),   // 0.0625 < 0.1: the 4th is cut
        ("0.5", 0.125, 3), // 0.125 is not below 0.125: shot
        ("0.5", 0.13, 2),  // 0.125 < 0.13: the 3rd is cut
        ("0.5", 0.5, 1),
        ("0.5", 0.6, 0),   // even the first, 0.5 < 0.6
        // the largest channel counts: 0.5ⁿ, not 0.1ⁿ or an average
        ("[0.5, 0.2, 0.1]", 0.1, 3),
        ("[0.1, 0.2, 0.5]", 0.1, 3),
    ];
    for (kr, threshold, reflected) in cases {
        let world = facing_mirrors(kr);
        let stop = Stop::contribution(threshold);
        let (_, counts) = trace_counted(&world, &BETWEEN, &stop);
        let what =
            format!("facing mirrors of kr {kr}, contribution ≥ {threshold}");
        assert_one_chain(&what, &counts, reflected, 0, 1);
        let cut: Vec<LoggedRay> = ray_tree(&world, &BETWEEN, &stop)
            .into_iter()
            .filter(|r| r.cut.is_some())
            .collect();
        let expected_weight = 0.5f64.powi(reflected as i32 + 1);
        assert!(
            cut.len() == 1,
            "the ray between {what}: rays cut: expected 1, got {}",
            cut.len()
        );
        assert!(
            cut[0].path.depth == reflected as u32 + 1,
            "the ray between {what}: the depth of the cut ray: expected {}, \
             got {}",
            reflected + 1,
            cut[0].path.depth
        );
        assert!(
            (cut[0].path.contribution() - expected_weight).abs() < 1e-15,
            "the ray between {what}: the contribution of the cut ray: \
             expected {expected_weight} (0.5^{}), got {}",
            reflected + 1,
            cut[0].path.contribution()
        );
    }
}

/// What the ray between the mirrors sees, by hand: every hit has the same
/// local colour L = ka·Ia + I·kd·(N·L̂) = 0.1·0.1 + 0.1/√26 (the light is
/// at (0, 5, 0), one unit across and five up from either hit; no ks), and
/// the k-th bounce brings it back scaled by krᵏ. So depth m gives
/// L·(1 + kr + … + krᵐ).
#[test]
fn facing_mirrors_colour_by_hand() {
    let local = 0.1 * 0.1 + 0.1 / 26f64.sqrt();
    let series = |kr: f64, m: u32| {
        (0..=m).map(|k| local * kr.powi(k as i32)).sum::<f64>()
    };
    let half = facing_mirrors("0.5");
    for m in [0, 1, 2, 5, 10] {
        let (colour, _) = trace_counted(&half, &BETWEEN, &Stop::depth(m));
        let expected = series(0.5, m);
        assert!(
            distance(colour, DVec3::splat(expected)) < 1e-12,
            "the ray between facing mirrors of kr 0.5, depth ≤ {m}: expected \
             {expected:.6} in every channel (L·(1 + kr + … + kr^{m}), L = \
             {local:.6} the local colour of every hit), got {}",
            rgb(colour)
        );
    }
    // kr = 0.5 and threshold 0.1: depths 0..=3 as worked above
    let (colour, _) = trace_counted(&half, &BETWEEN, &Stop::contribution(0.1));
    let expected = series(0.5, 3);
    assert!(
        distance(colour, DVec3::splat(expected)) < 1e-12,
        "the ray between facing mirrors of kr 0.5, contribution ≥ 0.1: \
         expected {expected:.6} in every channel (depths 0 to 3: the 4th ray \
         weighs 0.0625 < 0.1), got {}",
        rgb(colour)
    );
    // perfect mirrors to the safety depth: 65 equal terms
    let (colour, _) =
        trace_counted(&facing_mirrors("1"), &BETWEEN, &DEFAULT_STOP);
    assert!(
        distance(colour, DVec3::splat(65.0 * local)) < 1e-12,
        "the ray between perfect facing mirrors (kr 1), the default rule: \
         expected {:.6} in every channel (65 equal terms L, down to the \
         safety depth {SAFETY_DEPTH}), got {}",
        65.0 * local,
        rgb(colour)
    );
    // each channel is scaled by its own kr
    let (colour, _) = trace_counted(
        &facing_mirrors("[0.5, 0.25, 0]"),
        &BETWEEN,
        &Stop::depth(3),
    );
    let expected = DVec3::new(series(0.5, 3), series(0.25, 3), local);
    assert!(
        distance(colour, expected) < 1e-12,
        "the ray between facing mirrors of kr (0.5, 0.25, 0), depth ≤ 3: \
         expected {} (each channel scaled by its own kr), got {}",
        rgb(expected),
        rgb(colour)
    );
}

/// The ray trees of two pixels of the mirrors scene (160×90) that hit the
/// mirror ball: every ray in the order traced, with its depth, weight and
/// end, and the material of what it hits. (68, 50) under the default rule
/// sees the half-mirror ball in the mirror ball, and the floor in that; no
/// shadow ray where the light is behind the surface. (89, 29) sees the
/// mirror wall in the ball; its next ray (weight 0.8·kr of the wall) is
/// cut by depth 1, or by the contribution rule at 0.6 (0.576 < 0.6).
#[test]
fn pixel_trees_of_the_mirror_ball() {
    let world = chapter_scene("mirrors", 160, 90);
    let cases = [
        ((68, 50), DEFAULT_STOP),
        ((89, 29), Stop::depth(1)),
        ((89, 29), Stop::contribution(0.6)),
    ];
    let mut text = String::new();
    for ((column, row), stop) in cases {
        let rays = pixel_tree(&world, column, row, &stop);
        let mut table = Table::new(&[
            "#",
            "kind",
            "depth",
            "weight",
            "origin",
            "direction",
            "t",
            "ends",
        ]);
        for (i, r) in rays.iter().enumerate() {
            let material = || {
                world
                    .closest_hit(
                        &Ray::new(r.origin, r.direction),
                        Interval::FORWARD,
                    )
                    .map_or("?".to_string(), |(o, _)| {
                        world.material_of(o).name.clone()
                    })
            };
            let ends = match (r.cut, r.t) {
                (Some(Cut::Depth), _) => "cut: depth".to_string(),
                (Some(Cut::Contribution), _) => "cut: contribution".to_string(),
                (None, _) if r.shadow && r.blocked => "blocked".to_string(),
                (None, _) if r.shadow => "reaches the light".to_string(),
                (None, Some(_)) => format!("hits {}", material()),
                (None, None) => "background".to_string(),
            };
            // every secondary ray of this chapter is a reflected one
            let kind = if r.shadow {
                "Shadow"
            } else if r.is_primary() {
                "Primary"
            } else {
                "Reflected"
            };
            table.row(&[
                i.to_string(),
                kind.to_string(),
                r.path.depth.to_string(),
                vec3(r.path.weight),
                vec3(r.origin),
                vec3(r.direction),
                r.t.map_or("-".to_string(), num),
                ends,
            ]);
        }
        text += &format!("pixel ({column}, {row}), {stop:?}\n{table}\n");
    }
    insta::assert_snapshot!(text);
}

/// The largest colour any one ray can bring back from its own hit:
/// ka·Ia + Σᵢ Iᵢ·(kd + ks) over the materials (both checker colours), or
/// the background, channel by channel.
fn brightest_local(world: &World) -> DVec3 {
    let lights: DVec3 = world.lights.iter().map(|l| l.intensity).sum();
    world
        .materials
        .iter()
        .flat_map(|m| {
            let checker =
                m.checker.as_ref().map_or((m.ka, m.kd), |c| (c.ka, c.kd));
            [(m.ka, m.kd), checker]
                .map(|(ka, kd)| ka * world.ambient + lights * (kd + m.ks))
        })
        .fold(world.background, DVec3::max)
}

/// With every kr ≤ 1 no ray weighs more than 1; more precisely a ray at
/// depth k weighs at most krᵏ of the best mirror (0.8 in the mirrors
/// scene), so the terms of the sum shrink geometrically.
#[test]
fn no_weight_exceeds_one() {
    for name in ["mirrors", "facing-mirrors"] {
        let world = chapter_scene(name, 48, 27);
        let best = best_kr(&world);
        assert!(best < 1.0, "{name}: the best mirror's kr is {best}");
        let mut deepest = 0;
        for (column, row, _) in primary_rays(&world) {
            for r in pixel_tree(&world, column, row, &DEFAULT_STOP) {
                let w = r.path.weight;
                assert!(
                    w.min_element() >= 0.0 && w.max_element() <= 1.0,
                    "{name}, pixel ({column}, {row}), a ray at depth {}: \
                     expected a weight between 0 and 1 in every channel, got \
                     {w}",
                    r.path.depth
                );
                let bound = best.powi(r.path.depth as i32) * (1.0 + 1e-12);
                assert!(
                    w.max_element() <= bound,
                    "{name}, pixel ({column}, {row}), a ray at depth {}: \
                     expected a weight of at most {best}^{} = {bound}, got \
                     {w}",
                    r.path.depth,
                    r.path.depth
                );
                deepest = deepest.max(r.path.depth);
            }
        }
        assert!(
            deepest >= 2,
            "{name}: expected rays at depth 2 or more (mirrors see each \
             other), got none deeper than {deepest}"
        );
    }
}

/// Going one level deeper only adds light: the image at depth d + 1 is
/// nowhere darker than at depth d, and brighter by at most what the one
/// ray cut at depth d in that pixel can bring: its weight times the
/// brightest local colour (a pixel's tree is a chain here, one reflected
/// ray per hit, so at most one ray is cut).
#[test]
fn each_level_adds_at_most_its_cut_ray() {
    for name in ["mirrors", "facing-mirrors"] {
        each_level_adds_at_most_its_cut_ray_in(&chapter_scene(name, 48, 27));
    }
}

fn each_level_adds_at_most_its_cut_ray_in(world: &World) {
    let brightest = brightest_local(world);
    let images: Vec<_> = (0..=4)
        .map(|depth| {
            render(world, &Stop::depth(depth), &quiet(Some(2)))
                .unwrap()
                .0
        })
        .collect();
    let mut brighter = 0;
    for depth in 0..4 {
        let (shallow, deep) = (&images[depth], &images[depth + 1]);
        for (column, row, _) in primary_rays(world) {
            let (a, b) = (shallow.get(column, row), deep.get(column, row));
            let tree =
                pixel_tree(world, column, row, &Stop::depth(depth as u32));
            let cut: Vec<_> = tree.iter().filter(|r| r.cut.is_some()).collect();
            assert!(
                cut.len() <= 1,
                "pixel ({column}, {row}), depth ≤ {depth}: rays cut: expected \
                 at most 1 (a pixel's tree is a chain here), got {}",
                cut.len()
            );
            let bound = cut
                .first()
                .map_or(DVec3::ZERO, |r| r.path.weight * brightest);
            assert!(
                a.cmple(b).all() && (b - a).cmple(bound + 1e-12).all(),
                "pixel ({column}, {row}), from depth ≤ {depth} to depth ≤ {}: \
                 expected the colour {} to grow by at most {} (what the one \
                 cut ray can bring), got {}",
                depth + 1,
                rgb(a),
                rgb(bound),
                rgb(b)
            );
            brighter += usize::from(a != b);
        }
    }
    assert!(
        brighter > 100,
        "pixels that change when one level deeper is allowed: expected more \
         than 100, got {brighter}"
    );
}

/// The reflected ray leaves from the side the ray came from: it never
/// finds the surface it starts on (every shape here is convex or flat, so
/// a reflected ray cannot truly hit its own object again), and nothing at
/// t < 1e-9. The parent of a reflected ray is the primary or reflected ray
/// before it in the tree (a chain).
#[test]
fn reflected_rays_never_hit_their_own_surface() {
    for name in ["mirrors", "facing-mirrors"] {
        let world = chapter_scene(name, 48, 27);
        let object_hit = |r: &LoggedRay| {
            world
                .closest_hit(
                    &Ray::new(r.origin, r.direction),
                    Interval::FORWARD,
                )
                .map(|(object, hit)| (hit.t, object))
        };
        let (mut checked, mut self_hits, mut too_close) = (0, 0, 0);
        for (column, row, _) in primary_rays(&world) {
            let tree = pixel_tree(&world, column, row, &DEFAULT_STOP);
            let mut parent: Option<&LoggedRay> = None;
            for r in tree.iter().filter(|r| !r.shadow) {
                if !r.is_primary() && r.cut.is_none() {
                    let Some((_, source)) = parent.and_then(object_hit) else {
                        panic!(
                            "{name}, pixel ({column}, {row}): expected a \
                             reflected ray only where the ray before it hit \
                             a mirror, got one from {} along {} after a ray \
                             that hit nothing",
                            r.origin, r.direction
                        );
                    };
                    checked += 1;
                    if let Some((t, object)) = object_hit(r) {
                        self_hits += usize::from(object == source);
                        too_close += usize::from(t < 1e-9);
                    }
                }
                parent = Some(r);
            }
        }
        assert!(
            checked > 200,
            "{name}: reflected rays checked: expected more than 200, got \
             {checked}"
        );
        assert!(
            (self_hits, too_close) == (0, 0),
            "{name}: reflected rays that hit the surface they start on, and \
             that hit something closer than t = 1e-9: expected 0 and 0 of \
             {checked} (start off the surface, on the side the ray came \
             from), got {self_hits} and {too_close}"
        );
    }
}
