//! Scenes: what to render, read from a TOML file (chapters 1–5 each read the parts they use).
//!
//! [`load()`] reads a file, [`parse()`] a string; both check every value and report a bad one as
//! `file:line:col: what was expected`. The result is a [`Scene`]: the camera settings, image
//! size, lights, materials and placed objects, ready to render. [`format`](mod@format) is the
//! file's shape as TOML, [`load`](mod@load) checks it and builds the scene, [`model`] holds
//! the scene's types.
//!
//! ```toml
//! [camera]
//! eye = [0.0, 1.0, 6.0]
//!
//! [[objects]]
//! sphere = { center = [0.0, 0.0, 0.0], radius = 1.0 }
//! ```
//!
//! Course book: [The scene file](../../../../docs/book/scene-format.html) (`docs/src/scene-format.md`).

pub mod format;
pub mod load;
pub mod model;
pub mod scatter;

pub use load::{Parts, load, load_parts, parse, parse_parts};
pub use model::{CameraSettings, Scene};

/// The default scene (`scenes/showcase.toml`), compiled into the library: what every chapter
/// binary renders when no scene file is given.
pub const SHOWCASE: &str = include_str!("../../../../scenes/showcase.toml");
/// The name the default scene goes by in messages.
pub const SHOWCASE_NAME: &str = "scenes/showcase.toml";

/// The default scene, parsed.
pub fn showcase() -> Result<Scene, crate::error::Error> {
    parse(SHOWCASE, SHOWCASE_NAME)
}

/// The `parts` of the default scene that a chapter uses.
pub fn showcase_parts(parts: Parts) -> Result<Scene, crate::error::Error> {
    parse_parts(SHOWCASE, SHOWCASE_NAME, parts)
}
