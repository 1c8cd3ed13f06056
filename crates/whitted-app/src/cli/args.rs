//! The groups of arguments a chapter binary takes, as clap reads them: [`Common`] to every
//! chapter, [`Objects`], [`Accuracy`] and [`Tracing`] from the chapter that first needs each
//! ([`super::offers`]). Each field's doc comment is its line in `--help`, and README.md and the
//! chapters' READMEs print that help (`tests/docs.rs` compares them).
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::path::PathBuf;

use clap::Args;

use whitted::accel::Accel;
use whitted::offset::OffsetKind;
use whitted::output::Encoding;
use whitted::render::View;
use whitted::scene::load::{MAX_DEPTH, MAX_SAMPLES, MAX_SIDE};
use whitted::shapes::Numerics;

use super::choices::choice;

/// Arguments shared by every chapter.
#[derive(Args, Debug, Clone)]
pub struct Common {
    /// Scene file (TOML). Without it, the built-in showcase scene (scenes/showcase.toml) is rendered.
    pub scene: Option<PathBuf>,
    /// Where to write the PNG image [default: BINARY_NAME.png in the current directory].
    #[arg(short, long, value_name = "OUT.png")]
    pub output: Option<PathBuf>,
    /// Image width in pixels; alone, the height follows the scene's aspect ratio.
    #[arg(long, value_name = "W", value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64))]
    pub width: Option<u32>,
    /// Image height in pixels; alone, the width follows the scene's aspect ratio.
    #[arg(long, value_name = "H", value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64))]
    pub height: Option<u32>,
    /// How the PNG's bytes encode the linear intensities (`--inspect` prints the same bytes).
    #[arg(long, value_parser = choice::<Encoding>(), default_value = Encoding::default().name())]
    pub encoding: Encoding,
    /// No progress bar and no statistics line (errors and warnings are still printed).
    #[arg(short, long)]
    pub quiet: bool,
    /// Open a live window instead of writing a file; its help, with the keys, is
    /// [`window_help`].
    #[arg(long, help = window_help(false), long_help = window_help(true))]
    pub window: bool,
    /// Compare the render with REF.png (of the same size): write your render, the reference and
    /// the differing pixels side by side, and print on stdout how many differ. With --window,
    /// Tab shows the reference and the difference.
    #[arg(long, value_name = "REF.png")]
    pub compare: Option<PathBuf>,
    /// Trace the pixels of TREES.json (the reference's ray trees, chapters/chNN_name/trees.json)
    /// with this code and the settings the file records, and print, for each pixel whose tree
    /// differs, the first quantity that does and the functions that computed it. No image is
    /// written unless -o or --compare asks for one.
    #[arg(long, value_name = "TREES.json", conflicts_with = "window")]
    pub against: Option<PathBuf>,
    /// Print the ray tree of every STEP-th pixel of every STEP-th row as JSON lines, after a
    /// line with the settings they were traced with, and exit (`whitted trees` reads them).
    #[arg(long, value_name = "STEP", hide = true,
          value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64),
          conflicts_with_all = ["output", "compare", "against", "window"])]
    pub inspect_grid: Option<u32>,
    /// With --inspect or --against: print JSON (its shapes: docs/src/inspect.md).
    #[arg(long)]
    pub json: bool,
}

/// The largest image `--window` opens without `--width` or `--height`.
pub const WINDOW_FIT: (u32, u32) = (1280, 960);

/// The help of `--window`, with the keys from the window's keymap
/// ([`crate::window::keys`]): in one line (`-h`), or a key a line (`--help`).
#[must_use]
pub fn window_help(long: bool) -> String {
    let what = "Open a live window instead of writing a file: the image refines coarse to fine";
    if long {
        format!(
            "{what}. Without --width/--height the image is the scene's size, shrunk to fit {}×{}. \
             Its keys (H in the window prints them too):\n{}",
            WINDOW_FIT.0,
            WINDOW_FIT.1,
            crate::window::keys::lines()
        )
    } else {
        format!("{what}; keys: {}", crate::window::keys::summary())
    }
}

/// The switches of the chapters that trace objects: what a pixel shows, how the
/// nearest hit is searched for, and one pixel's ray tree.
#[derive(Args, Debug, Clone)]
pub struct Objects {
    /// What each pixel shows.
    #[arg(long, value_parser = choice::<View>(), default_value = View::default().name())]
    pub view: View,
    /// How ray queries are accelerated (notes: "Computational Aspects"); the image is the same
    /// with every choice, only the time changes.
    #[arg(long, value_parser = choice::<Accel>(), default_value = Accel::default().name())]
    pub accel: Accel,
    /// Trace every pixel alone by the plain road, instead of the camera rays and feelers of
    /// 8×8 blocks as packets (a BVH or an octree, one sample a pixel); the same image either way.
    #[arg(long)]
    pub no_packets: bool,
    /// Print the ray tree of pixel X,Y (column X, row Y from the top, from 0) — hits, each
    /// light's I_a, I_d, I_s and feeler, mirror and transmitted rays — and exit, writing no image.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel, conflicts_with_all = ["output", "compare", "against", "inspect_grid"], allow_hyphen_values = true)]
    pub inspect: Option<(u32, u32)>,
}

/// Reads `X,Y` as a pixel's column and row.
fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("expected X,Y: a pixel's column and row, such as 320,240 (got `{text}`)");
    let (x, y) = text.split_once(',').ok_or_else(bad)?;
    let x = x.trim().parse().map_err(|_| bad())?;
    let y = y.trim().parse().map_err(|_| bad())?;
    Ok((x, y))
}

/// The tracing controls of the chapter with recursion: samples a pixel and depth.
#[derive(Args, Debug, Clone)]
pub struct Tracing {
    /// Samples per pixel (jittered from a fixed seed: the same image every run) [default: the scene's, else 1].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=MAX_SAMPLES as i64))]
    pub samples: Option<u32>,
    /// Maximum recursion depth of mirror and transmitted rays [default: the scene's, else 5].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(0..=MAX_DEPTH as i64))]
    pub max_depth: Option<u32>,
    /// Also print the samples, depth, threads and the acceleration structure built (and, in a
    /// build with `--features counters`, the node visits, box tests and object tests).
    #[arg(long)]
    pub stats: bool,
}

/// The accuracy switches of the chapters with secondary rays: which intersection formulas, and
/// how secondary rays leave a surface (see [`whitted::shapes::quadratic`] and [`whitted::offset`]).
#[derive(Args, Debug, Clone)]
pub struct Accuracy {
    /// Which intersection formulas.
    #[arg(long, alias = "formula", value_parser = choice::<Numerics>(), default_value = Numerics::default().name())]
    pub numerics: Numerics,
    /// How feeler, mirror and transmitted rays leave a surface.
    #[arg(long, value_parser = choice::<OffsetKind>(), default_value = OffsetKind::default().name())]
    pub offset: OffsetKind,
}
