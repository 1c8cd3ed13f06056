//! A chapter binary's program from start to end: [`main`] reads the command line and [`run`]
//! runs it under [`guard`]: the scene read and the options set, then the one mode the
//! arguments ask for ([`Mode`]), each mode a function in a file of its own.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::path::PathBuf;
use std::process::ExitCode;

use whitted::error::Error;
use whitted::output;
use whitted::render::Chapter;

use super::exit::guard;
use super::mode::Mode;
use super::options::{options, read_scene};
use super::parse::{ChapterArgs, command, parsed_or_exit};
use super::{against, inspect, png, window};

/// A chapter binary's whole program: reads its command line ([`command`]) and runs it
/// ([`run`]); returns the exit status.
#[must_use]
pub fn main(chapter: Chapter, about: &str) -> ExitCode {
    let parsed = command(chapter, about)
        .try_get_matches()
        .and_then(|m| ChapterArgs::from_matches(chapter, &m));
    run(chapter, &parsed_or_exit(parsed))
}

/// Runs a chapter: read, render, write (or inspect, or open the window). Returns the exit
/// status (0, or 2 after printing the error).
pub fn run(chapter: Chapter, args: &ChapterArgs) -> ExitCode {
    guard(|| dispatch(chapter, args))
}

/// Reads what every mode needs, in the order its errors are reported (the switches, the
/// `--against` file, the destination, the scene), then runs the mode.
fn dispatch(chapter: Chapter, args: &ChapterArgs) -> Result<(), Error> {
    let common = &args.common;
    let mode = Mode::of(args)?;
    let out = common
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("{}.png", chapter.about().binary)));
    if mode.writes_image() {
        output::check_destination(&out)?;
    }
    let scene = read_scene(common.scene.as_deref(), chapter)?;
    for w in &scene.warnings {
        eprintln!("warning: {w}");
    }
    let options = options(&scene, chapter, args);
    match mode {
        Mode::Inspect(pixel) => {
            inspect::print_tree(&scene, &options, pixel, common.encoding, common.json)
        }
        Mode::Grid(step) => inspect::print_grid(&scene, &options, step),
        Mode::Against(trees) => {
            against::print_against(&scene, &options, &trees, common).map(|_| ())
        }
        Mode::Window => window::open(scene, options, chapter, out, common),
        Mode::Png(trees) => png::render(&scene, &options, &out, args, trees.as_ref()),
    }
}
