//! Packets: a block of pixels whose first rays are traced together, the same image bit for bit.
//!
//! With one ray a pixel and a BVH or an octree, the camera rays of a [`super::BLOCK`] ×
//! [`super::BLOCK`] block of pixels go through the structure as one packet
//! ([`crate::accel::Accelerator::nearest_packet`]), and so do their feelers towards each light
//! ([`crate::accel::Accelerator::transmittance_packet`]): the camera rays are the road's own
//! (`Tracer::sample_ray`), the feelers too ([`ShadingPoint::new`], `Tracer::feeler`). The
//! answers go in a table, and then each pixel is rendered by the road of one pixel itself,
//! [`Tracer::pixel`], asking a `Packed` query: it answers from the table the rays it holds —
//! only a ray equal to the one traced, bit for bit, and the shading point made of its hit —
//! and any other ray (mirror and transmitted rays, their feelers) from the acceleration
//! structure. So the packets own no step of the road: they change the time, never a bit of the
//! image. [`Options::packets`] turns them off, and the tests render both ways and compare.
//!
//! The road does again, for each pixel, a little of what the table was built with: it makes
//! its camera ray and its feelers itself, and finds them in the table. That is the price of one
//! road (measured in `docs/src/performance.md`).
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use std::cell::Cell;

use arrayvec::ArrayVec;

use super::accelerated::Accelerated;
use super::recorder::Recorder;
use super::tracer::{Feeler, Query, ShadingPoint};
use super::{Chapter, Options, Stats, Tracer, View};
use crate::accel::{Accel, PACKET};
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::shapes::Nearest;

/// Up to one value per pixel of a block.
pub(crate) type Block<T> = ArrayVec<T, PACKET>;

/// What the packets of one block found, pixel by pixel (kept from one block to the next, so
/// its memory is allocated once per band of tiles).
pub(crate) struct Table<'a> {
    /// How many pixels the block has.
    len: usize,
    /// Each pixel's camera ray …
    rays: [Ray; PACKET],
    /// … its nearest hit …
    nearest: [Option<Nearest>; PACKET],
    /// … and what shading needs to know of it, made to build its feelers.
    points: Block<Option<ShadingPoint<'a>>>,
    /// `feelers[light][pixel]`: the feeler the pixel's camera hit sends towards the light, if
    /// any, with the share of the light it lets through.
    feelers: Vec<[Option<(Feeler, Real)>; PACKET]>,
}

impl Table<'_> {
    /// An empty table.
    pub(crate) fn new() -> Self {
        Self {
            len: 0,
            rays: [Ray::new(Vec3::ZERO, Vec3::ZERO); PACKET],
            nearest: [None; PACKET],
            points: Block::new(),
            feelers: Vec::new(),
        }
    }
}

/// The [`Query`] the pixels of a block are rendered with, one after the other: the rays its
/// packets traced answered from the table, every other ray by the structure.
pub(crate) struct Packed<'t, 'a> {
    table: &'t Table<'a>,
    structure: &'t Accelerated<'a>,
    /// The pixel being rendered: its place in the block.
    pixel: Cell<usize>,
    /// The first light whose feeler from this pixel the road has not asked for yet (it asks
    /// in the order of the lights).
    light: Cell<usize>,
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
    fn nearest_camera(&self, ray: &Ray) -> Option<Nearest> {
        let i = self.pixel.get();
        if same(&self.table.rays[i], ray) {
            self.table.nearest[i]
        } else {
            self.structure.nearest_camera(ray)
        }
    }

    #[inline]
    fn shading_point(&self, ray: &Ray, nearest: &Nearest) -> ShadingPoint<'_> {
        let i = self.pixel.get();
        match self.table.points.get(i) {
            Some(Some(s)) if same(&self.table.rays[i], ray) => *s,
            _ => self.structure.shading_point(ray, nearest),
        }
    }

    #[inline]
    fn share(&self, feeler: &Feeler, rec: &mut impl Recorder) -> Real {
        let i = self.pixel.get();
        for l in self.light.get()..self.table.feelers.len() {
            if let Some((traced, share)) = &self.table.feelers[l][i]
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

/// Whether a block's first rays go as packets: packets asked for, one ray a pixel, from
/// chapter 2 on, through a BVH or an octree.
fn packets(tracer: &Tracer) -> bool {
    let o: &Options = tracer.options;
    o.packets
        && o.samples_per_pixel() == 1
        && o.chapter >= Chapter::GenericObjects
        && matches!(tracer.query().accel().kind(), Accel::Bvh | Accel::Octree)
}

/// The colours of the pixels x0..x1 of rows y0..y1 (at most [`PACKET`] of them), row after
/// row: [`Tracer::pixel`] of each, its first rays traced as packets when that pays. `table`
/// keeps its allocation from one block to the next.
pub(crate) fn block<'a>(
    tracer: &Tracer<'a>,
    (x0, x1): (u32, u32),
    (y0, y1): (u32, u32),
    table: &mut Table<'a>,
    stats: &mut Stats,
) -> Block<Vec3> {
    let pixels = (y0..y1).flat_map(|y| (x0..x1).map(move |x| (x, y)));
    if !packets(tracer) {
        return pixels.map(|(x, y)| tracer.pixel(x, y, stats)).collect();
    }
    trace_camera_rays(tracer, pixels.clone(), table);
    let o = tracer.options;
    table.points.clear();
    table.feelers.clear();
    if o.chapter >= Chapter::Shadows && matches!(o.view, View::Color | View::Shadows) {
        trace_feelers(tracer, table);
    }
    let packed = tracer.asking(Packed {
        table,
        structure: tracer.query(),
        pixel: Cell::new(0),
        light: Cell::new(0),
    });
    pixels
        .enumerate()
        .map(|(i, (x, y))| {
            packed.query().pixel.set(i);
            packed.query().light.set(0);
            packed.pixel(x, y, stats)
        })
        .collect()
}

/// Traces the camera rays of the pixels (the road's, `Tracer::sample_ray`) as one packet.
fn trace_camera_rays(tracer: &Tracer, pixels: impl Iterator<Item = (u32, u32)>, table: &mut Table) {
    let mut n = 0;
    for (x, y) in pixels {
        table.rays[n] = tracer.sample_ray(x, y, (0, 1)).1;
        n += 1;
    }
    table.len = n;
    tracer
        .query()
        .nearest_camera_packet(&table.rays[..n], &mut table.nearest[..n]);
}

/// Traces the feelers the road sends from the camera rays' hits (`Tracer::shading_point`,
/// `Tracer::feeler`), light by light as one packet.
fn trace_feelers<'a>(tracer: &Tracer<'a>, table: &mut Table<'a>) {
    let n = table.len;
    for i in 0..n {
        let point = table.nearest[i].map(|h| ShadingPoint::new(tracer.scene, &table.rays[i], &h));
        table.points.push(point);
    }
    let lights = &tracer.scene.lights;
    table.feelers.resize(lights.len(), [None; PACKET]);
    for (light, row) in lights.iter().zip(table.feelers.iter_mut()) {
        // the pixels that send a feeler towards this light, and their feelers
        let mut who = Block::<usize>::new();
        let mut rays = Block::<Ray>::new();
        let mut u_min = Block::<Real>::new();
        for (i, s) in table.points.iter().enumerate() {
            row[i] = None;
            if let Some(feeler) = s.as_ref().and_then(|s| tracer.feeler(s, light)) {
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
