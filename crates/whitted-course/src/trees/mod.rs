//! The reference's ray trees as data, and the course's known mistakes: `whitted trees
//! [--check]`.
//!
//! For each chapter, the chapter's binary renders its scene as the book's figure of it
//! (`docs/figures.toml`, the figure `chNN_name.png`: the same settings `cargo learn` renders
//! the student's picture with) and prints the ray tree of every [`STEP`]-th pixel of every
//! [`STEP`]-th row (`--inspect-grid`). Of those pixels, a few are kept, chosen greedily so
//! that together they show every [feature](features) of the scene's trees: each object and
//! each part of it hit (by any ray), each light lit, in shadow, in a translucent shadow and
//! behind the surface, each light's highlight, each kind of branch and each reason a branch
//! stops (total internal reflection among them), a miss, and each quarter of the image. Only
//! *steady* pixels are kept: pixels whose neighbours at [`STEP`] pixels all have trees of the
//! same shape ([`signature`]), so that a tree traced in f32, or with a formula written in
//! another correct way, has the reference's shape there too.
//!
//! Then the course's known mistakes ([`crate::mistakes`]) are applied to the reference one
//! at a time (one build, each behind a switch), and each one's chapter is traced `--against`
//! every steady pixel: a mistake whose trees differ at none of the pixels kept adds the
//! steadiest pixel where its trees do differ, so that every known mistake shows in the data.
//! `chapters/chNN_name/trees.json` is written (its shape: `docs/src/inspect.md`), then each
//! mistake's fingerprint, rendered with `--compare` beside the figure and `--against` the
//! file, into `chapters/mistakes.json` ([`whitted_learn::trees`]). Both ship with a handout.
//! They hold numbers at a few pixels, which the figures show already, and the mistakes' words:
//! nothing of the code.
//!
//! `whitted trees --check` keeps the pixels of the committed files: it checks that the
//! reference's trees there are still the committed ones (within the tolerances of the
//! comparison), and that the pixels chosen for the scene's features are still those a fresh
//! choice makes. It needs no build of the mistakes.
//!
//! Its files, one job each: `grid.rs` traces the trees to choose from, `shape.rs` says what
//! one tree is made of, `choose.rs` keeps the pixels, `file.rs` writes and reads a trees file,
//! `switched.rs` traces the known mistakes, `check.rs` compares the committed files, `run.rs`
//! runs a chapter binary, and `command.rs` puts the steps in order.
//!
//! Course book: [The ray tree of one pixel](../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

mod check;
mod choose;
mod command;
mod file;
mod grid;
mod run;
mod shape;
mod switched;
mod values;

pub use check::mistakes_unseen;
pub use command::{TreesArgs, command};
pub use grid::STEP;
pub use shape::{HIGHLIGHT, features, signature};

/// Where the known mistakes and each chapter's trees are kept, and the known mistakes' file
/// (the student's loop reads them).
pub use whitted_learn::trees::{MISTAKES, Mistakes, trees_file};
