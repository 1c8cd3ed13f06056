//! The acceleration structure as the road's [`Query`]: [`Accelerated`], the structure of
//! [`crate::accel`] with the scene it was built for, asks it the road's questions one ray at a
//! time ([`crate::accel::query`]) or, for the packets of [`super::packets`], a packet at a time
//! ([`crate::accel::packet`]). It answers exactly what [`EveryObject`], the notes' loop over
//! every object, answers; and for `--accel none`, which asks for no structure at all, it is
//! that loop: every ray goes to [`EveryObject`].
//!
//! Every render asks it ([`Tracer::new`](super::Tracer::new)).
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use std::borrow::Cow;

use super::query::Query;
use super::recorder::Recorder;
use super::shortcuts::Shortcuts;
use super::tracer::EveryObject;
use crate::accel::{Accel, Accelerator, counters};
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shadow::Feeler;
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

    /// The notes' own loop over the scene's objects, when the structure is none at all
    /// (`--accel none`).
    #[inline]
    fn every_object(&self) -> Option<EveryObject<'a>> {
        (self.accel.kind() == Accel::None).then_some(EveryObject {
            scene: self.scene,
            numerics: self.numerics,
        })
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
        match self.every_object() {
            Some(every) => {
                counters::every_object(self.scene.objects.len());
                every.nearest(ray, t_min)
            }
            None => self
                .accel
                .nearest(&self.scene.objects, ray, t_min, self.numerics),
        }
    }

    #[inline]
    fn share(&self, feeler: &Feeler, rec: &mut impl Recorder) -> Real {
        match self.every_object() {
            Some(every) => {
                counters::every_object(self.scene.objects.len());
                every.share(feeler, rec)
            }
            None => {
                let (objects, materials) = (&self.scene.objects, &self.scene.materials);
                self.accel.transmittance(
                    objects,
                    materials,
                    &feeler.ray,
                    feeler.u_min,
                    self.numerics,
                )
            }
        }
    }
}

impl Shortcuts for Accelerated<'_> {
    #[inline]
    fn nearest_camera(&self, ray: &Ray) -> Option<Nearest> {
        match self.every_object() {
            Some(_) => self.nearest(ray, 0.0),
            None => self
                .accel
                .nearest_camera(&self.scene.objects, ray, self.numerics),
        }
    }
}
