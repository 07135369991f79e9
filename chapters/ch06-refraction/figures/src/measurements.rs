//! The data behind chapter 6's chart: for each material of the lecture's
//! table, one ball rendered with the exact Fresnel split, with Schlick's
//! approximation and with no split at all; how far the last two are from
//! the first and how many rays each shoots (computed, the same on every
//! machine), how long a render takes and how long one call of each
//! reflectance formula takes (measured, on this machine).
//!
//! `raystep measure` runs [`measure_fresnel`] and writes its rows into
//! `book/src/figures/ch06/fresnel.csv`; `raystep figures` draws the chart
//! from that file, so the figures stay byte-identical between runs.
use std::hint::black_box;

use raystep_figure::as_jobs;
use raystep_render::csv::{Decimals, Plain, Row};
use raystep_render::timing::Timing;
use raystep_render::{Progress, RenderOptions, image_error};
use raystep_scene::Shape as ShapeSpec;

use ch06::{DEFAULT_STOP, DVec3, Fresnel, REFRACTIVE_INDICES, World, render};
use serde::{Deserialize, Serialize};

/// The scene the chart's worlds are cut from: one ball of each material.
pub const MATERIALS_SCENE: &str = include_str!("../../scenes/materials.toml");

/// The three ways to split kt on the chart, with their names in the CSV.
pub const CHART_MODES: [(&str, Fresnel); 3] = [
    ("exact", Fresnel::Exact),
    ("schlick", Fresnel::Schlick),
    ("off", Fresnel::Off),
];

/// What every image is compared with: the exact Fresnel equations.
pub const REFERENCE: Fresnel = Fresnel::Exact;

/// The image size measured: 160 × 90.
pub const CHART_SIZE: (u32, u32) = (160, 90);

/// Calls of a reflectance formula per timed batch.
pub const CALLS: u32 = 100_000;

/// `scenes/materials.toml` with only the ball of `material`, moved to the
/// middle of the row (x = 0) so that every material has the same checks
/// behind it, seen from close up at [`CHART_SIZE`].
///
/// # Panics
/// If the scene has no ball of that material.
pub fn one_ball(material: &str) -> World {
    ch03::world(&one_ball_scene(material), "materials.toml")
        .expect("the chapter's scene builds")
}

/// The scene file of [`one_ball`].
///
/// # Panics
/// If the scene has no ball of that material.
pub fn one_ball_scene(material: &str) -> raystep_scene::Scene {
    let mut scene = raystep_scene::parse(MATERIALS_SCENE, "materials.toml")
        .expect("the chapter's scene parses");
    // the floor, the wall and the ball of `material`; no other ball
    let materials = &scene.materials;
    scene.objects.retain(|o| match o.shape {
        ShapeSpec::Sphere { .. } => materials[o.material].name == material,
        _ => true,
    });
    let ball = scene
        .objects
        .iter_mut()
        .find_map(|o| match &mut o.shape {
            ShapeSpec::Sphere { center, .. } => Some(center),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no ball of `{material}` in materials.toml"));
    ball.x = 0.0;
    let centre = *ball;
    scene.camera.look_at = centre;
    scene.camera.look_from = centre + DVec3::new(0.0, 0.6, 4.0);
    (scene.width, scene.height) = CHART_SIZE;
    scene
}

/// One material with one way of splitting kt: a line of `fresnel.csv`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FresnelRow {
    /// The material's name in [`REFRACTIVE_INDICES`].
    pub material: String,
    /// Its index of refraction.
    #[serde(with = "Plain")]
    pub ior: f64,
    /// The mode's name in [`CHART_MODES`].
    pub mode: String,
    /// RMSE against the [`REFERENCE`] image, in 8-bit levels.
    #[serde(with = "Decimals::<6>")]
    pub rmse: f64,
    /// The largest error against it, in 8-bit levels.
    #[serde(with = "Plain")]
    pub max_error: f64,
    /// Every ray shot: primary, shadow, reflected and transmitted.
    pub rays: u64,
    /// The median time of one single-threaded render, in milliseconds.
    #[serde(with = "Decimals::<3>")]
    pub millis: f64,
    /// The median time of one call of the mode's reflectance, in
    /// nanoseconds (half the calls entering the material, half leaving).
    #[serde(with = "Decimals::<3>")]
    pub nanos_per_call: f64,
}

impl Row for FresnelRow {
    fn check(&self) -> Result<(), String> {
        if CHART_MODES.iter().any(|(name, _)| *name == self.mode) {
            Ok(())
        } else {
            Err(format!("unknown mode `{}`", self.mode))
        }
    }
}

/// One timed batch: [`CALLS`] reflectances of `mode` at cos θ spread over
/// [0, 1], half of them entering a material of index `ior` from vacuum,
/// half leaving it.
fn batch(mode: Fresnel, ior: f64) -> f64 {
    let mut sum = 0.0;
    for k in 0..CALLS {
        let cos_theta = f64::from(k / 2) / f64::from(CALLS / 2);
        let (n_theta, n_phi) = if k % 2 == 0 { (1.0, ior) } else { (ior, 1.0) };
        sum += black_box(mode).reflectance(
            black_box(cos_theta),
            n_theta,
            black_box(n_phi),
        );
    }
    sum
}

/// How a render is timed: 8 renders of 160 × 90 per sample, the three
/// modes of a material taking turns; `raystep measure --repeats` sets the
/// number of rounds.
pub const RENDER_TIMING: Timing = Timing {
    rounds: 11,
    batch: 8,
};

/// Measures every mode of [`CHART_MODES`] on the one-ball world of every
/// material of [`REFRACTIVE_INDICES`]: errors and ray counts once
/// (computed); render time per [`RENDER_TIMING`] and time per call of the
/// reflectance (batches of [`CALLS`]) with `rounds` rounds, the modes of a
/// material taking turns (measured). `step` is called after each material,
/// for a progress bar.
pub fn measure_fresnel(
    rounds: usize, mut step: impl FnMut(),
) -> Vec<FresnelRow> {
    let options = RenderOptions {
        threads: Some(1),
        progress: Progress::Never,
    };
    let draw = |world: &World, mode: Fresnel| {
        render(world, &DEFAULT_STOP, mode, &options).expect("a small render")
    };
    let mut rows = Vec::new();
    for (material, ior) in REFRACTIVE_INDICES {
        let world = one_ball(material);
        let (reference, _) = draw(&world, REFERENCE);
        let (mut renders, mut formulas): (Vec<_>, Vec<_>) = CHART_MODES
            .iter()
            .map(|&(_, mode)| {
                let world = &world;
                let draw = &draw;
                (
                    Box::new(move || {
                        black_box(draw(world, mode));
                    }) as Box<dyn FnMut() + '_>,
                    Box::new(move || {
                        black_box(batch(mode, ior));
                    }) as Box<dyn FnMut() + '_>,
                )
            })
            .unzip();
        let millis = RENDER_TIMING
            .with_rounds(rounds)
            .median_ms(&mut as_jobs(&mut renders), || ());
        let formula_ms = Timing { rounds, batch: 1 }
            .median_ms(&mut as_jobs(&mut formulas), || ());
        for (k, (name, mode)) in CHART_MODES.into_iter().enumerate() {
            let (image, counts) = draw(&world, mode);
            let error = image_error(&image, &reference);
            rows.push(FresnelRow {
                material: material.to_string(),
                ior,
                mode: name.to_string(),
                rmse: error.rmse,
                max_error: error.max,
                rays: counts.total(),
                millis: millis[k],
                nanos_per_call: formula_ms[k] * 1e6 / f64::from(CALLS),
            });
        }
        step();
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_render::csv::{from_csv, from_lines, to_csv};

    #[test]
    fn csv_round_trip_and_errors() {
        let rows = vec![FresnelRow {
            material: "glass".into(),
            ior: 1.5,
            mode: "schlick".into(),
            rmse: 0.25,
            max_error: 7.0,
            rays: 41234,
            millis: 3.5,
            nanos_per_call: 2.125,
        }];
        let csv = to_csv(&rows);
        assert!(
            csv.contains("\nglass,1.5,schlick,0.250000,7,41234,3.500,2.125\n")
        );
        assert_eq!(from_csv::<FresnelRow>(&csv).unwrap(), rows);
        let bad = from_lines::<FresnelRow>("glass,1.5,cheap,0,0,1,1,1\n");
        assert_eq!(bad.unwrap_err(), "line 2: unknown mode `cheap`");
    }

    /// The committed file reads and writes back byte for byte: a new
    /// measurement writes its format.
    #[test]
    fn the_committed_csv_writes_back_unchanged() {
        raystep_figure::writes_back::<FresnelRow>("ch06", "fresnel.csv")
            .unwrap();
    }

    #[test]
    fn one_ball_keeps_one_ball_of_the_material_in_the_middle() {
        for (material, ior) in REFRACTIVE_INDICES {
            let (scene, world) = (one_ball_scene(material), one_ball(material));
            let balls: Vec<_> = scene
                .objects
                .iter()
                .filter_map(|o| match &o.shape {
                    ShapeSpec::Sphere { center, .. } => {
                        Some((center, &scene.materials[o.material]))
                    }
                    _ => None,
                })
                .collect();
            assert_eq!(balls.len(), 1, "{material}: one ball");
            let (center, ball_material) = balls[0];
            assert_eq!(ball_material.name, material);
            assert_eq!(ball_material.ior, ior);
            assert_eq!(center.x, 0.0, "{material}: in the middle");
            // the floor and the wall stay
            assert_eq!(world.objects.len(), 3, "{material}");
            // the middle pixel looks at the ball
            let ray = world.camera.pixel_ray(80, 45, 160, 90);
            let (object, _) = world
                .closest_hit(&ray, ch06::Interval::FORWARD)
                .expect("the middle pixel hits");
            let shape = &scene.objects[object].shape;
            assert!(matches!(shape, ShapeSpec::Sphere { .. }), "{material}");
        }
    }

    #[test]
    fn each_batch_averages_entering_and_leaving() {
        // Off reflects nothing; exact and Schlick agree at normal incidence
        // and both are 1 past the critical angle, so their sums are close
        // but not equal.
        assert_eq!(batch(Fresnel::Off, 1.5), 0.0);
        let (exact, schlick) =
            (batch(Fresnel::Exact, 1.5), batch(Fresnel::Schlick, 1.5));
        assert!(exact > 0.0 && schlick > 0.0);
        assert!(
            (exact - schlick).abs() / exact < 0.1,
            "{exact} vs {schlick}"
        );
        assert_ne!(exact, schlick);
    }
}
