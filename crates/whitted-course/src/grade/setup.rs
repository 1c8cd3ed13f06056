//! How a grading is set up: which chapters, the hidden tests, the time limit, where it
//! builds, and its sandbox.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use super::alone::Judging;
use super::judge_copy::Judge;
use super::sandbox;
use super::sandbox::watch::CompileLimits;

/// The default time limit of one test.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_secs(20);

/// The chapters a grading asks for: one (`4`) or a range of them (`1-3`), as `--chapter`
/// takes them and as a package's scripts pass them on ([`std::fmt::Display`] writes them back).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Chapters {
    /// The first chapter.
    pub first: u8,
    /// The last chapter (the first, for one).
    pub last: u8,
}

impl Chapters {
    /// Reads `4` or `1-3`: chapters of the course, the first not after the last.
    pub fn parse(text: &str) -> Result<Self, String> {
        let (first, last) = crate::handout::parse_chapters(text)?;
        let known = |c: u8| crate::syllabus::chapter(c).is_some();
        if !known(first) || !known(last) || first > last {
            return Err(format!(
                "expected chapters from {} to {}, the first not after the last, found `{text}`",
                crate::syllabus::FIRST,
                crate::syllabus::LAST
            ));
        }
        Ok(Self { first, last })
    }

    /// The chapters, in order.
    #[must_use]
    pub fn list(self) -> Vec<u8> {
        (self.first..=self.last).collect()
    }

    /// Every chapter of `chapters` in order, or all of the course's when `None`.
    #[must_use]
    pub fn or_all(chapters: Option<Self>) -> Vec<u8> {
        chapters.map_or_else(
            || crate::syllabus::CHAPTERS.iter().map(|c| c.number).collect(),
            Self::list,
        )
    }
}

impl std::fmt::Display for Chapters {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.first == self.last {
            write!(f, "{}", self.first)
        } else {
            write!(f, "{}-{}", self.first, self.last)
        }
    }
}

/// How a grading is set up: which chapter, the hidden tests, the time limit, where it builds.
#[derive(Clone, Debug)]
pub struct GradeSetup {
    /// Grade only these chapters (their exercises and their test files); all five when `None`.
    pub chapter: Option<Chapters>,
    /// The instructor's hidden tests: a directory of `*.rs` test files.
    pub hidden: Option<PathBuf>,
    /// The time limit of each test.
    pub timeout: Duration,
    /// Where cargo builds, kept from one grading to the next so the dependencies are built
    /// once, with the graded copy beside the build (a class gives each worker its own
    /// directory under it); a fresh copy with its own `target/` when `None`. Never to be used
    /// by two gradings at once.
    pub target_dir: Option<PathBuf>,
    /// Keep the graded copy (its path is printed) instead of removing it.
    pub keep: bool,
    /// Build and run the student's code in a sandbox ([`sandbox`]); with `None` it runs with
    /// the grader's rights.
    pub sandbox: Option<SandboxSetup>,
    /// Render the last graded chapter's figure with the student's code, for the leaderboard
    /// ([`Grade::render`](crate::grade::Grade::render)).
    pub render: bool,
    /// For each graded chapter that lost points, render its figure with the student's code
    /// beside the book's and compare its ray trees with the reference's
    /// ([`Grade::feedback`](crate::grade::Grade::feedback)).
    pub feedback: bool,
    /// Refuse to compile a body that does more than compute
    /// ([`screen()`](crate::grade::screen())). Always on from the command line; off only where
    /// a test proves the second lock, the runner's, alone.
    pub screen: bool,
    /// The limits of each process of the submission's build (the compiler's CPU time and
    /// memory): a body that stalls the compiler is graded as not written.
    pub compile: CompileLimits,
    /// How an exercise's tests are judged: alone (the student's body for it, the reference's for
    /// every other exercise), or with the student's whole road (`--whole-road`).
    pub judging: Judging,
    /// The judge, built once for a class ([`super::judge_copy::prepare`]); a grading without
    /// one builds its own beside its build directory (or in a temporary directory).
    pub judge: Option<Arc<Judge>>,
}

/// What a sandboxed grading needs to know.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SandboxSetup {
    /// The `whitted` program, whose hidden `sandbox-run` command nextest starts each test
    /// binary with.
    pub runner: PathBuf,
    /// The worker's number: as root, its tests run as user [`sandbox::FIRST_UID`] + this.
    pub worker: usize,
    /// Namespaces (bubblewrap), or a user of its own only.
    pub level: sandbox::Level,
}

impl Default for GradeSetup {
    fn default() -> Self {
        Self {
            chapter: None,
            hidden: None,
            timeout: DEFAULT_TIMEOUT,
            target_dir: None,
            keep: false,
            sandbox: None,
            render: false,
            feedback: true,
            screen: true,
            judging: Judging::default(),
            compile: CompileLimits::default(),
            judge: None,
        }
    }
}
