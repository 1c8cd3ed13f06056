//! `whitted-learn` — the student's loop, which `cargo learn` runs: the verdict on the next
//! exercise, the progress, hints, the chapter's picture, and all of it after every save.
//!
//! ```text
//! cargo learn              the verdict on the next exercise, the progress, the picture
//! cargo learn watch        the same after every save
//! cargo learn hint [EXERCISE]  the next hint (of the next exercise, or of EXERCISE: 2.3 or its name)
//! cargo learn list         every exercise with its state and points
//! cargo learn reset EXERCISE  its body back to the handout's todo!(), yours kept in .whitted/reset/
//! ```
//!
//! Exit status: 0 once checked (whatever the exercises' state), 1 when the code does not
//! compile, 2 on an error, printed as one line `error: …`.

#![deny(missing_docs)]

use std::process::ExitCode;

use clap::Parser;
use whitted_learn::cli::{LearnArgs, learn};

/// The student's loop of whitted, the toolkit for learning classic ray tracing.
#[derive(Parser)]
#[command(name = "cargo learn", bin_name = "cargo learn", version)]
struct Args {
    #[command(flatten)]
    learn: LearnArgs,
}

fn main() -> ExitCode {
    let args: Args = whitted_learn::args::parse_args();
    match learn(&args.learn) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
