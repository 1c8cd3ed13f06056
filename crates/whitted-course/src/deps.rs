//! Which tests of a handout depend on which exercises: measured, and written down.
//!
//! A handout replaces an exercise's body by `todo!()`; a test fails then exactly when it runs
//! that body. The same happens when the body is *poisoned* (`if poisoned { todo!() }` first
//! thing in its solution region, see [`super::prove`]), and poisoning needs one build for
//! every exercise at once. So [`measure`] copies the project, poisons every exercise behind
//! the switch `WHITTED_POISON`, builds the handout's test targets once, checks they all pass
//! unpoisoned, and then runs them with one exercise poisoned at a time: the tests that fail
//! are the tests that depend on it.
//!
//! The result is written down in [`MAP_PATH`], `chapters/exercise-tests.toml`, next to the
//! manifest: each `[[tests]]` table names tests (as `target::name`, or a prefix of it) and
//! the exercises they run, by name. `whitted formulas deps --write` writes it; `whitted formulas
//! --deps` measures again and [`check`]s the file, which CI does, so the list of what a
//! handout fails cannot drift from the tests. A handout of the exercises S fails exactly the
//! tests whose table names one of S ([`expected`]).
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use super::ToolError;
use super::cargo::{TestOutcome, TestRun};
use super::manifest::Manifest;
use super::poison;
use super::prove::PoisonedRuns;
use super::source;

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

pub use whitted_learn::map::{Group, MAP_PATH, TestId, expected, load_map, needs_of, parse_map};

/// The tests that fail when the exercises `stripped` (manifest indices) are missing and each
/// exercise is judged alone (`whitted grade`'s default, [`crate::grade::Judging::Alone`]): an
/// exercise's own test (`ex_NAME_…`) runs the student's body of that exercise only, so it fails
/// when that exercise is stripped and the test needs it; a test of no exercise runs the student's
/// whole road, so it fails when it needs any stripped exercise ([`expected`]).
#[must_use]
pub fn expected_alone(
    manifest: &Manifest,
    map: &[Group],
    tests: &BTreeSet<TestId>,
    stripped: &[usize],
) -> BTreeSet<TestId> {
    tests
        .iter()
        .filter(|t| {
            let needs = needs_of(map, t);
            match manifest.exercise_of_test(crate::cargo::test_name(t)) {
                Some(own) => stripped.contains(&own) && needs.contains(&own),
                None => needs.iter().any(|i| stripped.contains(i)),
            }
        })
        .cloned()
        .collect()
}

/// The differences between what was measured and what the map says, one line per exercise
/// that disagrees, and one per test the map does not name (empty when they agree).
#[must_use]
pub fn check(manifest: &Manifest, map: &[Group], measured: &Measured) -> Vec<String> {
    let mut out = Vec::new();
    for t in &measured.tests {
        if !map.iter().any(|g| g.matches(t)) {
            out.push(format!("test {t} is not in {MAP_PATH}"));
        }
    }
    for (i, e) in manifest.entries.iter().enumerate() {
        let said = expected(map, &measured.tests, &[i]);
        let failing = &measured.failing[i];
        let unsaid: Vec<&String> = failing.difference(&said).collect();
        let wrong: Vec<&String> = said.difference(failing).collect();
        if !unsaid.is_empty() || !wrong.is_empty() {
            out.push(format!(
                "exercise {} ({}): {}{}",
                e.exercise.id,
                e.function,
                if unsaid.is_empty() {
                    String::new()
                } else {
                    format!("fail without it, the map does not say so: {unsaid:?}; ")
                },
                if wrong.is_empty() {
                    String::new()
                } else {
                    format!("the map says they need it, yet they pass without it: {wrong:?}")
                }
            ));
        }
    }
    out
}

/// Measures the dependencies of the handout's tests on each exercise (see the module's
/// documentation). `options.features` selects the build's features, `options.jobs` how many
/// runs go on at once.
pub fn measure(
    root: &Path,
    manifest: &Manifest,
    options: &PoisonedRuns,
) -> Result<Measured, ToolError> {
    let locations = source::locate_all(root, manifest)?;
    let poisoned =
        poison::PoisonedCopy::new(root, manifest, &locations, "whitted-deps-", options.keep)?;
    let (copy, runs) = (&poisoned.project, &poisoned.runs);
    let target_dir = options
        .target_dir
        .clone()
        .unwrap_or_else(|| root.join("target").join("prove"));
    let exes = poison::build_tests(
        copy,
        &target_dir,
        &manifest.handout.tests,
        &options.features,
    )?;

    // one run of every target, with the entries `poison` poisoned (none for the baseline)
    let run_all = |poison: Option<usize>| -> Result<TestRun, ToolError> {
        let mut all = TestRun::default();
        for (target, exe) in &exes {
            let log = runs.join(format!(
                "{target}-{}",
                poison.map_or("none".into(), |k| k.to_string())
            ));
            let run = poison::run_tests(target, exe, copy, None, poison, &log, options.timeout)?;
            if let Some(why) = &run.unfinished {
                return Err(ToolError::Cargo(format!(
                    "tests/{target} with exercise {} poisoned did not finish: {why}",
                    poison.map_or("none".into(), |k| manifest.entries[k].exercise.name.clone())
                )));
            }
            all.merge(run);
        }
        Ok(all)
    };
    let baseline = run_all(None)?;
    let red = baseline.with(TestOutcome::Failed);
    if !red.is_empty() {
        return Err(ToolError::Baseline(format!(
            "the handout's tests fail without any exercise missing: {red:?}"
        )));
    }
    let tests: BTreeSet<TestId> = baseline
        .with(TestOutcome::Passed)
        .into_iter()
        .cloned()
        .collect();
    eprintln!(
        "deps: baseline green ({} tests); taking out each of {} exercises in turn",
        tests.len(),
        manifest.entries.len()
    );

    let all: Vec<usize> = (0..manifest.entries.len()).collect();
    let failing = crate::parallel::in_parallel(&all, options.jobs, |k| {
        Ok(run_all(Some(k))?
            .with(TestOutcome::Failed)
            .into_iter()
            .cloned()
            .collect())
    })?;
    Ok(Measured { tests, failing })
}

/// The map's text for the measurements: every test, grouped by the exact set of exercises
/// it fails without (named in the manifest's order), each group written with
/// `target::prefix` where every test of a prefix shares the set: an exercise's test prefix
/// (`ex_viewing_basis_`), or else the name's first word (`ch1_`, `centre_`).
#[must_use]
pub fn map_text(manifest: &Manifest, measured: &Measured) -> String {
    let mut needs: BTreeMap<&TestId, Vec<usize>> =
        measured.tests.iter().map(|t| (t, Vec::new())).collect();
    for (i, failing) in measured.failing.iter().enumerate() {
        for t in failing {
            if let Some(n) = needs.get_mut(t) {
                n.push(i);
            }
        }
    }
    let mut groups: BTreeMap<Vec<usize>, Vec<&TestId>> = BTreeMap::new();
    for (t, set) in &needs {
        groups.entry(set.clone()).or_default().push(t);
    }
    let mut out = String::from(
        "# Which exercises each test of a handout runs: without any one of them, the test fails.\n\
         # Measured by `whitted formulas deps --write` (each exercise poisoned in turn); do not\n\
         # edit. CI measures again and checks this file (`whitted formulas deps`).\n",
    );
    // the groups in the order of their first exercise, tests that need none last
    let mut ordered: Vec<(Vec<usize>, Vec<&TestId>)> = groups.into_iter().collect();
    ordered.sort_by_key(|(set, _)| (set.is_empty(), set.clone()));
    for (set, tests) in ordered {
        let mut written: Vec<String> = Vec::new();
        for t in &tests {
            let (target, name) = t.split_once("::").unwrap_or(("", t));
            let prefix = match manifest.exercise_of_test(crate::cargo::test_name(name)) {
                Some(e) => {
                    let own = crate::cargo::test_name(name);
                    let module = &name[..name.len() - own.len()];
                    Some(format!(
                        "{target}::{module}{}",
                        manifest.entries[e].exercise.test_prefix()
                    ))
                }
                None => name
                    .split_once('_')
                    .map(|(head, _)| format!("{target}::{head}_")),
            };
            let whole = prefix.filter(|p| {
                measured
                    .tests
                    .iter()
                    .filter(|x| x.starts_with(p.as_str()))
                    .all(|x| tests.contains(&x))
            });
            let entry = whole.unwrap_or_else(|| (*t).clone());
            if !written.contains(&entry) {
                written.push(entry);
            }
        }
        out += &format!(
            "\n[[tests]]\ntests = [\n{}]\nneeds = [{}]\n",
            written
                .iter()
                .map(|w| format!("    {w:?},\n"))
                .collect::<String>(),
            wrapped(
                set.iter()
                    .map(|&i| format!("{:?}", manifest.entries[i].exercise.name))
            )
        );
    }
    out
}

/// Items joined by `, `, on lines of at most 100 characters after the first (indented by 4)
/// when they do not fit on one.
fn wrapped(items: impl Iterator<Item = String>) -> String {
    let items: Vec<String> = items.collect();
    let one = items.join(", ");
    if one.len() <= 88 {
        return one;
    }
    let mut out = String::from("\n   ");
    let mut width = 3;
    for item in items {
        if width + item.len() + 2 > 100 {
            out += "\n   ";
            width = 3;
        }
        out += " ";
        out += &item;
        out += ",";
        width += item.len() + 2;
    }
    out + "\n"
}
