//! Exercise 2 (★): the z-buffer's depth test.

use crate::DepthBuffer;

impl DepthBuffer {
    // ANCHOR: test_and_set
    /// The z test: is a surface at depth `z` closer than what pixel
    /// (column, row) shows? If so it is kept (the buffer remembers `z`)
    /// and the caller shades the pixel; if not, the buffer is unchanged.
    /// A tie keeps what was drawn first (of two coincident surfaces, the
    /// drawing order decides). NaN is never closer.
    pub fn test_and_set(&mut self, column: u32, row: u32, z: f64) -> bool {
        // TODO:
        // 1. The index of the pixel (self.index(column, row)).
        // 2. If z is smaller than the stored depth (self.depths[i]): store
        //    z there, return true.
        // 3. Otherwise (farther, equal, or NaN): change nothing, return false.
        let _ = (column, row, z);
        todo!("ch07 exercise 2: the depth test")
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
    // TODO: interpolate 1/z with the weights, then invert:
    // 1 / (λa/za + λb/zb + λc/zc). (Interpolating z itself is wrong.)
    let _ = (lambda, z);
    todo!("ch07 exercise 2: perspective_depth")
}
// ANCHOR_END: perspective_depth
