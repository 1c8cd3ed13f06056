//! The known mistakes in the tests: the copy with every mistake behind its switch
//! ([`crate::mistakes`]) builds the test targets that hold the mistakes' exercises' own tests,
//! and each mistake's exercise's tests run with it switched on. What each failing test prints
//! (its values, [`whitted_learn::known::values_of`]) is kept with the mistake in
//! `chapters/mistakes.json`, so that `cargo learn` tells the mistake from the exercise's
//! tests on the save that makes it ([`whitted_learn::known`]).
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Duration;

use crate::cargo::{Build, Built, Stderr};
use crate::manifest::Manifest;
use crate::mistakes::{self, Mutant};
use crate::{ToolError, layout};
use whitted_learn::known::failing_values;

/// How long one mistake's exercise's tests may run.
const TIME_LIMIT: Duration = Duration::from_secs(120);

/// Each mutant's failing tests of its own exercise, by mutant name: test name → values. Built
/// in the copy `copy` (made by [`mistakes::switch`]) into `target`, with the manifest
/// `manifest` and the map of `root`, which say which test target holds each exercise's tests.
pub(super) fn record(
    root: &Path,
    copy: &Path,
    target: &Path,
    manifest: &Manifest,
    mutants: &[Mutant],
) -> Result<BTreeMap<String, BTreeMap<String, String>>, ToolError> {
    let map = crate::deps::load_map(root, manifest)?;
    let target_of = whitted_learn::learn::targets_of(manifest, &map);
    let index = |m: &Mutant| {
        manifest.by_name(&m.exercise).ok_or_else(|| {
            ToolError::Usage(format!("mutant {}: no exercise {}", m.name, m.exercise))
        })
    };
    let mut targets: Vec<String> = Vec::new();
    for m in mutants {
        let i = index(m)?;
        let t = target_of[i].clone().ok_or_else(|| {
            ToolError::Usage(format!(
                "mutant {}: exercise {} has no test target",
                m.name, m.exercise
            ))
        })?;
        if !targets.contains(&t) {
            targets.push(t);
        }
    }
    println!(
        "building the tests of the mistakes' exercises ({}) with the mistakes behind a switch",
        targets.join(", ")
    );
    let built = build_copy(
        copy,
        target,
        &targets,
        &[],
        "the tests of the copy with the mistakes",
    )?;
    let mut out = BTreeMap::new();
    for m in mutants {
        let i = index(m)?;
        let t = target_of[i].clone().unwrap_or_default();
        let exe = built
            .executables
            .get(&t)
            .ok_or_else(|| ToolError::Build(format!("cargo built no test executable {t}")))?;
        let prefix = manifest.entries[i].exercise.test_prefix();
        let run = whitted_learn::cargo::Run {
            target: &t,
            exe,
            dir: &copy.join(layout::CORE),
            args: std::slice::from_ref(&prefix),
            env: &[(mistakes::SWITCH_VAR, m.name.clone())],
            env_remove: &["WHITTED_BLESS"],
            log: None,
            timeout: TIME_LIMIT,
        }
        .run()?;
        if let Some(why) = &run.unfinished {
            return Err(ToolError::Build(format!(
                "mistake {}: the tests of {} did not finish: {why}",
                m.name, m.exercise
            )));
        }
        let failing = failing_values(&run, &prefix);
        println!(
            "mistake {} ({}): {} of its exercise's tests fail",
            m.name,
            m.exercise,
            failing.len()
        );
        out.insert(m.name.clone(), failing);
    }
    Ok(out)
}

/// Builds, in the copy `copy` with the mistakes behind their switches, into `target`, the
/// renderer's test targets `tests` and the chapter binaries `bins` (the packages of each); an
/// error that names `what` when it does not build.
pub(super) fn build_copy(
    copy: &Path,
    target: &Path,
    tests: &[String],
    bins: &[String],
    what: &str,
) -> Result<Built, ToolError> {
    let packages: &[&str] = if bins.is_empty() {
        &[layout::CORE_PACKAGE]
    } else {
        &[layout::APP_PACKAGE]
    };
    let built = Build {
        project: copy,
        packages,
        tests,
        bins,
        examples: &[],
        profile: None,
        features: &[],
        target_dir: Some(target),
        debug_info: false,
        locked: true,
        stderr: Stderr::Inherit,
        wrapper: None,
    }
    .run()?;
    if !built.success {
        return Err(ToolError::Build(format!(
            "{what} does not build: {}",
            built.first_error()
        )));
    }
    Ok(built)
}
