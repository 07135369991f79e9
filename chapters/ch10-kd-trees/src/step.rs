//! The traversal's types: one interior node's plane, and what the ray
//! does with it.

/// An interior node as the traversal step sees it, along the node's axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Split {
    /// Where the plane cuts the axis.
    pub plane: f64,
    /// The child below the plane.
    pub below: u32,
    /// The child above it.
    pub above: u32,
}

/// Which children a ray passes through, over which stretch of `t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// Only this child (the ray does not cross the plane inside the node).
    One(u32),
    /// Both: first `near`, over `[t_min, near_until]`, then `far`, over
    /// `[far_from, t_max]` (pushed on the stack for later).
    Both {
        /// The child the ray is in first.
        near: u32,
        /// The child it goes on to.
        far: u32,
        /// Where the ray leaves `near`: where it crosses the plane.
        near_until: f64,
        /// Where it enters `far`: the same crossing, or `t_min` for a
        /// ray lying in the plane (then it is in both all along).
        far_from: f64,
    },
}
