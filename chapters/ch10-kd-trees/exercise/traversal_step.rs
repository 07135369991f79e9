//! Exercise 2 (★★★): one step of the front-to-back traversal.
#[allow(unused_imports)]
use ch09::EXIT_SLACK;

use crate::{Split, Step};

// ANCHOR: traversal_step
/// At an interior node the ray is inside over `[t_min, t_max]`: which of
/// the node's two children does it pass through, nearest first?
///
/// `origin` and `inverse` are the ray's origin and 1/direction along the
/// node's axis. The ray crosses the plane at t_plane = (plane − origin) ·
/// inverse; before that it is on the side it comes from (below, if it goes
/// up), after it on the other. So the *near* child is below for a ray
/// going up (inverse > 0), above for one going down, and:
///
/// * t_plane after `t_max` (or never): only the near child;
/// * t_plane before `t_min` (or behind the origin): only the far child;
/// * otherwise both, near over [t_min, t_plane], far over [t_plane, t_max].
///
/// A ray *lying in* the plane (origin on it, direction parallel to it)
/// gives 0 · ∞ = NaN: it is in both children all along, and objects
/// touching the plane from either side can meet it. Comparisons with
/// `t_min` and `t_max` allow the slack [`EXIT_SLACK`] of each: rounding
/// may move t_plane by an ulp or two, and visiting one child too many is
/// safe where one too few is not.
pub fn traversal_step(
    split: Split, origin: f64, inverse: f64, t_min: f64, t_max: f64,
) -> Step {
    // TODO:
    // 1. Near and far: near is `split.below` if the ray goes up
    //    (inverse > 0), else `split.above`; far is the other.
    // 2. t_plane = (plane − origin) · inverse.
    // 3. If t_plane is NaN (a ray lying in the plane): `Step::Both` with
    //    near = below, far = above, near_until = t_max, far_from = t_min.
    // 4. t_plane > t_max + EXIT_SLACK·|t_max| → `Step::One(near)`;
    //    t_plane < t_min − EXIT_SLACK·|t_min| → `Step::One(far)`;
    //    else `Step::Both` with near_until = far_from = t_plane.
    let _ = (split, origin, inverse, t_min, t_max);
    todo!("ch10 exercise 2: traversal_step")
}
// ANCHOR_END: traversal_step
