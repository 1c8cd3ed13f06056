//! libtest's report read back: each test's outcome and each failure's message, gathered into
//! one [`TestRun`] keyed `target::name`.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::{BTreeMap, BTreeSet};

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
