//! The fast walk through a [`MeshBvh`], asked through the mesh seam
//! ([`MeshAccelerator`]): the ray prepared once ([`PreparedRay`]), the
//! boxes tested in the precision they are stored in.
use raystep_core::{Interval, Ray32};
use raystep_world::{MeshAccelerator, MeshHit, TraceCounts};

use super::brute_force::MeshBruteForce;
use super::mesh_bvh::{MeshBvh, Node32, Node64, Nodes, outward};
use super::prepared_ray::{Closest, PreparedRay};

/// γ₃ for `f32` and for `f64`: the widening of a slab's exit (part 1).
const GAMMA3_F32: f32 = 3.0 * (f32::EPSILON / 2.0) / (1.0 - 1.5 * f32::EPSILON);
const GAMMA3_F64: f64 = 3.0 * (f64::EPSILON / 2.0) / (1.0 - 1.5 * f64::EPSILON);

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
        &self, ray: &PreparedRay, (t_min, t_max): (f32, f32), widen: f32,
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

impl MeshAccelerator for MeshBvh {
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let ray = PreparedRay::traced(ray)?;
        match &self.nodes {
            Nodes::Double(n) => self.closest(n, |n| n, &ray, interval, counts),
            Nodes::Single(n) => self.closest(n, Robust, &ray, interval, counts),
            Nodes::SingleNearest(n) => {
                self.closest(n, Plain, &ray, interval, counts)
            }
        }
    }

    fn any_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        let Some(ray) = PreparedRay::traced(ray) else {
            return false;
        };
        match &self.nodes {
            Nodes::Double(n) => self.any(n, |n| n, &ray, interval, counts),
            Nodes::Single(n) => self.any(n, Robust, &ray, interval, counts),
            Nodes::SingleNearest(n) => {
                self.any(n, Plain, &ray, interval, counts)
            }
        }
    }
}

impl MeshBvh {
    /// Brute force with the same triangle test: every triangle, in the
    /// mesh's order, the closest kept. What the walk must agree with.
    pub fn brute_force(
        &self, ray: &Ray32, interval: Interval,
    ) -> Option<MeshHit> {
        let mut uncounted = TraceCounts::default();
        MeshBruteForce(&self.all).closest_hit(ray, interval, &mut uncounted)
    }

    // ANCHOR: fast_closest
    /// The near-first walk of [`Bvh`](crate::Bvh)'s closest hit, over
    /// nodes of type `N` seen through `view` (their precision's test).
    fn closest<'a, N: 'a, V: SlabNode>(
        &self, nodes: &'a [N], view: impl Fn(&'a N) -> V, ray: &PreparedRay,
        interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let mut closest = Closest::new(interval);
        // Step 1: triangles outside the tree (none in a finite mesh).
        for &id in &self.unbounded {
            closest.test(ray, id, &self.all[id as usize], counts);
        }
        // Step 2: a stack of (node, entry t); the depth bounds its size.
        let mut stack = Stack::new(self.depth + 1, (0, 0.0));
        let mut span = V::span(closest.interval);
        if let Some(root) = nodes.first()
            && let Some(t) = view(root).enter(ray, span)
        {
            stack.push((0, t));
        }
        while let Some((k, entry)) = stack.pop() {
            // Step 3: a box entered beyond the closest hit holds nothing
            // closer (the comparison as loose as the box test's).
            if entry > V::reach(closest.interval.max) {
                continue;
            }
            counts.nodes += 1;
            let (first, count) = view(&nodes[k as usize]).link();
            if count > 0 {
                // Step 4: a leaf: its triangles lie side by side.
                let range = first as usize..(first + count) as usize;
                for k in range {
                    let (id, v) = (self.ids[k], &self.corners[k]);
                    if closest.test(ray, id, v, counts) {
                        span = V::span(closest.interval);
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
        closest.hit
    }
    // ANCHOR_END: fast_closest

    /// The any-hit walk: the same, stopped at the first triangle hit.
    fn any<'a, N: 'a, V: SlabNode>(
        &self, nodes: &'a [N], view: impl Fn(&'a N) -> V, ray: &PreparedRay,
        interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        for &id in &self.unbounded {
            if ray.blocked_by(&self.all[id as usize], interval, counts) {
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
                if ray.blocked_by(&self.corners[k], interval, counts) {
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
