//! Packets: a block of pixels traced together where that pays, the same image bit for bit.
//!
//! With one ray a pixel and a BVH or an octree, the camera rays of a [`super::BLOCK`] ×
//! [`super::BLOCK`]
//! block of pixels go through the structure as one packet
//! ([`crate::accel::Accelerator::nearest_packet`]), and so do their feelers towards each light
//! ([`crate::accel::Accelerator::transmittance_packet`]). Every pixel is then shaded by the
//! road of one pixel itself (`Tracer::local_light`, `Tracer::reflect_and_refract`), which
//! looks its feelers' shares up instead of tracing them one by one; its mirror and transmitted
//! rays are traced one by one. The packets change the time, never a bit of the image:
//! [`Options::packets`] turns them off, and the tests render both ways and compare.
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use arrayvec::ArrayVec;

use super::tracer::Surface;
use super::{Chapter, Options, Stats, Tracer, View};
use crate::accel::{Accel, PACKET};
use crate::ray::Ray;
use crate::real::{Real, Vec3};

/// Up to one value per pixel of a block.
pub(crate) type Block<T> = ArrayVec<T, PACKET>;

/// The shares of each light's feelers for the pixels of a block: `shares[light][pixel]`.
pub(crate) type Shares = Vec<[Real; PACKET]>;

impl Tracer<'_> {
    /// Whether `Tracer::block` traces a block's camera rays together: packets asked for, one
    /// ray a pixel, from chapter 2 on, through a BVH or an octree.
    fn packets(&self) -> bool {
        let o: &Options = self.options;
        o.packets
            && o.view != View::Rays // counts each pixel's rays on the plain road
            && o.samples_per_pixel() == 1
            && o.chapter >= Chapter::GenericObjects
            && matches!(self.accel.kind(), Accel::Bvh | Accel::Octree)
    }

    /// The colours of the pixels x0..x1 of rows y0..y1 (at most [`PACKET`] of them), row after
    /// row: the colours [`Tracer::pixel`] gives, traced as packets when `Tracer::packets`.
    /// `scratch` keeps its allocation from one block to the next.
    pub(crate) fn block(
        &self,
        (x0, x1): (u32, u32),
        (y0, y1): (u32, u32),
        scratch: &mut Shares,
        stats: &mut Stats,
    ) -> Block<Vec3> {
        let pixels = (y0..y1).flat_map(|y| (x0..x1).map(move |x| (x, y)));
        if !self.packets() {
            return pixels.map(|(x, y)| self.pixel(x, y, stats)).collect();
        }
        let rays: Block<Ray> = pixels
            .map(|(x, y)| self.camera.pixel_ray(x, y, 0.5, 0.5))
            .collect();
        let mut nearest = [None; PACKET];
        let nearest = &mut nearest[..rays.len()];
        self.accel.nearest_packet(
            &self.scene.objects,
            &rays,
            0.0,
            self.options.numerics,
            nearest,
        );
        stats.primary += rays.len() as u64;
        let o = self.options;
        if o.view != View::Color || o.chapter < Chapter::Shading {
            let seen = rays.iter().zip(nearest.iter());
            return seen.map(|(ray, n)| self.seen(ray, *n, stats)).collect();
        }
        let surfaces: Block<Option<Surface>> = rays
            .iter()
            .zip(nearest.iter())
            .map(|(ray, n)| n.as_ref().map(|n| self.surface(ray, n)))
            .collect();
        self.trace_feelers(&surfaces, scratch);
        surfaces
            .iter()
            .enumerate()
            .map(|(i, s)| match s {
                Some(s) => {
                    let local = self.local_light(s, |l, _| scratch[l][i], stats);
                    self.reflect_and_refract(s, local, 0, 1.0, stats)
                }
                None => self.scene.background,
            })
            .collect()
    }

    /// Traces, light by light, the feelers `Tracer::feeler` sends from the surfaces as one
    /// packet, and keeps their shares in `shares[light][pixel]`, ready for
    /// `Tracer::local_light` to look up.
    fn trace_feelers(&self, surfaces: &[Option<Surface>], shares: &mut Shares) {
        let lights = &self.scene.lights;
        shares.clear();
        shares.resize(lights.len(), [1.0; PACKET]);
        for (light, row) in lights.iter().zip(shares.iter_mut()) {
            // the pixels that send a feeler towards this light, and their feelers
            let mut who = Block::<usize>::new();
            let mut feelers = Block::<Ray>::new();
            let mut u_min = Block::<Real>::new();
            for (i, s) in surfaces.iter().enumerate() {
                if let Some((feeler, u)) = s.as_ref().and_then(|s| self.feeler(s, light)) {
                    who.push(i);
                    feelers.push(feeler);
                    u_min.push(u);
                }
            }
            if who.is_empty() {
                continue;
            }
            let mut out = [1.0; PACKET];
            self.accel.transmittance_packet(
                &self.scene.objects,
                &self.scene.materials,
                light.position,
                &feelers,
                &u_min,
                self.options.numerics,
                &mut out[..who.len()],
            );
            for (k, &i) in who.iter().enumerate() {
                row[i] = out[k];
            }
        }
    }
}
