//! The acceleration structure as the road's [`Query`]: [`Accelerated`], the structure of
//! [`crate::accel`] with the scene it was built for, asks it the road's questions one ray at a
//! time ([`crate::accel::query`]) or, for the packets of [`super::packets`], a packet at a time
//! ([`crate::accel::packet`]). It answers exactly what [`EveryObject`](super::EveryObject),
//! the notes' loop over every object, answers.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use std::borrow::Cow;

use super::Recorder;
use super::tracer::{Feeler, Query, ShadingPoint};
use crate::accel::Accelerator;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shapes::{Nearest, Numerics};

/// An acceleration structure with the scene it was built for: the road's [`Query`] in every
/// render.
#[derive(Clone, Debug)]
pub struct Accelerated<'a> {
    accel: Cow<'a, Accelerator>,
    scene: &'a Scene,
    numerics: Numerics,
}

impl<'a> Accelerated<'a> {
    /// The structure `accel`, built for `scene`, whose objects it intersects with `numerics`.
    #[must_use]
    pub fn new(accel: Cow<'a, Accelerator>, scene: &'a Scene, numerics: Numerics) -> Self {
        Self {
            accel,
            scene,
            numerics,
        }
    }

    /// The structure.
    #[must_use]
    pub fn accel(&self) -> &Accelerator {
        &self.accel
    }

    /// [`Accelerator::nearest_packet`] for camera rays (t > 0) of this scene.
    pub(crate) fn nearest_camera_packet(&self, rays: &[Ray], out: &mut [Option<Nearest>]) {
        let objects = &self.scene.objects;
        self.accel
            .nearest_packet(objects, rays, 0.0, self.numerics, out);
    }

    /// [`Accelerator::transmittance_packet`] for feelers of this scene towards the light at
    /// `light`.
    pub(crate) fn share_packet(
        &self,
        light: Vec3,
        feelers: &[Ray],
        u_min: &[Real],
        out: &mut [Real],
    ) {
        let (objects, materials) = (&self.scene.objects, &self.scene.materials);
        self.accel.transmittance_packet(
            objects,
            materials,
            light,
            feelers,
            u_min,
            self.numerics,
            out,
        );
    }
}

impl Query for Accelerated<'_> {
    #[inline]
    fn nearest(&self, ray: &Ray, t_min: Real) -> Option<Nearest> {
        self.accel
            .nearest(&self.scene.objects, ray, t_min, self.numerics)
    }

    #[inline]
    fn nearest_camera(&self, ray: &Ray) -> Option<Nearest> {
        self.accel
            .nearest_camera(&self.scene.objects, ray, self.numerics)
    }

    #[inline]
    fn shading_point(&self, ray: &Ray, nearest: &Nearest) -> Cow<'_, ShadingPoint<'_>> {
        Cow::Owned(ShadingPoint::new(self.scene, ray, nearest))
    }

    #[inline]
    fn share(&self, feeler: &Feeler, _: &mut impl Recorder) -> Real {
        let (objects, materials) = (&self.scene.objects, &self.scene.materials);
        self.accel
            .transmittance(objects, materials, &feeler.ray, feeler.u_min, self.numerics)
    }
}
