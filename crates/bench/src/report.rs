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
    /// Ray–triangle tests per ray (NaN, `null` in JSON, for a method
    /// with its own triangle test, which counts nothing).
    pub triangles_per_ray: f64,
    /// Rays whose answer differs from the first method's (as the
    /// method's `agreement` says).
    pub disagreements: usize,
}

/// One method on every ray set.
#[derive(Clone, Debug, Serialize)]
pub struct MethodReport {
    /// `ours: SAH, 16 bins, f32`, `obvhs Bvh2`, ...
    pub method: String,
    /// Our trees only.
    pub ours: bool,
    /// How its answers were checked against the first method's: `exact`
    /// (the same `t`), or `t within 1e-4` (relative) where either tests
    /// triangles its own way (Embree).
    pub agreement: String,
    /// Does it test triangles its own way (and so count none)?
    #[serde(skip)]
    pub own_triangle_test: bool,
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
            agreement: "exact".into(),
            own_triangle_test: method.own_triangle_test(),
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
            report.triangles_per_ray = if self.own_triangle_test {
                f64::NAN
            } else {
                report.counts.triangles as f64 / n
            };
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
    /// Peers asked for that could not run, each with why, e.g. `Embree:
    /// libembree3.so.3 not found (...)`.
    pub skipped: Vec<String>,
}

impl BenchReport {
    /// The table for the terminal: one row per method and set, with the
    /// speed as a ratio to the first method's; a method checked within a
    /// tolerance is marked ≈; the skipped peers below.
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
        let exact = |m: &MethodReport| m.agreement == agreement_name(None);
        let label = |m: &MethodReport| {
            let mark = if exact(m) { "" } else { " ≈" };
            format!("{}{mark}", m.method)
        };
        // the method column as wide as its longest name
        let width = self
            .methods
            .iter()
            .map(|m| label(m).chars().count())
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
                        label(method),
                        format!("{:.1}", method.build_ms),
                        method.bytes.map_or("—".into(), |b| {
                            format!("{:.1}", b as f64 / 1e6)
                        }),
                    )
                } else {
                    (String::new(), String::new(), String::new())
                };
                let tests = if set.triangles_per_ray.is_nan() {
                    "—".into()
                } else {
                    format!("{:.1}", set.triangles_per_ray)
                };
                out += &format!(
                    "{:<width$} {:>9} {:>9} {:<11} {:>9.3} {:>7.2} {:>9} {:>9} {:>8}\n",
                    name,
                    build,
                    bytes,
                    set.set,
                    set.mrays_per_s,
                    ratio,
                    set.nodes_per_ray
                        .map_or("—".into(), |n| format!("{n:.1}")),
                    tests,
                    set.disagreements
                );
            }
        }
        if let Some(m) = self.methods.iter().find(|m| !exact(m)) {
            out += &format!(
                "≈ agrees with the first method if {} (relative): one of \
                 the two tests triangles its own way\n",
                m.agreement
            );
        }
        for why in &self.skipped {
            out += &format!("skipped: {why}\n");
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

/// How a report names a tolerance: `exact`, or `t within 1e-4`.
pub fn agreement_name(tolerance: Option<f32>) -> String {
    match tolerance {
        None => "exact".into(),
        Some(tolerance) => format!("t within {tolerance:e}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rays::Question;

    /// Embree's row is marked and explained, its name unchanged in JSON;
    /// a peer that could not run is listed under the table.
    #[test]
    fn a_tolerance_and_a_skipped_peer_are_shown() {
        let sets = [RaySet {
            name: "primary".into(),
            question: Question::Closest,
            rays: Vec::new(),
        }];
        let mut embree = MethodReport::new(
            &Method::Embree {
                version: 31305,
                robust: false,
                isa: None,
            },
            &sets,
        );
        embree.agreement = agreement_name(Some(1e-4));
        embree.finish(&sets);
        let report = BenchReport {
            mesh: "bunny.obj".into(),
            triangles: 1,
            threads: 1,
            rounds: 1,
            sets: Vec::new(),
            methods: vec![embree],
            skipped: vec!["Embree: why".into()],
        };
        let table = report.table();
        assert!(table.contains("Embree 3.13.5 ≈"), "{table}");
        assert!(table.contains("if t within 1e-4 (relative)"), "{table}");
        assert!(table.contains("\nskipped: Embree: why\n"), "{table}");
        let json = serde_json::to_value(&report).unwrap();
        assert_eq!(json["methods"][0]["method"], "Embree 3.13.5");
        assert_eq!(json["methods"][0]["agreement"], "t within 1e-4");
        assert!(json["methods"][0]["sets"][0]["triangles_per_ray"].is_null());
        assert_eq!(json["skipped"][0], "Embree: why");
    }
}
