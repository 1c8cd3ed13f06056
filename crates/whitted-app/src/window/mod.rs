//! The live window (`--window` on every chapter binary): the image refines as you watch,
//! the keys move the camera and switch chapter, view and depth, a click shows the ray tree
//! of a pixel drawn over the image, and with `--compare REF.png` a key shows the reference and
//! the difference beside the render.
//!
//! | module | what it holds |
//! |---|---|
//! | [`schedule`] | the coarse-to-fine passes: blocks of 8, 4, 2, 1 pixels, no pixel traced twice |
//! | [`progressive`] | the render thread, its rayon pool, and cancelling by generation |
//! | [`canvas`] | the image as the passes fill it in, and the screen's pixels |
//! | [`comparison`] | `--compare`: the render at the reference's size, compared on its own thread |
//! | [`action`] | what a key asks for: move, turn, depth, chapter, view … |
//! | [`camera`] | the camera as the keys move and turn it, and as `C` prints it |
//! | [`keys`] | the keymap: every key, what it asks for, and the help written from it |
//! | [`state`] | what the keys change: input → state → commands, no display needed |
//! | [`overlay`] | the ray tree of a clicked pixel, projected into the view and drawn |
//! | [`shell`] | minifb: the window, its loop, reloading the scene file |
//!
//! The road of one pixel is the renderer's own ([`whitted::render::Tracer::pixel`]): the window
//! only decides which pixels to trace first and where to paint them.
//!
//! Course book: [The live window](../../../../docs/book/window.html) (`docs/src/window.md`).

pub mod action;
pub mod camera;
pub mod canvas;
pub mod comparison;
pub mod keys;
pub mod overlay;
pub mod progressive;
pub mod schedule;
pub mod shell;
pub mod state;

pub use shell::{Setup, run};
