//! A build: `cargo test --no-run` of test targets or `cargo build` of binaries, with
//! `--message-format=json` read as it comes — the executables built by target name, and the
//! compiler's errors with the file, line and column of their primary span. Cargo's own status
//! lines go where [`Stderr`] says.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::{Duration, Instant};

use super::command::{Wrapper, wrapped};
use crate::ToolError;

/// Where cargo's status lines go during a build.
pub enum Stderr<'a> {
    /// Straight to this program's stderr (cargo draws its progress bar on a terminal).
    Inherit,
    /// Kept, and returned in [`Built::stderr`].
    Keep,
    /// Each line to this function as it comes (and kept as well).
    Lines(&'a (dyn Fn(&str) + Sync)),
}

/// What to build.
pub struct Build<'a> {
    /// The project (the workspace's directory).
    pub project: &'a Path,
    /// The packages selected (`-p`); none selects cargo's default.
    pub packages: &'a [&'a str],
    /// Test targets (`--test NAME`), built with `cargo test --no-run`.
    pub tests: &'a [String],
    /// Binaries (`--bin NAME`), built with `cargo build`; used only when `tests` is empty.
    pub bins: &'a [String],
    /// Examples (`--example NAME`), built with `cargo build` beside `bins`; used only when
    /// `tests` is empty.
    pub examples: &'a [String],
    /// The profile of a `cargo build` of binaries (`--profile`); cargo's default when `None`.
    /// A test build always uses the test profile.
    pub profile: Option<&'a str>,
    /// Cargo features (`--features`).
    pub features: &'a [String],
    /// Where cargo builds; the project's `target/` when `None`.
    pub target_dir: Option<&'a Path>,
    /// Whether the dev profile keeps its debug information.
    pub debug_info: bool,
    /// `--locked`: the project's `Cargo.lock` must do as it is.
    pub locked: bool,
    /// Where cargo's status lines go.
    pub stderr: Stderr<'a>,
    /// The program cargo runs inside (a sandbox that sees only what the build needs); cargo
    /// itself when `None`.
    pub wrapper: Option<&'a Wrapper>,
}

/// A compiler error (or cargo's, when it names no source file).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The file of its primary span, as the compiler names it (relative to the workspace's
    /// directory for the workspace's own crates); empty when it has none.
    pub file: PathBuf,
    /// Its line, from 1 (0 when it has no place).
    pub line: usize,
    /// Its column, from 1 (0 when it has no place).
    pub column: usize,
    /// Its message, one line (`mismatched types`).
    pub message: String,
    /// The whole error as the compiler prints it, with the code it points at.
    pub rendered: String,
}

impl Diagnostic {
    /// `file:line:col: message`, or the message alone when the error has no place.
    #[must_use]
    pub fn one_line(&self) -> String {
        if self.line == 0 {
            self.message.clone()
        } else {
            format!(
                "{}:{}:{}: {}",
                self.file.display(),
                self.line,
                self.column,
                self.message
            )
        }
    }
}

/// What a build made.
#[derive(Clone, Debug, Default)]
pub struct Built {
    /// Whether cargo succeeded.
    pub success: bool,
    /// The executables built, by target name (a test target's, or a binary's).
    pub executables: BTreeMap<String, PathBuf>,
    /// The compiler's errors, in the order they came.
    pub errors: Vec<Diagnostic>,
    /// Cargo's status lines (unless they went straight to the terminal).
    pub stderr: String,
    /// How long the build took.
    pub elapsed: Duration,
}

impl Built {
    /// The first error as one line: the compiler's, else cargo's last `error` line.
    #[must_use]
    pub fn first_error(&self) -> String {
        match self.errors.first() {
            Some(d) => d.one_line(),
            None => self
                .stderr
                .lines()
                .rev()
                .find(|l| l.trim_start().starts_with("error"))
                .unwrap_or("cargo failed")
                .trim()
                .to_string(),
        }
    }
}

impl Build<'_> {
    /// Runs the build; `Err` only when cargo cannot be started.
    pub fn run(&self) -> Result<Built, ToolError> {
        let started = Instant::now();
        let mut command = wrapped(self.project, self.target_dir, self.debug_info, self.wrapper);
        if self.tests.is_empty() {
            command.arg("build");
            if let Some(p) = self.profile {
                command.args(["--profile", p]);
            }
        } else {
            command.args(["test", "--no-run"]);
        }
        command.arg("--message-format=json");
        if self.locked {
            command.arg("--locked");
        }
        for p in self.packages {
            command.args(["-p", p]);
        }
        if self.tests.is_empty() {
            for b in self.bins {
                command.args(["--bin", b]);
            }
            for e in self.examples {
                command.args(["--example", e]);
            }
        } else {
            for t in self.tests {
                command.args(["--test", t]);
            }
        }
        if !self.features.is_empty() {
            command.args(["--features", &self.features.join(",")]);
        }
        command.stdout(Stdio::piped()).stderr(match self.stderr {
            Stderr::Inherit => Stdio::inherit(),
            _ => Stdio::piped(),
        });
        let mut child = command
            .spawn()
            .map_err(|e| ToolError::Cargo(format!("cannot run cargo: {e}")))?;
        let stdout = child.stdout.take();
        let stderr = child.stderr.take();
        let mut built = Built::default();
        let kept = std::thread::scope(|scope| {
            let reader = scope.spawn(|| {
                let mut kept = String::new();
                if let Some(err) = stderr {
                    for line in BufReader::new(err).lines().map_while(Result::ok) {
                        if let Stderr::Lines(f) = self.stderr {
                            f(&line);
                        }
                        kept.push_str(&line);
                        kept.push('\n');
                    }
                }
                kept
            });
            if let Some(out) = stdout {
                for line in BufReader::new(out).lines().map_while(Result::ok) {
                    read_message(&line, &mut built);
                }
            }
            reader.join().unwrap_or_default()
        });
        built.stderr = kept;
        built.success = child
            .wait()
            .map_err(|e| ToolError::Cargo(format!("waiting for cargo: {e}")))?
            .success();
        built.elapsed = started.elapsed();
        Ok(built)
    }
}

/// Takes one line of cargo's JSON messages into `built`.
fn read_message(line: &str, built: &mut Built) {
    let Ok(msg) = serde_json::from_str::<serde_json::Value>(line) else {
        return;
    };
    match msg["reason"].as_str() {
        Some("compiler-artifact") => {
            if let (Some(name), Some(exe)) =
                (msg["target"]["name"].as_str(), msg["executable"].as_str())
            {
                built
                    .executables
                    .insert(name.to_string(), PathBuf::from(exe));
            }
        }
        Some("compiler-message") if msg["message"]["level"] == "error" => {
            let m = &msg["message"];
            let spans = m["spans"].as_array().cloned().unwrap_or_default();
            let span = spans
                .iter()
                .find(|s| s["is_primary"] == true)
                .or(spans.first());
            let number = |s: Option<&serde_json::Value>, key: &str| {
                s.and_then(|s| s[key].as_u64()).unwrap_or(0) as usize
            };
            built.errors.push(Diagnostic {
                file: PathBuf::from(span.and_then(|s| s["file_name"].as_str()).unwrap_or("")),
                line: number(span, "line_start"),
                column: number(span, "column_start"),
                message: m["message"].as_str().unwrap_or("").to_string(),
                rendered: m["rendered"].as_str().unwrap_or("").to_string(),
            });
        }
        _ => {}
    }
}
