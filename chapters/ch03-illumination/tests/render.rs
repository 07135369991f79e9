//! The whole chapter at work: one ray per pixel, the closest hit, the local
//! model. These use every exercise.
use std::path::Path;

use ch03::{DVec3, RenderOptions, Terms, World, render};
use raystep_check::{Tolerance, assert_image_matches, differing_pixels};
use raystep_render::Progress;

fn spheres(width: u32, height: u32) -> World {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/spheres.toml");
    let mut world = ch03::load(&path).expect("the chapter's scene loads");
    // the same 16:9 framing, fewer pixels
    (world.width, world.height) = (width, height);
    world
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

#[test]
fn ascii_render() {
    let image = render(&spheres(64, 36), Terms::All, &quiet(Some(2))).unwrap();
    insta::assert_snapshot!(image.to_ascii(64));
}

/// The scene at 160×90 against the reference render, within the default
/// tolerance (2 levels of 8-bit sRGB on at most 0.1 % of the pixels). On a
/// mismatch, actual, expected and diff images land in target/image-diffs/.
#[test]
fn matches_the_reference_render() {
    let image = render(&spheres(160, 90), Terms::All, &quiet(Some(2))).unwrap();
    let expected = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/images/spheres-160x90.png");
    assert_image_matches(&image, &expected, Tolerance::default());
}

/// Rows run in parallel, but every pixel is computed on its own: one thread
/// or two give the same bits.
#[test]
fn same_image_for_one_and_two_threads() {
    let world = spheres(48, 27);
    let one = render(&world, Terms::All, &quiet(Some(1))).unwrap();
    let two = render(&world, Terms::All, &quiet(Some(2))).unwrap();
    let differing = differing_pixels(&one, &two);
    assert!(
        differing == 0,
        "pixels that differ between one thread and two: expected 0 (every \
         pixel is computed on its own), got {differing}"
    );
}

/// Adding terms never darkens a pixel: ambient ≤ ambient + diffuse ≤ all,
/// channel by channel; and the ambient-only image is flat per material
/// (ka·Ia does not depend on the geometry).
#[test]
fn terms_add_up() {
    let world = spheres(48, 27);
    let [a, ad, all] = [Terms::Ambient, Terms::AmbientDiffuse, Terms::All]
        .map(|terms| render(&world, terms, &quiet(Some(2))).unwrap());
    for (i, ((a, ad), all)) in a
        .pixels()
        .iter()
        .zip(ad.pixels())
        .zip(all.pixels())
        .enumerate()
    {
        assert!(
            a.cmple(*ad).all() && ad.cmple(*all).all(),
            "pixel ({}, {}): expected ambient ≤ ambient + diffuse ≤ all \
             terms in every channel (no term is negative), got {a}, {ad} and \
             {all}",
            i % 48,
            i / 48
        );
    }
    let mut ambient_levels: Vec<[u64; 3]> = a
        .pixels()
        .iter()
        .map(|c| c.to_array().map(f64::to_bits))
        .collect();
    ambient_levels.sort_unstable();
    ambient_levels.dedup();
    // black sky, floor, three spheres
    assert!(
        ambient_levels.len() == 5,
        "different colours in the ambient-only image: expected 5 (black sky, \
         floor, three spheres: ka·Ia is the same all over a material), got \
         {}",
        ambient_levels.len()
    );
    assert!(
        a.pixels().contains(&DVec3::ZERO),
        "the ambient-only image: expected black sky pixels, got none"
    );
}
