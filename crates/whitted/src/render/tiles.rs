//! Rendering an image, or a rectangle of it: tiles in parallel around the road of one pixel.
//!
//! The image is cut into [`TILE`] × [`TILE`] tiles, rendered in parallel (rayon): one band of
//! tile rows per task, written straight into the framebuffer, so memory is the framebuffer
//! itself. Every pixel depends only on its own coordinates (supersampling positions come from
//! a hash of the pixel and the sample's index), so the image is the same whatever the number
//! of threads. Inside a tile, pixels go by blocks of [`BLOCK`] × [`BLOCK`]: a block is traced
//! as packets where that pays ([`super::packets`]), pixel by pixel otherwise. Every render
//! asks the acceleration structure the options name ([`build_accel`]): the tracer
//! [`Tracer::new`] makes, or [`Tracer::with_accel`] with one built beforehand.
//!
//! There is one tile loop, [`render_rect`], and the whole image is one call of it. It renders
//! any [`Rect`] of the image into a framebuffer the caller keeps, reports each finished tile,
//! and asks before each tile whether to stop. That is what the live window needs: it renders
//! the part of the image in view, draws each tile as it arrives, and abandons a render the
//! moment the student moves the camera or changes the view, instead of waiting for the last
//! tile of an image nobody wants any more. A tile of a rectangle is the same pixels, bit for
//! bit, as that tile of the whole image: tiles stay on the image's grid, cut to the rectangle.
//!
//! ```
//! use whitted::render::{Finished, Framebuffer, Options, Rect, Chapter, Tracer, render_rect};
//!
//! let scene = whitted::scene::showcase().unwrap(); // the showcase
//! let mut options = Options::for_scene(&scene, Chapter::Shading);
//! (options.width, options.height) = (64, 48);
//! let tracer = Tracer::new(&scene, &options);
//! let mut fb = Framebuffer::new(64, 48);
//! // the top-left quarter, never cancelled, tiles reported as they finish
//! let finished = render_rect(&tracer, Rect::new(0, 0, 32, 24), &mut fb, &|| false, &|tile| {
//!     assert!(tile.x1 <= 32 && tile.y1 <= 24);
//! });
//! assert!(matches!(finished, Ok(Finished::Done(stats)) if stats.primary == 32 * 24));
//! ```
//!
//! Course book: [Performance](../../../../../docs/book/performance.html) (`docs/src/performance.md`).

use std::borrow::Cow;
use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::accelerated::Accelerated;
use super::framebuffer::Framebuffer;
use super::options::{Chapter, Options};
use super::packets::{self, Feelers};
use super::stats::Stats;
use super::tracer::Tracer;
use crate::accel::Accel;
use crate::accel::Accelerator;
use crate::error::Error;
use crate::real::Vec3;
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
    let camera = options.camera(scene);
    // chapter 1 intersects nothing
    let kind = if options.chapter == Chapter::CameraRays {
        Accel::None
    } else {
        options.accel
    };
    Accelerator::build(&scene.objects, &camera, kind, TILE)
}

impl<'a> Tracer<'a, Accelerated<'a>> {
    /// A tracer for the scene with the options' image size, asking the acceleration structure
    /// the options name (built here, [`build_accel`]): the tracer of every render.
    #[must_use]
    pub fn new(scene: &'a Scene, options: &'a Options) -> Self {
        let accel = Cow::Owned(build_accel(scene, options));
        Self::with_query(
            scene,
            options,
            Accelerated::new(accel, scene, options.numerics),
        )
    }

    /// A tracer using an acceleration structure built beforehand (see [`build_accel`]).
    #[must_use]
    pub fn with_accel(scene: &'a Scene, options: &'a Options, accel: &'a Accelerator) -> Self {
        let accel = Cow::Borrowed(accel);
        Self::with_query(
            scene,
            options,
            Accelerated::new(accel, scene, options.numerics),
        )
    }
}

/// Renders the scene: returns the image and the rays cast.
#[must_use]
pub fn render(scene: &Scene, options: &Options) -> (Framebuffer, Stats) {
    let accel = build_accel(scene, options);
    render_with(scene, options, &accel, &|_| {})
}

/// Renders the scene with a prepared acceleration structure, calling `progress(pixels)` as
/// each tile is done (from any thread): [`render_rect`] over the whole image, never cancelled,
/// into a new framebuffer.
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
    // the whole image, never cancelled: the same tile loop as a rectangle's
    let stats = tile_loop(
        &tracer,
        Rect::new(0, 0, w, h),
        &mut fb,
        &|| false,
        &|tile| progress(tile.pixels()),
    )
    .stats();
    (fb, stats)
}

/// A rectangle of pixels: columns `x0..x1` and rows `y0..y1` (half-open, so `x1` and `y1` are
/// not in it), in image coordinates, row 0 at the top. A rectangle with `x0 >= x1` or
/// `y0 >= y1` holds no pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Rect {
    /// First column.
    pub x0: u32,
    /// First row.
    pub y0: u32,
    /// One past the last column.
    pub x1: u32,
    /// One past the last row.
    pub y1: u32,
}

impl Rect {
    /// Columns `x0..x1`, rows `y0..y1`.
    #[must_use]
    pub const fn new(x0: u32, y0: u32, x1: u32, y1: u32) -> Self {
        Self { x0, y0, x1, y1 }
    }

    /// Columns in the rectangle (0 if it is empty).
    #[must_use]
    pub const fn width(&self) -> u32 {
        self.x1.saturating_sub(self.x0)
    }

    /// Rows in the rectangle (0 if it is empty).
    #[must_use]
    pub const fn height(&self) -> u32 {
        self.y1.saturating_sub(self.y0)
    }

    /// Pixels in the rectangle.
    #[must_use]
    pub const fn pixels(&self) -> u64 {
        self.width() as u64 * self.height() as u64
    }

    /// Whether the rectangle holds no pixel.
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }

    /// Whether pixel (x, y) lies in the rectangle.
    #[must_use]
    pub const fn contains(&self, x: u32, y: u32) -> bool {
        self.x0 <= x && x < self.x1 && self.y0 <= y && y < self.y1
    }

    /// The part of the rectangle inside an image of `width` × `height` pixels.
    #[must_use]
    pub fn clip(&self, width: u32, height: u32) -> Self {
        Self {
            x0: self.x0.min(width),
            y0: self.y0.min(height),
            x1: self.x1.min(width),
            y1: self.y1.min(height),
        }
    }
}

/// How a [`render_rect`] ended, with the rays cast by the tiles it rendered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[must_use]
pub enum Finished {
    /// Every tile of the rectangle was rendered.
    Done(Stats),
    /// `cancel()` said stop: only the tiles reported to `progress` were rendered; the rest of
    /// the rectangle keeps what the framebuffer held before.
    Cancelled(Stats),
}

impl Finished {
    /// The rays cast by the tiles rendered, whichever way the render ended.
    #[must_use]
    pub fn stats(&self) -> Stats {
        match *self {
            Self::Done(s) | Self::Cancelled(s) => s,
        }
    }

    /// A render's end: [`Finished::Cancelled`] if it was stopped, else [`Finished::Done`].
    pub fn new(cancelled: bool, stats: Stats) -> Self {
        if cancelled {
            Self::Cancelled(stats)
        } else {
            Self::Done(stats)
        }
    }

    /// Whether the render was cancelled before its last tile.
    #[must_use]
    pub fn is_cancelled(&self) -> bool {
        matches!(self, Self::Cancelled(_))
    }
}

/// Renders the pixels of `rect` into `fb`, tile by tile in parallel, and leaves every other
/// pixel of `fb` as it was. This is the render the live window drives; [`render`] is this call
/// over the whole image.
///
/// - **Tiles** lie on the image's grid of [`TILE`] × [`TILE`] tiles, cut to `rect`, so each
///   pixel comes out bit for bit as in a render of the whole image. `rect` is first clipped to
///   the image: a rectangle reaching past the image renders its part inside it, and an empty
///   rectangle, or one wholly outside, renders nothing and is [`Finished::Done`].
/// - **Cancelling**: `cancel()` is asked before each tile starts, and a tile starts only if it
///   said `false`. Once it has said `true`, every thread sees the stop before its next tile and
///   starts no more (tiles already under way on other threads finish and are reported), and
///   the call returns [`Finished::Cancelled`] with the rays of the tiles done. The stop holds
///   even if `cancel()` would say `false` again; it is not asked once a thread has seen the
///   stop, nor when there is no tile to start.
/// - **Progress**: `progress(tile)` is called, from the thread that rendered it, with the
///   rectangle of each tile as soon as its pixels are in `fb`: every tile of the clipped
///   rectangle exactly once if the render is not cancelled, and together they cover it.
///
/// `fb` must be the size of the tracer's image (its options' `width` × `height`), since the
/// camera's rays are aimed for that size; a framebuffer of another size is refused with
/// [`Error::Usage`] and left untouched. Every view's pixels are final when their tile is
/// reported: the scales of the depth and rays views are fixed when the tracer is made
/// ([`super::views`]).
pub fn render_rect(
    tracer: &Tracer<'_, Accelerated<'_>>,
    rect: Rect,
    fb: &mut Framebuffer,
    cancel: &(dyn Fn() -> bool + Sync),
    progress: &(dyn Fn(Rect) + Sync),
) -> Result<Finished, Error> {
    let o = tracer.options;
    if (fb.width, fb.height) != (o.width, o.height) || fb.pixels.len() != pixel_count(o) {
        return Err(Error::Usage(format!(
            "a framebuffer of {}×{} ({} pixels) cannot hold a render of {}×{}",
            fb.width,
            fb.height,
            fb.pixels.len(),
            o.width,
            o.height
        )));
    }
    Ok(tile_loop(tracer, rect, fb, cancel, progress))
}

/// Pixels in the options' image.
fn pixel_count(o: &Options) -> usize {
    o.width as usize * o.height as usize
}

/// The tile loop of [`render_rect`], for a framebuffer known to be the tracer's size.
fn tile_loop(
    tracer: &Tracer<'_, Accelerated<'_>>,
    rect: Rect,
    fb: &mut Framebuffer,
    cancel: &(dyn Fn() -> bool + Sync),
    progress: &(dyn Fn(Rect) + Sync),
) -> Finished {
    let w = fb.width;
    let rect = rect.clip(w, fb.height);
    if rect.is_empty() {
        return Finished::Done(Stats::default());
    }
    // set by the first `cancel()` that says stop, so no thread starts another tile
    let stopped = AtomicBool::new(false);
    // one band of TILE rows per task, from the band holding the rectangle's first row to the
    // one holding its last; inside a band, tile by tile
    let band = (w as usize) * TILE as usize;
    let first = rect.y0 / TILE;
    let bands = (rect.y1 - 1) / TILE - first + 1;
    let start = first as usize * band;
    let end = (start + bands as usize * band).min(fb.pixels.len());
    let stats = fb.pixels[start..end]
        .par_chunks_mut(band)
        .enumerate()
        .map(|(i, rows)| {
            let mut stats = Stats::default();
            // start this thread's counts afresh: they are this band's when it ends
            let _ = crate::accel::counters::take();
            let mut scratch = Feelers::new();
            let top = (first + i as u32) * TILE; // the band's first row in the image
            let y0 = top.max(rect.y0);
            let y1 = top.saturating_add(TILE).min(rect.y1);
            let mut tx = rect.x0 - rect.x0 % TILE;
            while tx < rect.x1 {
                if stopped.load(Ordering::Relaxed) || cancel() {
                    stopped.store(true, Ordering::Relaxed);
                    break;
                }
                let tile = Rect::new(
                    tx.max(rect.x0),
                    y0,
                    tx.saturating_add(TILE).min(rect.x1),
                    y1,
                );
                render_tile(tracer, tile, top, w, rows, &mut scratch, &mut stats);
                progress(tile);
                tx = tx.saturating_add(TILE);
            }
            stats.work = crate::accel::counters::take();
            stats
        })
        .reduce(Stats::default, Stats::sum);
    Finished::new(stopped.into_inner(), stats)
}

/// Renders one tile (a part of one band of an image `w` pixels wide) into the band's pixels
/// `rows`, whose first row is image row `top`: block by block, blocks on the image's grid of
/// [`BLOCK`] × [`BLOCK`] cut to the tile.
fn render_tile(
    tracer: &Tracer<'_, Accelerated<'_>>,
    tile: Rect,
    top: u32,
    w: u32,
    rows: &mut [Vec3],
    scratch: &mut Feelers,
    stats: &mut Stats,
) {
    let mut by = tile.y0 - tile.y0 % BLOCK;
    while by < tile.y1 {
        let (y0, y1) = (by.max(tile.y0), by.saturating_add(BLOCK).min(tile.y1));
        let mut bx = tile.x0 - tile.x0 % BLOCK;
        while bx < tile.x1 {
            let (x0, x1) = (bx.max(tile.x0), bx.saturating_add(BLOCK).min(tile.x1));
            let colours = packets::block(tracer, (x0, x1), (y0, y1), scratch, stats);
            let mut c = colours.iter();
            for y in y0..y1 {
                let row = (y - top) as usize * w as usize;
                for p in &mut rows[row + x0 as usize..row + x1 as usize] {
                    *p = *c.next().expect("one colour a pixel");
                }
            }
            bx = bx.saturating_add(BLOCK);
        }
        by = by.saturating_add(BLOCK);
    }
}
