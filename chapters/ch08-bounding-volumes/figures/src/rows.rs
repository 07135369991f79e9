//! The rows of chapter 8's two CSV files, as `raystep measure` writes them
//! and the charts read them.
use raystep_render::csv::{CsvRow, Record};

/// The groups of [`CostRow::group`]: the lecture's fast and slow
/// primitives, and the two bounding volumes.
pub const GROUPS: [&str; 3] = ["fast", "slow", "bound"];

/// One line of `costs.csv`: the median time of one ray–primitive test, for
/// rays that hit it or rays that miss it.
#[derive(Clone, Debug, PartialEq)]
pub struct CostRow {
    /// The primitive's name (`sphere`, `torus`, `bound: box`, …).
    pub primitive: String,
    /// `fast`, `slow` or `bound`.
    pub group: String,
    /// `hit` or `miss`: which rays were timed.
    pub rays: String,
    /// Nanoseconds per test (median of the rounds).
    pub nanos: f64,
}

impl CsvRow for CostRow {
    const HEADER: &'static str = "primitive,group,rays,nanos";

    fn to_line(&self) -> String {
        format!(
            "{},{},{},{:.2}",
            self.primitive, self.group, self.rays, self.nanos
        )
    }

    fn from_record(r: &Record) -> Result<CostRow, String> {
        let group = r.text(1);
        if !GROUPS.contains(&group) {
            return Err(r.error(format!("unknown group `{group}`")));
        }
        let rays = r.text(2);
        if rays != "hit" && rays != "miss" {
            return Err(r.error(format!("rays: `hit` or `miss`, got `{rays}`")));
        }
        Ok(CostRow {
            primitive: r.text(0).to_string(),
            group: group.to_string(),
            rays: rays.to_string(),
            nanos: r.number(3, "nanos")?,
        })
    }
}

/// One line of `bounding.csv`: an object tested with one kind of bound (or
/// none), on one seeded set of random lines: how many rays hit the bound
/// and the object (counted), and the time per ray (measured).
#[derive(Clone, Debug, PartialEq)]
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
    pub nanos: f64,
}

impl BoundingRow {
    /// The fraction of the bound's hits that miss the object: object tests
    /// spent for nothing.
    pub fn wasted_of_bound_hits(&self) -> f64 {
        (self.bound_hits - self.object_hits) as f64 / self.bound_hits as f64
    }
}

impl CsvRow for BoundingRow {
    const HEADER: &'static str =
        "object,bound,rays,bound_hits,object_hits,nanos";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{},{},{:.2}",
            r.object, r.bound, r.rays, r.bound_hits, r.object_hits, r.nanos
        )
    }

    fn from_record(r: &Record) -> Result<BoundingRow, String> {
        let row = BoundingRow {
            object: r.text(0).to_string(),
            bound: r.text(1).to_string(),
            rays: r.count(2, "rays")?,
            bound_hits: r.count(3, "bound_hits")?,
            object_hits: r.count(4, "object_hits")?,
            nanos: r.number(5, "nanos")?,
        };
        if row.rays == 0
            || row.bound_hits > row.rays
            || row.object_hits > row.bound_hits
        {
            return Err(
                r.error("expected 0 < rays, object_hits ≤ bound_hits ≤ rays")
            );
        }
        Ok(row)
    }
}
