//! The builders' copies of the objects' boxes: `f32`, side by side with
//! their indices, for choosing splits only (the final boxes are the exact
//! `f64` unions of the objects' boxes).
use raystep_core::glam::{Vec3, Vec3A};
use raystep_core::{Aabb, DVec3};

/// One object as the builder moves it: its box in `f32`, relative to the
/// middle of the scene (so that a scene far from the origin keeps its
/// detail), and its index; 32 bytes, the same as a box of `f64`s'
/// two thirds.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub(crate) struct Item {
    min: Vec3,
    pub(crate) index: u32,
    max: Vec3,
}

impl Item {
    /// Twice the centroid (the halving changes no comparison).
    pub(crate) fn centroid2(&self) -> Vec3A {
        Vec3A::from(self.min) + Vec3A::from(self.max)
    }

    /// Its box.
    pub(crate) fn bounds(&self) -> Box32 {
        Box32 {
            min: self.min.into(),
            max: self.max.into(),
        }
    }
}

/// A box in `f32`, for choosing splits only.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Box32 {
    pub(crate) min: Vec3A,
    pub(crate) max: Vec3A,
}

impl Box32 {
    pub(crate) const EMPTY: Box32 = Box32 {
        min: Vec3A::INFINITY,
        max: Vec3A::NEG_INFINITY,
    };

    pub(crate) fn union(self, other: Box32) -> Box32 {
        Box32 {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    pub(crate) fn grow(self, p: Vec3A) -> Box32 {
        Box32 {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The surface area, 0 for an empty box.
    pub(crate) fn area(&self) -> f32 {
        let d = (self.max - self.min).max(Vec3A::ZERO);
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// In `f64`, for the cost model (a translated box: only its area is
    /// read).
    pub(crate) fn to_aabb(self) -> Aabb {
        Aabb {
            min: self.min.as_dvec3(),
            max: self.max.as_dvec3(),
        }
    }
}

/// The objects' boxes in `f32` around the middle of their union.
pub(crate) fn items(boxes: &[Aabb], order: &[u32]) -> Vec<Item> {
    let all = order
        .iter()
        .map(|&i| boxes[i as usize])
        .fold(Aabb::EMPTY, Aabb::union);
    let middle: DVec3 = 0.5 * all.min + 0.5 * all.max;
    order
        .iter()
        .map(|&index| {
            let b = boxes[index as usize];
            Item {
                min: (b.min - middle).as_vec3(),
                index,
                max: (b.max - middle).as_vec3(),
            }
        })
        .collect()
}

/// The box and the centroids' box of `items`.
pub(crate) fn measure(items: &[Item]) -> (Box32, Box32) {
    items
        .iter()
        .fold((Box32::EMPTY, Box32::EMPTY), |(b, c), item| {
            (b.union(item.bounds()), c.grow(item.centroid2()))
        })
}
