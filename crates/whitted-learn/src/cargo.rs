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
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::ffi::OsString;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::ToolError;

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

/// `cargo nextest run` of test targets, each test in its own process: how the grader runs a
/// submission's tests. Its report is the JUnit file the profile names (the caller's to read).
pub struct Nextest<'a> {
    /// The project (the workspace's directory).
    pub project: &'a Path,
    /// The package whose test targets run (`-p`).
    pub package: &'a str,
    /// The test targets (`--test NAME`), built before.
    pub tests: &'a [String],
    /// The nextest profile (in the project's `.config/nextest.toml`).
    pub profile: &'a str,
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

/// How a test ended, as libtest reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TestOutcome {
    /// `ok`
    Passed,
    /// `FAILED`
    Failed,
    /// `ignored`
    Ignored,
}

/// The results in libtest's output: one `(name, outcome)` per line `test NAME ... ok|FAILED|ignored`.
#[must_use]
pub fn parse_libtest(stdout: &str) -> Vec<(String, TestOutcome)> {
    stdout
        .lines()
        .filter_map(|line| {
            let rest = line.strip_prefix("test ")?;
            let (name, result) = rest.rsplit_once(" ... ")?;
            let outcome = match result.trim() {
                "ok" => TestOutcome::Passed,
                "FAILED" => TestOutcome::Failed,
                r if r.starts_with("ignored") => TestOutcome::Ignored,
                _ => return None,
            };
            Some((name.to_string(), outcome))
        })
        .collect()
}

/// libtest's `---- NAME stdout ----` blocks, by test name.
#[must_use]
pub fn failure_blocks(stdout: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    let mut current: Option<(String, String)> = None;
    for line in stdout.lines() {
        if let Some(name) = line
            .strip_prefix("---- ")
            .and_then(|l| l.strip_suffix(" stdout ----"))
        {
            if let Some((n, text)) = current.take() {
                out.insert(n, text);
            }
            current = Some((name.to_string(), String::new()));
        } else if line == "failures:" || line.starts_with("test result:") {
            if let Some((n, text)) = current.take() {
                out.insert(n, text);
            }
        } else if let Some((_, text)) = current.as_mut() {
            text.push_str(line);
            text.push('\n');
        }
    }
    if let Some((n, text)) = current {
        out.insert(n, text);
    }
    out
}

/// A test, as `target::name` (`ch02_generic_objects::sphere::ex_sphere_coefficients_…`).
pub type TestId = String;

/// What runs of test executables said: the one record of test results that the loop, the
/// proof and the dependency measurement read. Tests are keyed `target::name`, so runs of
/// several targets go into one ([`TestRun::merge`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TestRun {
    /// Each test's outcome.
    pub outcomes: BTreeMap<TestId, TestOutcome>,
    /// The output of each failed test (libtest's `---- NAME stdout ----` block).
    pub failures: BTreeMap<TestId, String>,
    /// The test targets that ran.
    pub targets: BTreeSet<String>,
    /// Whether every process ended with success.
    pub success: bool,
    /// Why a run did not finish normally (time limit, crash), if one did not.
    pub unfinished: Option<String>,
    /// When the targets did not build: the first compiler error's one-line place and message,
    /// then the compiler's whole text of it; nothing ran.
    pub build_error: Option<(String, String)>,
}

impl TestRun {
    /// The run of target `target` whose libtest output is `stdout`.
    #[must_use]
    pub fn from_libtest(target: &str, stdout: &str) -> Self {
        let id = |name: &str| format!("{target}::{name}");
        Self {
            outcomes: parse_libtest(stdout)
                .into_iter()
                .map(|(name, outcome)| (id(&name), outcome))
                .collect(),
            failures: failure_blocks(stdout)
                .into_iter()
                .map(|(name, text)| (id(&name), text))
                .collect(),
            targets: BTreeSet::from([target.to_string()]),
            success: true,
            unfinished: None,
            build_error: None,
        }
    }

    /// Adds the results of `other` (of other targets) to these.
    pub fn merge(&mut self, other: TestRun) {
        let first = self.targets.is_empty();
        self.outcomes.extend(other.outcomes);
        self.failures.extend(other.failures);
        self.targets.extend(other.targets);
        self.success = (first || self.success) && other.success;
        self.unfinished = self.unfinished.take().or(other.unfinished);
        self.build_error = self.build_error.take().or(other.build_error);
    }

    /// The tests that ended with `outcome`, in name order.
    #[must_use]
    pub fn with(&self, outcome: TestOutcome) -> Vec<&TestId> {
        self.outcomes
            .iter()
            .filter(|(_, o)| **o == outcome)
            .map(|(n, _)| n)
            .collect()
    }
}

/// A test's own name, without the target and module path before it.
#[must_use]
pub fn test_name(full: &str) -> &str {
    full.rsplit("::").next().unwrap_or(full)
}

/// How to run a test executable.
pub struct Run<'a> {
    /// The test target it is (the key of its tests in the [`TestRun`]).
    pub target: &'a str,
    /// The executable.
    pub exe: &'a Path,
    /// Its working directory.
    pub dir: &'a Path,
    /// libtest's arguments (a name filter, `--test-threads N` …).
    pub args: &'a [String],
    /// Environment variables to set, then to remove (a poison switch; `WHITTED_BLESS`).
    pub env: &'a [(&'a str, String)],
    /// Environment variables removed before the run.
    pub env_remove: &'a [&'a str],
    /// Where its stdout and stderr go (`LOG.out`, `LOG.err`); kept in memory when `None`.
    pub log: Option<&'a Path>,
    /// The time limit of the whole run.
    pub timeout: Duration,
}

impl Run<'_> {
    /// Runs the executable and reads libtest's report; `Err` only when it cannot be started or
    /// its output cannot be written.
    pub fn run(&self) -> Result<TestRun, ToolError> {
        let mut command = Command::new(self.exe);
        command
            .args(self.args)
            .current_dir(self.dir)
            // the failing line, not the stack, is what a report needs
            .env("RUST_BACKTRACE", "0")
            .stdin(Stdio::null());
        for v in self.env_remove {
            command.env_remove(v);
        }
        for (k, v) in self.env {
            command.env(k, v);
        }
        let (out_path, err_path) = match self.log {
            Some(log) => (log.with_extension("out"), log.with_extension("err")),
            None => {
                let dir =
                    tempfile::tempdir().map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
                let run = Run {
                    log: Some(&dir.path().join("run")),
                    ..*self
                };
                return run.run();
            }
        };
        let stdout = std::fs::File::create(&out_path).map_err(|e| ToolError::io(&out_path, e))?;
        let stderr = std::fs::File::create(&err_path).map_err(|e| ToolError::io(&err_path, e))?;
        let mut child = command
            .stdout(stdout)
            .stderr(stderr)
            .spawn()
            .map_err(|e| ToolError::Cargo(format!("cannot run {}: {e}", self.exe.display())))?;
        let started = Instant::now();
        let (status, unfinished) = loop {
            match child.try_wait() {
                Ok(Some(status)) => break (Some(status), None),
                Ok(None) if started.elapsed() > self.timeout => {
                    let _ = child.kill();
                    let _ = child.wait();
                    break (
                        None,
                        Some(format!(
                            "time limit of {} s reached",
                            self.timeout.as_secs()
                        )),
                    );
                }
                Ok(None) => std::thread::sleep(Duration::from_millis(5)),
                Err(e) => {
                    return Err(ToolError::Cargo(format!(
                        "waiting for {}: {e}",
                        self.exe.display()
                    )));
                }
            }
        };
        let text = std::fs::read_to_string(&out_path).map_err(|e| ToolError::io(&out_path, e))?;
        // a test process that ends without libtest's summary line crashed (abort, signal)
        let unfinished = unfinished.or_else(|| {
            (!text.contains("test result:")).then(|| {
                format!(
                    "the test process ended without a result ({}); its stderr: {}",
                    status.map_or("killed".into(), |s| s.to_string()),
                    err_path.display()
                )
            })
        });
        Ok(TestRun {
            success: status.is_some_and(|s| s.success()),
            unfinished,
            ..TestRun::from_libtest(self.target, &text)
        })
    }
}
