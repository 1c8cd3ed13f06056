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
//! Small functions make the chapter: [`in_front`] says whether a light can reach P at all,
//! [`feeler`] builds S(u) (a [`Feeler`] keeps it with the smallest u that counts), [`between`]
//! says whether a hit's u lies in ]u_min, 1] (and [`blocks`] whether one of an object's hits
//! does), and [`transmittance`] multiplies the transmissions of the objects that block. Which
//! objects to test is the road's [`Query`](crate::render::Query): every object in turn
//! ([`EveryObject`](crate::render::EveryObject)), or only those whose boxes the feeler meets
//! ([`crate::accel`]), with the same answer.
//!
//! ```toml
//! [[lights]]
//! position = [5.0, 8.0, 5.0]
//! shadows = true        # false: no feeler rays for this light
//! ```
//!
//! Course book: [Chapter 4, shadows](../../../../docs/book/ch04-shadows.html) (`docs/src/ch04-shadows.md`).

use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::shapes::Hits;

/// True when the light at L lies in front of the surface at P with the shading normal n:
/// n·(L − P) > 0. A light behind the surface cannot reach P, so no feeler goes towards it.
#[inline]
#[must_use]
pub fn in_front(n: Vec3, p: Vec3, light: Vec3) -> bool {
    n.dot(light - p) > 0.0
}

/// The feeler S(u) = P + (L − P)·u from the point P towards the light at L: u = 0 at P, u = 1
/// at the light, so an object between them is met with u ∈ ]0, 1].
#[inline]
#[must_use]
pub fn feeler(p: Vec3, light: Vec3) -> Ray {
    // BEGIN SOLUTION feeler_ray
    Ray::new(p, light - p)
    // END SOLUTION
}

// ANCHOR: ch4_feeler_type
/// A feeler towards a light, and the smallest u that counts.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Feeler {
    /// S(u) = P′ + (L − P′)·u from the offset start P′: u = 0 at P′, u = 1 at the light.
    pub ray: Ray,
    /// Hits count for u ∈ ]u_min, 1].
    pub u_min: Real,
}
// ANCHOR_END: ch4_feeler_type

/// True when a hit at u along a feeler lies between its start and the light: u ∈ ]u_min, 1]
/// (u_min = 0 unless the start is left on the surface, see [`crate::offset`]). A hit behind the
/// start (u ≤ u_min) or beyond the light (u > 1) casts no shadow.
#[inline]
#[must_use]
pub fn between(u: Real, u_min: Real) -> bool {
    // BEGIN SOLUTION blocks_light
    u > u_min && u <= 1.0
    // END SOLUTION
}

/// True when an object blocks a feeler: one of its hits lies [`between`] the feeler's start and
/// the light.
#[inline]
#[must_use]
pub fn blocks(hits: &Hits, u_min: Real) -> bool {
    hits.as_slice().iter().any(|h| between(h.t, u_min))
}

/// The share of a light that reaches the start of a feeler, from the transmissions k_t of the
/// objects it crosses (in scene order): 1 when it crosses none, their product otherwise, 0
/// as soon as one is opaque (k_t = 0).
#[must_use]
pub fn transmittance(crossed: impl IntoIterator<Item = Real>) -> Real {
    // BEGIN SOLUTION transmittance
    let mut share = 1.0;
    for k_t in crossed {
        share *= k_t;
        if share == 0.0 {
            break;
        }
    }
    share
    // END SOLUTION
}
