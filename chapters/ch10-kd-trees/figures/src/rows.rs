//! The rows of chapter 10's CSV files (written by `raystep measure`, read
//! by the charts and the book): build times, the tree variants on the
//! benchmark's rays, which structure a scene needs, and the stability
//! catalogue.
use raystep_render::csv::{CsvRow, Record};

/// Times must be positive (false for NaN too).
fn positive(r: &Record, values: &[f64]) -> Result<(), String> {
    if values.iter().all(|&x| x > 0.0) {
        Ok(())
    } else {
        Err(r.error("times and sizes must be positive"))
    }
}

/// One builder on one scene size (`kd-build.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct BuildRow {
    /// `median`, `SAH sorting`, `SAH events`, `SAH events perfect`.
    pub builder: String,
    /// Triangles.
    pub triangles: u64,
    /// Milliseconds to build (median of the rounds).
    pub build_ms: f64,
    /// Nodes.
    pub nodes: u64,
    /// Entries in the leaves.
    pub entries: u64,
    /// The tree's SAH cost.
    pub sah_cost: f64,
}

impl CsvRow for BuildRow {
    const HEADER: &'static str =
        "builder,triangles,build_ms,nodes,entries,sah_cost";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{:.3},{},{},{:.2}",
            r.builder, r.triangles, r.build_ms, r.nodes, r.entries, r.sah_cost
        )
    }

    fn from_record(r: &Record) -> Result<BuildRow, String> {
        let row = BuildRow {
            builder: r.text(0).to_string(),
            triangles: r.count(1, "triangles")?,
            build_ms: r.number(2, "build_ms")?,
            nodes: r.count(3, "nodes")?,
            entries: r.count(4, "entries")?,
            sah_cost: r.number(5, "sah_cost")?,
        };
        positive(r, &[row.build_ms, row.triangles as f64])?;
        Ok(row)
    }
}

/// One tree variant on one mesh, on the benchmark's rays (`kd-variants.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct VariantRow {
    /// `bunny`, `bunny-235k`, `uniform-10000`.
    pub scene: String,
    /// `SAH W&H boxes`, `SAH W&H perfect`, `SAH pbrt costs`, `SAH W&H
    /// depth 1.3`, `median`.
    pub variant: String,
    /// Milliseconds to build.
    pub build_ms: f64,
    /// Bytes of nodes, lists and triangles.
    pub bytes: u64,
    /// Nanoseconds per camera ray, per incoherent ray.
    pub primary_ns: f64,
    /// See `primary_ns`.
    pub incoherent_ns: f64,
    /// Nodes reached per camera ray, and triangle tests.
    pub primary_nodes: f64,
    /// See `primary_nodes`.
    pub primary_tests: f64,
    /// Nodes reached per incoherent ray, and triangle tests.
    pub incoherent_nodes: f64,
    /// See `incoherent_nodes`.
    pub incoherent_tests: f64,
}

impl CsvRow for VariantRow {
    const HEADER: &'static str = "scene,variant,build_ms,bytes,primary_ns,\
        incoherent_ns,primary_nodes,primary_tests,incoherent_nodes,incoherent_tests";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{:.3},{},{:.1},{:.1},{:.2},{:.2},{:.2},{:.2}",
            r.scene,
            r.variant,
            r.build_ms,
            r.bytes,
            r.primary_ns,
            r.incoherent_ns,
            r.primary_nodes,
            r.primary_tests,
            r.incoherent_nodes,
            r.incoherent_tests
        )
    }

    fn from_record(r: &Record) -> Result<VariantRow, String> {
        let row = VariantRow {
            scene: r.text(0).to_string(),
            variant: r.text(1).to_string(),
            build_ms: r.number(2, "build_ms")?,
            bytes: r.count(3, "bytes")?,
            primary_ns: r.number(4, "primary_ns")?,
            incoherent_ns: r.number(5, "incoherent_ns")?,
            primary_nodes: r.number(6, "primary_nodes")?,
            primary_tests: r.number(7, "primary_tests")?,
            incoherent_nodes: r.number(8, "incoherent_nodes")?,
            incoherent_tests: r.number(9, "incoherent_tests")?,
        };
        positive(r, &[row.build_ms, row.primary_ns, row.incoherent_ns])?;
        Ok(row)
    }
}

/// One structure on one scene family, on the tracers' own path (objects,
/// double precision): `which-structure.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct StructureRow {
    /// The family: `handful`, `slow`, `uniform-10000`, ...
    pub scene: String,
    /// Its objects.
    pub objects: u64,
    /// `brute`, `bvh`, `grid`, `kdtree`.
    pub method: String,
    /// Does chapter 10's rule pick this structure for this scene?
    pub chosen: bool,
    /// Milliseconds to build (0 for brute force).
    pub build_ms: f64,
    /// Bytes of the structure (not the objects; 0 for brute force).
    pub bytes: u64,
    /// Nanoseconds per camera ray, per incoherent ray (closest hit).
    pub primary_ns: f64,
    /// See `primary_ns`.
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

impl CsvRow for StructureRow {
    const HEADER: &'static str = "scene,objects,method,chosen,build_ms,bytes,\
        primary_ns,incoherent_ns,disagreements";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{},{:.3},{},{:.1},{:.1},{}",
            r.scene,
            r.objects,
            r.method,
            u8::from(r.chosen),
            r.build_ms,
            r.bytes,
            r.primary_ns,
            r.incoherent_ns,
            r.disagreements
        )
    }

    fn from_record(r: &Record) -> Result<StructureRow, String> {
        let row = StructureRow {
            scene: r.text(0).to_string(),
            objects: r.count(1, "objects")?,
            method: r.text(2).to_string(),
            chosen: r.count(3, "chosen")? == 1,
            build_ms: r.number(4, "build_ms")?,
            bytes: r.count(5, "bytes")?,
            primary_ns: r.number(6, "primary_ns")?,
            incoherent_ns: r.number(7, "incoherent_ns")?,
            disagreements: r.count(8, "disagreements")?,
        };
        positive(r, &[row.primary_ns, row.incoherent_ns])?;
        Ok(row)
    }
}

/// One kind of dangerous ray on one scene: disagreements with brute force
/// per tree (`kd-stability.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct StabilityRow {
    /// The scene.
    pub scene: String,
    /// The kind of ray.
    pub case: String,
    /// How many rays.
    pub rays: u64,
    /// Wrong answers: SAH (chosen costs), the same without a mailbox, the
    /// median tree, SAH with pbrt's costs.
    pub wrong: [u64; 4],
}

impl CsvRow for StabilityRow {
    const HEADER: &'static str = "scene,case,rays,wrong_sah,wrong_no_mailbox,wrong_median,wrong_sah_pbrt";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{},{},{},{}",
            r.scene,
            r.case,
            r.rays,
            r.wrong[0],
            r.wrong[1],
            r.wrong[2],
            r.wrong[3]
        )
    }

    fn from_record(r: &Record) -> Result<StabilityRow, String> {
        Ok(StabilityRow {
            scene: r.text(0).to_string(),
            case: r.text(1).to_string(),
            rays: r.count(2, "rays")?,
            wrong: [
                r.count(3, "wrong_sah")?,
                r.count(4, "wrong_no_mailbox")?,
                r.count(5, "wrong_median")?,
                r.count(6, "wrong_sah_pbrt")?,
            ],
        })
    }
}
