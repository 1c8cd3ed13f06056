//! The recorder: what the road of one pixel tells whoever listens as it goes.
//!
//! Every stop of the road ([`super::tracer`]) reports what it computed to a [`Recorder`], the
//! values themselves, as it computes them: a ray leaves (camera, mirror or transmitted, with
//! its weight and its k), it hits something or nothing, the ambient term, each light (whether
//! it lies in front, as the road decided, and its Phong terms), the objects its feeler crosses
//! and the share it lets through, the local light, a branch that was not followed and why, the
//! colour a ray brings back. Two recorders exist:
//!
//! - [`Stats`] keeps only the counts of rays by kind. Its methods are empty or one addition,
//!   and the road is compiled once per recorder, so a plain render pays nothing for the
//!   events it ignores.
//! - [`super::inspect::TreeRecorder`] keeps everything: the ray tree of one pixel, which
//!   `--inspect X,Y`, the live window and the book print. It computes nothing: what it shows
//!   is what the road handed it.
//!
//! A pair `(&mut A, &mut B)` of recorders is a recorder that tells both (the rays-per-pixel
//! view counts one pixel's rays this way while the tree records them).
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use super::stats::Stats;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::shading::Phong;
use crate::shadow::Feeler;
use crate::shapes::{Hits, Nearest};

/// The kinds of ray the road sends from the camera and from surfaces (feelers are reported
/// with their light, [`Recorder::light`]), and why a branch was not traced: words of the ray
/// tree, typed once in `whitted_syllabus::tree`.
pub use whitted_syllabus::tree::{RayKind, Stop};

/// Listens to the road of one pixel. Every method has an empty default: a recorder takes
/// the events it wants. Events come in the order of the road, one ray at a time: a ray's
/// [`Recorder::ray`] is followed by its [`Recorder::hit`], then (when shaded) its ambient,
/// lights (each light's [`Recorder::crossing`]s first, when the query names them), local
/// light, branches — each traced branch a whole nested ray — and last its [`Recorder::done`].
pub trait Recorder {
    /// Sample `index` of the pixel starts, at (dx, dy) within the pixel (0.5, 0.5 = centre).
    #[inline]
    fn sample(&mut self, index: u32, dx: Real, dy: Real) {
        let _ = (index, dx, dy);
    }

    /// A ray leaves: its kind, the ray, the smallest t that counts, its depth (0 for a camera
    /// ray), its weight (1 for a camera ray; times k_r or k_t at each bounce) and the k its
    /// light counts at the hit it leaves (k_r for a mirror ray, plus k_t under total internal
    /// reflection; k_t for a transmitted ray; 1 for a camera ray).
    #[inline]
    fn ray(&mut self, kind: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real, k: Real) {
        let _ = (kind, ray, t_min, depth, weight, k);
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

    /// Object number `object`, whose hits with the feeler under way are `hits` (their u; the
    /// normals left in object space), blocks it
    /// ([`crate::shadow::blocks`]); its transmission is `k_t`. Told by a query that tests
    /// every object ([`super::EveryObject`]), in scene order, before the feeler's
    /// [`Recorder::light`].
    #[inline]
    fn crossing(&mut self, object: usize, hits: &Hits, k_t: Real) {
        let _ = (object, hits, k_t);
    }

    /// Light number `light` seen from the hit: whether it lies in front of the surface, as the
    /// road decided it once for this light (n·(L − P) > 0, [`crate::shadow::in_front`]), its
    /// Phong terms before shadowing (`phong.sum` = I_d + I_s), the feeler sent towards it (from
    /// chapter 4, if it casts shadows, lies in front and adds something), the share of it that
    /// arrives (1 without a feeler) and (I_d + I_s)·share.
    #[inline]
    fn light(
        &mut self,
        light: usize,
        in_front: bool,
        phong: &Phong,
        feeler: Option<&Feeler>,
        share: Real,
        arriving: Vec3,
    ) {
        let _ = (light, in_front, phong, feeler, share, arriving);
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
    fn ray(&mut self, kind: RayKind, _: &Ray, _: Real, _: u32, _: Real, _: Real) {
        match kind {
            RayKind::Camera => self.primary += 1,
            RayKind::Mirror => self.reflected += 1,
            RayKind::Transmitted => self.refracted += 1,
        }
    }

    #[inline]
    fn light(&mut self, _: usize, _: bool, _: &Phong, f: Option<&Feeler>, _: Real, _: Vec3) {
        self.shadow += u64::from(f.is_some());
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

    fn ray(&mut self, kind: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real, k: Real) {
        self.0.ray(kind, ray, t_min, depth, weight, k);
        self.1.ray(kind, ray, t_min, depth, weight, k);
    }

    fn hit(&mut self, nearest: Option<&Nearest>) {
        self.0.hit(nearest);
        self.1.hit(nearest);
    }

    fn ambient(&mut self, i_a: Vec3) {
        self.0.ambient(i_a);
        self.1.ambient(i_a);
    }

    fn crossing(&mut self, object: usize, hits: &Hits, k_t: Real) {
        self.0.crossing(object, hits, k_t);
        self.1.crossing(object, hits, k_t);
    }

    fn light(
        &mut self,
        light: usize,
        in_front: bool,
        phong: &Phong,
        feeler: Option<&Feeler>,
        share: Real,
        arriving: Vec3,
    ) {
        self.0
            .light(light, in_front, phong, feeler, share, arriving);
        self.1
            .light(light, in_front, phong, feeler, share, arriving);
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
