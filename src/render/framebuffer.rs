//! The framebuffer: the rendered image in linear RGB, the byte each intensity becomes in the
//! PNG, and the limit on the image's size.

use crate::error::Error;
use crate::real::{Real, Vec3};

/// A linear-RGB image, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row-major pixels, top row first.
    pub pixels: Vec<Vec3>,
}

impl Framebuffer {
    /// A black image of `width` × `height` pixels.
    #[must_use]
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            pixels: vec![Vec3::ZERO; (width as usize) * (height as usize)],
        }
    }

    /// The pixel at column x, row y (from the top).
    #[must_use]
    pub fn get(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[(y * self.width + x) as usize]
    }
}

/// One linear intensity as the byte the PNG holds: clamp to [0, 1], scale by 255, round; NaN
/// becomes 0 (see [`crate::output`]).
#[must_use]
pub fn to_byte(x: Real) -> u8 {
    if x.is_nan() {
        return 0;
    }
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The largest framebuffer a render may allocate: 4 GiB, that is width × height × 3 ×
/// `size_of::<Real>()` bytes (f64: 178 956 970 pixels, e.g. 13 377 × 13 377; f32: twice as
/// many). The 8-bit copy written to the PNG adds 3 bytes per pixel.
pub const MAX_FRAMEBUFFER_BYTES: u64 = 4 << 30;

/// Refuses an image whose framebuffer would pass [`MAX_FRAMEBUFFER_BYTES`]: call it before
/// any work starts.
pub fn check_size(width: u32, height: u32) -> Result<(), Error> {
    let bytes = u64::from(width) * u64::from(height) * std::mem::size_of::<Vec3>() as u64;
    if bytes > MAX_FRAMEBUFFER_BYTES {
        return Err(Error::Usage(format!(
            "image {width}×{height} is too large: its framebuffer would take {:.1} GiB, more than the limit of {} GiB",
            bytes as f64 / (1u64 << 30) as f64,
            MAX_FRAMEBUFFER_BYTES >> 30
        )));
    }
    Ok(())
}
