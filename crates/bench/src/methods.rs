//! What a benchmark compares: our hierarchy (a builder and a node
//! precision), our grid (chapter 9), our kd-tree (chapter 10), the steps
//! of chapter 11 and, with the `peers` feature, other libraries'
//! hierarchies (with `embree`, Intel's Embree too) — each built on the
//! same triangles and asked through the mesh seam,
//! [`MeshAccelerator`](raystep_world::MeshAccelerator).
use std::time::Instant;

use ch08::{Builder, Bvh, MeshBvh, NodePrecision, triangle_boxes};
use ch09::{Fill, MeshGrid, Resolution};
use ch10::{Clip, KdBuilder, KdCosts, MeshKd};
use raystep_core::DVec3;

use crate::built::Built;
use crate::embree_isa::EmbreeIsa;

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
        /// The instruction set its kernels were told to use
        /// (`--embree-isa`), or `None`: the best this CPU has, its default.
        isa: Option<EmbreeIsa>,
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
            Method::Embree {
                version,
                robust,
                isa,
            } => format!(
                "Embree {}.{}.{}{}{}",
                version / 10000,
                version / 100 % 100,
                version % 100,
                if *robust { " robust" } else { "" },
                isa.map_or(String::new(), |isa| format!(" {}", isa.name()))
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
    /// With `isa`, Embree's default build a third time, its kernels kept
    /// to that instruction set.
    pub fn peers(isa: Option<EmbreeIsa>) -> Vec<Method> {
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
                isa: None,
            });
            peers.push(Method::Embree {
                version,
                robust: true,
                isa: None,
            });
            if isa.is_some() {
                peers.push(Method::Embree {
                    version,
                    robust: false,
                    isa,
                });
            }
        }
        #[cfg(not(feature = "embree"))]
        let _ = isa;
        peers
    }

    /// Of `peers`, Embree in its default mode only (with `--embree-isa`,
    /// also its row kept to that instruction set): `raystep bench
    /// --embree-alone`.
    pub fn embree_alone(peers: Vec<Method>) -> Vec<Method> {
        peers
            .into_iter()
            .filter(|m| matches!(m, Method::Embree { robust: false, .. }))
            .collect()
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
                    tracer: Box::new(bvh),
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
                    tracer: Box::new(grid),
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
                    tracer: Box::new(kd),
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
                    tracer: Box::new(fast),
                }
            }
            #[cfg(feature = "embree")]
            Method::Embree { robust, isa, .. } => {
                crate::embree::build(triangles, robust, isa)
            }
            #[cfg(feature = "peers")]
            Method::ObvhsBvh2 => crate::peers::obvhs_bvh2(triangles),
            #[cfg(feature = "peers")]
            Method::ObvhsCwBvh => crate::peers::obvhs_cwbvh(triangles),
            #[cfg(feature = "peers")]
            Method::BvhCrate => crate::peers::bvh_crate(triangles),
            #[allow(unreachable_patterns)] // with `peers` and `embree` on
            _ => unreachable!("a peer is built only with its feature"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Embree's rows are told apart by their names: the robust one, and
    /// the one kept to an instruction set (`--embree-isa`).
    #[test]
    fn embree_rows_are_named_by_flag_and_instruction_set() {
        let embree = |robust, isa| Method::Embree {
            version: 31305,
            robust,
            isa,
        };
        assert_eq!(embree(false, None).name(), "Embree 3.13.5");
        assert_eq!(embree(true, None).name(), "Embree 3.13.5 robust");
        assert_eq!(
            embree(false, Some(EmbreeIsa::Avx2)).name(),
            "Embree 3.13.5 avx2"
        );
        assert_eq!(EmbreeIsa::Sse42.name(), "sse4.2");
    }

    #[test]
    fn embree_alone_keeps_its_default_mode_only() {
        let embree = |robust, isa| Method::Embree {
            version: 31305,
            robust,
            isa,
        };
        let peers = vec![
            Method::ObvhsBvh2,
            Method::ObvhsCwBvh,
            Method::BvhCrate,
            embree(false, None),
            embree(true, None),
            embree(false, Some(EmbreeIsa::Avx2)),
        ];
        assert_eq!(
            Method::embree_alone(peers),
            vec![embree(false, None), embree(false, Some(EmbreeIsa::Avx2))]
        );
    }
}
