//! The proof that every formula function is on every render path of its chapter.
//!
//! A render path is a test of the manifest's `[prove] test` target (`tests/render_paths.rs`):
//! it renders a chapter's scene one way (scalar, packets, an acceleration structure …) and
//! compares the image with a golden one. The proof works on a copy of the project, so the
//! working tree is never touched:
//!
//! 1. every file that git knows (tracked, or new and not ignored) is copied to a temporary
//!    directory (without git, every file outside `target/` and `.git/`);
//! 2. in the copy, each manifest function `K` gets a first statement
//!    `if crate::__poison::on(K) { todo!("poisoned: PATH") }`, and `src/lib.rs` gets the hidden
//!    module `__poison`, whose `on(k)` is true when the environment variable `WHITTED_POISON`
//!    holds `k` (read once);
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

use std::collections::BTreeMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use super::ToolError;
use super::cargo::TestOutcome;
use super::cargo::{self, Build, Stderr, TestRun};
use super::layout;
use super::manifest::Manifest;
use super::source::{self, Location};

/// The environment variable that names the poisoned function's number.
pub const POISON_VAR: &str = "WHITTED_POISON";

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

/// The statement that poisons function number `index` (its path is `function`).
#[must_use]
pub fn guard(index: usize, function: &str) -> String {
    format!(" if crate::__poison::on({index}) {{ todo!(\"poisoned: {function}\") }}")
}

/// The module appended to the copy's `src/lib.rs`.
pub const POISON_MODULE: &str = r#"

/// The poison switch of `whitted formulas --prove`; it exists only in the proof's copy.
#[doc(hidden)]
pub mod __poison {
    /// Whether formula function `k` is poisoned: `WHITTED_POISON` lists it (read once), as
    /// numbers and ranges: `3`, `3,7`, `10-48`.
    pub fn on(k: usize) -> bool {
        static POISONED: std::sync::OnceLock<Vec<(usize, usize)>> = std::sync::OnceLock::new();
        POISONED
            .get_or_init(|| {
                let text = std::env::var("WHITTED_POISON").unwrap_or_default();
                text.split(',')
                    .filter_map(|part| {
                        let (a, b) = part.split_once('-').unwrap_or((part, part));
                        Some((a.trim().parse().ok()?, b.trim().parse().ok()?))
                    })
                    .collect()
            })
            .iter()
            .any(|&(a, b)| (a..=b).contains(&k))
    }
}
"#;

/// Finds every manifest function under `root`. An error names the entry and the file.
pub fn locate_all(root: &Path, manifest: &Manifest) -> Result<Vec<Location>, ToolError> {
    manifest
        .entries
        .iter()
        .map(|entry| {
            let found =
                source::locate(root, &entry.function).map_err(|message| ToolError::Function {
                    manifest: manifest.file.clone(),
                    line: entry.line,
                    function: entry.function.clone(),
                    message,
                })?;
            if found.is_const {
                return Err(ToolError::Function {
                    manifest: manifest.file.clone(),
                    line: entry.line,
                    function: entry.function.clone(),
                    message: format!(
                        "is a const fn ({}:{}): its body cannot test the poison switch",
                        found.file.display(),
                        found.line
                    ),
                });
            }
            Ok(found)
        })
        .collect()
}

/// The poisoned text of each source file that holds manifest functions: every body at
/// `locations` (in manifest order) gets its guard — first thing in the exercise's solution
/// region when the body has one (so that poisoning a function does what a handout's
/// `todo!()` does, and code before the region, such as a chapter's stage check, still runs),
/// else first thing in the body. Files are read under `root`.
pub fn poisoned_sources(
    root: &Path,
    manifest: &Manifest,
    locations: &[Location],
) -> Result<BTreeMap<PathBuf, String>, ToolError> {
    let mut by_file: BTreeMap<PathBuf, Vec<(usize, &Location)>> = BTreeMap::new();
    for (index, at) in locations.iter().enumerate() {
        by_file
            .entry(at.file.clone())
            .or_default()
            .push((index, at));
    }
    by_file
        .into_iter()
        .map(|(file, found)| {
            let path = root.join(&file);
            let text = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
            let mut inserts: Vec<(usize, String)> = Vec::new();
            for (index, at) in found {
                let entry = &manifest.entries[index];
                let guard = guard(index, &entry.function);
                if text
                    .get(at.body.clone())
                    .is_none_or(|b| !b.starts_with('{'))
                {
                    return Err(ToolError::Markers(format!(
                        "{}: bytes {:?} are not the body of {}",
                        file.display(),
                        at.body,
                        entry.function
                    )));
                }
                inserts.push(match region_start(&text, at, &entry.exercise.name) {
                    Some((offset, indent)) => (offset, format!("{indent}{}\n", guard.trim_start())),
                    // no region: right after the body's opening brace
                    None => (at.body.start + 1, guard),
                });
            }
            // from the end, so that the offsets before each insertion stay right
            let mut edited = text;
            inserts.sort_by_key(|(offset, _)| std::cmp::Reverse(*offset));
            for (offset, line) in inserts {
                edited.insert_str(offset, &line);
            }
            Ok((file, edited))
        })
        .collect()
}

/// Where the solution region `// BEGIN SOLUTION name` of the body at `at` starts its code: the
/// byte after the marker line, and the marker's indentation.
fn region_start(text: &str, at: &Location, name: &str) -> Option<(usize, String)> {
    let body = text.get(at.body.clone())?;
    let mut offset = at.body.start;
    for line in body.split_inclusive('\n') {
        let trimmed = line.trim();
        if trimmed
            .strip_prefix(super::handout::BEGIN)
            .is_some_and(|rest| rest.trim() == name)
        {
            let indent = line[..line.len() - line.trim_start().len()].to_string();
            return Some((offset + line.len(), indent));
        }
        offset += line.len();
    }
    None
}

/// A copy of the project in a temporary directory, every manifest function behind the poison
/// switch (see [`poisoned_sources`] and [`POISON_MODULE`]), and a directory for test runs'
/// output beside it.
pub struct PoisonedCopy {
    /// The temporary directory (removed when dropped, unless kept).
    pub temp: tempfile::TempDir,
    /// The copy of the project.
    pub project: PathBuf,
    /// Where the test runs' output goes.
    pub runs: PathBuf,
    /// How many files were copied.
    pub files: usize,
}

impl PoisonedCopy {
    /// Copies the project at `root` into a new temporary directory named `prefix…`, poisons
    /// the functions at `locations` (in manifest order) and adds the switch to `src/lib.rs`.
    /// `keep` keeps the directory, even when a later step fails.
    pub fn new(
        root: &Path,
        manifest: &Manifest,
        locations: &[Location],
        prefix: &str,
        keep: bool,
    ) -> Result<Self, ToolError> {
        let mut temp = tempfile::Builder::new()
            .prefix(prefix)
            .tempdir()
            .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
        temp.disable_cleanup(keep);
        let project = temp.path().join("project");
        let runs = temp.path().join("runs");
        std::fs::create_dir_all(&runs).map_err(|e| ToolError::io(&runs, e))?;
        let files = crate::files::copy_project(root, &project)?;
        for (file, text) in poisoned_sources(&project, manifest, locations)? {
            let path = project.join(file);
            std::fs::write(&path, text).map_err(|e| ToolError::io(&path, e))?;
        }
        let lib = project.join(layout::core_lib());
        let mut lib_text = std::fs::read_to_string(&lib).map_err(|e| ToolError::io(&lib, e))?;
        lib_text.push_str(POISON_MODULE);
        std::fs::write(&lib, lib_text).map_err(|e| ToolError::io(&lib, e))?;
        Ok(Self {
            temp,
            project,
            runs,
            files,
        })
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
    let locations = locate_all(root, manifest)?;

    // the copy, poisoned
    let poisoned = PoisonedCopy::new(root, manifest, &locations, "whitted-prove-", options.keep)?;
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
    let exe = build(copy, &target_dir, &manifest.prove.test, &options.features)?;
    let build_time = started.elapsed();

    // the baseline, then each function
    let ran = Instant::now();
    let target = manifest.prove.test.as_str();
    let baseline = run_tests(
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
        let run = run_tests(
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

/// Builds the test target `test` of the project at `project` into `target_dir`; returns the
/// test executable.
fn build(
    project: &Path,
    target_dir: &Path,
    test: &str,
    features: &[String],
) -> Result<PathBuf, ToolError> {
    let mut built = build_tests(project, target_dir, &[test.to_string()], features)?;
    built.remove(test).ok_or_else(|| {
        ToolError::Build(format!(
            "cargo built no test executable for {}",
            layout::core_test_file(test).display()
        ))
    })
}

/// Builds the renderer's test targets `tests` of the project at `project` into `target_dir`;
/// returns each one's executable, by target name. Cargo's lines go to stderr.
pub fn build_tests(
    project: &Path,
    target_dir: &Path,
    tests: &[String],
    features: &[String],
) -> Result<BTreeMap<String, PathBuf>, ToolError> {
    let test = tests.join(", ");
    eprintln!(
        "proof: building the poisoned copy's tests ({test}) into {}{}",
        target_dir.display(),
        if features.is_empty() {
            String::new()
        } else {
            format!(" with --features {}", features.join(","))
        }
    );
    let built = Build {
        project,
        packages: &[layout::CORE_PACKAGE],
        tests,
        bins: &[],
        profile: None,
        features,
        target_dir: Some(target_dir),
        // no debug info: a panic's message is all the proof reads (measured in a single
        // crate: a warm build 60 s → 26 s, each test binary 100 MB → 4 MB)
        debug_info: false,
        locked: true,
        stderr: Stderr::Inherit,
    }
    .run()?;
    let exes: BTreeMap<String, PathBuf> = built
        .executables
        .into_iter()
        .filter(|(name, _)| tests.contains(name))
        .collect();
    if built.success && exes.len() == tests.len() {
        return Ok(exes);
    }
    for error in &built.errors {
        eprint!("{}", error.rendered);
    }
    Err(ToolError::Build(format!(
        "`cargo test --no-run` of tests {test} fails in the poisoned copy; cargo's and the compiler's messages are above"
    )))
}

/// Runs the test executable of `target` from `project`, with a test-name filter and a
/// poisoned function (none for the baseline); its output goes to `log.out` and `log.err`.
pub(crate) fn run_tests(
    target: &str,
    exe: &Path,
    project: &Path,
    filter: Option<&str>,
    poison: Option<usize>,
    log: &Path,
    timeout: Duration,
) -> Result<TestRun, ToolError> {
    let mut args: Vec<String> = filter.map(str::to_string).into_iter().collect();
    args.extend(["--test-threads".to_string(), "2".to_string()]);
    let env: Vec<(&str, String)> = poison
        .map(|k| (POISON_VAR, k.to_string()))
        .into_iter()
        .collect();
    cargo::Run {
        target,
        exe,
        dir: project,
        args: &args,
        env: &env,
        // a blessing run would overwrite the goldens and pass
        env_remove: &[POISON_VAR, "WHITTED_BLESS"],
        log: Some(log),
        timeout,
    }
    .run()
}
