//! The data behind chapter 7's chart: how long each method takes to draw
//! the same scene as its number of triangles grows (measured, on this
//! machine), and how much work each did (counted, the same on every
//! machine).
//!
//! The scenes are `shapes.toml` (12 triangles) alone, then with a ball of
//! 20·4ⁿ triangles (n = 0 … 6) in the middle, and with the Stanford bunny
//! (3674 triangles) in the ball's place.
//!
//! `raystep measure` runs [`measure_scaling`] and writes its rows into
//! `book/src/figures/ch07/scaling.csv`; `raystep figures` draws the chart
//! from that file, so the figures stay byte-identical between runs.
use std::path::{Path, PathBuf};

use raystep_core::DVec3;
use raystep_render::csv::{Decimals, Row};
use raystep_render::timing::Timing;

use ch07::{Mesh, MeshError, SHAPES, Stage, rasterize, raycast};
use serde::{Deserialize, Serialize};

/// The image size measured: 160 × 90, as in the chapter's other figures.
pub const CHART_SIZE: (u32, u32) = (160, 90);

/// The ball's subdivisions on the chart: 20 … 81 920 triangles.
pub const BALL_SUBDIVISIONS: [u32; 7] = [0, 1, 2, 3, 4, 5, 6];

/// The name of the rasterizer in the CSV.
pub const RASTERIZE: &str = "rasterize";
/// The name of the brute-force ray caster in the CSV.
pub const RAYCAST: &str = "raycast";

/// Where the ball sits in `shapes.toml` ([`ch07::shapes`]), and its size:
/// the bunny is fitted into the same box.
const BALL_CENTRE: DVec3 = DVec3::new(0.0, 0.8, 0.2);
const BALL_SIZE: f64 = 1.6;

/// One stage on the chart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChartScene {
    /// `shapes.toml` alone: 12 triangles.
    Alone,
    /// `shapes.toml` with the ball of `n` subdivisions: 12 + 20·4ⁿ.
    Ball(u32),
    /// `shapes.toml` with the Stanford bunny in the ball's place.
    Bunny,
}

/// Every stage on the chart, the fastest first.
pub fn chart_scenes() -> Vec<ChartScene> {
    let balls = BALL_SUBDIVISIONS.iter().map(|&n| ChartScene::Ball(n));
    std::iter::once(ChartScene::Alone)
        .chain(balls)
        .chain(std::iter::once(ChartScene::Bunny))
        .collect()
}

/// The Stanford bunny: `../shared/meshes/bunny.obj` beside the workspace
/// (it is not part of the repository).
pub fn bunny_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../../shared/meshes/bunny.obj")
}

impl ChartScene {
    /// Its name in the CSV: `shapes`, `ball-3`, `bunny`.
    pub fn name(self) -> String {
        match self {
            ChartScene::Alone => "shapes".to_string(),
            ChartScene::Ball(n) => format!("ball-{n}"),
            ChartScene::Bunny => "bunny".to_string(),
        }
    }

    /// The stage at [`CHART_SIZE`], the bunny read from `bunny` (see
    /// [`bunny_path`]); an error names that file if it cannot be read.
    pub fn stage(self, bunny: &Path) -> Result<Stage, MeshError> {
        let (width, height) = CHART_SIZE;
        match self {
            ChartScene::Alone => Ok(shapes_alone(width, height)),
            ChartScene::Ball(n) => Ok(ch07::shapes(n, width, height)),
            ChartScene::Bunny => {
                let bunny =
                    Mesh::load_obj(bunny)?.fitted(BALL_CENTRE, BALL_SIZE);
                let mut stage = shapes_alone(width, height);
                let material = ball_material(&stage);
                stage.add_mesh(&bunny, material);
                Ok(stage)
            }
        }
    }

    /// How its two renders are timed, given `rounds` from `raystep
    /// measure --repeats`: the two methods take turns, 4 renders per
    /// sample on the small stages; one render per sample from the ball of
    /// 1292 triangles on, where one ray-cast render takes 0.1 s or more;
    /// and on the two largest balls, where it takes seconds, at most 3
    /// rounds (the median of 3 such renders is steady enough, and the
    /// whole run stays within a few minutes).
    pub fn timing(self, rounds: usize) -> Timing {
        match self {
            ChartScene::Ball(n) if n >= 5 => Timing {
                rounds: rounds.min(3),
                batch: 1,
            },
            ChartScene::Ball(3 | 4) | ChartScene::Bunny => {
                Timing { rounds, batch: 1 }
            }
            _ => TIMING.with_rounds(rounds),
        }
    }
}

/// How a small stage is timed: 4 renders per sample, the two methods
/// taking turns; `raystep measure --repeats` sets the number of rounds.
pub const TIMING: Timing = Timing {
    rounds: 11,
    batch: 4,
};

/// How many times [`measure_scaling`] calls its `step` for `rounds`.
pub fn steps(rounds: usize) -> u64 {
    chart_scenes()
        .into_iter()
        .map(|s| s.timing(rounds).rounds.max(1) as u64)
        .sum()
}

/// `shapes.toml` alone at `width × height`.
fn shapes_alone(width: u32, height: u32) -> Stage {
    let mut scene = raystep_scene::parse(SHAPES, "shapes.toml")
        .expect("the chapter's scene parses");
    (scene.width, scene.height) = (width, height);
    Stage::from_scene(&scene, "shapes.toml")
        .expect("the chapter's scene builds")
}

/// The index of the ball's material in `shapes.toml`.
fn ball_material(stage: &Stage) -> usize {
    stage
        .world
        .materials
        .iter()
        .position(|m| m.name == "ball")
        .expect("shapes.toml has a ball material")
}

/// One method on one stage: a line of `scaling.csv`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ScalingRow {
    /// The stage's [`ChartScene::name`].
    pub scene: String,
    /// The stage's triangles (what the rasterizer draws).
    pub triangles: u64,
    /// [`RASTERIZE`] or [`RAYCAST`].
    pub method: String,
    /// The work of the inner loop. Rasterizing: pixel centres tested
    /// against a triangle's edges (every pixel of each triangle's bounding
    /// box). Ray casting: ray–object tests, every pixel's ray against every
    /// object of the world (pixels × objects; the scene file's two quads
    /// are one object each, two triangles for the rasterizer).
    pub tests: u64,
    /// Rasterizing: tested pixels a triangle covers. Ray casting: pixels
    /// whose ray hits something.
    pub covered: u64,
    /// Pixels shaded. Rasterizing: covered pixels that passed the z test (a
    /// pixel is shaded again each time a closer triangle covers it). Ray
    /// casting: once per pixel that hits.
    pub shaded: u64,
    /// The median time of one single-threaded render, in milliseconds.
    #[serde(with = "Decimals::<4>")]
    pub millis: f64,
}

impl Row for ScalingRow {
    fn check(&self) -> Result<(), String> {
        if self.method != RASTERIZE && self.method != RAYCAST {
            return Err(format!("unknown method `{}`", self.method));
        }
        // a log–log chart has no place for 0 ms or 0 triangles
        if self.millis <= 0.0 {
            let millis = self.millis;
            return Err(format!("millis `{millis}` is not a positive number"));
        }
        if self.triangles == 0 {
            return Err("no triangles".into());
        }
        Ok(())
    }
}

/// The computed part of both methods' rows on `stage` (no time yet).
pub fn count(scene: &str, stage: &Stage) -> [ScalingRow; 2] {
    let (_, raster) = rasterize(stage);
    let cast = raycast(stage);
    let pixels = u64::from(stage.world.width) * u64::from(stage.world.height);
    let hits = cast.id.iter().filter(|id| id.is_some()).count() as u64;
    let row = |method: &str, tests, covered, shaded| ScalingRow {
        scene: scene.to_string(),
        triangles: stage.triangles.len() as u64,
        method: method.to_string(),
        tests,
        covered,
        shaded,
        millis: 0.0,
    };
    [
        row(RASTERIZE, raster.tested, raster.covered, raster.shaded),
        row(
            RAYCAST,
            pixels * stage.world.objects.len() as u64,
            hits,
            hits,
        ),
    ]
}

/// Every stage of [`chart_scenes`], the bunny read from `bunny` first, so
/// that a missing file fails at once, before any timing; the error names
/// the file.
pub fn chart_stages(bunny: &Path) -> Result<Vec<(ChartScene, Stage)>, String> {
    let mut scenes = chart_scenes();
    scenes.sort_by_key(|&s| s != ChartScene::Bunny);
    let mut stages = scenes
        .into_iter()
        .map(|scene| Ok((scene, scene.stage(bunny)?)))
        .collect::<Result<Vec<_>, MeshError>>()
        .map_err(|e| {
            format!(
                "{e} (the chart needs ../shared/meshes beside the workspace)"
            )
        })?;
    // back in chart order
    stages.rotate_left(1);
    Ok(stages)
}

/// Draws every stage of [`chart_stages`] with both methods: the counts
/// once (computed), the time per [`ChartScene::timing`] with `rounds`
/// rounds, the median of single-threaded renders (measured), the two
/// methods taking turns. `step` is called after each round of each stage,
/// for a progress bar. An error names the bunny's file if it is missing.
pub fn measure_scaling(
    rounds: usize, mut step: impl FnMut(),
) -> Result<Vec<ScalingRow>, String> {
    let mut rows = Vec::new();
    for (scene, stage) in &chart_stages(&bunny_path())? {
        let mut counted = count(&scene.name(), stage);
        let mut raster = || {
            let _ = rasterize(stage);
        };
        let mut cast = || {
            let _ = raycast(stage);
        };
        let times = scene
            .timing(rounds)
            .median_ms(&mut [&mut raster, &mut cast], &mut step);
        for (row, millis) in counted.iter_mut().zip(times) {
            row.millis = millis;
        }
        rows.extend(counted);
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_render::csv::{from_csv, from_lines, to_csv};

    fn scaling_row(method: &str, millis: f64) -> ScalingRow {
        ScalingRow {
            scene: "ball-2".into(),
            triangles: 332,
            method: method.into(),
            tests: 40_000,
            covered: 9_000,
            shaded: 7_000,
            millis,
        }
    }

    #[test]
    fn csv_round_trip_and_errors() {
        let rows =
            vec![scaling_row(RASTERIZE, 1.25), scaling_row(RAYCAST, 1234.5)];
        let csv = to_csv(&rows);
        assert!(
            csv.contains("\nball-2,332,rasterize,40000,9000,7000,1.2500\n")
        );
        assert!(
            csv.contains("\nball-2,332,raycast,40000,9000,7000,1234.5000\n")
        );
        assert_eq!(from_csv::<ScalingRow>(&csv).unwrap(), rows);
        for (lines, error) in [
            ("shapes,12,bvh,1,1,1,1\n", "unknown method `bvh`"),
            // a log–log chart has no place for 0 ms or 0 triangles
            (
                "shapes,12,raycast,1,1,1,0\n",
                "millis `0` is not a positive number",
            ),
            ("shapes,0,raycast,1,1,1,1\n", "no triangles"),
        ] {
            let error = format!("line 2: {error}");
            assert_eq!(from_lines::<ScalingRow>(lines), Err(error));
        }
    }

    /// The committed file reads and writes back byte for byte: a new
    /// measurement writes its format.
    #[test]
    fn the_committed_csv_writes_back_unchanged() {
        raystep_figure::writes_back::<ScalingRow>("ch07", "scaling.csv")
            .unwrap();
    }

    #[test]
    fn the_balls_grow_by_four_from_the_scene_alone() {
        let names: Vec<String> =
            chart_scenes().into_iter().map(ChartScene::name).collect();
        assert_eq!(
            names,
            [
                "shapes", "ball-0", "ball-1", "ball-2", "ball-3", "ball-4",
                "ball-5", "ball-6", "bunny"
            ]
        );
        // shapes.toml: floor 2, pyramid 4, prism 2 gables + 2 quads of 2
        let alone = ChartScene::Alone.stage(&bunny_path()).unwrap();
        assert_eq!(alone.triangles.len(), 12);
        assert_eq!(alone.world.objects.len(), 10);
        for n in [0, 2] {
            let stage = ChartScene::Ball(n).stage(&bunny_path()).unwrap();
            assert_eq!(stage.triangles.len(), 12 + 20 * 4usize.pow(n));
            assert_eq!(stage.world.objects.len(), 10 + 20 * 4usize.pow(n));
        }
    }

    #[test]
    fn the_slow_stages_are_timed_with_fewer_renders() {
        assert_eq!(ChartScene::Ball(2).timing(7), TIMING.with_rounds(7));
        let slower = ChartScene::Ball(4).timing(7);
        assert_eq!((slower.rounds, slower.batch), (7, 1));
        let slow = ChartScene::Ball(6).timing(7);
        assert_eq!((slow.rounds, slow.batch), (3, 1));
        assert_eq!(ChartScene::Ball(5).timing(1).rounds, 1);
        // 7 stages of 7 rounds, 2 of 3
        assert_eq!(steps(7), 7 * 7 + 2 * 3);
    }

    /// The counts of the scene alone, checked against what they mean.
    #[test]
    fn the_counts_are_the_work_of_each_loop() {
        let stage = ChartScene::Alone.stage(&bunny_path()).unwrap();
        let [raster, cast] = count("shapes", &stage);
        let pixels = 160 * 90;
        // the ray caster tests every pixel's ray against each of 10 objects
        assert_eq!(cast.tests, pixels * 10);
        // the floor fills the lower part of the image, the sky the rest
        assert!(
            cast.covered > pixels / 3 && cast.covered < pixels,
            "{cast:?}"
        );
        assert_eq!(cast.shaded, cast.covered);
        // the rasterizer tests more pixels than it covers, and covers at
        // least every pixel the ray caster hits; it shades at least once
        // per visible pixel and at most once per covered one
        assert!(raster.tests > raster.covered);
        assert!(raster.covered >= cast.covered);
        assert!(
            raster.shaded >= cast.shaded && raster.shaded <= raster.covered
        );
    }

    /// The counts in the committed CSV are what the code computes now, on
    /// the stages quick enough to draw in a test (a stale CSV fails here;
    /// rerun `raystep measure --chapter ch07`).
    #[test]
    fn the_committed_counts_are_computed_by_the_code() {
        let committed: Vec<ScalingRow> =
            raystep_figure::measured("ch07", "scaling.csv")
                .expect("a good scaling.csv");
        let find = |name: &str, method: &str| {
            committed
                .iter()
                .find(|r| r.scene == name && r.method == method)
                .unwrap_or_else(|| panic!("{name} {method} in the CSV"))
        };
        for scene in [
            ChartScene::Alone,
            ChartScene::Ball(0),
            ChartScene::Ball(1),
            ChartScene::Ball(2),
        ] {
            let name = scene.name();
            let stage = scene.stage(&bunny_path()).unwrap();
            for now in count(&name, &stage) {
                let row = find(&name, &now.method);
                assert_eq!(
                    (row.triangles, row.tests, row.covered, row.shaded),
                    (now.triangles, now.tests, now.covered, now.shaded),
                    "{name} {}",
                    now.method
                );
            }
        }
        // the bunny: every one of its 3674 triangles is drawn (none has
        // zero area), beside the scene's 12
        let bunny = ChartScene::Bunny.stage(&bunny_path()).unwrap();
        assert_eq!(bunny.triangles.len(), 12 + 3674);
        assert_eq!(find("bunny", RAYCAST).triangles, 12 + 3674);
        // every ray-cast row: each of 160 × 90 rays against each object,
        // one fewer object than triangles for each of the two quads
        for row in committed.iter().filter(|r| r.method == RAYCAST) {
            assert_eq!(
                row.tests,
                160 * 90 * (row.triangles - 2),
                "{}",
                row.scene
            );
        }
    }

    #[test]
    fn a_missing_bunny_is_named_before_any_stage_is_built() {
        let error = chart_stages(Path::new("no/such/bunny.obj")).unwrap_err();
        assert!(error.starts_with("no/such/bunny.obj: "), "{error}");
        assert!(error.ends_with(
            "(the chart needs ../shared/meshes beside the workspace)"
        ));
    }
}
