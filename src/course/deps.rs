//! Which tests of a handout depend on which exercises, measured.
//!
//! A handout replaces an exercise's body by `todo!()`; a test fails then exactly when it runs
//! that body. The same happens when the body is *poisoned* (`if poisoned { todo!() }` first
//! thing, see [`super::prove`]), and poisoning needs one build for every exercise at once. So
//! [`measure`] copies the project, poisons every exercise behind the switch
//! `WHITTED_POISON`, builds the handout's test targets once, checks they all pass unpoisoned,
//! and then runs them with one exercise poisoned at a time: the tests that fail are the tests
//! that depend on it.
//!
//! The manifest states the same dependencies (each exercise's own tests `exC_K_…`, its
//! `needs`, and the `[[renders]]` tables that need it); [`check`] compares the two,
//! so a test that calls an exercise the manifest does not say it needs is caught, and so is a
//! dependency the manifest claims but the tests never exercise.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use super::Error;
use super::learn::test_name;
use super::manifest::Manifest;
use super::prove::{self, Options, TestOutcome};

/// A test, as `target::name` (`ch02_generic_objects::ex2_3_…`).
pub type TestId = String;

/// What poisoning each exercise did to the handout's tests.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Measured {
    /// Every test of the handout's targets.
    pub tests: BTreeSet<TestId>,
    /// For each manifest entry (in order), the tests that failed with it poisoned.
    pub failing: Vec<BTreeSet<TestId>>,
}

impl Measured {
    /// The tests that fail when the exercises `stripped` (manifest indices) are missing.
    #[must_use]
    pub fn expected(&self, stripped: &[usize]) -> BTreeSet<TestId> {
        stripped
            .iter()
            .flat_map(|&i| self.failing[i].iter().cloned())
            .collect()
    }
}

/// The tests the manifest says depend on entry `index`: the own tests of the exercise and of
/// every exercise that needs it (directly or through others), and the tests of every
/// `[[renders]]` table that needs it.
#[must_use]
pub fn declared(manifest: &Manifest, tests: &BTreeSet<TestId>, index: usize) -> BTreeSet<TestId> {
    let dependents = dependents(manifest, index);
    tests
        .iter()
        .filter(|t| {
            let name = test_name(t);
            let own = dependents
                .iter()
                .any(|&d| name.starts_with(&manifest.entries[d].exercise.test_prefix()));
            let render = manifest
                .renders
                .iter()
                .any(|r| r.needs.contains(&index) && r.matches(t));
            own || render
        })
        .cloned()
        .collect()
}

/// Entry `index` and every entry whose `needs` reach it.
#[must_use]
pub fn dependents(manifest: &Manifest, index: usize) -> BTreeSet<usize> {
    let mut out = BTreeSet::from([index]);
    loop {
        let before = out.len();
        for (i, e) in manifest.entries.iter().enumerate() {
            if e.exercise
                .needs
                .iter()
                .any(|id| out.iter().any(|&j| manifest.entries[j].exercise.id == *id))
            {
                out.insert(i);
            }
        }
        if out.len() == before {
            return out;
        }
    }
}

/// The differences between what was measured and what the manifest declares, one line per
/// exercise that disagrees (empty when they agree).
#[must_use]
pub fn check(manifest: &Manifest, measured: &Measured) -> Vec<String> {
    let mut out = Vec::new();
    for (i, e) in manifest.entries.iter().enumerate() {
        let declared = declared(manifest, &measured.tests, i);
        let failing = &measured.failing[i];
        let undeclared: Vec<&String> = failing.difference(&declared).collect();
        let unneeded: Vec<&String> = declared.difference(failing).collect();
        if !undeclared.is_empty() || !unneeded.is_empty() {
            out.push(format!(
                "exercise {} ({}): {}{}",
                e.exercise.id,
                e.function,
                if undeclared.is_empty() {
                    String::new()
                } else {
                    format!("fail without the manifest saying so: {undeclared:?}; ")
                },
                if unneeded.is_empty() {
                    String::new()
                } else {
                    format!(
                        "the manifest says they need it, yet they pass without it: {unneeded:?}"
                    )
                }
            ));
        }
    }
    out
}

/// Measures the dependencies of the handout's tests on each exercise (see the module's
/// documentation). `options.features` selects the build's features, `options.jobs` how many
/// runs go on at once.
pub fn measure(root: &Path, manifest: &Manifest, options: &Options) -> Result<Measured, Error> {
    let locations = prove::locate_all(root, manifest)?;
    let mut temp = tempfile::Builder::new()
        .prefix("whitted-deps-")
        .tempdir()
        .map_err(|e| Error::io(std::env::temp_dir(), e))?;
    temp.disable_cleanup(options.keep);
    let copy = temp.path().join("project");
    let runs = temp.path().join("runs");
    std::fs::create_dir_all(&runs).map_err(|e| Error::io(&runs, e))?;
    prove::copy_project(root, &copy)?;
    for (file, text) in prove::poisoned_sources(&copy, manifest, &locations)? {
        let path = copy.join(file);
        std::fs::write(&path, text).map_err(|e| Error::io(&path, e))?;
    }
    let lib = copy.join("src/lib.rs");
    let mut lib_text = std::fs::read_to_string(&lib).map_err(|e| Error::io(&lib, e))?;
    lib_text.push_str(prove::POISON_MODULE);
    std::fs::write(&lib, lib_text).map_err(|e| Error::io(&lib, e))?;
    let target_dir = options
        .target_dir
        .clone()
        .unwrap_or_else(|| root.join("target").join("prove"));
    let exes = prove::build_tests(
        &copy,
        &target_dir,
        &manifest.handout.tests,
        &options.features,
    )?;

    // one run of every target, with the entries `poison` poisoned (none for the baseline)
    let run_all = |poison: Option<usize>| -> Result<BTreeMap<TestId, TestOutcome>, Error> {
        let mut out = BTreeMap::new();
        for (target, exe) in &exes {
            let log = runs.join(format!(
                "{target}-{}",
                poison.map_or("none".into(), |k| k.to_string())
            ));
            let run = prove::run_tests(exe, &copy, None, poison, &log, options.timeout)?;
            if let Some(why) = run.unfinished {
                return Err(Error::Proof(format!(
                    "tests/{target} with exercise {} poisoned did not finish: {why}",
                    poison.map_or("none".into(), |k| manifest.entries[k].exercise.id.clone())
                )));
            }
            for (name, outcome) in run.results {
                out.insert(format!("{target}::{name}"), outcome);
            }
        }
        Ok(out)
    };
    let baseline = run_all(None)?;
    let red: Vec<&String> = baseline
        .iter()
        .filter(|(_, o)| **o == TestOutcome::Failed)
        .map(|(n, _)| n)
        .collect();
    if !red.is_empty() {
        return Err(Error::Proof(format!(
            "the handout's tests fail without any exercise missing: {red:?}"
        )));
    }
    let tests: BTreeSet<TestId> = baseline
        .iter()
        .filter(|(_, o)| **o == TestOutcome::Passed)
        .map(|(n, _)| n.clone())
        .collect();
    eprintln!(
        "deps: baseline green ({} tests); taking out each of {} exercises in turn",
        tests.len(),
        manifest.entries.len()
    );

    let next = AtomicUsize::new(0);
    let results: Mutex<BTreeMap<usize, BTreeSet<TestId>>> = Mutex::new(BTreeMap::new());
    let failure: Mutex<Option<Error>> = Mutex::new(None);
    std::thread::scope(|scope| {
        for _ in 0..options.jobs.max(1) {
            scope.spawn(|| {
                loop {
                    let k = next.fetch_add(1, Ordering::SeqCst);
                    if k >= manifest.entries.len() {
                        break;
                    }
                    match run_all(Some(k)) {
                        Ok(run) => {
                            let failed = run
                                .into_iter()
                                .filter(|(_, o)| *o == TestOutcome::Failed)
                                .map(|(n, _)| n)
                                .collect();
                            results
                                .lock()
                                .unwrap_or_else(|p| p.into_inner())
                                .insert(k, failed);
                        }
                        Err(e) => {
                            failure
                                .lock()
                                .unwrap_or_else(|p| p.into_inner())
                                .get_or_insert(e);
                            break;
                        }
                    }
                }
            });
        }
    });
    if let Some(e) = failure.into_inner().unwrap_or_else(|p| p.into_inner()) {
        return Err(e);
    }
    let results = results.into_inner().unwrap_or_else(|p| p.into_inner());
    Ok(Measured {
        tests,
        failing: results.into_values().collect(),
    })
}

/// The `needs` lines and `[[renders]]` tables the measurements call for. An exercise
/// `needs` the earlier exercises whose poisoning fails one of its own tests (minus those
/// reached through another need). The other tests are grouped by the exact set of exercises
/// they fail without; each group is one `[[renders]]` table, its tests written as
/// `target::chN_` prefixes where a whole prefix shares the set.
#[must_use]
pub fn suggest(manifest: &Manifest, measured: &Measured) -> Vec<String> {
    let n = manifest.entries.len();
    let own_of = |t: &str| {
        (0..n).find(|&e| test_name(t).starts_with(&manifest.entries[e].exercise.test_prefix()))
    };
    // needs[d] = the exercises whose poisoning fails one of d's own tests
    let mut needs: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); n];
    // for the other tests, the exercises each fails without
    let mut others: BTreeMap<&TestId, Vec<usize>> = BTreeMap::new();
    for (i, failing) in measured.failing.iter().enumerate() {
        for t in failing {
            match own_of(t) {
                Some(d) if d != i => {
                    needs[d].insert(i);
                }
                Some(_) => {}
                None => others.entry(t).or_default().push(i),
            }
        }
    }
    let reach = |from: usize| -> BTreeSet<usize> {
        let mut seen = BTreeSet::new();
        let mut stack: Vec<usize> = needs[from].iter().copied().collect();
        while let Some(x) = stack.pop() {
            if seen.insert(x) {
                stack.extend(needs[x].iter().copied());
            }
        }
        seen
    };
    let mut out = Vec::new();
    for (entry, own) in manifest.entries.iter().zip(&needs) {
        let direct: Vec<String> = own
            .iter()
            .copied()
            .filter(|&i| !own.iter().any(|&j| j != i && reach(j).contains(&i)))
            .map(|i| format!("{:?}", manifest.entries[i].exercise.id))
            .collect();
        if !direct.is_empty() {
            out.push(format!(
                "# {} {}\nneeds = [{}]",
                entry.exercise.id,
                entry.function,
                direct.join(", ")
            ));
        }
    }
    // group the other tests by what they need
    let mut groups: BTreeMap<Vec<usize>, Vec<&TestId>> = BTreeMap::new();
    for (t, set) in &others {
        groups.entry(set.clone()).or_default().push(t);
    }
    for (set, tests) in groups {
        let mut written: Vec<String> = Vec::new();
        for t in &tests {
            let (target, name) = t.split_once("::").unwrap_or(("", t));
            let prefix = name
                .split_once('_')
                .map(|(head, _)| format!("{target}::{head}_"));
            let whole = prefix.as_ref().filter(|p| {
                let all: Vec<&TestId> = measured
                    .tests
                    .iter()
                    .filter(|x| x.starts_with(p.as_str()))
                    .collect();
                all.iter().all(|x| tests.contains(x))
            });
            let entry = whole.cloned().unwrap_or_else(|| (*t).clone());
            if !written.contains(&entry) {
                written.push(entry);
            }
        }
        let ids = crate::course::manifest::compress_ids(&manifest.entries, &set);
        out.push(format!(
            "[[renders]]\ntests = [{}]\nneeds = [{}]",
            written
                .iter()
                .map(|w| format!("{w:?}"))
                .collect::<Vec<_>>()
                .join(", "),
            ids.iter()
                .map(|i| format!("{i:?}"))
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    out
}
