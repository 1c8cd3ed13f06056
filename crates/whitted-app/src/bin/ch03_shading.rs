//! Chapter 3 — shading: ambient, diffuse and specular (Phong) light from every light source.
//! The chapter: chapters/ch03_shading/README.md and its page of the course book.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::Parser;
use whitted::render::Chapter;
use whitted_app::cli::{Common, ViewArg, run};

/// Chapter 3 of whitted: shades the nearest hit with the notes' Phong model,
/// I = ρa·I_m + Σ I_p/(a0 + a1·d + a2·d²)·(ρd·max(n·s, 0) + ρs·max(r·v, 0)^f),
/// per RGB channel, for every light. No shadows yet: every light reaches every point.
#[derive(Parser)]
#[command(name = "ch03_shading", version)]
struct Args {
    #[command(flatten)]
    common: Common,
    #[command(flatten)]
    view: ViewArg,
}

fn main() -> ExitCode {
    let args: Args = whitted_app::cli::parse_args();
    run(
        "ch03_shading",
        Chapter::Shading,
        &args.common,
        Some(&args.view),
        None,
        None,
    )
}
