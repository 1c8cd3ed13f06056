//! Running a test executable directly (not through `cargo test` again), with a time limit, its
//! output kept in files and read back as a [`TestRun`].
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::libtest::TestRun;
use crate::ToolError;

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
