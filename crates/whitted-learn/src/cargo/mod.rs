//! Running cargo on a project, and the test executables it builds: the one runner that
//! `learn`, `grade`, the proof and the dependency measurement use.
//!
//! A build is `cargo test --no-run` (test targets) or `cargo build` (binaries) with
//! `--message-format=json`, read as it comes: the executables built, by target name, and the
//! compiler's errors with the file, line and column of their primary span. Cargo's own status
//! lines (`Compiling glam …`) go where [`Stderr`] says: through to the terminal, kept, or handed
//! to a function line by line (`learn` shows them only when a build is slow). A test executable
//! is run directly (not through `cargo test` again), with a time limit, and libtest's output is
//! read back: each test's outcome and each failure's message.
//!
//! | file | what it holds |
//! |---|---|
//! | `command.rs` | the cargo program, its directories, a wrapper it runs inside |
//! | `build.rs` | [`Build`]: test targets or binaries built, read as cargo reports them |
//! | `nextest.rs` | [`Nextest`]: the grader's run of a submission's tests |
//! | `libtest.rs` | [`TestRun`]: libtest's report read back |
//! | `run.rs` | [`Run`]: one test executable run, with a time limit |
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

mod build;
mod command;
mod libtest;
mod nextest;
mod run;

pub use build::{Build, Built, Diagnostic, Stderr};
pub use command::{Wrapper, command, program, wrapped};
pub use libtest::{TestId, TestOutcome, TestRun, failure_blocks, parse_libtest, test_name};
pub use nextest::Nextest;
pub use run::Run;
