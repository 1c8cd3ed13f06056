//! What a faster [`Query`] may offer the road besides its answers: [`Shortcuts`].
//!
//! The notes' step 4 is the whole question ([`Query`]); these two hooks only let an answer
//! come sooner, never differently. A camera ray leaves the eye through the image, so
//! projection extents can narrow the objects it is tested against
//! ([`Shortcuts::nearest_camera`]); and a query that has made the shading point of a camera
//! ray's hit already (the packets make them for their feelers) can lend it instead of the road
//! making it again ([`Shortcuts::shading_point`]). Each default is the plain answer, so the
//! notes' own loop takes no shortcut at all.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use std::borrow::Cow;

use super::query::{Query, ShadingPoint};
use crate::ray::Ray;
use crate::scene::Scene;
use crate::shapes::Nearest;

/// What a [`Query`] may answer sooner: the same answers as the plain questions, by default
/// those very questions.
pub trait Shortcuts: Query {
    /// [`Query::nearest`] of a camera ray, t > 0: the same answer. A camera ray leaves the eye
    /// through the image, which lets projection extents narrow the objects to test.
    #[inline]
    fn nearest_camera(&self, ray: &Ray) -> Option<Nearest> {
        self.nearest(ray, 0.0)
    }

    /// What shading needs to know of `nearest`, the nearest hit of `ray` in `scene`:
    /// [`ShadingPoint::new`] of it, made here, or lent by a query that made it already.
    #[inline]
    fn shading_point<'s>(
        &'s self,
        scene: &'s Scene,
        ray: &Ray,
        nearest: &Nearest,
    ) -> Cow<'s, ShadingPoint<'s>> {
        Cow::Owned(ShadingPoint::new(scene, ray, nearest))
    }
}
