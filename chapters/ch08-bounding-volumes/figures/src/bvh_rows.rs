//! The rows of part 2's CSV files (written by `raystep measure`, read by
//! the charts): builders, scaling, node precision, and chapter 7's
//! question.
use raystep_render::csv::{CsvRow, Record};

/// One builder on one mesh (`bvh-builders.csv`): the tree (counted) and
/// its build and trace times (measured, one thread, medians).
#[derive(Clone, Debug, PartialEq)]
pub struct BuilderRow {
    /// `bunny` or `bunny-235k`.
    pub mesh: String,
    /// The mesh's triangles.
    pub triangles: u64,
    /// The builder's name (`SAH, 16 bins`).
    pub builder: String,
    /// Milliseconds from the triangles to the fast layout.
    pub build_ms: f64,
    /// The tree's SAH cost.
    pub sah_cost: f64,
    /// Its nodes.
    pub nodes: u64,
    /// Its depth.
    pub depth: u64,
    /// Its balance ([`ch08::TreeStats::balance`]: 1 for a perfectly
    /// balanced tree).
    pub balance: f64,
    /// Nanoseconds per primary ray (closest hit).
    pub primary_ns: f64,
    /// Nanoseconds per incoherent ray (closest hit).
    pub incoherent_ns: f64,
    /// Node visits per incoherent ray.
    pub incoherent_nodes: f64,
    /// Triangle tests per incoherent ray.
    pub incoherent_triangles: f64,
}

impl CsvRow for BuilderRow {
    const HEADER: &'static str = "mesh,triangles,builder,build_ms,sah_cost,\
        nodes,depth,balance,primary_ns,incoherent_ns,incoherent_nodes,\
        incoherent_triangles";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{:.3},{:.3},{},{},{:.3},{:.1},{:.1},{:.2},{:.2}",
            r.mesh,
            r.triangles,
            r.builder,
            r.build_ms,
            r.sah_cost,
            r.nodes,
            r.depth,
            r.balance,
            r.primary_ns,
            r.incoherent_ns,
            r.incoherent_nodes,
            r.incoherent_triangles
        )
    }

    fn from_record(r: &Record) -> Result<BuilderRow, String> {
        let row = BuilderRow {
            mesh: r.text(0).to_string(),
            triangles: r.count(1, "triangles")?,
            builder: r.text(2).to_string(),
            build_ms: r.number(3, "build_ms")?,
            sah_cost: r.number(4, "sah_cost")?,
            nodes: r.count(5, "nodes")?,
            depth: r.count(6, "depth")?,
            balance: r.number(7, "balance")?,
            primary_ns: r.number(8, "primary_ns")?,
            incoherent_ns: r.number(9, "incoherent_ns")?,
            incoherent_nodes: r.number(10, "incoherent_nodes")?,
            incoherent_triangles: r.number(11, "incoherent_triangles")?,
        };
        let times = [row.build_ms, row.primary_ns, row.incoherent_ns];
        let positive = |x: f64| x > 0.0; // false for NaN too
        if !times.into_iter().all(positive) || !positive(row.sah_cost) {
            return Err(r.error("times and the SAH cost must be positive"));
        }
        Ok(row)
    }
}

/// Brute force or the hierarchy on one mesh size (`bvh-scaling.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct ScalingRow {
    /// The mesh's triangles.
    pub triangles: u64,
    /// `brute force` or `BVH`.
    pub method: String,
    /// Rays timed.
    pub rays: u64,
    /// Nanoseconds per ray (closest hit; median of the rounds).
    pub ns_per_ray: f64,
    /// Node visits per ray (0 for brute force).
    pub nodes_per_ray: f64,
    /// Triangle tests per ray.
    pub triangles_per_ray: f64,
}

/// The two methods of [`ScalingRow`].
pub const BRUTE: &str = "brute force";
/// See [`BRUTE`].
pub const BVH: &str = "BVH";

impl CsvRow for ScalingRow {
    const HEADER: &'static str =
        "triangles,method,rays,ns_per_ray,nodes_per_ray,triangles_per_ray";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{:.1},{:.2},{:.2}",
            r.triangles,
            r.method,
            r.rays,
            r.ns_per_ray,
            r.nodes_per_ray,
            r.triangles_per_ray
        )
    }

    fn from_record(r: &Record) -> Result<ScalingRow, String> {
        let method = r.text(1);
        if method != BRUTE && method != BVH {
            return Err(r.error(format!("unknown method `{method}`")));
        }
        let row = ScalingRow {
            triangles: r.count(0, "triangles")?,
            method: method.to_string(),
            rays: r.count(2, "rays")?,
            ns_per_ray: r.number(3, "ns_per_ray")?,
            nodes_per_ray: r.number(4, "nodes_per_ray")?,
            triangles_per_ray: r.number(5, "triangles_per_ray")?,
        };
        let timed = row.ns_per_ray > 0.0; // false for NaN too
        if row.triangles == 0 || row.rays == 0 || !timed {
            return Err(r.error("expected triangles, rays and time > 0"));
        }
        Ok(row)
    }
}

/// One node precision (`bvh-precision.csv`): its speed (measured) and the
/// rays aimed at shared edges that leak through it (counted).
#[derive(Clone, Debug, PartialEq)]
pub struct PrecisionRow {
    /// `f64`, `f32`, `f32 nearest`.
    pub precision: String,
    /// Nanoseconds per primary ray on the big bunny.
    pub primary_ns: f64,
    /// Nanoseconds per incoherent ray on the big bunny.
    pub incoherent_ns: f64,
    /// Rays aimed at shared edges (all three surfaces).
    pub edge_rays: u64,
    /// Of them, leaks: through the bunny, the moved bunny, the floor.
    pub leaks: [u64; 3],
}

impl CsvRow for PrecisionRow {
    const HEADER: &'static str = "precision,primary_ns,incoherent_ns,\
        edge_rays,leaks_bunny,leaks_moved,leaks_floor";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{:.1},{:.1},{},{},{},{}",
            r.precision,
            r.primary_ns,
            r.incoherent_ns,
            r.edge_rays,
            r.leaks[0],
            r.leaks[1],
            r.leaks[2]
        )
    }

    fn from_record(r: &Record) -> Result<PrecisionRow, String> {
        Ok(PrecisionRow {
            precision: r.text(0).to_string(),
            primary_ns: r.number(1, "primary_ns")?,
            incoherent_ns: r.number(2, "incoherent_ns")?,
            edge_rays: r.count(3, "edge_rays")?,
            leaks: [
                r.count(4, "leaks_bunny")?,
                r.count(5, "leaks_moved")?,
                r.count(6, "leaks_floor")?,
            ],
        })
    }
}

/// One method drawing one of chapter 7's stages (`bvh-zbuffer.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct ZbufferRow {
    /// The stage's name (`shapes`, `ball-3`, `bunny`).
    pub scene: String,
    /// Its triangles.
    pub triangles: u64,
    /// [`RASTERIZE`], [`RAYCAST_BRUTE`] or [`RAYCAST_BVH`].
    pub method: String,
    /// Milliseconds to build the hierarchy (0 for the others).
    pub build_ms: f64,
    /// Milliseconds for one image (median of the rounds).
    pub millis: f64,
}

/// The methods of [`ZbufferRow`].
pub const RASTERIZE: &str = "rasterize";
/// See [`RASTERIZE`].
pub const RAYCAST_BRUTE: &str = "raycast";
/// See [`RASTERIZE`].
pub const RAYCAST_BVH: &str = "raycast-bvh";

impl CsvRow for ZbufferRow {
    const HEADER: &'static str = "scene,triangles,method,build_ms,millis";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{:.4},{:.4}",
            r.scene, r.triangles, r.method, r.build_ms, r.millis
        )
    }

    fn from_record(r: &Record) -> Result<ZbufferRow, String> {
        let method = r.text(2);
        if ![RASTERIZE, RAYCAST_BRUTE, RAYCAST_BVH].contains(&method) {
            return Err(r.error(format!("unknown method `{method}`")));
        }
        let row = ZbufferRow {
            scene: r.text(0).to_string(),
            triangles: r.count(1, "triangles")?,
            method: method.to_string(),
            build_ms: r.number(3, "build_ms")?,
            millis: r.number(4, "millis")?,
        };
        let timed = row.millis > 0.0; // false for NaN too
        if row.triangles == 0 || !timed {
            return Err(r.error("expected triangles and millis > 0"));
        }
        Ok(row)
    }
}
