//! The rows of part 2's CSV files (written by `raystep measure`, read by
//! the charts): builders, scaling, node precision, and chapter 7's
//! question.
use raystep_render::csv::{Decimals, Row, positive};
use serde::{Deserialize, Serialize};

/// One builder on one mesh (`bvh-builders.csv`): the tree (counted) and
/// its build and trace times (measured, one thread, medians).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BuilderRow {
    /// `bunny` or `bunny-235k`.
    pub mesh: String,
    /// The mesh's triangles.
    pub triangles: u64,
    /// The builder's name (`SAH, 16 bins`).
    pub builder: String,
    /// Milliseconds from the triangles to the fast layout.
    #[serde(with = "Decimals::<3>")]
    pub build_ms: f64,
    /// The tree's SAH cost.
    #[serde(with = "Decimals::<3>")]
    pub sah_cost: f64,
    /// Its nodes.
    pub nodes: u64,
    /// Its depth.
    pub depth: u64,
    /// Its balance ([`ch08::TreeStats::balance`]: 1 for a perfectly
    /// balanced tree).
    #[serde(with = "Decimals::<3>")]
    pub balance: f64,
    /// Nanoseconds per primary ray (closest hit).
    #[serde(with = "Decimals::<1>")]
    pub primary_ns: f64,
    /// Nanoseconds per incoherent ray (closest hit).
    #[serde(with = "Decimals::<1>")]
    pub incoherent_ns: f64,
    /// Node visits per incoherent ray.
    #[serde(with = "Decimals::<2>")]
    pub incoherent_nodes: f64,
    /// Triangle tests per incoherent ray.
    #[serde(with = "Decimals::<2>")]
    pub incoherent_triangles: f64,
}

impl Row for BuilderRow {
    fn check(&self) -> Result<(), String> {
        let (build, primary, incoherent) =
            (self.build_ms, self.primary_ns, self.incoherent_ns);
        let values = [build, primary, incoherent, self.sah_cost];
        positive(&values, "times and the SAH cost")
    }
}

/// Brute force or the hierarchy on one mesh size (`bvh-scaling.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ScalingRow {
    /// The mesh's triangles.
    pub triangles: u64,
    /// `brute force` or `BVH`.
    pub method: String,
    /// Rays timed.
    pub rays: u64,
    /// Nanoseconds per ray (closest hit; median of the rounds).
    #[serde(with = "Decimals::<1>")]
    pub ns_per_ray: f64,
    /// Node visits per ray (0 for brute force).
    #[serde(with = "Decimals::<2>")]
    pub nodes_per_ray: f64,
    /// Triangle tests per ray.
    #[serde(with = "Decimals::<2>")]
    pub triangles_per_ray: f64,
}

/// The two methods of [`ScalingRow`].
pub const BRUTE: &str = "brute force";
/// See [`BRUTE`].
pub const BVH: &str = "BVH";

impl Row for ScalingRow {
    fn check(&self) -> Result<(), String> {
        if self.method != BRUTE && self.method != BVH {
            return Err(format!("unknown method `{}`", self.method));
        }
        if self.triangles == 0 || self.rays == 0 || self.ns_per_ray <= 0.0 {
            return Err("expected triangles, rays and time > 0".into());
        }
        Ok(())
    }
}

/// One node precision (`bvh-precision.csv`): its speed (measured) and the
/// rays aimed at shared edges that leak through it (counted).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PrecisionRow {
    /// `f64`, `f32`, `f32 nearest`.
    pub precision: String,
    /// Nanoseconds per primary ray on the big bunny.
    #[serde(with = "Decimals::<1>")]
    pub primary_ns: f64,
    /// Nanoseconds per incoherent ray on the big bunny.
    #[serde(with = "Decimals::<1>")]
    pub incoherent_ns: f64,
    /// Rays aimed at shared edges (all three surfaces).
    pub edge_rays: u64,
    /// Of them, leaks through the bunny...
    pub leaks_bunny: u64,
    /// ... through the moved bunny...
    pub leaks_moved: u64,
    /// ... and through the floor.
    pub leaks_floor: u64,
}

impl PrecisionRow {
    /// The leaks through the bunny, the moved bunny and the floor.
    pub fn leaks(&self) -> [u64; 3] {
        [self.leaks_bunny, self.leaks_moved, self.leaks_floor]
    }
}

impl Row for PrecisionRow {}

/// One method drawing one of chapter 7's stages (`bvh-zbuffer.csv`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ZbufferRow {
    /// The stage's name (`shapes`, `ball-3`, `bunny`).
    pub scene: String,
    /// Its triangles.
    pub triangles: u64,
    /// [`RASTERIZE`], [`RAYCAST_BRUTE`] or [`RAYCAST_BVH`].
    pub method: String,
    /// Milliseconds to build the hierarchy (0 for the others).
    #[serde(with = "Decimals::<4>")]
    pub build_ms: f64,
    /// Milliseconds for one image (median of the rounds).
    #[serde(with = "Decimals::<4>")]
    pub millis: f64,
}

/// The methods of [`ZbufferRow`].
pub const RASTERIZE: &str = "rasterize";
/// See [`RASTERIZE`].
pub const RAYCAST_BRUTE: &str = "raycast";
/// See [`RASTERIZE`].
pub const RAYCAST_BVH: &str = "raycast-bvh";

impl Row for ZbufferRow {
    fn check(&self) -> Result<(), String> {
        if ![RASTERIZE, RAYCAST_BRUTE, RAYCAST_BVH]
            .contains(&self.method.as_str())
        {
            return Err(format!("unknown method `{}`", self.method));
        }
        if self.triangles == 0 || self.millis <= 0.0 {
            return Err("expected triangles and millis > 0".into());
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raystep_figure::writes_back;

    /// The committed files read and write back byte for byte: a new
    /// measurement writes their format.
    #[test]
    fn the_committed_csv_files_write_back_unchanged() {
        writes_back::<BuilderRow>("ch08", "bvh-builders.csv").unwrap();
        writes_back::<ScalingRow>("ch08", "bvh-scaling.csv").unwrap();
        writes_back::<PrecisionRow>("ch08", "bvh-precision.csv").unwrap();
        writes_back::<ZbufferRow>("ch08", "bvh-zbuffer.csv").unwrap();
    }
}
