//! Chapter 5 — reflection and refraction (notes: "Reflection and Refraction", "Lighting Equations").
//!
//! A ray with unit direction d meets a surface with unit normal n. The mirror ray leaves along
//!
//! ```text
//! l = d − 2(d·n)·n
//! ```
//!
//! (the notes write the hit point r(t₀) where the direction d belongs: an erratum). The
//! transmitted ray obeys Snell's law, sin θ₁/c₁ = sin θ₂/c₂, that is n₁·sin θ₁ = n₂·sin θ₂ with
//! indices n = c₀/c. With η = n₁/n₂ and cos θ₁ = −d·n (n facing the incoming ray):
//!
//! ```text
//! sin²θ₂ = η²·(1 − cos²θ₁)
//! t = η·d + (η·cos θ₁ − cos θ₂)·n       cos θ₂ = √(1 − sin²θ₂)
//! ```
//!
//! Past the critical angle there is no transmitted ray: total internal reflection. It starts
//! where sin θ₂ = 1, (c₂/c₁)·sin θc = 1, i.e. sin θc = n₂/n₁ (the notes print c₁/c₂, which
//! gives sin θc > 1 for glass to air: an erratum), so a ray with sin θ₁ > n₂/n₁ is all
//! reflected. The notes' index n₂₁ = c₁/c₂ of medium 2 relative to medium 1 is n₂/n₁ in
//! absolute indices n = c₀/c.
//!
//! ```toml
//! [materials.glass]
//! transmission = 0.9
//! reflection = 0.1
//! ior = 1.5
//! ```
//!
//! Course book: [Chapter 5, reflection and refraction](../../../../docs/book/ch05-reflection-refraction.html) (`docs/src/ch05-reflection-refraction.md`).

use crate::real::{Real, Vec3};

/// l = d − 2(d·n)·n: the mirror direction of the incoming direction d about the unit normal n.
///
/// The notes' lighting equation reflects the direction d a ray *arrives* along, so l leaves on
/// the side the ray came from, whichever way n points. Chapter 3's highlight
/// ([`crate::shading::mirror`]) reflects s, the unit vector *towards* the light, r = 2(n·s)·n
/// − s: the same reflection of the opposite vector, r = −reflect(s, n). Each chapter keeps the
/// notes' own form of it.
#[must_use]
pub fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    // BEGIN SOLUTION mirror_ray
    d - 2.0 * d.dot(n) * n
    // END SOLUTION
}

/// The transmitted direction for the unit incoming direction `d`, the unit normal `n` facing
/// the incoming ray (d·n ≤ 0), going from index n₁ into index n₂ (Snell: n₁·sin θ₁ = n₂·sin θ₂);
/// `None` under total internal reflection, when θ₁ is past the critical angle
/// ([`critical_angle_sine`]).
#[must_use]
pub fn refract(d: Vec3, n: Vec3, n1: Real, n2: Real) -> Option<Vec3> {
    // BEGIN SOLUTION refract
    let cos1 = -d.dot(n);
    let sin1_sq = (1.0 - cos1 * cos1).max(0.0);
    if let Some(sin_c) = critical_angle_sine(n1, n2)
        && sin1_sq > sin_c * sin_c
    {
        return None; // sin θ₁ > sin θc: total internal reflection
    }
    let eta = n1 / n2;
    let sin2_sq = eta * eta * sin1_sq; // sin²θ₂ = η²·sin²θ₁
    let cos2 = (1.0 - sin2_sq).max(0.0).sqrt();
    Some(eta * d + (eta * cos1 - cos2) * n)
    // END SOLUTION
}

/// sin θc = n₂/n₁, the sine of the critical angle going from index n₁ into index n₂, where the
/// transmitted ray would leave at θ₂ = 90°; `None` when n₁ ≤ n₂ (no total internal reflection
/// is possible). In the notes' speeds, (c₂/c₁)·sin θc = 1 (they print c₁/c₂: an erratum).
#[must_use]
pub fn critical_angle_sine(n1: Real, n2: Real) -> Option<Real> {
    // BEGIN SOLUTION critical_angle
    (n1 > n2).then(|| n2 / n1)
    // END SOLUTION
}

/// The critical angle θc itself, in radians: asin([`critical_angle_sine`]).
#[must_use]
pub fn critical_angle(n1: Real, n2: Real) -> Option<Real> {
    critical_angle_sine(n1, n2).map(Real::asin)
}

/// The indices (n₁, n₂) for a ray hitting a surface of index `ior` in air: entering goes from
/// air into the material, leaving from the material into air.
#[must_use]
pub fn indices(entering: bool, ior: Real) -> (Real, Real) {
    // BEGIN SOLUTION refractive_indices
    if entering { (1.0, ior) } else { (ior, 1.0) }
    // END SOLUTION
}
