//! The chapter's scene rasterized: ASCII renders of the ids and the
//! colours, the reference image, and what the rasterizer counted. These
//! use both exercises.
use std::path::Path;

use ch07::{rasterize, raycast, shapes};
use raystep_check::{Table, Tolerance, assert_image_matches};

/// The id buffer of the shapes scene with an icosahedron of 20 triangles
/// for a ball, so that every object has a character of its own: `0` `1`
/// the floor, `2`–`5` the pyramid, `6`–`9` the prism, `a`–`t` the ball.
#[test]
fn ascii_ids() {
    let (raster, _) = rasterize(&shapes(0, 64, 36));
    insta::assert_snapshot!(raster.ids_to_ascii());
}

/// The colour image of the shapes scene (ball of 320 triangles), from
/// both methods: the same local shading on the same pixels.
#[test]
fn ascii_render() {
    let stage = shapes(2, 64, 36);
    let (raster, _) = rasterize(&stage);
    let text = raster.color.to_ascii(64);
    assert_eq!(
        raycast(&stage).color.to_ascii(64),
        text,
        "the ray caster's image"
    );
    insta::assert_snapshot!(text);
}

/// The shapes scene at 160×90, rasterized, against the reference render,
/// within the default tolerance (2 levels of 8-bit sRGB on at most 0.1 %
/// of the pixels). On a mismatch, actual, expected and diff images land
/// in target/image-diffs/; RAYSTEP_BLESS=1 rewrites the reference.
#[test]
fn matches_the_reference_render() {
    let (raster, _) = rasterize(&shapes(2, 160, 90));
    assert_image_matches(&raster.color, &reference(), Tolerance::default());
}

/// The ray caster's image of the same scene matches the same reference:
/// the two methods draw the same picture.
#[test]
fn the_ray_cast_image_matches_it_too() {
    let cast = raycast(&shapes(2, 160, 90));
    assert_image_matches(&cast.color, &reference(), Tolerance::default());
}

fn reference() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/images/shapes-160x90.png")
}

/// What the rasterizer does at three sizes: pixel centres tested (the
/// triangles' bounding boxes), covered, and shaded (closer than what the
/// pixel showed). Each is at most the one before, and every pixel that
/// shows an object was shaded at least once.
#[test]
fn raster_counts() {
    let mut table = Table::new(&[
        "scene",
        "triangles",
        "tested",
        "covered",
        "shaded",
        "pixels shown",
    ]);
    for (subdivisions, width, height) in
        [(0, 64, 36), (2, 64, 36), (2, 160, 90)]
    {
        let (buffers, counts) = rasterize(&shapes(subdivisions, width, height));
        let shown = buffers.id.iter().filter(|id| id.is_some()).count() as u64;
        let scene = format!("shapes({subdivisions}) {width}×{height}");
        assert!(
            counts.tested >= counts.covered,
            "{scene}: pixel centres covered: expected at most the {} tested, \
             got {}",
            counts.tested,
            counts.covered
        );
        assert!(
            counts.covered >= counts.shaded,
            "{scene}: pixels shaded (closer than what they showed): expected \
             at most the {} covered, got {}",
            counts.covered,
            counts.shaded
        );
        assert!(
            counts.shaded >= shown,
            "{scene}: pixels shaded: expected at least the {shown} pixels \
             that show an object, got {}",
            counts.shaded
        );
        table.row(&[
            format!("shapes({subdivisions}) {width}×{height}"),
            counts.triangles.to_string(),
            counts.tested.to_string(),
            counts.covered.to_string(),
            counts.shaded.to_string(),
            shown.to_string(),
        ]);
    }
    insta::assert_snapshot!(table.to_string());
}
