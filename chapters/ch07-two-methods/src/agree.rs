//! Do the two methods see the same thing? Their id buffers, compared
//! pixel by pixel, and where they differ, why.
use raystep_core::DVec2;

use crate::{Buffers, Projection, Stage, clip_near};

/// A pixel centre closer than this to a triangle's edge on screen (in
/// pixels) is *on* the edge as far as the two methods can tell: each
/// computes the edge in its own way (2D edge functions on the projected
/// corners; a 3D ray against the polygon), and their rounding differs by
/// far less than this.
pub const ON_EDGE: f64 = 1e-6;

/// The two id buffers compared.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Agreement {
    /// Pixels compared.
    pub pixels: usize,
    /// Pixels where the ids differ, and their centre lies within
    /// [`ON_EDGE`] of an edge of a triangle of one of the two objects:
    /// a silhouette or a shared edge, where the sampling rules differ.
    pub on_edges: Vec<(u32, u32)>,
    /// Pixels where the ids differ anywhere else: should be none.
    pub elsewhere: Vec<(u32, u32)>,
    /// The largest relative difference of the depths where the ids agree
    /// (and are not the background).
    pub worst_depth: f64,
}

impl Agreement {
    /// Every pixel whose ids differ.
    pub fn differing(&self) -> usize {
        self.on_edges.len() + self.elsewhere.len()
    }
}

// ANCHOR: compare
/// Compares the buffers of the two methods, drawn from `stage`.
pub fn compare(stage: &Stage, a: &Buffers, b: &Buffers) -> Agreement {
    let world = &stage.world;
    let projection = Projection {
        camera: world.camera,
        width: world.width,
        height: world.height,
    };
    let mut agreement = Agreement {
        pixels: a.id.len(),
        ..Agreement::default()
    };
    for row in 0..a.height() {
        for column in 0..a.width() {
            let (ia, ib) = (a.id_at(column, row), b.id_at(column, row));
            if ia == ib {
                if ia.is_some() {
                    let (za, zb) =
                        (a.depth_at(column, row), b.depth_at(column, row));
                    let relative = (za - zb).abs() / za.abs().max(zb.abs());
                    agreement.worst_depth = agreement.worst_depth.max(relative);
                }
                continue;
            }
            let p = Projection::pixel_centre(column, row);
            let near_edge = stage
                .triangles
                .iter()
                .filter(|t| Some(t.object) == ia || Some(t.object) == ib)
                .any(|t| edge_distance(&projection, &t.corners, p) <= ON_EDGE);
            if near_edge {
                agreement.on_edges.push((column, row));
            } else {
                agreement.elsewhere.push((column, row));
            }
        }
    }
    agreement
}
// ANCHOR_END: compare

/// The distance on screen from `p` to the nearest edge of the triangle
/// (after clipping at the near plane), in pixels.
pub fn edge_distance(
    projection: &Projection, corners: &[raystep_core::DVec3; 3], p: DVec2,
) -> f64 {
    let view = clip_near(corners.map(|c| projection.view(c)));
    let screen: Vec<DVec2> =
        view.iter().map(|&v| projection.to_pixels(v)).collect();
    let mut best = f64::INFINITY;
    for i in 0..screen.len() {
        let (s, e) = (screen[i], screen[(i + 1) % screen.len()]);
        let d = e - s;
        let t = if d.length_squared() > 0.0 {
            ((p - s).dot(d) / d.length_squared()).clamp(0.0, 1.0)
        } else {
            0.0
        };
        best = best.min((s + d * t - p).length());
    }
    best
}
