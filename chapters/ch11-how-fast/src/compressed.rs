//! Step 5e: compressed wide nodes. An 8-wide node of plain `f32` boxes
//! is 256 bytes, four cache lines, and an incoherent ray pays a cache
//! miss for most of them. Stored as one origin and one power-of-two
//! scale per axis, and each child's planes as 8-bit multiples of the
//! scale from the origin (as in Ylitie, Karras and Laine 2017), the node
//! is 96 bytes.
//!
//! The boxes stay conservative and the test stays exactly chapter 8's:
//! each child's low planes are rounded down and its high planes up to
//! the lattice, and the origin and scale are chosen so that every
//! lattice plane (origin + q·2ᵉ, q = 0…255) is exactly an `f32` — the
//! decoded box is an `f32` box that contains the child's, and the slab
//! test with its widened exit runs on it unchanged.
use crate::ray::FastRay;
use crate::wide::{Links, WideNode};

/// A leaf's link: its count in the top 4 bits, its first triangle below.
const COUNT_SHIFT: u32 = 28;

// ANCHOR: compressed_node
/// Eight children in 96 bytes: per axis an origin and an exponent; per
/// child its link and its six planes as bytes (`qlo[axis][child]`); a
/// bit per child that exists.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(32))]
pub struct CompressedNode {
    /// The lattice's origin per axis (a multiple of its scale).
    pub origin: [f32; 3],
    /// The lattice's scale per axis is 2^exponent.
    pub exponent: [i8; 3],
    /// Bit `i`: child `i` exists.
    pub valid: u8,
    /// A node's index, or a leaf's count (top 4 bits) and first triangle.
    pub child: [u32; 8],
    /// The children's low planes, in steps of the scale from the origin.
    pub qlo: [[u8; 8]; 3],
    /// Their high planes.
    pub qhi: [[u8; 8]; 3],
}
// ANCHOR_END: compressed_node

impl Links for CompressedNode {
    #[inline(always)]
    fn link(&self, i: usize) -> (u32, u32) {
        let c = self.child[i];
        if c >> COUNT_SHIFT == 0 {
            (c, 0)
        } else {
            (c & ((1 << COUNT_SHIFT) - 1), c >> COUNT_SHIFT)
        }
    }
}

impl CompressedNode {
    // ANCHOR: quantize
    /// `node` compressed: every child's box grows to the lattice, never
    /// shrinks.
    pub fn new(node: &WideNode<8>) -> CompressedNode {
        let mut q = CompressedNode {
            origin: [0.0; 3],
            exponent: [0; 3],
            valid: 0,
            child: [0; 8],
            qlo: [[255; 8]; 3],
            qhi: [[0; 8]; 3],
        };
        for i in 0..8 {
            if node.lo[0][i] > node.hi[0][i] {
                continue; // an empty slot
            }
            q.valid |= 1 << i;
            q.child[i] = if node.count[i] == 0 {
                assert!(node.child[i] < 1 << COUNT_SHIFT, "too many nodes");
                node.child[i]
            } else {
                assert!(node.count[i] < 16, "leaves hold at most 15");
                assert!(node.child[i] < 1 << COUNT_SHIFT, "too many triangles");
                node.count[i] << COUNT_SHIFT | node.child[i]
            };
        }
        for axis in 0..3 {
            // Step 1: the children's extent along the axis (in f64: every
            // f32 is exact there, and so are the sums below).
            let live = (0..8).filter(|i| q.valid >> i & 1 == 1);
            let lo = live.clone().map(|i| f64::from(node.lo[axis][i]));
            let hi = live.map(|i| f64::from(node.hi[axis][i]));
            let (lo, hi) = (
                lo.fold(f64::INFINITY, f64::min),
                hi.fold(f64::NEG_INFINITY, f64::max),
            );
            if lo > hi {
                continue; // no child
            }
            // Step 2: the smallest scale 2^e whose lattice from a
            // multiple of 2^e below `lo` reaches `hi` in 255 steps, and
            // whose 256 planes are all exact f32s (|plane| < 2^24·2^e).
            let mut e = ((hi - lo) / 255.0).log2().floor().max(-120.0) as i32;
            let origin = loop {
                let s = 2f64.powi(e);
                let origin = (lo / s).floor() * s;
                let top = origin + 255.0 * s;
                let exact = origin.abs().max(top.abs()) < 2f64.powi(24) * s;
                if top >= hi && exact {
                    break origin;
                }
                e += 1;
            };
            let s = 2f64.powi(e);
            q.origin[axis] = origin as f32;
            q.exponent[axis] = e as i8;
            // Step 3: low planes rounded down, high planes up.
            for i in 0..8 {
                if q.valid >> i & 1 == 1 {
                    let l = f64::from(node.lo[axis][i]);
                    let h = f64::from(node.hi[axis][i]);
                    q.qlo[axis][i] = ((l - origin) / s).floor() as u8;
                    q.qhi[axis][i] = ((h - origin) / s).ceil() as u8;
                }
            }
        }
        q
    }
    // ANCHOR_END: quantize

    /// Child `i`'s box as the tests decode it: `[lo, hi]` per axis.
    pub fn decoded(&self, i: usize) -> [[f32; 3]; 2] {
        let plane = |axis: usize, q: u8| {
            let s = 2f32.powi(i32::from(self.exponent[axis]));
            f32::from(q) * s + self.origin[axis]
        };
        [
            [0, 1, 2].map(|a| plane(a, self.qlo[a][i])),
            [0, 1, 2].map(|a| plane(a, self.qhi[a][i])),
        ]
    }
}

/// The box test of every child of a compressed node, one after another
/// (any CPU): each plane decoded, then chapter 8's slab test.
#[inline(always)]
pub fn scalar_boxes(
    node: &CompressedNode, ray: &FastRay, (t_min, t_max): (f32, f32),
) -> ([f32; 8], u32) {
    let mut near = [t_min; 8];
    let mut mask = 0;
    let scale = [0, 1, 2].map(|a| 2f32.powi(i32::from(node.exponent[a])));
    #[allow(clippy::needless_range_loop)] // one child, one axis of arrays
    for i in 0..8 {
        let mut far = t_max;
        for axis in 0..3 {
            let decode = |q: u8| f32::from(q) * scale[axis] + node.origin[axis];
            let (lo, hi) =
                (decode(node.qlo[axis][i]), decode(node.qhi[axis][i]));
            let (t0, t1) = ray.slab(axis, lo, hi);
            near[i] = near[i].max(t0);
            far = far.min(t1);
        }
        mask |= u32::from(near[i] <= far) << i;
    }
    (near, mask & u32::from(node.valid))
}
