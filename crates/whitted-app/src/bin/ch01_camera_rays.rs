//! Chapter 1 — camera rays: one ray per pixel, coloured by its direction (d̂ + 1)/2.
//! The chapter: chapters/ch01_camera_rays/README.md and its page of the course book.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::Parser;
use whitted::render::Chapter;
use whitted_app::cli::{Common, run};

/// Chapter 1 of whitted: builds the viewing coordinates and the near plane from the scene's
/// camera and shoots one ray through each pixel centre. Each pixel shows its ray's direction
/// as a colour: red = x, green = y, blue = z, each mapped from [−1, 1] to [0, 1].
#[derive(Parser)]
#[command(name = "ch01_camera_rays", version)]
struct Args {
    #[command(flatten)]
    common: Common,
}

fn main() -> ExitCode {
    let args: Args = whitted_app::cli::parse_args();
    run(
        "ch01_camera_rays",
        Chapter::CameraRays,
        &args.common,
        None,
        None,
        None,
    )
}
