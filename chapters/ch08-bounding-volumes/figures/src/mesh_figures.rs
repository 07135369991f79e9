//! Meshes in scenes: the chapter's committed mesh scenes rendered (the
//! bunny on a floor, a thousand instanced bunnies, one mesh shaded flat
//! and smooth), each by chapter 6's tracer over the chapter's hierarchy
//! as `raystep render --accel bvh` draws it (the image is the same with
//! any accelerator).
use std::path::Path;

use raystep_figure::palette;
use raystep_figure::{Anchor, DVec2, Figure, Page};
use raystep_render::{Image, Progress, RenderOptions};

use crate::instance_measurements::bvh;

/// The render of `scenes/<stem>.toml` at its own size (the meshes from
/// ../shared beside the workspace, or the chapter's tests/meshes).
fn render_scene(stem: &str) -> Image {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../scenes/{stem}.toml"));
    let scene = raystep_scene::load(&path).unwrap_or_else(|e| {
        panic!("{e} (the meshes live in ../shared/meshes)")
    });
    let options = RenderOptions {
        threads: None,
        progress: Progress::Never,
    };
    crate::render(&scene, &format!("{stem}.toml"), &options, bvh)
        .unwrap_or_else(|e| panic!("{stem}.toml renders: {e}"))
}

/// A page holding `image` at its size, with `strip` px above it for
/// labels.
fn image_page(image: &Image, strip: f64) -> Page {
    let (w, h) = (f64::from(image.width()), f64::from(image.height()));
    let mut page = Page::new(w, h + strip);
    page.image(
        DVec2::new(0.0, 0.0),
        DVec2::new(w, h),
        image.width(),
        image.height(),
        &image.to_srgb8(),
    );
    page
}

/// Every figure of meshes in scenes.
pub fn all() -> Vec<Figure> {
    vec![bunny_scene(), bunnies_scene(), smooth_shading()]
}

/// The render of `scenes/<stem>.toml` with `title` in a strip above it.
fn titled_render(stem: &str, title: &str) -> Page {
    let image = render_scene(stem);
    let strip = 30.0;
    let mut page = image_page(&image, strip);
    let (w, h) = (f64::from(image.width()), f64::from(image.height()));
    page.label_sized(
        DVec2::new(w / 2.0, h + 0.5 * strip),
        title,
        Anchor::Center,
        16.0,
        palette::BLACK,
    );
    page
}

/// `scenes/bunny.toml`: the bunny flattened into the world on a floor.
fn bunny_scene() -> Figure {
    let page = titled_render("bunny", "scenes/bunny.toml: one mesh, flattened");
    Figure::new(
        "bunny-scene",
        "scenes/bunny.toml rendered by chapter 6's tracer: the Stanford bunny (3 674 triangles, from ../shared/meshes/bunny.obj, scaled to 1 and turned 20° about y) as one mesh object, flattened into the world one triangle an object, shaded flat (its OBJ has no vertex normals), on a checkered floor under two lights; its shadow is chapter 4's. 480 × 360, through the 16-bin SAH hierarchy (raystep render --accel bvh; every accelerator gives the same bytes).",
        page,
    )
}

/// `scenes/bunnies.toml`: a thousand instances of one bunny.
fn bunnies_scene() -> Figure {
    let page = titled_render(
        crate::STEM_BUNNIES,
        "scenes/bunnies.toml: 1 000 instances of one mesh",
    );
    Figure::new(
        "bunnies-scene",
        "scenes/bunnies.toml rendered by chapter 6's tracer: 1 000 instances of the one bunny mesh, each turned about y by its own angle, on a floor: 3.7 million triangles placed, 3 674 stored, in one structure the instances share, under a top hierarchy over the 1 000 instances and the floor (raystep render --accel bvh). 480 × 270.",
        page,
    )
}

/// `scenes/smooth-shading.toml`: one mesh, flat and smooth.
fn smooth_shading() -> Figure {
    let image = render_scene("smooth-shading");
    let strip = 30.0;
    let mut page = image_page(&image, strip);
    let (w, h) = (f64::from(image.width()), f64::from(image.height()));
    for (x, text) in
        [(0.3, "flat (smooth = false)"), (0.7, "smooth (vn blended)")]
    {
        page.label_sized(
            DVec2::new(x * w, h + 0.5 * strip),
            text,
            Anchor::Center,
            16.0,
            palette::BLACK,
        );
    }
    Figure::new(
        "smooth-shading",
        "One mesh shaded two ways (scenes/smooth-shading.toml): the octasphere, an octahedron split once and pushed onto the unit sphere (32 triangles, a vn normal at each of its 18 vertices). Left, smooth = false: every point of a triangle gets the triangle's normal, so each facet is lit evenly and the edges show. Right, as its file says: each hit's normal is the three vertex normals blended by the hit's barycentric coordinates, so the light varies smoothly across the facets, and the highlight is round. The outline is the same polygon in both: smooth shading bends the normals, not the surface. That shows on the right of the smooth one: where a blended normal still faces the second light but its flat facet does not, the shadow ray leaves the facet into the mesh and is blocked by the mesh itself, and the facet goes dark with a sharp edge (the shadow terminator problem of coarse smooth meshes).",
        page,
    )
}
