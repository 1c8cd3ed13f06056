//! What the window shows: the image as the passes fill it in, and the pixels on screen.
//!
//! The canvas keeps two images of the same size: the linear framebuffer (the notes' I, what
//! `P` saves) and the screen's `0RGB` pixels, encoded for display ([`Encoding`]). A tile of
//! pass k paints each pixel it traced over its k-step block ([`schedule::block`]), so the
//! image refines in place; updates of any generation but the current one are dropped.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use super::progressive::Update;
use super::schedule::{self, PASSES};
use whitted::output::Encoding;
use whitted::real::Vec3;
use whitted::render::{Framebuffer, Rect, Stats};

/// The image of the live window.
pub struct Canvas {
    /// The linear image: each traced pixel's colour over its block.
    pub fb: Framebuffer,
    /// The screen's pixels, `0x00RRGGBB`, row by row from the top.
    pub screen: Vec<u32>,
    /// How intensities become screen bytes.
    pub encoding: Encoding,
    /// The generation whose tiles are accepted.
    pub generation: u64,
    /// The passes of that generation complete (0 to [`PASSES`]).
    pub passes_done: usize,
    /// The rays and time of the last complete pass.
    pub last: Option<(Stats, std::time::Duration)>,
}

impl Canvas {
    /// A black canvas of `width` × `height`.
    #[must_use]
    pub fn new(width: u32, height: u32, encoding: Encoding) -> Self {
        Self {
            fb: Framebuffer::new(width, height),
            screen: vec![0; width as usize * height as usize],
            encoding,
            generation: 0,
            passes_done: 0,
            last: None,
        }
    }

    /// Starts accepting the tiles of `generation` only. The image stays as it is until they
    /// paint over it, so the screen never goes black between two camera positions.
    pub fn expect(&mut self, generation: u64) {
        self.generation = generation;
        self.passes_done = 0;
        self.last = None;
    }

    /// Whether every pass of the current generation is done.
    #[must_use]
    pub fn complete(&self) -> bool {
        self.passes_done == PASSES
    }

    /// Takes an update from the worker: paints a tile, or notes a finished pass. Returns
    /// whether the update was the current generation's (the others are dropped unseen).
    pub fn apply(&mut self, update: &Update) -> bool {
        if update.generation() != self.generation {
            return false;
        }
        match update {
            Update::Tile {
                pass,
                rect,
                colours,
                ..
            } => self.paint(*pass, *rect, colours),
            Update::PassDone {
                pass,
                elapsed,
                stats,
                ..
            } => {
                self.passes_done = pass + 1;
                self.last = Some((*stats, *elapsed));
            }
            Update::Ready { .. } | Update::Failed { .. } => {}
        }
        true
    }

    /// Paints the colours pass `pass` traced in tile `rect` over their blocks.
    fn paint(&mut self, pass: usize, rect: Rect, colours: &[Vec3]) {
        let (w, h) = (self.fb.width, self.fb.height);
        for ((x, y), &c) in schedule::pixels(pass, rect).zip(colours) {
            let pixel = self.screen_pixel(c);
            let b = schedule::block(pass, x, y, w, h);
            for yy in b.y0..b.y1 {
                let row = (yy * w) as usize;
                self.fb.pixels[row + b.x0 as usize..row + b.x1 as usize].fill(c);
                self.screen[row + b.x0 as usize..row + b.x1 as usize].fill(pixel);
            }
        }
    }

    /// A linear colour as a screen pixel `0x00RRGGBB`.
    #[must_use]
    pub fn screen_pixel(&self, c: Vec3) -> u32 {
        let e = self.encoding;
        (u32::from(e.byte(c.x)) << 16) | (u32::from(e.byte(c.y)) << 8) | u32::from(e.byte(c.z))
    }

    /// The screen's pixels scaled to a window of `width` × `height` (nearest pixel), into
    /// `frame`, resized to fit. The window then shows them one to one, and the overlay is
    /// drawn at the window's own resolution.
    pub fn blit(&self, frame: &mut Vec<u32>, width: u32, height: u32) {
        scale(
            &self.screen,
            (self.fb.width, self.fb.height),
            frame,
            (width, height),
        );
    }
}

/// Screen pixels `src` of `size` (width, height) scaled to `to` by the nearest pixel, into
/// `frame`, resized to fit.
pub fn scale(src: &[u32], size: (u32, u32), frame: &mut Vec<u32>, to: (u32, u32)) {
    let ((w, h), (width, height)) = (size, to);
    frame.resize(width as usize * height as usize, 0);
    if to == size {
        frame.copy_from_slice(src);
        return;
    }
    let column: Vec<usize> = (0..u64::from(width))
        .map(|x| (x * u64::from(w) / u64::from(width)) as usize)
        .collect();
    for (y, row) in frame.chunks_exact_mut(width as usize).enumerate() {
        let sy = (y as u64 * u64::from(h) / u64::from(height)) as usize;
        let line = &src[sy * w as usize..(sy + 1) * w as usize];
        for (p, &sx) in row.iter_mut().zip(&column) {
            *p = line[sx];
        }
    }
}
