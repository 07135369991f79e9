//! The rows of chapter 10's CSV files (written by `raystep measure`, read
//! by the charts and the book): build times, the tree variants on the
//! benchmark's rays, which structure a scene needs, and the stability
//! catalogue.
use raystep_render::csv::{Decimals, Flag, Row, positive};
use serde::{Deserialize, Serialize};

/// One builder on one scene size (`kd-build.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BuildRow {
    /// `median`, `SAH sorting`, `SAH events`, `SAH events perfect`.
    pub builder: String,
    /// Triangles.
    pub triangles: u64,
    /// Milliseconds to build (median of the rounds).
    #[serde(with = "Decimals::<3>")]
    pub build_ms: f64,
    /// Nodes.
    pub nodes: u64,
    /// Entries in the leaves.
    pub entries: u64,
    /// The tree's SAH cost.
    #[serde(with = "Decimals::<2>")]
    pub sah_cost: f64,
}

impl Row for BuildRow {
    fn check(&self) -> Result<(), String> {
        positive(&[self.build_ms, self.triangles as f64], "times and sizes")
    }
}

/// One tree variant on one mesh, on the benchmark's rays (`kd-variants.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VariantRow {
    /// `bunny`, `bunny-235k`, `uniform-10000`.
    pub scene: String,
    /// `SAH W&H boxes`, `SAH W&H perfect`, `SAH pbrt costs`, `SAH W&H
    /// depth 1.3`, `median`.
    pub variant: String,
    /// Milliseconds to build.
    #[serde(with = "Decimals::<3>")]
    pub build_ms: f64,
    /// Bytes of nodes, lists and triangles.
    pub bytes: u64,
    /// Nanoseconds per camera ray, per incoherent ray.
    #[serde(with = "Decimals::<1>")]
    pub primary_ns: f64,
    /// See `primary_ns`.
    #[serde(with = "Decimals::<1>")]
    pub incoherent_ns: f64,
    /// Nodes reached per camera ray, and triangle tests.
    #[serde(with = "Decimals::<2>")]
    pub primary_nodes: f64,
    /// See `primary_nodes`.
    #[serde(with = "Decimals::<2>")]
    pub primary_tests: f64,
    /// Nodes reached per incoherent ray, and triangle tests.
    #[serde(with = "Decimals::<2>")]
    pub incoherent_nodes: f64,
    /// See `incoherent_nodes`.
    #[serde(with = "Decimals::<2>")]
    pub incoherent_tests: f64,
}

impl Row for VariantRow {
    fn check(&self) -> Result<(), String> {
        positive(
            &[self.build_ms, self.primary_ns, self.incoherent_ns],
            "times and sizes",
        )
    }
}

/// One structure on one scene family, on the tracers' own path (objects,
/// double precision): `which-structure.csv`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StructureRow {
    /// The family: `handful`, `slow`, `uniform-10000`, ...
    pub scene: String,
    /// Its objects.
    pub objects: u64,
    /// `brute`, `bvh`, `grid`, `kdtree`.
    pub method: String,
    /// Does chapter 10's rule pick this structure for this scene?
    #[serde(with = "Flag")]
    pub chosen: bool,
    /// Milliseconds to build (0 for brute force).
    #[serde(with = "Decimals::<3>")]
    pub build_ms: f64,
    /// Bytes of the structure (not the objects; 0 for brute force).
    pub bytes: u64,
    /// Nanoseconds per camera ray, per incoherent ray (closest hit).
    #[serde(with = "Decimals::<1>")]
    pub primary_ns: f64,
    /// See `primary_ns`.
    #[serde(with = "Decimals::<1>")]
    pub incoherent_ns: f64,
    /// Answers unlike brute force's, on the rays brute force traced.
    pub disagreements: u64,
}

impl StructureRow {
    /// Milliseconds to build and trace `rays` rays, half camera rays and
    /// half incoherent ones.
    pub fn total_ms(&self, rays: f64) -> f64 {
        self.build_ms
            + rays * 0.5 * (self.primary_ns + self.incoherent_ns) * 1e-6
    }
}

impl Row for StructureRow {
    fn check(&self) -> Result<(), String> {
        positive(&[self.primary_ns, self.incoherent_ns], "times and sizes")
    }
}

/// One kind of dangerous ray on one scene: disagreements with brute force
/// per tree (`kd-stability.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StabilityRow {
    /// The scene.
    pub scene: String,
    /// The kind of ray.
    pub case: String,
    /// How many rays.
    pub rays: u64,
    /// Wrong answers of the SAH tree (chosen costs)...
    pub wrong_sah: u64,
    /// ... of the same without a mailbox...
    pub wrong_no_mailbox: u64,
    /// ... of the median tree...
    pub wrong_median: u64,
    /// ... and of SAH with pbrt's costs.
    pub wrong_sah_pbrt: u64,
}

impl Row for StabilityRow {}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_figure::writes_back;

    /// The committed files read and write back byte for byte: a new
    /// measurement writes their format.
    #[test]
    fn the_committed_csv_files_write_back_unchanged() {
        writes_back::<BuildRow>("ch10", "kd-build.csv").unwrap();
        writes_back::<VariantRow>("ch10", "kd-variants.csv").unwrap();
        writes_back::<StructureRow>("ch10", "which-structure.csv").unwrap();
        writes_back::<StabilityRow>("ch10", "kd-stability.csv").unwrap();
    }
}
