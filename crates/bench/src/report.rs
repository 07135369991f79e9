//! What a benchmark reports: per method and ray set, speed (median of the
//! rounds), the work per ray that explains it, and disagreements; as a
//! table for the terminal and as JSON.
use ch08::{TraceCounts, TreeStats};
use serde::Serialize;

use crate::methods::Method;
use crate::rays::{Question, RaySet};

/// One method on one ray set.
#[derive(Clone, Debug, Serialize)]
pub struct SetReport {
    /// The set's name.
    pub set: String,
    /// Millions of rays per second (the median of the rounds).
    pub mrays_per_s: f64,
    /// The work of all the set's rays (node visits are 0 for the peers,
    /// which do not count them).
    #[serde(skip)]
    pub counts: TraceCounts,
    /// Node visits per ray.
    pub nodes_per_ray: Option<f64>,
    /// Ray–triangle tests per ray.
    pub triangles_per_ray: f64,
    /// Rays whose answer differs from the first method's.
    pub disagreements: usize,
}

/// One method on every ray set.
#[derive(Clone, Debug, Serialize)]
pub struct MethodReport {
    /// `ours: SAH, 16 bins, f32`, `obvhs Bvh2`, ...
    pub method: String,
    /// Our trees only.
    pub ours: bool,
    /// Milliseconds to build (the median of the rounds).
    pub build_ms: f64,
    /// Bytes of nodes and triangles, where known.
    pub bytes: Option<usize>,
    /// Our trees: the tree's shape.
    #[serde(skip)]
    pub tree: Option<TreeStats>,
    /// Our trees: the SAH cost.
    pub sah_cost: Option<f64>,
    /// Our trees: the node count.
    pub nodes: Option<usize>,
    /// Our trees: the depth.
    pub depth: Option<usize>,
    /// Our trees: the leaves' mean depth over a balanced tree's
    /// ([`TreeStats::balance`]).
    pub balance: Option<f64>,
    /// Our trees: the mean objects per leaf.
    pub mean_leaf: Option<f64>,
    /// One entry per ray set.
    pub sets: Vec<SetReport>,
}

impl MethodReport {
    /// An empty report for `method` over `sets`.
    pub fn new(method: &Method, sets: &[RaySet]) -> MethodReport {
        MethodReport {
            method: method.name(),
            ours: method.is_ours(),
            build_ms: f64::NAN,
            bytes: None,
            tree: None,
            sah_cost: None,
            nodes: None,
            depth: None,
            balance: None,
            mean_leaf: None,
            sets: sets
                .iter()
                .map(|set| SetReport {
                    set: set.name.clone(),
                    mrays_per_s: f64::NAN,
                    counts: TraceCounts::default(),
                    nodes_per_ray: None,
                    triangles_per_ray: f64::NAN,
                    disagreements: 0,
                })
                .collect(),
        }
    }

    /// Fills the per-ray columns from the counts.
    pub fn finish(&mut self, sets: &[RaySet]) {
        if let Some(tree) = self.tree {
            self.sah_cost = Some(tree.sah_cost);
            self.nodes = Some(tree.nodes);
            self.depth = Some(tree.depth);
            self.balance = Some(tree.balance);
            self.mean_leaf = Some(tree.mean_leaf);
        }
        for (report, set) in self.sets.iter_mut().zip(sets) {
            let n = set.rays.len().max(1) as f64;
            report.triangles_per_ray = report.counts.triangles as f64 / n;
            report.nodes_per_ray =
                self.ours.then(|| report.counts.nodes as f64 / n);
        }
    }
}

/// A ray set as the report lists it.
#[derive(Clone, Debug, Serialize)]
pub struct SetInfo {
    /// Its name.
    pub name: String,
    /// How many rays.
    pub rays: usize,
    /// Closest hit or any hit.
    pub question: Question,
    /// Rays checked against brute force, and how many of the first
    /// method's answers differed.
    pub brute_force_checked: usize,
    /// See `brute_force_checked`.
    pub brute_force_disagreements: usize,
}

/// The whole benchmark.
#[derive(Clone, Debug, Serialize)]
pub struct BenchReport {
    /// The mesh file.
    pub mesh: String,
    /// Its triangles.
    pub triangles: usize,
    /// Threads tracing (and building, where a method can).
    pub threads: usize,
    /// Rounds; times are medians over them.
    pub rounds: usize,
    /// The ray sets.
    pub sets: Vec<SetInfo>,
    /// One entry per method; the first is the reference.
    pub methods: Vec<MethodReport>,
}

impl BenchReport {
    /// The table for the terminal: one row per method and set, with the
    /// speed as a ratio to the first method's.
    pub fn table(&self) -> String {
        let mut out = format!(
            "{}: {} triangles, {} thread(s), median of {} round(s)\n",
            self.mesh, self.triangles, self.threads, self.rounds
        );
        for set in &self.sets {
            out += &format!(
                "  {} rays: {} ({:?} hit); brute force checked {} of them, \
                 {} disagreements\n",
                set.name,
                set.rays,
                set.question,
                set.brute_force_checked,
                set.brute_force_disagreements
            );
        }
        // the method column as wide as its longest name
        let width = self
            .methods
            .iter()
            .map(|m| m.method.chars().count())
            .fold(30, usize::max);
        out += &format!(
            "\n{:<width$} {:>9} {:>9} {:<11} {:>9} {:>7} {:>9} {:>9} {:>8}\n",
            "method",
            "build ms",
            "MB",
            "rays",
            "Mrays/s",
            "× first",
            "nodes/ray",
            "tris/ray",
            "disagree"
        );
        let first = self.methods.first();
        for method in &self.methods {
            for (s, set) in method.sets.iter().enumerate() {
                let ratio = first.map_or(f64::NAN, |f| {
                    set.mrays_per_s / f.sets[s].mrays_per_s
                });
                let (name, build, bytes) = if s == 0 {
                    (
                        method.method.clone(),
                        format!("{:.1}", method.build_ms),
                        method.bytes.map_or("—".into(), |b| {
                            format!("{:.1}", b as f64 / 1e6)
                        }),
                    )
                } else {
                    (String::new(), String::new(), String::new())
                };
                out += &format!(
                    "{:<width$} {:>9} {:>9} {:<11} {:>9.3} {:>7.2} {:>9} {:>9.1} {:>8}\n",
                    name,
                    build,
                    bytes,
                    set.set,
                    set.mrays_per_s,
                    ratio,
                    set.nodes_per_ray
                        .map_or("—".into(), |n| format!("{n:.1}")),
                    set.triangles_per_ray,
                    set.disagreements
                );
            }
        }
        for method in &self.methods {
            if let Some(tree) = method.tree {
                out += &format!(
                    "{}: SAH cost {:.1}, {} nodes, depth {}, balance {:.3}, \
                     {:.2} per leaf\n",
                    method.method,
                    tree.sah_cost,
                    tree.nodes,
                    tree.depth,
                    tree.balance,
                    tree.mean_leaf,
                );
            }
        }
        out
    }
}
