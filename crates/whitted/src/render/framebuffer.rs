//! The framebuffer: the rendered image in linear RGB, the byte each intensity becomes in the
//! PNG ([`Encoding`]: sRGB or linear, see [`crate::output`] for why), and the limit on the
//! image's size.
//!
//! Course book: [Chapter 3, shading](../../../../../docs/book/ch03-shading.html) (`docs/src/ch03-shading.md`).

use std::sync::LazyLock;

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

/// One linear intensity as a byte, without any encoding curve: clamp to [0, 1], scale by 255,
/// round; NaN becomes 0. The byte of `--encoding linear`; the default PNG is sRGB-encoded
/// (see [`Encoding`]).
#[must_use]
pub fn to_byte(x: Real) -> u8 {
    if x.is_nan() {
        return 0;
    }
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// How the PNG's bytes stand for the framebuffer's linear intensities.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Encoding {
    /// The sRGB transfer function (IEC 61966-2-1), what screens and image viewers expect:
    /// linear 0.5 is the byte 188.
    #[default]
    Srgb,
    /// The linear intensities as bytes ([`to_byte`]): 0.5 is the byte 128. Looks too dark in
    /// a viewer, but each byte is the notes' I times 255.
    Linear,
}

impl Encoding {
    /// Every encoding, the default first.
    pub const ALL: [Encoding; 2] = [Encoding::Srgb, Encoding::Linear];

    /// The encoding's name on the command line (`--encoding`) and in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Encoding::Srgb => "srgb",
            Encoding::Linear => "linear",
        }
    }

    /// One linear intensity as the byte the PNG holds: clamped to [0, 1], encoded, times 255,
    /// rounded; NaN becomes 0.
    ///
    /// For sRGB the byte is exactly that of the transfer function (IEC 61966-2-1, written out
    /// in [`crate::output`]), found without a power: it is the number of the 255 thresholds
    /// t₀ < t₁ < … < t₂₅₄ that x reaches, t_k being the smallest intensity whose encoding
    /// rounds to k + 1. Two tables, computed once: the byte at the lower end of each bucket of
    /// 1/4096, and the thresholds, of which x is compared with the one or two above that byte
    /// (`tests/encoding.rs` checks it against the formula).
    #[must_use]
    pub fn byte(self, x: Real) -> u8 {
        match self {
            Encoding::Linear => to_byte(x),
            Encoding::Srgb => srgb_byte(x),
        }
    }
}

/// The sRGB byte of a linear intensity by the formula itself: with x clamped to [0, 1],
/// V = 12.92·x up to x = 0.0031308, V = 1.055·x^(1/2.4) − 0.055 above, byte = round(255·V);
/// NaN → 0. The definition [`srgb_thresholds`] are computed from.
fn srgb_byte_by_formula(x: Real) -> u8 {
    if x.is_nan() {
        return 0;
    }
    let x = x.clamp(0.0, 1.0);
    let v = if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    };
    (v * 255.0).round() as u8
}

/// The number of equal buckets [i/B, (i+1)/B) of [0, 1] in which [`srgb_byte`] starts its
/// count. A power of two, so that ⌊x·B⌋ is exact; fine enough that a bucket holds at most
/// one or two thresholds (the curve is steepest at its knee, 12.92 × 255 / 4096 ≈ 0.8 bytes a
/// bucket).
const SRGB_BUCKETS: usize = 4096;

/// The tables of the sRGB encoding, computed once.
struct SrgbTables {
    /// t_k for k = 0 … 254: the smallest intensity whose sRGB byte (by the formula) exceeds k.
    thresholds: [Real; 255],
    /// The byte of each bucket's lower end i/B: the thresholds it reaches.
    start: [u8; SRGB_BUCKETS],
}

static SRGB: LazyLock<SrgbTables> = LazyLock::new(|| {
    let thresholds = srgb_thresholds();
    let start = std::array::from_fn(|i| {
        let x = i as Real / SRGB_BUCKETS as Real;
        thresholds.partition_point(|&t| t <= x) as u8
    });
    SrgbTables { thresholds, start }
});

/// The sRGB byte of `x`, exactly that of [`srgb_byte_by_formula`], without a power: start
/// from the byte of the lower end of x's bucket and count the thresholds x also reaches (at
/// most a couple). NaN and x ≤ 0 give 0, x ≥ 1 gives 255.
fn srgb_byte(x: Real) -> u8 {
    if x.is_nan() || x <= 0.0 {
        return 0;
    }
    if x >= 1.0 {
        return 255;
    }
    let tables = &*SRGB;
    // exact: B is a power of two, so x·B only shifts the exponent
    let mut byte = tables.start[(x * SRGB_BUCKETS as Real) as usize];
    while byte < 255 && x >= tables.thresholds[usize::from(byte)] {
        byte += 1;
    }
    byte
}

/// t_k for k = 0 … 254: the formula inverted at V = (k + ½)/255 gives t_k to within a few
/// ulps, and a walk of single ulps from there lands on the smallest float whose byte, by the
/// formula, exceeds k (a bisection over the bit patterns of [0, 1], ordered as the numbers
/// are, if the walk were ever long). 255 inversions instead of 255 bisections of 64 steps:
/// the table costs a few microseconds at start-up, not a third of a millisecond.
fn srgb_thresholds() -> [Real; 255] {
    std::array::from_fn(|k| {
        let above = |x: Real| usize::from(srgb_byte_by_formula(x)) > k;
        let v = (k as Real + 0.5) / 255.0;
        let mut x = if v <= 12.92 * 0.003_130_8 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        };
        for _ in 0..64 {
            match (above(x), above(x.next_down())) {
                (true, false) => return x,
                (true, true) => x = x.next_down(),
                (false, _) => x = x.next_up(),
            }
        }
        // invariant: `lo` is not above k, `hi` is (the byte of 0 is 0, that of 1 is 255)
        let (mut lo, mut hi) = (Real::to_bits(0.0), Real::to_bits(1.0));
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if above(Real::from_bits(mid)) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Real::from_bits(hi)
    })
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
