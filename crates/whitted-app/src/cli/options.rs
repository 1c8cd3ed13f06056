//! What the command line sets before any mode runs: the scene it names (or the showcase), the
//! image's size, and the render's [`Options`]: the scene's and the chapter's, then each
//! argument group's switches over them.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::path::Path;

use whitted::error::Error;
use whitted::real::Real;
use whitted::render::{Chapter, Options};
use whitted::scene::load::MAX_SIDE;
use whitted::scene::{self, Scene};

use super::parse::ChapterArgs;

/// Reads the scene named on the command line, or the embedded showcase: the parts the chapter
/// `chapter` uses ([`Chapter::reads`]).
pub fn read_scene(path: Option<&Path>, chapter: Chapter) -> Result<Scene, Error> {
    match path {
        Some(p) => scene::load_parts(p, chapter.reads()),
        None => scene::showcase_parts(chapter.reads()),
    }
}

/// The image size after the command line's overrides, keeping the scene's aspect ratio when
/// only one side is given.
#[must_use]
pub fn image_size(scene: &Scene, width: Option<u32>, height: Option<u32>) -> (u32, u32) {
    let aspect = scene.width as Real / scene.height as Real;
    let clampside = |x: Real| (x.round() as u32).clamp(1, MAX_SIDE);
    match (width, height) {
        (Some(w), Some(h)) => (w, h),
        (Some(w), None) => (w, clampside(w as Real / aspect)),
        (None, Some(h)) => (clampside(h as Real * aspect), h),
        (None, None) => (scene.width, scene.height),
    }
}

/// The options of `chapter`'s render of `scene`: [`Options::for_scene`], then the size and
/// each group's switches the command line gave.
#[must_use]
pub fn options(scene: &Scene, chapter: Chapter, args: &ChapterArgs) -> Options {
    let ChapterArgs {
        common,
        objects,
        accuracy,
        tracing,
    } = args;
    let mut options = Options::for_scene(scene, chapter);
    (options.width, options.height) = image_size(scene, common.width, common.height);
    if let Some(o) = objects {
        options.view = o.view;
        options.accel = o.accel;
        options.packets = !o.no_packets;
    }
    if let Some(t) = tracing {
        options.samples = t.samples.unwrap_or(options.samples);
        options.max_depth = t.max_depth.unwrap_or(options.max_depth);
    }
    if let Some(a) = accuracy {
        options.numerics = a.numerics;
        options.offset = a.offset.offset();
    }
    options
}
