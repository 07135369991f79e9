//! A tree's constructors: the objects without a finite box set aside,
//! the rest handed to the builder asked for.
use raystep_core::{Aabb, DVec3};
use raystep_world::Object;

use crate::builder_io::{Input, Output};
use crate::{
    Clip, KdBuilder, KdCosts, KdTree, build_events, build_sorting, median,
};

impl KdTree {
    /// The tree over `boxes` (object `i` has box `boxes[i]`), cut by
    /// `builder` with the cost model `costs` (the median builder uses
    /// only its depth rule). Objects without a finite box go to [`KdTree::unbounded`].
    pub fn build(boxes: &[Aabb], builder: KdBuilder, costs: KdCosts) -> KdTree {
        build(boxes, None, builder, costs)
    }

    /// The tree over triangles; with [`Clip::Triangles`], perfect splits.
    pub fn for_triangles(
        triangles: &[[DVec3; 3]], builder: KdBuilder, costs: KdCosts,
        clip: Clip,
    ) -> KdTree {
        let boxes: Vec<Aabb> = triangles
            .iter()
            .map(|t| Aabb::around(t.iter().copied()))
            .collect();
        let clip = (clip == Clip::Triangles).then_some(triangles);
        build(&boxes, clip, builder, costs)
    }

    /// The tree over the objects' boxes ([`Shape::bounds`]).
    ///
    /// [`Shape::bounds`]: raystep_core::Shape::bounds
    pub fn for_objects(
        objects: &[Object], builder: KdBuilder, costs: KdCosts,
    ) -> KdTree {
        let boxes: Vec<Aabb> =
            objects.iter().map(|o| o.shape.bounds()).collect();
        KdTree::build(&boxes, builder, costs)
    }
}

/// Does the box hold a finite, non-empty stretch of space?
fn is_bounded(b: &Aabb) -> bool {
    !b.is_empty() && b.min.is_finite() && b.max.is_finite()
}

/// Sorts out the unbounded objects, then hands the rest to a builder.
fn build(
    boxes: &[Aabb], triangles: Option<&[[DVec3; 3]]>, builder: KdBuilder,
    costs: KdCosts,
) -> KdTree {
    let (inside, unbounded): (Vec<u32>, Vec<u32>) =
        (0..boxes.len() as u32).partition(|&i| is_bounded(&boxes[i as usize]));
    let bounds = inside
        .iter()
        .map(|&i| boxes[i as usize])
        .reduce(Aabb::union)
        .unwrap_or(Aabb::EMPTY);
    let input = Input {
        boxes,
        triangles,
        costs,
        max_depth: costs.max_depth(inside.len()),
    };
    let mut out = Output::default();
    match builder {
        KdBuilder::Median => {
            median::subtree(&input, &inside, bounds, 0, &mut out)
        }
        KdBuilder::SahSorting => {
            build_sorting::subtree(&input, &inside, bounds, 0, &mut out)
        }
        KdBuilder::SahEvents => {
            build_events::build(&input, &inside, bounds, &mut out)
        }
    }
    KdTree {
        nodes: out.nodes,
        items: out.items,
        bounds,
        unbounded,
        mailboxing: true,
    }
}
