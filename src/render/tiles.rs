//! Rendering a whole image: tiles in parallel around the road of one pixel.
//!
//! The image is cut into [`TILE`] × [`TILE`] tiles, rendered in parallel (rayon): one band of
//! tile rows per task, written straight into the framebuffer, so memory is the framebuffer
//! itself. Every pixel depends only on its own coordinates (supersampling positions come from
//! a hash of the pixel and the sample's index), so the image is the same whatever the number
//! of threads. Inside a tile, pixels go by blocks of [`BLOCK`] × [`BLOCK`]: a block is traced
//! as packets where that pays ([`super::packets`]), pixel by pixel otherwise.

use rayon::prelude::*;

use super::{Framebuffer, Options, Stage, Stats, Tracer};
use crate::accel::Accel;
use crate::accel::Accelerator;
use crate::scene::Scene;

/// Side of the square tiles the image is rendered in.
pub const TILE: u32 = 16;

/// Side of the square blocks of pixels whose camera rays are traced as one packet
/// (BLOCK² ≤ [`crate::accel::PACKET`]). 8 × 8 measured fastest on the 100 000-sphere field
/// (11% below 4 × 4, no slower on the showcase); 16 × 16 gained nothing more.
pub const BLOCK: u32 = 8;

const _: () = assert!((BLOCK * BLOCK) as usize <= crate::accel::PACKET);

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
    let mut fb = Framebuffer::new(w, h);
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
            let mut scratch = Vec::new();
            let y0 = ty as u32 * TILE;
            let y1 = (y0 + TILE).min(h);
            for x0 in (0..w).step_by(TILE as usize) {
                let x1 = (x0 + TILE).min(w);
                for by in (y0..y1).step_by(BLOCK as usize) {
                    let by1 = (by + BLOCK).min(y1);
                    for bx in (x0..x1).step_by(BLOCK as usize) {
                        let bx1 = (bx + BLOCK).min(x1);
                        let colours = tracer.block((bx, bx1), (by, by1), &mut scratch, &mut stats);
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
    (fb, stats)
}
