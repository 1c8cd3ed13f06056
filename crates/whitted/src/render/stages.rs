//! The pictures of single exercises: what chapters 3 and 5 draw while they are written.
//!
//! A chapter's own picture needs all of its exercises (chapter 3's colour is the local light
//! of exercise 3.7, which calls every exercise before it). Each view here calls only one
//! exercise and the ones before it, so that a student sees the quantity they have just written
//! over the chapter's scene, and the course book shows the same picture beside it. A view
//! shows the quantity itself, never a sum the next exercises write: the picture of 3.3 is each
//! light's cosine max(n·s, 0), not the diffuse term I_p·att·ρd·max(n·s, 0) of exercise 3.6.
//!
//! | view | exercise | the colour at a hit |
//! |---|---|---|
//! | `ambient` | 3.1 | I_a = ρa·I_m |
//! | `attenuation` | 3.2 | Σ_lights colour(i) · att_i, att = 1/(a0 + a1·d + a2·d²) |
//! | `diffuse` | 3.3 | Σ_lights colour(i) · max(n·s_i, 0) |
//! | `mirror` | 3.4 | (r + 1)/2 for the first light, r = 2(n·s)·n − s |
//! | `highlight` | 3.5 | Σ_lights colour(i) · max(r_i·v, 0)^f (zero for ρs = 0) |
//! | `direct` | 3.6 | Σ_lights I_d + I_s, without I_a and without shadows |
//! | `refracted` | 5.3 | (t + 1)/2 for the transmitted direction t of a translucent hit |
//! | `mirrored` | 5.4 | (l + 1)/2 for the mirror ray l = d − 2(d·n)·n of a reflective hit |
//!
//! colour(i) is the shadow mask's colour of light i ([`light_colour`]: red, green, blue …). A
//! factor that must lie in [0, 1] and does not (a cosine left unclamped, a negative highlight)
//! paints its pixel [`OUT_OF_RANGE`], which no right formula gives. A hit these views have
//! nothing to say of (no light, a material that neither reflects nor transmits) is
//! [`NOTHING`]; a miss is the background. Every view is a function of the shading point, so a
//! tile rendered alone comes out as in the whole image.
//!
//! Course book: [Chapter 3, shading](../../../../../docs/book/ch03-shading.html) (`docs/src/ch03-shading.md`).

use super::options::View;
use super::query::ShadingPoint;
use super::scales::light_colour;
use crate::camera::direction_colour;
use crate::light::Light;
use crate::optics;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading;

/// The colour of a factor outside [0, 1]: magenta.
pub const OUT_OF_RANGE: Vec3 = Vec3::new(1.0, 0.0, 1.0);

/// The colour of a hit a view has nothing to show of: the shadow mask's dim grey.
pub const NOTHING: Vec3 = Vec3::splat(0.12);

/// Whether `view` is one of this module's pictures of a single exercise ([`View::STAGES`]).
#[must_use]
pub fn is_stage(view: View) -> bool {
    View::STAGES.contains(&view)
}

/// The colour of the stage view `view` at the shading point `s` of `scene` (see the module's
/// table); [`NOTHING`] for a view that is not a stage.
#[must_use]
pub fn colour(view: View, s: &ShadingPoint, scene: &Scene) -> Vec3 {
    let (lights, ambient) = (scene.lights.as_slice(), scene.ambient);
    let v = -s.d; // towards the viewer
    match view {
        View::Ambient => shading::ambient(s.material, ambient),
        View::Attenuation => per_light(s, lights, |light, d, _| {
            let att = light.attenuation_at(d);
            // a0 + a1·d + a2·d² ≥ a0 > 0: att is positive and finite
            (att.is_finite() && att >= 0.0).then_some(att.min(1.0))
        }),
        View::Diffuse => per_light(s, lights, |_, _, dir| unit(shading::lambert(s.n, dir))),
        View::Mirror => match lights.first().and_then(|l| towards(s.p, l)) {
            Some((_, dir)) => direction_colour(shading::mirror(dir, s.n)),
            None => NOTHING,
        },
        View::Highlight => {
            if s.material.specular == Vec3::ZERO {
                return NOTHING; // ρs = 0: the material has no highlight
            }
            let f = s.material.shininess;
            per_light(s, lights, |_, _, dir| {
                unit(shading::highlight(s.n, dir, v, f))
            })
        }
        View::Direct => lights
            .iter()
            .map(|light| shading::direct(s.material, light, s.p, s.n, v))
            .sum(),
        View::Refracted => {
            if !s.material.is_translucent() {
                return NOTHING;
            }
            // the side that was hit, as the shape found it
            let (n1, n2) = optics::indices(s.hit.entering, s.material.ior);
            match optics::refract(s.d, s.n, n1, n2) {
                Some(t) => direction_colour(t),
                None => Vec3::ONE, // total internal reflection: white
            }
        }
        View::Mirrored => {
            if s.material.reflection > 0.0 {
                direction_colour(optics::reflect(s.d, s.n))
            } else {
                NOTHING
            }
        }
        _ => NOTHING,
    }
}

/// The distance d = ‖L − P‖ to `light` and the unit direction s = (L − P)/d; `None` for a
/// light at P.
fn towards(p: Vec3, light: &Light) -> Option<(Real, Vec3)> {
    let to_light = light.position - p;
    let d = to_light.length();
    (d > 0.0).then(|| (d, to_light / d))
}

/// Σ_lights colour(i) · factor_i, where `factor(light, d, s)` is light i's factor (`None` when
/// it lies outside its range: then the pixel is [`OUT_OF_RANGE`]); [`NOTHING`] without lights.
fn per_light(
    s: &ShadingPoint,
    lights: &[Light],
    factor: impl Fn(&Light, Real, Vec3) -> Option<Real>,
) -> Vec3 {
    if lights.is_empty() {
        return NOTHING;
    }
    let mut sum = Vec3::ZERO;
    for (i, light) in lights.iter().enumerate() {
        let Some((d, dir)) = towards(s.p, light) else {
            continue;
        };
        match factor(light, d, dir) {
            Some(x) => sum += light_colour(i) * x,
            None => return OUT_OF_RANGE,
        }
    }
    sum.min(Vec3::ONE)
}

/// `x` when it lies in [0, 1] (a cosine's or a highlight's range), else `None`.
fn unit(x: Real) -> Option<Real> {
    (0.0..=1.0).contains(&x).then_some(x)
}
