use raystep_core::{DVec2, DVec3};

// ANCHOR: project
/// The axis (0 = x, 1 = y, 2 = z) along which `normal` is largest.
///
/// Dropping that coordinate projects a polygon onto the coordinate plane
/// where it looks biggest, so its 2D shape is the least squashed.
pub fn dominant_axis(normal: DVec3) -> usize {
    let n = normal.abs();
    if n.x >= n.y && n.x >= n.z {
        0
    } else if n.y >= n.z {
        1
    } else {
        2
    }
}

/// `p` with coordinate `axis` dropped, the other two kept in cyclic order
/// (x → (y, z), y → (z, x), z → (x, y)), so a polygon counter-clockwise
/// around a normal with a positive `axis` component stays counter-clockwise.
pub fn project(p: DVec3, axis: usize) -> DVec2 {
    match axis {
        0 => DVec2::new(p.y, p.z),
        1 => DVec2::new(p.z, p.x),
        _ => DVec2::new(p.x, p.y),
    }
}
// ANCHOR_END: project

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drops_the_largest_normal_component() {
        assert_eq!(dominant_axis(DVec3::new(0.1, -0.9, 0.3)), 1);
        assert_eq!(dominant_axis(DVec3::new(0.0, 0.0, -1.0)), 2);
        assert_eq!(project(DVec3::new(1.0, 2.0, 3.0), 0), DVec2::new(2.0, 3.0));
        assert_eq!(project(DVec3::new(1.0, 2.0, 3.0), 1), DVec2::new(3.0, 1.0));
    }
}
