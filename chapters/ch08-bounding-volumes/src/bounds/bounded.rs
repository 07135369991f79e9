//! A bounding volume in front of an object: the cheap test first, the
//! object's own test only for the rays that come near it.
use raystep_core::{Aabb, Hit, Interval, Ray, Shape};

use crate::{BoundingSphere, Primitive};

/// A bounding volume: a box or a sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// An axis-aligned box, hit by the robust slab test (exercise 1,
    /// [`slab_test`](crate::slab_test)).
    Box(Aabb),
    /// A sphere ([`BoundingSphere::hit`]).
    Sphere(BoundingSphere),
}

impl Bound {
    /// The part of `interval` in which `ray` is inside the volume, or None.
    pub fn hit(&self, ray: &Ray, interval: Interval) -> Option<Interval> {
        match self {
            Bound::Box(b) => crate::slab_test(b, ray, interval),
            Bound::Sphere(s) => s.hit(ray, interval),
        }
    }
}

/// Which bounding volume to put around an object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BoundKind {
    /// Its box, [`Shape::bounds`].
    Box,
    /// Its own bounding sphere, [`Primitive::bounding_sphere`].
    Sphere,
    /// The sphere through its box's corners ([`BoundingSphere::around_box`]):
    /// what a sphere bound is when nothing better is known.
    BoxSphere,
}

impl BoundKind {
    /// The three kinds, in the order tables show them.
    pub const ALL: [BoundKind; 3] =
        [BoundKind::Box, BoundKind::Sphere, BoundKind::BoxSphere];

    /// `box`, `sphere` or `box's sphere`: the name tables and charts show.
    pub fn name(self) -> &'static str {
        match self {
            BoundKind::Box => "box",
            BoundKind::Sphere => "sphere",
            BoundKind::BoxSphere => "box's sphere",
        }
    }

    /// This kind of volume around `object`.
    pub fn around(self, object: &dyn Primitive) -> Bound {
        match self {
            BoundKind::Box => Bound::Box(object.bounds()),
            BoundKind::Sphere => Bound::Sphere(object.bounding_sphere()),
            BoundKind::BoxSphere => {
                Bound::Sphere(BoundingSphere::around_box(&object.bounds()))
            }
        }
    }
}

/// How many tests a [`Bounded`] made: of its bound, and of the object
/// behind it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TestCounts {
    /// Tests of the bounding volume: one per ray.
    pub bound: u64,
    /// Tests of the object: one per ray that hit the bound.
    pub object: u64,
}

/// An object behind a bounding volume: a [`Shape`] that tests the bound
/// first and the object only when the bound is hit.
///
/// The object is asked about the ray's whole interval, not only the part
/// inside the bound, so a bounded object answers exactly what the object
/// answers, for every ray whose bound test says yes. The box test never
/// says no to a ray that meets the box ([`slab_test`](crate::slab_test));
/// a sphere bound should be a little larger than the object where they
/// touch.
#[derive(Debug)]
pub struct Bounded {
    object: Box<dyn Shape>,
    bound: Bound,
}

impl Bounded {
    /// `object` behind `bound` (which must contain it).
    pub fn new(object: Box<dyn Shape>, bound: Bound) -> Bounded {
        Bounded { object, bound }
    }

    /// `object` behind its own box.
    pub fn boxed(object: Box<dyn Shape>) -> Bounded {
        let bound = Bound::Box(object.bounds());
        Bounded::new(object, bound)
    }

    /// A primitive behind this kind of bound.
    pub fn around(object: Box<dyn Primitive>, kind: BoundKind) -> Bounded {
        let bound = kind.around(object.as_ref());
        Bounded::new(object, bound)
    }

    /// The object behind the bound.
    pub fn object(&self) -> &dyn Shape {
        self.object.as_ref()
    }

    /// The bounding volume.
    pub fn bound(&self) -> Bound {
        self.bound
    }

    /// [`Shape::intersect`], adding the tests it makes to `counts`.
    pub fn intersect_counted(
        &self, ray: &Ray, interval: Interval, counts: &mut TestCounts,
    ) -> Option<Hit> {
        counts.bound += 1;
        self.bound.hit(ray, interval)?;
        counts.object += 1;
        self.object.intersect(ray, interval)
    }
}

// ANCHOR: bounded_intersect
/// The bounding-volume test: the cheap question first ("does the ray come
/// near?"), the expensive one only if the answer is yes.
pub fn bounded_intersect(
    bound: &Bound, object: &dyn Shape, ray: &Ray, interval: Interval,
) -> Option<Hit> {
    // Step 1: test the bound. A miss there is a miss of the object.
    bound.hit(ray, interval)?;
    // Step 2: test the object, on the whole interval: a hit the bound's
    // rounding put a hair outside its interval is still found.
    object.intersect(ray, interval)
}
// ANCHOR_END: bounded_intersect

impl Shape for Bounded {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        bounded_intersect(&self.bound, self.object.as_ref(), ray, interval)
    }

    fn bounds(&self) -> Aabb {
        self.object.bounds()
    }
}
