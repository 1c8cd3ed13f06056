//! Chapter 3 — materials (notes: "Shading", "Reflection and Refraction").
//!
//! A material holds, per RGB channel, how much ambient (ρa), diffuse (ρd) and specular (ρs)
//! light it reflects, the specular exponent f, and for chapter 5 its mirror reflection and
//! transmission coefficients and its index of refraction.
//!
//! ```toml
//! [materials.glass]
//! ambient = 0.0
//! diffuse = 0.05
//! specular = 0.6
//! shininess = 200
//! reflection = 0.1
//! transmission = 0.85
//! ior = 1.5
//! ```
//!
//! Course book: [Chapter 3, shading](../../../../docs/book/ch03-shading.html) (`docs/src/ch03-shading.md`).

use crate::real::{Real, Vec3};

/// How a surface answers light.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Material {
    /// ρa per channel.
    pub ambient: Vec3,
    /// ρd per channel.
    pub diffuse: Vec3,
    /// ρs per channel.
    pub specular: Vec3,
    /// The specular exponent f.
    pub shininess: Real,
    /// Share of the mirror-reflected light I_l added to the colour (0 = matte).
    pub reflection: Real,
    /// Share of the transmitted light I_r added to the colour (0 = opaque).
    pub transmission: Real,
    /// Index of refraction relative to the surrounding air.
    pub ior: Real,
}

impl Default for Material {
    /// A matte light grey: ρa = 0.1, ρd = 0.7, ρs = 0.2, f = 32, opaque, no mirror.
    fn default() -> Self {
        Self {
            ambient: Vec3::splat(0.1),
            diffuse: Vec3::splat(0.7),
            specular: Vec3::splat(0.2),
            shininess: 32.0,
            reflection: 0.0,
            transmission: 0.0,
            ior: 1.5,
        }
    }
}

impl Material {
    /// True when the material lets light through (spawns refracted rays, dims shadows).
    #[must_use]
    pub fn is_translucent(&self) -> bool {
        self.transmission > 0.0
    }

    /// The channels where ρa + ρd + ρs exceeds 1 (the notes want the sum to be 1).
    #[must_use]
    pub fn over_unity_channels(&self) -> Vec<&'static str> {
        let sum = self.ambient + self.diffuse + self.specular;
        ["red", "green", "blue"]
            .into_iter()
            .zip(sum.to_array())
            .filter(|&(_, s)| s > 1.0 + 1e-6)
            .map(|(name, _)| name)
            .collect()
    }
}
