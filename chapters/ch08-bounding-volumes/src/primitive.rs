use raystep_core::Shape;

use crate::BoundingSphere;

/// One of the chapter's primitives: a [`Shape`] with a name for tables
/// and charts, and a bounding sphere of its own besides its box
/// ([`Shape::bounds`]).
pub trait Primitive: Shape {
    /// `sphere`, `box`, `torus`, …: the name tables and charts show.
    fn name(&self) -> &'static str;

    /// A sphere around the whole surface, as tight as the shape allows
    /// (a sphere is its own; a torus's is R + r around its centre).
    fn bounding_sphere(&self) -> BoundingSphere;
}
