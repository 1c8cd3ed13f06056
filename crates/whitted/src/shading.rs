//! Chapter 3 — shading (notes: "Shading").
//!
//! At a hit point with unit normal n, unit vector s towards a light, unit vector v towards the
//! viewer and r the mirror direction of s about n, each RGB channel receives
//!
//! ```text
//! I = ρa·I_m + Σ_lights  I_p / (a0 + a1·d + a2·d²) · ( ρd·max(n·s, 0) + ρs·max(r·v, 0)^f )
//! r = 2(n·s)·n − s
//! ```
//!
//! The notes write n·s and (r·v)^f without clamping; a light behind the surface (n·s < 0) would
//! then *subtract* light, and a negative r·v raised to an even f would add a highlight that
//! does not exist. whitted clamps both at 0 and drops the specular term entirely when n·s ≤ 0
//! (docs/src/errata.md).
//!
//! The normal used for shading faces the viewer: for the plane, an open surface, this means
//! the side the camera sees is lit like a front face; for closed shapes it only matters for
//! rays that travel inside glass.
//!
//! ```toml
//! [ambient]
//! intensity = 0.3
//!
//! [materials.red]
//! ambient = [0.1, 0.0, 0.0]
//! diffuse = [0.6, 0.05, 0.05]
//! specular = 0.3
//! shininess = 40
//! ```
//!
//! Course book: [Chapter 3, shading](../../../../docs/book/ch03-shading.html) (`docs/src/ch03-shading.md`).

use crate::light::Light;
use crate::material::Material;
use crate::real::{Real, Vec3};

/// The ambient term I_a = ρa·I_m, per channel.
#[must_use]
pub fn ambient(material: &Material, ambient_light: Vec3) -> Vec3 {
    // BEGIN SOLUTION ambient
    material.ambient * ambient_light
    // END SOLUTION
}

/// r = 2(n·s)·n − s: the mirror direction of s about the unit normal n.
///
/// The notes' Phong model reflects s, the unit vector from P *towards* the light, so r leaves
/// the surface on the viewer's side and the highlight compares it with v. Chapter 5's mirror
/// ray ([`crate::optics::reflect`]) reflects a ray's direction d *arriving* at the surface,
/// l = d − 2(d·n)·n: the same reflection of the opposite vector, r = −reflect(s, n). Each
/// chapter keeps the notes' own form of it.
#[must_use]
pub fn mirror(s: Vec3, n: Vec3) -> Vec3 {
    // BEGIN SOLUTION mirror_direction
    2.0 * n.dot(s) * n - s
    // END SOLUTION
}

/// max(n·s, 0): the cosine law of the diffuse term, zero for a light behind the surface.
#[must_use]
pub fn lambert(n: Vec3, s: Vec3) -> Real {
    // BEGIN SOLUTION lambert
    n.dot(s).max(0.0)
    // END SOLUTION
}

/// max(r·v, 0)^f: the specular highlight, zero when the light is behind the surface (n·s ≤ 0).
#[must_use]
pub fn highlight(n: Vec3, s: Vec3, v: Vec3, shininess: Real) -> Real {
    // BEGIN SOLUTION highlight
    if n.dot(s) <= 0.0 {
        return 0.0;
    }
    let cos = mirror(s, n).dot(v).max(0.0);
    if cos == 0.0 && shininess > 0.0 {
        return 0.0; // 0^f for f > 0, without the cost of a powf (half the lit points)
    }
    cos.powf(shininess)
    // END SOLUTION
}

/// One light's Phong terms at a point, before shadowing, as [`phong`] computes them: each
/// factor of I_d + I_s = I_p·att·(ρd·max(n·s, 0) + ρs·max(r·v, 0)^f), per channel, and the sum.
/// The ray tree shows these very numbers ([`crate::render::inspect`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Phong {
    /// att = 1/(a0 + a1·d + a2·d²) at the light's distance d.
    pub attenuation: Real,
    /// I_p·att: the light's intensity arriving at P, per channel.
    pub intensity: Vec3,
    /// ρd·max(n·s, 0): the diffuse factor.
    pub diffuse: Vec3,
    /// ρs·max(r·v, 0)^f: the specular factor (zero for a matte material, ρs = 0).
    pub specular: Vec3,
    /// I_d + I_s = I_p·att·(ρd·max(n·s, 0) + ρs·max(r·v, 0)^f): `intensity` × (`diffuse` +
    /// `specular`).
    pub sum: Vec3,
}

// ANCHOR: ch3_phong
/// One light's diffuse and specular contribution at a point P with unit normal n seen from the
/// unit direction v, before shadowing, with its factors: per channel,
/// I_p/(a0 + a1·d + a2·d²)·(ρd·max(n·s, 0) + ρs·max(r·v, 0)^f), for d = ‖L − P‖ and
/// s = (L − P)/d. A light at P itself (d = 0) has no direction s: it adds nothing (every
/// factor but the attenuation is zero).
#[inline]
#[must_use]
pub fn phong(material: &Material, light: &Light, p: Vec3, n: Vec3, v: Vec3) -> Phong {
    // ANCHOR_END: ch3_phong
    // BEGIN SOLUTION direct_light
    let to_light = light.position - p;
    let d = to_light.length();
    let attenuation = light.attenuation_at(d);
    if d == 0.0 {
        return Phong {
            attenuation,
            ..Phong::default()
        };
    }
    let s = to_light / d;
    let diffuse = material.diffuse * lambert(n, s);
    // a matte material (ρs = 0) needs no highlight: ρs·h is 0 for any h in [0, 1]
    let specular = if material.specular == Vec3::ZERO {
        Vec3::ZERO
    } else {
        material.specular * highlight(n, s, v, material.shininess)
    };
    let intensity = light.intensity * attenuation; // I_p·att
    Phong {
        attenuation,
        intensity,
        diffuse,
        specular,
        sum: intensity * (diffuse + specular),
    }
    // END SOLUTION
}

/// I_d + I_s of one light before shadowing: the sum of [`phong`]'s terms.
#[must_use]
pub fn direct(material: &Material, light: &Light, p: Vec3, n: Vec3, v: Vec3) -> Vec3 {
    phong(material, light, p, n, v).sum
}

// ANCHOR: ch3_facing
/// The shading normal: n turned to face against the direction `d` of the ray that hit, towards
/// where it came from. For the plane, an open surface, the side the camera sees is then lit
/// like a front face.
#[must_use]
pub fn facing(n: Vec3, d: Vec3) -> Vec3 {
    if n.dot(d) > 0.0 { -n } else { n }
}
// ANCHOR_END: ch3_facing
