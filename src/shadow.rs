//! Chapter 4 — shadows (notes: "Shadowing").
//!
//! From a hit point P, a feeler ray towards the light at L:
//!
//! ```text
//! S(u) = P + (L − P)·u
//! ```
//!
//! u = 0 is P and u = 1 is the light. An opaque object met with u ∈ ]0, 1] puts P in that
//! light's shadow: the light's diffuse and specular terms are dropped and only ambient light
//! remains. An object beyond the light (u > 1) or behind P (u ≤ 0) casts no shadow. A
//! translucent object in between lets through its transmission share of the light (no
//! caustics: the feeler is not bent). The feeler starts from an offset origin so that it does
//! not meet the surface it leaves (see [`crate::offset`]).
//!
//! [`transmittance`] is the brute-force form, every object in turn; the renderer asks the
//! acceleration structure instead ([`crate::accel::Accelerator::transmittance`]), which skips
//! the objects the feeler cannot meet and returns exactly the same share.
//!
//! ```toml
//! [[lights]]
//! position = [5.0, 8.0, 5.0]
//! shadows = true        # false: no feeler rays for this light
//! ```

use crate::material::Material;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::shapes::{Formula, Hits, Object};

/// True when one of a feeler's hits lies between its start and the light: u ∈ ]u_min, 1].
#[must_use]
pub fn blocks(hits: &Hits, u_min: Real) -> bool {
    hits.as_slice().iter().any(|h| h.t > u_min && h.t <= 1.0)
}

/// The share of a light that reaches the start of the feeler `S(u) = origin + (L − origin)·u`:
/// 1 when nothing lies between, 0 behind an opaque object, and the product of the
/// transmission coefficients of the translucent objects crossed with u ∈ ]u_min, 1].
#[must_use]
pub fn transmittance(
    objects: &[Object],
    materials: &[Material],
    origin: Vec3,
    light: Vec3,
    u_min: Real,
    formula: Formula,
) -> Real {
    let feeler = Ray::new(origin, light - origin); // S(u) = P + (L − P)u
    let mut share = 1.0;
    for object in objects {
        if blocks(&object.intersect(&feeler, formula), u_min) {
            share *= materials[object.material].transmission;
            if share == 0.0 {
                break;
            }
        }
    }
    share
}
