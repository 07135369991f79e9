//! Step 3: the leaves' triangles laid out for the test, and the test
//! made for the walk. Side by side in leaf order (as chapter 8 already
//! has them), and in `f32` when that loses nothing: every corner of a
//! mesh read from an OBJ file is an `f32`, so 36 bytes per triangle hold
//! exactly what chapter 8's 72 do. The test widens them back to `f64`
//! (exactly) and runs chapter 8's watertight test — its common case
//! inlined here, every other case handed to chapter 8's own code: the
//! same answer, bit for bit.
use ch08::{Bvh, MeshHit, PreparedRay, Ray32, Shear, TraceCounts};
use raystep_core::{DVec2, DVec3, Interval};

use crate::ray::FastRay;

/// The triangles of the leaves, in leaf order.
#[derive(Clone, Debug, PartialEq)]
pub enum LeafTriangles {
    /// Corners in `f64` and chapter 8's test, as chapter 8 has them (step
    /// 2).
    Lecture(Vec<[DVec3; 3]>),
    /// Corners in `f64` (some are not `f32`s), the inlined test.
    Double(Vec<[DVec3; 3]>),
    /// Corners in `f32` (each exactly an `f32`), the inlined test.
    Single(Vec<[f32; 9]>),
    /// As `Single`, laid out for step 6's test, three edges at once.
    #[cfg(target_arch = "x86_64")]
    Lanes(Vec<crate::simd_triangle::TriangleLanes>),
}

impl LeafTriangles {
    // ANCHOR: leaf_triangles
    /// `triangles` (in leaf order) as chapter 8 has them, or (`step3`)
    /// in `f32` if every coordinate is exactly an `f32` (else in `f64`)
    /// with the inlined test.
    pub fn new(triangles: Vec<[DVec3; 3]>, step3: bool) -> LeafTriangles {
        if !step3 {
            return LeafTriangles::Lecture(triangles);
        }
        let exact = |x: f64| f64::from(x as f32) == x || x.is_nan();
        let fits = triangles
            .iter()
            .flatten()
            .all(|p| p.to_array().into_iter().all(exact));
        if !fits {
            return LeafTriangles::Double(triangles);
        }
        LeafTriangles::Single(
            triangles
                .iter()
                .map(|[a, b, c]| {
                    let f = |p: &DVec3, i: usize| p[i] as f32;
                    [
                        f(a, 0),
                        f(a, 1),
                        f(a, 2),
                        f(b, 0),
                        f(b, 1),
                        f(b, 2),
                        f(c, 0),
                        f(c, 1),
                        f(c, 2),
                    ]
                })
                .collect(),
        )
    }

    /// Chapter 8's watertight test of triangle `k`: its `t` within
    /// `interval`.
    #[inline(always)]
    pub fn test(
        &self, k: usize, ray: &FastRay, interval: Interval,
    ) -> Option<f64> {
        match self {
            LeafTriangles::Lecture(v) => match &ray.exact {
                Some(exact) => exact.triangle(&v[k], interval),
                None => PreparedRay::new(&ray.ray).triangle(&v[k], interval),
            },
            LeafTriangles::Double(v) => watertight(&v[k], ray, interval),
            LeafTriangles::Single(v) => {
                let v = &v[k];
                let corner = |i: usize| {
                    DVec3::new(
                        f64::from(v[i]),
                        f64::from(v[i + 1]),
                        f64::from(v[i + 2]),
                    )
                };
                let corners = [corner(0), corner(3), corner(6)];
                watertight(&corners, ray, interval)
            }
            #[cfg(target_arch = "x86_64")]
            LeafTriangles::Lanes(v) => {
                crate::simd_triangle::watertight_lanes(&v[k], ray, interval)
            }
        }
    }
    // ANCHOR_END: leaf_triangles

    /// Step 6: `f32` triangles laid out for the test with SIMD, where the
    /// CPU has AVX2 (the same triangles elsewhere).
    pub fn with_lanes(self) -> LeafTriangles {
        #[cfg(target_arch = "x86_64")]
        if let LeafTriangles::Single(v) = &self {
            use crate::simd_triangle::TriangleLanes;
            let lanes = v.iter().map(TriangleLanes::new).collect();
            if let Some(lanes) = lanes {
                return LeafTriangles::Lanes(lanes);
            }
        }
        self
    }

    /// How many triangles.
    pub fn len(&self) -> usize {
        match self {
            LeafTriangles::Lecture(v) | LeafTriangles::Double(v) => v.len(),
            LeafTriangles::Single(v) => v.len(),
            #[cfg(target_arch = "x86_64")]
            LeafTriangles::Lanes(v) => v.len(),
        }
    }

    /// Does the walk prepare chapter 8's test for each ray?
    pub fn lecture(&self) -> bool {
        matches!(self, LeafTriangles::Lecture(_))
    }

    /// No triangles?
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Their bytes.
    pub fn bytes(&self) -> usize {
        match self {
            LeafTriangles::Lecture(v) | LeafTriangles::Double(v) => {
                v.len() * size_of::<[DVec3; 3]>()
            }
            LeafTriangles::Single(v) => v.len() * size_of::<[f32; 9]>(),
            #[cfg(target_arch = "x86_64")]
            LeafTriangles::Lanes(v) => {
                v.len() * size_of::<crate::simd_triangle::TriangleLanes>()
            }
        }
    }
}

// ANCHOR: watertight
/// Chapter 8's watertight test of the triangle `v`, the same arithmetic in
/// the same order, inlined into the walk. Its one slow part, the exact
/// edge function where the fast one is within rounding of 0, is left to
/// chapter 8: a triangle for which that matters (no two edge functions
/// surely of opposite signs, one of them unsure) goes to
/// [`PreparedRay::triangle`] whole.
#[inline(always)]
pub fn watertight(
    v: &[DVec3; 3], ray: &FastRay, interval: Interval,
) -> Option<f64> {
    // Step 1: the corners sheared (chapter 8's steps 1–3).
    let shear = Shear {
        axes: ray.axes,
        shear: ray.shear,
    };
    let [(a, za), (b, zb), (c, zc)] =
        v.map(|vertex| shear.vertex(ray.origin64, vertex));
    // Step 2: the fast edge functions, and whether each sign is sure.
    let edge = |p: DVec2, q: DVec2| {
        let (left, right) = (p.x * q.y, p.y * q.x);
        let fast = left - right;
        let sure = fast.abs() > 2.0 * f64::EPSILON * (left.abs() + right.abs());
        (fast, sure)
    };
    let [(e0, s0), (e1, s1), (e2, s2)] = [edge(b, c), edge(c, a), edge(a, b)];
    // Step 3: two sure signs that differ: outside, whatever the third.
    let positive = (s0 && e0 > 0.0) || (s1 && e1 > 0.0) || (s2 && e2 > 0.0);
    let negative = (s0 && e0 < 0.0) || (s1 && e1 < 0.0) || (s2 && e2 < 0.0);
    if positive && negative {
        return None;
    }
    if !(s0 && s1 && s2) {
        // Step 4: an unsure sign: chapter 8's exact test decides.
        return PreparedRay::new(&ray.ray).triangle(v, interval);
    }
    // Step 5: all three sure and of one sign (none is 0): t, as chapter
    // 8 computes it, and no hit where det is within rounding of 0 (a ray
    // in the triangle's plane).
    let sheared = [(a, za), (b, zb), (c, zc)];
    let (det, noise) = (e0 + e1 + e2, shear.det_rounding(&sheared));
    if !det.is_finite() || det.abs() <= noise {
        return None;
    }
    let t = (e0 * za + e1 * zb + e2 * zc) / det;
    interval.contains(t).then_some(t)
}
// ANCHOR_END: watertight

/// What a fast walk reads besides its nodes: the leaves' triangles side
/// by side in leaf order, each one's index in the mesh, and the triangles
/// kept outside the tree.
#[derive(Clone, Debug, PartialEq)]
pub struct Leaves {
    /// The triangles in leaf order.
    pub triangles: LeafTriangles,
    /// Each one's index in the mesh.
    pub ids: Vec<u32>,
    /// Triangles with no finite box, tested by every ray first.
    pub outside: Outside,
    /// Step 8: the leaves in blocks of four, which the leaves' links
    /// then name (`(first block, blocks)`), if built.
    pub blocks: Option<crate::leaf4::Blocks4>,
}

impl Leaves {
    /// The leaves of `tree` (built over `triangles`' boxes), in `f32` if
    /// `single` (and exact).
    pub fn new(triangles: &[[DVec3; 3]], tree: &Bvh, single: bool) -> Leaves {
        let ordered = tree.order.iter().map(|&i| triangles[i as usize]);
        Leaves {
            triangles: LeafTriangles::new(ordered.collect(), single),
            ids: tree.order.clone(),
            outside: Outside::new(triangles, &tree.unbounded),
            blocks: None,
        }
    }

    /// Step 8's leaves before their blocks: no triangle laid out one by
    /// one (the blocks will hold them all), only those outside the tree.
    pub fn for_blocks(triangles: &[[DVec3; 3]], tree: &Bvh) -> Leaves {
        Leaves {
            triangles: LeafTriangles::Single(Vec::new()),
            ids: Vec::new(),
            outside: Outside::new(triangles, &tree.unbounded),
            blocks: None,
        }
    }

    /// Step 6: the same triangles laid out for the test with SIMD
    /// ([`LeafTriangles::with_lanes`]).
    pub fn with_lanes(self) -> Leaves {
        Leaves {
            triangles: self.triangles.with_lanes(),
            ..self
        }
    }

    /// `ray` ready for the walk (`None`: a ray not traced).
    #[inline(always)]
    pub fn ray(&self, ray: &Ray32) -> Option<FastRay> {
        FastRay::new(ray, self.triangles.lecture())
    }

    /// Bytes of the triangles, their indices and those outside (of the
    /// blocks instead, if built).
    pub fn bytes(&self) -> usize {
        match &self.blocks {
            Some(blocks) => blocks.bytes() + self.outside.bytes(),
            None => {
                self.triangles.bytes()
                    + self.ids.len() * size_of::<u32>()
                    + self.outside.bytes()
            }
        }
    }

    /// A leaf of the walks: its `count` triangles from `first`, each
    /// tested within `interval`, which every hit shortens; the closest
    /// hit (or, `any`, the first) as the mesh's triangle.
    #[inline(always)]
    pub fn leaf(
        &self, (first, count): (u32, u32), ray: &FastRay,
        interval: &mut Interval, any: bool, counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        if let Some(blocks) = &self.blocks {
            // Step 10: two blocks at once, where built so.
            #[cfg(target_arch = "x86_64")]
            if blocks.pairs() {
                // SAFETY: the blocks are paired only where the CPU has
                // AVX-512F (`Wide::in_pairs`).
                return unsafe {
                    crate::pairs512::leaf(
                        blocks,
                        (first, count),
                        ray,
                        interval,
                        any,
                        counts,
                    )
                };
            }
            return blocks.leaf((first, count), ray, interval, any, counts);
        }
        let mut closest = None;
        for j in first as usize..(first + count) as usize {
            counts.triangles += 1;
            if let Some(t) = self.triangles.test(j, ray, *interval) {
                *interval = interval.with_max(t);
                closest = Some(MeshHit {
                    triangle: self.ids[j],
                    t,
                });
                if any {
                    break;
                }
            }
        }
        closest
    }
}

/// The triangles kept outside a tree (no finite box: a corner at ±∞ or
/// NaN), with their indices in the mesh; every ray tests them first.
/// None in a finite mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outside(pub Vec<(u32, [DVec3; 3])>);

impl Outside {
    /// The mesh's triangles numbered `ids`.
    pub fn new(triangles: &[[DVec3; 3]], ids: &[u32]) -> Outside {
        Outside(ids.iter().map(|&k| (k, triangles[k as usize])).collect())
    }

    /// Step 1 of every walk: the closest of them within `interval` (or,
    /// `any`, the first), counted.
    #[inline(always)]
    pub fn closest(
        &self, ray: &FastRay, interval: &mut Interval, any: bool,
        counts: &mut TraceCounts,
    ) -> Option<MeshHit> {
        let mut closest = None;
        for (id, v) in &self.0 {
            counts.triangles += 1;
            if let Some(t) = watertight(v, ray, *interval) {
                *interval = interval.with_max(t);
                closest = Some(MeshHit { triangle: *id, t });
                if any {
                    break;
                }
            }
        }
        closest
    }

    /// Their bytes.
    pub fn bytes(&self) -> usize {
        self.0.len() * size_of::<(u32, [DVec3; 3])>()
    }
}
