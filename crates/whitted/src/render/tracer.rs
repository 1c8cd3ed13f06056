//! The road of one pixel: every chapter's renderer, one stop after another.
//!
//! ```text
//! pixel (x, y) ─► camera ray (ch1) ─► nearest hit over the objects (ch2)
//!   ─► I_a + Σ lights (I_d + I_s) (ch3) ─► × the share of each feeler (ch4)
//!   ─► + k_t·I_r + k_r·I_l from the transmitted and mirror rays, recursively (ch5) ─► colour
//! ```
//!
//! Read it top to bottom: [`Tracer::pixel`] → `Tracer::camera_ray` → [`Tracer::nearest`]
//! → `Tracer::shade` → `Tracer::local_light` (with `Tracer::feeler`) →
//! `Tracer::reflect_and_refract` → [`Tracer::trace`] for each new ray. Each stop calls the
//! small function of the notes' formula ([`crate::camera`], [`crate::shapes`], [`crate::shading`],
//! [`crate::shadow`], [`crate::optics`]); no formula is computed here. How far a chapter goes:
//!
//! | [`Chapter`] | what a camera ray returns |
//! |---|---|
//! | 1 [`Chapter::CameraRays`] | the ray direction as a colour, (d̂ + 1)/2 |
//! | 2 [`Chapter::GenericObjects`] | the nearest hit, seen through a [`View`] (flat colour, normals, depth) |
//! | 3 [`Chapter::Shading`] | ambient + diffuse + specular from every light (Phong) |
//! | 4 [`Chapter::Shadows`] | the same, each light tested by a feeler ray |
//! | 5 [`Chapter::ReflectionRefraction`] | plus mirror and transmitted rays, recursively: I = I_a + I_d + I_s + I_l + I_r |
//!
//! The scene decides which stops are needed: no feeler for a light with `shadows = false`, no
//! mirror ray from a material with `reflection = 0`, no transmitted ray where
//! `transmission = 0`. Every stop tells a [`Recorder`] what it did: a plain render's
//! [`Stats`](super::Stats) counts rays, `--inspect`'s [`super::inspect::TreeRecorder`] keeps
//! the ray tree. The nearest hit, and what a feeler crosses, are asked of the acceleration
//! structure ([`crate::accel`]), which gives exactly what testing every object in turn gives.
//! Tiles ([`super::tiles`]) and packets ([`super::packets`]) sit around this road and call
//! the same functions. Course book: [Chapter 1, camera rays](../../../../../docs/book/ch01-camera-rays.html) (`docs/src/ch01-camera-rays.md`).

use std::borrow::Cow;

use super::recorder::{RayKind, Recorder, Stop};
use super::{Chapter, Options, View, build_accel, sampling, views};
use crate::accel::Accelerator;
use crate::camera::{Camera, direction_colour};
use crate::light::Light;
use crate::material::Material;
use crate::offset::SpawnPoint;
use crate::optics;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading;
use crate::shadow;
use crate::shapes::{Hit, Nearest};

/// Traces rays through one scene with one set of options.
pub struct Tracer<'a> {
    pub(crate) scene: &'a Scene,
    /// The options it renders with: size, chapter, view, depth …
    pub options: &'a Options,
    pub(crate) camera: Camera,
    pub(crate) accel: Cow<'a, Accelerator>,
    /// The scales of the depth and rays-per-pixel views, fixed before the first pixel.
    pub(crate) scales: views::Scales,
}

/// A hit as shading sees it.
pub struct Surface<'s> {
    /// The hit (world normal, pointing out of the object).
    pub hit: Hit,
    /// The material hit.
    pub material: &'s Material,
    /// The hit point P = r(t).
    pub p: Vec3,
    /// The ray's unit direction.
    pub d: Vec3,
    /// The shading normal n, turned towards the viewer.
    pub n: Vec3,
    /// Where rays leaving the hit start.
    pub spawn: SpawnPoint,
}

// ANCHOR: ch4_feeler_type
/// A feeler S(u) = P′ + (L − P′)·u from the offset start P′, and the smallest u that counts.
pub type Feeler = (Ray, Real);
// ANCHOR_END: ch4_feeler_type

impl<'a> Tracer<'a> {
    /// A tracer for the scene with the options' image size (builds `options.accel`).
    #[must_use]
    pub fn new(scene: &'a Scene, options: &'a Options) -> Self {
        Self::with(scene, options, Cow::Owned(build_accel(scene, options)))
    }

    /// A tracer using an acceleration structure built beforehand (see [`build_accel`]).
    #[must_use]
    pub fn with_accel(scene: &'a Scene, options: &'a Options, accel: &'a Accelerator) -> Self {
        Self::with(scene, options, Cow::Borrowed(accel))
    }

    fn with(scene: &'a Scene, options: &'a Options, accel: Cow<'a, Accelerator>) -> Self {
        let mut tracer = Self {
            scene,
            options,
            camera: options.camera(scene),
            accel,
            scales: views::Scales::default(),
        };
        tracer.scales = views::Scales::measure(&tracer);
        tracer
    }

    /// The camera at the options' image size.
    #[must_use]
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    // ANCHOR: ch1_pixel
    /// The colour of pixel (x, y), row y from the top: the mean over its samples. `rec`
    /// hears every stop of the road ([`Stats`](super::Stats) counts the rays).
    pub fn pixel(&self, x: u32, y: u32, rec: &mut impl Recorder) -> Vec3 {
        if self.options.view == View::Rays {
            // the colour is the number of rays this pixel cast
            let mut count = super::Stats::default();
            self.samples(x, y, &mut (rec, &mut count));
            return self.scales.heat(count.total());
        }
        self.samples(x, y, rec)
    }

    /// The mean of the colours the samples of pixel (x, y) bring back.
    fn samples(&self, x: u32, y: u32, rec: &mut impl Recorder) -> Vec3 {
        let o = self.options;
        let samples = o.samples_per_pixel();
        let mut sum = Vec3::ZERO;
        for s in 0..samples {
            let (dx, dy) = sampling::sample_position(o.seed, samples, x, y, s);
            rec.sample(s, dx, dy);
            let ray = self.camera.pixel_ray(x, y, dx, dy); // chapter 1: r(t) = e + d·t
            rec.ray(RayKind::Camera, &ray, 0.0, 0, 1.0);
            let colour = self.camera_ray(&ray, (x, y), rec);
            rec.done(colour);
            sum += colour;
        }
        sum / samples as Real
    }
    // ANCHOR_END: ch1_pixel

    // ANCHOR: ch1_camera_ray
    /// What the camera ray of image pixel `pixel` brings back.
    fn camera_ray(&self, ray: &Ray, pixel: (u32, u32), rec: &mut impl Recorder) -> Vec3 {
        if self.options.chapter == Chapter::CameraRays {
            return direction_colour(ray.dir); // chapter 1: (d̂ + 1)/2
        }
        let nearest = self.nearest_from(ray, 0.0, Some(pixel));
        rec.hit(nearest.as_ref());
        self.seen(ray, nearest, rec)
    }
    // ANCHOR_END: ch1_camera_ray

    // ANCHOR: ch2_seen
    /// The colour of a camera ray (from chapter 2 on) whose nearest hit is `nearest`, as the
    /// view shows it.
    pub(crate) fn seen(
        &self,
        ray: &Ray,
        nearest: Option<Nearest>,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        let o = self.options;
        match o.view {
            View::Color | View::Rays if o.chapter == Chapter::GenericObjects => self.flat(nearest),
            View::Color | View::Rays => self.shade(ray, nearest, 0, 1.0, rec),
            View::Flat => self.flat(nearest),
            View::Normals => match nearest {
                Some(n) => direction_colour(facing(n.hit.normal, ray.dir)),
                None => self.scene.background,
            },
            View::Depth => self
                .scales
                .depth(nearest.map(|n| n.hit.t * ray.dir.length())),
            View::Shadows => match nearest {
                Some(n) => self.shadow_mask(&self.surface(ray, &n), rec),
                None => Vec3::ZERO,
            },
        }
    }

    /// Chapter 2's colour: the diffuse colour ρd of the material hit, unlit.
    fn flat(&self, nearest: Option<Nearest>) -> Vec3 {
        match nearest {
            Some(n) => self.scene.materials[self.scene.objects[n.object].material].diffuse,
            None => self.scene.background,
        }
    }
    // ANCHOR_END: ch2_seen

    // ANCHOR: ch2_nearest
    /// The nearest hit with t > `t_min` over all objects (the notes' step 5: the smallest t;
    /// of equal t, the object listed first).
    #[must_use]
    pub fn nearest(&self, ray: &Ray, t_min: Real) -> Option<Nearest> {
        self.nearest_from(ray, t_min, None)
    }

    /// [`Tracer::nearest`] for a ray that may be the camera ray of image pixel `pixel`.
    fn nearest_from(&self, ray: &Ray, t_min: Real, pixel: Option<(u32, u32)>) -> Option<Nearest> {
        self.accel.nearest(
            &self.scene.objects,
            ray,
            t_min,
            self.options.numerics,
            pixel,
        )
    }
    // ANCHOR_END: ch2_nearest

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
        let nearest = self.nearest(ray, t_min);
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
        let s = self.surface(ray, &nearest);
        let local = self.local_light(&s, |_, feeler| self.transmittance(feeler), rec);
        self.reflect_and_refract(&s, local, depth, weight, rec)
    }
    // ANCHOR_END: ch3_shade

    // ANCHOR: ch3_surface
    /// What shading needs to know of a hit.
    pub(crate) fn surface<'s>(&'s self, ray: &Ray, nearest: &Nearest) -> Surface<'s> {
        let hit = nearest.hit;
        let object = &self.scene.objects[nearest.object];
        let d = crate::numeric::normalize(ray.dir);
        Surface {
            hit,
            material: &self.scene.materials[object.material],
            p: ray.at(hit.t),
            d,
            n: facing(hit.normal, d), // shading normal, towards the viewer
            spawn: SpawnPoint::new(object, ray, &hit),
        }
    }
    // ANCHOR_END: ch3_surface

    // ANCHOR: ch3_local_light_sig
    /// The local light I_a + Σ_lights (I_d + I_s)·share (chapters 3 and 4): Phong's terms of
    /// every light, each times the share of that light its feeler lets through (from chapter 4;
    /// 1 before). `share(light, feeler)` answers for the feeler towards light number `light`:
    /// `Tracer::shade` traces it (`Tracer::transmittance`); a packet of pixels looks up
    /// what it traced for all of them at once.
    pub(crate) fn local_light(
        &self,
        s: &Surface,
        mut share: impl FnMut(usize, &Feeler) -> Real,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        // ANCHOR_END: ch3_local_light_sig
        // BEGIN SOLUTION local_light
        let i_a = shading::ambient(s.material, self.scene.ambient); // I_a
        rec.ambient(i_a);
        let mut color = i_a;
        for (l, light) in self.scene.lights.iter().enumerate() {
            let unshadowed = shading::direct(s.material, light, s.p, s.n, -s.d); // I_d + I_s
            if unshadowed == Vec3::ZERO {
                rec.light(l, s, unshadowed, None, 1.0);
                continue; // the light is behind the surface: nothing to shadow
            }
            let arriving = match self.feeler(s, light) {
                Some(feeler) => {
                    let arriving = share(l, &feeler);
                    rec.light(l, s, unshadowed, Some(&feeler), arriving);
                    arriving
                }
                None => {
                    rec.light(l, s, unshadowed, None, 1.0);
                    1.0
                }
            };
            color += unshadowed * arriving;
        }
        rec.local(color);
        color
        // END SOLUTION
    }

    // ANCHOR: ch4_feeler_sig
    /// From chapter 4, the feeler S(u) = P′ + (L − P′)·u towards a `light` that casts shadows
    /// and lies in front, n·(L − P) > 0, from P moved off the surface to P′ ([`crate::offset`]).
    pub(crate) fn feeler(&self, s: &Surface, light: &Light) -> Option<Feeler> {
        let o = self.options;
        if o.chapter < Chapter::Shadows {
            return None; // no feelers before chapter 4 (given: not part of the exercise)
        }
        // ANCHOR_END: ch4_feeler_sig
        // BEGIN SOLUTION send_feeler
        if !light.shadows || s.n.dot(light.position - s.p) <= 0.0 {
            return None;
        }
        let (start, u_min) = o.offset.spawn(&s.spawn, light.position - s.p);
        Some((shadow::feeler(start, light.position), u_min))
        // END SOLUTION
    }

    // ANCHOR: ch4_transmittance
    /// The share of its light that a feeler lets through: the product of the transmissions of
    /// the objects it crosses with u ∈ ]u_min, 1] ([`crate::shadow`]).
    #[inline] // two callers (this road and the shadow-mask view): keep it in the road
    pub(crate) fn transmittance(&self, (feeler, u_min): &Feeler) -> Real {
        self.accel.transmittance(
            &self.scene.objects,
            &self.scene.materials,
            feeler,
            *u_min,
            self.options.numerics,
        )
    }
    // ANCHOR_END: ch4_transmittance

    // ANCHOR: ch5_reflect_and_refract_sig
    /// `color` + k_t·I_r + k_r·I_l (chapter 5, while `depth < max_depth`): the light of the
    /// transmitted ray (Snell's law, [`optics::refract`]) and of the mirror ray
    /// ([`optics::reflect`]), each traced in turn. Under total internal reflection the
    /// transmitted share goes to the mirror ray. A ray whose weight would fall below
    /// `min_weight` is not traced.
    pub(crate) fn reflect_and_refract(
        &self,
        s: &Surface,
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
            let entering = s.hit.normal.dot(d) < 0.0; // the side that was hit
            let (n1, n2) = optics::indices(entering, material.ior);
            match optics::refract(d, n, n1, n2) {
                Some(t_dir) => {
                    let k_t = material.transmission;
                    if weight * k_t >= o.min_weight {
                        let (origin, t0) = o.offset.spawn(&s.spawn, t_dir);
                        let ray = Ray::new(origin, t_dir);
                        let i_r = self.follow(
                            RayKind::Transmitted,
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
                let i_l = self.follow(RayKind::Mirror, &ray, t0, depth + 1, weight * k_r, rec);
                color += k_r * i_l;
            } else {
                rec.stopped(RayKind::Mirror, Stop::Weight);
            }
        }
        color
        // END SOLUTION
    }

    // ANCHOR: ch5_follow
    /// Traces a mirror or transmitted ray, telling `rec` it leaves and what it brings back.
    fn follow(
        &self,
        kind: RayKind,
        ray: &Ray,
        t_min: Real,
        depth: u32,
        weight: Real,
        rec: &mut impl Recorder,
    ) -> Vec3 {
        rec.ray(kind, ray, t_min, depth, weight);
        let colour = self.trace(ray, t_min, depth, weight, rec);
        rec.done(colour);
        colour
    }
    // ANCHOR_END: ch5_follow
}

// ANCHOR: ch3_facing
/// The normal n turned to face against the direction `d` (towards where the ray came from).
fn facing(n: Vec3, d: Vec3) -> Vec3 {
    if n.dot(d) > 0.0 { -n } else { n }
}
// ANCHOR_END: ch3_facing
