//! Exercise 1 (★★): does a triangle on screen cover a sample point? Edge
//! functions (chapter 1's implicit lines, as chapter 2 evaluates them)
//! and a fill rule for points exactly on an edge.
#![allow(unused_imports)]
use ch02::{edge_function, owns_boundary};
use raystep_core::DVec2;

// ANCHOR: covers
/// Does the triangle with screen corners `corners` (in either winding)
/// cover the point `p`?
///
/// Inside means on the inner side of all three edges. A point exactly on
/// an edge (edge function 0) is covered only if the triangle owns that edge
/// (chapter 2's [`owns_boundary`]): two triangles sharing an edge walk it
/// in opposite directions, so exactly one of them owns it and every sample
/// on it is drawn once. A triangle of zero area covers nothing.
pub fn covers(corners: &[DVec2; 3], p: DVec2) -> bool {
    // TODO:
    // 1. The signed area: edge_function(a, b, c). Zero: return false.
    // 2. Walk the edges so that the inside is on their positive side (where
    //    edge_function > 0, as c is for a → b): a→b, b→c, c→a
    //    for a positive area, a→c, c→b, b→a for a negative one.
    // 3. Covered if every edge function f = edge_function(from, to, p) is
    //    > 0, or == 0 on an edge with owns_boundary(from, to).
    let _ = (corners, p);
    todo!("ch07 exercise 1: covers")
}
// ANCHOR_END: covers

// ANCHOR: barycentric
/// The weights (λa, λb, λc) of `p` in the triangle: each corner's edge
/// function (of the opposite edge) over the triangle's; they sum to 1 and
/// `p = λa·a + λb·b + λc·c`. None for a triangle of zero area.
pub fn barycentric(corners: &[DVec2; 3], p: DVec2) -> Option<[f64; 3]> {
    // TODO: area = edge_function(a, b, c) (None if 0), then
    // [edge_function(b, c, p), edge_function(c, a, p), edge_function(a, b, p)]
    // each divided by the area.
    let _ = (corners, p);
    todo!("ch07 exercise 1: barycentric")
}
// ANCHOR_END: barycentric
