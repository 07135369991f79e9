//! The builders of a [`Bvh`](crate::Bvh), by name: four split top-down,
//! two merge bottom-up.

/// How a [`Bvh`](crate::Bvh) is built. Every builder gives the same node
/// layout, so the walk, [`MeshBvh`](crate::MeshBvh) and the measurements
/// are shared.
///
/// The first four split top-down, the last two merge bottom-up.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builder {
    /// Split at the middle of the centroids' box, along its longest axis.
    Midpoint,
    /// Split at the median centroid along that axis: two halves of equal
    /// count.
    Median,
    /// Split where the surface area heuristic is lowest, among `bins`
    /// equal slices of the centroids' box on each axis.
    BinnedSah {
        /// How many slices per axis (at least 2).
        bins: usize,
    },
    /// Split where the surface area heuristic is lowest among every cut
    /// between two neighbouring centroids on each axis (Wald 2007's full
    /// sweep).
    SweepSah,
    /// Merge, again and again, the two clusters whose union has the
    /// smallest area (Walter et al. 2008, exact). Quadratic: above
    /// [`AGGLOMERATIVE_LIMIT`] objects it is PLOC with radius 8.
    Agglomerative,
    /// PLOC (Meister and Bittner 2018): clusters sorted along a Morton
    /// curve; each pair of mutual nearest neighbours within `radius`
    /// places of each other merges, round after round.
    Ploc {
        /// How far along the curve a cluster looks (at least 1).
        radius: usize,
    },
}

/// The most objects [`Builder::Agglomerative`] clusters exactly.
pub const AGGLOMERATIVE_LIMIT: usize = 4096;

impl Builder {
    /// Every builder, in the order tables show them.
    pub const ALL: [Builder; 9] = [
        Builder::Midpoint,
        Builder::Median,
        Builder::BinnedSah { bins: 4 },
        Builder::BinnedSah { bins: 8 },
        Builder::BinnedSah { bins: 16 },
        Builder::BinnedSah { bins: 32 },
        Builder::SweepSah,
        Builder::Agglomerative,
        Builder::Ploc { radius: 8 },
    ];

    /// `midpoint`, `SAH, 16 bins`, `PLOC, radius 8`: the name tables show.
    pub fn name(self) -> String {
        match self {
            Builder::Midpoint => "midpoint".to_string(),
            Builder::Median => "median".to_string(),
            Builder::BinnedSah { bins } => format!("SAH, {bins} bins"),
            Builder::SweepSah => "SAH, full sweep".to_string(),
            Builder::Agglomerative => "agglomerative".to_string(),
            Builder::Ploc { radius } => format!("PLOC, radius {radius}"),
        }
    }
}
