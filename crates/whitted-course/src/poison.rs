//! The poisoned copy of the project, on which the proof and the dependency measurement run:
//! every manifest function behind a switch that makes it panic (`WHITTED_POISON=K`), built
//! once, its tests run with one function poisoned at a time.
//!
//! In the copy, each manifest function `K` gets a first statement
//! `if crate::__poison::on(K) { todo!("poisoned: PATH") }` — first thing in its solution region,
//! so that poisoning a function does what a handout's `todo!()` does — and the renderer's
//! `lib.rs` gets the hidden module `__poison`, whose `on(k)` is true when the environment
//! variable `WHITTED_POISON` holds `k` (read once). The copy is built into `target/prove` of the
//! real project, so that the dependencies are compiled only the first time.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

use crate::cargo::{self, Build, Stderr, TestRun};
use crate::manifest::Manifest;
use crate::source::Location;
use crate::{ToolError, layout};

/// The environment variable that names the poisoned function's number.
pub const POISON_VAR: &str = "WHITTED_POISON";
/// The statement that poisons function number `index` (its path is `function`).
#[must_use]
pub fn guard(index: usize, function: &str) -> String {
    format!(" if crate::__poison::on({index}) {{ todo!(\"poisoned: {function}\") }}")
}
/// The module appended to the copy's `src/lib.rs`.
pub const POISON_MODULE: &str = r#"
/// The poison switch of `whitted formulas prove`; it exists only in the proof's copy.
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
/// Builds the test target `test` of the project at `project` into `target_dir`; returns the
/// test executable.
pub fn build_one(
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
        examples: &[],
        profile: None,
        features,
        target_dir: Some(target_dir),
        // no debug info: a panic's message is all the proof reads (measured in a single
        // crate: a warm build 60 s → 26 s, each test binary 100 MB → 4 MB)
        debug_info: false,
        locked: true,
        stderr: Stderr::Inherit,
        wrapper: None,
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
pub fn run_tests(
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
