//! A bad OBJ file is refused with the file and, where one is to blame,
//! the line: the OBJ reader alone names neither.
use std::fs;
use std::path::PathBuf;

use raystep_scene::Mesh;

/// Writes `text` to a scratch file named `name`; its path.
fn obj(name: &str, text: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("mesh-errors");
    fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

fn message(path: &std::path::Path) -> String {
    Mesh::load_obj(path).unwrap_err().to_string()
}

#[test]
fn a_good_file_reads() {
    let path = obj(
        "square.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",
    );
    let mesh = Mesh::load_obj(&path).unwrap();
    assert_eq!(mesh.triangles.len(), 2, "a quad is two triangles");
}

#[test]
fn each_bad_file_is_named_with_its_line() {
    let missing = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("none.obj");
    let text = message(&missing);
    assert!(text.starts_with(&missing.display().to_string()), "{text}");
    assert!(text.contains("No such file"), "{text}");
    let cases = [
        (
            "number.obj",
            "v 0 0 0\nv 1 0 0\nv 1 1 zero\nf 1 2 3\n",
            "line 3",
        ),
        ("short.obj", "v 0 0 0\nv 1 0\nv 1 1 0\nf 1 2 3\n", "line 2"),
        (
            "index.obj",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n",
            "line 4",
        ),
        ("zero.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 1 2\n", "line 4"),
        ("empty.obj", "v 0 0 0\nv 1 0 0\n", "no faces"),
        (
            "nan.obj",
            "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n",
            "vertex 3",
        ),
    ];
    for (name, text, expected) in cases {
        let message = message(&obj(name, text));
        assert!(message.contains(name), "{name}: {message}");
        assert!(message.contains(expected), "{name}: {message}");
    }
}
