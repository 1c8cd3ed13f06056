//! What the planet measurement measures: the radii, the angles of the rays and the light of
//! the acne test; the [`Planet`] as the scene loader places it, with what the fixes need; and
//! the camera rays ([`samples`]), the same numbers in every build.

use glam::{DMat4, DVec3};
use whitted::ray::Ray;
use whitted::real::{Real, Vec3, real, vec3};
use whitted::shapes::{Object, Shape};
use whitted::transform::{Placement, Step, rotation_from_z};

use crate::measure::wide;

/// The radii measured (world units).
pub const RADII: [f64; 5] = [1e3, 1e4, 1e5, 1e6, 1e7];
/// The rays' angles below the horizontal, in degrees, steep to grazing. The horizon of a
/// sphere of radius R seen from height h lies √(2h/R) radians below the horizontal: 2.6° for
/// R = 1e3, so every ray here meets every sphere.
pub const ANGLES: [f64; 4] = [90.0, 30.0, 10.0, 3.0];
/// Rays per radius and angle.
pub const RAYS: usize = 1000;
/// The light of the shadow-acne test, high above the patch the rays hit.
pub const LIGHT: [f64; 3] = [400.0, 1000.0, 300.0];

/// A planet of radius R: the sphere as the scene loader places it, and what the fixes need.
pub struct Planet {
    /// R, as the scene file gives it (every radius measured is exact in f32 and f64).
    pub radius: f64,
    /// The sphere placed by M = translate (0, −R, 0) · scale R: its top is the origin.
    pub sphere: Object,
    /// Fix (d): the plane y = 0, tangent to the sphere at its top.
    pub plane: Object,
    /// Fix (b): the centre (0, −R, 0) at the build's precision.
    pub centre: Vec3,
    /// R at the build's precision.
    pub r: Real,
    /// Fix (b′): a point of the surface near the camera, the top (0, 0, 0), chosen once, as a
    /// renderer would once per frame.
    pub anchor: Vec3,
    /// Fix (b′): the outward normal at the anchor, (0, 1, 0).
    pub normal: Vec3,
    /// Fixes (c₁) and (c₂): M⁻¹ = scale 1/R · translate (0, R, 0), built in f64.
    pub wide_inv: DMat4,
}

impl Planet {
    /// The planet of radius `radius`.
    pub fn new(radius: f64) -> Self {
        let steps = [
            Step::Scale(Vec3::splat(real(radius))),
            Step::Translate(vec3(0.0, -radius, 0.0)),
        ];
        let placement = Placement::from_steps(&steps).expect("a non-zero radius");
        let up = Placement::from_steps(&[rotation_from_z(Vec3::Y)]).expect("a rotation");
        Self {
            radius,
            sphere: Object::new(Shape::Sphere, placement),
            plane: Object::new(Shape::Plane, up),
            centre: vec3(0.0, -radius, 0.0),
            r: real(radius),
            anchor: Vec3::ZERO,
            normal: Vec3::Y,
            wide_inv: DMat4::from_scale(DVec3::splat(1.0 / radius))
                * DMat4::from_translation(DVec3::new(0.0, radius, 0.0)),
        }
    }
}

/// One camera ray: the ray at the build's precision and the number of its angle in
/// [`ANGLES`].
pub struct Sample {
    /// The ray, at the build's precision.
    pub ray: Ray,
    /// The number of its angle in [`ANGLES`].
    pub angle: usize,
}

/// The rays of every angle: each from a camera at (x, 1 ± 0.1, z) with |x|, |z| ≤ 1, at a
/// random azimuth. The same f64 numbers in every build (then rounded to [`Real`]).
pub fn samples() -> Vec<Sample> {
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut out = Vec::with_capacity(ANGLES.len() * RAYS);
    for (angle, degrees) in ANGLES.iter().enumerate() {
        let (down, level) = degrees.to_radians().sin_cos();
        for _ in 0..RAYS {
            let e = vec3(next(), 1.0 + 0.1 * next(), next());
            let (s, c) = (std::f64::consts::PI * next()).sin_cos();
            let d = vec3(level * c, -down, level * s);
            out.push(Sample {
                ray: Ray::new(e, d),
                angle,
            });
        }
    }
    out
}

/// A vector of [`Real`] as f64.
pub fn wide3(v: Vec3) -> DVec3 {
    DVec3::new(wide(v.x), wide(v.y), wide(v.z))
}
