//! Precision: one switch for the whole toolkit.
//!
//! Every chapter computes with [`Real`] and the glam aliases below. By default they are
//! double precision (`f64`, [`glam::DVec3`], [`glam::DMat4`]); building with the cargo feature
//! `f32` turns them all into single precision (`f32`, [`glam::Vec3`], [`glam::Mat4`]), so the
//! same code and the same tests measure what precision costs and buys.
//!
//! ```text
//! cargo test                 # f64
//! cargo test --features f32  # f32
//! ```
//!
//! Course book: [The speed–accuracy trade](../../../../docs/book/tradeoff.html) (`docs/src/tradeoff.md`).

#[cfg(not(feature = "f32"))]
mod imp {
    /// The scalar type of every computation.
    pub type Real = f64;
    /// A 3-vector of [`Real`]: points, directions, normals and RGB colours.
    pub type Vec3 = glam::DVec3;
    /// A homogeneous 4-vector of [`Real`].
    pub type Vec4 = glam::DVec4;
    /// A 3×3 matrix of [`Real`].
    pub type Mat3 = glam::DMat3;
    /// A 4×4 matrix of [`Real`]: placements M, M⁻¹ and (M⁻¹)ᵀ.
    pub type Mat4 = glam::DMat4;
    /// Constants (π and friends) at the chosen precision.
    pub use std::f64::consts;
    /// The name of the precision in use, for reports.
    pub const PRECISION: &str = "f64";
}

#[cfg(feature = "f32")]
mod imp {
    /// The scalar type of every computation.
    pub type Real = f32;
    /// A 3-vector of [`Real`]: points, directions, normals and RGB colours.
    pub type Vec3 = glam::Vec3;
    /// A homogeneous 4-vector of [`Real`].
    pub type Vec4 = glam::Vec4;
    /// A 3×3 matrix of [`Real`].
    pub type Mat3 = glam::Mat3;
    /// A 4×4 matrix of [`Real`]: placements M, M⁻¹ and (M⁻¹)ᵀ.
    pub type Mat4 = glam::Mat4;
    /// Constants (π and friends) at the chosen precision.
    pub use std::f32::consts;
    /// The name of the precision in use, for reports.
    pub const PRECISION: &str = "f32";
}

pub use imp::*;

/// Converts an `f64` (as read from a scene file or written in a test) to [`Real`].
#[inline]
#[must_use]
pub fn real(x: f64) -> Real {
    x as Real
}

/// Builds a [`Vec3`] from three `f64` values.
#[inline]
#[must_use]
pub fn vec3(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(real(x), real(y), real(z))
}

/// Builds a [`Vec3`] from an `[f64; 3]` array.
#[inline]
#[must_use]
pub fn vec3_from(a: [f64; 3]) -> Vec3 {
    vec3(a[0], a[1], a[2])
}
