use crate::Polygon;
use raystep_core::{Camera, DVec3, Hit, Interval, Ray};

/// Which polygon each pixel sees: the lecture's "for each pixel, shoot a
/// ray; for each object, does it hit? keep the closest".
#[derive(Clone, Debug, PartialEq)]
pub struct HitMap {
    /// Pixels per row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Row by row from the top: the index of the closest polygon, or None.
    pub ids: Vec<Option<usize>>,
}

impl HitMap {
    /// The polygon seen at pixel `(column, row)`.
    pub fn get(&self, column: u32, row: u32) -> Option<usize> {
        self.ids[(row * self.width + column) as usize]
    }

    /// One character per pixel: `.` for nothing, `A`, `B`, … for polygon
    /// 0, 1, …; one line per row.
    pub fn to_ascii(&self) -> String {
        let mut s = String::new();
        for row in self.ids.chunks(self.width as usize) {
            for id in row {
                s.push(match id {
                    Some(i) => char::from(b'A' + (*i % 26) as u8),
                    None => '.',
                });
            }
            s.push('\n');
        }
        s
    }
}

// ANCHOR: closest_hit
/// The closest hit of `ray` among `polygons` within `interval`, with the
/// index of the polygon hit.
pub fn closest_hit(
    polygons: &[Polygon], ray: &Ray, interval: Interval,
) -> Option<(usize, Hit)> {
    let mut closest = None;
    let mut interval = interval;
    for (i, polygon) in polygons.iter().enumerate() {
        if let Some(hit) = polygon.intersect(ray, interval) {
            // Anything farther than this hit can no longer be the closest.
            interval = interval.with_max(hit.t);
            closest = Some((i, hit));
        }
    }
    closest
}
// ANCHOR_END: closest_hit

/// Casts one ray through the centre of every pixel of a `width × height`
/// image and records the closest polygon.
pub fn hit_map(
    polygons: &[Polygon], camera: &Camera, width: u32, height: u32,
) -> HitMap {
    let mut ids = Vec::with_capacity((width * height) as usize);
    for row in 0..height {
        for column in 0..width {
            let ray = camera.pixel_ray(column, row, width, height);
            ids.push(
                closest_hit(polygons, &ray, Interval::FORWARD).map(|(i, _)| i),
            );
        }
    }
    HitMap { width, height, ids }
}

/// The lecture's small scene: a triangle, a square behind it, a concave
/// L-shape, and a tilted quadrilateral, seen by [`demo_camera`].
pub fn demo_scene() -> Vec<Polygon> {
    let v = DVec3::new;
    let polygons = [
        // A: a triangle in front
        vec![v(-1.6, -0.9, 0.5), v(0.2, -0.6, 0.5), v(-0.8, 1.0, 0.5)],
        // B: a square behind it, partly hidden
        vec![
            v(-0.6, -1.0, -0.5),
            v(1.0, -1.0, -0.5),
            v(1.0, 0.6, -0.5),
            v(-0.6, 0.6, -0.5),
        ],
        // C: a concave L-shape on the right
        vec![
            v(1.3, -1.1, 0.0),
            v(2.4, -1.1, 0.0),
            v(2.4, -0.6, 0.0),
            v(1.8, -0.6, 0.0),
            v(1.8, 0.9, 0.0),
            v(1.3, 0.9, 0.0),
        ],
        // D: a quadrilateral tilted away from the camera
        vec![
            v(-2.4, 1.1, -1.0),
            v(-0.4, 1.1, 0.0),
            v(-0.4, 1.7, -0.6),
            v(-2.4, 1.7, -1.6),
        ],
    ];
    polygons
        .into_iter()
        .map(|vertices| {
            Polygon::new(vertices).expect("the demo polygons are proper")
        })
        .collect()
}

/// The camera of the demo scene: on +z, looking at the origin, 2:1 aspect.
pub fn demo_camera() -> Camera {
    Camera::look_at(
        DVec3::new(0.0, 0.2, 6.0),
        DVec3::new(0.0, 0.2, 0.0),
        DVec3::Y,
        36.0,
        2.0,
    )
}
