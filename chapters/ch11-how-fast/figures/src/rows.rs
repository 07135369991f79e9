//! The rows of the appendix's CSV file (written by `raystep measure`,
//! read by the chart and the book): each step and each peer on the big
//! bunny's three ray sets.
use raystep_render::csv::{Decimals, Row, positive};
use serde::{Deserialize, Serialize};

/// One method at one thread count (`fast-steps.csv`). The columns' names
/// are short, so that the book can show the file in 80 columns: `thr`
/// threads, `prim`/`shad`/`inc` Mrays/s, `n_p`/`t_p` and `n_i`/`t_i`
/// nodes and triangle tests per primary and incoherent ray.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StepRow {
    /// `1 lecture`, `2 ordered`, …, or a peer's name.
    pub method: String,
    /// `ours` or `peer`.
    pub kind: String,
    /// Threads tracing.
    #[serde(rename = "thr")]
    pub threads: u64,
    /// Milliseconds to build (median of the rounds).
    #[serde(with = "Decimals::<0>")]
    pub build_ms: f64,
    /// Megabytes of nodes and triangles (0: not known).
    #[serde(rename = "MB", with = "Decimals::<1>")]
    pub mb: f64,
    /// Bytes of one node (0: not known).
    #[serde(rename = "node_B")]
    pub node_bytes: u64,
    /// Millions of rays per second: primary rays...
    #[serde(rename = "prim", with = "Decimals::<2>")]
    pub primary_mrays: f64,
    /// ... shadow rays...
    #[serde(rename = "shad", with = "Decimals::<2>")]
    pub shadow_mrays: f64,
    /// ... and incoherent rays.
    #[serde(rename = "inc", with = "Decimals::<2>")]
    pub incoherent_mrays: f64,
    /// Nodes reached per primary ray (0: not known).
    #[serde(rename = "n_p", with = "Decimals::<1>")]
    pub primary_nodes: f64,
    /// Triangle tests per primary ray (0: not known).
    #[serde(rename = "t_p", with = "Decimals::<1>")]
    pub primary_tests: f64,
    /// Nodes reached per incoherent ray (0: not known).
    #[serde(rename = "n_i", with = "Decimals::<1>")]
    pub incoherent_nodes: f64,
    /// Triangle tests per incoherent ray (0: not known).
    #[serde(rename = "t_i", with = "Decimals::<1>")]
    pub incoherent_tests: f64,
    /// Rays answered unlike the lecture's tree (all sets).
    pub wrong: u64,
}

impl StepRow {
    /// Millions of rays per second: primary, shadow, incoherent.
    pub fn mrays(&self) -> [f64; 3] {
        [self.primary_mrays, self.shadow_mrays, self.incoherent_mrays]
    }
}

impl Row for StepRow {
    fn check(&self) -> Result<(), String> {
        if self.kind != "ours" && self.kind != "peer" {
            return Err("kind must be `ours` or `peer`".into());
        }
        let [primary, shadow, incoherent] = self.mrays();
        let values = [primary, shadow, incoherent, self.build_ms];
        positive(&values, "speeds and build times")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The committed file reads and writes back byte for byte: a new
    /// measurement writes its format.
    #[test]
    fn the_committed_csv_writes_back_unchanged() {
        raystep_figure::writes_back::<StepRow>("ch11", "fast-steps.csv")
            .unwrap();
    }
}
