//! The instruction sets Embree's kernels can be kept to (`raystep bench
//! --embree-isa`), apart from the peer itself so that the methods can name
//! one without the `embree` feature.

/// An instruction set Embree can be told to keep to (its device's `isa`
/// setting): to compare its kernels on one CPU, in one run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EmbreeIsa {
    /// SSE2.
    Sse2,
    /// SSE4.2.
    Sse42,
    /// AVX.
    Avx,
    /// AVX2.
    Avx2,
    /// AVX-512 (Skylake-X's set).
    Avx512,
}

impl EmbreeIsa {
    /// Its name in Embree's device settings (and in the bench's rows).
    pub fn name(self) -> &'static str {
        match self {
            EmbreeIsa::Sse2 => "sse2",
            EmbreeIsa::Sse42 => "sse4.2",
            EmbreeIsa::Avx => "avx",
            EmbreeIsa::Avx2 => "avx2",
            EmbreeIsa::Avx512 => "avx512",
        }
    }
}
