//! The plain run of a chapter binary: render the image and write it as a PNG. With
//! `--compare REF.png` the PNG holds the render, the reference and their difference side by
//! side and stdout gets the line that says how they differ; with `--against TREES.json` the
//! reference's trees are traced after the render. Unless `--quiet`, stderr gets what was
//! written and the statistics lines.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::io::IsTerminal;
use std::path::Path;
use std::time::Instant;

use whitted::error::Error;
use whitted::output;
use whitted::render::inspect::against::TreeFile;
use whitted::render::{self, Options};
use whitted::scene::Scene;

use super::against::print_against;
use super::parse::ChapterArgs;
use super::progress::Progress;
use super::reference::Reference;
use super::stats::{summary, work_line};
use super::stdout::print_out;

/// Renders `scene` with `options` and writes the PNG to `out` (the comparison with
/// `--compare`'s reference instead, if one is given), then traces `trees` if `--against`
/// gave them. The sizes are checked before any rendering starts.
pub fn render(
    scene: &Scene,
    options: &Options,
    out: &Path,
    args: &ChapterArgs,
    against: Option<&TreeFile>,
) -> Result<(), Error> {
    let common = &args.common;
    let reference = Reference::of(common.compare.as_deref())?;
    render::check_size(options.width, options.height)?;
    if let Some(r) = &reference {
        r.check(out, (options.width, options.height))?;
    }
    let start = Instant::now();
    let accel = render::build_accel(scene, options);
    let progress = Progress::new(
        u64::from(options.width) * u64::from(options.height),
        !common.quiet && std::io::stderr().is_terminal(),
    );
    let (fb, stats) = render::render_with(scene, options, &accel, &|n| progress.advance(n));
    progress.finish();
    let seconds = start.elapsed().as_secs_f64();
    match &reference {
        None => output::save(&fb, out, common.encoding)?,
        Some(r) => {
            let line = r.write_comparison(&fb, common.encoding, out)?;
            print_out(&format!("{line}\n"))?;
        }
    }
    let traced = match against {
        Some(trees) => Some(print_against(scene, options, trees, common)?),
        None => None,
    };
    if !common.quiet {
        match &reference {
            None => eprintln!("wrote {} ({}×{})", out.display(), fb.width, fb.height),
            Some(r) => eprintln!(
                "wrote {}: your render, {} and the difference, {}×{} each",
                out.display(),
                r.path.display(),
                fb.width,
                fb.height
            ),
        }
        if args.tracing.as_ref().is_some_and(|t| t.stats) {
            eprintln!(
                "{} sample(s)/px, depth {}, {} thread(s), {} mirror rays by total internal reflection; {}",
                options.samples,
                options.max_depth,
                rayon::current_num_threads(),
                stats.total_internal,
                accel.describe()
            );
            if whitted::accel::counters::ENABLED {
                eprintln!("{}", work_line(&stats.work));
            }
        }
        eprintln!("{}", summary(fb.width, fb.height, &stats, seconds));
        if let Some((pixels, seconds)) = traced {
            eprintln!("traced {pixels} pixels' trees against the reference's in {seconds:.3} s");
        }
    }
    Ok(())
}
