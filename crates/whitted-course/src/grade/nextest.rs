//! Running the graded copy's tests with cargo-nextest, each in its own process under its time
//! limit: the profile the grader writes, and the run that leaves nextest's JUnit report.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;
use std::time::Duration;

use super::junit::parse_junit;
use super::sandbox::Sandbox;
use super::test_result::TestResult;
use crate::manifest::Manifest;
use crate::{ToolError, cargo, files, layout};

/// The nextest profile the grader writes into the copy: no retries, no fail-fast, a time
/// limit per test, and a JUnit file the grader reads.
pub const NEXTEST_PROFILE: &str = "grading";

/// Where nextest keeps its reports, in the graded copy.
pub(super) const STORE: &str = "nextest-store";

/// Writes the grading profile into the copy's `.config/nextest.toml`.
pub(super) fn write_profile(project: &Path, timeout: Duration) -> Result<(), ToolError> {
    let dir = project.join(".config");
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let text = format!(
        "# written by `whitted grade`: every test in its own process, stopped after its time limit\n\
         [store]\n\
         dir = \"{STORE}\"\n\n\
         [profile.{NEXTEST_PROFILE}]\n\
         fail-fast = false\n\
         retries = 0\n\
         slow-timeout = {{ period = \"{}s\", terminate-after = 1 }}\n\
         status-level = \"none\"\n\
         final-status-level = \"none\"\n\
         failure-output = \"never\"\n\
         success-output = \"never\"\n\n\
         [profile.{NEXTEST_PROFILE}.junit]\n\
         path = \"junit.xml\"\n\
         store-success-output = false\n\
         store-failure-output = true\n",
        timeout.as_secs().max(1)
    );
    files::write_if_changed(&dir.join("nextest.toml"), text.as_bytes()).map(|_| ())
}

/// Runs the built targets with nextest's grading profile and reads its JUnit report. What
/// runs is what was built: nextest is given the binaries that `cargo nextest list` finds
/// (inside `wrapper`, the build sandbox, when there is one) and builds nothing itself, so
/// `listed_then` may take away what the tests must not see (the hidden tests' sources) between
/// the listing and the run; each test binary goes through the `sandbox`'s runner when there
/// is one.
#[allow(clippy::too_many_arguments)]
pub(super) fn run(
    project: &Path,
    target_dir: &Path,
    targets: &[String],
    manifest: &Manifest,
    hidden: &[String],
    wrapper: Option<&cargo::Wrapper>,
    sandbox: Option<&Sandbox>,
    listed_then: impl FnOnce() -> Result<(), ToolError>,
) -> Result<Vec<TestResult>, ToolError> {
    // in the copy, not the (perhaps shared) target directory: one report per copy
    let store = project.join(STORE);
    let junit = store.join(NEXTEST_PROFILE).join("junit.xml");
    let _ = std::fs::remove_file(&junit);
    std::fs::create_dir_all(&store).map_err(|e| ToolError::io(&store, e))?;
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
    let binaries = store.join("binaries.json");
    let metadata = store.join("cargo-metadata.json");
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
    listed_then()?;
    let env = match sandbox {
        Some(s) => s.runner_env()?,
        None => Vec::new(),
    };
    let ran = cargo::Nextest {
        project,
        package: layout::CORE_PACKAGE,
        tests: targets,
        profile: NEXTEST_PROFILE,
        target_dir,
        reuse: Some((&binaries, &metadata)),
        env: &env,
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
    // the next submission graded in this copy must not find this one's results
    let _ = std::fs::remove_dir_all(&store);
    parse_junit(&text, manifest, hidden)
}
