//! Chapter 2 — placing generic objects (notes: "Ray Tracing Process").
//!
//! A generic object q′ is placed in the scene by a 4×4 matrix M: q = M·q′. Instead of moving
//! the object, the ray is moved into the object's own space with M⁻¹:
//!
//! ```text
//! M⁻¹r(t) = M⁻¹e + M⁻¹d·t
//! ```
//!
//! The direction M⁻¹d is *not* renormalised, so a hit at parameter t in object space is the
//! point r(t) in world space: t is the same in both spaces. Normals do not move like points:
//! a world normal is (M⁻¹)ᵀ·n′, renormalised.
//!
//! A [`Placement`] is built from a list of [`Step`]s applied in order (first step first). It
//! caches M, M⁻¹ and (M⁻¹)ᵀ once, and builds M⁻¹ from the inverse steps in reverse order
//! (translate −t, rotate −θ, scale 1/s): no numeric 4×4 inversion.
//!
//! ```toml
//! transform = [ { scale = [0.9, 0.9, 1.1] }, { rotate_x = -90.0 }, { translate = [0.2, 0.1, -2.2] } ]
//! ```
//!
//! Course book: [Chapter 2, generic objects](../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use crate::real::{Mat3, Mat4, Real, Vec3, Vec4};

/// One elementary placement step. Angles are in degrees, as in the scene file.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Step {
    /// Scale by (sx, sy, sz); every factor must be finite and non-zero.
    Scale(Vec3),
    /// Rotate about the x axis (right-handed).
    RotateX(Real),
    /// Rotate about the y axis (right-handed).
    RotateY(Real),
    /// Rotate about the z axis (right-handed).
    RotateZ(Real),
    /// Rotate about an axis through the origin; the axis need not be unit length.
    RotateAxis(Vec3, Real),
    /// Translate by t.
    Translate(Vec3),
}

impl Step {
    /// The step's matrix. A rotation by a whole multiple of 90° has exact entries 0 and ±1
    /// (see [`sin_cos_degrees`]), so an upright plane, cylinder or cone is placed exactly.
    #[must_use]
    pub fn matrix(&self) -> Mat4 {
        // BEGIN SOLUTION step_matrix
        match *self {
            Step::Scale(s) => Mat4::from_scale(s),
            Step::RotateX(a) => {
                let (s, c) = sin_cos_degrees(a);
                Mat4::from_cols(
                    Vec4::X,
                    Vec4::new(0.0, c, s, 0.0),
                    Vec4::new(0.0, -s, c, 0.0),
                    Vec4::W,
                )
            }
            Step::RotateY(a) => {
                let (s, c) = sin_cos_degrees(a);
                Mat4::from_cols(
                    Vec4::new(c, 0.0, -s, 0.0),
                    Vec4::Y,
                    Vec4::new(s, 0.0, c, 0.0),
                    Vec4::W,
                )
            }
            Step::RotateZ(a) => {
                let (s, c) = sin_cos_degrees(a);
                Mat4::from_cols(
                    Vec4::new(c, s, 0.0, 0.0),
                    Vec4::new(-s, c, 0.0, 0.0),
                    Vec4::Z,
                    Vec4::W,
                )
            }
            Step::RotateAxis(axis, a) => rotation_about(axis.normalize(), sin_cos_degrees(a)),
            Step::Translate(t) => Mat4::from_translation(t),
        }
        // END SOLUTION
    }

    /// The inverse step: scale 1/s, rotate −θ, translate −t.
    #[must_use]
    pub fn inverse(&self) -> Step {
        // BEGIN SOLUTION step_inverse
        match *self {
            Step::Scale(s) => Step::Scale(s.recip()),
            Step::RotateX(a) => Step::RotateX(-a),
            Step::RotateY(a) => Step::RotateY(-a),
            Step::RotateZ(a) => Step::RotateZ(-a),
            Step::RotateAxis(axis, a) => Step::RotateAxis(axis, -a),
            Step::Translate(t) => Step::Translate(-t),
        }
        // END SOLUTION
    }

    /// Whether the step can be inverted: a scale needs finite non-zero factors, a rotation
    /// a finite angle (and a non-zero finite axis), a translation finite components.
    #[must_use]
    pub fn is_invertible(&self) -> bool {
        match *self {
            Step::Scale(s) => s.is_finite() && s.cmpne(Vec3::ZERO).all() && s.recip().is_finite(),
            Step::RotateX(a) | Step::RotateY(a) | Step::RotateZ(a) => a.is_finite(),
            Step::RotateAxis(axis, a) => {
                a.is_finite() && axis.is_finite() && axis.try_normalize().is_some()
            }
            Step::Translate(t) => t.is_finite(),
        }
    }
}

/// (sin θ, cos θ) for θ in degrees. For a whole multiple of 90° the values are exact: 0 and ±1,
/// where `θ.to_radians().sin_cos()` would give cos 90° = 6.1e-17 (f64) or −4.4e-8 (f32), tilting
/// an upright plane by that much: a ray parallel to the floor would then meet it far away.
#[must_use]
pub fn sin_cos_degrees(degrees: Real) -> (Real, Real) {
    let turns = degrees / 90.0;
    if turns == turns.round() && turns.abs() < 1e15 {
        // a whole number of quarter turns: which quarter, from 0 to 3
        return match (turns.round() as i64).rem_euclid(4) {
            0 => (0.0, 1.0),
            1 => (1.0, 0.0),
            2 => (0.0, -1.0),
            _ => (-1.0, 0.0),
        };
    }
    degrees.to_radians().sin_cos()
}

/// The rotation about the unit `axis` whose angle has sine and cosine `(s, c)` (Rodrigues'
/// formula: R = c·I + s·[axis]ₓ + (1 − c)·axis·axisᵀ).
fn rotation_about(axis: Vec3, (s, c): (Real, Real)) -> Mat4 {
    let k = 1.0 - c;
    let (x, y, z) = (axis.x, axis.y, axis.z);
    let (xs, ys, zs) = (x * s, y * s, z * s);
    let (xy, xz, yz) = (x * y * k, x * z * k, y * z * k);
    Mat4::from_cols(
        Vec4::new(x * x * k + c, xy + zs, xz - ys, 0.0),
        Vec4::new(xy - zs, y * y * k + c, yz + xs, 0.0),
        Vec4::new(xz + ys, yz - xs, z * z * k + c, 0.0),
        Vec4::W,
    )
}

/// The rotation that turns +z onto the unit vector `to`, as a single step. Onto a coordinate
/// axis (±x, ±y, −z) it is a quarter or half turn about x or y, whose matrix is exact.
#[must_use]
pub fn rotation_from_z(to: Vec3) -> Step {
    // rotating z by θ about x gives (0, −sin θ, cos θ); about y, (sin θ, 0, cos θ)
    match to.to_array() {
        [0.0, 0.0, z] if z > 0.0 => return Step::RotateZ(0.0),
        [0.0, 0.0, _] => return Step::RotateX(180.0),
        [0.0, y, 0.0] => return Step::RotateX(if y > 0.0 { -90.0 } else { 90.0 }),
        [x, 0.0, 0.0] => return Step::RotateY(if x > 0.0 { 90.0 } else { -90.0 }),
        _ => {}
    }
    let z = Vec3::Z;
    let cos = z.dot(to).clamp(-1.0, 1.0);
    match z.cross(to).try_normalize() {
        Some(axis) => Step::RotateAxis(axis, cos.acos().to_degrees()),
        // parallel: nothing to do, or a half turn about x
        None if cos > 0.0 => Step::RotateZ(0.0),
        None => Step::RotateX(180.0),
    }
}

/// A placement M with its cached inverse M⁻¹ and the normal matrix (M⁻¹)ᵀ.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Placement {
    m: Mat4,
    inv: Mat4,
    normal_matrix: Mat3,
    wide_inv: WideInverse,
}

impl Default for Placement {
    fn default() -> Self {
        Self::identity()
    }
}

impl Placement {
    /// The identity placement: the generic object as it is.
    #[must_use]
    pub fn identity() -> Self {
        Self {
            m: Mat4::IDENTITY,
            inv: Mat4::IDENTITY,
            normal_matrix: Mat3::IDENTITY,
            wide_inv: WideInverse::of(&Mat4::IDENTITY),
        }
    }

    /// M = S_k ⋯ S_2·S_1 for the steps S_1 … S_k applied in order, and M⁻¹ = S_1⁻¹·S_2⁻¹ ⋯ S_k⁻¹
    /// from the inverse steps. Returns `None` if a step cannot be inverted (see
    /// [`Step::is_invertible`]).
    #[must_use]
    pub fn from_steps(steps: &[Step]) -> Option<Self> {
        // BEGIN SOLUTION placement_from_steps
        let mut m = Mat4::IDENTITY;
        let mut inv = Mat4::IDENTITY;
        for step in steps {
            if !step.is_invertible() {
                return None;
            }
            m = step.matrix() * m;
            inv *= step.inverse().matrix();
        }
        Some(Self::from_matrices(m, inv))
        // END SOLUTION
    }

    // ANCHOR: ch2_from_matrices
    /// A placement from M and its known inverse.
    #[must_use]
    pub fn from_matrices(m: Mat4, inv: Mat4) -> Self {
        Self {
            m,
            inv,
            normal_matrix: Mat3::from_mat4(inv).transpose(),
            wide_inv: WideInverse::of(&m), // the f32 build's M⁻¹ in f64 (nothing in f64)
        }
    }
    // ANCHOR_END: ch2_from_matrices

    /// M: object space → world space.
    #[inline]
    #[must_use]
    pub fn m(&self) -> &Mat4 {
        &self.m
    }

    /// M⁻¹: world space → object space.
    #[inline]
    #[must_use]
    pub fn inv(&self) -> &Mat4 {
        &self.inv
    }

    /// M⁻¹ as the f32 build also keeps it, in f64 (see [`WideInverse`]).
    #[inline]
    #[must_use]
    pub fn wide_inv(&self) -> &WideInverse {
        &self.wide_inv
    }

    /// (M⁻¹)ᵀ restricted to 3×3: carries object-space normals to world space.
    #[inline]
    #[must_use]
    pub fn normal_matrix(&self) -> &Mat3 {
        &self.normal_matrix
    }

    // ANCHOR: ch2_normal_to_world_sig
    /// Carries an object-space normal to world space: (M⁻¹)ᵀ·n′, renormalised.
    #[inline]
    #[must_use]
    pub fn normal_to_world(&self, n_object: Vec3) -> Vec3 {
        // ANCHOR_END: ch2_normal_to_world_sig
        // BEGIN SOLUTION normal_to_world
        crate::numeric::normalize(self.normal_matrix * n_object)
        // END SOLUTION
    }
}

/// M⁻¹ in f64, which the f32 build keeps beside its f32 M⁻¹ for [`crate::shapes::refine`].
///
/// A sphere of radius R is placed by M = translate · scale R, and M⁻¹ carries a point h
/// above its surface to the distance 1 + h/R from the unit sphere's centre. In f32, whose
/// numbers near 1 are 1.2e-7 apart, that height survives only to R·u (u = 6e-8): 6e-4 world
/// units for R = 1e4, more than the whole error allowed on a hit 0.79 away. The f32 M⁻¹
/// itself is M's inverse rounded, so it places the surface off by as much; M⁻¹ inverted
/// from M in f64 carries the same points with 1e-16. In the f64 build, which holds the
/// planet to R·u = 1e-12 without it, the type is empty and costs nothing.
#[cfg(feature = "f32")]
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct WideInverse(pub glam::DMat4);

#[cfg(feature = "f32")]
impl WideInverse {
    /// M⁻¹ computed from M in f64.
    #[must_use]
    pub fn of(m: &Mat4) -> Self {
        Self(m.as_dmat4().inverse())
    }
}

/// M⁻¹ in f64, which the f32 build keeps beside its f32 M⁻¹ for [`crate::shapes::refine`];
/// empty in the f64 build, which needs nothing more (see the f32 build's documentation).
#[cfg(not(feature = "f32"))]
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct WideInverse;

#[cfg(not(feature = "f32"))]
impl WideInverse {
    /// Nothing to keep in the f64 build.
    #[must_use]
    pub fn of(_m: &Mat4) -> Self {
        Self
    }
}
