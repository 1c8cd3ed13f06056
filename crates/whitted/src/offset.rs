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
//! | [`Offset::ErrorBound`] (default) | move P back onto the surface, then along the normal by a bound on its rounding error, to the side the new ray leaves by |
//!
//! The error bound works in two steps, after the idea of pbrt-v4 ("Managing Rounding Error")
//! and Wächter & Binder (Ray Tracing Gems, ch. 6). The computed P = e + d·t is off the surface
//! by an error that grows with |e| and |d·t|: a camera 1e4 units away puts every hit point
//! ~1e4·u off its surface. So P is first moved back onto the surface in object space
//! ([`crate::shapes::Object::reproject`]), whose error depends only on the sizes of P and of
//! the placement M. Then the origin is pushed along the normal by a bound on that error,
//! δ = γ_k·(|M|·(|q|, 1) + |M|·|M⁻¹|·(|P|, 1)) with γ_k = k·u/(1 − k·u), u the unit roundoff
//! and k = [`ERROR_OPS`] roundings. The push is tiny near the origin and grows with the scene's
//! coordinates, so it works at 1e-3 and at 1e4 units alike, without the camera's distance
//! inflating it.
//!
//! Course book: [Chapter 4, shadows](../../../../docs/book/ch04-shadows.html) (`docs/src/ch04-shadows.md`).

use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::shapes::{Hit, Object};

/// How secondary rays leave a surface.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
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

    // ANCHOR: ch4_spawn
    /// The origin and the smallest accepted t of a ray leaving the point `p` (computed as
    /// `e + d·t` from a ray of origin `e`, direction `d`, at parameter `t`) of a surface with
    /// unit normal `n`, along `dir`.
    #[inline]
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
                let push = hit.normal.abs().dot(hit.error);
                (hit.refined + hit.normal * (side * push), 0.0)
            }
        }
    }
    // ANCHOR_END: ch4_spawn
}

/// The three strategies by name (`--offset fixed|scaled|error-bound`), each with its
/// default ε.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum OffsetKind {
    /// [`Offset::Fixed`] with ε = [`Offset::FIXED_EPSILON`].
    Fixed,
    /// [`Offset::Scaled`] with ε = [`Offset::SCALED_EPSILON`].
    Scaled,
    /// [`Offset::ErrorBound`] (the default).
    #[default]
    ErrorBound,
}

impl OffsetKind {
    /// The three, the classic first.
    pub const ALL: [OffsetKind; 3] = [
        OffsetKind::Fixed,
        OffsetKind::Scaled,
        OffsetKind::ErrorBound,
    ];

    /// The strategy with its default ε.
    #[must_use]
    pub fn offset(self) -> Offset {
        match self {
            OffsetKind::Fixed => Offset::Fixed(Offset::FIXED_EPSILON),
            OffsetKind::Scaled => Offset::Scaled(Offset::SCALED_EPSILON),
            OffsetKind::ErrorBound => Offset::ErrorBound,
        }
    }

    /// The name used on the command line and in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            OffsetKind::Fixed => "fixed",
            OffsetKind::Scaled => "scaled",
            OffsetKind::ErrorBound => "error-bound",
        }
    }
}

/// A hit point with what the offset strategies need to know about how it was computed.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SpawnPoint {
    /// The hit point P = e + d·t as the ray computed it.
    pub p: Vec3,
    /// The unit geometric normal there (either side).
    pub normal: Vec3,
    /// P moved back onto the surface (see [`crate::shapes::Object::reproject`]).
    pub refined: Vec3,
    /// A componentwise bound on the rounding error of `refined`, already multiplied by γ.
    pub error: Vec3,
}

impl SpawnPoint {
    /// The spawn point of `hit`, found by `ray` on `object`.
    #[must_use]
    pub fn new(object: &Object, ray: &Ray, hit: &Hit) -> Self {
        let p = ray.at(hit.t);
        let (refined, magnitude) = object.reproject(p, hit.part);
        Self {
            p,
            normal: hit.normal,
            refined,
            error: gamma(ERROR_OPS) * magnitude,
        }
    }
}

/// The number of roundings the error bound allows for: the projection onto the surface (about
/// six), the way back through M (three), the way into object space of the next ray (three) and
/// its own intersection arithmetic, with a margin.
pub const ERROR_OPS: Real = 32.0;

/// γ_k = k·u/(1 − k·u) for the unit roundoff u of [`Real`].
#[must_use]
pub fn gamma(k: Real) -> Real {
    let u = Real::EPSILON / 2.0;
    k * u / (1.0 - k * u)
}
