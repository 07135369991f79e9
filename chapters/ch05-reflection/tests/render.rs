//! The whole chapter at work on `scenes/mirrors.toml`: every pixel traced
//! recursively under the default rule (contribution ≥ 1/1000). These use
//! both exercises.
use std::path::Path;

use ch05::{DEFAULT_STOP, RayCounts, pixel_tree, render};
use raystep_check::{Tolerance, assert_image_matches, differing_pixels};

mod common;
use common::{chapter_scene, quiet};

#[test]
fn ascii_render() {
    let world = chapter_scene("mirrors", 64, 36);
    let (image, _) = render(&world, &DEFAULT_STOP, &quiet(Some(2))).unwrap();
    insta::assert_snapshot!(image.to_ascii(64));
}

/// The scene at 160×90 against the reference render, within the default
/// tolerance (2 levels of 8-bit sRGB on at most 0.1 % of the pixels). On a
/// mismatch, actual, expected and diff images land in target/image-diffs/;
/// RAYSTEP_BLESS=1 rewrites the reference.
#[test]
fn matches_the_reference_render() {
    let world = chapter_scene("mirrors", 160, 90);
    let (image, _) = render(&world, &DEFAULT_STOP, &quiet(Some(2))).unwrap();
    let expected = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/images/mirrors-160x90.png");
    assert_image_matches(&image, &expected, Tolerance::default());
}

/// Rows run in parallel, but every pixel is traced on its own and its rays
/// counted in its own log: one thread or two give the same bits and the
/// same counts.
#[test]
fn same_image_and_counts_for_one_and_two_threads() {
    let world = chapter_scene("mirrors", 48, 27);
    let (one, one_counts) =
        render(&world, &DEFAULT_STOP, &quiet(Some(1))).unwrap();
    let (two, two_counts) =
        render(&world, &DEFAULT_STOP, &quiet(Some(2))).unwrap();
    let differing = differing_pixels(&one, &two);
    assert!(
        differing == 0,
        "pixels that differ between one thread and two: expected 0 (every \
         pixel is traced on its own), got {differing}"
    );
    assert!(
        one_counts == two_counts,
        "ray counts: expected the same on one thread and on two, got \
         {one_counts:?} and {two_counts:?}"
    );
    assert!(
        one_counts.secondary > 0,
        "reflected rays in the mirrors scene: expected some, got none"
    );
}

/// The render's counts are the sum of its pixels' ray trees: every ray a
/// tree holds is counted once, by kind or by the rule that cut it.
#[test]
fn counts_are_the_pixels_trees_added_up() {
    let world = chapter_scene("mirrors", 48, 27);
    let (_, counts) = render(&world, &DEFAULT_STOP, &quiet(Some(2))).unwrap();
    let mut summed = RayCounts::default();
    for row in 0..world.height {
        for column in 0..world.width {
            for ray in pixel_tree(&world, column, row, &DEFAULT_STOP) {
                let n = match ray.cut {
                    Some(ch05::Cut::Depth) => &mut summed.cut_by_depth,
                    Some(ch05::Cut::Contribution) => {
                        &mut summed.cut_by_contribution
                    }
                    None if ray.shadow => &mut summed.shadow,
                    None if ray.is_primary() => &mut summed.primary,
                    None => &mut summed.secondary,
                };
                *n += 1;
            }
        }
    }
    assert!(
        summed == counts,
        "the render's ray counts: expected the sum of its pixels' ray trees, \
         {summed:?}, got {counts:?}"
    );
}
