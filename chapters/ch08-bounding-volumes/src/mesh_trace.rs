//! The fast walk through a [`MeshBvh`]: everything that depends on the
//! ray alone (the reciprocal direction, the watertight test's shear) is
//! computed once per ray, not once per box or per triangle.
use raystep_core::{DVec3, Interval};

use crate::mesh_bvh::{Node32, Node64, Nodes, outward};
use crate::watertight::sheared_hit;
use crate::{MeshBvh, Ray32, Shear};

/// What one walk did: the work a ray costs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceCounts {
    /// Nodes taken from the stack and looked at (interior or leaf).
    pub nodes: u64,
    /// Ray–triangle tests.
    pub triangles: u64,
}

impl TraceCounts {
    /// Both counts added.
    pub fn add(&mut self, other: TraceCounts) {
        self.nodes += other.nodes;
        self.triangles += other.triangles;
    }
}

/// A hit of the mesh: which triangle (the mesh's index) and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshHit {
    /// The triangle's index in the mesh.
    pub triangle: u32,
    /// The ray's parameter at the hit.
    pub t: f64,
}

/// γ₃ for `f32` and for `f64`: the widening of a slab's exit (part 1).
const GAMMA3_F32: f32 = 3.0 * (f32::EPSILON / 2.0) / (1.0 - 1.5 * f32::EPSILON);
const GAMMA3_F64: f64 = 3.0 * (f64::EPSILON / 2.0) / (1.0 - 1.5 * f64::EPSILON);

/// Step 1 of every walk: the ray's part of every test, once.
///
/// Public so that other hierarchies (the benchmark's peers) can be handed
/// the very same triangle test: [`PreparedRay::triangle`].
pub struct PreparedRay {
    /// The origin, and the watertight test's axes and shear.
    origin: DVec3,
    shear: Shear,
    /// The slab test's origin and reciprocal direction, in both
    /// precisions, and per axis whether the ray goes toward −axis (then
    /// it enters the slab through its max plane).
    origin32: [f32; 3],
    inverse32: [f32; 3],
    origin64: [f64; 3],
    inverse64: [f64; 3],
    negative: [usize; 3],
}

impl PreparedRay {
    /// The ray's reciprocal direction and shear.
    pub fn new(ray: &Ray32) -> PreparedRay {
        let d = ray.direction.as_dvec3();
        let inverse32 = ray.direction.to_array().map(|x| 1.0 / x);
        PreparedRay {
            origin: ray.origin.as_dvec3(),
            // The watertight test's steps 1 and 2 (exercise 2).
            shear: Shear::of(d),
            origin32: ray.origin.to_array(),
            inverse32,
            origin64: ray.origin.as_dvec3().to_array(),
            inverse64: d.to_array().map(|x| 1.0 / x),
            negative: inverse32.map(|x| usize::from(x.is_sign_negative())),
        }
    }

    /// The watertight test's step 3 and the rest: the hit `t` of the
    /// triangle `v` within `interval`. The same numbers as
    /// [`watertight`](crate::watertight) gives, computed in the same
    /// order.
    #[inline]
    pub fn triangle(&self, v: &[DVec3; 3], interval: Interval) -> Option<f64> {
        // Step 3 (exercise 2), then steps 4–7.
        let sheared = v.map(|vertex| self.shear.vertex(self.origin, vertex));
        sheared_hit(sheared, interval)
    }
}

/// A node's box test and link, in whatever precision it is stored.
trait SlabNode {
    /// The interval in the test's precision, its end already widened.
    type Span: Copy;
    /// `interval` as the test wants it (computed when it changes, not
    /// for every box).
    fn span(interval: Interval) -> Self::Span;
    /// The `t` at which the ray enters the box, if it meets the box
    /// within the span.
    fn enter(&self, ray: &PreparedRay, span: Self::Span) -> Option<f64>;
    /// `(first, count)`, as in [`BvhNode`](crate::BvhNode).
    fn link(&self) -> (u32, u32);
    /// The farthest entry `t` the box test lets through for an interval
    /// ending at `t_max`: a box popped later that begins beyond it holds
    /// nothing closer.
    fn reach(t_max: f64) -> f64;
}

impl SlabNode for &Node64 {
    type Span = (f64, f64);

    fn span(interval: Interval) -> (f64, f64) {
        (interval.min, interval.max * (1.0 + 2.0 * GAMMA3_F64))
    }

    #[inline]
    fn enter(&self, ray: &PreparedRay, span: (f64, f64)) -> Option<f64> {
        let (mut near, mut far) = span;
        #[allow(clippy::needless_range_loop)] // one axis of five arrays
        for axis in 0..3 {
            // Part 1's slab test: near and far planes chosen by the
            // sign bit of 1/d, the exit widened, NaN ignored by max/min.
            let s = ray.negative[axis];
            let o = ray.origin64[axis];
            let t0 = (self.bounds[s][axis] - o) * ray.inverse64[axis];
            let t1 = (self.bounds[1 - s][axis] - o) * ray.inverse64[axis];
            near = near.max(t0);
            far = far.min(t1 * (1.0 + 2.0 * GAMMA3_F64));
        }
        (near <= far).then_some(near)
    }

    fn link(&self) -> (u32, u32) {
        (self.first, self.count)
    }

    fn reach(t_max: f64) -> f64 {
        t_max * (1.0 + 2.0 * GAMMA3_F64)
    }
}

/// An `f32` node tested robustly: exits (and the interval's end) widened
/// by 1 + 2γ₃, so rounding never loses a box (Ize, JCGT 2013).
struct Robust<'a>(&'a Node32);
/// An `f32` node tested as it is, rounding and all.
struct Plain<'a>(&'a Node32);

impl Node32 {
    /// The slab test in `f32`, the exit scaled by `widen`.
    #[inline]
    fn slab(
        &self,
        ray: &PreparedRay,
        (t_min, t_max): (f32, f32),
        widen: f32,
    ) -> Option<f32> {
        let bounds = [self.min, self.max];
        let (mut near, mut far) = (t_min, t_max);
        #[allow(clippy::needless_range_loop)] // one axis of five arrays
        for axis in 0..3 {
            let s = ray.negative[axis];
            let o = ray.origin32[axis];
            let t0 = (bounds[s][axis] - o) * ray.inverse32[axis];
            let t1 = (bounds[1 - s][axis] - o) * ray.inverse32[axis];
            near = near.max(t0);
            far = far.min(t1 * widen);
        }
        (near <= far).then_some(near)
    }
}

impl SlabNode for Robust<'_> {
    type Span = (f32, f32);

    fn span(interval: Interval) -> (f32, f32) {
        // The interval's ends in f32, rounded outward, the end widened.
        let widen = 1.0 + 2.0 * GAMMA3_F32;
        let hi = outward(interval.max, true) * widen;
        (outward(interval.min, false), hi)
    }

    #[inline]
    fn enter(&self, ray: &PreparedRay, span: (f32, f32)) -> Option<f64> {
        self.0
            .slab(ray, span, 1.0 + 2.0 * GAMMA3_F32)
            .map(f64::from)
    }

    fn link(&self) -> (u32, u32) {
        (self.0.first, self.0.count)
    }

    fn reach(t_max: f64) -> f64 {
        // f32's widening, and the rounding of the entry back to f64.
        t_max * (1.0 + 4.0 * f64::from(GAMMA3_F32))
    }
}

impl SlabNode for Plain<'_> {
    type Span = (f32, f32);

    fn span(interval: Interval) -> (f32, f32) {
        (interval.min as f32, interval.max as f32)
    }

    #[inline]
    fn enter(&self, ray: &PreparedRay, span: (f32, f32)) -> Option<f64> {
        self.0.slab(ray, span, 1.0).map(f64::from)
    }

    fn link(&self) -> (u32, u32) {
        (self.0.first, self.0.count)
    }

    fn reach(t_max: f64) -> f64 {
        t_max
    }
}

impl MeshBvh {
    /// The closest hit of `ray` within `interval`, and what it cost
    /// (added to `counts`). A ray with a NaN, an infinity or a zero
    /// direction is answered None without being traced.
    pub fn closest_hit(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        if !ray.is_valid() {
            return None;
        }
        let ray = PreparedRay::new(ray);
        match &self.nodes {
            Nodes::Double(n) => self.closest(n, |n| n, &ray, interval, counts),
            Nodes::Single(n) => self.closest(n, Robust, &ray, interval, counts),
            Nodes::SingleNearest(n) => {
                self.closest(n, Plain, &ray, interval, counts)
            }
        }
    }

    /// Does anything meet `ray` within `interval`? (A shadow ray.)
    pub fn any_hit(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        if !ray.is_valid() {
            return false;
        }
        let ray = PreparedRay::new(ray);
        match &self.nodes {
            Nodes::Double(n) => self.any(n, |n| n, &ray, interval, counts),
            Nodes::Single(n) => self.any(n, Robust, &ray, interval, counts),
            Nodes::SingleNearest(n) => {
                self.any(n, Plain, &ray, interval, counts)
            }
        }
    }

    /// Brute force with the same triangle test: every triangle, in the
    /// mesh's order, the closest kept. What the walk must agree with.
    pub fn brute_force(
        &self,
        ray: &Ray32,
        interval: Interval,
    ) -> Option<MeshHit> {
        if !ray.is_valid() {
            return None;
        }
        let ray = PreparedRay::new(ray);
        let mut interval = interval;
        let mut closest = None;
        for (k, v) in self.all.iter().enumerate() {
            if let Some(t) = ray.triangle(v, interval) {
                interval = interval.with_max(t);
                closest = Some(MeshHit {
                    triangle: k as u32,
                    t,
                });
            }
        }
        closest
    }

    // ANCHOR: fast_closest
    /// The near-first walk of [`Bvh`](crate::Bvh)'s closest hit, over
    /// nodes of type `N` seen through `view` (their precision's test).
    fn closest<'a, N: 'a, V: SlabNode>(
        &self,
        nodes: &'a [N],
        view: impl Fn(&'a N) -> V,
        ray: &PreparedRay,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let mut interval = interval;
        let mut closest = None;
        // Step 1: triangles outside the tree (none in a finite mesh).
        for &id in &self.unbounded {
            counts.triangles += 1;
            if let Some(t) = ray.triangle(&self.all[id as usize], interval) {
                interval = interval.with_max(t);
                closest = Some(MeshHit { triangle: id, t });
            }
        }
        // Step 2: a stack of (node, entry t); the depth bounds its size.
        let mut stack = Stack::new(self.depth + 1, (0, 0.0));
        let mut span = V::span(interval);
        if let Some(root) = nodes.first()
            && let Some(t) = view(root).enter(ray, span)
        {
            stack.push((0, t));
        }
        while let Some((k, entry)) = stack.pop() {
            // Step 3: a box entered beyond the closest hit holds nothing
            // closer (the comparison as loose as the box test's).
            if entry > V::reach(interval.max) {
                continue;
            }
            counts.nodes += 1;
            let (first, count) = view(&nodes[k as usize]).link();
            if count > 0 {
                // Step 4: a leaf: its triangles lie side by side.
                let range = first as usize..(first + count) as usize;
                for k in range {
                    counts.triangles += 1;
                    if let Some(t) = ray.triangle(&self.corners[k], interval) {
                        interval = interval.with_max(t);
                        span = V::span(interval);
                        closest = Some(MeshHit {
                            triangle: self.ids[k],
                            t,
                        });
                    }
                }
                continue;
            }
            // Step 5: both children's boxes; the nearer is pushed last so
            // that it is visited first.
            let (a, b) = (first, first + 1);
            let ta = view(&nodes[a as usize]).enter(ray, span);
            let tb = view(&nodes[b as usize]).enter(ray, span);
            match (ta, tb) {
                (Some(ta), Some(tb)) if tb < ta => {
                    stack.push((a, ta));
                    stack.push((b, tb));
                }
                (Some(ta), Some(tb)) => {
                    stack.push((b, tb));
                    stack.push((a, ta));
                }
                (Some(ta), None) => stack.push((a, ta)),
                (None, Some(tb)) => stack.push((b, tb)),
                (None, None) => {}
            }
        }
        closest
    }
    // ANCHOR_END: fast_closest

    /// The any-hit walk: the same, stopped at the first triangle hit.
    fn any<'a, N: 'a, V: SlabNode>(
        &self,
        nodes: &'a [N],
        view: impl Fn(&'a N) -> V,
        ray: &PreparedRay,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        for &id in &self.unbounded {
            counts.triangles += 1;
            if ray.triangle(&self.all[id as usize], interval).is_some() {
                return true;
            }
        }
        let mut stack = Stack::new(self.depth + 1, 0);
        let span = V::span(interval);
        if !nodes.is_empty() {
            stack.push(0);
        }
        while let Some(k) = stack.pop() {
            let node = view(&nodes[k as usize]);
            if node.enter(ray, span).is_none() {
                continue;
            }
            counts.nodes += 1;
            let (first, count) = node.link();
            if count == 0 {
                stack.push(first);
                stack.push(first + 1);
                continue;
            }
            for k in first as usize..(first + count) as usize {
                counts.triangles += 1;
                if ray.triangle(&self.corners[k], interval).is_some() {
                    return true; // one blocker is enough
                }
            }
        }
        false
    }
}

/// The walk's stack: on the call stack for trees up to `FIXED` deep (no
/// heap allocation per ray; 32 entries, as the array is cleared for every
/// ray), on the heap for deeper ones. `capacity` (the
/// tree's depth + 1) is never exceeded: each visit pops one node and
/// pushes at most two.
struct Stack<T: Copy> {
    fixed: [T; FIXED],
    spilled: Vec<T>,
    deep: bool,
    len: usize,
}

/// The deepest tree whose walk keeps its stack on the call stack.
const FIXED: usize = 32;

impl<T: Copy> Stack<T> {
    #[inline]
    fn new(capacity: usize, zero: T) -> Stack<T> {
        let deep = capacity > FIXED;
        Stack {
            fixed: [zero; FIXED],
            spilled: if deep {
                vec![zero; capacity]
            } else {
                Vec::new()
            },
            deep,
            len: 0,
        }
    }

    #[inline]
    fn push(&mut self, value: T) {
        if self.deep {
            self.spilled[self.len] = value;
        } else {
            self.fixed[self.len] = value;
        }
        self.len += 1;
    }

    #[inline]
    fn pop(&mut self) -> Option<T> {
        if self.len == 0 {
            return None;
        }
        self.len -= 1;
        Some(if self.deep {
            self.spilled[self.len]
        } else {
            self.fixed[self.len]
        })
    }
}
