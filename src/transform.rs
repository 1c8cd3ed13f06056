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

use crate::real::{Mat3, Mat4, Real, Vec3};

/// One elementary placement step. Angles are in degrees, as in the scene file.
#[derive(Clone, Copy, Debug, PartialEq)]
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
    /// The step's matrix.
    #[must_use]
    pub fn matrix(&self) -> Mat4 {
        match *self {
            Step::Scale(s) => Mat4::from_scale(s),
            Step::RotateX(a) => Mat4::from_rotation_x(a.to_radians()),
            Step::RotateY(a) => Mat4::from_rotation_y(a.to_radians()),
            Step::RotateZ(a) => Mat4::from_rotation_z(a.to_radians()),
            Step::RotateAxis(axis, a) => Mat4::from_axis_angle(axis.normalize(), a.to_radians()),
            Step::Translate(t) => Mat4::from_translation(t),
        }
    }

    /// The inverse step: scale 1/s, rotate −θ, translate −t.
    #[must_use]
    pub fn inverse(&self) -> Step {
        match *self {
            Step::Scale(s) => Step::Scale(s.recip()),
            Step::RotateX(a) => Step::RotateX(-a),
            Step::RotateY(a) => Step::RotateY(-a),
            Step::RotateZ(a) => Step::RotateZ(-a),
            Step::RotateAxis(axis, a) => Step::RotateAxis(axis, -a),
            Step::Translate(t) => Step::Translate(-t),
        }
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

/// The rotation that turns +z onto the unit vector `to`, as a single step.
#[must_use]
pub fn rotation_from_z(to: Vec3) -> Step {
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
#[derive(Clone, Debug, PartialEq)]
pub struct Placement {
    /// M: object space → world space.
    pub m: Mat4,
    /// M⁻¹: world space → object space.
    pub inv: Mat4,
    /// (M⁻¹)ᵀ restricted to 3×3: carries object-space normals to world space.
    pub normal_matrix: Mat3,
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
        }
    }

    /// M = S_k ⋯ S_2·S_1 for the steps S_1 … S_k applied in order, and M⁻¹ = S_1⁻¹·S_2⁻¹ ⋯ S_k⁻¹
    /// from the inverse steps. Returns `None` if a step cannot be inverted (see
    /// [`Step::is_invertible`]).
    #[must_use]
    pub fn from_steps(steps: &[Step]) -> Option<Self> {
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
    }

    /// A placement from M and its known inverse.
    #[must_use]
    pub fn from_matrices(m: Mat4, inv: Mat4) -> Self {
        Self {
            m,
            inv,
            normal_matrix: Mat3::from_mat4(inv).transpose(),
        }
    }

    /// Carries an object-space normal to world space: (M⁻¹)ᵀ·n′, renormalised.
    #[inline]
    #[must_use]
    pub fn normal_to_world(&self, n_object: Vec3) -> Vec3 {
        crate::numeric::normalize(self.normal_matrix * n_object)
    }
}
