//! The rows of chapter 8's two CSV files, as `raystep measure` writes them
//! and the charts read them.
use raystep_render::csv::{Decimals, Row};
use serde::{Deserialize, Serialize};

/// The groups of [`CostRow::group`]: the lecture's fast and slow
/// primitives, and the two bounding volumes.
pub const GROUPS: [&str; 3] = ["fast", "slow", "bound"];

/// One line of `costs.csv`: the median time of one ray–primitive test, for
/// rays that hit it or rays that miss it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CostRow {
    /// The primitive's name (`sphere`, `torus`, `bound: box`, …).
    pub primitive: String,
    /// `fast`, `slow` or `bound`.
    pub group: String,
    /// `hit` or `miss`: which rays were timed.
    pub rays: String,
    /// Nanoseconds per test (median of the rounds).
    #[serde(with = "Decimals::<2>")]
    pub nanos: f64,
}

impl Row for CostRow {
    fn check(&self) -> Result<(), String> {
        let (group, rays) = (&self.group, &self.rays);
        if !GROUPS.contains(&group.as_str()) {
            return Err(format!("unknown group `{group}`"));
        }
        if rays != "hit" && rays != "miss" {
            return Err(format!("rays: `hit` or `miss`, got `{rays}`"));
        }
        Ok(())
    }
}

/// One line of `bounding.csv`: an object tested with one kind of bound (or
/// none), on one seeded set of random lines: how many rays hit the bound
/// and the object (counted), and the time per ray (measured).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BoundingRow {
    /// The object's name.
    pub object: String,
    /// `none`, `box`, `sphere` (its own tight sphere) or `box's sphere`
    /// (the box's circumsphere).
    pub bound: String,
    /// Rays shot.
    pub rays: u64,
    /// Rays that hit the bound (all of them for `none`).
    pub bound_hits: u64,
    /// Rays that hit the object.
    pub object_hits: u64,
    /// Nanoseconds per ray, bound test included (median of the rounds).
    #[serde(with = "Decimals::<2>")]
    pub nanos: f64,
}

impl BoundingRow {
    /// The fraction of the bound's hits that miss the object: object tests
    /// spent for nothing.
    pub fn wasted_of_bound_hits(&self) -> f64 {
        (self.bound_hits - self.object_hits) as f64 / self.bound_hits as f64
    }
}

impl Row for BoundingRow {
    fn check(&self) -> Result<(), String> {
        if self.rays == 0
            || self.bound_hits > self.rays
            || self.object_hits > self.bound_hits
        {
            return Err(
                "expected 0 < rays, object_hits ≤ bound_hits ≤ rays".into()
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_figure::writes_back;
    use raystep_render::csv::from_lines;

    /// The committed files read and write back byte for byte: a new
    /// measurement writes their format.
    #[test]
    fn the_committed_csv_files_write_back_unchanged() {
        writes_back::<CostRow>("ch08", "costs.csv").unwrap();
        writes_back::<BoundingRow>("ch08", "bounding.csv").unwrap();
    }

    #[test]
    fn a_row_must_name_a_known_group_and_consistent_hits() {
        let costs = from_lines::<CostRow>("box,fast,hit,1\nbox,odd,hit,1\n");
        assert_eq!(costs.unwrap_err(), "line 3: unknown group `odd`");
        let hits = from_lines::<BoundingRow>("ball,box,10,5,6,1.5\n");
        assert_eq!(
            hits.unwrap_err(),
            "line 2: expected 0 < rays, object_hits ≤ bound_hits ≤ rays"
        );
    }
}
