//! Scene files: a complete scene, the defaults, named indices of
//! refraction, and one test per kind of bad input with its exact message.

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::Arc;

use raystep_core::DVec3;
use raystep_scene::{
    Ball, CameraSpec, Checker, Instance, Light, MAX_SIZE, Material, Mesh,
    Object, Placement, REFRACTIVE_INDICES, Scene, SceneError, Shape,
    TorusSolver, TriangleTest, index_of_refraction, load, parse,
};

const EXAMPLE: &str = include_str!("../src/example.toml");

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// What the example and the minimal scene share: the eye at (0, 1, 5)
/// looking at the origin, every other value of the image, the camera,
/// the ambient and the background at its default (the example writes
/// the defaults out); no lights, materials or objects yet.
fn framed() -> Scene {
    Scene {
        width: 320,
        height: 180,
        camera: CameraSpec {
            look_from: v(0.0, 1.0, 5.0),
            look_at: DVec3::ZERO,
            up: DVec3::Y,
            vfov: 40.0,
        },
        ambient: DVec3::splat(0.1),
        background: DVec3::ZERO,
        lights: vec![],
        materials: vec![],
        objects: vec![],
        meshes: BTreeMap::new(),
        instances: vec![],
    }
}

/// `meshes/tetra.obj`, as the example's mesh object and instances read it.
fn tetra() -> Mesh {
    let corners = [
        v(1.0, 1.0, 1.0),
        v(1.0, -1.0, -1.0),
        v(-1.0, 1.0, -1.0),
        v(-1.0, -1.0, 1.0),
    ];
    Mesh {
        vertices: corners.to_vec(),
        triangles: vec![[0, 1, 2], [1, 3, 2], [0, 2, 3], [0, 3, 1]],
        // each `vn` is its corner, normalised
        normals: corners.iter().map(|c| c.normalize()).collect(),
    }
}

#[test]
fn the_complete_example_scene_reads_into_the_expected_values() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/example.toml");
    let scene = load(&path).unwrap();
    assert_eq!(scene, parse(EXAMPLE, "example.toml").unwrap());
    let red = Material {
        name: "red".into(),
        ka: v(0.1, 0.0, 0.0),
        kd: v(0.7, 0.1, 0.1),
        ks: DVec3::splat(0.3),
        p: 32.0,
        kr: DVec3::ZERO,
        kt: DVec3::ZERO,
        ior: 1.0,
        checker: None,
    };
    let glass = Material {
        name: "glass".into(),
        ka: DVec3::ZERO,
        kd: DVec3::ZERO,
        ks: DVec3::splat(0.5),
        p: 200.0,
        kr: DVec3::splat(0.1),
        kt: DVec3::splat(0.9),
        ior: 1.5,
        checker: None,
    };
    let default = Material {
        ka: DVec3::splat(0.5),
        kd: DVec3::splat(0.5),
        checker: Some(Checker {
            size: 1.0,
            ka: DVec3::splat(0.1),
            kd: DVec3::splat(0.1),
        }),
        ..Material::default()
    };
    let expected = Scene {
        lights: vec![
            Light {
                position: v(5.0, 5.0, 5.0),
                intensity: DVec3::ONE,
            },
            Light {
                position: v(-5.0, 3.0, 2.0),
                intensity: v(0.2, 0.2, 0.3),
            },
        ],
        // "default" first, then the others in file order
        materials: vec![default, red, glass],
        objects: vec![
            Object {
                shape: Shape::Sphere {
                    center: DVec3::ZERO,
                    radius: 1.0,
                },
                material: 1,
                line: 50,
            },
            Object {
                shape: Shape::Sphere {
                    center: v(1.5, 0.0, 1.0),
                    radius: 0.5,
                },
                material: 2,
                line: 54,
            },
            Object {
                shape: Shape::Plane {
                    point: v(0.0, -1.0, 0.0),
                    normal: DVec3::Y, // normalised from [0, 2, 0]
                },
                material: 0,
                line: 58,
            },
            Object {
                shape: Shape::Polygon {
                    vertices: vec![
                        v(-2.0, -1.0, -2.0),
                        v(2.0, -1.0, -2.0),
                        v(0.0, 2.0, -2.0),
                    ],
                },
                material: 1,
                line: 61,
            },
            Object {
                shape: Shape::Box {
                    min: v(-1.0, -1.0, -1.0),
                    max: v(1.0, 0.0, 1.0),
                },
                material: 0,
                line: 67,
            },
            Object {
                shape: Shape::Cylinder {
                    base: v(0.0, 0.0, 0.0),
                    top: v(0.0, 2.0, 0.0),
                    radius: 0.5,
                },
                material: 0,
                line: 70,
            },
            Object {
                shape: Shape::Ellipsoid {
                    center: DVec3::ZERO,
                    radii: v(2.0, 1.0, 0.5),
                },
                material: 0,
                line: 73,
            },
            Object {
                shape: Shape::Triangle {
                    vertices: [DVec3::ZERO, DVec3::X, DVec3::Y],
                    test: TriangleTest::Watertight,
                },
                material: 0,
                line: 76,
            },
            Object {
                shape: Shape::Torus {
                    center: DVec3::ZERO,
                    axis: DVec3::Y,
                    major: 1.0,
                    minor: 0.25,
                    solver: TorusSolver::Bracketed,
                },
                material: 0,
                line: 79,
            },
            Object {
                shape: Shape::Saddle {
                    center: DVec3::ZERO,
                    size: 1.0,
                },
                material: 0,
                line: 82,
            },
            Object {
                shape: Shape::Blobby {
                    balls: vec![
                        Ball {
                            center: DVec3::ZERO,
                            radius: 1.0,
                            strength: 1.0,
                        },
                        Ball {
                            center: v(0.8, 0.0, 0.0),
                            radius: 1.0,
                            strength: 1.0,
                        },
                    ],
                    threshold: 0.5,
                },
                material: 0,
                line: 85,
            },
            Object {
                shape: Shape::Mesh {
                    // smooth = false: the same mesh without its normals
                    mesh: Arc::new(Mesh {
                        normals: vec![],
                        ..tetra()
                    }),
                    placement: Placement {
                        scale: DVec3::splat(0.5),
                        rotate: v(0.0, 90.0, 0.0),
                        translate: v(0.0, 0.5, 0.0),
                    },
                },
                material: 1,
                line: 95,
            },
        ],
        meshes: BTreeMap::from([("tetra".to_owned(), Arc::new(tetra()))]),
        instances: vec![
            Instance {
                mesh: "tetra".into(),
                placement: Placement {
                    scale: v(1.0, 2.0, 1.0),
                    rotate: v(0.0, 45.0, 0.0),
                    translate: v(2.0, 0.0, 0.0),
                },
                material: 2,
                line: 108,
            },
            Instance {
                mesh: "tetra".into(),
                placement: Placement {
                    translate: v(-2.0, 0.0, 0.0),
                    ..Placement::IDENTITY
                },
                material: 0,
                line: 115,
            },
        ],
        ..framed()
    };
    assert_eq!(scene, expected);
    for instance in &scene.instances {
        let header = EXAMPLE.lines().nth(instance.line - 1).unwrap();
        assert!(
            header.starts_with("[[instances]]"),
            "line {}",
            instance.line
        );
    }
    for object in &scene.objects {
        let header = EXAMPLE.lines().nth(object.line - 1).unwrap();
        assert!(header.starts_with("[[objects]]"), "line {}", object.line);
    }
    let camera = scene.camera();
    assert!((camera.aspect - 16.0 / 9.0).abs() < 1e-12);
    assert!((camera.forward - v(0.0, -1.0, -5.0).normalize()).length() < 1e-12);
    assert_eq!(scene.material(&scene.objects[1]).name, "glass");
}

#[test]
fn a_scene_with_only_a_camera_gets_every_default() {
    let scene = parse(
        "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n",
        "minimal.toml",
    )
    .unwrap();
    assert_eq!(
        scene,
        Scene {
            materials: vec![Material {
                name: "default".into(),
                ka: DVec3::splat(0.7),
                kd: DVec3::splat(0.7),
                ks: DVec3::ZERO,
                p: 32.0,
                kr: DVec3::ZERO,
                kt: DVec3::ZERO,
                ior: 1.0,
                checker: None,
            }],
            ..framed()
        }
    );
}

#[test]
fn material_fields_default_one_by_one_and_ka_follows_kd() {
    let scene = parse(
        "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n\
         [materials.blue]\nkd = [0, 0, 0.8]\n\
         [[objects]]\n[objects.sphere]\ncenter = [0, 0, 0]\nradius = 2\n",
        "m.toml",
    )
    .unwrap();
    assert_eq!(
        scene.materials[1],
        Material {
            name: "blue".into(),
            ka: v(0.0, 0.0, 0.8),
            kd: v(0.0, 0.0, 0.8),
            ..Material::default()
        }
    );
    // an object without `material` uses "default", and a sub-table works
    // as well as an inline table
    assert_eq!(scene.objects[0].material, 0);
    assert_eq!(scene.objects[0].line, 6);
    assert_eq!(
        scene.objects[0].shape,
        Shape::Sphere {
            center: DVec3::ZERO,
            radius: 2.0
        }
    );
}

#[test]
fn ior_takes_the_lectures_names_or_a_number() {
    assert_eq!(REFRACTIVE_INDICES.len(), 7);
    for (name, ior) in REFRACTIVE_INDICES {
        assert_eq!(index_of_refraction(name), Some(ior));
        let source = format!(
            "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n[materials.m]\nior = {name:?}\n"
        );
        assert_eq!(parse(&source, "ior.toml").unwrap().materials[1].ior, ior);
    }
    assert_eq!(index_of_refraction("water"), Some(1.33));
    assert_eq!(index_of_refraction("diamond"), Some(2.417));
    assert_eq!(index_of_refraction("DIAMOND"), Some(2.417));
    assert_eq!(index_of_refraction("unobtainium"), None);
    let numeric = "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n[materials.m]\nior = 1.7\n";
    assert_eq!(parse(numeric, "ior.toml").unwrap().materials[1].ior, 1.7);
}

#[test]
fn an_unreadable_file_names_the_path_and_the_os_error() {
    let error = load(Path::new("/nonexistent/scene.toml")).unwrap_err();
    assert!(matches!(error, SceneError::Read { .. }));
    assert_eq!(
        error.to_string(),
        "/nonexistent/scene.toml: cannot read the scene file: No such file or directory (os error 2)"
    );
}

/// A valid camera, three lines, for the cases below that are about
/// something else.
macro_rules! camera {
    () => {
        "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n"
    };
}

/// One `#[test]` per bad input, asserting its exact message, plus
/// `ERROR_TABLE`, all of them, for the snapshot that documents them.
macro_rules! bad_inputs {
    ($($name:ident: $source:expr => $message:expr;)*) => {
        $(
            #[test]
            fn $name() {
                let error = parse($source, "bad.toml").unwrap_err();
                assert_eq!(error.to_string(), $message);
            }
        )*
        const ERROR_TABLE: &[(&str, &str)] = &[$((stringify!($name), $source)),*];
    };
}

bad_inputs! {
    toml_syntax_error:
        "[camera]\nlook_from = [0, 1, 5\nlook_at = [0, 0, 0]\n"
        => "bad.toml:3:1: TOML syntax: missing comma between array elements, expected `,`";
    toml_duplicate_key:
        concat!(camera!(), "vfov = 40\nvfov = 50\n")
        => "bad.toml:5:1: TOML syntax: duplicate key `vfov`";
    unknown_top_level_table:
        concat!(camera!(), "[light]\nposition = [1, 1, 1]\n")
        => "bad.toml:4:2: light: unknown field, expected one of `image`, `camera`, `ambient`, `background`, `lights`, `materials`, `objects`, `meshes`, `instances`";
    unknown_camera_field:
        concat!(camera!(), "fov = 40\n")
        => "bad.toml:4:1: camera.fov: unknown field, expected one of `look_from`, `look_at`, `up`, `vfov`";
    unknown_field_in_an_inline_table:
        concat!(camera!(), "[[objects]]\nsphere = { center = [0, 0, 0], radius = 1, color = 1 }\n")
        => "bad.toml:5:44: objects[0].sphere.color: unknown field, expected `center` or `radius`";
    top_level_key_below_a_table_header:
        concat!(camera!(), "lights = [{ position = [1, 1, 1] }]\n")
        => "bad.toml:4:1: camera.lights: unknown field, expected one of `look_from`, `look_at`, `up`, `vfov` (`lights` belongs at the top of the file, above the first [table] header)";
    unknown_material_field:
        concat!(camera!(), "[materials.red]\nkd = 1\nshininess = 3\n")
        => "bad.toml:6:1: materials.red.shininess: unknown field, expected one of `ka`, `kd`, `ks`, `p`, `kr`, `kt`, `ior`, `checker`";
    missing_camera:
        "[image]\nwidth = 10\n"
        => "bad.toml:1:1: camera: required, but missing";
    missing_look_from:
        "# no eye\n[camera]\nlook_at = [0, 0, 0]\n"
        => "bad.toml:2:1: camera.look_from: required, but missing";
    missing_sphere_radius:
        concat!(camera!(), "[[objects]]\nsphere = { center = [0, 0, 0] }\n")
        => "bad.toml:5:10: objects[0].sphere.radius: required, but missing";
    missing_light_position:
        concat!(camera!(), "[[lights]]\nintensity = 1\n[[lights]]\nintensity = 2\n")
        => "bad.toml:4:1: lights[0].position: required, but missing";
    wrong_type_string_for_a_number:
        concat!(camera!(), "vfov = \"wide\"\n")
        => "bad.toml:4:8: camera.vfov: expected a number, got string \"wide\"";
    wrong_type_number_for_a_table:
        "camera = 3\n"
        => "bad.toml:1:10: camera: expected a table, got integer `3`";
    wrong_type_table_for_an_array:
        concat!(camera!(), "[objects]\nsphere = { center = [0, 0, 0], radius = 1 }\n")
        => "bad.toml:4:1: objects: expected an array, got a table";
    wrong_type_number_for_a_point:
        concat!(camera!(), "up = 1\n")
        => "bad.toml:4:6: camera.up: expected an array of 3 numbers [x, y, z], got integer `1`";
    wrong_type_in_a_point:
        "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, \"a\", 0]\n"
        => "bad.toml:3:15: camera.look_at[1]: expected a number, got string \"a\"";
    wrong_length_of_a_point:
        "[camera]\nlook_from = [0, 1]\nlook_at = [0, 0, 0]\n"
        => "bad.toml:2:13: camera.look_from: expected an array of 3 numbers [x, y, z], got 2 elements";
    wrong_length_of_a_colour:
        concat!(camera!(), "[ambient]\nintensity = [0.1, 0.1, 0.1, 1]\n")
        => "bad.toml:5:13: ambient.intensity: expected an array of 3 numbers [r, g, b], got 4 elements";
    wrong_type_float_for_an_integer:
        concat!(camera!(), "[image]\nwidth = 320.5\n")
        => "bad.toml:5:9: image.width: expected an integer, got floating point `320.5`";
    wrong_type_number_for_a_material_name:
        concat!(camera!(), "[[objects]]\nsphere = { center = [0, 0, 0], radius = 1 }\nmaterial = 1\n")
        => "bad.toml:6:12: objects[0].material: expected a string, got integer `1`";
    negative_radius:
        concat!(camera!(), "[[objects]]\nplane = { point = [0, 0, 0], normal = [0, 1, 0] }\n",
                "[[objects]]\nsphere = { center = [0, 0, 0], radius = 1 }\n",
                "[[objects]]\nsphere = { center = [0, 0, 0], radius = -1 }\n")
        => "bad.toml:9:41: objects[2].sphere.radius: must be positive, got -1";
    zero_radius:
        concat!(camera!(), "[[objects]]\n[objects.sphere]\ncenter = [0, 0, 0]\nradius = 0.0\n")
        => "bad.toml:7:10: objects[0].sphere.radius: must be positive, got 0";
    zero_plane_normal:
        concat!(camera!(), "[[objects]]\nplane = { point = [0, 0, 0], normal = [0, 0, 0] }\n")
        => "bad.toml:5:39: objects[0].plane.normal: must have a non-zero length, got [0, 0, 0]";
    too_few_polygon_vertices:
        concat!(camera!(), "[[objects]]\npolygon = { vertices = [[0, 0, 0], [1, 0, 0]] }\n")
        => "bad.toml:5:24: objects[0].polygon.vertices: a polygon needs at least 3 vertices, got 2";
    infinite_coordinate:
        "[camera]\nlook_from = [0, inf, 5]\nlook_at = [0, 0, 0]\n"
        => "bad.toml:2:17: camera.look_from[1]: must be a finite number, got inf";
    nan_radius:
        concat!(camera!(), "[[objects]]\nsphere = { center = [0, 0, 0], radius = nan }\n")
        => "bad.toml:5:41: objects[0].sphere.radius: must be a finite number, got nan";
    infinite_intensity:
        concat!(camera!(), "[[lights]]\nposition = [1, 1, 1]\nintensity = -inf\n")
        => "bad.toml:6:13: lights[0].intensity: must be a finite number, got -inf";
    negative_colour_component:
        concat!(camera!(), "[materials.red]\nkd = [0.5, -0.1, 0]\n")
        => "bad.toml:5:12: materials.red.kd[1]: must not be negative, got -0.1";
    negative_grey_intensity:
        concat!(camera!(), "[[lights]]\nposition = [1, 1, 1]\nintensity = -1\n")
        => "bad.toml:6:13: lights[0].intensity: must not be negative, got -1";
    zero_phong_exponent:
        concat!(camera!(), "[materials.shiny]\np = 0\n")
        => "bad.toml:5:5: materials.shiny.p: must be positive, got 0";
    zero_checker_size:
        concat!(camera!(), "[materials.floor]\nchecker = { size = 0 }\n")
        => "bad.toml:5:20: materials.floor.checker.size: must be positive, got 0";
    negative_background:
        concat!(camera!(), "[background]\nintensity = [0, -0.5, 0]\n")
        => "bad.toml:5:17: background.intensity[1]: must not be negative, got -0.5";
    negative_ior:
        concat!(camera!(), "[materials.odd]\nior = -1.5\n")
        => "bad.toml:5:7: materials.odd.ior: must be positive, got -1.5";
    unknown_ior_name:
        concat!(camera!(), "[materials.lens]\nior = \"glas\"\n")
        => "bad.toml:5:7: materials.lens.ior: unknown name \"glas\", expected a positive number or one of vacuum, air, water, glass, ice, quartz, diamond";
    unknown_material_in_an_object:
        concat!(camera!(), "[materials.red]\nkd = [1, 0, 0]\n[materials.green]\nkd = [0, 1, 0]\n",
                "[[objects]]\nsphere = { center = [0, 0, 0], radius = 1 }\nmaterial = \"blue\"\n")
        => "bad.toml:10:12: objects[0].material: unknown material \"blue\", defined: default, red, green";
    image_width_zero:
        concat!(camera!(), "[image]\nwidth = 0\n")
        => "bad.toml:5:9: image.width: must be between 1 and 4096 (MAX_SIZE), got 0";
    image_height_too_large:
        concat!(camera!(), "[image]\nheight = 5000\n")
        => "bad.toml:5:10: image.height: must be between 1 and 4096 (MAX_SIZE), got 5000";
    image_width_negative:
        concat!("image = { width = -3 }\n", camera!())
        => "bad.toml:1:19: image.width: must be between 1 and 4096 (MAX_SIZE), got -3";
    vfov_zero:
        concat!(camera!(), "vfov = 0\n")
        => "bad.toml:4:8: camera.vfov: must be between 0 and 180 degrees (both excluded), got 0";
    vfov_180:
        concat!(camera!(), "vfov = 180.0\n")
        => "bad.toml:4:8: camera.vfov: must be between 0 and 180 degrees (both excluded), got 180";
    up_parallel_to_the_view:
        "[camera]\nlook_from = [0, 5, 0]\nlook_at = [0, 0, 0]\nup = [0, 2, 0]\n"
        => "bad.toml:4:6: camera.up: must not be parallel to the view direction (look_at - look_from = [0, -5, 0]), got [0, 2, 0]";
    default_up_parallel_to_the_view:
        "[camera]\nlook_from = [0, 5, 0]\nlook_at = [0, 0, 0]\n"
        => "bad.toml:1:1: camera.up: the default [0, 1, 0] is parallel to the view direction (look_at - look_from = [0, -5, 0]); give another `up`";
    up_zero:
        concat!(camera!(), "up = [0, 0, 0]\n")
        => "bad.toml:4:6: camera.up: must not be zero-length, got [0, 0, 0]";
    look_from_equals_look_at:
        "[camera]\nlook_from = [1, 2, 3]\nlook_at = [1, 2, 3]\n"
        => "bad.toml:3:11: camera.look_at: must differ from look_from, both are [1, 2, 3]";
    look_at_too_far_for_a_direction:
        "[camera]\nlook_from = [-1e308, 0, 0]\nlook_at = [1e308, 0, 0]\n"
        => "bad.toml:3:11: camera.look_at: too close to or too far from look_from to give a view direction (look_at - look_from = [inf, 0, 0])";
    object_without_a_shape:
        concat!(camera!(), "[[objects]]\nsphere = { center = [0, 0, 0], radius = 1 }\n[[objects]]\nmaterial = \"default\"\n")
        => "bad.toml:6:1: objects[1]: needs a shape: one of `sphere`, `plane`, `polygon`, `box`, `cylinder`, `ellipsoid`, `triangle`, `torus`, `saddle`, `blobby` or `mesh`";
    degenerate_box:
        concat!(camera!(), "[[objects]]\nbox = { min = [0, 0, 0], max = [1, 0, 1] }\n")
        => "bad.toml:5:32: objects[0].box.max: must be greater than min on every axis (a box with no volume is degenerate), got min = [0, 0, 0], max = [1, 0, 1]";
    cylinder_without_an_axis:
        concat!(camera!(), "[[objects]]\ncylinder = { base = [1, 2, 3], top = [1, 2, 3], radius = 1 }\n")
        => "bad.toml:5:38: objects[0].cylinder.top: must differ from base (the axis needs a direction), got base = [1, 2, 3], top = [1, 2, 3]";
    negative_cylinder_radius:
        concat!(camera!(), "[[objects]]\ncylinder = { base = [0, 0, 0], top = [0, 1, 0], radius = -0.5 }\n")
        => "bad.toml:5:58: objects[0].cylinder.radius: must be positive, got -0.5";
    zero_ellipsoid_radius:
        concat!(camera!(), "[[objects]]\nellipsoid = { center = [0, 0, 0], radii = [1, 0, 1] }\n")
        => "bad.toml:5:43: objects[0].ellipsoid.radii: must all be positive, got [1, 0, 1]";
    four_triangle_vertices:
        concat!(camera!(), "[[objects]]\ntriangle = { vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]] }\n")
        => "bad.toml:5:25: objects[0].triangle.vertices: a triangle has exactly 3 vertices, got 4";
    unknown_triangle_test:
        concat!(camera!(), "[[objects]]\ntriangle = { vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], test = \"fast\" }\n")
        => "bad.toml:5:67: objects[0].triangle.test: unknown name \"fast\", expected one of \"watertight\", \"moller-trumbore\", \"plane-inside\"";
    spindle_torus:
        concat!(camera!(), "[[objects]]\ntorus = { center = [0, 0, 0], major = 1, minor = 1.5 }\n")
        => "bad.toml:5:50: objects[0].torus.minor: must be less than major (1): only ring tori, got 1.5; a spindle or horn torus (minor ≥ major) intersects itself and is refused";
    zero_torus_radius:
        concat!(camera!(), "[[objects]]\ntorus = { center = [0, 0, 0], major = 0, minor = 0.5 }\n")
        => "bad.toml:5:39: objects[0].torus.major: must be positive, got 0";
    zero_torus_axis:
        concat!(camera!(), "[[objects]]\ntorus = { center = [0, 0, 0], axis = [0, 0, 0], major = 1, minor = 0.5 }\n")
        => "bad.toml:5:38: objects[0].torus.axis: must have a non-zero length, got [0, 0, 0]";
    nan_in_a_torus:
        concat!(camera!(), "[[objects]]\ntorus = { center = [0, nan, 0], major = 1, minor = 0.5 }\n")
        => "bad.toml:5:24: objects[0].torus.center[1]: must be a finite number, got nan";
    negative_saddle_size:
        concat!(camera!(), "[[objects]]\nsaddle = { center = [0, 0, 0], size = -2 }\n")
        => "bad.toml:5:39: objects[0].saddle.size: must be positive, got -2";
    blobby_without_balls:
        concat!(camera!(), "[[objects]]\nblobby = { threshold = 0.5, balls = [] }\n")
        => "bad.toml:5:37: objects[0].blobby.balls: a blobby object needs at least 1 ball, got 0";
    blobby_ball_with_zero_radius:
        concat!(camera!(), "[[objects]]\nblobby = { threshold = 0.5, balls = [{ center = [0, 0, 0], radius = 0 }] }\n")
        => "bad.toml:5:69: objects[0].blobby.balls[0].radius: must be positive, got 0";
    blobby_threshold_too_high:
        concat!(camera!(), "[[objects]]\nblobby = { threshold = 2, balls = [{ center = [0, 0, 0], radius = 1 }] }\n")
        => "bad.toml:5:24: objects[0].blobby.threshold: must be less than the balls' total strength (1), or the surface is empty; got 2";
    object_with_two_shapes:
        concat!(camera!(), "[[objects]]\nsphere = { center = [0, 0, 0], radius = 1 }\nplane = { point = [0, 0, 0], normal = [0, 1, 0] }\n")
        => "bad.toml:6:9: objects[0].plane: an object has exactly one shape, this one already has `sphere`";
    // meshes: every field is checked before any OBJ file is read, so
    // these files need not exist
    zero_instance_scale:
        concat!(camera!(), "[meshes.bunny]\nobj = \"bunny.obj\"\n",
                "[[instances]]\nmesh = \"bunny\"\n[[instances]]\nmesh = \"bunny\"\nscale = 2\n",
                "[[instances]]\nmesh = \"bunny\"\n[[instances]]\nmesh = \"bunny\"\nscale = [1, 0, 1]\n")
        => "bad.toml:15:9: instances[3].scale: must not be 0, got [1, 0, 1]";
    zero_object_mesh_scale:
        concat!(camera!(), "[[objects]]\nmesh = { obj = \"tetra.obj\", scale = 0 }\n")
        => "bad.toml:5:37: objects[0].mesh.scale: must not be 0, got 0";
    nan_in_a_placement:
        concat!(camera!(), "[meshes.bunny]\nobj = \"bunny.obj\"\n[[instances]]\nmesh = \"bunny\"\ntranslate = [1, nan, 0]\n")
        => "bad.toml:8:17: instances[0].translate[1]: must be a finite number, got nan";
    nan_mesh_scale:
        concat!(camera!(), "[[objects]]\nmesh = { obj = \"tetra.obj\", scale = nan }\n")
        => "bad.toml:5:37: objects[0].mesh.scale: must be a finite number, got nan";
    infinite_rotation:
        concat!(camera!(), "[[objects]]\nmesh = { obj = \"tetra.obj\", rotate = [0, inf, 0] }\n")
        => "bad.toml:5:42: objects[0].mesh.rotate[1]: must be a finite number, got inf";
    unknown_mesh_name:
        concat!(camera!(), "[meshes.bunny]\nobj = \"bunny.obj\"\n[[instances]]\nmesh = \"bunyn\"\n")
        => "bad.toml:7:8: instances[0].mesh: no mesh \"bunyn\" in [meshes]; there are bunny";
    instance_without_meshes:
        concat!(camera!(), "[[instances]]\nmesh = \"bunny\"\n")
        => "bad.toml:5:8: instances[0].mesh: no mesh \"bunny\" in [meshes]; there are none";
    unknown_material_in_an_instance:
        concat!(camera!(), "[meshes.bunny]\nobj = \"bunny.obj\"\n[[instances]]\nmesh = \"bunny\"\nmaterial = \"clay\"\n")
        => "bad.toml:8:12: instances[0].material: unknown material \"clay\", defined: default";
    unknown_field_in_a_mesh:
        concat!(camera!(), "[[objects]]\nmesh = { obj = \"tetra.obj\", rotation = [0, 90, 0] }\n")
        => "bad.toml:5:29: objects[0].mesh.rotation: unknown field, expected one of `obj`, `smooth`, `scale`, `rotate`, `translate`";
    unknown_field_in_a_named_mesh:
        concat!(camera!(), "[meshes.bunny]\nobj = \"bunny.obj\"\nscale = 2\n")
        => "bad.toml:6:1: meshes.bunny.scale: unknown field, expected `obj` or `smooth`";
    unknown_field_in_an_instance:
        concat!(camera!(), "[meshes.bunny]\nobj = \"bunny.obj\"\n[[instances]]\nmesh = \"bunny\"\nsmooth = false\n")
        => "bad.toml:8:1: instances[0].smooth: unknown field, expected one of `mesh`, `scale`, `rotate`, `translate`, `material`";
    missing_obj:
        concat!(camera!(), "[meshes.bunny]\nsmooth = false\n")
        => "bad.toml:4:1: meshes.bunny.obj: required, but missing";
    empty_obj_path:
        concat!(camera!(), "[[objects]]\nmesh = { obj = \"\" }\n")
        => "bad.toml:5:16: objects[0].mesh.obj: must name an OBJ file, got \"\"";
    object_mesh_by_name:
        concat!(camera!(), "[[objects]]\nmesh = \"bunny\"\n")
        => "bad.toml:5:8: objects[0].mesh: expected a table, got string \"bunny\"";
}

#[test]
fn every_bad_input_and_its_message() {
    let mut table = String::from("case | message\n---- | -------\n");
    for (name, source) in ERROR_TABLE {
        let error = parse(source, "bad.toml").unwrap_err();
        table.push_str(&format!("{name} | {error}\n"));
    }
    let error = load(Path::new("/nonexistent/scene.toml")).unwrap_err();
    table.push_str(&format!("unreadable_file | {error}\n"));
    insta::assert_snapshot!(table);
}

#[test]
fn a_tiny_plane_normal_still_has_a_direction() {
    let source = format!(
        "{}[[objects]]\nplane = {{ point = [0, 0, 0], normal = [0, 0, -1e-200] }}\n",
        camera!()
    );
    let scene = parse(&source, "ok.toml").unwrap();
    assert_eq!(
        scene.objects[0].shape,
        Shape::Plane {
            point: DVec3::ZERO,
            normal: DVec3::NEG_Z
        }
    );
}

#[test]
fn limits_are_inclusive() {
    let source =
        format!("{}[image]\nwidth = 1\nheight = {MAX_SIZE}\n", camera!());
    let scene = parse(&source, "ok.toml").unwrap();
    assert_eq!((scene.width, scene.height), (1, MAX_SIZE));
}

#[test]
fn a_checker_alternates_cube_by_cube_and_the_default_tiles_are_the_materials_own()
 {
    let scene = parse(
        "[camera]\nlook_from = [0, 1, 5]\nlook_at = [0, 0, 0]\n\
         [materials.floor]\nkd = 0.8\nchecker = { size = 2, kd = [0.2, 0, 0] }\n",
        "c.toml",
    )
    .unwrap();
    let floor = &scene.materials[1];
    let own = (DVec3::splat(0.8), DVec3::splat(0.8));
    let odd = (v(0.2, 0.0, 0.0), v(0.2, 0.0, 0.0)); // ka follows the checker's kd
    // cube (0,0,0) spans -1..1 on each axis and is even; one step of 2
    // along any axis flips the colour, two steps do not
    assert_eq!(floor.ka_kd_at(v(0.5, 0.5, 0.5)), own);
    assert_eq!(floor.ka_kd_at(v(2.5, 0.5, 0.5)), odd);
    assert_eq!(floor.ka_kd_at(v(-1.5, 0.5, 0.5)), odd);
    assert_eq!(floor.ka_kd_at(v(2.5, -1.5, 0.5)), own);
    assert_eq!(floor.ka_kd_at(v(-3.5, -1.0, 5.0)), odd); // cubes -2, 0, 3 (5/2 + 1/2 = 3)
    // a floor on a lattice plane (y = -2, a multiple of the size) is
    // mid-layer: y a hair above or below gives the same colour
    let below = floor.ka_kd_at(v(0.5, -2.0 - 1e-12, 0.5));
    assert_eq!(floor.ka_kd_at(v(0.5, -2.0 + 1e-12, 0.5)), below);
    // a material without a checker is the same everywhere
    assert_eq!(
        scene.materials[0].ka_kd_at(v(2.5, 0.5, 0.5)).1,
        DVec3::splat(0.7)
    );
}
