//! The trace loop shared by every chapter: one straight road with more stops per chapter.
//!
//! [`render`] shoots one or more rays through every pixel and asks [`Tracer::trace`] for the
//! light coming back along each. [`Stage`] decides which stops exist:
//!
//! | stage | what a primary ray returns |
//! |---|---|
//! | 1 [`Stage::CameraRays`] | the ray direction as a colour, (d̂ + 1)/2 |
//! | 2 [`Stage::GenericObjects`] | the nearest hit, seen through a [`View`] (flat colour, normals, depth) |
//! | 3 [`Stage::Shading`] | ambient + diffuse + specular from every light (Phong) |
//! | 4 [`Stage::Shadows`] | the same, each light tested by a feeler ray |
//! | 5 [`Stage::ReflectionRefraction`] | plus mirror and transmitted rays, recursively: I = I_a + I_d + I_s + I_l + I_r |
//!
//! and the scene decides which of those stops are needed: no feeler for a light with
//! `shadows = false`, no mirror ray from a material with `reflection = 0`, no transmitted ray
//! where `transmission = 0`. [`Stats`] counts the rays of each kind, which is how the tests
//! show that no work is done for a feature a scene does not use.
//!
//! The image is cut into tiles rendered in parallel (rayon). Every pixel depends only on its
//! own coordinates (supersampling positions come from a hash of the pixel and sample index),
//! so the image is the same whatever the number of threads. Tiles are written straight into
//! the framebuffer (one band of tile rows per task), so memory is the framebuffer itself:
//! [`check_size`] refuses, before any work, an image whose framebuffer would pass
//! [`MAX_FRAMEBUFFER_BYTES`].
//!
//! Nearest-hit and feeler queries go through the acceleration structure chosen by
//! [`Options::accel`] (notes: "Computational Aspects"; see [`crate::accel`]); every choice
//! gives the same image.

use std::borrow::Cow;

use rayon::prelude::*;

use crate::accel::{Accel, Accelerator};

use crate::camera::Camera;
use crate::error::Error;
use crate::offset::{Offset, SpawnPoint};
use crate::optics;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading;
use crate::shapes::{Formula, Hit};

/// Which chapter's renderer runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stage {
    /// Chapter 1: rays only.
    CameraRays = 1,
    /// Chapter 2: nearest hit.
    GenericObjects = 2,
    /// Chapter 3: Phong shading.
    Shading = 3,
    /// Chapter 4: shadows.
    Shadows = 4,
    /// Chapter 5: reflection and refraction.
    ReflectionRefraction = 5,
}

/// What a stage-2 (or later) render shows at each pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, clap::ValueEnum)]
pub enum View {
    /// The stage's own colour (for stage 2: the flat colour).
    #[default]
    Color,
    /// The material's diffuse colour ρd, unlit.
    Flat,
    /// The world normal n mapped to a colour, (n + 1)/2.
    Normals,
    /// Distance to the nearest hit, near = white, far = dark.
    Depth,
}

/// Everything about a render that is not in the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// The chapter.
    pub stage: Stage,
    /// What to show.
    pub view: View,
    /// Image width (pixels).
    pub width: u32,
    /// Image height (pixels).
    pub height: u32,
    /// Samples per pixel (1 = the pixel centre).
    pub samples: u32,
    /// Maximum recursion depth: a primary ray has depth 0, its mirror ray depth 1 …
    pub max_depth: u32,
    /// A secondary ray whose weight (product of reflection/transmission shares) falls below
    /// this is not traced.
    pub min_weight: Real,
    /// Textbook or robust intersection formulas.
    pub formula: Formula,
    /// How secondary rays leave a surface.
    pub offset: Offset,
    /// Seed of the supersampling positions.
    pub seed: u64,
    /// Which acceleration structure answers ray queries (the image does not depend on it).
    pub accel: Accel,
}

impl Options {
    /// The scene's own settings for `stage`: its size, samples and depth, robust formulas and
    /// the default offset.
    #[must_use]
    pub fn for_scene(scene: &Scene, stage: Stage) -> Self {
        Self {
            stage,
            view: View::Color,
            width: scene.width,
            height: scene.height,
            // supersampling belongs to chapter 5; earlier chapters shoot one ray per pixel centre
            samples: if stage == Stage::ReflectionRefraction {
                scene.samples
            } else {
                1
            },
            max_depth: scene.max_depth,
            min_weight: Self::MIN_WEIGHT,
            formula: Formula::default(),
            offset: Offset::default(),
            seed: 0x5eed,
            accel: Accel::default(),
        }
    }

    /// The default weight threshold: a contribution below 1/1000 (a quarter of one 8-bit step)
    /// cannot change a pixel.
    pub const MIN_WEIGHT: Real = 1e-3;
}

/// Rays cast, by kind, and (built with the `counters` feature) the work behind their queries.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Camera rays.
    pub primary: u64,
    /// Feeler rays towards lights.
    pub shadow: u64,
    /// Mirror rays.
    pub reflected: u64,
    /// Transmitted rays.
    pub refracted: u64,
    /// Mirror rays spawned by total internal reflection (counted in `reflected` too).
    pub total_internal: u64,
    /// What the ray queries tested (all zero unless built with the `counters` feature).
    pub work: crate::accel::counters::Counts,
}

impl Stats {
    /// All rays.
    #[must_use]
    pub fn total(&self) -> u64 {
        self.primary + self.shadow + self.reflected + self.refracted
    }

    fn add(&mut self, o: &Stats) {
        self.primary += o.primary;
        self.shadow += o.shadow;
        self.reflected += o.reflected;
        self.refracted += o.refracted;
        self.total_internal += o.total_internal;
        self.work.add(&o.work);
    }
}

/// A linear-RGB image, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row-major pixels, top row first.
    pub pixels: Vec<Vec3>,
}

impl Framebuffer {
    /// The pixel at column x, row y (from the top).
    #[must_use]
    pub fn get(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[(y * self.width + x) as usize]
    }
}

/// The nearest hit of a ray: the hit, the object's index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nearest {
    /// The hit.
    pub hit: Hit,
    /// Index of the object hit.
    pub object: usize,
}

/// Traces rays through one scene with one set of options.
pub struct Tracer<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// The options.
    pub options: &'a Options,
    /// The camera at the options' image size.
    pub camera: Camera,
    /// The acceleration structure over the scene's objects.
    pub accel: Cow<'a, Accelerator>,
}

/// Side of the square tiles the image is rendered in.
pub const TILE: u32 = 16;

/// The largest framebuffer a render may allocate: 4 GiB, that is width × height × 3 ×
/// `size_of::<Real>()` bytes (f64: 178 956 970 pixels, e.g. 13 377 × 13 377; f32: twice as
/// many). The 8-bit copy written to the PNG adds 3 bytes per pixel.
pub const MAX_FRAMEBUFFER_BYTES: u64 = 4 << 30;

/// Refuses an image whose framebuffer would pass [`MAX_FRAMEBUFFER_BYTES`]: call it before
/// any work starts.
pub fn check_size(width: u32, height: u32) -> Result<(), Error> {
    let bytes = u64::from(width) * u64::from(height) * std::mem::size_of::<Vec3>() as u64;
    if bytes > MAX_FRAMEBUFFER_BYTES {
        return Err(Error::Usage(format!(
            "image {width}×{height} is too large: its framebuffer would take {:.1} GiB, more than the limit of {} GiB",
            bytes as f64 / (1u64 << 30) as f64,
            MAX_FRAMEBUFFER_BYTES >> 30
        )));
    }
    Ok(())
}

/// Builds the acceleration structure `options.accel` for the scene seen at the options' size.
#[must_use]
pub fn build_accel(scene: &Scene, options: &Options) -> Accelerator {
    let camera = scene.camera.camera(options.width, options.height);
    // chapter 1 intersects nothing
    let kind = if options.stage == Stage::CameraRays {
        Accel::None
    } else {
        options.accel
    };
    Accelerator::build(&scene.objects, &camera, kind, TILE)
}

/// Renders the scene: returns the image and the rays cast.
#[must_use]
pub fn render(scene: &Scene, options: &Options) -> (Framebuffer, Stats) {
    let accel = build_accel(scene, options);
    render_with(scene, options, &accel, &|_| {})
}

/// Renders the scene with a prepared acceleration structure, calling `progress(pixels)` as
/// each tile is done (from any thread).
#[must_use]
pub fn render_with(
    scene: &Scene,
    options: &Options,
    accel: &Accelerator,
    progress: &(dyn Fn(u64) + Sync),
) -> (Framebuffer, Stats) {
    let tracer = Tracer::with_accel(scene, options, accel);
    let (w, h) = (options.width, options.height);
    let mut fb = Framebuffer {
        width: w,
        height: h,
        pixels: vec![Vec3::ZERO; (w as usize) * (h as usize)],
    };
    // one band of TILE rows per task; inside it, tile by tile
    let band = (w as usize) * TILE as usize;
    let stats = fb
        .pixels
        .par_chunks_mut(band)
        .enumerate()
        .map(|(ty, rows)| {
            let mut stats = Stats::default();
            // start this thread's counts afresh: they are this band's when it ends
            let _ = crate::accel::counters::take();
            let y0 = ty as u32 * TILE;
            let y1 = (y0 + TILE).min(h);
            for x0 in (0..w).step_by(TILE as usize) {
                let x1 = (x0 + TILE).min(w);
                for y in y0..y1 {
                    let row = (y - y0) as usize * w as usize;
                    for x in x0..x1 {
                        rows[row + x as usize] = tracer.pixel(x, y, &mut stats);
                    }
                }
                progress(u64::from((x1 - x0) * (y1 - y0)));
            }
            stats.work = crate::accel::counters::take();
            stats
        })
        .reduce(Stats::default, |mut a, b| {
            a.add(&b);
            a
        });
    if options.view == View::Depth && options.stage >= Stage::GenericObjects {
        shade_depth(&mut fb);
    }
    (fb, stats)
}

/// Maps distances (∞ for a miss) to grey levels: nearest 1, farthest 0.15, misses 0.
fn shade_depth(fb: &mut Framebuffer) {
    let finite = fb.pixels.iter().map(|p| p.x).filter(|d| d.is_finite());
    let (lo, hi) = finite.fold((Real::INFINITY, Real::NEG_INFINITY), |(lo, hi), d| {
        (lo.min(d), hi.max(d))
    });
    let range = (hi - lo).max(Real::MIN_POSITIVE);
    for p in &mut fb.pixels {
        *p = if p.x.is_finite() {
            Vec3::splat(1.0 - 0.85 * (p.x - lo) / range)
        } else {
            Vec3::ZERO
        };
    }
}

/// A well-mixed 64-bit hash (the SplitMix64 finaliser) for sample positions.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// A number in [0, 1) from a hash.
fn unit(h: u64) -> Real {
    (h >> 11) as Real * (1.0 / (1u64 << 53) as Real)
}

impl<'a> Tracer<'a> {
    /// A tracer for the scene with the options' image size (builds `options.accel`).
    #[must_use]
    pub fn new(scene: &'a Scene, options: &'a Options) -> Self {
        Self {
            scene,
            options,
            camera: scene.camera.camera(options.width, options.height),
            accel: Cow::Owned(build_accel(scene, options)),
        }
    }

    /// A tracer using an acceleration structure built beforehand (see [`build_accel`]).
    #[must_use]
    pub fn with_accel(scene: &'a Scene, options: &'a Options, accel: &'a Accelerator) -> Self {
        Self {
            scene,
            options,
            camera: scene.camera.camera(options.width, options.height),
            accel: Cow::Borrowed(accel),
        }
    }

    /// The position inside pixel (x, y) of sample `s`: the centre for one sample; for a square
    /// number of samples k², one jittered point in each cell of a k × k grid; otherwise
    /// jittered points over the whole pixel. The jitter comes from a hash of the seed, the pixel
    /// and the sample index, so every run (and every thread count) gives the same image.
    #[must_use]
    pub fn sample_position(&self, x: u32, y: u32, s: u32) -> (Real, Real) {
        let n = self.options.samples;
        if n <= 1 {
            return (0.5, 0.5);
        }
        let h = mix(self.options.seed ^ mix(((y as u64) << 32 | x as u64) ^ mix(s as u64)));
        let (jx, jy) = (unit(h), unit(mix(h)));
        let k = (n as f64).sqrt().round() as u32;
        if k * k == n {
            let (sx, sy) = (s % k, s / k);
            ((sx as Real + jx) / k as Real, (sy as Real + jy) / k as Real)
        } else {
            (jx, jy)
        }
    }

    /// The colour of pixel (x, y), row y from the top: the mean over its samples.
    pub fn pixel(&self, x: u32, y: u32, stats: &mut Stats) -> Vec3 {
        let o = self.options;
        let samples = if o.view == View::Depth {
            1
        } else {
            o.samples.max(1)
        };
        let mut sum = Vec3::ZERO;
        for s in 0..samples {
            let (dx, dy) = if samples == 1 {
                (0.5, 0.5)
            } else {
                self.sample_position(x, y, s)
            };
            let ray = self.camera.pixel_ray(x, y, dx, dy);
            stats.primary += 1;
            sum += self.primary(&ray, (x, y), stats);
        }
        sum / samples as Real
    }

    fn primary(&self, ray: &Ray, pixel: (u32, u32), stats: &mut Stats) -> Vec3 {
        let at = Some(pixel);
        let o = self.options;
        if o.stage == Stage::CameraRays {
            return (crate::numeric::normalize(ray.dir) + Vec3::ONE) * 0.5;
        }
        match o.view {
            View::Color if o.stage == Stage::GenericObjects => self.flat(ray, at),
            View::Color => self.trace_from(ray, 0.0, 0, 1.0, stats, at),
            View::Flat => self.flat(ray, at),
            View::Normals => match self.nearest_from(ray, 0.0, at) {
                Some(n) => (self.facing(n.hit.normal, ray.dir) + Vec3::ONE) * 0.5,
                None => self.scene.background,
            },
            View::Depth => match self.nearest_from(ray, 0.0, at) {
                Some(n) => Vec3::splat(n.hit.t * ray.dir.length()),
                None => Vec3::splat(Real::INFINITY),
            },
        }
    }

    fn flat(&self, ray: &Ray, at: Option<(u32, u32)>) -> Vec3 {
        match self.nearest_from(ray, 0.0, at) {
            Some(n) => self.scene.materials[self.scene.objects[n.object].material].diffuse,
            None => self.scene.background,
        }
    }

    /// The nearest hit with t > `t_min` over all objects (the notes' step 5: smallest t; among
    /// equal t, the object listed first).
    #[must_use]
    pub fn nearest(&self, ray: &Ray, t_min: Real) -> Option<Nearest> {
        self.nearest_from(ray, t_min, None)
    }

    /// [`Tracer::nearest`] for a ray that may be the camera ray of image pixel `pixel`.
    fn nearest_from(&self, ray: &Ray, t_min: Real, pixel: Option<(u32, u32)>) -> Option<Nearest> {
        self.accel
            .nearest(&self.scene.objects, ray, t_min, self.options.formula, pixel)
    }

    /// The normal turned to face against the direction `d` (towards where the ray came from).
    fn facing(&self, n: Vec3, d: Vec3) -> Vec3 {
        if n.dot(d) > 0.0 { -n } else { n }
    }

    /// The light coming back along `ray` (stages 3–5): local Phong shading, shadows from
    /// stage 4, mirror and transmitted rays from stage 5 while `depth < max_depth` and the
    /// ray's `weight` stays above the threshold.
    pub fn trace(
        &self,
        ray: &Ray,
        t_min: Real,
        depth: u32,
        weight: Real,
        stats: &mut Stats,
    ) -> Vec3 {
        self.trace_from(ray, t_min, depth, weight, stats, None)
    }

    /// [`Tracer::trace`] for a ray that may be the camera ray of image pixel `pixel`.
    fn trace_from(
        &self,
        ray: &Ray,
        t_min: Real,
        depth: u32,
        weight: Real,
        stats: &mut Stats,
        pixel: Option<(u32, u32)>,
    ) -> Vec3 {
        let Some(nearest) = self.nearest_from(ray, t_min, pixel) else {
            return self.scene.background;
        };
        let scene = self.scene;
        let o = self.options;
        let hit = nearest.hit;
        let object = &scene.objects[nearest.object];
        let material = &scene.materials[object.material];
        let p = ray.at(hit.t);
        let d = crate::numeric::normalize(ray.dir);
        let n = self.facing(hit.normal, d); // shading normal, towards the viewer
        let v = -d;
        let spawn = SpawnPoint::new(object, ray, &hit);

        // I_a + Σ (I_d + I_s), with feelers from stage 4
        let mut color = shading::ambient(material, scene.ambient);
        for light in &scene.lights {
            let mut local = shading::direct(material, light, p, n, v);
            if local == Vec3::ZERO {
                continue; // light behind the surface: no feeler needed
            }
            if o.stage >= Stage::Shadows && light.shadows {
                stats.shadow += 1;
                let (origin, u_min) = o.offset.spawn(&spawn, light.position - p);
                local *= self.accel.transmittance(
                    &scene.objects,
                    &scene.materials,
                    origin,
                    light.position,
                    u_min,
                    o.formula,
                );
            }
            color += local;
        }

        if o.stage < Stage::ReflectionRefraction || depth >= o.max_depth {
            return color;
        }

        // I_l + I_r
        let mut kr = material.reflection;
        if material.is_translucent() {
            let entering = hit.normal.dot(d) < 0.0; // the side that was hit
            let (n1, n2) = optics::indices(entering, material.ior);
            match optics::refract(d, n, n1 / n2) {
                Some(t_dir) => {
                    let w = weight * material.transmission;
                    if w >= o.min_weight {
                        stats.refracted += 1;
                        let (origin, t0) = o.offset.spawn(&spawn, t_dir);
                        let r = Ray::new(origin, t_dir);
                        color += material.transmission * self.trace(&r, t0, depth + 1, w, stats);
                    }
                }
                None => {
                    kr += material.transmission; // total internal reflection: all goes to the mirror ray
                    stats.total_internal += 1;
                }
            }
        }
        if kr > 0.0 && weight * kr >= o.min_weight {
            stats.reflected += 1;
            let l = optics::reflect(d, n);
            let (origin, t0) = o.offset.spawn(&spawn, l);
            let r = Ray::new(origin, l);
            color += kr * self.trace(&r, t0, depth + 1, weight * kr, stats);
        }
        color
    }
}
