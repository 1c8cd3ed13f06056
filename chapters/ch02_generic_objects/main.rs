//! Chapter 2 — generic objects: the nearest hit of each camera ray.
//! See README.md beside this file.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::Parser;
use whitted::cli::{Common, ViewArg, run};
use whitted::render::Stage;

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
    let args: Args = whitted::cli::parse_args();
    run(
        "ch02_generic_objects",
        Stage::GenericObjects,
        &args.common,
        Some(&args.view),
        None,
        None,
    )
}
