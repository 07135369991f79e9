//! The z-buffer: one depth per pixel.

// ANCHOR: depth_buffer
/// One depth per pixel: the view depth of the closest surface drawn there
/// so far, +∞ where nothing is drawn yet. The z test that fills it,
/// [`DepthBuffer::test_and_set`], is exercise 2.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthBuffer {
    width: u32,
    pub(crate) depths: Vec<f64>,
}

impl DepthBuffer {
    /// A `width × height` buffer with nothing drawn: every depth +∞.
    pub fn new(width: u32, height: u32) -> DepthBuffer {
        DepthBuffer {
            width,
            depths: vec![f64::INFINITY; width as usize * height as usize],
        }
    }

    /// The depth at pixel (column, row).
    pub fn get(&self, column: u32, row: u32) -> f64 {
        self.depths[self.index(column, row)]
    }

    /// Every depth, row by row from the top.
    pub fn depths(&self) -> &[f64] {
        &self.depths
    }

    /// Where pixel (column, row) is in `depths`.
    pub(crate) fn index(&self, column: u32, row: u32) -> usize {
        row as usize * self.width as usize + column as usize
    }
}
// ANCHOR_END: depth_buffer
