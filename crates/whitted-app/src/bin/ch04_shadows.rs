//! Chapter 4 — shadows: a feeler ray towards each light.
//! The chapter: chapters/ch04_shadows/README.md and its page of the course book.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::Parser;
use whitted::render::Chapter;
use whitted_app::cli::{Accuracy, Common, ViewArg, run};

/// Chapter 4 of whitted: chapter 3's shading, where each light first sends a feeler ray
/// S(u) = P + (L − P)·u from the hit point; an opaque object with u ∈ ]0, 1] leaves the point
/// with ambient light only, a translucent one lets its transmission share through.
#[derive(Parser)]
#[command(name = "ch04_shadows", version)]
struct Args {
    #[command(flatten)]
    common: Common,
    #[command(flatten)]
    view: ViewArg,
    #[command(flatten)]
    accuracy: Accuracy,
}

fn main() -> ExitCode {
    let args: Args = whitted_app::cli::parse_args();
    run(
        "ch04_shadows",
        Chapter::Shadows,
        &args.common,
        Some(&args.view),
        None,
        Some(&args.accuracy),
    )
}
