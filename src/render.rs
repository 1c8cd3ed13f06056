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
//!
//! With a BVH or an octree and one ray a pixel, a tile is traced in blocks of [`BLOCK`] ×
//! [`BLOCK`] pixels: their camera rays go through the structure as one packet, and so do
//! their feelers towards each light ([`crate::accel::Accelerator::nearest_packet`],
//! [`crate::accel::Accelerator::transmittance_packet`]). Each pixel is then shaded as
//! [`Tracer::trace`] shades it, with the same sums in the same order, and its mirror and
//! transmitted rays are traced one by one: the packets change the time, not a bit of the
//! image.

use std::borrow::Cow;

use arrayvec::ArrayVec;
use rayon::prelude::*;

use crate::accel::{Accel, Accelerator};

use crate::camera::Camera;
use crate::error::Error;
use crate::light::Light;
use crate::material::Material;
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

/// Up to one value per pixel of a block (see [`Tracer::block`]).
type Block<T> = ArrayVec<T, { crate::accel::PACKET }>;

/// A hit as shading sees it.
struct Surface<'s> {
    /// The hit (object space t, world normal).
    hit: Hit,
    /// The material hit.
    material: &'s Material,
    /// The hit point.
    p: Vec3,
    /// The ray's unit direction.
    d: Vec3,
    /// The shading normal, turned towards the viewer.
    n: Vec3,
    /// Where rays leaving the hit start.
    spawn: SpawnPoint,
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

/// Side of the square blocks of pixels whose camera rays are traced as one packet
/// (BLOCK² ≤ [`crate::accel::PACKET`]).
pub const BLOCK: u32 = 4;

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
                // blocks of BLOCK × BLOCK pixels, whose camera rays go through the tree together
                for by in (y0..y1).step_by(BLOCK as usize) {
                    let by1 = (by + BLOCK).min(y1);
                    for bx in (x0..x1).step_by(BLOCK as usize) {
                        let bx1 = (bx + BLOCK).min(x1);
                        let colours = tracer.block((bx, bx1), (by, by1), &mut stats);
                        let mut c = colours.iter();
                        for y in by..by1 {
                            let row = (y - y0) as usize * w as usize;
                            for x in bx..bx1 {
                                rows[row + x as usize] = *c.next().expect("one colour a pixel");
                            }
                        }
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
        if self.options.stage == Stage::CameraRays {
            return (crate::numeric::normalize(ray.dir) + Vec3::ONE) * 0.5;
        }
        let nearest = self.nearest_from(ray, 0.0, Some(pixel));
        self.seen(ray, nearest, stats)
    }

    /// The colour of a camera ray (from stage 2 on) whose nearest hit is `nearest`.
    fn seen(&self, ray: &Ray, nearest: Option<Nearest>, stats: &mut Stats) -> Vec3 {
        let o = self.options;
        match o.view {
            View::Color if o.stage == Stage::GenericObjects => self.flat(nearest),
            View::Color => self.shade(ray, nearest, 0, 1.0, stats),
            View::Flat => self.flat(nearest),
            View::Normals => match nearest {
                Some(n) => (self.facing(n.hit.normal, ray.dir) + Vec3::ONE) * 0.5,
                None => self.scene.background,
            },
            View::Depth => match nearest {
                Some(n) => Vec3::splat(n.hit.t * ray.dir.length()),
                None => Vec3::splat(Real::INFINITY),
            },
        }
    }

    fn flat(&self, nearest: Option<Nearest>) -> Vec3 {
        match nearest {
            Some(n) => self.scene.materials[self.scene.objects[n.object].material].diffuse,
            None => self.scene.background,
        }
    }

    /// Whether [`Tracer::block`] may trace the camera rays of a block of pixels together:
    /// one ray a pixel, from stage 2 on, through a BVH or an octree.
    fn packets(&self) -> bool {
        let o = self.options;
        (o.samples <= 1 || o.view == View::Depth)
            && o.stage >= Stage::GenericObjects
            && matches!(self.accel.kind(), Accel::Bvh | Accel::Octree)
    }

    /// The colours of the pixels x0..x1 of rows y0..y1 (at most [`crate::accel::PACKET`] of
    /// them), row after row: the same colours as [`Tracer::pixel`] gives, with the camera
    /// rays, and then the feelers towards each light, walked through the structure as
    /// packets when [`Tracer::packets`].
    fn block(&self, (x0, x1): (u32, u32), (y0, y1): (u32, u32), stats: &mut Stats) -> Block<Vec3> {
        let mut out = ArrayVec::new();
        if !self.packets() {
            for y in y0..y1 {
                for x in x0..x1 {
                    out.push(self.pixel(x, y, stats));
                }
            }
            return out;
        }
        let rays: Block<Ray> = (y0..y1)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .map(|(x, y)| self.camera.pixel_ray(x, y, 0.5, 0.5))
            .collect();
        let mut nearest = [None; crate::accel::PACKET];
        let nearest = &mut nearest[..rays.len()];
        self.accel.nearest_packet(
            &self.scene.objects,
            &rays,
            0.0,
            self.options.formula,
            nearest,
        );
        stats.primary += rays.len() as u64;
        let o = self.options;
        if o.view != View::Color || o.stage < Stage::Shading {
            for (ray, n) in rays.iter().zip(nearest.iter()) {
                out.push(self.seen(ray, *n, stats));
            }
            return out;
        }
        // Tracer::shade for the whole block, with the feelers towards each light traced as
        // one packet: the same sums, in the same order, pixel by pixel
        let surfaces: Block<Option<Surface>> = rays
            .iter()
            .zip(nearest.iter())
            .map(|(ray, n)| n.as_ref().map(|n| self.surface(ray, n)))
            .collect();
        let mut color: Block<Vec3> = surfaces
            .iter()
            .map(|s| match s {
                Some(s) => shading::ambient(s.material, self.scene.ambient),
                None => self.scene.background,
            })
            .collect();
        for light in &self.scene.lights {
            let mut local = [None; crate::accel::PACKET];
            // the pixels that send a feeler, with its origin and u_min
            let (mut who, mut origins, mut u_min) = (
                Block::<usize>::new(),
                Block::<Vec3>::new(),
                Block::<Real>::new(),
            );
            for (i, s) in surfaces.iter().enumerate() {
                let Some((l, feeler)) = s.as_ref().and_then(|s| self.direct(s, light, stats))
                else {
                    continue;
                };
                local[i] = Some(l);
                if let Some((origin, u)) = feeler {
                    who.push(i);
                    origins.push(origin);
                    u_min.push(u);
                }
            }
            let mut share = [1.0; crate::accel::PACKET];
            if !who.is_empty() {
                self.accel.transmittance_packet(
                    &self.scene.objects,
                    &self.scene.materials,
                    &origins,
                    light.position,
                    &u_min,
                    o.formula,
                    &mut share[..who.len()],
                );
            }
            for (k, &i) in who.iter().enumerate() {
                if let Some(l) = &mut local[i] {
                    *l *= share[k];
                }
            }
            for (c, l) in color.iter_mut().zip(local) {
                if let Some(l) = l {
                    *c += l;
                }
            }
        }
        for (s, c) in surfaces.iter().zip(color) {
            out.push(match s {
                Some(s) => self.bounce(s, c, 0, 1.0, stats),
                None => c,
            });
        }
        out
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
        self.shade(
            ray,
            self.nearest_from(ray, t_min, pixel),
            depth,
            weight,
            stats,
        )
    }

    /// The light coming back along `ray` whose nearest hit is `nearest` (see
    /// [`Tracer::trace`]).
    fn shade(
        &self,
        ray: &Ray,
        nearest: Option<Nearest>,
        depth: u32,
        weight: Real,
        stats: &mut Stats,
    ) -> Vec3 {
        let Some(nearest) = nearest else {
            return self.scene.background;
        };
        let s = self.surface(ray, &nearest);
        let o = self.options;

        // I_a + Σ (I_d + I_s), with feelers from stage 4
        let mut color = shading::ambient(s.material, self.scene.ambient);
        for light in &self.scene.lights {
            let Some((mut local, feeler)) = self.direct(&s, light, stats) else {
                continue; // light behind the surface: no feeler needed
            };
            if let Some((origin, u_min)) = feeler {
                local *= self.accel.transmittance(
                    &self.scene.objects,
                    &self.scene.materials,
                    origin,
                    light.position,
                    u_min,
                    o.formula,
                );
            }
            color += local;
        }
        self.bounce(&s, color, depth, weight, stats)
    }

    /// What shading needs to know of a hit.
    fn surface<'s>(&'s self, ray: &Ray, nearest: &Nearest) -> Surface<'s> {
        let hit = nearest.hit;
        let object = &self.scene.objects[nearest.object];
        let d = crate::numeric::normalize(ray.dir);
        Surface {
            hit,
            material: &self.scene.materials[object.material],
            p: ray.at(hit.t),
            d,
            n: self.facing(hit.normal, d), // shading normal, towards the viewer
            spawn: SpawnPoint::new(object, ray, &hit),
        }
    }

    /// I_d + I_s of one light at the surface, unshadowed, and from stage 4 the feeler that
    /// will say how much of it arrives (origin, u_min); `None` when the light is behind the
    /// surface.
    fn direct(
        &self,
        s: &Surface,
        light: &Light,
        stats: &mut Stats,
    ) -> Option<(Vec3, Option<(Vec3, Real)>)> {
        let local = shading::direct(s.material, light, s.p, s.n, -s.d);
        if local == Vec3::ZERO {
            return None;
        }
        let o = self.options;
        let feeler = (o.stage >= Stage::Shadows && light.shadows).then(|| {
            stats.shadow += 1;
            o.offset.spawn(&s.spawn, light.position - s.p)
        });
        Some((local, feeler))
    }

    /// `color` plus, from stage 5 and while `depth < max_depth`, the light of the mirror and
    /// transmitted rays (I_l + I_r).
    fn bounce(
        &self,
        s: &Surface,
        mut color: Vec3,
        depth: u32,
        weight: Real,
        stats: &mut Stats,
    ) -> Vec3 {
        let o = self.options;
        if o.stage < Stage::ReflectionRefraction || depth >= o.max_depth {
            return color;
        }
        let (hit, material, d, n, spawn) = (s.hit, s.material, s.d, s.n, &s.spawn);

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
                        let (origin, t0) = o.offset.spawn(spawn, t_dir);
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
            let (origin, t0) = o.offset.spawn(spawn, l);
            let r = Ray::new(origin, l);
            color += kr * self.trace(&r, t0, depth + 1, weight * kr, stats);
        }
        color
    }
}
