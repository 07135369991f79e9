//! What a benchmark compares: our hierarchy (a builder and a node
//! precision), our grid (chapter 9), our kd-tree (chapter 10) and, with
//! the `peers` feature, other libraries' hierarchies (with `embree`,
//! Intel's Embree too) — each built on the same triangles and asked
//! through one trait.
use std::time::Instant;

use ch08::{
    Builder, Bvh, MeshBvh, NodePrecision, PreparedRay, Ray32, TraceCounts,
    TreeStats, triangle_boxes,
};
use ch09::{Fill, MeshGrid, Resolution};
use ch10::{Clip, KdBuilder, KdCosts, MeshKd};
use raystep_core::{DVec3, Interval};

/// A built structure's answers. Hits are `(triangle, t)`, with `t` in
/// `f32` (what the peers report, and the hit file holds).
pub trait Tracer: Sync {
    /// The closest hit within `interval`.
    fn closest(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<(u32, f32)>;
    /// Is anything hit within `interval`?
    fn any(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool;
}

/// One method of the comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method {
    /// Our hierarchy: a builder, and the precision of its nodes.
    Ours(Builder, NodePrecision),
    /// Our uniform grid (chapter 9).
    Grid(GridSpec),
    /// Our kd-tree (chapter 10).
    Kd(KdSpec),
    /// A step of the appendix "how fast can it go".
    Fast(ch11::Step),
    /// obvhs's `Bvh2` (PLOC, reinsertion, leaves collapsed by the SAH;
    /// its `medium_build` preset), walked by its own traversal.
    ObvhsBvh2,
    /// obvhs's compressed 8-wide `CwBvh` (same preset).
    ObvhsCwBvh,
    /// The `bvh` crate (svenstaro): its binned-SAH build and its
    /// traversal iterator.
    BvhCrate,
    /// Intel's Embree 3 (its default, medium-quality build), loaded at
    /// run time: the one method with its own triangle test.
    Embree {
        /// The library's version, MAJOR·10000 + MINOR·100 + PATCH.
        version: u32,
        /// With its robust flag (`RTC_SCENE_FLAG_ROBUST`): no ray through
        /// a crack between triangles, a little slower.
        robust: bool,
    },
}

/// How one of our grids is made and walked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridSpec {
    /// Which cells list a triangle.
    pub fill: Fill,
    /// Cells along the longest axis (`None`: the rule, 3·∛N).
    pub cells: Option<usize>,
    /// Does a ray skip triangles it has already tested?
    pub mailbox: bool,
}

impl GridSpec {
    /// The rule's resolution, filled by `fill`, mailboxing on.
    pub fn rule(fill: Fill) -> GridSpec {
        GridSpec {
            fill,
            cells: None,
            mailbox: true,
        }
    }
}

/// How one of our kd-trees is made and walked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KdSpec {
    /// How it chooses its planes.
    pub builder: KdBuilder,
    /// Which box of a triangle the builder weighs in a node.
    pub clip: Clip,
    /// The SAH's constants.
    pub costs: KdCosts,
    /// Does a ray skip triangles it has already tested?
    pub mailbox: bool,
}

impl KdSpec {
    /// SAH planes from events, the chapter's costs, clipped by `clip`,
    /// mailboxing on.
    pub fn sah(clip: Clip) -> KdSpec {
        KdSpec {
            builder: KdBuilder::SahEvents,
            clip,
            costs: KdCosts::CHOSEN,
            mailbox: true,
        }
    }
}

/// What building gave: the tracer and what it is made of.
pub struct Built {
    /// Asks the structure.
    pub tracer: Box<dyn Tracer>,
    /// Milliseconds from the triangles' boxes to a tracer.
    pub build_ms: f64,
    /// Bytes of nodes and reordered triangles (`None`: not known).
    pub bytes: Option<usize>,
    /// Our trees only: the tree's shape ([`Bvh::stats`]).
    pub tree: Option<TreeStats>,
}

impl Method {
    /// The name tables show, e.g. `ours: SAH, 16 bins, f32`.
    pub fn name(&self) -> String {
        match self {
            Method::Ours(builder, precision) => {
                format!("ours: {}, {}", builder.name(), precision.name())
            }
            Method::Grid(spec) => {
                let cells = match spec.cells {
                    None => "rule".to_string(),
                    Some(n) => format!("{n} cells"),
                };
                let mailbox = if spec.mailbox { "" } else { ", no mailbox" };
                format!("grid: {cells}, {}{mailbox}", spec.fill.name())
            }
            Method::Kd(spec) => {
                let clip = spec.clip.name();
                let mailbox = if spec.mailbox { "" } else { ", no mailbox" };
                let costs = if spec.costs == KdCosts::CHOSEN {
                    String::new()
                } else {
                    format!(", costs {}", spec.costs.name())
                };
                format!(
                    "kd-tree: {}, {clip}{costs}{mailbox}",
                    spec.builder.name()
                )
            }
            Method::Fast(step) => format!("fast: {}", step.name()),
            Method::ObvhsBvh2 => "obvhs Bvh2".into(),
            Method::ObvhsCwBvh => "obvhs CwBvh".into(),
            Method::BvhCrate => "bvh".into(),
            Method::Embree { version, robust } => format!(
                "Embree {}.{}.{}{}",
                version / 10000,
                version / 100 % 100,
                version % 100,
                if *robust { " robust" } else { "" }
            ),
        }
    }

    /// Is this one of ours?
    pub fn is_ours(&self) -> bool {
        matches!(
            self,
            Method::Ours(..)
                | Method::Grid(..)
                | Method::Kd(..)
                | Method::Fast(..)
        )
    }

    /// Does it test triangles its own way, not with the chapter's
    /// watertight test? Then its `t` may differ from ours in the last
    /// bits, and answers are compared within
    /// [`OWN_TEST_TOLERANCE`](crate::OWN_TEST_TOLERANCE).
    pub fn own_triangle_test(&self) -> bool {
        matches!(self, Method::Embree { .. })
    }

    /// The peers this build was compiled with that can run here (none
    /// without the `peers` feature; Embree only where its library loads).
    pub fn peers() -> Vec<Method> {
        let mut peers = Vec::new();
        if cfg!(feature = "peers") {
            peers.extend([
                Method::ObvhsBvh2,
                Method::ObvhsCwBvh,
                Method::BvhCrate,
            ]);
        }
        #[cfg(feature = "embree")]
        if let Ok(version) = crate::embree::probe() {
            peers.push(Method::Embree {
                version,
                robust: false,
            });
            peers.push(Method::Embree {
                version,
                robust: true,
            });
        }
        peers
    }

    /// The peers this build has (the `peers` feature) that cannot run
    /// here, one line each saying why: Embree, where its library does not
    /// load or was not built in.
    pub fn skipped_peers() -> Vec<String> {
        #[cfg(feature = "embree")]
        let why = crate::embree::probe().err();
        #[cfg(not(feature = "embree"))]
        let why = cfg!(feature = "peers").then(|| {
            "this raystep was built without it (`--features embree`)"
                .to_string()
        });
        why.map(|why| format!("Embree: {why}"))
            .into_iter()
            .collect()
    }

    /// Builds the structure over `triangles`, timed.
    pub fn build(&self, triangles: &[[DVec3; 3]]) -> Built {
        match *self {
            Method::Ours(builder, precision) => {
                let start = Instant::now();
                let tree = Bvh::build(&triangle_boxes(triangles), builder);
                let bvh = MeshBvh::new(triangles, &tree, precision);
                let build_ms = start.elapsed().as_secs_f64() * 1e3;
                Built {
                    build_ms,
                    bytes: Some(bvh.bytes()),
                    tree: Some(tree.stats()),
                    tracer: Box::new(Ours(bvh)),
                }
            }
            Method::Grid(spec) => {
                let resolution =
                    spec.cells.map_or(Resolution::Rule, Resolution::Longest);
                let start = Instant::now();
                let mut grid = MeshGrid::new(triangles, resolution, spec.fill);
                grid.grid.mailboxing = spec.mailbox;
                let build_ms = start.elapsed().as_secs_f64() * 1e3;
                Built {
                    build_ms,
                    bytes: Some(grid.bytes()),
                    tree: None,
                    tracer: Box::new(GridTracer(grid)),
                }
            }
            Method::Kd(spec) => {
                let start = Instant::now();
                let mut kd =
                    MeshKd::new(triangles, spec.builder, spec.costs, spec.clip);
                kd.tree.mailboxing = spec.mailbox;
                let build_ms = start.elapsed().as_secs_f64() * 1e3;
                Built {
                    build_ms,
                    bytes: Some(kd.bytes()),
                    tree: None,
                    tracer: Box::new(KdTracer(kd)),
                }
            }
            Method::Fast(step) => {
                let start = Instant::now();
                let fast = ch11::FastBvh::build(triangles, step);
                let build_ms = start.elapsed().as_secs_f64() * 1e3;
                Built {
                    build_ms,
                    bytes: Some(fast.bytes()),
                    tree: None,
                    tracer: Box::new(FastTracer(fast)),
                }
            }
            #[cfg(feature = "embree")]
            Method::Embree { robust, .. } => {
                crate::embree::build(triangles, robust)
            }
            #[cfg(feature = "peers")]
            peer => crate::peers::build(peer, triangles),
            #[cfg(not(feature = "peers"))]
            _ => unreachable!("peers are built with the `peers` feature"),
        }
    }
}

struct Ours(MeshBvh);

impl Tracer for Ours {
    fn closest(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<(u32, f32)> {
        let hit = self.0.closest_hit(ray, interval, counts)?;
        Some((hit.triangle, hit.t as f32))
    }

    fn any(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        self.0.any_hit(ray, interval, counts)
    }
}

/// Chapter 9's grid: `nodes` in the counts are the cells visited.
struct GridTracer(MeshGrid);

impl Tracer for GridTracer {
    fn closest(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<(u32, f32)> {
        let hit = self.0.closest_hit(ray, interval, counts)?;
        Some((hit.triangle, hit.t as f32))
    }

    fn any(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        self.0.any_hit(ray, interval, counts)
    }
}

/// Chapter 10's kd-tree: `nodes` in the counts are the nodes reached.
struct KdTracer(MeshKd);

impl Tracer for KdTracer {
    fn closest(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<(u32, f32)> {
        let hit = self.0.closest_hit(ray, interval, counts)?;
        Some((hit.triangle, hit.t as f32))
    }

    fn any(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        self.0.any_hit(ray, interval, counts)
    }
}

/// A step of the appendix: `nodes` in the counts are the nodes reached
/// (a wide node once for all its boxes).
struct FastTracer(ch11::FastBvh);

impl Tracer for FastTracer {
    fn closest(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<(u32, f32)> {
        let hit = self.0.closest_hit(ray, interval, counts)?;
        Some((hit.triangle, hit.t as f32))
    }

    fn any(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        self.0.any_hit(ray, interval, counts)
    }
}

/// The closest hit among `candidates` (a triangle's index and corners),
/// each tested with the chapter's watertight test, counted.
pub(crate) fn closest_among<'a>(
    ray: &PreparedRay,
    candidates: impl Iterator<Item = (u32, &'a [DVec3; 3])>,
    interval: Interval,
    counts: &mut TraceCounts,
) -> Option<(u32, f32)> {
    let mut interval = interval;
    let mut closest = None;
    for (k, v) in candidates {
        counts.triangles += 1;
        if let Some(t) = ray.triangle(v, interval) {
            interval = interval.with_max(t);
            closest = Some((k, t as f32));
        }
    }
    closest
}

/// Does any of `candidates` meet the ray? Stops at the first, counted.
pub(crate) fn any_among<'a>(
    ray: &PreparedRay,
    mut candidates: impl Iterator<Item = &'a [DVec3; 3]>,
    interval: Interval,
    counts: &mut TraceCounts,
) -> bool {
    candidates.any(|v| {
        counts.triangles += 1;
        ray.triangle(v, interval).is_some()
    })
}

/// Brute force with the chapter's watertight test: every triangle.
pub struct BruteForce<'a>(pub &'a [[DVec3; 3]]);

impl Tracer for BruteForce<'_> {
    fn closest(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> Option<(u32, f32)> {
        if !ray.is_valid() {
            return None;
        }
        let all = self.0.iter().enumerate().map(|(k, v)| (k as u32, v));
        closest_among(&PreparedRay::new(ray), all, interval, counts)
    }

    fn any(
        &self,
        ray: &Ray32,
        interval: Interval,
        counts: &mut TraceCounts,
    ) -> bool {
        ray.is_valid()
            && any_among(
                &PreparedRay::new(ray),
                self.0.iter(),
                interval,
                counts,
            )
    }
}
