//! `tradeoff` — what each accuracy choice costs in time and buys in error, measured.
//!
//! ```text
//! cargo run --release --bin tradeoff            # writes docs/tradeoff.md and docs/tradeoff.svg
//! cargo run --release --bin tradeoff -- --quick # a smaller run, to try it out
//! ```
//!
//! It renders three fixed scenes (the showcase, the showcase seen from 1e4 units away, and a
//! grazing-angle scene) under a set of settings: precision f32/f64, textbook or robust
//! formulas, each offset strategy, 1/4/16 samples per pixel and several recursion depths. Each
//! setting's render time is the median of several runs; its error is measured against a
//! reference (f64, robust formulas, error-bound offset, many samples, deep recursion): RMSE and
//! largest error in 8-bit levels, the share of pixels off by more than 1/255, and the pixels
//! whose centre ray hits an object in one image and nothing in the other.
//!
//! Both precisions come from one command: the f64 build builds the f32 variant of itself
//! (`cargo build --release --features f32`, in its own target directory) and runs it as a
//! worker that renders the same settings and dumps raw pixels. The workers also time each
//! shape's intersection routine (ns per ray–shape test), textbook against robust, and measure
//! how the generic-object method fares for a planet-sized sphere seen from one unit above it
//! (the hit's error in world units, shadow acne, and what fixes it at what cost).
//!
//! | module | topic |
//! |---|---|
//! | [`settings`] | the scenes and the render settings measured |
//! | [`measure`] | timed renders (median of runs), hit masks, the references, the machine's load |
//! | [`worker`] | the worker of each precision, the f32 build, the files they leave |
//! | [`shapes`] | ns per ray–shape test |
//! | [`metrics`] | error against the reference; the rows of results |
//! | [`planet`] | a huge sphere seen from close by: errors, acne, fixes, and its section of the report |
//! | [`report`] | docs/tradeoff.md |
//! | [`plot`] | docs/tradeoff.svg |

mod measure;
mod metrics;
mod planet;
mod plot;
mod report;
mod settings;
mod shapes;
mod worker;

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use whitted::real::PRECISION;

/// Measures the speed–accuracy trade of whitted's accuracy switches and writes a Markdown
/// table and an SVG plot under docs/.
#[derive(Parser)]
#[command(name = "tradeoff", version)]
struct Args {
    /// Image width of every render.
    #[arg(long, default_value_t = 240)]
    width: u32,
    /// Image height of every render.
    #[arg(long, default_value_t = 180)]
    height: u32,
    /// Timed runs per setting (the median is reported).
    #[arg(long, default_value_t = 7)]
    runs: usize,
    /// Samples per pixel of the reference images.
    #[arg(long, default_value_t = 64)]
    reference_samples: u32,
    /// A small, fast run: 80×60 pixels, 3 runs, a 16-sample reference.
    #[arg(long)]
    quick: bool,
    /// Where to write tradeoff.md and tradeoff.svg.
    #[arg(long, default_value = "docs")]
    out: PathBuf,
    /// Internal: render every setting at this build's precision into DIR and exit.
    #[arg(long, value_name = "DIR", hide = true)]
    worker: Option<PathBuf>,
}

fn main() -> ExitCode {
    let mut args = Args::parse();
    if args.quick {
        (args.width, args.height, args.runs, args.reference_samples) = (80, 60, 3, 16);
    }
    if let Some(dir) = &args.worker {
        return match worker::worker(dir, &args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::from(2)
            }
        };
    }
    match coordinate(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// The whole measurement, from the f64 build: run both workers, render the references,
/// compare, and write the report (with the workers' planet measurements) and the plot.
fn coordinate(args: &Args) -> Result<(), String> {
    if PRECISION != "f64" {
        return Err("run the f64 build: it builds and runs the f32 variant itself".into());
    }
    let started = Instant::now();
    let load_before = measure::load_average();
    let f32_exe = worker::build_f32()?;
    let work = tempfile::tempdir().map_err(|e| e.to_string())?;
    let dirs = [
        ("f64", work.path().join("f64")),
        ("f32", work.path().join("f32")),
    ];
    let this = std::env::current_exe().map_err(|e| e.to_string())?;
    worker::run_worker(&this, &dirs[0].1, args)?;
    worker::run_worker(&f32_exe, &dirs[1].1, args)?;

    eprintln!("rendering the references …");
    let n = (args.width * args.height) as usize;
    let references = measure::references(args.width, args.height, args.reference_samples);
    let rows = metrics::rows(&dirs, &references, n)?;
    let micro = worker::read_shape_timings(&dirs)?;
    let planet = planet::report::section(
        &planet::Measured::read(&dirs[0].1)?,
        &planet::Measured::read(&dirs[1].1)?,
    );

    std::fs::create_dir_all(&args.out).map_err(|e| e.to_string())?;
    let load = report::machine_note(load_before, measure::load_average());
    let seconds = started.elapsed().as_secs_f64();
    let md = report::report(&rows, &micro, &planet, args, seconds, &load);
    let md_path = args.out.join("tradeoff.md");
    whitted::output::write_file(&md_path, md.as_bytes()).map_err(|e| e.to_string())?;
    let svg_path = args.out.join("tradeoff.svg");
    plot::plot(&rows, &svg_path)?;
    eprintln!(
        "wrote {} and {} in {:.0} s",
        md_path.display(),
        svg_path.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}
