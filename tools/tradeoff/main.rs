//! `tradeoff` — what each accuracy choice costs in time and buys in error, measured.
//!
//! ```text
//! cargo run --release --bin tradeoff             # measures; writes docs/src/tradeoff.{json,md,svg}
//! cargo run --release --bin tradeoff -- --quick  # a smaller run, to try it out
//! cargo run --release --bin tradeoff -- --replot # rewrites tradeoff.md and tradeoff.svg from
//!                                                # docs/src/tradeoff.json, measuring nothing
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
//! The outputs are pages of the mdBook in docs/src/: the raw results `tradeoff.json`, the
//! report `tradeoff.md` and its plot `tradeoff.svg`. The report and the plot are written from
//! the JSON alone (the measuring run writes the JSON, reads it back and writes them from that),
//! so `--replot` gives the same bytes, and a test re-plots the committed JSON and compares.
//!
//! | module | topic |
//! |---|---|
//! | [`settings`] | the scenes and the render settings measured |
//! | [`measure`] | timed renders (median of runs), hit masks, the references, the machine's load |
//! | [`worker`] | the worker of each precision, the f32 build, the files they leave |
//! | [`shapes`] | ns per ray–shape test |
//! | [`metrics`] | error against the reference; the rows of results |
//! | [`planet`] | a huge sphere seen from close by: errors, acne, fixes, and its section of the report |
//! | [`results`] | the raw results as JSON: docs/src/tradeoff.json |
//! | [`finite`] | serde for numbers that may be NaN or ∞ (written as `null`) |
//! | [`front`] | the faster-and-more-accurate (Pareto) front of time against error |
//! | [`report`] | docs/src/tradeoff.md |
//! | [`plot`] | docs/src/tradeoff.svg |

#![deny(missing_docs)]

mod finite;
mod front;
mod measure;
mod metrics;
mod planet;
mod plot;
mod report;
mod results;
mod settings;
mod shapes;
mod worker;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use whitted::real::PRECISION;

/// Measures the speed–accuracy trade of whitted's accuracy switches and writes the raw
/// results (JSON), a Markdown report and an SVG plot under docs/src/.
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
    /// Where to write tradeoff.json, tradeoff.md and tradeoff.svg.
    #[arg(long, default_value = "docs/src")]
    out: PathBuf,
    /// Measure nothing: read tradeoff.json in the --out directory and write tradeoff.md and
    /// tradeoff.svg again from it.
    #[arg(long)]
    replot: bool,
    /// Internal: render every setting at this build's precision into DIR and exit.
    #[arg(long, value_name = "DIR", hide = true)]
    worker: Option<PathBuf>,
}

impl Args {
    /// What each worker renders.
    fn run(&self) -> worker::Run {
        worker::Run {
            width: self.width,
            height: self.height,
            runs: self.runs,
        }
    }
}

fn main() -> ExitCode {
    let mut args = Args::parse();
    if args.quick {
        (args.width, args.height, args.runs, args.reference_samples) = (80, 60, 3, 16);
    }
    if let Some(dir) = &args.worker {
        return match worker::worker(dir, &args.run()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::from(2)
            }
        };
    }
    let done = if args.replot {
        replot(&args.out, &args.out)
    } else {
        coordinate(&args)
    };
    match done {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// The whole measurement, from the f64 build: run both workers, render the references,
/// compare, write the raw results, and from them the report (with the workers' planet
/// measurements) and the plot.
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
    worker::run_worker(&this, &dirs[0].1, &args.run())?;
    worker::run_worker(&f32_exe, &dirs[1].1, &args.run())?;

    eprintln!("rendering the references …");
    let n = (args.width * args.height) as usize;
    let references = measure::references(args.width, args.height, args.reference_samples);
    let rows = metrics::rows(&dirs, &references, n)?;
    let load_after = measure::load_average();
    let shapes = worker::read_shape_timings(&dirs)?;
    let planet = results::PlanetLines {
        f64: planet::Measured::lines(&dirs[0].1)?,
        f32: planet::Measured::lines(&dirs[1].1)?,
    };
    let machine = results::Machine {
        cores: std::thread::available_parallelism().map_or(1, |n| n.get()),
        load_before,
        load_after,
    };
    let results = results::Results::new(
        (args.width, args.height, args.runs, args.reference_samples),
        started.elapsed().as_secs_f64(),
        machine,
        rows,
        shapes,
        planet,
    );
    std::fs::create_dir_all(&args.out).map_err(|e| e.to_string())?;
    let json_path = args.out.join(JSON);
    let json = results.to_json()?;
    whitted::output::write_file(&json_path, json.as_bytes()).map_err(|e| e.to_string())?;
    // the report and the plot from the JSON as written, exactly as --replot makes them
    let results = results::Results::from_json(&json)?;
    write_pages(&results, &args.out)?;
    eprintln!(
        "wrote {}, {} and {} in {:.0} s",
        json_path.display(),
        args.out.join(MARKDOWN).display(),
        args.out.join(SVG).display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// The file names of the raw results, the report and the plot.
const JSON: &str = "tradeoff.json";
const MARKDOWN: &str = "tradeoff.md";
const SVG: &str = "tradeoff.svg";

/// The report and the plot, from the results, into `out`.
fn write_pages(results: &results::Results, out: &Path) -> Result<(), String> {
    let md = report::report(results)?;
    whitted::output::write_file(&out.join(MARKDOWN), md.as_bytes()).map_err(|e| e.to_string())?;
    let svg = plot::svg(results)?;
    whitted::output::write_file(&out.join(SVG), svg.as_bytes()).map_err(|e| e.to_string())
}

/// `--replot`: reads `from`/tradeoff.json and writes the report and the plot into `to`.
fn replot(from: &Path, to: &Path) -> Result<(), String> {
    let results = results::Results::read(&from.join(JSON))?;
    std::fs::create_dir_all(to).map_err(|e| e.to_string())?;
    write_pages(&results, to)?;
    eprintln!(
        "wrote {} and {} from {}",
        to.join(MARKDOWN).display(),
        to.join(SVG).display(),
        from.join(JSON).display()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    /// The committed pages: docs/src/ of this repository.
    fn committed() -> &'static Path {
        Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/src"))
    }

    /// The figures cannot drift: re-plotting the committed JSON gives the committed SVG and
    /// Markdown byte for byte (rerun `cargo run --release --bin tradeoff -- --replot` after
    /// changing the plot or the report's code, and commit what it writes).
    /// The page is part of an mdBook with KaTeX on: a `$` in its text must be escaped.
    #[test]
    fn the_committed_page_has_no_bare_dollar() {
        let md = std::fs::read_to_string(committed().join(super::MARKDOWN)).unwrap();
        for (i, line) in md.lines().enumerate() {
            let bare = line
                .char_indices()
                .filter(|&(k, c)| c == '$' && !line[..k].ends_with('\\'))
                .count();
            assert_eq!(bare, 0, "line {} has a `$` without `\\`: {line}", i + 1);
        }
    }

    #[test]
    fn replot_of_the_committed_json_gives_the_committed_svg_and_markdown() {
        let tmp = tempfile::tempdir().unwrap();
        super::replot(committed(), tmp.path()).unwrap();
        for name in [super::SVG, super::MARKDOWN] {
            let fresh = std::fs::read(tmp.path().join(name)).unwrap();
            let kept = std::fs::read(committed().join(name)).unwrap();
            assert!(
                fresh == kept,
                "docs/src/{name} is not what `cargo run --release --bin tradeoff -- --replot` \
                 writes from docs/src/tradeoff.json: rerun it and commit the result"
            );
        }
    }
}
