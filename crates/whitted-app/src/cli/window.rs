//! `--window`: the chapter binary opens the live window ([`crate::window`]) instead of writing
//! a file. Without `--width` or `--height` the image is the scene's size, shrunk to fit
//! [`WINDOW_FIT`]; the sizes (and the reference's, with `--compare`) are checked before the
//! window opens.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use std::path::PathBuf;

use whitted::error::Error;
use whitted::render::{self, Chapter, Options};
use whitted::scene::Scene;

use super::args::{Common, WINDOW_FIT};
use super::reference::Reference;

/// Opens the window on `scene` rendered with `options` by `chapter`'s binary; its save key
/// writes to `out`. Returns when the window is closed.
pub fn open(
    scene: Scene,
    mut options: Options,
    chapter: Chapter,
    out: PathBuf,
    common: &Common,
) -> Result<(), Error> {
    let reference = Reference::of(common.compare.as_deref())?;
    if common.width.is_none() && common.height.is_none() {
        (options.width, options.height) = fit(options.width, options.height, WINDOW_FIT);
    }
    render::check_size(options.width, options.height)?;
    if let Some(r) = &reference {
        // the comparison renders at the reference's size
        render::check_size(r.image.width, r.image.height)?;
    }
    crate::window::run(crate::window::Setup {
        scene_path: common.scene.clone(),
        scene,
        options,
        max_chapter: chapter,
        encoding: common.encoding,
        save_to: out,
        quiet: common.quiet,
        reference,
    })
}

/// `width` × `height` shrunk, keeping its aspect ratio, to fit in `bound` (unchanged if it
/// fits already).
#[must_use]
pub fn fit(width: u32, height: u32, bound: (u32, u32)) -> (u32, u32) {
    let scale = (f64::from(bound.0) / f64::from(width))
        .min(f64::from(bound.1) / f64::from(height))
        .min(1.0);
    let side = |x: u32| ((f64::from(x) * scale).round() as u32).max(1);
    (side(width), side(height))
}
