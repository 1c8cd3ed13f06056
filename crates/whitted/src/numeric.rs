//! Small numerical helpers shared by every chapter.
//!
//! [`normalize`] divides by the largest component before taking the length, so vectors as
//! large as 1e30 or as small as 1e-30 (in f32, where their squared length would overflow or
//! underflow) still come out unit length. The naive form `v / |v|` is kept as
//! [`normalize_naive`] so its failure can be shown.
//!
//! Course book: [The speed–accuracy trade](../../../../docs/book/tradeoff.html) (`docs/src/tradeoff.md`).

use crate::real::{Real, Vec3};

/// v / |v|, computed after scaling v by its largest absolute component so that |v|² neither
/// overflows nor underflows. Returns the zero vector for a zero or non-finite input.
#[inline]
#[must_use]
pub fn normalize(v: Vec3) -> Vec3 {
    let m = v.abs().max_element();
    if !(m > 0.0 && m.is_finite()) {
        return Vec3::ZERO;
    }
    let w = v / m;
    w / w.length()
}

/// The textbook v / |v|: fails (0 or NaN) when |v|² overflows or underflows.
#[inline]
#[must_use]
pub fn normalize_naive(v: Vec3) -> Vec3 {
    v / (v.x * v.x + v.y * v.y + v.z * v.z).sqrt()
}

/// The sign of x as ±1, with +1 for +0 (and −1 for −0), so that b + sign(b)·√Δ never cancels.
#[inline]
#[must_use]
pub fn sign(x: Real) -> Real {
    (1.0 as Real).copysign(x)
}
