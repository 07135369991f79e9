use raystep_core::DVec3;

/// One light as seen from a surface point: the inputs of the lecture's sum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Lᵢ: the unit direction from the point toward the light.
    pub direction: DVec3,
    /// Iᵢ: the light's intensity per channel.
    pub intensity: DVec3,
    /// Sᵢ: 1 if the point sees the light, 0 if it is in shadow (chapter 4
    /// computes it; in this chapter every light is visible).
    pub visibility: f64,
}

/// The terms of the lecture's local model, each on its own, so a figure
/// can show them one by one.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShadingTerms {
    /// ka·Ia.
    pub ambient: DVec3,
    /// Σ Sᵢ·Iᵢ·kd·(N·Lᵢ).
    pub diffuse: DVec3,
    /// Σ Sᵢ·Iᵢ·ks·(Rᵢ·V)^p.
    pub specular: DVec3,
}

impl ShadingTerms {
    /// L = ambient + diffuse + specular.
    pub fn sum(&self) -> DVec3 {
        self.ambient + self.diffuse + self.specular
    }
}
