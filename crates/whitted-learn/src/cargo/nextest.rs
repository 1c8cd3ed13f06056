//! `cargo nextest run`: how the grader runs a submission's tests, each in its own process.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::Path;

use super::command::command;
use crate::ToolError;

/// `cargo nextest run` of test targets, each test in its own process: how the grader runs a
/// submission's tests. Its report is the JUnit file the profile names (the caller's to read).
pub struct Nextest<'a> {
    /// The project (the workspace's directory).
    pub project: &'a Path,
    /// The package whose test targets run (`-p`).
    pub package: &'a str,
    /// The test targets (`--test NAME`), built before.
    pub tests: &'a [String],
    /// The nextest profile (in the project's `.config/nextest.toml`, or in `config`).
    pub profile: &'a str,
    /// nextest's configuration file (`--config-file`), when not the project's own.
    pub config: Option<&'a Path>,
    /// Where cargo builds.
    pub target_dir: &'a Path,
    /// Run what was built, without building: nextest's binaries metadata (of `cargo nextest
    /// list --list-type binaries-only --message-format json`) and cargo's metadata (of
    /// `cargo metadata --no-deps`); the binaries listed are the ones that run, and
    /// `package` and `tests` are not used.
    pub reuse: Option<(&'a Path, &'a Path)>,
    /// More environment variables (a target runner that starts each test binary in a
    /// sandbox: `CARGO_TARGET_<TRIPLE>_RUNNER`).
    pub env: &'a [(OsString, OsString)],
}

impl Nextest<'_> {
    /// Runs the tests, without colour or backtraces, every test to the end (no fail-fast);
    /// `Err` when nextest cannot be started or is not installed, with its last line.
    pub fn run(&self) -> Result<(), ToolError> {
        let mut command = command(self.project, Some(self.target_dir), false);
        command.args([
            "nextest",
            "run",
            "--profile",
            self.profile,
            "--no-fail-fast",
            "--no-tests=pass",
        ]);
        if let Some(config) = self.config {
            command.arg("--config-file").arg(config);
        }
        match self.reuse {
            Some((binaries, metadata)) => {
                command.arg("--binaries-metadata").arg(binaries);
                command.arg("--cargo-metadata").arg(metadata);
            }
            None => {
                command.args(["--locked", "-p", self.package]);
                for t in self.tests {
                    command.args(["--test", t]);
                }
            }
        }
        command.envs(self.env.iter().cloned());
        let out = command
            .env("RUST_BACKTRACE", "0")
            .env("NO_COLOR", "1")
            .output()
            .map_err(|e| ToolError::Cargo(format!("cannot run cargo nextest: {e}")))?;
        let stderr = String::from_utf8_lossy(&out.stderr);
        if stderr.contains("no such command: `nextest`") {
            return Err(ToolError::Cargo(
                "cargo-nextest is not installed: cargo install --locked cargo-nextest".into(),
            ));
        }
        if out.status.success() || out.status.code() == Some(100) {
            return Ok(()); // 100: some tests failed, which is what grading measures
        }
        // its last lines that say something (not the separators of its summary)
        let mut said: Vec<&str> = stderr
            .lines()
            .map(str::trim)
            .filter(|l| l.chars().any(char::is_alphanumeric))
            .rev()
            .take(3)
            .collect();
        said.reverse();
        Err(ToolError::Cargo(format!(
            "cargo nextest failed ({}): {}",
            out.status,
            said.join(" / ")
        )))
    }
}
