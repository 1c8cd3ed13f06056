//! Where the samples of a pixel go (chapter 5's supersampling).
//!
//! One sample a pixel goes through its centre. k² samples put one jittered point in each cell
//! of a k × k grid over the pixel; any other number jitters over the whole pixel. The jitter
//! comes from a hash of the seed, the pixel and the sample's index, so every run, on any number
//! of threads, gives the same image.
//!
//! Course book: [Chapter 5, reflection and refraction](../../../../../docs/book/ch05-reflection-refraction.html) (`docs/src/ch05-reflection-refraction.md`).

use crate::real::Real;

// ANCHOR: ch5_sample_position
/// The position inside pixel (x, y) of sample `s` of `n`, as (dx, dy) ∈ [0, 1)², (½, ½) being
/// the centre.
#[inline]
#[must_use]
pub fn sample_position(seed: u64, n: u32, x: u32, y: u32, s: u32) -> (Real, Real) {
    if n <= 1 {
        return (0.5, 0.5);
    }
    let h = mix(seed ^ mix(((y as u64) << 32 | x as u64) ^ mix(s as u64)));
    let (jx, jy) = (unit(h), unit(mix(h)));
    let k = (n as f64).sqrt().round() as u32;
    if k * k == n {
        let (sx, sy) = (s % k, s / k);
        ((sx as Real + jx) / k as Real, (sy as Real + jy) / k as Real)
    } else {
        (jx, jy)
    }
}
// ANCHOR_END: ch5_sample_position

/// A well-mixed 64-bit hash (the SplitMix64 finaliser).
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A number in [0, 1) from a hash.
fn unit(h: u64) -> Real {
    (h >> 11) as Real * (1.0 / (1u64 << 53) as Real)
}
