//! Running the judge's tests with cargo-nextest, each in its own process under its time
//! limit: the binaries listed once, the profile the grader writes for each run, and the run
//! that leaves nextest's JUnit report.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::time::Duration;

use super::junit::parse_junit;
use super::test_result::TestResult;
use crate::manifest::Manifest;
use crate::{ToolError, cargo, files, layout};

/// The nextest profile the grader writes for a run: no retries, no fail-fast, a time limit per
/// test, and a JUnit file the grader reads.
pub const NEXTEST_PROFILE: &str = "grading";

/// How many times the time limit a test of no exercise gets: it judges the student's whole
/// road, every call across the wire (measured: `supersampling_is_the_same_every_run` takes
/// 0.01 s in one process and 3.7–8.6 s across it on the 2-core machine, idle to busy).
pub(super) const WHOLE_ROAD_TIMES: u32 = 3;

/// How many times a test's limit of CPU time nextest's own limit on the wall clock is, when
/// the grader's clock ([`super::clock`]) runs the tests: a last resort, far beyond the clock's
/// own stop on the wall clock on any load it measures.
pub(super) const CEILING_TIMES: u32 = 60;

/// Writes the grading profile into the nextest configuration file `config`, its reports kept
/// in `store`: no retries, no fail-fast, a time limit per test (three times as long for a test
/// of no exercise), and a JUnit file. The limit is `timeout` on the wall clock, or, when the
/// grader's clock runs the tests (`clocked`), [`CEILING_TIMES`] that: the clock stops a test
/// at `timeout` of CPU time.
pub(super) fn write_profile(
    config: &Path,
    store: &Path,
    timeout: Duration,
    clocked: bool,
) -> Result<(), ToolError> {
    let timeout = if clocked {
        timeout * CEILING_TIMES
    } else {
        timeout
    };
    let text = format!(
        "# written by `whitted grade`: every test in its own process, stopped after its time limit\n\
         [store]\n\
         dir = {store:?}\n\n\
         [profile.{NEXTEST_PROFILE}]\n\
         fail-fast = false\n\
         retries = 0\n\
         slow-timeout = {{ period = \"{}s\", terminate-after = 1 }}\n\
         status-level = \"none\"\n\
         final-status-level = \"none\"\n\
         failure-output = \"never\"\n\
         success-output = \"never\"\n\n\
         # the tests of no exercise count no points and send every call of the student's whole\n\
         # road across the wire: a render makes thousands of round trips\n\
         [[profile.{NEXTEST_PROFILE}.overrides]]\n\
         filter = 'not test(/(^|::)ex_/)'\n\
         slow-timeout = {{ period = \"{}s\", terminate-after = 1 }}\n\n\
         [profile.{NEXTEST_PROFILE}.junit]\n\
         path = \"junit.xml\"\n\
         store-success-output = false\n\
         store-failure-output = true\n",
        timeout.as_secs().max(1),
        timeout.as_secs().max(1) * u64::from(WHOLE_ROAD_TIMES),
        store = store.to_string_lossy(),
    );
    files::write_if_changed(config, text.as_bytes()).map(|_| ())
}

/// A project's test binaries as nextest lists them: its binaries' metadata and cargo's, which
/// a run reuses without building.
#[derive(Clone, Debug)]
pub struct Listed {
    /// nextest's binaries metadata (`cargo nextest list --list-type binaries-only`).
    pub binaries: PathBuf,
    /// cargo's metadata (`cargo metadata --no-deps`).
    pub metadata: PathBuf,
}

/// Lists the built test `targets` of the project (inside `wrapper`, a build sandbox, when
/// there is one) into the directory `to`: what runs is what was built.
pub(super) fn list(
    project: &Path,
    target_dir: &Path,
    targets: &[String],
    wrapper: Option<&cargo::Wrapper>,
    to: &Path,
) -> Result<Listed, ToolError> {
    std::fs::create_dir_all(to).map_err(|e| ToolError::io(to, e))?;
    let listed = |args: &[&str], to: &Path| -> Result<(), ToolError> {
        let out = cargo::wrapped(project, Some(target_dir), false, wrapper)
            .args(args)
            .output()
            .map_err(|e| ToolError::Cargo(format!("cannot run cargo {}: {e}", args[0])))?;
        if !out.status.success() {
            let err = String::from_utf8_lossy(&out.stderr);
            return Err(ToolError::Cargo(format!(
                "cargo {} failed: {}",
                args[0],
                err.lines()
                    .rev()
                    .find(|l| !l.trim().is_empty())
                    .unwrap_or("")
            )));
        }
        files::write_file(to, &out.stdout)
    };
    let binaries = to.join("binaries.json");
    let metadata = to.join("cargo-metadata.json");
    let mut list = vec![
        "nextest",
        "list",
        "--list-type",
        "binaries-only",
        "--message-format",
        "json",
        "--locked",
        "-p",
        layout::CORE_PACKAGE,
    ];
    for t in targets {
        list.extend(["--test", t.as_str()]);
    }
    listed(&list, &binaries)?;
    listed(
        &["metadata", "--format-version", "1", "--no-deps", "--locked"],
        &metadata,
    )?;
    Ok(Listed { binaries, metadata })
}

/// Runs the `listed` test binaries of the project with the grading profile, written with its
/// reports into the directory `run` (a run's own: runs beside each other never share one),
/// the tests given `env` (in which the grader's clock is nextest's runner when `clocked`) and
/// their limit `timeout`; reads the JUnit report.
pub(super) fn run(
    project: &Path,
    target_dir: &Path,
    listed: &Listed,
    run: &Path,
    (timeout, clocked): (Duration, bool),
    env: &[(OsString, OsString)],
    (manifest, hidden): (&Manifest, &[String]),
) -> Result<Vec<TestResult>, ToolError> {
    let store = run.join("store");
    let config = run.join("nextest.toml");
    write_profile(&config, &store, timeout, clocked)?;
    let junit = store.join(NEXTEST_PROFILE).join("junit.xml");
    let _ = std::fs::remove_file(&junit);
    std::fs::create_dir_all(&store).map_err(|e| ToolError::io(&store, e))?;
    let ran = cargo::Nextest {
        project,
        package: layout::CORE_PACKAGE,
        tests: &[],
        profile: NEXTEST_PROFILE,
        config: Some(&config),
        target_dir,
        reuse: Some((&listed.binaries, &listed.metadata)),
        env,
    }
    .run();
    let text = match (std::fs::read_to_string(&junit), ran) {
        (Ok(text), _) => text,
        (Err(_), Err(e)) => return Err(e),
        (Err(e), Ok(())) => {
            return Err(ToolError::Cargo(format!(
                "the tests ran, but nextest wrote no report {}: {e}",
                junit.display()
            )));
        }
    };
    parse_junit(&text, manifest, hidden)
}
