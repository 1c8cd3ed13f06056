//! Building and running for the loop: which test target decides each exercise, the build of
//! test targets or chapter binaries (cargo's lines shown only once a build is slow), and the
//! runs of the test executables, each within its time limit.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use super::say::Say;
use crate::cargo::{self, Build, Built, Stderr, TestRun, test_name};
use crate::manifest::Manifest;
use crate::map::Group;
use crate::{ToolError, layout};

/// The packages every build of the loop selects: the renderer's and the binaries', so that
/// cargo resolves their dependencies alike (see [`crate::learn`]).
pub const PACKAGES: [&str; 2] = [layout::CORE_PACKAGE, layout::APP_PACKAGE];

/// How long a build may run before its cargo lines are shown.
const QUIET_BUILD: Duration = Duration::from_millis(1500);

/// Whether this run of the tool has said why a build is slow.
static SAID_SLOW: AtomicBool = AtomicBool::new(false);

/// The time limit of one test target's run: a loop that never ends stops there.
pub const TEST_TIME_LIMIT: Duration = Duration::from_secs(60);

/// The test target that holds each exercise's own tests (by manifest index): the map's, or
/// else the handout target named after its chapter (`ch02_…`).
#[must_use]
pub fn targets_of(manifest: &Manifest, map: &[Group]) -> Vec<Option<String>> {
    manifest
        .entries
        .iter()
        .map(|e| {
            let prefix = e.exercise.test_prefix();
            map.iter()
                .flat_map(|g| &g.tests)
                .filter_map(|t| t.split_once("::"))
                .find(|(_, name)| test_name(name).starts_with(&prefix))
                .map(|(target, _)| target.to_string())
                .or_else(|| {
                    let binary = whitted_syllabus::chapter(e.chapter)?.binary;
                    manifest
                        .handout
                        .tests
                        .iter()
                        .find(|t| *t == binary)
                        .cloned()
                })
        })
        .collect()
}

/// A build of the loop: the packages of [`PACKAGES`], cargo's lines shown once it is slow.
pub(crate) fn build(
    root: &Path,
    tests: &[String],
    bins: &[String],
    say: &Say,
) -> Result<Built, ToolError> {
    let started = Instant::now();
    let held: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    let showing = AtomicBool::new(false);
    let relay = |line: &str| {
        let line = line.trim_end();
        let worth = [
            "Compiling",
            "Downloading",
            "Downloaded",
            "Updating",
            "Blocking",
        ]
        .iter()
        .any(|w| line.trim_start().starts_with(w));
        if !worth {
            return;
        }
        if showing.load(Ordering::Relaxed) {
            say.status(line);
            return;
        }
        let mut held = held.lock().unwrap_or_else(|p| p.into_inner());
        held.push(line.to_string());
        if started.elapsed() > QUIET_BUILD {
            showing.store(true, Ordering::Relaxed);
            // said once a run: the builds of one check (its tests, its picture) are one wait
            if !SAID_SLOW.swap(true, Ordering::Relaxed) {
                say.status(
                    "  compiling (a fresh handout's first build compiles the renderer's \
                     dependencies too: a minute or two; after that a save takes seconds)",
                );
            }
            for l in held.drain(..) {
                say.status(&l);
            }
        }
    };
    Build {
        project: root,
        packages: &PACKAGES,
        tests,
        bins,
        examples: &[],
        // the test profile for binaries too: cargo compiles the derive macros once per
        // profile, and the tests use this one
        profile: Some("test"),
        features: &[],
        target_dir: None,
        debug_info: true,
        locked: false,
        stderr: Stderr::Lines(&relay),
        wrapper: None,
    }
    .run()
}

/// Runs the test executable `exe` of the test target `target` in `dir` as every check does:
/// all its tests, within [`TEST_TIME_LIMIT`], without `WHITTED_BLESS` (no golden image is
/// rewritten) and with RUST_BACKTRACE=0 (the runner's: a student's RUST_BACKTRACE=1 would put
/// a stack in every message).
pub fn run_tests(target: &str, exe: &Path, dir: &Path) -> Result<TestRun, ToolError> {
    cargo::Run {
        target,
        exe,
        dir,
        args: &[],
        env: &[],
        env_remove: &["WHITTED_BLESS"],
        log: None,
        timeout: TEST_TIME_LIMIT,
    }
    .run()
}

/// Builds and runs the test targets `targets` into `run`; `false` when they did not build (the
/// error is in `run`).
pub(super) fn check_targets(
    root: &Path,
    targets: &[String],
    run: &mut TestRun,
    say: &Say,
) -> Result<bool, ToolError> {
    let built = build(root, targets, &[], say)?;
    if !built.success {
        let rendered = built
            .errors
            .first()
            .map_or_else(|| built.stderr.clone(), |d| d.rendered.clone());
        run.build_error = Some((built.first_error(), rendered));
        return Ok(false);
    }
    for target in targets {
        let exe = built.executables.get(target).ok_or_else(|| {
            ToolError::Cargo(format!(
                "cargo built no test executable for {}",
                layout::core_test_target(root, target).display()
            ))
        })?;
        let result = run_tests(target, exe, &root.join(layout::CORE))?;
        if let Some(why) = &result.unfinished {
            return Err(ToolError::Cargo(format!(
                "the tests of {} did not finish: {why}",
                layout::core_test_target(root, target).display()
            )));
        }
        run.merge(result);
    }
    Ok(true)
}
