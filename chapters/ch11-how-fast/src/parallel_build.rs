//! Step 7: the tree built on several threads.
//!
//! Chapter 8's builder runs on one thread. Here the top of the tree is
//! split with the same binned SAH, each set's objects binned in chunks on
//! the threads of the current rayon pool and the two halves split side
//! by side (`rayon::join`); a set small enough (a *part*) is handed to
//! chapter 8's builder whole, the parts built side by side too, and the
//! parts' trees are stitched under the top. The result is a [`Bvh`] with
//! chapter 8's layout, the same whatever the number of threads: each
//! join's halves and each part keep their place, and the chunks' bins
//! are merged in chunk order.
//!
//! The top copies chapter 8's binned split exactly (the same `f32` boxes
//! around the middle of the scene, the same cuts, the same partition),
//! so its nodes are the ones chapter 8 makes; inside a part, chapter 8
//! rounds the boxes around the part's own middle, which moves a few
//! cuts. A part is a set of at most max(4096, n / 32) objects: 32 parts
//! or more share out well on any number of threads, and parts of 2048
//! or 16 384 objects measured the same within the noise.
//!
//! On the 235 136-triangle bunny, binned SAH with 16 bins (measured on a
//! 2-core machine, medians of 31 rounds, taking turns):
//!
//! | build                   | time   | × ch. 8 | SAH cost  |
//! |-------------------------|--------|---------|-----------|
//! | chapter 8, one thread   | 180 ms | 1       | 36.537575 |
//! | parallel, 1-thread pool | 193 ms | 1.07    | 36.537643 |
//! | parallel, 2-thread pool | 103 ms | 0.57    | 36.537643 |
//!
//! The machine is noisy: between runs the sequential median moved from
//! 162 to 198 ms, and the median of each round's ratio from 1.03 to
//! 1.07 (one thread) and 0.57 to 0.59 (two). One thread pays for what
//! the top adds (its own copy of the boxes, each part's boxes gathered,
//! the stitching); two split the parts between them, but the first
//! split's partition, step 1 and the stitching stay on one thread.
use ch08::{Builder, Bvh, BvhNode, MAX_LEAF};
use rayon::prelude::*;
use raystep_core::glam::{Vec3, Vec3A};
use raystep_core::{Aabb, DVec3};

/// The least size of [`build_parallel`]'s parts: a smaller part is not
/// worth a split of the top (parts of 2048 objects gained nothing).
pub const MIN_PART: usize = 4096;

/// How many objects are binned together on one thread.
const CHUNK: usize = 4096;

/// The deepest the top goes: a scene that the SAH peels one object at a
/// time would otherwise recurse once per object; below it chapter 8's
/// builder (which keeps its own stack) takes over.
const MAX_TOP_DEPTH: usize = 32;

// ANCHOR: build_parallel
/// Chapter 8's binned SAH tree (`bins` slices per axis), built on the
/// threads of the current rayon pool.
pub fn build_parallel(boxes: &[Aabb], bins: usize) -> Bvh {
    let part = (boxes.len() / 32).max(MIN_PART);
    build_parallel_with(boxes, bins, part)
}
// ANCHOR_END: build_parallel

/// [`build_parallel`], its parts at most `part` objects (never fewer
/// than [`MAX_LEAF`](ch08::MAX_LEAF): above it chapter 8 always splits).
pub fn build_parallel_with(boxes: &[Aabb], bins: usize, part: usize) -> Bvh {
    // Step 1: objects with a finite box go into the tree, the rest
    // (planes, empty boxes) are asked by every ray, as in chapter 8.
    let (order, unbounded): (Vec<u32>, Vec<u32>) = (0..boxes.len() as u32)
        .partition(|&i| {
            let b = boxes[i as usize];
            b.min.is_finite() && b.max.is_finite() && !b.is_empty()
        });
    if order.is_empty() {
        return Bvh {
            nodes: Vec::new(),
            order,
            unbounded,
        };
    }
    // Step 2: the top, split on the pool's threads; step 3, inside it:
    // each part built by chapter 8.
    let mut items = items(boxes, &order);
    let centroids = in_chunks(&items, |chunk| {
        chunk
            .iter()
            .fold(Box32::EMPTY, |c, i| c.grow(i.centroid2()))
    })
    .into_iter()
    .fold(Box32::EMPTY, Box32::union);
    let plan = Plan {
        boxes,
        bins,
        part: part.max(MAX_LEAF),
    };
    let top = split_top(&mut items, centroids, &plan, 0);
    // Step 4: the top's nodes and the parts' trees in one array, its
    // size known beforehand (growing it would copy it again and again).
    let mut nodes = Vec::with_capacity(top.nodes());
    nodes.push(PLACEHOLDER);
    let mut tree = Bvh {
        nodes,
        order: Vec::with_capacity(items.len()),
        unbounded,
    };
    stitch(top, 0, &mut tree);
    tree
}

/// What every set of the top is split with.
struct Plan<'a> {
    boxes: &'a [Aabb],
    bins: usize,
    part: usize,
}

/// The top of the tree: two halves, or a part built by chapter 8 (its
/// `order` already the objects' indices in the whole list).
enum Top {
    Split(Box<[Top; 2]>),
    Part(Bvh),
}

impl Top {
    /// How many nodes it has.
    fn nodes(&self) -> usize {
        match self {
            Top::Split(halves) => 1 + halves[0].nodes() + halves[1].nodes(),
            Top::Part(tree) => tree.nodes.len(),
        }
    }
}

/// A node whose box and links are written later.
const PLACEHOLDER: BvhNode = BvhNode {
    bounds: Aabb::EMPTY,
    first: 0,
    count: 0,
};

// ANCHOR: split_top
/// Splits `items` (whose centroids' box is `centroids`) in two, the
/// halves on two threads, down to the parts.
fn split_top(
    items: &mut [Item], centroids: Box32, plan: &Plan, depth: usize,
) -> Top {
    if items.len() <= plan.part || depth == MAX_TOP_DEPTH {
        return part(items, plan);
    }
    let Some((left, [lc, rc])) = split(items, &centroids, plan.bins) else {
        return part(items, plan); // all centroids in one place
    };
    let (l, r) = items.split_at_mut(left);
    let (l, r) = rayon::join(
        || split_top(l, lc, plan, depth + 1),
        || split_top(r, rc, plan, depth + 1),
    );
    Top::Split(Box::new([l, r]))
}

/// Step 3: chapter 8's tree over the part's own boxes, its order turned
/// back into the objects' indices.
fn part(items: &[Item], plan: &Plan) -> Top {
    let boxes: Vec<Aabb> = items
        .iter()
        .map(|item| plan.boxes[item.index as usize])
        .collect();
    let mut tree = Bvh::build(&boxes, Builder::BinnedSah { bins: plan.bins });
    debug_assert!(tree.unbounded.is_empty());
    for i in &mut tree.order {
        *i = items[*i as usize].index;
    }
    Top::Part(tree)
}
// ANCHOR_END: split_top

// ANCHOR: stitch
/// Writes `top` into `tree`, its root at node `slot` (a placeholder
/// already there): a split's two children side by side at the end, a
/// part's root at `slot` and its other nodes at the end, their links
/// shifted (a leaf's by where its objects now start in `order`).
fn stitch(top: Top, slot: usize, tree: &mut Bvh) {
    match top {
        Top::Split(halves) => {
            let first = tree.nodes.len();
            tree.nodes.extend([PLACEHOLDER; 2]);
            let [l, r] = *halves;
            stitch(l, first, tree);
            stitch(r, first + 1, tree);
            let (a, b) =
                (tree.nodes[first].bounds, tree.nodes[first + 1].bounds);
            tree.nodes[slot] = BvhNode {
                bounds: a.union(b),
                first: first as u32,
                count: 0,
            };
        }
        Top::Part(part) => {
            // The part's node k ≥ 1 goes to `base + k`, its objects to
            // the end of `order`.
            let base = (tree.nodes.len() - 1) as u32;
            let objects = tree.order.len() as u32;
            let mut nodes = part.nodes.into_iter().map(|node| BvhNode {
                first: node.first + if node.is_leaf() { objects } else { base },
                ..node
            });
            tree.nodes[slot] = nodes.next().expect("a part has a root");
            tree.nodes.extend(nodes);
            tree.order.extend(part.order);
        }
    }
}
// ANCHOR_END: stitch

/// `f` on each chunk of `items`, on the pool's threads; the answers in
/// chunk order (so that merging them never depends on the threads).
fn in_chunks<T: Send>(
    items: &[Item], f: impl Fn(&[Item]) -> T + Sync + Send,
) -> Vec<T> {
    items.par_chunks(CHUNK).map(f).collect()
}

/// One object as the top moves it (chapter 8's builder's own copy): its
/// box in `f32` around the middle of the scene, and its index.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
struct Item {
    min: Vec3,
    index: u32,
    max: Vec3,
}

impl Item {
    /// Twice the centroid (the halving changes no comparison).
    fn centroid2(&self) -> Vec3A {
        Vec3A::from(self.min) + Vec3A::from(self.max)
    }

    /// Its box.
    fn bounds(&self) -> Box32 {
        Box32 {
            min: self.min.into(),
            max: self.max.into(),
        }
    }
}

/// The objects `order`'s boxes in `f32` around the middle of their
/// union, as chapter 8's builder makes them, on the pool's threads.
fn items(boxes: &[Aabb], order: &[u32]) -> Vec<Item> {
    let all = order
        .par_chunks(CHUNK)
        .map(|chunk| {
            let boxes = chunk.iter().map(|&i| boxes[i as usize]);
            boxes.fold(Aabb::EMPTY, Aabb::union)
        })
        .collect::<Vec<Aabb>>()
        .into_iter()
        .fold(Aabb::EMPTY, Aabb::union);
    let middle: DVec3 = 0.5 * all.min + 0.5 * all.max;
    order
        .par_iter()
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

/// A box in `f32`, for choosing splits only.
#[derive(Clone, Copy, Debug)]
struct Box32 {
    min: Vec3A,
    max: Vec3A,
}

impl Box32 {
    const EMPTY: Box32 = Box32 {
        min: Vec3A::INFINITY,
        max: Vec3A::NEG_INFINITY,
    };

    /// The smallest box around both.
    fn union(self, other: Box32) -> Box32 {
        Box32 {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The box grown to contain `p`.
    fn grow(self, p: Vec3A) -> Box32 {
        Box32 {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The surface area, 0 for an empty box.
    fn area(&self) -> f32 {
        let d = (self.max - self.min).max(Vec3A::ZERO);
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }
}

/// One slice of the centroids' box on one axis: how many centroids fall
/// in it, and the box around their objects.
#[derive(Clone, Copy, Debug)]
struct Bin {
    bounds: Box32,
    count: u32,
}

impl Bin {
    const EMPTY: Bin = Bin {
        bounds: Box32::EMPTY,
        count: 0,
    };

    /// Both bins' objects in one.
    fn union(self, other: Bin) -> Bin {
        Bin {
            bounds: self.bounds.union(other.bounds),
            count: self.count + other.count,
        }
    }
}

/// `count` equal slices of a centroids' box on each axis.
struct Slices {
    min: Vec3A,
    scale: Vec3A,
    last: Vec3A,
    count: usize,
}

impl Slices {
    /// Each axis's slice of `item`'s centroid (chapter 8's arithmetic).
    fn of(&self, item: &Item) -> [usize; 3] {
        let b = ((item.centroid2() - self.min) * self.scale)
            .clamp(Vec3A::ZERO, self.last)
            .as_ivec3();
        [b.x as usize, b.y as usize, b.z as usize]
    }

    /// The bins of `items`: axis `a`'s slice `k` at `a * count + k`.
    fn bin(&self, items: &[Item]) -> Vec<Bin> {
        let mut bins = vec![Bin::EMPTY; 3 * self.count];
        for item in items {
            let bounds = item.bounds();
            for (axis, k) in self.of(item).into_iter().enumerate() {
                let bin = &mut bins[axis * self.count + k];
                bin.bounds = bin.bounds.union(bounds);
                bin.count += 1;
            }
        }
        bins
    }
}

// ANCHOR: split
/// Chapter 8's binned SAH split of `items` (centroids' box `c`, `count`
/// slices per axis), the binning on the pool's threads: the objects
/// reordered, how many go left, and the two sides' centroids' boxes.
/// None if no cut leaves objects on both sides.
fn split(
    items: &mut [Item], c: &Box32, count: usize,
) -> Option<(usize, [Box32; 2])> {
    let count = count.min(items.len()).max(2);
    let extent = c.max - c.min;
    let slices = Slices {
        min: c.min,
        scale: Vec3A::select(
            extent.cmpgt(Vec3A::ZERO),
            count as f32 / extent,
            Vec3A::ZERO,
        ),
        last: Vec3A::splat((count - 1) as f32),
        count,
    };
    // Step 1: each chunk's bins on a thread, merged in chunk order.
    let bins = in_chunks(items, |chunk| slices.bin(chunk))
        .into_iter()
        .reduce(|a, b| a.iter().zip(&b).map(|(x, y)| x.union(*y)).collect())?;
    // Step 2: on each axis, the cost of cutting after each bin, swept
    // from the right, then from the left; the cheapest cut.
    let n = items.len() as u32;
    let mut best: Option<(f32, usize, usize)> = None;
    let mut right = vec![Box32::EMPTY; count];
    for axis in 0..3 {
        if extent[axis] <= 0.0 {
            continue;
        }
        let bins = &bins[axis * count..(axis + 1) * count];
        let mut b = Box32::EMPTY;
        for k in (1..count).rev() {
            b = b.union(bins[k].bounds);
            right[k - 1] = b;
        }
        let (mut left, mut b) = (0, Box32::EMPTY);
        for cut in 0..count - 1 {
            left += bins[cut].count;
            b = b.union(bins[cut].bounds);
            if left == 0 || left == n {
                continue;
            }
            let cost =
                b.area() * left as f32 + right[cut].area() * (n - left) as f32;
            if best.is_none_or(|(c, ..)| cost < c) {
                best = Some((cost, axis, cut));
            }
        }
    }
    let (_, axis, cut) = best?;
    // Step 3: the partition, which measures the centroids on the way.
    let (mut lc, mut rc) = (Box32::EMPTY, Box32::EMPTY);
    let (mut i, mut j) = (0, items.len());
    while i < j {
        let centroid = items[i].centroid2();
        if slices.of(&items[i])[axis] <= cut {
            lc = lc.grow(centroid);
            i += 1;
        } else {
            rc = rc.grow(centroid);
            j -= 1;
            items.swap(i, j);
        }
    }
    Some((i, [lc, rc]))
}
// ANCHOR_END: split
