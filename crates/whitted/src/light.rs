//! Chapter 3 — point lights (notes: "Shading").
//!
//! A light at L with RGB intensity I_p. Its contribution at distance d is divided by
//! a0 + a1·d + a2·d² to model depth (the default (1, 0, 0) means no attenuation).
//!
//! ```toml
//! [[lights]]
//! position = [-5.0, 8.0, 6.0]
//! intensity = [0.8, 0.8, 0.8]
//! attenuation = [1.0, 0.0, 0.0]
//! shadows = true
//! ```
//!
//! Course book: [Chapter 3, shading](../../../../docs/book/ch03-shading.html) (`docs/src/ch03-shading.md`).

use crate::real::{Real, Vec3};

/// A point light.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Light {
    /// Its position L.
    pub position: Vec3,
    /// I_p per channel.
    pub intensity: Vec3,
    /// (a0, a1, a2) of the attenuation a0 + a1·d + a2·d².
    pub attenuation: [Real; 3],
    /// Whether chapter 4 casts feeler rays towards it.
    pub shadows: bool,
}

impl Light {
    /// A white light of intensity 1 at `position`, no attenuation, casting shadows.
    #[must_use]
    pub fn white(position: Vec3) -> Self {
        Self {
            position,
            intensity: Vec3::ONE,
            attenuation: [1.0, 0.0, 0.0],
            shadows: true,
        }
    }

    /// The factor 1 / (a0 + a1·d + a2·d²) for a point at distance d from the light. The
    /// denominator is kept above machine epsilon, so a light with a0 = 0 stays finite at d = 0.
    #[must_use]
    pub fn attenuation_at(&self, d: Real) -> Real {
        // BEGIN SOLUTION attenuation
        let [a0, a1, a2] = self.attenuation;
        1.0 / (a0 + a1 * d + a2 * d * d).max(Real::EPSILON)
        // END SOLUTION
    }
}
