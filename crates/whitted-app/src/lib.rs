//! # whitted-app — the programs around the renderer
//!
//! The renderer (the crate `whitted`) computes images; this crate turns it into programs. One
//! binary per chapter of the syllabus (`src/bin/NAME.rs`, NAME the chapter's binary), each a
//! few lines that name its [`whitted::render::Chapter`] and say what it does, over what they
//! share:
//!
//! - [`cli`]: the command line of every chapter binary, built from its chapter (name, number,
//!   title, argument groups), the render to a PNG, `--inspect`, one-line errors with exit
//!   status 2;
//! - [`compare`]: the render beside a reference image with the difference marked, for
//!   `--compare REF.png` and the window's compare key;
//! - [`window`]: the live window of `--window`, the image refined coarse to fine as you watch,
//!   keys for the camera, chapter, view and depth, and the ray tree of a clicked pixel drawn over
//!   the image.
//!
//! Course book: [Introduction](../../../docs/book/introduction.html) (`docs/src/introduction.md`).

#![deny(missing_docs)]

pub mod cli;
pub mod compare;
pub mod window;
