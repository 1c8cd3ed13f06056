//! `whitted grade`: a student's copy graded by the instructor's tests, points from the
//! manifest.
//!
//! What is graded is the student's code and nothing else: the body of each exercise, the lines
//! between `// BEGIN SOLUTION sphere_coefficients` and `// END SOLUTION` in the student's files. Those bodies
//! are put into a copy of the **instructor's** project — its tests, its manifest, its
//! `Cargo.lock`, its code around the exercises — so a student who edits a test, the manifest
//! or the renderer gains nothing. An exercise whose markers are missing counts as not written.
//! With a build directory ([`GradeSetup::target_dir`]) the copy is kept beside it and rewritten
//! file by file for each submission, so that cargo recompiles only the bodies that differ from
//! the last submission's; without one, it is a fresh temporary directory.
//!
//! Then, in that copy:
//!
//! 1. **Build.** An exercise whose body does not compile is put back to its `todo!()` and the
//!    build is tried again, so a compile error costs only the exercise it is in; its first
//!    error goes into the report.
//! 2. **Run** every test of the graded chapters with cargo-nextest, each test in its own
//!    process with its own time limit: a `todo!()`, a panic, a stack overflow, an abort or an
//!    endless loop fails the tests it touches and no others.
//! 3. **Score.** An exercise's points ([`super::manifest::Exercise::points`]) are shared
//!    equally by its tests, the ones named after it (`ex_sphere_coefficients_…`), public and
//!    hidden alike.
//!
//! Hidden tests are the instructor's own test files (`--hidden DIR`, each `*.rs` a test target
//! added to the copy as `tests/hidden_NAME.rs`), compiled against the same public API. Their
//! tests follow the same naming, so they count for the exercise they name; reports for
//! students show their points, never their names or messages ([`super::report`]).
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use super::cargo::test_name;
use super::handout::{self, BEGIN, END, Region};
use super::manifest::Manifest;
use super::{ToolError, cargo, files, layout};

/// The nextest profile the grader writes into the copy: no retries, no fail-fast, a time
/// limit per test, and a JUnit file the grader reads.
pub const NEXTEST_PROFILE: &str = "grading";

/// Where nextest keeps its reports, in the graded copy.
const STORE: &str = "nextest-store";

/// The graded copy's directory, inside the build directory when grading has one.
const COPY: &str = "graded-copy";

/// The default time limit of one test.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_secs(20);

/// How a grading is set up: which chapter, the hidden tests, the time limit, where it builds.
#[derive(Clone, Debug)]
pub struct GradeSetup {
    /// Grade only this chapter (its exercises and its test file); all five when `None`.
    pub chapter: Option<u8>,
    /// The instructor's hidden tests: a directory of `*.rs` test files.
    pub hidden: Option<PathBuf>,
    /// The time limit of each test.
    pub timeout: Duration,
    /// Where cargo builds, kept from one grading to the next so the dependencies are built
    /// once, with the graded copy beside the build (a class gives each worker its own
    /// directory under it); a fresh copy with its own `target/` when `None`. Never to be used
    /// by two gradings at once.
    pub target_dir: Option<PathBuf>,
    /// Keep the graded copy (its path is printed) instead of removing it.
    pub keep: bool,
}

impl Default for GradeSetup {
    fn default() -> Self {
        Self {
            chapter: None,
            hidden: None,
            timeout: DEFAULT_TIMEOUT,
            target_dir: None,
            keep: false,
        }
    }
}

/// How one test ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// It passed.
    Passed,
    /// It failed: an assertion, a panic, a `todo!()`.
    Failed,
    /// It ran past its time limit and was stopped.
    TimedOut,
    /// Its process died: a stack overflow, an abort, a signal.
    Crashed,
}

impl Status {
    /// The word for reports.
    #[must_use]
    pub fn word(&self) -> &'static str {
        match self {
            Status::Passed => "passed",
            Status::Failed => "failed",
            Status::TimedOut => "timed out",
            Status::Crashed => "crashed",
        }
    }
}

/// One test's result.
#[derive(Clone, Debug, PartialEq)]
pub struct TestResult {
    /// The test's name (`ex_sphere_discriminant_…`).
    pub name: String,
    /// Its test target (`ch02_generic_objects`, `hidden_extra`).
    pub target: String,
    /// The manifest entry of the exercise it belongs to, if its name says one.
    pub exercise: Option<usize>,
    /// Whether it is one of the instructor's hidden tests.
    pub hidden: bool,
    /// How it ended.
    pub status: Status,
    /// Why it failed, in a line or two (empty when it passed).
    pub message: String,
}

/// One exercise's points.
#[derive(Clone, Debug, PartialEq)]
pub struct ExerciseScore {
    /// The manifest entry.
    pub entry: usize,
    /// Points earned.
    pub score: f64,
    /// Points possible.
    pub max: f64,
    /// Its tests that passed.
    pub passed: usize,
    /// Its tests.
    pub total: usize,
    /// What the grader noticed: the body did not compile, its markers were missing …
    pub note: Option<String>,
}

/// A graded submission.
#[derive(Clone, Debug, PartialEq)]
pub struct Grade {
    /// The submission's name (its directory's name).
    pub student: String,
    /// The chapters graded.
    pub chapters: Vec<u8>,
    /// The exercises of those chapters, in manifest order.
    pub exercises: Vec<ExerciseScore>,
    /// Every test run.
    pub tests: Vec<TestResult>,
    /// Remarks about the whole submission (it did not build at all …).
    pub notes: Vec<String>,
    /// How long grading took.
    pub elapsed: Duration,
}

impl Grade {
    /// Points earned.
    #[must_use]
    pub fn score(&self) -> f64 {
        self.exercises.iter().map(|e| e.score).sum()
    }

    /// Points possible.
    #[must_use]
    pub fn max(&self) -> f64 {
        self.exercises.iter().map(|e| e.max).sum()
    }

    /// Points earned and possible in chapter `chapter`.
    #[must_use]
    pub fn chapter(&self, manifest: &Manifest, chapter: u8) -> (f64, f64) {
        self.exercises
            .iter()
            .filter(|e| manifest.entries[e.entry].chapter == chapter)
            .fold((0.0, 0.0), |(s, m), e| (s + e.score, m + e.max))
    }
}

/// The body a student wrote for the region `r` of the exercise named `name`: the lines between
/// the region's markers in the same file of the submission. `Err` says why there is none.
pub fn student_body(submission: &Path, r: &Region, name: &str) -> Result<String, String> {
    let path = submission.join(&r.file);
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", r.file.display()))?;
    let begin = format!("{BEGIN} {name}");
    let mut lines = text.split_inclusive('\n');
    if !lines.by_ref().any(|l| l.trim() == begin) {
        return Err(format!(
            "`{begin}` is missing from {}: graded as not written",
            r.file.display()
        ));
    }
    let mut body = String::new();
    for line in lines {
        let t = line.trim();
        if t == END {
            return Ok(body);
        }
        if t.starts_with(BEGIN) {
            break;
        }
        body.push_str(line);
    }
    Err(format!(
        "`{begin}` is not closed by `{END}` in {}: graded as not written",
        r.file.display()
    ))
}

/// An exercise's body in a spliced file: its manifest entry, and the first and last line
/// (from 1) an error in it may be reported on.
type BodyLines = (usize, usize, usize);

/// A source file of the graded copy and the lines each exercise's body holds in it.
struct Spliced {
    /// The file, relative to the project.
    file: PathBuf,
    /// The reference text.
    reference: String,
    /// The regions in the file, in order, with the body each one now holds.
    regions: Vec<(Region, String)>,
}

impl Spliced {
    /// The text with every region's body in place, and for each region the lines (from 1,
    /// inclusive) an error in its body may be reported on: from its BEGIN line to the line
    /// after its END line.
    fn text(&self) -> (String, Vec<BodyLines>) {
        let mut out = String::new();
        let mut lines = Vec::new();
        let mut at = 0;
        for (r, body) in &self.regions {
            let head_end = self.reference[r.bytes.start..]
                .find('\n')
                .map_or(r.bytes.end, |i| r.bytes.start + i + 1);
            out.push_str(&self.reference[at..head_end]);
            // the BEGIN line, the body, the END line and the line after it: a syntax error
            // in a body is often reported at the token that follows it
            let first = out.lines().count();
            let mut body = body.clone();
            if !body.is_empty() && !body.ends_with('\n') {
                body.push('\n');
            }
            out.push_str(&body);
            let last = out.lines().count() + 2;
            lines.push((r.entry, first, last));
            out.push_str(&r.indent);
            out.push_str(END);
            out.push('\n');
            at = r.bytes.end;
        }
        out.push_str(&self.reference[at..]);
        (out, lines)
    }
}

/// Grades the submission at `submission` with the instructor's project at `root`.
pub fn grade(
    root: &Path,
    manifest: &Manifest,
    submission: &Path,
    options: &GradeSetup,
) -> Result<Grade, ToolError> {
    let start = Instant::now();
    if !submission.join(layout::core_src()).is_dir() {
        return Err(ToolError::Usage(format!(
            "{} is not a copy of the handout: it has no {}/ directory",
            submission.display(),
            layout::core_src().display()
        )));
    }
    let chapters: Vec<u8> = match options.chapter {
        Some(c) if crate::syllabus::chapter(c).is_some() => vec![c],
        Some(c) => {
            return Err(ToolError::Usage(format!(
                "--chapter {c}: the chapters are {} to {}",
                crate::syllabus::FIRST,
                crate::syllabus::LAST
            )));
        }
        None => crate::syllabus::CHAPTERS.iter().map(|c| c.number).collect(),
    };
    let student = submission
        .canonicalize()
        .ok()
        .and_then(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .unwrap_or_else(|| submission.display().to_string());
    // the graded copy: beside the build directory when there is one, kept from one grading to
    // the next and updated file by file, so that cargo recompiles only what differs from the
    // last submission; else a fresh temporary directory
    let mut temp = None;
    let project = match &options.target_dir {
        Some(dir) => {
            let project = dir.join(COPY);
            files::sync_project(root, &project, &[".config", STORE])?;
            if options.keep {
                eprintln!("grade: the graded copy is {}", project.display());
            }
            project
        }
        None => {
            let mut t = tempfile::Builder::new()
                .prefix("whitted-grade-")
                .tempdir()
                .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
            t.disable_cleanup(options.keep);
            if options.keep {
                eprintln!("grade: the graded copy is kept in {}", t.path().display());
            }
            let project = t.path().join("project");
            files::copy_project(root, &project)?;
            temp = Some(t);
            project
        }
    };
    let mut notes: BTreeMap<usize, String> = BTreeMap::new();
    let mut files = splice(root, manifest, submission, &chapters, &mut notes)?;
    let hidden = add_hidden(&project, options.hidden.as_deref())?;
    write_profile(&project, options.timeout)?;
    let targets: Vec<String> = chapter_targets(manifest, &chapters)
        .into_iter()
        .chain(hidden.iter().cloned())
        .collect();
    let target_dir = options
        .target_dir
        .clone()
        .unwrap_or_else(|| project.join("target"));
    let mut whole = Vec::new();
    // build; an exercise that does not compile goes back to its todo!() and the build again
    loop {
        // each file's body lines, as written, for placing the compiler's errors
        let mut placed = Vec::with_capacity(files.len());
        for f in &files {
            let (text, lines) = f.text();
            files::write_if_changed(&project.join(&f.file), text.as_bytes())?;
            placed.push((f.file.clone(), lines));
        }
        let errors = build(&project, &target_dir, &targets)?;
        if errors.is_empty() {
            break;
        }
        let mut broken = blame(&placed, &errors);
        if broken.is_empty() {
            // not on a body's lines (an unclosed brace is reported at the end of the file):
            // every student body of the files with errors goes back to its todo!()
            broken = blame_files(&files, &errors, |e| {
                chapters.contains(&manifest.entries[e].chapter) && !notes.contains_key(&e)
            });
        }
        if broken.is_empty() {
            whole.push(format!(
                "the submission does not build, and not because of an exercise's body: {}",
                errors[0].1
            ));
            break;
        }
        for (entry, message) in broken {
            let e = &manifest.entries[entry];
            notes.insert(
                entry,
                format!("does not compile, graded as not written: {message}"),
            );
            for f in &mut files {
                for (r, body) in &mut f.regions {
                    if r.entry == entry {
                        *body = format!("{}{}\n", r.indent, handout::todo_statement(e));
                    }
                }
            }
        }
    }
    let tests = if whole.is_empty() {
        run(&project, &target_dir, &targets, manifest, &hidden)?
    } else {
        Vec::new()
    };
    let exercises = score(manifest, &chapters, &tests, &notes);
    drop(temp);
    Ok(Grade {
        student,
        chapters,
        exercises,
        tests,
        notes: whole,
        elapsed: start.elapsed(),
    })
}

/// The graded copy's source files with the student's bodies in the regions of `chapters`
/// (the other regions keep the reference code). A body that cannot be found is noted and
/// replaced by the exercise's `todo!()`.
fn splice(
    root: &Path,
    manifest: &Manifest,
    submission: &Path,
    chapters: &[u8],
    notes: &mut BTreeMap<usize, String>,
) -> Result<Vec<Spliced>, ToolError> {
    let mut by_file: BTreeMap<PathBuf, Vec<(Region, String)>> = BTreeMap::new();
    for r in handout::regions(root, manifest)? {
        let e = &manifest.entries[r.entry];
        let body = if chapters.contains(&e.chapter) {
            student_body(submission, &r, &e.exercise.name).unwrap_or_else(|why| {
                notes.insert(r.entry, why);
                format!("{}{}\n", r.indent, handout::todo_statement(e))
            })
        } else {
            r.solution.clone()
        };
        by_file.entry(r.file.clone()).or_default().push((r, body));
    }
    by_file
        .into_iter()
        .map(|(file, mut regions)| {
            regions.sort_by_key(|(r, _)| r.bytes.start);
            let path = root.join(&file);
            let reference = std::fs::read_to_string(&path).map_err(|e| ToolError::io(&path, e))?;
            Ok(Spliced {
                file,
                reference,
                regions,
            })
        })
        .collect()
}

/// Copies each `*.rs` of the hidden directory into the copy's `tests/` as `hidden_NAME.rs`;
/// returns the test targets added.
fn add_hidden(project: &Path, hidden: Option<&Path>) -> Result<Vec<String>, ToolError> {
    // a kept copy may hold the hidden tests of an earlier grading
    let tests = project.join(layout::core_tests());
    if let Ok(entries) = std::fs::read_dir(&tests) {
        for e in entries.flatten() {
            if e.file_name().to_string_lossy().starts_with("hidden_") {
                let _ = std::fs::remove_file(e.path());
            }
        }
    }
    let Some(dir) = hidden else {
        return Ok(Vec::new());
    };
    let mut targets = Vec::new();
    let entries = std::fs::read_dir(dir).map_err(|e| ToolError::io(dir, e))?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "rs"))
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(ToolError::Usage(format!(
            "--hidden {}: the directory holds no .rs test file",
            dir.display()
        )));
    }
    for f in files {
        let stem: String = f
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        let target = format!("hidden_{stem}");
        let to = project.join(layout::core_test_file(&target));
        let bytes = std::fs::read(&f).map_err(|e| ToolError::io(&f, e))?;
        files::write_if_changed(&to, &bytes)?;
        targets.push(target);
    }
    Ok(targets)
}

/// Writes the grading profile into the copy's `.config/nextest.toml`.
fn write_profile(project: &Path, timeout: Duration) -> Result<(), ToolError> {
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

/// A compiler error: the file and line of its primary span, and its message with its place.
type CompileError = ((PathBuf, usize), String);

/// Builds the test targets; returns the compiler's errors, each as the primary span's file
/// and line, and the error's first line with its place (empty when the build succeeded).
fn build(
    project: &Path,
    target_dir: &Path,
    targets: &[String],
) -> Result<Vec<CompileError>, ToolError> {
    let built = cargo::Build {
        project,
        packages: &[layout::CORE_PACKAGE],
        tests: targets,
        bins: &[],
        profile: None,
        features: &[],
        target_dir: Some(target_dir),
        debug_info: false,
        locked: true,
        stderr: cargo::Stderr::Keep,
    }
    .run()?;
    if built.success {
        return Ok(Vec::new());
    }
    let mut errors: Vec<CompileError> = built
        .errors
        .iter()
        .map(|d| {
            (
                (d.file.clone(), d.line),
                format!("{}:{}: {}", d.file.display(), d.line, d.message),
            )
        })
        .collect();
    if errors.is_empty() {
        errors.push(((PathBuf::new(), 0), built.first_error()));
    }
    Ok(errors)
}

/// The exercises whose bodies hold the errors, each with its first error; `placed` gives
/// each file's body lines as [`Spliced::text`] wrote them.
fn blame(placed: &[(PathBuf, Vec<BodyLines>)], errors: &[CompileError]) -> BTreeMap<usize, String> {
    let mut out = BTreeMap::new();
    for ((file, line), message) in errors {
        for (_, lines) in placed.iter().filter(|(f, _)| f == file) {
            for &(entry, first, last) in lines {
                if (first..=last).contains(line) {
                    out.entry(entry).or_insert_with(|| message.clone());
                }
            }
        }
    }
    out
}

/// Every region of the files the errors are in whose entry passes `graded` (still the
/// student's), each with the file's first error.
fn blame_files(
    files: &[Spliced],
    errors: &[CompileError],
    graded: impl Fn(usize) -> bool,
) -> BTreeMap<usize, String> {
    let mut out = BTreeMap::new();
    for ((file, _), message) in errors {
        for f in files.iter().filter(|f| &f.file == file) {
            for (r, _) in &f.regions {
                if graded(r.entry) {
                    out.entry(r.entry).or_insert_with(|| {
                        format!("{message} (the error could not be placed in one body of this file, so each is graded as not written)")
                    });
                }
            }
        }
    }
    out
}

/// Runs the built targets with nextest's grading profile and reads its JUnit report.
fn run(
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

/// The results in a JUnit report of nextest.
pub fn parse_junit(
    text: &str,
    manifest: &Manifest,
    hidden: &[String],
) -> Result<Vec<TestResult>, ToolError> {
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| ToolError::Cargo(format!("cannot read nextest's JUnit report: {e}")))?;
    let mut out = Vec::new();
    for case in doc.descendants().filter(|n| n.has_tag_name("testcase")) {
        let name = test_name(case.attribute("name").unwrap_or("")).to_string();
        let class = case.attribute("classname").unwrap_or("");
        let target = class.rsplit("::").next().unwrap_or(class).to_string();
        let failure = case
            .children()
            .find(|n| n.has_tag_name("failure") || n.has_tag_name("error"));
        let (status, message) = match failure {
            None => (Status::Passed, String::new()),
            Some(f) => {
                let kind = f.attribute("type").unwrap_or("");
                let body = f.text().unwrap_or("");
                if kind.contains("timeout") {
                    (
                        Status::TimedOut,
                        "stopped at the time limit: an endless loop, or far too slow".into(),
                    )
                } else if kind.contains("abort") || kind.contains("signal") {
                    let what = f.attribute("message").unwrap_or(kind);
                    (
                        Status::Crashed,
                        format!("the test's process died ({what}): a stack overflow or an abort"),
                    )
                } else {
                    (Status::Failed, panic_message(body))
                }
            }
        };
        let exercise = manifest.exercise_of_test(&name);
        out.push(TestResult {
            hidden: hidden.contains(&target),
            name,
            target,
            exercise,
            status,
            message,
        });
    }
    out.sort_by(|a, b| (&a.target, &a.name).cmp(&(&b.target, &b.name)));
    Ok(out)
}

/// The message of a panic in a test's output: the lines after `panicked at …:`, up to the
/// backtrace note, at most three.
#[must_use]
pub fn panic_message(output: &str) -> String {
    let mut lines = output.lines();
    if !lines.by_ref().any(|l| l.contains("panicked at")) {
        return output.lines().next().unwrap_or("failed").trim().to_string();
    }
    let message: Vec<&str> = lines
        .take_while(|l| !l.starts_with("note:") && !l.starts_with("stack backtrace"))
        .filter(|l| !l.trim().is_empty())
        .take(3)
        .collect();
    let text = message.join(" / ");
    if text.starts_with("not yet implemented") {
        format!("not written ({text})")
    } else {
        text
    }
}

/// Each graded exercise's points: its points shared equally by its tests.
fn score(
    manifest: &Manifest,
    chapters: &[u8],
    tests: &[TestResult],
    notes: &BTreeMap<usize, String>,
) -> Vec<ExerciseScore> {
    manifest
        .entries
        .iter()
        .enumerate()
        .filter(|(_, e)| chapters.contains(&e.chapter))
        .map(|(i, e)| {
            let own: Vec<&TestResult> = tests.iter().filter(|t| t.exercise == Some(i)).collect();
            let passed = own.iter().filter(|t| t.status == Status::Passed).count();
            let max = f64::from(e.exercise.points);
            let score = if own.is_empty() {
                0.0
            } else {
                max * passed as f64 / own.len() as f64
            };
            let note = notes.get(&i).cloned().or_else(|| {
                own.is_empty()
                    .then(|| "no test ran for this exercise".to_string())
            });
            ExerciseScore {
                entry: i,
                score,
                max,
                passed,
                total: own.len(),
                note,
            }
        })
        .collect()
}

/// The test targets of the graded chapters that the manifest's handout lists.
#[must_use]
pub fn chapter_targets(manifest: &Manifest, chapters: &[u8]) -> BTreeSet<String> {
    manifest
        .handout
        .tests
        .iter()
        .filter(|t| {
            chapters
                .iter()
                .filter_map(|&c| crate::syllabus::chapter(c))
                .any(|c| *t == c.binary)
        })
        .cloned()
        .collect()
}

/// One submission of a class and how its grading went.
#[derive(Clone, Debug)]
pub struct ClassEntry {
    /// The submission's directory name.
    pub student: String,
    /// Its grade, or why it could not be graded (not a copy of the project …).
    pub grade: Result<Grade, String>,
}

/// Grades every submission of a class: each subdirectory of `dir`, in name order, `jobs` at
/// a time, each in its own copy. With `options.target_dir` set, each of the `jobs` workers
/// builds into its own directory under it (`slot-0`, `slot-1` …), kept from one submission
/// to the next, so the dependencies are built once per worker. (One shared directory would
/// not do: every copy of the crate builds its tests to the same file names, and one
/// submission's tests would run another's code.) A submission that cannot be graded is
/// reported and the others go on.
pub fn grade_class(
    root: &Path,
    manifest: &Manifest,
    dir: &Path,
    options: &GradeSetup,
    jobs: usize,
    done: &(dyn Fn(&ClassEntry) + Sync),
) -> Result<Vec<ClassEntry>, ToolError> {
    let mut submissions: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| ToolError::io(dir, e))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.is_dir()
                && !p
                    .file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .collect();
    submissions.sort();
    if submissions.is_empty() {
        return Err(ToolError::Usage(format!(
            "--class {}: no submission directory in it",
            dir.display()
        )));
    }
    let items: Vec<usize> = (0..submissions.len()).collect();
    // one build directory per worker: two copies of the crate build to the same file names,
    // so two submissions must never share one at the same time
    let slots: std::sync::Mutex<Vec<Option<PathBuf>>> = std::sync::Mutex::new(
        (0..jobs.max(1))
            .map(|i| {
                options
                    .target_dir
                    .as_ref()
                    .map(|t| t.join(format!("slot-{i}")))
            })
            .collect(),
    );
    crate::parallel::in_parallel(&items, jobs, |i| {
        let path = &submissions[i];
        let slot = slots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .pop()
            .flatten();
        let mut own = options.clone();
        own.target_dir.clone_from(&slot);
        let entry = ClassEntry {
            student: path.file_name().map_or_else(
                || path.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            ),
            grade: grade(root, manifest, path, &own).map_err(|e| e.to_string()),
        };
        slots.lock().unwrap_or_else(|p| p.into_inner()).push(slot);
        done(&entry);
        Ok(entry)
    })
}
