//! The command line of `whitted autograder`: the package a platform takes, and what that
//! package runs for each submission (`grade`, `prebuild`, `check`).
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::options::Options;
use super::run::{self, Submission};
use super::{Platform, Settings, package};
use crate::ToolError;
use crate::grade::{Chapters, GradeSetup, Judging, SandboxArgs};
use crate::manifest::Manifest;

/// The arguments of `whitted autograder`: a package's, or a subcommand's.
#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true)]
pub struct AutograderArgs {
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
    /// The handout the students were given (`whitted handout --chapters 4 --out DIR`): the
    /// package's manifest carries its list of the students' exercises, so only those are
    /// graded and counted, not the earlier chapters' code it gave them.
    #[arg(long, value_name = "DIR")]
    handout: Option<PathBuf>,
}

/// How a package grades: the same for the package and for each grading it runs.
#[derive(clap::Args, Clone)]
struct PackageGrading {
    /// The instructor's hidden tests: a directory of .rs test files.
    #[arg(long, value_name = "DIR")]
    hidden: Option<PathBuf>,
    /// Grade only these chapters' exercises: one (4) or a range (1-3), of chapters 1 to 5.
    #[arg(long, value_name = "N|A-B", value_parser = Chapters::parse)]
    chapter: Option<Chapters>,
    /// The limit of one test, in seconds of CPU time (the test and the student's process
    /// together), as `whitted grade --timeout`.
    #[arg(long, value_name = "SECONDS", default_value_t = 20,
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    timeout: u64,
    /// When students see the hidden tests' points (Gradescope's visibility).
    #[arg(long, value_name = "WHEN", default_value = "after_due_date",
          value_parser = ["hidden", "after_due_date", "after_published", "visible"])]
    hidden_visibility: String,
    /// Post the leaderboard: the render's speed (millions of the figure's pixels a second, on
    /// the grader's clock) and its share of pixels off the book's figure, as the grader
    /// compares them.
    #[arg(long)]
    leaderboard: bool,
    /// Judge every test with all of the student's bodies together, as `whitted grade
    /// --whole-road` does, instead of each exercise alone.
    #[arg(long)]
    whole_road: bool,
}

impl PackageGrading {
    /// How each exercise's tests are judged.
    fn judging(&self) -> Judging {
        if self.whole_road {
            Judging::WholeRoad
        } else {
            Judging::Alone
        }
    }

    /// How the results are shown.
    fn settings(&self) -> Settings {
        Settings {
            hidden_visibility: self.hidden_visibility.clone(),
            leaderboard: self.leaderboard,
        }
    }
}

#[derive(clap::Subcommand)]
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

impl AutograderArgs {
    /// Runs `whitted autograder` as the arguments ask: writes a package, or runs what a
    /// package runs.
    pub fn run(self) -> Result<ExitCode, ToolError> {
        match self.what {
            Some(AutograderCommand::Grade {
                platform,
                submission,
                results,
                grading,
                build,
            }) => {
                let (root, manifest, setup) = build.setup(&grading)?;
                let s = Submission {
                    platform,
                    dir: &submission,
                    results: &results,
                    settings: grading.settings(),
                };
                run::grade_submission(&root, &manifest, &setup, &s)?;
                Ok(ExitCode::SUCCESS)
            }
            Some(AutograderCommand::Prebuild { grading, build }) => {
                let (root, manifest, setup) = build.setup(&grading)?;
                run::prebuild(&root, &manifest, &setup)
            }
            Some(AutograderCommand::Check { results, exercise }) => run::check(&results, &exercise),
            None => {
                let (Some(platform), Some(out)) = (self.platform, self.out) else {
                    return Err(ToolError::Usage(
                        "whitted autograder needs --platform and --out".into(),
                    ));
                };
                let options = Options {
                    chapter: self.grading.chapter,
                    hidden: self.grading.hidden.clone(),
                    timeout: self.grading.timeout,
                    settings: self.grading.settings(),
                    sandbox: self.sandbox.level(),
                    judging: self.grading.judging(),
                    handout: self
                        .handout
                        .as_deref()
                        .map(crate::handout::later::listed_in)
                        .transpose()?,
                };
                write_package(self.root.as_ref(), platform, &options, &out)
            }
        }
    }
}

impl PackageBuild {
    /// The project, its manifest, and how each of the package's gradings (`grading`) is set
    /// up.
    fn setup(
        &self,
        grading: &PackageGrading,
    ) -> Result<(PathBuf, Manifest, GradeSetup), ToolError> {
        let root = crate::project::root(self.root.as_ref())?;
        let manifest = crate::cli::read_manifest(&root)?;
        let target = self
            .target_dir
            .clone()
            .unwrap_or_else(|| root.join("target").join("grade"));
        let setup = run::setup(
            grading.chapter,
            grading.hidden.clone(),
            grading.timeout,
            target,
            self.sandbox.setup()?,
            grading.leaderboard,
        );
        let setup = GradeSetup {
            judging: grading.judging(),
            ..setup
        };
        Ok((root, manifest, setup))
    }
}

/// Writes `platform`'s package of the project at `root` (`--root`, or the nearest) into
/// `out`, and says which files it wrote.
fn write_package(
    root: Option<&PathBuf>,
    platform: Platform,
    options: &Options,
    out: &Path,
) -> Result<ExitCode, ToolError> {
    let root = crate::project::root(root)?;
    let manifest = crate::cli::read_manifest(&root)?;
    if let Some(h) = &options.hidden
        && !h.is_dir()
    {
        return Err(ToolError::Usage(format!(
            "--hidden {}: not a directory",
            h.display()
        )));
    }
    let manifest = match &options.handout {
        Some(names) => crate::handout::later::listed_manifest(&root, names)?.1,
        None => manifest,
    };
    if options.chapter.is_none() && manifest.handout.exercises.is_none() {
        eprintln!(
            "note: the package grades every exercise of the manifest ({} of them, {} points); for a week's handout, --handout DIR grades only the exercises it gave the students to write, --chapter N a chapter's",
            manifest.entries.len(),
            manifest
                .entries
                .iter()
                .map(|e| e.exercise.points)
                .sum::<u32>()
        );
    }
    let written = package::write(&root, &manifest, platform, options, out)?;
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
