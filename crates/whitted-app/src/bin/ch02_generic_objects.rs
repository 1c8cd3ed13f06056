//! Chapter 2 — generic objects: the nearest hit of each camera ray.
//! The chapter: chapters/ch02_generic_objects/README.md and its page of the course book.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::Parser;
use whitted::render::Chapter;
use whitted_app::cli::{Common, ViewArg, run};

/// Chapter 2 of whitted: intersects each camera ray with the scene's spheres, planes,
/// cylinders, cones and convex polyhedra (each a generic shape placed by a matrix M), keeps
/// the nearest hit and shows it unlit: its material's flat colour, its normal, or its depth.
#[derive(Parser)]
#[command(name = "ch02_generic_objects", version)]
struct Args {
    #[command(flatten)]
    common: Common,
    #[command(flatten)]
    view: ViewArg,
}

fn main() -> ExitCode {
    let args: Args = whitted_app::cli::parse_args();
    run(
        "ch02_generic_objects",
        Chapter::GenericObjects,
        &args.common,
        Some(&args.view),
        None,
        None,
    )
}
