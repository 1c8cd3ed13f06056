//! The road of one pixel: every chapter's renderer, one stop after another.
//!
//! ```text
//! pixel (x, y) ─► camera ray (ch1) ─► nearest hit over the objects (ch2)
//!   ─► I_a + Σ lights (I_d + I_s) (ch3) ─► × the share of each feeler (ch4)
//!   ─► + k_t·I_r + k_r·I_l from the transmitted and mirror rays, recursively (ch5) ─► colour
//! ```
//!
//! Read it top to bottom: `Tracer::camera_ray` (each sample of [`Tracer::pixel`]) →
//! [`Query::nearest`] (the notes' step 4, [`EveryObject`]) → `Tracer::hit_colour` →
//! `Tracer::shade` → `Tracer::local_light` (with `Tracer::feeler` and [`Query::share`]) →
//! `Tracer::reflect_and_refract` → [`Tracer::trace`] for each new ray. Each stop calls the small
//! function of the notes' formula (camera, shapes, shading, shadow, optics). The road itself
//! adds up what they bring back (the sums of the lighting equation) and decides which rays to
//! send: a feeler for a light in front that casts shadows, a branch while the depth and its
//! weight allow, the transmitted share moved to the mirror ray under total internal reflection.
//! How far a chapter goes:
//!
//! | [`Chapter`] | what a camera ray returns |
//! |---|---|
//! | 1 [`Chapter::CameraRays`] | the ray direction as a colour, (d̂ + 1)/2 |
//! | 2 [`Chapter::GenericObjects`] | the nearest hit: the diffuse colour ρd of its material, unlit |
//! | 3 [`Chapter::Shading`] | ambient + diffuse + specular from every light (Phong) |
//! | 4 [`Chapter::Shadows`] | the same, each light tested by a feeler ray |
//! | 5 [`Chapter::ReflectionRefraction`] | plus mirror and transmitted rays, recursively: I = I_a + I_d + I_s + I_l + I_r |
//!
//! Every stop tells a [`Recorder`] what it computed ([`Stats`](super::Stats) counts rays, the
//! inspector keeps the ray tree). The nearest hit of a ray and the share of a feeler are asked
//! of a [`Query`] ([`super::query`]): the notes' own answer, [`EveryObject`], tests every object
//! in turn; the structures ([`super::Accelerated`]) and the packets give the same answers
//! sooner, and may take the [`Shortcuts`] beside it.
//!
//! Around the road, and calling it: the pixel and its samples ([`super::pixel`]), the views
//! that show a hit otherwise than the chapter does ([`super::views`], [`super::stages`]), the
//! ray tree ([`super::inspect`]), and the speed machinery ([`super::tiles`],
//! [`super::packets`], [`super::accelerated`]). The road calls none of them.
//!
//! Course book: [Chapter 1, camera rays](../../../../../docs/book/ch01-camera-rays.html) (`docs/src/ch01-camera-rays.md`).

use super::options::{Chapter, Options};
use super::query::{Query, ShadingPoint};
use super::recorder::{RayKind, Recorder, Stop};
use super::scales::Scales;
use super::shortcuts::Shortcuts;
use crate::camera::{Camera, direction_colour};
use crate::light::Light;
use crate::optics;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading;
use crate::shadow::{self, Feeler};
use crate::shapes::{Nearest, Numerics, nearer};

/// The notes' own [`Query`]: every object of the scene, in turn.
#[derive(Clone, Copy, Debug)]
pub struct EveryObject<'s> {
    /// The scene whose objects are tested.
    pub scene: &'s Scene,
    /// How each object is intersected.
    pub numerics: Numerics,
}

// ANCHOR: ch2_every_object
impl Query for EveryObject<'_> {
    fn nearest(&self, ray: &Ray, t_min: Real) -> Option<Nearest> {
        let mut nearest: Option<Nearest> = None;
        for (i, object) in self.scene.objects.iter().enumerate() {
            // step 4: this object's intersections; its visible one is the first after t_min
            let hits = object.intersect_object_space(ray, self.numerics);
            let Some(hit) = hits.first_after(t_min) else {
                continue;
            };
            // step 5: keep the smallest t (of equal t, the object listed first)
            if nearest.is_none_or(|best| nearer(hit.t, i, best.hit.t, best.object)) {
                nearest = Some(Nearest { hit, object: i });
            }
        }
        // the winner's normal, and only the winner's, carried to the world: (M⁻¹)ᵀ·n′ (and
        // its t refined, in the f32 build: see `Object::refine`)
        nearest.map(|mut n| {
            let object = &self.scene.objects[n.object];
            n.hit = object.refine(ray, n.hit, self.numerics);
            n.hit.normal = object.placement.normal_to_world(n.hit.normal);
            n
        })
    }

    fn share(&self, feeler: &Feeler, rec: &mut impl Recorder) -> Real {
        let mut crossed = Vec::new(); // the k_t of each object the feeler crosses, in order
        for (i, object) in self.scene.objects.iter().enumerate() {
            let hits = object.intersect_object_space(&feeler.ray, self.numerics);
            if shadow::blocks(&hits, feeler.u_min) {
                let k_t = self.scene.materials[object.material].transmission;
                rec.crossing(i, &hits, k_t);
                crossed.push(k_t);
            }
        }
        shadow::transmittance(crossed)
    }
}
// ANCHOR_END: ch2_every_object

/// The notes' loop takes no shortcut: its camera rays and shading points are the plain ones.
impl Shortcuts for EveryObject<'_> {}

/// Traces rays through one scene with one set of options, asking its [`Query`] `Q` for the
/// nearest hits and the feelers' shares (every render asks the acceleration structure of the
/// options, [`super::Accelerated`], made by `Tracer::new`).
pub struct Tracer<'a, Q> {
    pub(crate) scene: &'a Scene,
    /// The options it renders with: size, chapter, view, depth …
    pub options: &'a Options,
    pub(super) camera: Camera,
    pub(super) query: Q,
    /// The scales of the depth and rays-per-pixel views, fixed before the first pixel.
    pub(super) scales: Scales,
}

impl<'a, Q: Query> Tracer<'a, Q> {
    /// A tracer that asks `query` for the nearest hits and the feelers' shares.
    #[must_use]
    pub fn with_query(scene: &'a Scene, options: &'a Options, query: Q) -> Self {
        let camera = options.camera(scene);
        let scales = Scales::measure(options, scene, &camera, &query);
        Self {
            scene,
            options,
            camera,
            query,
            scales,
        }
    }

    /// The same tracer (scene, options, camera, scales) asking `query` instead.
    #[must_use]
    pub fn asking<R: Query>(&self, query: R) -> Tracer<'a, R> {
        Tracer {
            scene: self.scene,
            options: self.options,
            camera: self.camera.clone(),
            query,
            scales: self.scales,
        }
    }

    /// The camera at the options' image size.
    #[must_use]
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// What the tracer asks for nearest hits and feelers' shares.
    #[must_use]
    pub fn query(&self) -> &Q {
        &self.query
    }

    /// The scales of the views whose colours need one (depth, rays per pixel), fixed before
    /// the first pixel is traced.
    #[must_use]
    pub fn scales(&self) -> &Scales {
        &self.scales
    }

    // ANCHOR: ch2_nearest
    /// The nearest hit with t > `t_min` over all objects (the notes' steps 4 and 5: the
    /// smallest t; of equal t, the object listed first), as the tracer's [`Query`] finds it.
    #[must_use]
    pub fn nearest(&self, ray: &Ray, t_min: Real) -> Option<Nearest> {
        self.query.nearest(ray, t_min)
    }
    // ANCHOR_END: ch2_nearest
}

impl<Q: Query + Shortcuts> Tracer<'_, Q> {
    // ANCHOR: ch1_camera_ray
    /// What a camera ray brings back, `rec` told that it leaves, all that follows and the
    /// colour: in chapter 1 its direction; from chapter 2 on its nearest hit as `show` draws
    /// it — the chapter's own colour ([`Tracer::hit_colour`]), or another view's.
    pub(crate) fn camera_ray<R: Recorder>(
        &self,
        ray: &Ray,
        rec: &mut R,
        show: impl FnOnce(Option<Nearest>, &mut R) -> Vec3,
    ) -> Vec3 {
        rec.ray(RayKind::Camera, ray, 0.0, 0, 1.0, 1.0);
        let colour = if self.options.chapter == Chapter::CameraRays {
            direction_colour(ray.dir) // chapter 1: (d̂ + 1)/2
        } else {
            let nearest = self.query.nearest_camera(ray); // chapter 2: step 4, t > 0
            rec.hit(nearest.as_ref());
            show(nearest, rec)
        };
        rec.done(colour);
        colour
    }
    // ANCHOR_END: ch1_camera_ray

    // ANCHOR: ch2_hit_colour
    /// The chapter's own colour of a camera ray (from chapter 2 on) whose nearest hit is
    /// `nearest`: chapter 2's flat colour, then the hit shaded.
    pub(crate) fn hit_colour(
        &self,
        ray: &Ray,
        nearest: Option<Nearest>,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        if self.options.chapter == Chapter::GenericObjects {
            self.flat(nearest)
        } else {
            self.shade(ray, nearest, 0, 1.0, rec)
        }
    }

    /// Chapter 2's colour: the diffuse colour ρd of the material hit, unlit.
    pub(crate) fn flat(&self, nearest: Option<Nearest>) -> Vec3 {
        nearest.map_or(self.scene.background, |n| {
            self.scene.materials[self.scene.objects[n.object].material].diffuse
        })
    }
    // ANCHOR_END: ch2_hit_colour

    // ANCHOR: ch5_trace
    /// The light coming back along `ray` (chapters 3–5): the nearest hit after `t_min`, shaded.
    /// `depth` counts the bounces that led here and `weight` the share of the pixel the ray
    /// carries.
    pub fn trace(
        &self,
        ray: &Ray,
        t_min: Real,
        depth: u32,
        weight: Real,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        let nearest = self.query.nearest(ray, t_min);
        rec.hit(nearest.as_ref());
        self.shade(ray, nearest, depth, weight, rec)
    }
    // ANCHOR_END: ch5_trace

    // ANCHOR: ch3_shade
    /// I = I_a + I_d + I_s + I_l + I_r at the nearest hit of `ray` (the background colour for
    /// a miss): the local light, then from chapter 5 the mirror and transmitted rays.
    fn shade(
        &self,
        ray: &Ray,
        nearest: Option<Nearest>,
        depth: u32,
        weight: Real,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        let Some(nearest) = nearest else {
            return self.scene.background;
        };
        let s = self.query.shading_point(self.scene, ray, &nearest);
        let local = self.local_light(&s, rec);
        self.reflect_and_refract(&s, local, depth, weight, rec)
    }
    // ANCHOR_END: ch3_shade

    // ANCHOR: ch3_local_light_sig
    /// The local light I_a + Σ_lights (I_d + I_s)·share (chapters 3 and 4): Phong's terms of
    /// every light ([`shading::phong`]), each times the share of that light its feeler lets
    /// through (from chapter 4, [`Query::share`]; 1 without a feeler). Whether a light lies in
    /// front of the surface is decided here, once per light ([`shadow::in_front`]): it decides
    /// whether a feeler goes towards it, and the recorder is told.
    pub(crate) fn local_light(&self, s: &ShadingPoint, rec: &mut impl Recorder) -> Vec3 {
        // ANCHOR_END: ch3_local_light_sig
        // BEGIN SOLUTION local_light
        let i_a = shading::ambient(s.material, self.scene.ambient); // I_a
        rec.ambient(i_a);
        let mut color = i_a;
        for (l, light) in self.scene.lights.iter().enumerate() {
            let in_front = shadow::in_front(s.n, s.p, light.position); // n·(L − P) > 0
            let phong = shading::phong(s.material, light, s.p, s.n, -s.d); // I_d + I_s
            // a light behind the surface, or one that adds nothing, has nothing to shadow
            let feeler = if in_front && phong.sum != Vec3::ZERO {
                self.feeler(s, light)
            } else {
                None
            };
            let share = match &feeler {
                Some(feeler) => self.query.share(feeler, rec),
                None => 1.0,
            };
            let arriving = phong.sum * share; // (I_d + I_s)·share
            rec.light(l, in_front, &phong, feeler.as_ref(), share, arriving);
            color += arriving;
        }
        rec.local(color);
        color
        // END SOLUTION
    }

    // ANCHOR: ch4_feeler_sig
    /// From chapter 4, the feeler S(u) = P′ + (L − P′)·u towards a `light` that casts shadows,
    /// from P moved off the surface to P′ ([`crate::offset`]). It is asked only for a light in
    /// front of the surface, n·(L − P) > 0, as the caller has decided ([`shadow::in_front`]).
    #[inline]
    pub(crate) fn feeler(&self, s: &ShadingPoint, light: &Light) -> Option<Feeler> {
        let o = self.options;
        if o.chapter < Chapter::Shadows {
            return None; // no feelers before chapter 4 (given: not part of the exercise)
        }
        // ANCHOR_END: ch4_feeler_sig
        // BEGIN SOLUTION send_feeler
        if !light.shadows {
            return None;
        }
        let (start, u_min) = o.offset.spawn(&s.spawn, light.position - s.p);
        Some(Feeler {
            ray: shadow::feeler(start, light.position),
            u_min,
        })
        // END SOLUTION
    }

    // ANCHOR: ch5_reflect_and_refract_sig
    /// `color` + k_t·I_r + k_r·I_l (chapter 5, while `depth < max_depth`): the light of the
    /// transmitted ray (Snell's law, [`optics::refract`]) and of the mirror ray
    /// ([`optics::reflect`]), each traced in turn. Under total internal reflection the
    /// transmitted share goes to the mirror ray. A ray whose weight would fall below
    /// `min_weight` is not traced.
    pub(crate) fn reflect_and_refract(
        &self,
        s: &ShadingPoint,
        mut color: Vec3,
        depth: u32,
        weight: Real,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        let o = self.options;
        if o.chapter < Chapter::ReflectionRefraction {
            return color; // no secondary rays before chapter 5 (given: not part of the exercise)
        }
        // ANCHOR_END: ch5_reflect_and_refract_sig
        // BEGIN SOLUTION reflect_and_refract
        let (material, d, n) = (s.material, s.d, s.n);
        if depth >= o.max_depth {
            if material.is_translucent() {
                rec.stopped(RayKind::Transmitted, Stop::MaxDepth);
            }
            if material.reflection > 0.0 {
                rec.stopped(RayKind::Mirror, Stop::MaxDepth);
            }
            return color;
        }
        let mut k_r = material.reflection;
        if material.is_translucent() {
            // the side that was hit, as the shape found it
            let (n1, n2) = optics::indices(s.hit.entering, material.ior);
            match optics::refract(d, n, n1, n2) {
                Some(t_dir) => {
                    let k_t = material.transmission;
                    if weight * k_t >= o.min_weight {
                        let (origin, t0) = o.offset.spawn(&s.spawn, t_dir);
                        let ray = Ray::new(origin, t_dir);
                        let i_r = self.trace_branch(
                            RayKind::Transmitted,
                            k_t,
                            &ray,
                            t0,
                            depth + 1,
                            weight * k_t,
                            rec,
                        );
                        color += k_t * i_r;
                    } else {
                        rec.stopped(RayKind::Transmitted, Stop::Weight);
                    }
                }
                None => {
                    k_r += material.transmission; // total internal reflection
                    rec.stopped(RayKind::Transmitted, Stop::TotalInternalReflection);
                }
            }
        }
        if k_r > 0.0 {
            if weight * k_r >= o.min_weight {
                let l = optics::reflect(d, n);
                let (origin, t0) = o.offset.spawn(&s.spawn, l);
                let ray = Ray::new(origin, l);
                let i_l =
                    self.trace_branch(RayKind::Mirror, k_r, &ray, t0, depth + 1, weight * k_r, rec);
                color += k_r * i_l;
            } else {
                rec.stopped(RayKind::Mirror, Stop::Weight);
            }
        }
        color
        // END SOLUTION
    }

    // ANCHOR: ch5_trace_branch
    /// Traces a mirror or transmitted branch of a hit: tells `rec` that it leaves, whose light
    /// counts `k` times (k_r or k_t) at the hit it leaves, then what it brings back.
    #[allow(clippy::too_many_arguments)] // the branch's values the recorder hears, each named
    fn trace_branch(
        &self,
        kind: RayKind,
        k: Real,
        ray: &Ray,
        t_min: Real,
        depth: u32,
        weight: Real,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        rec.ray(kind, ray, t_min, depth, weight, k);
        let colour = self.trace(ray, t_min, depth, weight, rec);
        rec.done(colour);
        colour
    }
    // ANCHOR_END: ch5_trace_branch
}
