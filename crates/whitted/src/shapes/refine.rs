//! The f32 build's last step of a ray's nearest hit: its t refined by one step of Newton's
//! method in f64, so that a huge object seen from close by is hit where it is (the trade
//! page's fix (c₂), `docs/src/tradeoff.md`: "A huge object seen from close by").
//!
//! A sphere of radius R placed by M is met in object space, where M⁻¹ carries the eye h above
//! its surface to the distance 1 + h/R from the centre. In f32 that number near 1 is rounded
//! to 1.2e-7, and the unit sphere's c = |e′|² − 1 keeps only what is left of h/R: the hit is
//! off by up to R·u world units (u = 6e-8), 6e-4 for a planet of radius 1e4, 0.08% of an eye
//! 0.79 above it. No f32 formula on the object-space ray can do better, since the ray itself
//! has lost it. So, once the notes' formulas have found the nearest hit in f32, its point is
//! carried into object space once more, in f64, by M⁻¹ kept in f64
//! ([`WideInverse`](crate::transform::WideInverse)), and t takes one step of Newton's method
//! there:
//!
//! ```text
//! P = M⁻¹(e + d·t)  (f64)      d′ = M⁻¹d      t ← t − F(P) / (∇F(P)·d′)
//! ```
//!
//! where F(P) = 0 is the generic equation of the part hit ([`Surface`]): |P|² − 1 for the
//! sphere, x² + y² − 1 for the tube, x² + y² − (1 − z)² for the cone, z − k for a cap or a
//! base, n·P − d for a facet. One step from the f32 root leaves an error of about
//! (error)²/(distance to the other root), far below f32's spacing, and t is rounded to f32
//! once. The hit's normal, part and side stay those the f32 formulas found.
//!
//! Only the hit a ray shows is refined, as the query that found it carries its normal to the
//! world ([`crate::shapes::Object::refine`]): the hits that lose to it and the feelers' hits
//! stay as the formulas found them. And the step is taken only where the f32 root has lost
//! digits that matter, the ray's origin much farther from the object's centre than from the
//! hit, and where it is safe (see [`refine`]): an ordinary view pays one comparison per ray,
//! and its f32 image does not change. Only [`Numerics::Robust`] refines:
//! [`Numerics::Textbook`] keeps the notes' formulas as printed, with their errors. In the f64
//! build, which holds the planet to R·u = 1e-12, [`refine`] returns t untouched and M⁻¹ in f64
//! is not kept: not one number of an f64 image changes.
//!
//! Course book: [The speed–accuracy trade](../../../../../docs/book/tradeoff.html) (`docs/src/tradeoff.md`).

use super::quadratic::Numerics;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::transform::Placement;

/// The generic equation F(P) = 0 of one part of a shape, which [`refine`] evaluates in f64.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Surface {
    /// The unit sphere: |P|² − 1.
    Sphere,
    /// The cylinder's wall, the unit tube about z: x² + y² − 1.
    Tube,
    /// The cone's wall, apex (0, 0, 1): x² + y² − (1 − z)².
    Cone,
    /// The plane z = k of a cap or of the cone's base: z − k.
    Level(Real),
    /// A facet n·P = d: n·P − d.
    Facet(Vec3, Real),
}

#[cfg(feature = "f32")]
impl Surface {
    /// Along the line P(t) = e′ + d′·t, at the point `p` = P(t): F(P) and its first and
    /// second derivatives in t, F′ = ∇F·d′ and F″ = d′ᵀ·H·d′ (H the Hessian of F), in f64.
    #[inline]
    fn along(self, p: glam::DVec3, d: glam::DVec3) -> (f64, f64, f64) {
        match self {
            Surface::Sphere => (
                p.length_squared() - 1.0,
                2.0 * p.dot(d),
                2.0 * d.length_squared(),
            ),
            Surface::Tube => (
                p.x * p.x + p.y * p.y - 1.0,
                2.0 * (p.x * d.x + p.y * d.y),
                2.0 * (d.x * d.x + d.y * d.y),
            ),
            Surface::Cone => {
                let w = 1.0 - p.z;
                (
                    p.x * p.x + p.y * p.y - w * w,
                    2.0 * (p.x * d.x + p.y * d.y + w * d.z),
                    2.0 * (d.x * d.x + d.y * d.y - d.z * d.z),
                )
            }
            Surface::Level(k) => (p.z - f64::from(k), d.z, 0.0),
            Surface::Facet(n, c) => {
                let n = n.as_dvec3();
                (n.dot(p) - f64::from(c), n.dot(d), 0.0)
            }
        }
    }
}

/// How much farther from the object's centre than from the hit the ray's origin must be for
/// [`refine`] to take its step (see there).
pub const FAR_FROM_CENTRE: Real = 16.0;

/// The t of the visible hit of the world `ray` with a shape placed by `placement` (found by
/// the f32 formulas), refined by one Newton step in f64 on the equation `surface()` of the
/// part it hit, the hit point carried into object space by M⁻¹ in f64
/// ([`Placement::wide_inv`]).
///
/// The step is taken where the f32 root has lost digits that matter. Rounding the
/// object-space origin e′ = M⁻¹e costs u·|e′| in object space, which M carries back to about
/// u·|e − c| in the world, c = M·0 the object's centre, whatever M's scales: against the
/// distance |d|·t to the hit, a relative error of u·|e − c|/(|d|·t). So the step is taken
/// only when |e − c| > [`FAR_FROM_CENTRE`]·|d|·t (a planet 0.79 below an eye 1e4 from its
/// centre); elsewhere the f32 root is already good to about 17·u, and a ray pays one
/// comparison.
///
/// Along the ray F is a quadratic (linear for a plane) whose other root lies 2|F′|/|F″| away
/// from this one; the step F/F′ is taken when it is also shorter than a quarter of that,
/// where Newton's method from t comes closer to the root it started near (not near a graze,
/// where the two roots meet and F′ vanishes).
#[cfg(feature = "f32")]
#[inline(always)]
#[must_use]
pub fn refine(
    t: Real,
    placement: &Placement,
    ray: &Ray,
    numerics: Numerics,
    surface: impl FnOnce() -> Option<Surface>,
) -> Real {
    let Some(surface) = surface() else {
        return t;
    };
    let centre = placement.m().w_axis.truncate();
    let reach = FAR_FROM_CENTRE * t;
    let far = (ray.origin - centre).length_squared() > reach * reach * ray.dir.length_squared();
    if far && numerics == Numerics::Robust {
        newton_step(t, placement, ray, surface)
    } else {
        t
    }
}

/// The step of [`refine`], once it is to be taken (kept out of line: most rays never take it).
#[cfg(feature = "f32")]
#[inline(never)]
fn newton_step(t: Real, placement: &Placement, ray: &Ray, surface: Surface) -> Real {
    // the hit point in f64, carried by M⁻¹ in f64; the direction needs no more than f32 (it
    // only gives the step's slope, to a relative 1e-7)
    let t_wide = f64::from(t);
    let p = ray.origin.as_dvec3() + ray.dir.as_dvec3() * t_wide;
    let p = placement.wide_inv().0.transform_point3(p);
    let d = placement.inv().transform_vector3(ray.dir).as_dvec3();
    let (f, slope, curvature) = surface.along(p, d);
    let step = f / slope;
    if step.is_finite() && (step * curvature).abs() < slope.abs() / 2.0 {
        (t_wide - step) as Real
    } else {
        t
    }
}

/// The t as the formulas found it: the f64 build needs no refinement (see the module's
/// documentation).
#[cfg(not(feature = "f32"))]
#[inline]
#[must_use]
pub fn refine(
    t: Real,
    _placement: &Placement,
    _ray: &Ray,
    _numerics: Numerics,
    _surface: impl FnOnce() -> Option<Surface>,
) -> Real {
    t
}
