//! Triangles a rasterizer must survive: of zero area on screen, entirely
//! behind the camera, and crossing the near plane (in front of the eye
//! and behind it at once, where the perspective divide would flip or
//! blow up). These use both exercises.
use ch07::{
    DVec3, Mesh, NEAR, Projection, Stage, clip_near, compare, rasterize,
    raycast,
};

mod common;
use common::{polygon, stage_from};

/// A camera at (0, 1, 0) looking ahead and a little down, 48×27 pixels,
/// and these objects.
fn stage(objects: &[(&[[f64; 3]], &str)]) -> Stage {
    let mut text = String::from(
        "[camera]\nlook_from = [0, 1, 0]\nlook_at = [0, 0.6, -4]\nvfov = 60\n\
         [ambient]\nintensity = 0.2\n\
         [[lights]]\nposition = [2, 5, 2]\nintensity = 0.8\n\
         [materials.floor]\nkd = 0.7\nchecker = { size = 1, kd = 0.2 }\n\
         [materials.wall]\nkd = [0.8, 0.4, 0.3]\n",
    );
    for (vertices, material) in objects {
        text.push_str(&polygon(vertices, material));
    }
    stage_from(&text, "degenerate.toml", 48, 27)
}

/// A floor triangle reaching 30 units behind the eye on both sides and 30
/// ahead: it passes under the eye, two of its corners are behind it.
const FLOOR: &[[f64; 3]] =
    &[[-30.0, 0.0, 30.0], [30.0, 0.0, 30.0], [0.0, 0.0, -30.0]];
/// A wall at x = 1.5 from 5 units behind the eye to 6 ahead: one corner
/// behind, so clipping leaves a quadrilateral (two triangles).
const WALL: &[[f64; 3]] =
    &[[1.5, 0.3, 5.0], [1.5, 0.3, -6.0], [1.5, 2.5, -6.0]];
/// A triangle 3 to 4 units behind the eye.
const BEHIND: &[[f64; 3]] =
    &[[-1.0, 0.5, 3.0], [1.0, 0.5, 4.0], [0.0, 2.0, 3.0]];
/// A triangle in the plane x = 0, which holds the eye: seen edge on, it
/// projects onto one line, a triangle of zero area on screen.
const EDGE_ON: &[[f64; 3]] =
    &[[0.0, 0.0, -2.0], [0.0, 0.5, -5.0], [0.0, 2.0, -3.0]];

/// How many of the stage's triangles are in front of, across and behind
/// the near plane.
fn clip_cases(stage: &Stage) -> (usize, usize, usize) {
    let world = &stage.world;
    let projection = Projection {
        camera: world.camera,
        width: world.width,
        height: world.height,
    };
    let mut cases = (0, 0, 0);
    for t in &stage.triangles {
        let view = t.corners.map(|c| projection.view(c));
        match view.iter().filter(|v| v.z >= NEAR).count() {
            3 => cases.0 += 1,
            0 => cases.2 += 1,
            _ => cases.1 += 1,
        }
    }
    cases
}

/// The floor and the wall cross the near plane; rasterizing them does not
/// panic, draws one triangle for the floor (two corners cut off) and two
/// for the wall (one corner cut off), and shows what the ray caster shows
/// except on edges, with the same depths.
#[test]
fn triangles_crossing_the_near_plane_are_clipped() {
    let stage = stage(&[(FLOOR, "floor"), (WALL, "wall")]);
    assert_eq!(clip_cases(&stage), (0, 2, 0), "(in front, across, behind)");
    let (raster, counts) = rasterize(&stage);
    assert_eq!(counts.triangles, 1 + 2, "triangles drawn after clipping");
    let cast = raycast(&stage);
    let agreement = compare(&stage, &raster, &cast);
    let elsewhere = &agreement.elsewhere;
    assert!(
        elsewhere.is_empty(),
        "the floor and the wall, clipped: pixels whose ids differ between \
         the rasterizer and the ray caster away from every edge: expected 0, \
         got {}, the first at {:?}",
        elsewhere.len(),
        &elsewhere[..elsewhere.len().min(5)]
    );
    assert!(
        agreement.worst_depth <= 1e-9,
        "the floor and the wall, clipped: the largest relative difference of \
         the depths: expected at most 1e-9, got {}",
        agreement.worst_depth
    );
    // both objects are seen, the floor in a third of the image at least
    let seen = |id: usize| raster.id.iter().filter(|&&i| i == Some(id)).count();
    assert!(
        seen(0) > 48 * 27 / 3,
        "floor pixels: expected more than a third of 48×27, got {}",
        seen(0)
    );
    assert!(
        seen(1) > 20,
        "wall pixels: expected more than 20, got {}",
        seen(1)
    );
    insta::assert_snapshot!(format!(
        "{} pixels differ, all on edges\n\nrasterized ids (0 floor, 1 wall):\n{}",
        agreement.differing(),
        raster.ids_to_ascii()
    ));
}

/// What the near plane leaves of a triangle, corner by corner: nothing
/// closer to the eye than NEAR.
#[test]
fn clipping_keeps_only_what_is_in_front() {
    let stage = stage(&[(FLOOR, "floor"), (WALL, "wall")]);
    let world = &stage.world;
    let projection = Projection {
        camera: world.camera,
        width: world.width,
        height: world.height,
    };
    for t in &stage.triangles {
        let kept = clip_near(t.corners.map(|c| projection.view(c)));
        assert!((3..=4).contains(&kept.len()), "{kept:?}");
        assert!(kept.iter().all(|v| v.z >= NEAR), "{kept:?}");
        // and every corner projects to a finite point
        assert!(
            kept.iter().all(|&v| projection.to_pixels(v).is_finite()),
            "{kept:?}"
        );
    }
}

/// A triangle entirely behind the eye is drawn by neither method, and
/// neither is a triangle seen edge on (zero area on screen, and its plane
/// holds every ray that could meet it).
#[test]
fn triangles_behind_the_eye_or_edge_on_draw_nothing() {
    let stage = stage(&[(BEHIND, "wall"), (EDGE_ON, "wall")]);
    assert_eq!(clip_cases(&stage), (1, 0, 1), "(in front, across, behind)");
    let (raster, counts) = rasterize(&stage);
    // the edge-on one is drawn (it is in front) but covers nothing
    assert_eq!(counts.triangles, 1, "triangles drawn (the edge-on one)");
    assert!(
        counts.covered == 0,
        "a triangle seen edge on (zero area on screen): pixels covered: \
         expected 0, got {}",
        counts.covered
    );
    let cast = raycast(&stage);
    let drawn = raster.id.iter().filter(|id| id.is_some()).count();
    assert!(
        drawn == 0,
        "a triangle behind the eye and one seen edge on: pixels rasterized: \
         expected 0, got {drawn}"
    );
    assert!(cast.id.iter().all(Option::is_none), "ray-cast pixels");
    let set = raster.depth.iter().filter(|&&z| z != f64::INFINITY).count();
    assert!(
        set == 0,
        "a triangle behind the eye and one seen edge on: depths set: \
         expected 0 (every depth stays +∞), got {set}"
    );
    // the edge-on triangle's corners all land on the column boundary
    // x = 24 (a whole number: no pixel centre is on it)
    let projection = Projection {
        camera: stage.world.camera,
        width: 48,
        height: 27,
    };
    for c in EDGE_ON {
        let p = projection.to_pixels(projection.view(DVec3::from_array(*c)));
        assert_eq!(p.x, 24.0, "{p}");
    }
    // with the floor and the wall in front, nothing changes where they are
    let all = stage_with_all();
    let (raster, _) = rasterize(&all);
    let others = raster
        .id
        .iter()
        .filter(|&&id| !(id == Some(0) || id == Some(1) || id.is_none()))
        .count();
    assert!(
        others == 0,
        "the floor and the wall with the two triangles that draw nothing: \
         pixels showing one of those two: expected 0, got {others}"
    );
    let elsewhere = compare(&all, &raster, &raycast(&all)).elsewhere;
    assert!(
        elsewhere.is_empty(),
        "the floor, the wall and the two triangles that draw nothing: pixels \
         whose ids differ between the two methods away from every edge: \
         expected 0, got {}, the first at {:?}",
        elsewhere.len(),
        &elsewhere[..elsewhere.len().min(5)]
    );
}

fn stage_with_all() -> Stage {
    stage(&[
        (FLOOR, "floor"),
        (WALL, "wall"),
        (BEHIND, "wall"),
        (EDGE_ON, "wall"),
    ])
}

/// A mesh's triangles of zero area (a repeated corner, three corners on a
/// line) are left out of the stage, and counted.
#[test]
fn zero_area_mesh_triangles_are_skipped() {
    let mesh = Mesh {
        vertices: vec![
            DVec3::new(-1.0, 0.5, -3.0),
            DVec3::new(1.0, 0.5, -3.0),
            DVec3::new(0.0, 1.5, -3.0),
            DVec3::new(3.0, 0.5, -3.0),
        ],
        triangles: vec![[0, 1, 2], [0, 0, 2], [0, 1, 3], [2, 2, 2]],
        normals: Vec::new(),
    };
    let mut stage = stage(&[(FLOOR, "floor")]);
    let skipped = stage.add_mesh(&mesh, 0);
    assert_eq!(skipped, 3);
    assert_eq!(stage.world.objects.len(), 2);
    assert_eq!(stage.triangles.len(), 2);
    assert_eq!(stage.triangles[1].object, 1);
    let (raster, _) = rasterize(&stage);
    assert!(
        raster.id.contains(&Some(1)),
        "the mesh's one good triangle: expected it drawn, got no pixel"
    );
}

/// A floor of 24 triangles around a hub behind the eye: the spokes ahead
/// cross the near plane, each clipped once from either side. The clipped
/// fan still covers the floor's pixels exactly once: no gaps where two
/// clipped triangles meet, no pixel covered twice.
#[test]
fn a_fan_cut_by_the_near_plane_stays_watertight() {
    let hub = [0.37, 0.0, 3.1];
    let half = 30.0;
    // the square's outline, 6 points a side, counter-clockwise from above
    let mut ring = Vec::new();
    for k in 0..6 {
        let s = -half + 2.0 * half * f64::from(k) / 6.0;
        ring.push([s, 0.0, half]);
        ring.push([half, 0.0, -s]);
        ring.push([-s, 0.0, -half]);
        ring.push([-half, 0.0, s]);
    }
    let angle = |p: &[f64; 3]| (p[2] - hub[2]).atan2(p[0] - hub[0]);
    ring.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
    let triangles: Vec<[[f64; 3]; 3]> = (0..ring.len())
        .map(|i| [hub, ring[i], ring[(i + 1) % ring.len()]])
        .collect();
    let objects: Vec<(&[[f64; 3]], &str)> =
        triangles.iter().map(|t| (t.as_slice(), "floor")).collect();
    let stage = stage(&objects);
    let (_, across, _) = clip_cases(&stage);
    assert!(across >= 8, "triangles across the near plane: {across}");
    let (raster, counts) = rasterize(&stage);

    // which pixels' rays meet the floor well inside (gaps) or well outside
    // (overreach) the square; the pixels near its far edge are left out
    let world = &stage.world;
    let (mut inside, mut gaps, mut overreach) = (0, 0, 0);
    for (column, row, ray) in world.camera.pixel_rays(world.width, world.height)
    {
        let t = -ray.origin.y / ray.direction.y;
        let p = ray.origin + ray.direction * t;
        let drawn = raster.id_at(column, row).is_some();
        if t > 0.0 && p.x.abs().max(p.z.abs()) < 0.8 * half {
            inside += 1;
            gaps += usize::from(!drawn);
        } else if t <= 0.0 || p.x.abs().max(p.z.abs()) > 1.25 * half {
            overreach += usize::from(drawn);
        }
    }
    assert!(inside > 48 * 27 / 3, "floor pixels: {inside}");
    assert!(
        (gaps, overreach) == (0, 0),
        "a floor fan cut by the near plane: gaps (floor pixels not drawn) \
         and pixels drawn off the floor: expected 0 and 0, got {gaps} and \
         {overreach}"
    );
    let drawn = raster.id.iter().filter(|id| id.is_some()).count() as u64;
    assert!(
        counts.covered == drawn,
        "a floor fan cut by the near plane: pixels covered, counted with \
         repeats: expected {drawn}, one per pixel drawn (none covered \
         twice), got {}",
        counts.covered
    );
}
