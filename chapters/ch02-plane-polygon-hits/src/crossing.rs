use crate::edge_function;
use raystep_core::DVec2;

// ANCHOR: inside_crossing
/// The crossing-number test: is `p` inside the simple polygon `vertices`
/// (convex or not, either orientation)?
///
/// Walk a ray from `p` toward +x and count the edges it crosses: odd means
/// inside. An edge counts when one end is above `p` and the other is not
/// (half-open in y), and the crossing is strictly right of `p`. In exact
/// arithmetic that is the same as nudging `p` right by δ and up by δ², the
/// rule of [`owns_boundary`](crate::owns_boundary). Each straddling edge is
/// decided by one exactly antisymmetric number, the edge function, so two
/// polygons that both use this test never leave a gap or an overlap along
/// an edge they share. (The edge test also looks at edges that do not
/// straddle `p`; near a vertex where two edges are almost in line their f is
/// rounding noise, so the two tests can differ there.)
pub fn inside_crossing(vertices: &[DVec2], p: DVec2) -> bool {
    let mut inside = false;
    for (i, &a) in vertices.iter().enumerate() {
        let b = vertices[(i + 1) % vertices.len()];
        // Step 1: does the edge straddle the horizontal line through p?
        // (Half-open: an endpoint exactly at p's height counts as below.)
        if (a.y > p.y) != (b.y > p.y) {
            // Step 2: walk the edge upward, from its lower end to its upper.
            let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
            // Step 3: the crossing is right of p when p is strictly left of
            // the upward edge. The edge test's own edge function decides, so
            // both tests see every edge identically: exactly 0 for p on the
            // edge (at either endpoint too), exactly opposite for the two
            // polygons sharing it.
            if edge_function(lo, hi, p) > 0.0 {
                inside = !inside;
            }
        }
    }
    inside
}
// ANCHOR_END: inside_crossing
