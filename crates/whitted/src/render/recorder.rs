//! The recorder: what the road of one pixel tells whoever listens as it goes.
//!
//! Every stop of the road ([`super::tracer`]) reports what it did to a [`Recorder`]: a ray
//! leaves (camera, mirror or transmitted), it hits something or nothing, the ambient term,
//! each light's unshadowed terms and the share its feeler lets through, the local light, a
//! branch that was not followed and why, the colour a ray brings back. Two recorders exist:
//!
//! - [`Stats`] keeps only the counts of rays by kind. Its methods are empty or one addition,
//!   and the road is compiled once per recorder, so a plain render costs what it cost before
//!   the recorder existed.
//! - [`super::inspect::TreeRecorder`] keeps everything: the ray tree of one pixel, which
//!   `--inspect X,Y`, the live window and the book print.
//!
//! A pair `(&mut A, &mut B)` of recorders is a recorder that tells both (the rays-per-pixel
//! view counts one pixel's rays this way while the tree records them).
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use super::Stats;
use super::tracer::{Feeler, Surface};
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::shapes::Nearest;

/// The kinds of ray the road sends from the camera and from surfaces (feelers are reported
/// with their light, [`Recorder::light`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RayKind {
    /// The camera ray r(t) = e + d·t of a sample of the pixel (chapter 1).
    Camera,
    /// The mirror ray l = d − 2(d·n)n, whose light I_l counts k_r times (chapter 5).
    Mirror,
    /// The transmitted ray of Snell's law, whose light I_r counts k_t times (chapter 5).
    Transmitted,
}

impl RayKind {
    /// The name used in the inspector's text and JSON: `camera`, `mirror`, `transmitted`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Camera => "camera",
            Self::Mirror => "mirror",
            Self::Transmitted => "transmitted",
        }
    }
}

/// Why a mirror or transmitted ray was not traced although its material asks for it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stop {
    /// The ray would go past the maximum recursion depth (`--max-depth`).
    MaxDepth,
    /// Its weight, the product of the k_r and k_t that lead to it, would fall below the
    /// minimum weight: it could not change the pixel.
    Weight,
    /// Total internal reflection: no transmitted ray exists; its share k_t goes to the mirror
    /// ray.
    TotalInternalReflection,
}

impl Stop {
    /// The name used in the inspector's JSON: `max_depth`, `weight`, `total_internal_reflection`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::MaxDepth => "max_depth",
            Self::Weight => "weight",
            Self::TotalInternalReflection => "total_internal_reflection",
        }
    }
}

/// Listens to the road of one pixel. Every method has an empty default: a recorder takes
/// the events it wants. Events come in the order of the road, one ray at a time: a ray's
/// [`Recorder::ray`] is followed by its [`Recorder::hit`], then (when shaded) its ambient,
/// lights, local light, branches — each traced branch a whole nested ray — and last its
/// [`Recorder::done`].
pub trait Recorder {
    /// Sample `index` of the pixel starts, at (dx, dy) within the pixel (0.5, 0.5 = centre).
    #[inline]
    fn sample(&mut self, index: u32, dx: Real, dy: Real) {
        let _ = (index, dx, dy);
    }

    /// A ray leaves: its kind, the ray, the smallest t that counts, its depth (0 for a camera
    /// ray) and its weight (1 for a camera ray; times k_r or k_t at each bounce).
    #[inline]
    fn ray(&mut self, kind: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real) {
        let _ = (kind, ray, t_min, depth, weight);
    }

    /// The nearest hit of the ray that left last, or `None` when it hits nothing.
    #[inline]
    fn hit(&mut self, nearest: Option<&Nearest>) {
        let _ = nearest;
    }

    /// The ambient term I_a = ρa·I_m at the hit.
    #[inline]
    fn ambient(&mut self, i_a: Vec3) {
        let _ = i_a;
    }

    /// Light number `light` seen from the surface `s`: its unshadowed I_d + I_s, the feeler
    /// sent towards it (from chapter 4, if it casts shadows and lies in front) and the share
    /// of it that arrives (1 without a feeler).
    #[inline]
    fn light(
        &mut self,
        light: usize,
        s: &Surface,
        unshadowed: Vec3,
        feeler: Option<&Feeler>,
        share: Real,
    ) {
        let _ = (light, s, unshadowed, feeler, share);
    }

    /// The local light I_a + Σ (I_d + I_s)·share at the hit.
    #[inline]
    fn local(&mut self, colour: Vec3) {
        let _ = colour;
    }

    /// A branch of kind `kind` (mirror or transmitted) that the material asks for was not
    /// traced, for the reason `why`.
    #[inline]
    fn stopped(&mut self, kind: RayKind, why: Stop) {
        let _ = (kind, why);
    }

    /// The ray that left last (and is not done) brings back `colour`.
    #[inline]
    fn done(&mut self, colour: Vec3) {
        let _ = colour;
    }
}

/// The counts of a plain render: one addition per ray.
impl Recorder for Stats {
    #[inline]
    fn ray(&mut self, kind: RayKind, _: &Ray, _: Real, _: u32, _: Real) {
        match kind {
            RayKind::Camera => self.primary += 1,
            RayKind::Mirror => self.reflected += 1,
            RayKind::Transmitted => self.refracted += 1,
        }
    }

    #[inline]
    fn light(&mut self, _: usize, _: &Surface, _: Vec3, feeler: Option<&Feeler>, _: Real) {
        self.shadow += u64::from(feeler.is_some());
    }

    #[inline]
    fn stopped(&mut self, _: RayKind, why: Stop) {
        self.total_internal += u64::from(why == Stop::TotalInternalReflection);
    }
}

/// Two recorders told the same events, the first one first.
impl<A: Recorder, B: Recorder> Recorder for (&mut A, &mut B) {
    fn sample(&mut self, index: u32, dx: Real, dy: Real) {
        self.0.sample(index, dx, dy);
        self.1.sample(index, dx, dy);
    }

    fn ray(&mut self, kind: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real) {
        self.0.ray(kind, ray, t_min, depth, weight);
        self.1.ray(kind, ray, t_min, depth, weight);
    }

    fn hit(&mut self, nearest: Option<&Nearest>) {
        self.0.hit(nearest);
        self.1.hit(nearest);
    }

    fn ambient(&mut self, i_a: Vec3) {
        self.0.ambient(i_a);
        self.1.ambient(i_a);
    }

    fn light(
        &mut self,
        light: usize,
        s: &Surface,
        unshadowed: Vec3,
        feeler: Option<&Feeler>,
        share: Real,
    ) {
        self.0.light(light, s, unshadowed, feeler, share);
        self.1.light(light, s, unshadowed, feeler, share);
    }

    fn local(&mut self, colour: Vec3) {
        self.0.local(colour);
        self.1.local(colour);
    }

    fn stopped(&mut self, kind: RayKind, why: Stop) {
        self.0.stopped(kind, why);
        self.1.stopped(kind, why);
    }

    fn done(&mut self, colour: Vec3) {
        self.0.done(colour);
        self.1.done(colour);
    }
}
