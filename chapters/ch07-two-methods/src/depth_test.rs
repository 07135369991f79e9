//! Exercise 2: the z-buffer's depth test.

use crate::DepthBuffer;

impl DepthBuffer {
    // ANCHOR: test_and_set
    /// The z test: is a surface at depth `z` closer than what pixel
    /// (column, row) shows? If so it is kept (the buffer remembers `z`)
    /// and the caller shades the pixel; if not, the buffer is unchanged.
    /// A tie keeps what was drawn first (of two coincident surfaces, the
    /// drawing order decides). NaN is never closer.
    pub fn test_and_set(&mut self, column: u32, row: u32, z: f64) -> bool {
        let i = self.index(column, row);
        if z < self.depths[i] {
            self.depths[i] = z;
            true
        } else {
            false
        }
    }
    // ANCHOR_END: test_and_set
}

// ANCHOR: perspective_depth
/// The view depth at a point of a triangle on screen, from its weights
/// `lambda` (screen-space barycentric) and its corners' view depths `z`.
///
/// Depth is not linear on screen: equal steps across the screen cover
/// more and more of a receding triangle. 1/z is: it is linear in the
/// screen coordinates for any plane. So interpolate 1/z and invert:
/// z = 1 / (λa/za + λb/zb + λc/zc).
pub fn perspective_depth(lambda: [f64; 3], z: [f64; 3]) -> f64 {
    1.0 / (lambda[0] / z[0] + lambda[1] / z[1] + lambda[2] / z[2])
}
// ANCHOR_END: perspective_depth
