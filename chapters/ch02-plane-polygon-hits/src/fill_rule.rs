use raystep_core::DVec2;

// ANCHOR: owns_boundary
/// The tie rule for a point exactly on an edge: does the counter-clockwise
/// polygon with edge `a → b` own the points of that edge?
///
/// Two polygons sharing an edge walk it in opposite directions, so their
/// inward normals `R·(b − a)` are opposite and exactly one of them has
/// `n.x > 0`, or for a horizontal edge `n.y > 0`. That one owns the edge.
/// This is the same as nudging the point right by δ and up by δ²: every
/// point, on an edge or a shared vertex, then lies inside exactly one
/// polygon of a flat mesh — none falls between, none counts twice — as long
/// as the polygons compute the same hit point (one exactly shared plane).
pub fn owns_boundary(a: DVec2, b: DVec2) -> bool {
    let inward = ch01::rotate90(b - a);
    inward.x > 0.0 || (inward.x == 0.0 && inward.y > 0.0)
}
// ANCHOR_END: owns_boundary

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exactly_one_side_owns_an_edge() {
        let pairs = [
            (DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0)),
            (DVec2::new(0.0, 0.0), DVec2::new(0.0, 1.0)),
            (DVec2::new(0.0, 0.0), DVec2::new(1.0, 1.0)),
            (DVec2::new(2.0, -1.0), DVec2::new(-3.0, 0.5)),
        ];
        for (a, b) in pairs {
            assert_ne!(owns_boundary(a, b), owns_boundary(b, a), "{a} {b}");
        }
        // a bottom edge of a counter-clockwise square (interior above) is owned
        assert!(owns_boundary(DVec2::new(0.0, 0.0), DVec2::new(1.0, 0.0)));
        // its left edge (going down, interior to the right) is owned too
        assert!(owns_boundary(DVec2::new(0.0, 1.0), DVec2::new(0.0, 0.0)));
    }
}
