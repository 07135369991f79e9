//! The two methods on the same triangles: their id buffers differ only on
//! edges (silhouettes and shared edges), where the two sampling rules
//! meet. These tests use both exercises.
use ch07::{Agreement, Buffers, Stage, compare, rasterize, raycast, shapes};

mod common;
use common::{polygon, stage_from};

/// Both methods on `stage`, compared: asserts that the ids differ only on
/// edges and that the depths agree to 1e-9 (relative) wherever the ids do.
fn assert_agree(name: &str, stage: &Stage) -> Agreement {
    let (raster, _) = rasterize(stage);
    let agreement = compare(stage, &raster, &raycast(stage));
    let elsewhere = &agreement.elsewhere;
    assert!(
        elsewhere.is_empty(),
        "{name}: pixels whose ids differ between the rasterizer and the ray \
         caster away from every edge: expected 0 (the two sampling rules \
         may disagree only on edges), got {}, the first at {:?}",
        elsewhere.len(),
        &elsewhere[..elsewhere.len().min(5)]
    );
    assert!(
        agreement.worst_depth <= 1e-9,
        "{name}: the largest relative difference of the depths where both \
         methods show the same object: expected at most 1e-9, got {}",
        agreement.worst_depth
    );
    agreement
}

/// The chapter's scene with a ball of 320 triangles at `width × height`:
/// edges almost never pass within 1e-6 pixel of a pixel centre here, so
/// the two methods agree on every pixel.
fn assert_shapes_agree_everywhere(width: u32, height: u32) {
    let name = format!("shapes {width}×{height}");
    let agreement = assert_agree(&name, &shapes(2, width, height));
    assert_eq!(
        agreement.pixels,
        (width * height) as usize,
        "pixels compared"
    );
    assert!(
        agreement.differing() == 0,
        "{name}: pixels whose ids differ between the rasterizer and the ray \
         caster: expected 0 (no edge passes this close to a pixel centre \
         here), got {}, the first at {:?}",
        agreement.differing(),
        &agreement.on_edges[..agreement.on_edges.len().min(5)]
    );
}

#[test]
fn shapes_agree_at_64x36() {
    assert_shapes_agree_everywhere(64, 36);
}

#[test]
fn shapes_agree_at_160x90() {
    assert_shapes_agree_everywhere(160, 90);
}

/// Pixels per scene unit in the fan scene: the camera at (0, 0, 4) looks
/// straight down −z with half_height ½ on a 32×32 image, so a point
/// (x, y, 0) lands at pixel coordinates (16 + 8x, 16 − 8y), exactly.
const FAN_SCALE: f64 = 8.0;

/// A fan of 32 triangles (each its own object, windings alternating) in
/// the plane z = 0 facing the camera, around the point that projects onto
/// the centre of pixel (16, 16), out to a square of 12 pixels either side.
/// Every corner lands exactly on a pixel centre, and every spoke (with
/// directions like (−9, −12) pixels) and the outline pass exactly through
/// pixel centres: both methods meet points exactly on edges, the
/// rasterizer with its fill rule on screen, the ray caster with chapter
/// 02's rule in the plane of each polygon, after rounding.
fn fan_stage() -> Stage {
    let mut text = String::from(
        "[camera]\nlook_from = [0, 0, 4]\nlook_at = [0, 0, 0]\nvfov = 53\n\
         [ambient]\nintensity = 0.2\n\
         [[lights]]\nposition = [1, 2, 5]\nintensity = 0.8\n\
         [materials.light]\nkd = 0.8\n\
         [materials.dark]\nkd = 0.4\n",
    );
    // from pixel coordinates to the plane z = 0
    let at = |px: f64, py: f64| {
        [(px - 16.0) / FAN_SCALE, (16.0 - py) / FAN_SCALE, 0.0]
    };
    let hub = at(16.5, 16.5);
    // the outline, every 3 pixels, clockwise on screen from the top left
    let mut ring = Vec::new();
    for k in 0..8 {
        let s = f64::from(3 * k);
        ring.push(at(4.5 + s, 4.5)); // top
        ring.push(at(28.5, 4.5 + s)); // right
        ring.push(at(28.5 - s, 28.5)); // bottom
        ring.push(at(4.5, 28.5 - s)); // left
    }
    // in order around the outline
    ring.sort_by(|a, b| {
        let angle = |p: &[f64; 3]| (p[1] - hub[1]).atan2(p[0] - hub[0]);
        angle(b).total_cmp(&angle(a))
    });
    for i in 0..ring.len() {
        let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
        let (corners, material) = if i % 2 == 0 {
            ([hub, a, b], "light")
        } else {
            ([hub, b, a], "dark")
        };
        text.push_str(&polygon(&corners, material));
    }
    let mut stage = stage_from(&text, "fan.toml", 32, 32);
    stage.world.camera.half_height = 0.5;
    stage
}

/// The fan: the rasterizer covers every pixel of the square exactly once
/// (as many covered pixel tests as pixels shown: no double hits) and
/// leaves no gap; the ray caster may decide pixel centres on the spokes
/// the other way, but only there.
#[test]
fn a_fan_with_edges_through_pixel_centres() {
    let stage = fan_stage();
    assert_eq!(stage.triangles.len(), 32);
    let (raster, counts) = rasterize(&stage);
    // the square [4.5, 28.5)² of pixel centres, under the top-left rule
    let inside = |c: u32, r: u32| (4..28).contains(&c) && (4..28).contains(&r);
    for row in 0..32 {
        for column in 0..32 {
            let (drawn, expected) =
                (raster.id_at(column, row).is_some(), inside(column, row));
            assert!(
                drawn == expected,
                "the fan, pixel ({column}, {row}): expected {} (the fan \
                 covers the pixel centres of [4.5, 28.5)², its top and left \
                 sides its own), got {}",
                if expected { "drawn" } else { "not drawn" },
                if drawn { "drawn" } else { "not drawn" }
            );
        }
    }
    assert!(
        counts.covered == 24 * 24,
        "the fan: pixels covered, counted with repeats: expected 576 (each \
         of the 24×24 pixels once), got {}",
        counts.covered
    );
    let agreement = assert_agree("fan", &stage);
    insta::assert_snapshot!(format!(
        "{} pixels differ, all on edges\n\nrasterized ids, differing pixels as !:\n{}",
        agreement.differing(),
        marked(&raster, &agreement)
    ));
}

/// The id buffer as text with the differing pixels marked `!`.
fn marked(buffers: &Buffers, agreement: &Agreement) -> String {
    let width = buffers.width() as usize;
    let mut rows: Vec<Vec<char>> = buffers
        .ids_to_ascii()
        .lines()
        .map(|l| l.chars().collect())
        .collect();
    for &(column, row) in agreement.on_edges.iter().chain(&agreement.elsewhere)
    {
        rows[row as usize][column as usize] = '!';
    }
    rows.iter()
        .map(|r| {
            assert_eq!(r.len(), width);
            r.iter().collect::<String>() + "\n"
        })
        .collect()
}

/// The whole rasterizer against the ray caster on the shapes scene: where
/// both show the same object, the z-buffer holds the depth of the point
/// the ray hits, to 1e-9 relative.
#[test]
fn rasterized_depths_are_the_ray_casters() {
    let stage = shapes(1, 64, 36);
    let (raster, _) = rasterize(&stage);
    let cast = raycast(&stage);
    let mut compared = 0;
    for row in 0..36 {
        for column in 0..64 {
            let id = raster.id_at(column, row);
            if id.is_none() || id != cast.id_at(column, row) {
                continue;
            }
            let (zr, zc) =
                (raster.depth_at(column, row), cast.depth_at(column, row));
            assert!(
                relative(zr, zc) <= 1e-9,
                "pixel ({column}, {row}), object {id:?}: z-buffer {zr}, ray caster {zc}"
            );
            compared += 1;
        }
    }
    // most of the image shows an object (the sky is the top quarter)
    assert!(
        compared > 64 * 36 / 2,
        "pixels where both methods show the same object: expected more than \
         half of 64×36, got {compared}"
    );
    // and the background stays infinitely far in both
    for (i, id) in raster.id.iter().enumerate() {
        if id.is_none() {
            assert!(
                raster.depth[i] == f64::INFINITY,
                "background pixel ({}, {}): expected the depth +∞ (nothing \
                 drawn there), got {}",
                i % 64,
                i / 64,
                raster.depth[i]
            );
        }
    }
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs())
}
