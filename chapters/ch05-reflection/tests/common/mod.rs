//! What the chapter's test files share.
use ch05::{RenderOptions, World};
use raystep_render::Progress;
use std::path::Path;

/// A world from scene-file text, rendered at `width × height` (the camera
/// is built for that proportion).
pub fn world_from(text: &str, name: &str, width: u32, height: u32) -> World {
    let mut scene =
        raystep_scene::parse(text, name).expect("the test scene parses");
    (scene.width, scene.height) = (width, height);
    ch03::world(&scene, name).expect("the test scene builds")
}

/// The chapter's scene `scenes/<name>.toml` at `width × height`.
pub fn chapter_scene(name: &str, width: u32, height: u32) -> World {
    let file = format!("scenes/{name}.toml");
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(&file);
    let text =
        std::fs::read_to_string(&path).expect("the chapter's scene is there");
    world_from(&text, &file, width, height)
}

/// Render options for tests: no progress bar, and a pool of `threads`
/// threads of its own (`Some`), started from the test's thread: a panic in
/// a row (a `todo!()` in student mode) is then reported with the test
/// that made it, not with whichever test started rayon's global pool.
pub fn quiet(threads: Option<usize>) -> RenderOptions {
    RenderOptions {
        threads,
        progress: Progress::Never,
    }
}
