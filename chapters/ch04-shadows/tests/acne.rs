//! Acne and leaks of each strategy in the acne scene made tiny, normal
//! and huge. (Uses both exercises through the strategies.)
use ch04::{Offset, World, scaled_scene, shadow_errors};
use raystep_check::{Table, num};

/// The acne scene at `scale`, 96 × 54 pixels (its own 16:9).
fn scene(scale: f64) -> World {
    let mut world = scaled_scene(scale);
    (world.width, world.height) = (96, 54);
    world
}

const SCALES: [f64; 3] = [1e-3, 1.0, 1e4];

/// The strategies compared, with the fixed ε each takes.
#[rustfmt::skip]
const STRATEGIES: [(&str, Offset); 6] = [
    // No protection: t from 0. Most floor points round to exactly y = −1,
    // and the closed interval then counts the floor itself at t = 0; the
    // others lie half below their surface: most pixels get acne.
    ("TMin(0)", Offset::TMin(0.0)),
    // ε a fixed distance of 1e-4: at scale 1e-3 that is a tenth of a scene
    // unit. Still no leaks here: a ray that enters a sphere before ε leaves
    // it after ε, and that exit counts as a hit; only a blocker crossed
    // entirely within ε is lost (the thin sheet of tests/normal_offset.rs).
    // At larger scales ε is far above the rounding error: clean.
    ("TMin(1e-4)", Offset::TMin(1e-4)),
    // ε = 1e-12: below the rounding error of points at scale 1e4 (about
    // 1e-12 there), so those points find their own surface again (acne).
    ("TMin(1e-12)", Offset::TMin(1e-12)),
    // A fixed distance: at scale 1e-3 it is a tenth of a scene unit. Floor
    // points near a shadow's edge send their ray over the sphere (leaks),
    // and floor points just beside a sphere start inside it (acne).
    ("AlongNormal(1e-4)", Offset::AlongNormal(1e-4)),
    // A fixed distance small enough for every small scene: at 1e4 the hit
    // points' rounding error (a few ulps of numbers near 1e4 to 7e4, 2e-12
    // to 1.5e-11) passes it and acne returns. In f64 no single fixed
    // distance fails at both ends of 1e-3 … 1e4: the gap between rounding
    // error and scene detail is 13 orders of magnitude wide.
    ("AlongNormal(1e-12)", Offset::AlongNormal(1e-12)),
    ("ScaleAware", Offset::ScaleAware),
];

/// Fractions of the pixels (with the light in front of the surface) whose
/// shadow each strategy gets wrong, at scales 1e-3, 1 and 1e4.
#[test]
fn acne_and_leaks_table() {
    let mut table =
        Table::new(&["scale", "strategy", "pixels", "acne", "leaks"]);
    for scale in SCALES {
        let world = scene(scale);
        for (name, offset) in STRATEGIES {
            let e = shadow_errors(&world, offset);
            table.row(&[
                format!("{scale:e}"),
                name.to_string(),
                e.pixels.to_string(),
                num(e.acne_fraction()),
                num(e.leak_fraction()),
            ]);
        }
    }
    insta::assert_snapshot!(table.to_string());
}

/// The scale-aware offset gets every pixel right at every scale.
#[test]
fn scale_aware_has_no_acne_and_no_leaks() {
    for scale in [1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e3, 1e4] {
        let e = shadow_errors(&scene(scale), Offset::ScaleAware);
        assert!(
            e.pixels > 4000,
            "the acne scene at scale {scale}: expected more than 4000 \
             pixels with the light in front of the surface, got {}",
            e.pixels
        );
        assert!(
            (e.acne, e.leaks) == (0, 0),
            "the acne scene at scale {scale}, scale-aware offset: expected 0 \
             pixels with acne and 0 with leaks, got {} and {} (of {})",
            e.acne,
            e.leaks,
            e.pixels
        );
    }
}
