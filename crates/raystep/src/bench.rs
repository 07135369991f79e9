//! `raystep bench MESH.obj`: build and trace times of chapter 8's
//! hierarchies, chapter 9's grid and chapter 10's kd-tree on a triangle
//! mesh, beside obvhs and bvh (`--peers`).
use std::path::PathBuf;
use std::process::ExitCode;

use ch08::{Builder, NodePrecision};
use raystep_bench::{BenchOptions, hit_bytes, run as run_bench};

use crate::{Error, atomic_file};

/// `--builders`: our tree builders, by short name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum BuilderArg {
    /// Split at the middle of the centroids' box.
    Midpoint,
    /// Split at the median centroid.
    Median,
    /// Binned SAH, 4 bins.
    Sah4,
    /// Binned SAH, 8 bins.
    Sah8,
    /// Binned SAH, 16 bins.
    Sah16,
    /// Binned SAH, 32 bins.
    Sah32,
    /// SAH over every cut between neighbouring centroids.
    Sweep,
    /// Exact agglomerative clustering (PLOC above 4096 triangles).
    Agglomerative,
    /// PLOC, radius 8.
    Ploc,
}

impl BuilderArg {
    /// The builder it names.
    pub fn builder(self) -> Builder {
        match self {
            BuilderArg::Midpoint => Builder::Midpoint,
            BuilderArg::Median => Builder::Median,
            BuilderArg::Sah4 => Builder::BinnedSah { bins: 4 },
            BuilderArg::Sah8 => Builder::BinnedSah { bins: 8 },
            BuilderArg::Sah16 => Builder::BinnedSah { bins: 16 },
            BuilderArg::Sah32 => Builder::BinnedSah { bins: 32 },
            BuilderArg::Sweep => Builder::SweepSah,
            BuilderArg::Agglomerative => Builder::Agglomerative,
            BuilderArg::Ploc => Builder::Ploc { radius: 8 },
        }
    }
}

/// `--embree-isa`: the instruction set Embree's third row keeps to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum EmbreeIsaArg {
    /// SSE2.
    Sse2,
    /// SSE4.2.
    #[value(name = "sse4.2")]
    Sse42,
    /// AVX.
    Avx,
    /// AVX2.
    Avx2,
    /// AVX-512.
    Avx512,
}

impl EmbreeIsaArg {
    /// The bench's value.
    pub fn isa(self) -> raystep_bench::EmbreeIsa {
        use raystep_bench::EmbreeIsa as Isa;
        match self {
            EmbreeIsaArg::Sse2 => Isa::Sse2,
            EmbreeIsaArg::Sse42 => Isa::Sse42,
            EmbreeIsaArg::Avx => Isa::Avx,
            EmbreeIsaArg::Avx2 => Isa::Avx2,
            EmbreeIsaArg::Avx512 => Isa::Avx512,
        }
    }
}

/// `--accel`: which of our structures to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum AccelArg {
    /// Chapter 8's hierarchies (`--builders`, `--precision`).
    Bvh,
    /// Chapter 9's uniform grid (`--grid-fill`, `--grid-cells`).
    Grid,
    /// Chapter 10's kd-tree, SAH from events (`--kd-clip`).
    #[value(name = "kdtree")]
    KdTree,
    /// The appendix's fast hierarchies (`--fast`).
    Fast,
}

/// `--fast`: the appendix's steps, by the names (and with the help) chapter
/// 11 gives them.
pub use ch11::Step as FastArg;

/// `--grid-fill`: which cells list a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum FillArg {
    /// Every cell its bounding box overlaps.
    Boxes,
    /// Only the cells it passes through (the triangle–box test).
    Exact,
}

impl FillArg {
    /// The fill it names.
    pub fn fill(self) -> ch09::Fill {
        match self {
            FillArg::Boxes => ch09::Fill::Boxes,
            FillArg::Exact => ch09::Fill::Exact,
        }
    }
}

/// `--kd-clip`: which box of a triangle the kd-tree's builder weighs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ClipArg {
    /// Its bounding box cut to the node.
    Boxes,
    /// The box of the triangle clipped to the node ("perfect splits").
    Triangles,
}

impl ClipArg {
    /// The clip it names.
    pub fn clip(self) -> ch10::Clip {
        match self {
            ClipArg::Boxes => ch10::Clip::Boxes,
            ClipArg::Triangles => ch10::Clip::Triangles,
        }
    }
}

/// `--precision`: how our nodes store their boxes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PrecisionArg {
    /// f64 boxes.
    F64,
    /// f32 boxes rounded outward, exits widened (never misses).
    F32,
    /// f32 boxes rounded to nearest, no widening (may miss).
    F32Nearest,
}

impl PrecisionArg {
    /// The precision it names.
    pub fn precision(self) -> NodePrecision {
        match self {
            PrecisionArg::F64 => NodePrecision::Double,
            PrecisionArg::F32 => NodePrecision::Single,
            PrecisionArg::F32Nearest => NodePrecision::SingleNearest,
        }
    }
}

/// What `raystep bench` was asked to do: the benchmark, and the files to
/// write after it.
#[derive(Debug)]
pub struct Options {
    /// The benchmark.
    pub bench: BenchOptions,
    /// The JSON report.
    pub json: Option<PathBuf>,
    /// The hit file.
    pub write_hits: Option<PathBuf>,
}

/// Runs the benchmark, prints its table and writes the files asked for.
/// The output folders are checked first, and the files are written whole
/// once everything has run: a failure leaves no partial file.
pub fn run(options: &Options) -> Result<ExitCode, Error> {
    for path in options.json.iter().chain(&options.write_hits) {
        atomic_file::can_write(path)?;
    }
    let finished =
        run_bench(&options.bench).map_err(|e| Error::Usage(e.to_string()))?;
    print!("{}", finished.report.table());
    if let Some(path) = &options.json {
        let mut text = serde_json::to_string_pretty(&finished.report)
            .map_err(|e| Error::Usage(format!("{}: {e}", path.display())))?;
        text.push('\n');
        atomic_file::write(path, text.as_bytes())?;
    }
    if let Some(path) = &options.write_hits {
        atomic_file::write(path, &hit_bytes(&finished.answers))?;
    }
    Ok(ExitCode::SUCCESS)
}
