//! The rows of `instances.csv` (written by `raystep measure`, read by the
//! instances chart): a field of bunnies flattened into one hierarchy, or
//! instanced through two levels.
use raystep_render::csv::{Decimals, Row, positive};
use serde::{Deserialize, Serialize};

/// The two ways of [`InstanceRow::way`]: every triangle of every bunny
/// copied into the world, one hierarchy over all of them...
pub const FLATTENED: &str = "flattened";
/// ... or one hierarchy over the bunny's triangles, shared, and one over
/// the instances.
pub const INSTANCED: &str = "instanced";

/// One field of bunnies built one way: its structure (counted) and its
/// build and trace times (measured, one thread, medians of the rounds).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct InstanceRow {
    /// Bunnies in the field.
    pub bunnies: u64,
    /// [`FLATTENED`] or [`INSTANCED`].
    pub way: String,
    /// The world's objects: one per triangle, or one per bunny.
    pub objects: u64,
    /// Nodes of every hierarchy built (the top one, and the bunny's own).
    pub nodes: u64,
    /// Bytes of the objects: each world object, the shape it points to,
    /// and (instanced) the bunny's own triangles and normals, once.
    pub object_bytes: u64,
    /// Bytes of the hierarchies: their nodes and object indices.
    pub node_bytes: u64,
    /// Milliseconds from the scene in memory to a world ready to trace.
    #[serde(with = "Decimals::<3>")]
    pub build_ms: f64,
    /// Camera rays traced (closest hit).
    pub rays: u64,
    /// Of them, rays that hit a bunny.
    pub hits: u64,
    /// Nanoseconds per camera ray.
    #[serde(with = "Decimals::<1>")]
    pub trace_ns: f64,
}

impl InstanceRow {
    /// Everything the structure holds, in bytes.
    pub fn bytes(&self) -> u64 {
        self.object_bytes + self.node_bytes
    }
}

impl Row for InstanceRow {
    fn check(&self) -> Result<(), String> {
        if self.way != FLATTENED && self.way != INSTANCED {
            return Err(format!("unknown way `{}`", self.way));
        }
        if self.bunnies == 0 || self.rays == 0 || self.hits > self.rays {
            return Err("expected bunnies, rays > 0 and hits ≤ rays".into());
        }
        positive(&[self.build_ms, self.trace_ns], "times")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_figure::writes_back;
    use raystep_render::csv::from_lines;

    /// The committed file reads and writes back byte for byte: a new
    /// measurement writes its format.
    #[test]
    fn the_committed_csv_file_writes_back_unchanged() {
        writes_back::<InstanceRow>("ch08", "instances.csv").unwrap();
    }

    #[test]
    fn a_row_must_name_a_known_way() {
        let row = "1,copied,3674,4219,1,1,1.0,10,5,100.0\n";
        let rows = from_lines::<InstanceRow>(row);
        assert_eq!(rows.unwrap_err(), "line 2: unknown way `copied`");
    }
}
