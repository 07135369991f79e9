//! Exercise 1: does a triangle on screen cover a sample point? Edge
//! functions (chapter 1's implicit lines, as chapter 2 evaluates them)
//! and a fill rule for points exactly on an edge.
use ch02::{edge_function, owns_boundary};
use raystep_core::DVec2;

// ANCHOR: covers
/// Does the triangle with screen corners `corners` (in either winding)
/// cover the point `p`?
///
/// Inside means on the inner side of all three edges. A point exactly on
/// an edge (edge function 0) is covered only if the triangle owns that edge
/// (chapter 2's [`owns_boundary`], the top-left rule's cousin): two
/// triangles sharing an edge walk it in opposite directions, so exactly one
/// of them owns it and every sample on it is drawn once. A triangle of zero
/// area covers nothing.
pub fn covers(corners: &[DVec2; 3], p: DVec2) -> bool {
    let [a, b, c] = *corners;
    // Step 1: the signed area (twice it): the edge function of c
    // against the edge a → b. Zero: a degenerate triangle.
    let area = edge_function(a, b, c);
    if area == 0.0 {
        return false;
    }
    // Step 2: walk the edges so that the inside is on their positive
    // side (where edge_function > 0, as c is for a → b).
    let edges = if area > 0.0 {
        [(a, b), (b, c), (c, a)]
    } else {
        [(a, c), (c, b), (b, a)]
    };
    // Step 3: inside every edge, or on an edge the triangle owns.
    edges.iter().all(|&(from, to)| {
        let f = edge_function(from, to, p);
        f > 0.0 || (f == 0.0 && owns_boundary(from, to))
    })
}
// ANCHOR_END: covers

// ANCHOR: barycentric
/// The weights (λa, λb, λc) of `p` in the triangle: each corner's edge
/// function (of the opposite edge) over the triangle's; they sum to 1 and
/// `p = λa·a + λb·b + λc·c`. None for a triangle of zero area.
pub fn barycentric(corners: &[DVec2; 3], p: DVec2) -> Option<[f64; 3]> {
    let [a, b, c] = *corners;
    let area = edge_function(a, b, c);
    if area == 0.0 {
        return None;
    }
    Some([
        edge_function(b, c, p) / area,
        edge_function(c, a, p) / area,
        edge_function(a, b, p) / area,
    ])
}
// ANCHOR_END: barycentric
