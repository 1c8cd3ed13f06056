//! Packets: a block of pixels whose first rays are traced together, the same image bit for bit.
//!
//! With one ray a pixel and a BVH or an octree, the camera rays of a [`super::BLOCK`] ×
//! [`super::BLOCK`] block of pixels go through the structure as one packet
//! ([`crate::accel::Accelerator::nearest_packet`]), and so do their feelers towards each light
//! ([`crate::accel::Accelerator::transmittance_packet`]): the camera rays are the road's own
//! (`Tracer::sample_ray`), the feelers too ([`ShadingPoint::new`], `Tracer::feeler` towards
//! each light in front of the surface). Then each pixel's camera ray goes down the road of one
//! pixel itself (`Tracer::sample_colour`, a sample of [`Tracer::pixel`]), asking a `Packed`
//! query: it answers from what the packets found the rays they traced — only a ray equal to
//! the one traced, bit for bit — and lends the shading point it made of a camera ray's hit
//! ([`Shortcuts`]); any other ray (mirror and transmitted rays, their feelers) it asks of the
//! acceleration structure. So the packets own no step of the
//! road: no view, no background, no count of rays. They change the time, never a bit of the
//! image: [`Options::packets`] turns them off, and the tests render both ways and compare.
//!
//! The road makes each first feeler again, and finds it among those traced (the price of one
//! road; `docs/src/performance.md` has the measurements).
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use std::borrow::Cow;
use std::cell::Cell;

use arrayvec::ArrayVec;

use super::accelerated::Accelerated;
use super::options::{Chapter, Options, View};
use super::query::{Query, ShadingPoint};
use super::recorder::Recorder;
use super::shortcuts::Shortcuts;
use super::stats::Stats;
use super::tracer::Tracer;
use crate::accel::{Accel, PACKET};
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shadow::{self, Feeler};
use crate::shapes::Nearest;

/// Up to one value per pixel of a block.
pub(crate) type Block<T> = ArrayVec<T, PACKET>;

/// The feelers the camera hits of a block send, with the share of its light each lets through:
/// `feelers[light][pixel]` (kept from one block to the next, so that its memory is allocated
/// once per band of tiles).
pub(crate) type Feelers = Vec<[Option<(Feeler, Real)>; PACKET]>;

/// The [`Query`] the pixels of a block are rendered with, one after the other: the rays its
/// packets traced answered from what they found, every other ray by the structure.
struct Packed<'t, 'a> {
    /// Each pixel's camera ray …
    rays: &'t [Ray],
    /// … its nearest hit …
    nearest: &'t [Option<Nearest>],
    /// … what shading needs to know of it (made to build its feelers; empty when no feeler
    /// was traced) …
    points: &'t [Option<ShadingPoint<'a>>],
    /// … and its feelers, `feelers[light][pixel]`.
    feelers: &'t [[Option<(Feeler, Real)>; PACKET]],
    structure: &'t Accelerated<'a>,
    /// The pixel being rendered: its place in the block.
    pixel: Cell<usize>,
    /// The first light whose feeler from this pixel the road has not asked for yet (it asks
    /// in the order of the lights).
    light: Cell<usize>,
}

impl Packed<'_, '_> {
    /// Whether `ray` is the camera ray traced for the pixel being rendered: the very one the
    /// road was handed (a ray equal to it, not the same, is asked of the structure: the same
    /// answer).
    #[inline]
    fn traced(&self, ray: &Ray) -> bool {
        std::ptr::eq(ray, &self.rays[self.pixel.get()])
    }
}

/// Whether `a` and `b` are the same ray, bit for bit.
#[inline]
fn same(a: &Ray, b: &Ray) -> bool {
    let same = |x: Real, y: Real| x.to_bits() == y.to_bits();
    same(a.dir.x, b.dir.x)
        && same(a.dir.y, b.dir.y)
        && same(a.dir.z, b.dir.z)
        && same(a.origin.x, b.origin.x)
        && same(a.origin.y, b.origin.y)
        && same(a.origin.z, b.origin.z)
}

impl Query for Packed<'_, '_> {
    #[inline]
    fn nearest(&self, ray: &Ray, t_min: Real) -> Option<Nearest> {
        self.structure.nearest(ray, t_min)
    }

    #[inline]
    fn share(&self, feeler: &Feeler, rec: &mut impl Recorder) -> Real {
        let i = self.pixel.get();
        for l in self.light.get()..self.feelers.len() {
            if let Some((traced, share)) = &self.feelers[l][i]
                && traced.u_min.to_bits() == feeler.u_min.to_bits()
                && same(&traced.ray, &feeler.ray)
            {
                self.light.set(l + 1);
                return *share;
            }
        }
        self.structure.share(feeler, rec)
    }
}

impl Shortcuts for Packed<'_, '_> {
    #[inline]
    fn nearest_camera(&self, ray: &Ray) -> Option<Nearest> {
        let i = self.pixel.get();
        if self.traced(ray) {
            self.nearest[i]
        } else {
            self.structure.nearest_camera(ray)
        }
    }

    #[inline]
    fn shading_point<'s>(
        &'s self,
        scene: &'s Scene,
        ray: &Ray,
        nearest: &Nearest,
    ) -> Cow<'s, ShadingPoint<'s>> {
        let i = self.pixel.get();
        match self.points.get(i) {
            Some(Some(s)) if self.traced(ray) => Cow::Borrowed(s),
            _ => self.structure.shading_point(scene, ray, nearest),
        }
    }
}

/// Whether a block's first rays go as packets: packets asked for, one ray a pixel (not the
/// rays-per-pixel view, which counts each pixel's rays), from chapter 2 on, through a BVH or
/// an octree.
fn packets(tracer: &Tracer<'_, Accelerated<'_>>) -> bool {
    let o: &Options = tracer.options;
    o.packets
        && o.samples_per_pixel() == 1
        && o.view != View::Rays
        && o.chapter >= Chapter::GenericObjects
        && matches!(tracer.query().accel().kind(), Accel::Bvh | Accel::Octree)
}

/// The colours of the pixels x0..x1 of rows y0..y1 (at most [`PACKET`] of them), row after
/// row: [`Tracer::pixel`] of each, its first rays traced as packets when that pays. `scratch`
/// keeps its allocation from one block to the next.
pub(crate) fn block(
    tracer: &Tracer<'_, Accelerated<'_>>,
    (x0, x1): (u32, u32),
    (y0, y1): (u32, u32),
    scratch: &mut Feelers,
    stats: &mut Stats,
) -> Block<Vec3> {
    let pixels = (y0..y1).flat_map(|y| (x0..x1).map(move |x| (x, y)));
    if !packets(tracer) {
        return pixels.map(|(x, y)| tracer.pixel(x, y, stats)).collect();
    }
    // the camera rays, the road's own, as one packet
    let mut rays: Block<Ray> = Block::new();
    rays.extend(pixels.map(|(x, y)| tracer.sample_ray(x, y, (0, 1)).1));
    let mut nearest = [None; PACKET];
    let nearest = &mut nearest[..rays.len()];
    tracer.query().nearest_camera_packet(&rays, nearest);
    // their first feelers, light by light
    let o = tracer.options;
    let mut points: Block<Option<ShadingPoint>> = Block::new();
    if o.chapter >= Chapter::Shadows && matches!(o.view, View::Color | View::Shadows) {
        let point = |(ray, n): (&Ray, &Option<Nearest>)| {
            n.as_ref().map(|n| ShadingPoint::new(tracer.scene, ray, n))
        };
        points.extend(rays.iter().zip(nearest.iter()).map(point));
    }
    trace_feelers(tracer, &points, scratch);
    let packed = tracer.asking(Packed {
        rays: &rays,
        nearest,
        points: &points,
        feelers: scratch,
        structure: tracer.query(),
        pixel: Cell::new(0),
        light: Cell::new(0),
    });
    // each pixel's one sample down the road, from its camera ray
    rays.iter()
        .enumerate()
        .map(|(i, ray)| {
            packed.query().pixel.set(i);
            packed.query().light.set(0);
            packed.sample_colour(ray, stats)
        })
        .collect()
}

/// Traces, light by light as one packet, the feelers the road may send from the shading points
/// `points` (`Tracer::feeler` towards a light in front), into `feelers[light][pixel]`.
fn trace_feelers(
    tracer: &Tracer<'_, Accelerated<'_>>,
    points: &[Option<ShadingPoint>],
    feelers: &mut Feelers,
) {
    feelers.clear();
    if points.is_empty() {
        return;
    }
    let lights = &tracer.scene.lights;
    feelers.resize(lights.len(), [None; PACKET]);
    for (light, row) in lights.iter().zip(feelers.iter_mut()) {
        // the pixels that send a feeler towards this light, and their feelers
        let mut who = Block::<usize>::new();
        let mut rays = Block::<Ray>::new();
        let mut u_min = Block::<Real>::new();
        for (i, s) in points.iter().enumerate() {
            let in_front = |s: &&ShadingPoint| shadow::in_front(s.n, s.p, light.position);
            if let Some(feeler) = s
                .as_ref()
                .filter(in_front)
                .and_then(|s| tracer.feeler(s, light))
            {
                who.push(i);
                rays.push(feeler.ray);
                u_min.push(feeler.u_min);
            }
        }
        if who.is_empty() {
            continue;
        }
        let mut shares = [1.0; PACKET];
        let shares = &mut shares[..who.len()];
        tracer
            .query()
            .share_packet(light.position, &rays, &u_min, shares);
        for (k, &i) in who.iter().enumerate() {
            let feeler = Feeler {
                ray: rays[k],
                u_min: u_min[k],
            };
            row[i] = Some((feeler, shares[k]));
        }
    }
}
