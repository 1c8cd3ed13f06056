//! `whitted` — the course tools: the formula functions of the notes (the exercises), a
//! student's handout, the student's loop, grading and the course book. This file is the
//! command line and nothing else: each command is a function of the library.
//!
//! ```text
//! whitted formulas [list]                           the manifest, by chapter, with file:line
//! whitted formulas prove [--only PATH]... [--keep] [--features f32]
//!                                                   poison each function, run the render paths
//! whitted formulas deps [--write]                   which tests need which exercise (the map)
//! whitted formulas readmes                          each chapter README's exercises
//! whitted handout --out DIR [--chapters 1-3 | --exercises NAME,2.4]
//!                                                   a student's copy, the exercises as todo!()
//! whitted learn [list | hint [EXERCISE] | watch]    progress, the next exercise, hints, rerun on save
//! whitted grade [DIR] [--chapter N] [--hidden DIR] [--json F] [--junit F] [--csv F]
//!                                                   a student's copy graded with the instructor's tests
//! whitted grade --class DIR --out REPORTS           every submission of a class
//! whitted autograder --platform P --out DIR         a grading platform's package (gradescope,
//!                                                   classroom, prairielearn, codegrade)
//! whitted autograder grade|prebuild|check           what those packages run
//! whitted figures [--check]                         the book's figures, rendered or compared
//! whitted trees [--check]                           the reference's ray trees and the known
//!                                                   mistakes, written or compared
//! whitted book                                      the book, built and checked
//! ```
//!
//! Exit status: 0 when everything asked for is fine, 1 when some function is not proven (or
//! the map, a figure or the book is out of date), 2 on an error (a bad manifest, a function
//! not found, a build that fails …), printed as one line `error: …`.

#![deny(missing_docs)]

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use clap::{Parser, Subcommand};
use whitted_course::autograder::{self, Platform};
use whitted_course::cli::{find_root, read_manifest};
use whitted_course::grade::command::{Class, Reports};
use whitted_course::grade::sandbox::Level as SandboxLevel;
use whitted_course::prove::PoisonedRuns;
use whitted_course::{ToolError, book, figures, formulas, grade, handout, syllabus, trees};

/// The course tools of whitted, the toolkit for learning classic ray tracing.
#[derive(Parser)]
#[command(name = "whitted", version)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// The functions that compute the course notes' formulas (chapters/formulas.toml).
    ///
    /// `list` (the default) lists them by chapter, each with its file:line; `prove` shows that
    /// each one is on every render path of its chapter (in a copy of the project, one function
    /// at a time is made to panic, "poisoned", and every test of tests/render_paths.rs for its
    /// chapter must then fail); `deps` measures which tests need which exercise; `readmes`
    /// writes the chapter READMEs' exercises. Exit status: 0 fine, 1 something is not
    /// (unproven, out of date), 2 on an error.
    Formulas(FormulasArgs),
    /// Writes a student's copy of the project, with exercises taken out.
    ///
    /// Each chosen exercise's reference body (between `// BEGIN SOLUTION NAME` and
    /// `// END SOLUTION` in src/) becomes `todo!("exercise NAME (ID): … — see chapters/…/README.md")`;
    /// the others keep their reference code. Of tests/, only the targets of the manifest's
    /// [handout] tests go along; .ci/ stays behind. Without --chapters or --exercises, every
    /// exercise is taken out. DIR must not exist (or be empty).
    Handout(HandoutArgs),
    /// The student's loop: progress, the next exercise and its failing test, hints.
    ///
    /// Runs the exercise tests (`cargo test` on the manifest's [handout] tests) and shows, per
    /// chapter, how many exercises pass, then the next one to write with its first failing
    /// test, the formula it checks and the notes' section. Colour only on a terminal, and not
    /// with NO_COLOR set.
    Learn(whitted_course::cli::LearnArgs),
    /// Grades a student's copy (DIR, default the current project) with this project's tests.
    ///
    /// Only the student's exercise bodies (between `// BEGIN SOLUTION NAME` and `// END
    /// SOLUTION` in DIR's src/) are taken; they go into a fresh copy of this project, so the
    /// tests, the manifest and the code around the exercises are the instructor's. A body that
    /// does not compile is graded as not written, and the others still count; so is a body
    /// that names what a formula never needs (ending or starting a process, files, the network,
    /// the environment, `unsafe`, `macro_rules!`, the compile-time readers), which is never
    /// compiled. Each test runs in its own process under --timeout (cargo-nextest), so a panic,
    /// a stack overflow or an endless loop costs only its own tests, and passes only when
    /// libtest reported it `ok`: a process that ends early passes nothing. An exercise's points
    /// (chapters/formulas.toml) are shared by its tests. Exit status 0 once graded, whatever
    /// the score; 2 on an error.
    Grade(GradeArgs),
    /// Writes what a grading platform takes (Gradescope's zip, PrairieLearn's image and entry
    /// point, CodeGrade's scripts, GitHub Classroom's workflow) into --out; its subcommands are
    /// what those packages run.
    Autograder(AutograderArgs),
    /// Runs a test binary in the grader's sandbox: nextest's target runner while grading.
    #[command(name = "sandbox-run", hide = true)]
    SandboxRun {
        /// The test binary and its arguments.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true, required = true)]
        command: Vec<std::ffi::OsString>,
    },
    /// Renders the course book's figures (docs/figures.toml), or checks them with --check.
    ///
    /// Each figure is `BINARY ARGS -o docs/src/figures/FILE`, run from the project's root
    /// with the chapter binaries built next to this one (target/debug or target/release).
    /// With --check, each is rendered to a temporary directory and compared with the
    /// committed PNG: a channel may differ by at most 1/255. Exit status: 0 all written or all
    /// the same, 1 some differ, 2 on an error.
    Figures(FiguresArgs),
    /// Writes the reference's ray trees at a few pixels of each chapter scene
    /// (chapters/chNN_name/trees.json) and the known mistakes' fingerprints
    /// (chapters/mistakes.json), or checks the trees with --check.
    ///
    /// The pixels are chosen so that their trees show every object and part, each light lit
    /// and shadowed, every kind of branch and stop, and every hand-written mutant of
    /// crates/whitted-course/tests/mutants/hand-written.toml (built once, each behind a switch,
    /// into target/mistakes). With --check, the committed pixels are traced again by the
    /// chapter binaries built next to this one and compared. Exit status: 0 written or the same,
    /// 1 some differ, 2 on an error.
    Trees(TreesArgs),
    /// Builds the course book (docs/, mdBook with mdbook-katex) and checks it.
    ///
    /// Before the build, every {{#include file:anchor}} must give something; during it,
    /// mdBook and mdbook-katex must log no warning or error (a formula KaTeX cannot parse is
    /// only logged by them); after it, every internal link and image must resolve, nothing
    /// may load from the network, and each chapter page must show typeset math and a figure.
    /// The book is written to docs/book (open docs/book/index.html). Exit status: 0 clean,
    /// 1 problems found (each printed as file:line: …), 2 on an error (mdbook missing …).
    Book(BookArgs),
}

#[derive(clap::Args)]
struct FiguresArgs {
    /// Compare fresh renders with the committed figures instead of writing them.
    #[arg(long)]
    check: bool,
    /// Only the figures whose file names contain this text.
    #[arg(long, value_name = "TEXT")]
    only: Option<String>,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct TreesArgs {
    /// Compare the committed trees with the reference's instead of writing them.
    #[arg(long)]
    check: bool,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct BookArgs {
    /// The mdbook program to run.
    #[arg(long, value_name = "PATH", default_value = "mdbook")]
    mdbook: PathBuf,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct GradeArgs {
    /// The student's copy of the project [default: the current project].
    #[arg(value_name = "DIR", conflicts_with = "class")]
    submission: Option<PathBuf>,
    /// Grade only this chapter's exercises (1-5).
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u8).range(i64::from(syllabus::FIRST)..=i64::from(syllabus::LAST)))]
    chapter: Option<u8>,
    /// The instructor's hidden tests: a directory of .rs test files, each added as a test
    /// target; their tests are named after the exercise they check (ex_NAME_…), like the public
    /// ones. Students' reports show their points, not their names.
    #[arg(long, value_name = "DIR")]
    hidden: Option<PathBuf>,
    /// Write Gradescope's results.json here.
    #[arg(long, value_name = "FILE")]
    json: Option<PathBuf>,
    /// Write a JUnit XML report here.
    #[arg(long, value_name = "FILE")]
    junit: Option<PathBuf>,
    /// Write the gradebook's header and this submission's row here (CSV).
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
    /// The time limit of one test, in seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 20,
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    timeout: u64,
    /// Grade every submission of a class: each subdirectory of DIR.
    #[arg(long, value_name = "DIR", requires = "out")]
    class: Option<PathBuf>,
    /// With --class: where the reports go (one directory per student, and class.csv).
    #[arg(long, value_name = "DIR", requires = "class")]
    out: Option<PathBuf>,
    /// With --class: submissions graded at a time [default: the cores].
    #[arg(long, value_name = "N", requires = "class",
          value_parser = clap::value_parser!(u64).range(1..=64))]
    jobs: Option<u64>,
    /// Where cargo builds, kept between gradings so the dependencies are built once (a class
    /// gives each of its --jobs its own directory in it) [default: target/grade in the
    /// instructor's project].
    #[arg(long, value_name = "DIR")]
    target_dir: Option<PathBuf>,
    /// Keep each graded copy (its path is printed).
    #[arg(long)]
    keep: bool,
    /// Leave out the feedback of each chapter that lost points (its picture beside the book's
    /// figure, and the first wrong number of its ray trees): a faster grading, reports of the
    /// tests alone.
    #[arg(long)]
    no_feedback: bool,
    #[command(flatten)]
    sandbox: SandboxArgs,
    /// The instructor's project, whose tests and manifest grade [default: the nearest
    /// Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true)]
struct AutograderArgs {
    #[command(subcommand)]
    what: Option<AutograderCommand>,
    /// The platform.
    #[arg(long, value_enum, required = true)]
    platform: Option<Platform>,
    /// The directory to write the package into.
    #[arg(long, value_name = "DIR", required = true)]
    out: Option<PathBuf>,
    #[command(flatten)]
    grading: PackageGrading,
    /// The sandbox of the package's gradings (`--sandbox user` for a platform whose
    /// container makes no namespace: its setup.sh closes the project to other users).
    #[command(flatten)]
    sandbox: SandboxArgs,
    /// The instructor's project [default: the nearest Cargo.toml at or above the current
    /// directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

/// How a package grades: the same for the package and for each grading it runs.
#[derive(clap::Args, Clone)]
struct PackageGrading {
    /// The instructor's hidden tests: a directory of .rs test files.
    #[arg(long, value_name = "DIR")]
    hidden: Option<PathBuf>,
    /// Grade only this chapter's exercises (1-5).
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u8).range(i64::from(syllabus::FIRST)..=i64::from(syllabus::LAST)))]
    chapter: Option<u8>,
    /// The time limit of one test, in seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 20,
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    timeout: u64,
    /// When students see the hidden tests' points (Gradescope's visibility).
    #[arg(long, value_name = "WHEN", default_value = "after_due_date",
          value_parser = ["hidden", "after_due_date", "after_published", "visible"])]
    hidden_visibility: String,
    /// Post the leaderboard: the render's M rays/s and its error against the reference.
    #[arg(long)]
    leaderboard: bool,
}

impl PackageGrading {
    fn settings(&self) -> autograder::Settings {
        autograder::Settings {
            hidden_visibility: self.hidden_visibility.clone(),
            leaderboard: self.leaderboard,
        }
    }
}

#[derive(Subcommand)]
enum AutograderCommand {
    /// Grades one submission for a platform and writes its results file, always: a
    /// submission that cannot be graded gets one that says why.
    Grade {
        /// The platform whose results file is written.
        #[arg(long, value_enum)]
        platform: Platform,
        /// What the platform handed over: a copy of the handout, a folder holding one, or
        /// the exercise files uploaded one by one.
        #[arg(long, value_name = "DIR")]
        submission: PathBuf,
        /// Where the results go.
        #[arg(long, value_name = "FILE")]
        results: PathBuf,
        #[command(flatten)]
        grading: PackageGrading,
        #[command(flatten)]
        build: PackageBuild,
    },
    /// Builds once, in --target-dir, what every grading reuses (a handout whose every
    /// exercise is todo!(), built and run in the sandbox).
    Prebuild {
        #[command(flatten)]
        grading: PackageGrading,
        #[command(flatten)]
        build: PackageBuild,
    },
    /// Exit status 0 when the exercise (its name or id) got all its points in a
    /// results.json written for Gradescope or Classroom, 1 when not.
    Check {
        /// The results file.
        #[arg(long, value_name = "FILE")]
        results: PathBuf,
        /// The exercise.
        #[arg(long, value_name = "NAME")]
        exercise: String,
    },
}

/// Where a package's gradings build, and from which project.
#[derive(clap::Args, Clone)]
struct PackageBuild {
    /// The instructor's project [default: the nearest Cargo.toml at or above the current
    /// directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
    /// Where cargo builds, kept from one grading to the next [default: target/grade in the
    /// project].
    #[arg(long, value_name = "DIR")]
    target_dir: Option<PathBuf>,
    #[command(flatten)]
    sandbox: SandboxArgs,
}

/// The sandbox of a grading.
#[derive(clap::Args, Clone, Copy)]
struct SandboxArgs {
    /// The sandbox: bubblewrap's namespaces, or (as root, where no namespace can be made)
    /// the tests as a user of their own with limits, the project closed to other users.
    #[arg(long, value_enum, value_name = "LEVEL", default_value = "namespaces")]
    sandbox: SandboxLevel,
    /// Build and run the student's code without any sandbox, with this program's rights:
    /// only for work you trust.
    #[arg(long, conflicts_with = "sandbox")]
    unsandboxed: bool,
}

impl SandboxArgs {
    /// The level asked for; `None` unsandboxed.
    fn level(self) -> Option<SandboxLevel> {
        (!self.unsandboxed).then_some(self.sandbox)
    }
}

#[derive(clap::Args)]
struct HandoutArgs {
    /// The directory to write the student's copy into (it must not exist, or be empty).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Take out the exercises of these chapters only: 4, or a range such as 1-3.
    #[arg(long, value_name = "N|A-B", value_parser = whitted_course::handout::parse_chapters,
          conflicts_with = "exercises")]
    chapters: Option<(u8, u8)>,
    /// Take out these exercises only, by name or id (comma-separated): sphere_coefficients,2.7.
    #[arg(long, value_name = "IDS", value_delimiter = ',')]
    exercises: Vec<String>,
    /// The project to copy [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

#[derive(clap::Args)]
struct FormulasArgs {
    #[command(subcommand)]
    /// What to do with the functions [default: list them].
    what: Option<FormulasCommand>,
    /// The project's root (the directory of Cargo.toml) [default: the nearest one at or
    /// above the current directory].
    #[arg(long, value_name = "DIR", global = true)]
    root: Option<PathBuf>,
}

#[derive(Subcommand)]
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

fn main() -> ExitCode {
    let args: Args = whitted_course::args::parse_args();
    let result = match args.command {
        Command::Formulas(f) => run_formulas(&f),
        Command::Handout(h) => run_handout(&h),
        Command::Learn(l) => whitted_course::cli::learn(&l),
        Command::Grade(g) => run_grade(&g),
        Command::Autograder(a) => run_autograder(a),
        Command::SandboxRun { command } => return grade::runner::run_test(&command),
        Command::Figures(f) => project(f.root.as_ref())
            .and_then(|root| figures::command(&root, f.check, f.only.as_deref())),
        Command::Trees(t) => project(t.root.as_ref()).and_then(|root| {
            let manifest = read_manifest(&root)?;
            trees::command(&root, &manifest, t.check)
        }),
        Command::Book(b) => {
            project(b.root.as_ref()).and_then(|root| book::command(&root, &b.mdbook))
        }
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

fn run_autograder(args: AutograderArgs) -> Result<ExitCode, ToolError> {
    let setup = |grading: &PackageGrading, build: &PackageBuild| -> Result<_, ToolError> {
        let root = project(build.root.as_ref())?;
        let manifest = read_manifest(&root)?;
        let target = build
            .target_dir
            .clone()
            .unwrap_or_else(|| root.join("target").join("grade"));
        let setup = autograder::run::setup(
            grading.chapter,
            grading.hidden.clone(),
            grading.timeout,
            target,
            sandbox_setup(build.sandbox.level())?,
            grading.leaderboard,
        );
        Ok((root, manifest, setup))
    };
    match args.what {
        Some(AutograderCommand::Grade {
            platform,
            submission,
            results,
            grading,
            build,
        }) => {
            let (root, manifest, setup) = setup(&grading, &build)?;
            let s = autograder::run::Submission {
                platform,
                dir: &submission,
                results: &results,
                settings: grading.settings(),
            };
            autograder::run::grade_submission(&root, &manifest, &setup, &s)?;
            Ok(ExitCode::SUCCESS)
        }
        Some(AutograderCommand::Prebuild { grading, build }) => {
            let (root, manifest, setup) = setup(&grading, &build)?;
            autograder::run::prebuild(&root, &manifest, &setup)
        }
        Some(AutograderCommand::Check { results, exercise }) => {
            autograder::run::check(&results, &exercise)
        }
        None => {
            let (Some(platform), Some(out)) = (args.platform, args.out) else {
                return Err(ToolError::Usage(
                    "whitted autograder needs --platform and --out".into(),
                ));
            };
            let root = project(args.root.as_ref())?;
            let manifest = read_manifest(&root)?;
            let options = autograder::package::Options {
                chapter: args.grading.chapter,
                hidden: args.grading.hidden.clone(),
                timeout: args.grading.timeout,
                settings: args.grading.settings(),
                sandbox: args.sandbox.level(),
            };
            if let Some(h) = &options.hidden
                && !h.is_dir()
            {
                return Err(ToolError::Usage(format!(
                    "--hidden {}: not a directory",
                    h.display()
                )));
            }
            let written = autograder::package::write(&root, &manifest, platform, &options, &out)?;
            println!(
                "{} package in {}: {}",
                platform.name(),
                out.display(),
                written
                    .iter()
                    .map(|p| p.display().to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            );
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// The sandbox of a grading at `level` (none when `None`, `--unsandboxed`): this program runs
/// each test binary, sandboxed or not, and passes a test only when libtest reported it `ok`.
fn sandbox_setup(level: Option<SandboxLevel>) -> Result<Option<grade::SandboxSetup>, ToolError> {
    let level = level.unwrap_or(SandboxLevel::Off);
    let runner = std::env::current_exe()
        .map_err(|e| ToolError::Usage(format!("cannot find this program's path: {e}")))?;
    Ok(Some(grade::SandboxSetup {
        runner,
        worker: 0,
        level,
    }))
}

/// The project: `--root DIR`, or the nearest one at or above the current directory.
fn project(root: Option<&PathBuf>) -> Result<PathBuf, ToolError> {
    root.map_or_else(find_root, |r| Ok(r.clone()))
}

fn run_formulas(args: &FormulasArgs) -> Result<ExitCode, ToolError> {
    let root = project(args.root.as_ref())?;
    let manifest = read_manifest(&root)?;
    match &args.what {
        None | Some(FormulasCommand::List) => formulas::list(&root, &manifest),
        Some(FormulasCommand::Prove { only, runs }) => {
            formulas::prove(&root, &manifest, &runs.runs(only))
        }
        Some(FormulasCommand::Deps { write, runs }) => {
            formulas::deps(&root, &manifest, &runs.runs(&[]), *write)
        }
        Some(FormulasCommand::Readmes) => formulas::readmes(&root, &manifest),
    }
}

fn run_handout(args: &HandoutArgs) -> Result<ExitCode, ToolError> {
    let root = project(args.root.as_ref())?;
    let manifest = read_manifest(&root)?;
    handout::command(&root, &manifest, args.chapters, &args.exercises, &args.out)
}

fn run_grade(args: &GradeArgs) -> Result<ExitCode, ToolError> {
    let root = project(args.root.as_ref())?;
    let manifest = read_manifest(&root)?;
    let setup = grade::GradeSetup {
        chapter: args.chapter,
        hidden: args.hidden.clone(),
        timeout: Duration::from_secs(args.timeout),
        // kept between gradings: the dependencies are built once
        target_dir: Some(
            args.target_dir
                .clone()
                .unwrap_or_else(|| root.join("target").join("grade")),
        ),
        keep: args.keep,
        sandbox: sandbox_setup(args.sandbox.level())?,
        render: false,
        feedback: !args.no_feedback,
        screen: true,
    };
    let class = match (&args.class, &args.out) {
        (Some(dir), Some(out)) => Some(Class {
            dir,
            out,
            jobs: args.jobs.map(|j| j as usize),
        }),
        _ => None,
    };
    let reports = Reports {
        json: args.json.as_deref(),
        junit: args.junit.as_deref(),
        csv: args.csv.as_deref(),
    };
    grade::command::command(
        &root,
        &manifest,
        &setup,
        args.submission.as_deref(),
        class,
        reports,
    )
}
