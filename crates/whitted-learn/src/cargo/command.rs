//! The cargo command itself: which cargo runs, in which project and target directory, with or
//! without debug information, and inside which wrapper (a sandbox) when there is one.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::Path;
use std::process::{Command, Stdio};

/// The cargo to run: `$CARGO` when a cargo started this program, else `cargo` on the PATH.
#[must_use]
pub fn program() -> OsString {
    std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into())
}

/// `cargo ARGS` in `project`, reading no input; `target_dir` is where it builds (its own
/// `target/` when `None`), and without `debug_info` the dev profile builds no debug
/// information (the tools read messages, not backtraces: builds and links are twice as fast).
#[must_use]
pub fn command(project: &Path, target_dir: Option<&Path>, debug_info: bool) -> Command {
    wrapped(project, target_dir, debug_info, None)
}

/// A program that cargo is started inside, a sandbox for instance: cargo runs as
/// `PROGRAM ARGS… cargo …`, with only the environment variables listed here (every other one
/// is removed), and the working directory is the wrapper's business (`bwrap --chdir`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Wrapper {
    /// The program (`bwrap`).
    pub program: OsString,
    /// Its arguments, up to the command it runs.
    pub args: Vec<OsString>,
    /// The whole environment cargo gets, besides the variables [`command`] sets.
    pub env: Vec<(OsString, OsString)>,
}

/// [`command`], started inside `wrapper` when there is one.
#[must_use]
pub fn wrapped(
    project: &Path,
    target_dir: Option<&Path>,
    debug_info: bool,
    wrapper: Option<&Wrapper>,
) -> Command {
    let mut command = match wrapper {
        None => Command::new(program()),
        Some(w) => {
            let mut c = Command::new(&w.program);
            c.args(&w.args)
                .arg(program())
                .env_clear()
                .envs(w.env.iter().cloned());
            c
        }
    };
    command.current_dir(project).stdin(Stdio::null());
    if let Some(dir) = target_dir {
        command.env("CARGO_TARGET_DIR", dir);
    }
    if !debug_info {
        command.env("CARGO_PROFILE_DEV_DEBUG", "0");
        command.env("CARGO_PROFILE_TEST_DEBUG", "0");
    }
    command
}
