//! Exercise 2: the z test (`DepthBuffer::test_and_set`) and depth
//! interpolated under perspective (`perspective_depth`).
//!
//! The tests of `perspective_depth` find a pixel's screen weights with
//! their own arithmetic, not with exercise 1's `barycentric`, so they
//! judge this exercise alone. The z-buffer of a whole rasterized scene,
//! which needs exercise 1 too, is tested in `agreement.rs`.
use ch07::{Camera, DVec2, DVec3, DepthBuffer, Projection, perspective_depth};
use raystep_check::{Table, num};

const INF: f64 = f64::INFINITY;

#[test]
fn a_new_buffer_is_infinitely_far_everywhere() {
    let buffer = DepthBuffer::new(5, 3);
    assert!(
        buffer.depths() == [INF; 15],
        "a new 5 × 3 buffer: expected +∞ at all 15 pixels, got {:?}",
        buffer.depths()
    );
    let corner = buffer.get(4, 2);
    assert!(
        corner == INF,
        "a new 5 × 3 buffer at (4, 2): expected +∞, got {corner}"
    );
}

/// One pixel, surfaces arriving one after another: the closer one wins,
/// a farther or equally far one is rejected (the first drawn stays), NaN
/// is never closer, not even than +∞.
#[test]
fn the_closer_surface_wins() {
    let mut buffer = DepthBuffer::new(4, 4);
    #[rustfmt::skip]
    let steps = [
        // (depth drawn, kept?, depth the pixel then holds)
        (f64::NAN, false, INF),  // NaN against nothing drawn yet
        (5.0, true, 5.0),        // anything finite beats +∞
        (7.0, false, 5.0),       // farther
        (5.0, false, 5.0),       // as far: the first stays
        (2.5, true, 2.5),        // closer
        (f64::NAN, false, 2.5),  // NaN against a surface
        (2.5 + 1e-15, false, 2.5),
        (2.5 - 1e-15, true, 2.5 - 1e-15),
        (INF, false, 2.5 - 1e-15),
    ];
    for (i, (z, kept, holds)) in steps.into_iter().enumerate() {
        let before = buffer.get(1, 2);
        let got = buffer.test_and_set(1, 2, z);
        let why = if kept {
            "closer: keep it"
        } else if z == before {
            "as far: the first drawn stays"
        } else if z.is_nan() {
            "NaN is never closer"
        } else {
            "farther"
        };
        assert!(
            got == kept,
            "step {i}, drawing depth {z} over {before}: expected \
             test_and_set to return {kept} ({why}), got {got}"
        );
        let now = buffer.get(1, 2);
        assert!(
            now == holds,
            "step {i}, drawing depth {z} over {before}: expected the pixel \
             to hold {holds} afterwards, got {now}"
        );
    }
}

/// Writing pixels leaves every other pixel at +∞, and each pixel is
/// found where `depths()` says (row by row from the top): a buffer wider
/// than high catches swapped columns and rows.
#[test]
fn only_the_tested_pixel_changes() {
    let (width, height) = (5, 3);
    let mut buffer = DepthBuffer::new(width, height);
    let drawn = [(4, 0, 1.0), (0, 2, 2.0), (2, 1, 3.0), (3, 2, 4.0)];
    for (column, row, z) in drawn {
        assert!(
            buffer.test_and_set(column, row, z),
            "drawing depth {z} at pixel ({column}, {row}), where nothing is \
             drawn yet: expected true (anything finite is closer than +∞), \
             got false"
        );
    }
    for row in 0..height {
        for column in 0..width {
            let expected = drawn
                .iter()
                .find(|&&(c, r, _)| (c, r) == (column, row))
                .map_or(INF, |&(_, _, z)| z);
            let got = buffer.get(column, row);
            assert!(
                got == expected,
                "a 5×3 buffer after drawing {drawn:?} (column, row, depth): \
                 pixel ({column}, {row}): expected depth {expected}, got {got}"
            );
            let i = (row * width + column) as usize;
            let stored = buffer.depths()[i];
            assert!(
                stored == expected,
                "a 5×3 buffer after drawing {drawn:?}: depths()[{i}], pixel \
                 ({column}, {row}) row by row: expected {expected}, got \
                 {stored}"
            );
        }
    }
    // a rejected surface changes nothing anywhere
    let before = buffer.clone();
    let got = buffer.test_and_set(4, 0, 1.5);
    assert!(
        !got,
        "drawing depth 1.5 at pixel (4, 0), which holds 1: expected false \
         (farther), got true"
    );
    assert!(
        buffer == before,
        "drawing depth 1.5 at pixel (4, 0), which holds 1: expected the \
         buffer unchanged, got {:?} (was {:?})",
        buffer.depths(),
        before.depths()
    );
}

/// Worked by hand. Between depths 1 and 3, halfway across the screen is
/// not at depth 2 but at 1 / (½·1 + ½·⅓) = 1.5: the harmonic mean.
#[test]
fn perspective_depth_by_hand() {
    let z = [1.0, 3.0, 6.0];
    let cases = [
        ([1.0, 0.0, 0.0], 1.0),
        ([0.0, 1.0, 0.0], 3.0),
        ([0.0, 0.0, 1.0], 6.0),
        ([0.5, 0.5, 0.0], 1.5),
        ([0.0, 0.5, 0.5], 4.0),
        ([1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0], 2.0),
    ];
    for (lambda, expected) in cases {
        let got = perspective_depth(lambda, z);
        assert!(
            (got - expected).abs() <= 1e-12,
            "weights {lambda:?}, depths {z:?}: expected {expected}, got {got}"
        );
    }
    // a triangle facing the camera is at one depth everywhere
    let flat = perspective_depth([0.2, 0.3, 0.5], [4.0, 4.0, 4.0]);
    assert!(
        (flat - 4.0).abs() <= 1e-12,
        "weights [0.2, 0.3, 0.5], depths [4, 4, 4]: expected 4 (all corners \
         at one depth), got {flat}"
    );
}

/// The screen weights of `q` in the triangle `s`, by Cramer's rule on
/// q − s₀ = λ₁(s₁ − s₀) + λ₂(s₂ − s₀).
fn weights(s: [DVec2; 3], q: DVec2) -> [f64; 3] {
    let (e1, e2, d) = (s[1] - s[0], s[2] - s[0], q - s[0]);
    let det = e1.perp_dot(e2);
    let (l1, l2) = (d.perp_dot(e2) / det, e1.perp_dot(d) / det);
    [1.0 - l1 - l2, l1, l2]
}

/// A floor triangle receding from 1 to 20 units in front of a camera
/// looking down at it, at 48×27 pixels.
struct Receding {
    projection: Projection,
    corners: [DVec3; 3],
}

impl Receding {
    fn new() -> Receding {
        let (width, height) = (48, 27);
        let camera = Camera::look_at(
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(0.0, 0.5, -4.0),
            DVec3::Y,
            50.0,
            f64::from(width) / f64::from(height),
        );
        Receding {
            projection: Projection {
                camera,
                width,
                height,
            },
            corners: [
                DVec3::new(-1.5, 0.0, -1.5),
                DVec3::new(1.5, 0.0, -1.5),
                DVec3::new(0.0, 0.0, -20.0),
            ],
        }
    }

    /// Every pixel centre inside the triangle on screen.
    fn samples(&self) -> Vec<Sample> {
        let view = self.corners.map(|c| self.projection.view(c));
        let screen = view.map(|v| self.projection.to_pixels(v));
        let z = view.map(|v| v.z);
        let camera = &self.projection.camera;
        let (width, height) = (self.projection.width, self.projection.height);
        let mut samples = Vec::new();
        for row in 0..height {
            for column in 0..width {
                let lambda =
                    weights(screen, Projection::pixel_centre(column, row));
                if lambda.iter().any(|&l| l < 0.0) {
                    continue;
                }
                let ray = camera.pixel_ray(column, row, width, height);
                let t = -ray.origin.y / ray.direction.y;
                let exact = t * ray.direction.dot(camera.forward);
                samples.push(Sample {
                    column,
                    row,
                    lambda,
                    z,
                    exact,
                });
            }
        }
        samples
    }
}

/// One pixel of the receding triangle.
struct Sample {
    column: u32,
    row: u32,
    /// Its screen weights.
    lambda: [f64; 3],
    /// The corners' view depths.
    z: [f64; 3],
    /// The view depth of the point where the pixel's ray meets the floor
    /// y = 0, found in 3D.
    exact: f64,
}

impl Sample {
    /// What interpolating z linearly on screen gives: wrong.
    fn linear(&self) -> f64 {
        self.lambda[0] * self.z[0]
            + self.lambda[1] * self.z[1]
            + self.lambda[2] * self.z[2]
    }
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs())
}

/// At every pixel of the receding triangle, `perspective_depth` gives the
/// depth of the very point the pixel's ray meets (to 1e-9, relative);
/// interpolating z linearly on screen would be far off (by more than a
/// third of the depth somewhere).
#[test]
fn perspective_depth_is_the_depth_of_the_point_seen() {
    let scene = Receding::new();
    let samples = scene.samples();
    assert!(
        samples.len() > 100,
        "pixels in the receding triangle: expected more than 100, got {}",
        samples.len()
    );
    let (mut worst, mut worst_linear) = (0.0f64, 0.0f64);
    for s in &samples {
        let (column, row, lambda, z, exact) =
            (s.column, s.row, s.lambda, s.z, s.exact);
        let got = perspective_depth(lambda, z);
        assert!(
            relative(got, exact) <= 1e-9,
            "pixel ({column}, {row}): weights {lambda:?}, depths {z:?}: the point seen is at \
             depth {exact}, perspective_depth gives {got}"
        );
        worst = worst.max(relative(got, exact));
        worst_linear = worst_linear.max(relative(s.linear(), exact));
    }
    assert!(worst <= 1e-9, "the largest relative error: {worst}");
    assert!(
        worst_linear > 1.0 / 3.0,
        "linear interpolation is off by only {worst_linear}: the test triangle does not recede enough"
    );
}

/// Down the middle column of the receding triangle, from the far corner
/// to the near edge: the depth of the point seen, `perspective_depth`,
/// and what linear interpolation of z would give.
#[test]
fn receding_depth_table() {
    let scene = Receding::new();
    let column = scene.projection.width / 2;
    let mut table =
        Table::new(&["row", "depth seen", "perspective_depth", "linear z"]);
    for s in &scene.samples() {
        if s.column != column || s.row % 2 != 0 {
            continue;
        }
        table.row(&[
            s.row.to_string(),
            num(s.exact),
            num(perspective_depth(s.lambda, s.z)),
            num(s.linear()),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}
