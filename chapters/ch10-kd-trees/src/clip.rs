//! "Perfect splits": the part of a triangle inside a node, by clipping
//! it against the node's six planes (Sutherland–Hodgman).
use raystep_core::{Aabb, DVec3};

/// The box of the part of `triangle` inside `node`, padded by a rounding
/// margin (1e-9 of the node's size and 4 ulp of the coordinates: a
/// clipped corner may round inward, and the box must never be smaller
/// than the part it bounds); `None` when clipping leaves nothing.
pub fn clipped_bounds(triangle: &[DVec3; 3], node: &Aabb) -> Option<Aabb> {
    let mut polygon: Vec<DVec3> = triangle.to_vec();
    for axis in 0..3 {
        // Step 1: keep the side x[axis] ≥ min, then the side x[axis] ≤ max.
        polygon = clip(&polygon, axis, node.min[axis], 1.0);
        polygon = clip(&polygon, axis, node.max[axis], -1.0);
        if polygon.is_empty() {
            return None;
        }
    }
    // Step 2: its box, widened by the margin.
    let b = Aabb::around(polygon.iter().copied());
    let size = (node.max - node.min).max_element();
    let pad = DVec3::splat(1e-9 * size)
        + b.min.abs().max(b.max.abs()) * (4.0 * f64::EPSILON);
    Some(Aabb {
        min: b.min - pad,
        max: b.max + pad,
    })
}

/// The part of `polygon` where `sign · (x[axis] − plane) ≥ 0`.
fn clip(polygon: &[DVec3], axis: usize, plane: f64, sign: f64) -> Vec<DVec3> {
    let inside = |p: &DVec3| sign * (p[axis] - plane) >= 0.0;
    let mut out = Vec::with_capacity(polygon.len() + 1);
    for (k, a) in polygon.iter().enumerate() {
        let b = &polygon[(k + 1) % polygon.len()];
        if inside(a) {
            out.push(*a);
        }
        if inside(a) != inside(b) {
            // Where the edge crosses the plane (exactly on it along the axis).
            let s = (plane - a[axis]) / (b[axis] - a[axis]);
            let mut p = *a + (*b - *a) * s;
            p[axis] = plane;
            out.push(p);
        }
    }
    out
}
