//! What the road asks of the scene's objects: the notes' step 4 as a small trait, [`Query`], and
//! what shading needs to know of the hit it finds, [`ShadingPoint`].
//!
//! The road of one pixel ([`super::tracer`]) asks two questions of the objects: the nearest hit
//! of a ray ("find the intersections of this ray with objects; keep the smallest t"), and how
//! much of a light a feeler lets through (chapter 4). The notes' own answer, testing every
//! object in turn, sits on the road itself ([`super::EveryObject`]); the acceleration
//! structures and the packets answer the same questions, sooner, beside it. What else a faster
//! answer can offer the road is not part of the question: see [`super::shortcuts`].
//!
//! Course book: [Chapter 2, generic objects](../../../../../docs/book/ch02-generic-objects.html) (`docs/src/ch02-generic-objects.md`).

use super::recorder::Recorder;
use crate::material::Material;
use crate::offset::SpawnPoint;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading;
use crate::shadow::Feeler;
use crate::shapes::{Hit, Nearest};

// ANCHOR: ch2_query
/// What the road asks of the scene's objects: the nearest hit of a ray (the notes' step 4,
/// "find the intersections of this ray with objects; keep the smallest t"), and the share of
/// its light a feeler lets through (chapter 4). [`EveryObject`](super::EveryObject) answers by
/// testing every object in turn; the acceleration structures and the packets answer the same,
/// sooner.
pub trait Query {
    /// The nearest hit of `ray` with t > `t_min` (its normal in the world), of equal t the
    /// object listed first; `None` when the ray hits nothing.
    fn nearest(&self, ray: &Ray, t_min: Real) -> Option<Nearest>;

    /// The share of its light that `feeler` lets through: [`crate::shadow::transmittance`] of the
    /// transmissions of the objects it crosses with u ∈ ]u_min, 1], in scene order (0 behind
    /// an opaque one). An answer that tests every object tells `rec` each object crossed
    /// ([`Recorder::crossing`]).
    fn share(&self, feeler: &Feeler, rec: &mut impl Recorder) -> Real;
}
// ANCHOR_END: ch2_query

/// What shading needs to know of a hit: the shading point of the notes' formulas.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct ShadingPoint<'s> {
    /// The hit (world normal, pointing out of the object; which side the ray came from).
    pub hit: Hit,
    /// The material hit.
    pub material: &'s Material,
    /// The hit point P = r(t).
    pub p: Vec3,
    /// The ray's unit direction.
    pub d: Vec3,
    /// The shading normal n, turned towards the viewer ([`shading::facing`]).
    pub n: Vec3,
    /// Where rays leaving the hit start.
    pub spawn: SpawnPoint,
}

// ANCHOR: ch3_shading_point
impl<'s> ShadingPoint<'s> {
    /// What shading needs to know of `nearest`, the nearest hit of `ray` in `scene`.
    #[inline]
    #[must_use]
    pub fn new(scene: &'s Scene, ray: &Ray, nearest: &Nearest) -> Self {
        let hit = nearest.hit;
        let object = &scene.objects[nearest.object];
        let d = crate::numeric::normalize(ray.dir);
        Self {
            hit,
            material: &scene.materials[object.material],
            p: ray.at(hit.t),
            d,
            n: shading::facing(hit.normal, d), // shading normal, towards the viewer
            spawn: SpawnPoint::new(object, ray, &hit),
        }
    }
}
// ANCHOR_END: ch3_shading_point
