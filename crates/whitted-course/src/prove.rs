//! The proof that every formula function is on every render path of its chapter.
//!
//! A render path is a test of the manifest's `[prove] test` target (`tests/render_paths.rs`):
//! it renders a chapter's scene one way (scalar, packets, an acceleration structure …) and
//! compares the image with a golden one. The proof works on a copy of the project, so the
//! working tree is never touched:
//!
//! 1. every file that git knows (tracked, or new and not ignored) is copied to a temporary
//!    directory (without git, every file outside `target/` and `.git/`);
//! 2. in the copy, every manifest function is put behind the poison switch ([`crate::poison`]);
//! 3. the test target is built once (`cargo test --no-run`), into `target/prove` of the real
//!    project so that the dependencies are compiled only the first time;
//! 4. the tests run once unpoisoned: all must pass, since a proof needs a green baseline;
//! 5. for each function, the tests of its chapter (the `[prove] filter`) run with
//!    `WHITTED_POISON=K`. The function is proven when at least one test ran and every one of
//!    them failed: no render path of the chapter can produce its image without calling it.
//!
//! Two functions are tried at a time, each run under a time limit, so that a poisoned loop
//! cannot hang the proof.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use super::cargo::{self, TestOutcome, TestRun};
use super::manifest::Manifest;
use super::{ToolError, poison};

/// How the poisoned copy is built and its tests run: the settings of the proof and of the
/// dependency measurement ([`crate::deps::measure`]).
#[derive(Clone, Debug)]
pub struct PoisonedRuns {
    /// Prove only these functions (manifest paths); empty means all.
    pub only: Vec<String>,
    /// Keep the temporary copy of the project (its path is in the report).
    pub keep: bool,
    /// How many test runs go on at once.
    pub jobs: usize,
    /// The time limit of one test run.
    pub timeout: Duration,
    /// Where cargo builds the copy; `None` is `target/prove` under the project's root.
    pub target_dir: Option<PathBuf>,
    /// Cargo features the copy is built with (`f32` proves the single-precision build).
    pub features: Vec<String>,
}

impl Default for PoisonedRuns {
    fn default() -> Self {
        Self {
            only: Vec::new(),
            keep: false,
            jobs: 2,
            timeout: Duration::from_secs(120),
            target_dir: None,
            features: Vec::new(),
        }
    }
}

/// What poisoning one function did to its chapter's render paths.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Every test of the chapter failed: the function is on every render path.
    Proven,
    /// These tests still passed with the function poisoned.
    NotOnPath(Vec<String>),
    /// No test matched the chapter's filter.
    NoTests(String),
    /// The run did not finish normally (time limit, crash); the reason.
    Unfinished(String),
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Verdict::Proven => write!(f, "proven"),
            Verdict::NotOnPath(passed) => write!(f, "NOT on path: {}", passed.join(", ")),
            Verdict::NoTests(filter) => write!(f, "NOT proven: no test matches {filter:?}"),
            Verdict::Unfinished(why) => write!(f, "NOT proven: {why}"),
        }
    }
}

/// The outcome for one manifest entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    /// The entry's index in the manifest (its poison number).
    pub index: usize,
    /// What poisoning it did.
    pub verdict: Verdict,
}

/// The proof's result.
#[derive(Clone, Debug)]
pub struct Report {
    /// One row per function tried, in the manifest's order.
    pub rows: Vec<Row>,
    /// The copy of the project, when it was kept.
    pub kept: Option<PathBuf>,
    /// Time spent copying, editing and building.
    pub build_time: Duration,
    /// Time spent running the tests (the baseline and every poisoned run).
    pub run_time: Duration,
}

impl Report {
    /// How many functions were proven.
    #[must_use]
    pub fn proven(&self) -> usize {
        self.rows
            .iter()
            .filter(|r| r.verdict == Verdict::Proven)
            .count()
    }

    /// Writes the table (chapter, function, verdict) and the summary line.
    pub fn write_table(&self, manifest: &Manifest, out: &mut dyn Write) -> std::io::Result<()> {
        let width = self
            .rows
            .iter()
            .map(|r| manifest.entries[r.index].function.chars().count())
            .max()
            .unwrap_or(0)
            .max("function".len());
        writeln!(out, "chapter  {:<width$}  result", "function")?;
        for row in &self.rows {
            let entry = &manifest.entries[row.index];
            writeln!(
                out,
                "{:<7}  {:<width$}  {}",
                entry.chapter, entry.function, row.verdict
            )?;
        }
        writeln!(
            out,
            "{} of {} formula functions proven on every render path of their chapter",
            self.proven(),
            self.rows.len()
        )
    }
}

/// Runs the proof for the project at `root` (the directory of `Cargo.toml`). Progress goes to
/// stderr; the table is the caller's to print with [`Report::write_table`].
pub fn prove(
    root: &Path,
    manifest: &Manifest,
    options: &PoisonedRuns,
) -> Result<Report, ToolError> {
    let started = Instant::now();
    let selected = select(manifest, &options.only)?;
    let locations = crate::source::locate_all(root, manifest)?;

    // the copy, poisoned
    let poisoned =
        poison::PoisonedCopy::new(root, manifest, &locations, "whitted-prove-", options.keep)?;
    let (temp, copy, runs) = (&poisoned.temp, &poisoned.project, &poisoned.runs);
    eprintln!(
        "proof: {} files copied to {}; poisoning {} functions",
        poisoned.files,
        copy.display(),
        manifest.entries.len()
    );

    // one build
    let target_dir = options
        .target_dir
        .clone()
        .unwrap_or_else(|| root.join("target").join("prove"));
    let exe = poison::build_one(copy, &target_dir, &manifest.prove.test, &options.features)?;
    let build_time = started.elapsed();

    // the baseline, then each function
    let ran = Instant::now();
    let target = manifest.prove.test.as_str();
    let baseline = poison::run_tests(
        target,
        &exe,
        copy,
        None,
        None,
        &runs.join("baseline"),
        options.timeout,
    )?;
    let red: Vec<&str> = baseline
        .with(TestOutcome::Failed)
        .into_iter()
        .map(|n| cargo::test_name(n))
        .collect();
    if let Some(why) = &baseline.unfinished {
        return Err(ToolError::Baseline(format!(
            "the unpoisoned run of tests/{}.rs did not finish ({why}); a proof needs a green baseline",
            manifest.prove.test
        )));
    }
    if !red.is_empty() || !baseline.success {
        return Err(ToolError::Baseline(format!(
            "tests/{}.rs fails without any poison ({}); a proof needs a green baseline: run `cargo test --test {}`",
            manifest.prove.test,
            if red.is_empty() {
                format!(
                    "its output: {} (kept with --keep)",
                    runs.join("baseline.out").display()
                )
            } else {
                red.join(", ")
            },
            manifest.prove.test
        )));
    }
    if baseline.outcomes.is_empty() {
        return Err(ToolError::Baseline(format!(
            "tests/{}.rs has no tests: there is no render path to prove anything on",
            manifest.prove.test
        )));
    }
    eprintln!(
        "proof: baseline green ({} tests); poisoning {} functions, {} at a time",
        baseline.outcomes.len(),
        selected.len(),
        options.jobs.max(1)
    );

    let done = AtomicUsize::new(0);
    let rows = crate::parallel::in_parallel(&selected, options.jobs, |index| {
        let entry = &manifest.entries[index];
        let filter = manifest.prove.filter_for(entry.chapter);
        let log = runs.join(index.to_string());
        let run = poison::run_tests(
            target,
            &exe,
            copy,
            Some(&filter),
            Some(index),
            &log,
            options.timeout,
        )?;
        let verdict = verdict(&run, &filter);
        let n = done.fetch_add(1, Ordering::SeqCst) + 1;
        eprintln!("[{n}/{}] {}: {verdict}", selected.len(), entry.function);
        Ok(Row { index, verdict })
    })?;

    let kept = options.keep.then(|| temp.path().to_path_buf());
    Ok(Report {
        rows,
        kept,
        build_time,
        run_time: ran.elapsed(),
    })
}

/// The indices of the entries to prove: those named by `only`, or all.
fn select(manifest: &Manifest, only: &[String]) -> Result<Vec<usize>, ToolError> {
    if only.is_empty() {
        return Ok((0..manifest.entries.len()).collect());
    }
    let mut selected = Vec::new();
    for path in only {
        let index = manifest
            .entries
            .iter()
            .position(|e| &e.function == path)
            .ok_or_else(|| {
                ToolError::Usage(format!(
                    "--only {path}: no such function in {}",
                    manifest.file
                ))
            })?;
        if !selected.contains(&index) {
            selected.push(index);
        }
    }
    selected.sort_unstable();
    Ok(selected)
}

/// What a poisoned run proves.
fn verdict(run: &TestRun, filter: &str) -> Verdict {
    let passed: Vec<String> = run
        .with(TestOutcome::Passed)
        .into_iter()
        .map(|n| cargo::test_name(n).to_string())
        .collect();
    let failed = run.with(TestOutcome::Failed).len();
    if !passed.is_empty() {
        Verdict::NotOnPath(passed)
    } else if let Some(why) = &run.unfinished {
        Verdict::Unfinished(why.clone())
    } else if failed == 0 {
        Verdict::NoTests(filter.to_string())
    } else {
        Verdict::Proven
    }
}
