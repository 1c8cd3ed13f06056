//! What a package grades and how: the settings every grading of a platform's package gets,
//! which the package's scripts and workflow pass on.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::PathBuf;

use super::Settings;
use crate::grade::Judging;
use crate::grade::sandbox::Level;

/// The cargo-nextest version the packages install (the one `.ci/run` installs).
pub const NEXTEST_VERSION: &str = "0.9.143";

/// What a package grades and how.
#[derive(Clone, Debug)]
pub struct Options {
    /// Only this chapter, or all.
    pub chapter: Option<crate::grade::Chapters>,
    /// The hidden tests' directory.
    pub hidden: Option<PathBuf>,
    /// The time limit of one test, in seconds.
    pub timeout: u64,
    /// How results are shown.
    pub settings: Settings,
    /// The sandbox every grading of the package uses ([`Level::User`] for a platform whose
    /// container makes no namespace; `setup.sh` then closes the project to other users);
    /// `None` grades without one, the container then being the only sandbox.
    pub sandbox: Option<Level>,
    /// How each exercise's tests are judged (`--whole-road` for the student's whole road).
    pub judging: Judging,
    /// The exercises of the handout the students were given (its manifest's own list), which
    /// the package's manifest carries: only those are graded and counted. `None`: every
    /// exercise of the manifest (or of `chapter`).
    pub handout: Option<Vec<String>>,
}
