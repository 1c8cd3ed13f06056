//! Leaving a surface without hitting it again (chapters 4 and 5).
//!
//! A feeler, mirror or refracted ray starts at a hit point P that was computed with rounding
//! error: P may lie a little below the surface, and the new ray then "hits" the surface it
//! starts from at t ≈ 0. On a lit surface this shows as speckled false shadows ("shadow acne").
//! Three ways out, selectable per render:
//!
//! | strategy | what it does |
//! |---|---|
//! | [`Offset::Fixed`] | the classic: start at P, accept hits only for t > ε (ε in world units, along a unit direction) |
//! | [`Offset::Scaled`] | move P along the normal by ε·max(1, ‖P‖∞), to the side the new ray leaves by |
//! | [`Offset::ErrorBound`] (default) | move P along the normal by a bound on its rounding error, to the side the new ray leaves by |
//!
//! The error bound follows the idea of pbrt-v4 ("Managing Rounding Error"): the computed
//! P = e + d·t carries an absolute error of a few ulps of each of its terms, so per component
//! δ = γ·(|e| + |d·t| + |P|) with γ = k·u/(1 − k·u), u the unit roundoff and k a small count of
//! operations (here 64, covering the transform into object space, the root and the way back).
//! The offset along n is |n|·δ, which is tiny near the origin and grows with the scene's scale,
//! so it works at 1e-3 and at 1e4 units alike.

use crate::real::{Real, Vec3};

/// How secondary rays leave a surface.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Offset {
    /// Accept only t > ε from the unmoved hit point (ε in world units).
    Fixed(Real),
    /// Move the origin by ε·max(1, ‖P‖∞) along the normal.
    Scaled(Real),
    /// Move the origin by a bound on the rounding error of P along the normal.
    #[default]
    ErrorBound,
}

impl Offset {
    /// The classic fixed ε.
    pub const FIXED_EPSILON: Real = 1e-4;
    /// The relative ε of [`Offset::Scaled`].
    pub const SCALED_EPSILON: Real = 1e-4;

    /// Parses `fixed`, `scaled` or `error-bound`.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "fixed" => Some(Offset::Fixed(Self::FIXED_EPSILON)),
            "scaled" => Some(Offset::Scaled(Self::SCALED_EPSILON)),
            "error-bound" => Some(Offset::ErrorBound),
            _ => None,
        }
    }

    /// The origin and the smallest accepted t of a ray leaving the point `p` (computed as
    /// `e + d·t` from a ray of origin `e`, direction `d`, at parameter `t`) of a surface with
    /// unit normal `n`, along `dir`.
    #[must_use]
    pub fn spawn(&self, hit: &SpawnPoint, dir: Vec3) -> (Vec3, Real) {
        let side = if dir.dot(hit.normal) >= 0.0 {
            1.0
        } else {
            -1.0
        };
        match *self {
            Offset::Fixed(eps) => (hit.p, eps / dir.length()),
            Offset::Scaled(eps) => {
                let scale = hit.p.abs().max_element().max(1.0);
                (hit.p + hit.normal * (side * eps * scale), 0.0)
            }
            Offset::ErrorBound => {
                let delta = error_bound(hit);
                let push = hit.normal.abs().dot(delta);
                (hit.p + hit.normal * (side * push), 0.0)
            }
        }
    }
}

/// A hit point with what the offset strategies need to know about how it was computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpawnPoint {
    /// The hit point P = e + d·t.
    pub p: Vec3,
    /// The unit geometric normal there (either side).
    pub normal: Vec3,
    /// The origin e of the ray that found P.
    pub ray_origin: Vec3,
    /// d·t, the step from e to P.
    pub step: Vec3,
}

/// γ_k = k·u/(1 − k·u) for the unit roundoff u of [`Real`].
#[must_use]
pub fn gamma(k: Real) -> Real {
    let u = Real::EPSILON / 2.0;
    k * u / (1.0 - k * u)
}

/// A componentwise bound on the rounding error of P = e + d·t.
#[must_use]
pub fn error_bound(hit: &SpawnPoint) -> Vec3 {
    gamma(64.0) * (hit.ray_origin.abs() + hit.step.abs() + hit.p.abs())
}
