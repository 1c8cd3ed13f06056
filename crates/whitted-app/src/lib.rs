//! # whitted-app — the programs around the renderer
//!
//! The renderer (the crate `whitted`) computes images; this crate turns it into programs. One
//! binary per chapter (`src/bin/chNN_name.rs`), each a few lines that name the chapter's chapter
//! and the argument groups it offers, over what they share:
//!
//! - [`cli`]: the command line every chapter binary reads, the render to a PNG, `--inspect`,
//!   one-line errors with exit status 2;
//! - [`window`]: the live window of `--window`, the image refined coarse to fine as you watch,
//!   keys for the camera, chapter, view and depth, and the ray tree of a clicked pixel drawn over
//!   the image.
//!
//! Course book: [Introduction](../../../docs/book/introduction.html) (`docs/src/introduction.md`).

#![deny(missing_docs)]

pub mod cli;
pub mod window;
