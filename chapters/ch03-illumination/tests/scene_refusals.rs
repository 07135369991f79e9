//! What chapters 3–7 refuse in a scene file: what only chapter 8 traces
//! (its primitives, meshes and instances of meshes), each in one line
//! naming the file, the line and the entry.

/// The format's small mesh, by absolute path.
fn tetra() -> String {
    format!(
        "{}/../../crates/scene/meshes/tetra.obj",
        env!("CARGO_MANIFEST_DIR")
    )
}

#[test]
fn instances_of_a_mesh_are_refused_naming_the_entry() {
    let text = format!(
        "[camera]\nlook_from = [0, 0, 5]\nlook_at = [0, 0, 0]\n\n\
         [meshes.tetra]\nobj = \"{}\"\n\n[[instances]]\nmesh = \"tetra\"\n",
        tetra()
    );
    let error = ch03::parse(&text, "scene.toml").unwrap_err().to_string();
    assert_eq!(
        error,
        "scene.toml:8: instances[0]: instances of a mesh are chapter 8's, \
         which chapters 3–7 do not know: render this scene with `--chapter \
         ch08`"
    );
}

#[test]
fn a_mesh_object_is_refused_naming_the_entry() {
    let text = format!(
        "[camera]\nlook_from = [0, 0, 5]\nlook_at = [0, 0, 0]\n\n\
         [[objects]]\nmesh = {{ obj = \"{}\" }}\n",
        tetra()
    );
    let error = ch03::parse(&text, "scene.toml").unwrap_err().to_string();
    assert!(
        error.starts_with(
            "scene.toml:5: objects[0].mesh: a mesh is one of \
                           chapter 8's primitives"
        ),
        "{error}"
    );
}
