//! What the chapter's test files share.
use ch07::Stage;

/// The stage of a scene file's text at `width × height` (the camera is
/// built for that proportion); `name` names the file in errors.
pub fn stage_from(text: &str, name: &str, width: u32, height: u32) -> Stage {
    let mut scene =
        raystep_scene::parse(text, name).expect("the test scene parses");
    (scene.width, scene.height) = (width, height);
    Stage::from_scene(&scene, name)
        .expect("the test scene's objects are all polygons")
}

/// The scene-file lines of one polygon object of material `material`.
pub fn polygon(vertices: &[[f64; 3]], material: &str) -> String {
    let corners: Vec<String> = vertices
        .iter()
        .map(|[x, y, z]| format!("[{x}, {y}, {z}]"))
        .collect();
    format!(
        "\n[[objects]]\npolygon = {{ vertices = [{}] }}\nmaterial = \"{material}\"\n",
        corners.join(", ")
    )
}
