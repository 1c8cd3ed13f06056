//! The command line of `whitted grade`, and of the sandbox every grading command takes
//! (`--sandbox LEVEL`, `--unsandboxed`).
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use super::alone::Judging;
use super::claim::Claim;
use super::command::{Class, Reports, command};
use super::sandbox::Level;
use super::sandbox::watch::CompileLimits;
use super::setup::{Chapters, GradeSetup, SandboxSetup};
use crate::ToolError;

/// The arguments of `whitted grade`.
#[derive(clap::Args)]
pub struct GradeArgs {
    /// The student's copy of the project [default: the current project].
    #[arg(value_name = "DIR", conflicts_with = "class")]
    submission: Option<PathBuf>,
    /// Grade only these chapters' exercises: one (4) or a range (1-3), of chapters 1 to 5.
    #[arg(long, value_name = "N|A-B", value_parser = Chapters::parse)]
    chapter: Option<Chapters>,
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
    /// The limit of one test, in seconds of CPU time (the test and the student's process
    /// together; a test of no exercise gets three times as much): a busy machine makes a
    /// test slower, not costlier, so it fails no correct test. A test that waits without
    /// computing is stopped on the clock after twice this, longer on a busy machine.
    #[arg(long, value_name = "SECONDS", default_value_t = 20,
          value_parser = clap::value_parser!(u64).range(1..=3600))]
    timeout: u64,
    /// Grade every submission of a class: each subdirectory of DIR.
    #[arg(long, value_name = "DIR", requires = "out")]
    class: Option<PathBuf>,
    /// With --class: where the reports go (one directory per student, and class.csv).
    #[arg(long, value_name = "DIR", requires = "class")]
    out: Option<PathBuf>,
    /// With --class: a roster, lines `folder,id,email`, that fills the gradebook's id and
    /// e-mail columns (the folder is the submission's directory name).
    #[arg(long, value_name = "FILE", requires = "class")]
    roster: Option<PathBuf>,
    /// With --class: write class.csv anew. Without it, a regrade into an --out that holds a
    /// gradebook updates the rows of the submissions it grades and keeps the others.
    #[arg(long, requires = "class")]
    new_gradebook: bool,
    /// With --class: submissions graded at a time [default: the cores].
    #[arg(long, value_name = "N", requires = "class",
          value_parser = clap::value_parser!(u64).range(1..=64))]
    jobs: Option<u64>,
    /// Where cargo builds, kept between gradings so the dependencies are built once (a class
    /// gives each of its --jobs its own directory in it); no two gradings on one host build
    /// in one at a time [default: target/grade in the instructor's project, or target/grade-2
    /// … while another grading builds there].
    #[arg(long, value_name = "DIR")]
    target_dir: Option<PathBuf>,
    /// The handout the students were given (`whitted handout --chapters 4 --out DIR`): only
    /// the exercises its manifest lists as theirs are graded and counted, not the earlier
    /// chapters' code it gave them. Without it or --chapter, every exercise counts.
    #[arg(long, value_name = "DIR")]
    handout: Option<PathBuf>,
    /// Keep each graded copy (its path is printed).
    #[arg(long)]
    keep: bool,
    /// Leave out the feedback of each chapter that lost points (its picture beside the book's
    /// figure, and the first wrong number of its ray trees): a faster grading, reports of the
    /// tests alone.
    #[arg(long)]
    no_feedback: bool,
    /// Judge every test with all of the student's bodies together: a mistake then also costs
    /// the exercises whose tests call it. By default an exercise's tests run with the
    /// student's body for it and the reference's for every other exercise; the reports say
    /// which was used.
    #[arg(long)]
    whole_road: bool,
    /// The CPU time each process of a submission's build may take, in seconds: a body that
    /// stalls the compiler past it (an endless `const`, a generic blow-up) is graded as not
    /// written, and found in about log2(exercises) builds more.
    #[arg(long, value_name = "SECONDS", default_value_t = 120,
          value_parser = clap::value_parser!(u64).range(5..=3600))]
    compile_cpu: u64,
    /// The memory each process of a submission's build may take, in GiB (as --compile-cpu).
    #[arg(long, value_name = "GIB", default_value_t = 4,
          value_parser = clap::value_parser!(u64).range(1..=256))]
    compile_memory: u64,
    #[command(flatten)]
    sandbox: SandboxArgs,
    /// The instructor's project, whose tests and manifest grade [default: the nearest
    /// Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

impl GradeArgs {
    /// Runs `whitted grade` as the arguments ask: one submission, or a class.
    pub fn run(&self) -> Result<ExitCode, ToolError> {
        let root = crate::project::root(self.root.as_ref())?;
        let manifest = match &self.handout {
            Some(dir) => {
                crate::handout::later::listed_manifest(
                    &root,
                    &crate::handout::later::listed_in(dir)?,
                )?
                .1
            }
            None => crate::cli::read_manifest(&root)?,
        };
        // held until the grading ends: no other grading on this host builds in it
        let (target_dir, _claim) = build_dir(&root, self.target_dir.as_deref())?;
        let setup = GradeSetup {
            chapter: self.chapter,
            hidden: self.hidden.clone(),
            timeout: Duration::from_secs(self.timeout),
            // kept between gradings: the dependencies are built once
            target_dir: Some(target_dir),
            keep: self.keep,
            sandbox: self.sandbox.setup()?,
            render: false,
            feedback: !self.no_feedback,
            screen: true,
            judging: if self.whole_road {
                Judging::WholeRoad
            } else {
                Judging::Alone
            },
            compile: CompileLimits {
                cpu: Duration::from_secs(self.compile_cpu),
                memory: self.compile_memory << 30,
            },
            judge: None,
        };
        let class = match (&self.class, &self.out) {
            (Some(dir), Some(out)) => Some(Class {
                dir,
                out,
                jobs: self.jobs.map(|j| j as usize),
                roster: self.roster.as_deref(),
                new_gradebook: self.new_gradebook,
            }),
            _ => None,
        };
        let reports = Reports {
            json: self.json.as_deref(),
            junit: self.junit.as_deref(),
            csv: self.csv.as_deref(),
        };
        command(
            &root,
            &manifest,
            &setup,
            self.submission.as_deref(),
            class,
            reports,
        )
    }
}

/// The build directory of a grading, claimed for as long as it runs (the claim beside it,
/// `NAME.grading`; the judge's build is beside it too): `asked` (`--target-dir`), which no other
/// live grading may hold, or else `target/grade` of the project at `root`, or, when another
/// grading holds that one, the first of `target/grade-2`, `target/grade-3` … that none holds.
fn build_dir(root: &Path, asked: Option<&Path>) -> Result<(PathBuf, Claim), ToolError> {
    let claim = |dir: &Path| -> Result<Option<Claim>, ToolError> {
        let name = dir
            .file_name()
            .map_or_else(|| "build".to_string(), |n| n.to_string_lossy().into_owned());
        let at = dir.with_file_name(format!("{name}.grading"));
        if let Some(parent) = at.parent() {
            std::fs::create_dir_all(parent).map_err(|e| ToolError::io(parent, e))?;
        }
        Claim::try_take(&at).map_err(ToolError::Usage)
    };
    if let Some(dir) = asked {
        let dir = std::path::absolute(dir).map_err(|e| ToolError::io(dir, e))?;
        return match claim(&dir)? {
            Some(c) => Ok((dir, c)),
            None => Err(ToolError::Usage(format!(
                "--target-dir {}: another grading on this host builds there now; give this one a build directory of its own",
                dir.display()
            ))),
        };
    }
    let base = root.join("target").join("grade");
    for k in 1..=16 {
        let dir = if k == 1 {
            base.clone()
        } else {
            base.with_file_name(format!("grade-{k}"))
        };
        if let Some(c) = claim(&dir)? {
            if k > 1 {
                eprintln!(
                    "another grading on this host builds in {}: this one builds in {}",
                    base.display(),
                    dir.display()
                );
            }
            return Ok((dir, c));
        }
    }
    Err(ToolError::Usage(format!(
        "16 gradings on this host build in {} and beside it: give this one a --target-dir of its own",
        base.display()
    )))
}

/// The sandbox of a grading.
#[derive(clap::Args, Clone, Copy)]
pub struct SandboxArgs {
    /// The sandbox: bubblewrap's namespaces, or (as root, where no namespace can be made)
    /// the tests as a user of their own with limits, the project closed to other users.
    #[arg(long, value_enum, value_name = "LEVEL", default_value = "namespaces")]
    sandbox: Level,
    /// Build and run the student's code without any sandbox, with this program's rights:
    /// only for work you trust.
    #[arg(long, conflicts_with = "sandbox")]
    unsandboxed: bool,
}

impl SandboxArgs {
    /// The level asked for; `None` unsandboxed.
    #[must_use]
    pub fn level(self) -> Option<Level> {
        (!self.unsandboxed).then_some(self.sandbox)
    }

    /// The sandbox of a grading at the level asked for ([`Level::Off`] unsandboxed): this
    /// program runs each submission's server, sandboxed or not, under the runner's limits.
    pub fn setup(self) -> Result<Option<SandboxSetup>, ToolError> {
        let level = self.level().unwrap_or(Level::Off);
        let runner = std::env::current_exe()
            .map_err(|e| ToolError::Usage(format!("cannot find this program's path: {e}")))?;
        Ok(Some(SandboxSetup {
            runner,
            worker: 0,
            level,
        }))
    }
}
