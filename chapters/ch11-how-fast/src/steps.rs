//! The steps of the appendix, each one row of its table: what is built,
//! and one type that builds and traces any of them.
use ch08::{
    Builder, Bvh, MeshAccelerator, MeshHit, Ray32, TraceCounts, triangle_boxes,
};
use raystep_core::{DVec3, Interval};

use crate::binary::Binary;
use crate::compressed::CompressedNode;
use crate::leaf4::merge_leaves;
#[cfg(target_arch = "x86_64")]
use crate::simd8;
use crate::wide::{Wide, scalar_boxes};

/// One step of the way: each adds one thing to the one before it.
/// (Step 1, the baseline, is chapter 8's [`MeshBvh`](ch08::MeshBvh).)
///
/// The steps' one list: their order ([`Step::ALL`]), their names in
/// tables and on the command line (`raystep bench --fast NAME`) and the
/// command line's one-line help (each step's first paragraph) all come
/// from here.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, clap::ValueEnum)]
pub enum Step {
    /// Step 2: compact nodes, children ordered by the ray's direction.
    ///
    /// 2: chapter 8's tree (binned SAH, 16 bins) in compact nodes, each
    /// box tested when reached, children in the order the ray's direction
    /// gives.
    #[value(name = "ordered")]
    Ordered,
    /// Step 3: and the leaves' triangles in f32.
    ///
    /// 3: and the leaves' triangles in `f32` (exactly), half the bytes.
    #[value(name = "leaf-f32")]
    LeafLayout,
    /// Step 4: and the full-sweep SAH tree.
    ///
    /// 4: and a better tree: the full-sweep SAH of chapter 8 (a side
    /// step: the steps after it go back to the binned tree).
    #[value(name = "sweep-tree")]
    SweepTree,
    /// Step 4b: step 3's tree improved by tree rotations.
    ///
    /// 4b: step 3's tree improved by tree rotations (another side step).
    #[value(name = "rotated-tree")]
    RotatedTree,
    /// Step 5: 4-wide nodes, boxes tested one by one.
    ///
    /// 5a: and 4-wide nodes, their boxes tested one by one.
    #[value(name = "bvh4-scalar")]
    Wide4Scalar,
    /// 4-wide nodes, SSE.
    ///
    /// 5b: 4-wide nodes, the four boxes tested at once with SSE.
    #[value(name = "bvh4-sse")]
    Wide4,
    /// 8-wide nodes, one by one.
    ///
    /// 5c: 8-wide nodes, one by one.
    #[value(name = "bvh8-scalar")]
    Wide8Scalar,
    /// 8-wide nodes, AVX (one by one where the CPU lacks it).
    ///
    /// 5d: 8-wide nodes, eight at once with AVX (where the CPU has it).
    #[value(name = "bvh8-avx")]
    Wide8,
    /// 8-wide nodes compressed to 96 bytes, AVX2 (one by one where the
    /// CPU lacks it).
    ///
    /// 5e: 8-wide nodes compressed to 96 bytes, AVX2 (where the CPU has
    /// it).
    #[value(name = "bvh8-compressed")]
    Compressed8,
    /// `bvh8-avx` on the full-sweep tree.
    ///
    /// 5f: 5d on step 4's full-sweep tree (a slower build).
    #[value(name = "bvh8-avx-sweep")]
    Wide8Sweep,
    /// `bvh8-compressed` on the full-sweep tree.
    ///
    /// 5g: 5e on step 4's full-sweep tree.
    #[value(name = "bvh8-compressed-sweep")]
    Compressed8Sweep,
    /// Step 6: `bvh8-avx`, each triangle's edges tested at once (AVX2).
    ///
    /// 6a: 5d, and each triangle's three edges tested at once (AVX2,
    /// where the CPU has it).
    #[value(name = "bvh8-avx-tri")]
    Wide8Triangles,
    /// `bvh8-compressed`, each triangle's edges tested at once.
    ///
    /// 6b: 5e, and each triangle's three edges tested at once.
    #[value(name = "bvh8-compressed-tri")]
    Compressed8Triangles,
    /// Step 7: `bvh8-avx-tri`, its tree built on `--threads` threads.
    ///
    /// 7a: 6a, its tree built on the threads of the current rayon pool
    /// ([`build_parallel`](crate::parallel_build::build_parallel)).
    #[value(name = "bvh8-par")]
    Wide8Parallel,
    /// `bvh8-compressed-tri`, its tree built on `--threads` threads.
    ///
    /// 7b: 6b, its tree built on the pool's threads.
    #[value(name = "bvh8-compressed-par")]
    Compressed8Parallel,
    /// Step 8: `bvh8-avx-tri` with leaves of four, tested four at once.
    ///
    /// 8: 6a, its small subtrees merged into leaves of blocks of four
    /// triangles where the SAH says so, each block tested four triangles
    /// at once (AVX2, where the CPU has it).
    #[value(name = "bvh8-leaf4")]
    Wide8Leaf4,
    /// `bvh8-compressed-tri` with leaves of four, tested four at once.
    ///
    /// 8b: 6b (compressed nodes), its leaves as step 8's.
    #[value(name = "bvh8-compressed-leaf4")]
    Compressed8Leaf4,
    /// Step 9: `bvh8-leaf4`, any-hit rays taking children unsorted.
    ///
    /// 9: 8a, and a shadow ray (any hit) takes the children it hits in
    /// the node's order instead of nearest first.
    #[value(name = "bvh8-any-unsorted")]
    Wide8AnyUnsorted,
    /// Step 10: `bvh8-any-unsorted`, a leaf's two blocks tested at once
    /// with AVX-512 (as step 9 where the CPU lacks it).
    ///
    /// 10: 9, and a leaf's two blocks tested at once in the eight lanes
    /// of AVX-512 (where the CPU has it).
    #[value(name = "bvh8-avx512-pairs")]
    Wide8Pairs512,
    /// Step 11: step 9 with a walk whose critical path is shorter.
    ///
    /// 11: 9, walked with less between one node's load and the next: the
    /// exit planes' widening folded into the ray, the planes chosen once
    /// per ray, one and two children met taken by their own branches.
    #[value(name = "bvh8-short-path")]
    Wide8ShortPath,
    /// Step 12: step 11, its tree not split below eight triangles.
    ///
    /// 12: 11, its tree not split below eight triangles (two blocks:
    /// step 8 merges most such subtrees anyway): a shorter build.
    #[value(name = "bvh8-block-build")]
    Wide8BlockBuild,
    /// Step 13: step 12, its nodes and blocks in 2 MB pages.
    ///
    /// 13: 12, its nodes and blocks in 2 MB pages (where the system gives
    /// them: Linux's transparent huge pages), so that a few TLB entries
    /// cover the whole tree.
    #[value(name = "bvh8-huge-pages")]
    Wide8HugePages,
}

impl Step {
    /// Every step, in order: the list [`clap::ValueEnum`] derives from
    /// the declaration above (a test holds the two equal).
    pub const ALL: [Step; 22] = [
        Step::Ordered,
        Step::LeafLayout,
        Step::SweepTree,
        Step::RotatedTree,
        Step::Wide4Scalar,
        Step::Wide4,
        Step::Wide8Scalar,
        Step::Wide8,
        Step::Compressed8,
        Step::Wide8Sweep,
        Step::Compressed8Sweep,
        Step::Wide8Triangles,
        Step::Compressed8Triangles,
        Step::Wide8Parallel,
        Step::Compressed8Parallel,
        Step::Wide8Leaf4,
        Step::Compressed8Leaf4,
        Step::Wide8AnyUnsorted,
        Step::Wide8Pairs512,
        Step::Wide8ShortPath,
        Step::Wide8BlockBuild,
        Step::Wide8HugePages,
    ];

    /// The name tables and the command line use: its `#[value(name)]`.
    pub fn name(self) -> String {
        let value = clap::ValueEnum::to_possible_value(&self);
        value.expect("every step is named").get_name().to_string()
    }

    /// The tree builder the step starts from: chapter 8's binned SAH,
    /// but the full sweep for step 4 and for 5f and 5g (the wide steps
    /// on its tree: its build is 4–5 times as long).
    pub fn builder(self) -> Builder {
        match self {
            Step::SweepTree | Step::Wide8Sweep | Step::Compressed8Sweep => {
                Builder::SweepSah
            }
            _ => Builder::BinnedSah { bins: 16 },
        }
    }
}

/// How the boxes of a wide node are tested.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kernel {
    /// One box after another, on any CPU.
    Scalar,
    /// SSE (4 boxes), on x86-64.
    Sse,
    /// AVX (8 boxes), where the CPU has it.
    Avx,
    /// AVX2, where the CPU has it: 8 boxes, compressed or not, the walk
    /// compiled with AVX2 (which step 6's triangle test needs).
    Avx2,
    /// AVX-512 and AVX2, where the CPU has both: step 10's, the walk
    /// `Avx2`'s, a leaf's two blocks tested at once with AVX-512.
    Avx512,
    /// AVX2, step 11's walk (where the tree is no deeper than it takes).
    ShortPath,
}

/// The structure a step builds.
#[derive(Clone, Debug, PartialEq)]
enum Built {
    Binary(Binary),
    Wide4(Wide<4>, Kernel),
    Wide8(Wide<8>, Kernel),
    Compressed8(Wide<8, CompressedNode>, Kernel),
}

/// A triangle mesh's hierarchy as one step of the appendix builds it.
#[derive(Clone, Debug, PartialEq)]
pub struct FastBvh {
    built: Built,
    step: Step,
}

impl FastBvh {
    /// Builds `step`'s structure over `triangles`.
    pub fn build(triangles: &[[DVec3; 3]], step: Step) -> FastBvh {
        let boxes = triangle_boxes(triangles);
        let tree = match step {
            Step::RotatedTree => {
                let mut tree = Bvh::build(&boxes, step.builder());
                crate::rotations::rotate(&mut tree);
                tree
            }
            Step::Wide8Parallel | Step::Compressed8Parallel => {
                crate::parallel_build::build_parallel(&boxes, 16)
            }
            // Step 12: no node of eight triangles or fewer is split.
            Step::Wide8BlockBuild | Step::Wide8HugePages => {
                Bvh::build_with_leaves_of(&boxes, step.builder(), 8)
            }
            _ => Bvh::build(&boxes, step.builder()),
        };
        FastBvh::from_tree(triangles, &tree, step)
    }

    /// `step`'s structure from a tree already built (and, for step 4b,
    /// already rotated; steps 8 and 9 merge its leaves themselves).
    pub fn from_tree(
        triangles: &[[DVec3; 3]], tree: &Bvh, step: Step,
    ) -> FastBvh {
        let single = step != Step::Ordered;
        let built = match step {
            Step::Ordered
            | Step::LeafLayout
            | Step::SweepTree
            | Step::RotatedTree => {
                Built::Binary(Binary::new(triangles, tree, single))
            }
            Step::Wide4Scalar | Step::Wide4 => {
                let kernel =
                    if step == Step::Wide4 && cfg!(target_arch = "x86_64") {
                        Kernel::Sse
                    } else {
                        Kernel::Scalar
                    };
                Built::Wide4(Wide::new(triangles, tree, single), kernel)
            }
            Step::Wide8Scalar | Step::Wide8 | Step::Wide8Sweep => {
                let kernel = if step != Step::Wide8Scalar && avx() {
                    Kernel::Avx
                } else {
                    Kernel::Scalar
                };
                Built::Wide8(Wide::new(triangles, tree, single), kernel)
            }
            Step::Wide8Triangles | Step::Wide8Parallel => {
                let kernel = if avx2() {
                    Kernel::Avx2
                } else if avx() {
                    Kernel::Avx
                } else {
                    Kernel::Scalar
                };
                let wide: Wide<8> = Wide::new(triangles, tree, single);
                Built::Wide8(wide.with_lanes(), kernel)
            }
            Step::Wide8Leaf4
            | Step::Wide8AnyUnsorted
            | Step::Wide8Pairs512
            | Step::Wide8ShortPath
            | Step::Wide8BlockBuild
            | Step::Wide8HugePages => {
                let mut kernel = if avx2() {
                    Kernel::Avx2
                } else if avx() {
                    Kernel::Avx
                } else {
                    Kernel::Scalar
                };
                let wide = leaves_of_four(triangles, &merge_leaves(tree));
                let mut wide = match step {
                    Step::Wide8Leaf4 => wide,
                    _ => wide.unordered_any(),
                };
                if step == Step::Wide8Pairs512 && wide.in_pairs() {
                    kernel = Kernel::Avx512;
                }
                let short = matches!(
                    step,
                    Step::Wide8ShortPath
                        | Step::Wide8BlockBuild
                        | Step::Wide8HugePages
                );
                if short && short_path(&wide) {
                    kernel = Kernel::ShortPath;
                }
                // Step 13: the tree moved into 2 MB pages once built.
                if step == Step::Wide8HugePages {
                    wide = wide.in_huge_pages();
                }
                Built::Wide8(wide, kernel)
            }
            Step::Compressed8Leaf4 => {
                let kernel = if avx2() { Kernel::Avx2 } else { Kernel::Scalar };
                let wide = leaves_of_four(triangles, &merge_leaves(tree));
                Built::Compressed8(wide.map_nodes(CompressedNode::new), kernel)
            }
            Step::Compressed8
            | Step::Compressed8Sweep
            | Step::Compressed8Triangles
            | Step::Compressed8Parallel => {
                let kernel = if avx2() { Kernel::Avx2 } else { Kernel::Scalar };
                let mut wide: Wide<8> = Wide::new(triangles, tree, single);
                if matches!(
                    step,
                    Step::Compressed8Triangles | Step::Compressed8Parallel
                ) {
                    wide = wide.with_lanes();
                }
                Built::Compressed8(wide.map_nodes(CompressedNode::new), kernel)
            }
        };
        FastBvh { built, step }
    }

    /// The same structure, its boxes tested one by one (the fallback a
    /// CPU without SSE or AVX gets): for testing the fallback anywhere.
    pub fn scalar(mut self) -> FastBvh {
        match &mut self.built {
            Built::Binary(_) => {}
            Built::Wide4(_, k) => *k = Kernel::Scalar,
            Built::Wide8(w, k) => {
                *k = Kernel::Scalar;
                w.lane_by_lane();
            }
            Built::Compressed8(w, k) => {
                *k = Kernel::Scalar;
                w.lane_by_lane();
            }
        }
        self
    }

    /// The step it was built for.
    pub fn step(&self) -> Step {
        self.step
    }

    /// How its boxes are tested (scalar for binary trees).
    pub fn kernel(&self) -> Kernel {
        match &self.built {
            Built::Binary(_) => Kernel::Scalar,
            Built::Wide4(_, k)
            | Built::Wide8(_, k)
            | Built::Compressed8(_, k) => *k,
        }
    }

    /// How many nodes deep an 8-wide tree of boxes is (`None` for the
    /// other structures).
    pub fn depth(&self) -> Option<usize> {
        match &self.built {
            Built::Wide8(w, _) => Some(w.depth()),
            _ => None,
        }
    }

    /// Nodes, and the bytes of one node.
    pub fn nodes(&self) -> (usize, usize) {
        match &self.built {
            Built::Binary(b) => (b.node_count(), 32),
            Built::Wide4(w, _) => {
                (w.node_count(), size_of::<crate::WideNode<4>>())
            }
            Built::Wide8(w, _) => {
                (w.node_count(), size_of::<crate::WideNode<8>>())
            }
            Built::Compressed8(w, _) => {
                (w.node_count(), size_of::<CompressedNode>())
            }
        }
    }

    /// Bytes of everything a walk reads.
    pub fn bytes(&self) -> usize {
        match &self.built {
            Built::Binary(b) => b.bytes(),
            Built::Wide4(w, _) => w.bytes(),
            Built::Wide8(w, _) => w.bytes(),
            Built::Compressed8(w, _) => w.bytes(),
        }
    }
}

impl FastBvh {
    /// The closest hit within `interval` (or, `ANY`, the first found),
    /// counted (`nodes`: nodes reached; a wide node counts once for its
    /// `W` boxes): the structure's walk with its kernel.
    fn trace<const ANY: bool>(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        match &self.built {
            Built::Binary(b) => b.trace::<ANY>(ray, interval, counts),
            Built::Wide4(w, Kernel::Scalar) => {
                w.trace::<ANY>(ray, interval, counts, scalar_boxes)
            }
            #[cfg(target_arch = "x86_64")]
            Built::Wide4(w, _) => {
                w.trace::<ANY>(ray, interval, counts, crate::simd4::boxes4)
            }
            Built::Wide8(w, Kernel::Scalar) => {
                w.trace::<ANY>(ray, interval, counts, scalar_boxes)
            }
            #[cfg(target_arch = "x86_64")]
            Built::Wide8(w, Kernel::Avx2 | Kernel::Avx512) => {
                // SAFETY: the kernel is Avx2 only where `avx2()` said so,
                // Avx512 only where `pairs512::available()` did (AVX2
                // with AVX-512).
                unsafe { simd8::trace_avx2::<ANY>(w, ray, interval, counts) }
            }
            #[cfg(target_arch = "x86_64")]
            Built::Wide8(w, Kernel::ShortPath) => {
                // SAFETY: the kernel is ShortPath only where
                // `short_path()` said so.
                unsafe {
                    crate::short_path::trace::<ANY>(w, ray, interval, counts)
                }
            }
            #[cfg(target_arch = "x86_64")]
            Built::Wide8(w, _) => {
                // SAFETY: the kernel is Avx only where `avx()` said so.
                unsafe { simd8::trace::<ANY>(w, ray, interval, counts) }
            }
            Built::Compressed8(w, Kernel::Scalar) => w.trace::<ANY>(
                ray,
                interval,
                counts,
                crate::compressed::scalar_boxes,
            ),
            #[cfg(target_arch = "x86_64")]
            Built::Compressed8(w, _) => {
                // SAFETY: the kernel is Avx2 only where `avx2()` said so.
                unsafe {
                    simd8::trace_compressed::<ANY>(w, ray, interval, counts)
                }
            }
            #[cfg(not(target_arch = "x86_64"))]
            _ => unreachable!("SIMD kernels are chosen on x86-64 only"),
        }
    }
}

impl MeshAccelerator for FastBvh {
    /// The closest hit within `interval`, counted (`nodes`: nodes
    /// reached; a wide node counts once for its `W` boxes).
    fn closest_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        self.trace::<false>(ray, interval, counts)
    }

    /// Does anything meet the ray within `interval`?
    fn any_hit(
        &self, ray: &Ray32, interval: Interval, counts: &mut TraceCounts,
    ) -> bool {
        self.trace::<true>(ray, interval, counts).is_some()
    }
}

/// Step 8's structure: the 8-wide tree of `tree` with its leaves in
/// blocks of four (step 6's leaves if a coordinate is not an `f32`).
fn leaves_of_four(triangles: &[[DVec3; 3]], tree: &Bvh) -> Wide<8> {
    match crate::leaf4::Blocks4::new(triangles, tree) {
        // The blocks hold every triangle: none laid out one by one.
        Some((blocks, links)) => {
            let leaves =
                crate::leaf_triangles::Leaves::for_blocks(triangles, tree);
            Wide::with_leaves(tree, leaves).with_blocks(blocks, &links)
        }
        None => Wide::new(triangles, tree, true).with_lanes(),
    }
}

/// Has this CPU AVX2? (Always no off x86-64.)
fn avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        crate::simd8::available_avx2()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Does step 11's walk take `tree` on this CPU (AVX2, and a tree no
/// deeper than its array allows)?
fn short_path(tree: &Wide<8>) -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        crate::short_path::takes(tree)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let _ = tree;
        false
    }
}

/// Has this CPU AVX? (Always no off x86-64.)
fn avx() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        crate::simd8::available()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

#[cfg(test)]
mod tests {
    use clap::ValueEnum;

    use super::Step;

    /// [`Step::ALL`] is the declaration's order, as clap lists it.
    #[test]
    fn all_is_the_declared_list() {
        assert_eq!(Step::ALL.as_slice(), Step::value_variants());
    }
}
