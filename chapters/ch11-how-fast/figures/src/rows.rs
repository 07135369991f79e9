//! The rows of the appendix's CSV file (written by `raystep measure`,
//! read by the chart and the book): each step and each peer on the big
//! bunny's three ray sets.
use raystep_render::csv::{CsvRow, Record};

/// One method at one thread count (`fast-steps.csv`).
#[derive(Clone, Debug, PartialEq)]
pub struct StepRow {
    /// `1 lecture`, `2 ordered`, …, or a peer's name.
    pub method: String,
    /// `ours` or `peer`.
    pub kind: String,
    /// Threads tracing.
    pub threads: u64,
    /// Milliseconds to build (median of the rounds).
    pub build_ms: f64,
    /// Megabytes of nodes and triangles (0: not known).
    pub mb: f64,
    /// Bytes of one node (0: not known).
    pub node_bytes: u64,
    /// Millions of rays per second: primary, shadow, incoherent.
    pub mrays: [f64; 3],
    /// Nodes reached per ray, primary and incoherent (0: not known).
    pub nodes: [f64; 2],
    /// Triangle tests per ray, primary and incoherent (0: not known).
    pub tests: [f64; 2],
    /// Rays answered unlike the lecture's tree (all sets).
    pub wrong: u64,
}

impl CsvRow for StepRow {
    /// Short, so that the book can show the file in 80 columns: `thr`
    /// threads, `prim`/`shad`/`inc` Mrays/s, `n_p`/`t_p` and `n_i`/`t_i`
    /// nodes and triangle tests per primary and incoherent ray.
    const HEADER: &'static str = "method,kind,thr,build_ms,MB,node_B,prim,shad,inc,n_p,t_p,n_i,t_i,wrong";

    fn to_line(&self) -> String {
        let r = self;
        format!(
            "{},{},{},{:.0},{:.1},{},{:.2},{:.2},{:.2},{:.1},{:.1},{:.1},{:.1},{}",
            r.method,
            r.kind,
            r.threads,
            r.build_ms,
            r.mb,
            r.node_bytes,
            r.mrays[0],
            r.mrays[1],
            r.mrays[2],
            r.nodes[0],
            r.tests[0],
            r.nodes[1],
            r.tests[1],
            r.wrong
        )
    }

    fn from_record(r: &Record) -> Result<StepRow, String> {
        let row = StepRow {
            method: r.text(0).to_string(),
            kind: r.text(1).to_string(),
            threads: r.count(2, "thr")?,
            build_ms: r.number(3, "build_ms")?,
            mb: r.number(4, "MB")?,
            node_bytes: r.count(5, "node_B")?,
            mrays: [
                r.number(6, "prim")?,
                r.number(7, "shad")?,
                r.number(8, "inc")?,
            ],
            nodes: [r.number(9, "n_p")?, r.number(11, "n_i")?],
            tests: [r.number(10, "t_p")?, r.number(12, "t_i")?],
            wrong: r.count(13, "wrong")?,
        };
        if row.kind != "ours" && row.kind != "peer" {
            return Err(r.error("kind must be `ours` or `peer`"));
        }
        let positive = row.mrays.iter().all(|&x| x > 0.0) && row.build_ms > 0.0;
        if !positive {
            return Err(r.error("speeds and build times must be positive"));
        }
        Ok(row)
    }
}
