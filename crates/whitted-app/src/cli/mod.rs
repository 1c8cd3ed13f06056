//! The command line every chapter binary shares: [`main`] builds a chapter's command line from
//! the chapter alone ([`command`]), reads it, and runs the one mode it asks for.
//!
//! Every binary takes [`Common`]; the other groups come with the chapter that first needs
//! them: [`Objects`] from [`OBJECTS_FROM`] (objects to view, find and inspect), [`Accuracy`]
//! from [`ACCURACY_FROM`] (secondary rays leave surfaces), [`Tracing`] from [`TRACING_FROM`]
//! (recursion and supersampling). Each binary's arguments, as README.md and each chapter's
//! README list them, are written from [`command`] (`tests/docs.rs` compares them).
//!
//! Without SCENE the embedded default scene `scenes/showcase.toml` is rendered. The PNG is
//! sRGB-encoded, as viewers expect; `--encoding linear` writes the linear intensities as bytes
//! (see [`whitted::output`]). Every failure
//! is one line on stderr, `error: …`, and exit status 2; nothing is written unless the whole
//! image was rendered. An image whose framebuffer would pass
//! [`whitted::render::MAX_FRAMEBUFFER_BYTES`] is refused before any work starts.
//!
//! With `--compare REF.png` the PNG holds three images side by side, the render, REF.png and
//! their difference ([`crate::compare`]), and stdout gets one line saying how many pixels
//! differ and where the first is; the exit status is 0 whether they differ or not. REF.png
//! must have the render's size (checked before any work starts).
//!
//! A render that lasts more than a second shows a progress bar on stderr (only when stderr
//! is a terminal, and not with `--quiet`). Unless `--quiet`, the last line on stderr gives the
//! resolution, the rays cast by kind, the time and the millions of rays per second.
//!
//! | module | what it holds |
//! |---|---|
//! | [`choices`] | the library's sets of values (views, accelerations …) as choices, with their help |
//! | [`offers`] | the chapter from which each group of arguments is offered |
//! | [`args`] | the groups of arguments: [`Common`], [`Objects`], [`Accuracy`], [`Tracing`] |
//! | [`parse`] | a chapter's command line built from the chapter, read back as [`ChapterArgs`] |
//! | [`options`] | the scene, the image size and the render's options the command line sets |
//! | [`mode`] | which mode a run is, read from the arguments |
//! | [`program`] | the program: read, set up, then the mode's function, in one `match` |
//! | [`exit`] | the exit status: one line `error: …` and status 2 |
//! | [`inspect`] | `--inspect X,Y` and `--inspect-grid`: ray trees on stdout |
//! | [`against`] | `--against TREES.json`: the reference's trees traced with this code |
//! | [`window`] | `--window`: the size it opens at, and the live window started |
//! | [`png`] | the render written as a PNG, the comparison with `--compare`, the lines on stderr |
//! | [`reference`](mod@reference) | `--compare REF.png`: the reference, its checks, the comparison written |
//! | [`stats`] | the statistics lines after a render |
//! | [`progress`] | the progress bar of a long render |
//! | [`stdout`] | what the modes print on stdout |
//!
//! Course book: [Introduction](../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

pub mod against;
pub mod args;
pub mod choices;
pub mod exit;
pub mod inspect;
pub mod mode;
pub mod offers;
pub mod options;
pub mod parse;
pub mod png;
pub mod program;
pub mod progress;
pub mod reference;
pub mod stats;
pub mod stdout;
pub mod window;

pub use args::{Accuracy, Common, Objects, Tracing, WINDOW_FIT, window_help};
pub use choices::{Choice, choice};
pub use exit::guard;
pub use offers::{ACCURACY_FROM, OBJECTS_FROM, TRACING_FROM};
pub use options::{image_size, read_scene};
pub use parse::{ChapterArgs, command, parse_args, parsed_or_exit};
pub use program::{main, run};
pub use reference::Reference;
pub use stats::{summary, work_line};
pub use window::fit;

/// The one line of an exercise not written yet (it lives in [`whitted::error`], where the live
/// window finds it too).
pub use whitted::error::missing_exercise;
/// The default scene, compiled into every binary (it lives in the library).
pub use whitted::scene::{SHOWCASE, SHOWCASE_NAME};
