//! Chapter 5 — reflection and refraction: the complete Whitted renderer.
//! The chapter: chapters/ch05_reflection_refraction/README.md and its page of the course book.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::Parser;
use whitted::render::Chapter;
use whitted_app::cli::{Accuracy, Common, Tracing, ViewArg, run};

/// Chapter 5 of whitted, the complete renderer: I = I_a + I_d + I_s + I_l + I_r. Mirror
/// materials spawn reflected rays l = d − 2(d·n)n, translucent ones transmitted rays by
/// Snell's law (with total internal reflection), recursively up to --max-depth.
#[derive(Parser)]
#[command(name = "ch05_reflection_refraction", version)]
struct Args {
    #[command(flatten)]
    common: Common,
    #[command(flatten)]
    view: ViewArg,
    #[command(flatten)]
    accuracy: Accuracy,
    #[command(flatten)]
    tracing: Tracing,
}

fn main() -> ExitCode {
    let args: Args = whitted_app::cli::parse_args();
    run(
        "ch05_reflection_refraction",
        Chapter::ReflectionRefraction,
        &args.common,
        Some(&args.view),
        Some(&args.tracing),
        Some(&args.accuracy),
    )
}
