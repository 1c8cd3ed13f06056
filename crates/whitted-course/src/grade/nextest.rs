//! Running the graded copy's tests with cargo-nextest, each in its own process under its time
//! limit: the profile the grader writes, and the run that leaves nextest's JUnit report.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;
use std::time::Duration;

use super::TestResult;
use super::junit::parse_junit;
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

/// Runs the built targets with nextest's grading profile and reads its JUnit report.
pub(super) fn run(
    project: &Path,
    target_dir: &Path,
    targets: &[String],
    manifest: &Manifest,
    hidden: &[String],
) -> Result<Vec<TestResult>, ToolError> {
    // in the copy, not the (perhaps shared) target directory: one report per copy
    let junit = project.join(STORE).join(NEXTEST_PROFILE).join("junit.xml");
    let _ = std::fs::remove_file(&junit);
    let ran = cargo::Nextest {
        project,
        package: layout::CORE_PACKAGE,
        tests: targets,
        profile: NEXTEST_PROFILE,
        target_dir,
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
