//! Part 2: bounding volume hierarchies. The tree and its cost model
//! first, which every builder and walk shares and which imports none of
//! them; then how it is built (top-down by a split rule, bottom-up by
//! merging clusters), what a ray does in it (the walks), and its quality.

// A hierarchy of boxes: the tree, its cost model, a node's box test.
mod tree;

// Building top-down, on f32 copies of the boxes: the heuristic and the
// split rules (midpoint, median, binned SAH, full-sweep SAH).
// Exercise 5: the SAH cost of one split.
#[cfg_attr(feature = "exercise", path = "../../exercise/sah_split.rs")]
mod sah_split;

mod builder;

mod items;

mod sweep;

mod top_down;

// Building bottom-up: clusters merged (PLOC, agglomerative), the merges
// laid out as the same tree.
mod flatten;

mod ploc;

mod agglomerative;

// Every builder behind one call.
mod build;

// What a ray does: the tracer's two questions.
// Exercise 6: the near-first walk for the closest hit.
#[cfg_attr(feature = "exercise", path = "../../exercise/near_first.rs")]
mod near_first;

mod traverse;

// Tree quality, measured.
mod stats;

pub use builder::{AGGLOMERATIVE_LIMIT, Builder};
pub use near_first::near_first_closest_hit;
pub use sah_split::split_cost;
pub use stats::TreeStats;
pub use tree::{Bvh, BvhNode, INTERSECTION, MAX_LEAF, SahCosts, TRAVERSAL};
// A node's box test, as the walks (exercise 6 too) call it.
pub(crate) use tree::enter;
