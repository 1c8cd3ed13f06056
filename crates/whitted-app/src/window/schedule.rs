//! The coarse-to-fine schedule of the live window: four passes, no pixel traced twice.
//!
//! The first pass traces one pixel in 8 × 8 (every pixel whose column and row are multiples
//! of 8) and paints it over its whole 8 × 8 block, so a rough image is on screen after 1/64
//! of the work. Each later pass halves the step: pass 2 traces the pixels on the grid of
//! step 4 that are not on the grid of step 8, pass 3 those of step 2 not on step 4, and the
//! last pass every pixel left (an odd column or an odd row). Each pixel is traced in exactly
//! one pass, and each pass paints its pixels over blocks of its step, so every pass refines
//! what the one before left on screen; after the last one each pixel shows its own colour.
//!
//! ```text
//! step 8:  a . . . . . . . a     a: pass 1 (step 8)    b: pass 2 (step 4)
//!          . . . . . . . . .     c: pass 3 (step 2)    .: pass 4 (step 1)
//!          . . c . . . c . .
//!          . . . . . . . . .
//!          . . . . b . . . .
//! ```
//!
//! Passes run tile by tile ([`tiles`]), so a pass can be abandoned between tiles the moment
//! the camera moves; a coarse pass takes larger tiles, so that each tile is about the same
//! work.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use whitted::render::Rect;

/// The step of each pass: the side of the block a traced pixel stands for.
pub const STEPS: [u32; 4] = [8, 4, 2, 1];

/// The number of passes to a full image.
pub const PASSES: usize = STEPS.len();

/// Whether pass `pass` (0 to [`PASSES`] − 1) traces pixel (x, y): on the grid of its step,
/// and not on the grid of the pass before.
#[must_use]
pub fn traced_in(pass: usize, x: u32, y: u32) -> bool {
    let on = |step: u32| x.is_multiple_of(step) && y.is_multiple_of(step);
    on(STEPS[pass]) && (pass == 0 || !on(STEPS[pass - 1]))
}

/// The pixels pass `pass` traces inside `rect`, row by row from the top, left to right.
pub fn pixels(pass: usize, rect: Rect) -> impl Iterator<Item = (u32, u32)> {
    let step = STEPS[pass];
    let first = move |a: u32| a.div_ceil(step) * step;
    (first(rect.y0)..rect.y1)
        .step_by(step as usize)
        .flat_map(move |y| {
            (first(rect.x0)..rect.x1)
                .step_by(step as usize)
                .map(move |x| (x, y))
        })
        .filter(move |&(x, y)| traced_in(pass, x, y))
}

/// The block pixel (x, y) of pass `pass` is painted over: step × step pixels from (x, y),
/// cut to an image of `width` × `height`.
#[must_use]
pub fn block(pass: usize, x: u32, y: u32, width: u32, height: u32) -> Rect {
    let step = STEPS[pass];
    Rect::new(
        x,
        y,
        x.saturating_add(step).min(width),
        y.saturating_add(step).min(height),
    )
}

/// The side of the square tiles of pass `pass`: 32 × its step (256, 128, 64, 32 pixels), so
/// that a tile of every pass holds about the same work (768 pixels traced in a full tile of
/// passes 2 to 4, 1024 in pass 1). Equal tiles of 16 pixels would give pass 1 only 4 pixels
/// a tile, and the window a message for each.
#[must_use]
pub fn tile_side(pass: usize) -> u32 {
    32 * STEPS[pass]
}

/// The tiles of pass `pass` over an image of `width` × `height`, row by row: a grid of
/// [`tile_side`] squares from the top left, the last row and column cut to the image. Their
/// sides are multiples of every step, so each block a pass paints lies inside its tile.
#[must_use]
pub fn tiles(pass: usize, width: u32, height: u32) -> Vec<Rect> {
    let t = tile_side(pass);
    let mut out = Vec::new();
    for y in (0..height).step_by(t as usize) {
        for x in (0..width).step_by(t as usize) {
            out.push(Rect::new(
                x,
                y,
                x.saturating_add(t).min(width),
                y.saturating_add(t).min(height),
            ));
        }
    }
    out
}
