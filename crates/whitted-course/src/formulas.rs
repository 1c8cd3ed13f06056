//! `whitted formulas`: the formula functions of the manifest, and what the tools do with them.
//!
//! ```text
//! whitted formulas [list]         each function by chapter, with its file:line, formula, section
//! whitted formulas prove          every function is on every render path of its chapter
//! whitted formulas deps [--write] which tests need which exercise, checked against (or written
//!                                 to) chapters/exercise-tests.toml
//! whitted formulas readmes        each chapter README's exercises, written from the manifest
//! ```
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use crate::manifest::Manifest;
use crate::prove::PoisonedRuns;
use crate::{ToolError, deps, syllabus};

/// `whitted formulas list`: prints the manifest by chapter: function, file:line, formula,
/// section.
pub fn list(root: &Path, manifest: &Manifest) -> Result<ExitCode, ToolError> {
    let locations = crate::source::locate_all(root, manifest)?;
    let places: Vec<String> = locations
        .iter()
        .map(|l| format!("{}:{}", l.file.display(), l.line))
        .collect();
    let fn_width = manifest
        .entries
        .iter()
        .map(|e| e.function.chars().count())
        .max()
        .unwrap_or(0);
    let at_width = places.iter().map(|p| p.chars().count()).max().unwrap_or(0);
    for chapter in &syllabus::CHAPTERS {
        let (number, title) = (chapter.number, chapter.title);
        let entries: Vec<usize> = (0..manifest.entries.len())
            .filter(|&i| manifest.entries[i].chapter == number)
            .collect();
        if entries.is_empty() {
            continue;
        }
        println!("chapter {number} — {title}");
        for i in entries {
            let e = &manifest.entries[i];
            println!(
                "  {:<fn_width$}  {:<at_width$}  {}   ({})",
                e.function, places[i], e.formula, e.section
            );
        }
    }
    println!(
        "{} formula functions in {}; `whitted formulas prove` shows they are on every render path",
        manifest.entries.len(),
        manifest.file
    );

    Ok(ExitCode::SUCCESS)
}

/// `whitted formulas prove`: the proof, its table on stdout; status 1 when a function is not
/// proven.
pub fn prove(root: &Path, manifest: &Manifest, runs: &PoisonedRuns) -> Result<ExitCode, ToolError> {
    let report = crate::prove::prove(root, manifest, runs)?;
    eprintln!(
        "proof: build {:.1} s, test runs {:.1} s",
        report.build_time.as_secs_f64(),
        report.run_time.as_secs_f64()
    );
    if let Some(kept) = &report.kept {
        eprintln!(
            "proof: the poisoned copy and the runs' output are kept in {}",
            kept.display()
        );
    }
    let mut out = std::io::stdout().lock();
    report
        .write_table(manifest, &mut out)
        .map_err(|e| ToolError::io("stdout", e))?;
    Ok(if report.proven() == report.rows.len() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// `whitted formulas deps [--write]`: the measured dependencies, checked against the map
/// (status 1 when it is out of date), or written to it.
pub fn deps(
    root: &Path,
    manifest: &Manifest,
    runs: &PoisonedRuns,
    write: bool,
) -> Result<ExitCode, ToolError> {
    let measured = deps::measure(root, manifest, runs)?;
    for (e, failing) in manifest.entries.iter().zip(&measured.failing) {
        println!(
            "{:<5} {:<22} {:<44} {:>3} of {} tests fail without it",
            e.exercise.id,
            e.exercise.name,
            e.function,
            failing.len(),
            measured.tests.len()
        );
    }
    if write {
        let path = root.join(deps::MAP_PATH);
        crate::files::write_file(&path, deps::map_text(manifest, &measured).as_bytes())?;
        println!("wrote {}", deps::MAP_PATH);
        return Ok(ExitCode::SUCCESS);
    }
    let map = deps::load_map(root, manifest)?;
    let problems = deps::check(manifest, &map, &measured);
    if problems.is_empty() {
        println!(
            "{} says what the {} tests measure",
            deps::MAP_PATH,
            measured.tests.len()
        );
        return Ok(ExitCode::SUCCESS);
    }
    for p in &problems {
        println!("{p}");
    }
    println!(
        "\n{} is out of date: `cargo run --release --bin whitted -- formulas deps --write` rewrites it",
        deps::MAP_PATH
    );
    Ok(ExitCode::from(1))
}

/// `whitted formulas readmes`: rewrites the exercises section of each chapter's README.
pub fn readmes(root: &Path, manifest: &Manifest) -> Result<ExitCode, ToolError> {
    let changed = crate::readme::write_all(root, manifest)?;
    println!(
        "{}",
        if changed.is_empty() {
            "the chapter READMEs' exercises are current".to_string()
        } else {
            format!("rewrote the exercises of {}", changed.join(", "))
        }
    );
    Ok(ExitCode::SUCCESS)
}

/// The arguments of `whitted formulas`.
#[derive(clap::Args)]
pub struct FormulasArgs {
    #[command(subcommand)]
    /// What to do with the functions [default: list them].
    what: Option<FormulasCommand>,
    /// The project's root (the directory of Cargo.toml) [default: the nearest one at or
    /// above the current directory].
    #[arg(long, value_name = "DIR", global = true)]
    root: Option<PathBuf>,
}

#[derive(clap::Subcommand)]
enum FormulasCommand {
    /// Lists the functions by chapter, each with its file:line, the formula and the notes'
    /// section.
    List,
    /// Proves that each function is on every render path of its chapter: in a copy of the
    /// project built once (into target/prove), the render paths must pass unpoisoned, then
    /// fail with each function of their chapter poisoned in turn. Exit status 1 when some
    /// function is not proven.
    Prove {
        /// Prove only this function (a path as in the manifest, e.g. camera::viewing_basis);
        /// may be repeated.
        #[arg(long, value_name = "PATH")]
        only: Vec<String>,
        #[command(flatten)]
        runs: RunsArgs,
    },
    /// Measures which tests of a handout need which exercise (each poisoned in turn, the
    /// manifest's [handout] tests run) and checks chapters/exercise-tests.toml against it.
    /// Exit status 1 when it is out of date.
    Deps {
        /// Write chapters/exercise-tests.toml from the measurements.
        #[arg(long)]
        write: bool,
        #[command(flatten)]
        runs: RunsArgs,
    },
    /// Rewrites the "## Exercises" section of each chapter's README from the manifest.
    Readmes,
}

/// How the poisoned copy of `prove` and `deps` is built and run.
#[derive(clap::Args)]
struct RunsArgs {
    /// Keep the temporary copy of the project and the test runs' output, for debugging; its
    /// path is printed.
    #[arg(long)]
    keep: bool,
    /// The time limit of one test run, in seconds: a poisoned function that makes a render
    /// loop forever counts as not proven instead of hanging the proof.
    #[arg(long, value_name = "SECONDS", default_value_t = 120,
          value_parser = clap::value_parser!(u64).range(1..=86_400))]
    timeout: u64,
    /// Cargo features to build the poisoned copy with, comma-separated (`--features f32`
    /// works in single precision).
    #[arg(long, value_name = "LIST", value_delimiter = ',')]
    features: Vec<String>,
}

impl RunsArgs {
    /// The runs asked for, of the functions `only` (all when empty).
    fn runs(&self, only: &[String]) -> PoisonedRuns {
        PoisonedRuns {
            only: only.to_vec(),
            keep: self.keep,
            timeout: Duration::from_secs(self.timeout),
            features: self.features.clone(),
            ..PoisonedRuns::default()
        }
    }
}

impl FormulasArgs {
    /// Runs `whitted formulas` as the arguments ask, on the project they name.
    pub fn run(&self) -> Result<ExitCode, ToolError> {
        let root = crate::project::root(self.root.as_ref())?;
        let manifest = crate::cli::read_manifest(&root)?;
        match &self.what {
            None | Some(FormulasCommand::List) => list(&root, &manifest),
            Some(FormulasCommand::Prove { only, runs }) => {
                prove(&root, &manifest, &runs.runs(only))
            }
            Some(FormulasCommand::Deps { write, runs }) => {
                deps(&root, &manifest, &runs.runs(&[]), *write)
            }
            Some(FormulasCommand::Readmes) => readmes(&root, &manifest),
        }
    }
}
