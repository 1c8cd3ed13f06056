//! Rays: the parametric line r(t) = e + d·t of the notes' "Principles of Ray Tracing".
//!
//! Chapter 1 builds one ray per pixel; chapter 2 carries rays into object space with M⁻¹;
//! chapters 4 and 5 spawn feeler, reflected and refracted rays from hit points.
//!
//! Course book: [Chapter 1, camera rays](../../../../docs/book/ch01-camera-rays.html) (`docs/src/ch01-camera-rays.md`).

use crate::real::{Mat4, Real, Vec3};

// ANCHOR: ch2_ray
/// A ray r(t) = e + d·t. The direction is *not* required to be unit length: primary rays keep
/// the notes' d (which reaches the near plane at t = 1), and rays carried into object space
/// keep M⁻¹d unnormalised so that t means the same point in both spaces.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Ray {
    /// The origin e.
    pub origin: Vec3,
    /// The direction d.
    pub dir: Vec3,
}
// ANCHOR_END: ch2_ray

impl Ray {
    /// A ray from `origin` along `dir`.
    #[inline]
    #[must_use]
    pub fn new(origin: Vec3, dir: Vec3) -> Self {
        Self { origin, dir }
    }

    /// The point r(t) = e + d·t.
    #[inline]
    #[must_use]
    pub fn at(&self, t: Real) -> Vec3 {
        // BEGIN SOLUTION point_on_ray
        self.origin + self.dir * t
        // END SOLUTION
    }

    // ANCHOR: ch2_transformed_sig
    /// The ray M⁻¹r(t) = M⁻¹e + M⁻¹d·t: the origin moves as a point, the direction as a vector,
    /// and the direction is not renormalised.
    #[inline]
    #[must_use]
    pub fn transformed(&self, m: &Mat4) -> Self {
        // ANCHOR_END: ch2_transformed_sig
        // BEGIN SOLUTION ray_in_object_space
        Self {
            origin: m.transform_point3(self.origin),
            dir: m.transform_vector3(self.dir),
        }
        // END SOLUTION
    }
}
