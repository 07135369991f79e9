use crate::{Aabb, Hit, Interval, Ray};

/// A surface a tracer can hit: chapter 3's sphere, chapter 2's polygon
/// and plane, and every primitive a later chapter adds.
///
/// Each chapter implements it for the shapes it teaches, with the
/// intersection the lecture derives there; a world holds its objects as
/// `dyn Shape`, so a tracer never needs to know which kind it hit.
pub trait Shape: std::fmt::Debug + Send + Sync {
    /// The first hit of `ray` with the surface whose `t` lies in
    /// `interval`.
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit>;

    /// A box that contains the whole surface ([`Aabb::EVERYTHING`] if it
    /// is unbounded). Any ray that hits the surface within an interval
    /// hits this box within it.
    fn bounds(&self) -> Aabb;
}
