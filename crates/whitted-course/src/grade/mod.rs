//! `whitted grade`: a student's copy graded by the instructor's tests, points from the
//! manifest.
//!
//! What is graded is the student's code and nothing else: the body of each exercise, the lines
//! between `// BEGIN SOLUTION sphere_coefficients` and `// END SOLUTION` in the student's files. Those bodies
//! are put into a copy of the **instructor's** project — its tests, its manifest, its
//! `Cargo.lock`, its code around the exercises — so a student who edits a test, the manifest
//! or the renderer gains nothing. An exercise whose markers are missing counts as not written.
//! With a build directory ([`GradeSetup::target_dir`]) the copy is kept beside it and rewritten
//! file by file for each submission, so that cargo recompiles only the bodies that differ from
//! the last submission's; without one, it is a fresh temporary directory.
//!
//! A body that is not a formula's grammar (a path into the process, files, the network or the
//! environment, `unsafe`, an item, a lifetime, a macro outside the short list …) is not even
//! put in: it counts as not written ([`screen()`], the screen `cargo learn` runs at every save).
//!
//! **Each exercise is judged alone** ([`alone`]), **by a judge the student's code cannot
//! reach** ([`outside`], [`judge_copy`]): the tests run in the *judge*, a build of the
//! instructor's project with its tests, public and hidden, made once for a class; the graded
//! copy holds the student's bodies and none of the reference's for a graded exercise, and is
//! built into the *server*. A test named after an exercise sends that exercise's calls to the
//! server and runs every other exercise in the judge, so a mistake costs its own exercise
//! only; the tests of no exercise send every exercise (the student's whole road), and
//! `--whole-road` ([`Judging::WholeRoad`]) judges every test that way. The pictures and the
//! ray trees of the feedback are drawn by the graded copy's own chapter binaries.
//!
//! Then, for each submission:
//!
//! 1. **Build** the server. An exercise whose body does not compile is put back to its
//!    `todo!()` and the build is tried again, so a compile error costs only the exercise it
//!    is in; its first error goes into the report.
//! 2. **Run** every test of the graded chapters with cargo-nextest, each test in its own
//!    judge process with its own limit of CPU time ([`clock`]), each judge's process starting its own server in
//!    the sandbox through the [`runner`] (`whitted sandbox-run --serve`): a `todo!()`, a
//!    panic, a stack overflow, an abort or an endless loop on the server fails that
//!    exercise's tests and no others. Only values cross from the server; what it prints is
//!    cleaned ([`clean`]); the judge's assertions decide.
//! 3. **Score.** An exercise's points ([`super::manifest::Exercise::points`]) are shared
//!    equally by its tests, the ones named after it (`ex_sphere_coefficients_…`), public and
//!    hidden alike.
//!
//! Hidden tests are the instructor's own test files (`--hidden DIR`, each `*.rs` a test target
//! added to the judge as `tests/hidden_NAME.rs`, never to the graded copy), compiled against
//! the same public API. Their
//! tests follow the same naming, so they count for the exercise they name; reports for
//! students show their points, never their names or messages ([`super::report`]). A hidden
//! test named after no exercise, or a hidden file that does not build, stops the grading
//! before the first submission, at its file and line ([`hidden`]): nothing of it reaches a
//! student.
//!
//! Its files, one job each: `setup.rs` (how a grading is set up), `grading.rs` ([`grade()`],
//! the steps in order), `copy.rs` (the graded copy), `splice.rs`, `alone.rs` and `screen.rs`
//! (the student's bodies in it), `outside.rs` and `judge_copy.rs` (the wire and the judge),
//! `hidden.rs` (the hidden tests' names), `build.rs` and `blame.rs` (the build), `nextest.rs`, `clock.rs`, `junit.rs`, `runner.rs`,
//! `sandbox/`, `claim.rs` and `clean.rs` (the test run), `test_result.rs`, `score.rs` and `outcome.rs` (the results and the points),
//! `render.rs` and `explained.rs` (the pictures and their words), `class.rs` (a class),
//! `command.rs` (the reports) and `args.rs` (the command line).
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub mod alone;
mod args;
mod blame;
mod build;
pub mod claim;
mod class;
pub mod clean;
pub mod clock;
pub mod command;
mod copy;
mod explained;
mod grading;
pub mod hidden;
pub mod judge_copy;
mod junit;
mod nextest;
mod outcome;
pub mod outside;
mod render;
pub mod runner;
pub mod sandbox;
mod score;
pub mod screen;
mod setup;
mod splice;
mod test_result;

pub use alone::Judging;
pub use args::{GradeArgs, SandboxArgs};
pub use class::{ClassEntry, grade_class};
pub use explained::Explained;
pub use grading::grade;
pub use judge_copy::Judge;
pub use junit::{MESSAGE_CHARS, panic_message, parse_junit};
pub use nextest::NEXTEST_PROFILE;
pub use outcome::{ExerciseScore, Grade, Road, Timings};
pub use render::{ChapterFeedback, PICTURE_BYTES, RenderScore};
pub use score::{chapter_targets, recognise_known, scores};
pub use screen::screen;
pub use setup::{Chapters, DEFAULT_TIMEOUT, GradeSetup, SandboxSetup};
pub(crate) use splice::hidden_files;
pub use splice::student_body;
pub use test_result::{Status, TestResult};
pub use whitted_learn::trees::{Against, Parting};
