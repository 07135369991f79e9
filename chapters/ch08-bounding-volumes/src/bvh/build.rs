//! A [`Bvh`] built by the [`Builder`] asked for.
use raystep_core::Aabb;
use raystep_world::Object;

use super::agglomerative::agglomerative;
use super::builder::Builder;
use super::ploc::ploc;
use super::top_down::top_down;
use super::tree::Bvh;

impl Bvh {
    /// The hierarchy over `boxes` (object `i` has box `boxes[i]`), split by
    /// `builder`. An object without a finite box (a plane) is kept out of
    /// the tree, in [`Bvh::unbounded`]: it would make every box around it
    /// infinite.
    pub fn build(boxes: &[Aabb], builder: Builder) -> Bvh {
        match builder {
            Builder::Agglomerative => agglomerative(boxes),
            Builder::Ploc { radius } => ploc(boxes, radius),
            rule => top_down(boxes, rule, 1),
        }
    }

    /// [`Bvh::build`] with a top-down `builder`, but a node of at most
    /// `leaf` objects kept as a leaf without being split: for leaves
    /// tested several objects at once (the appendix's blocks of four
    /// triangles), whose cost the SAH's one-test-per-object does not
    /// know. The bottom-up builders build as [`Bvh::build`] does.
    pub fn build_with_leaves_of(
        boxes: &[Aabb], builder: Builder, leaf: usize,
    ) -> Bvh {
        match builder {
            Builder::Agglomerative | Builder::Ploc { .. } => {
                Bvh::build(boxes, builder)
            }
            rule => top_down(boxes, rule, leaf.max(1)),
        }
    }

    /// The hierarchy over the objects' boxes ([`Shape::bounds`]).
    ///
    /// [`Shape::bounds`]: raystep_core::Shape::bounds
    pub fn for_objects(objects: &[Object], builder: Builder) -> Bvh {
        let boxes: Vec<Aabb> =
            objects.iter().map(|o| o.shape.bounds()).collect();
        Bvh::build(&boxes, builder)
    }
}
