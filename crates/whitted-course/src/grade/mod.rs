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
//! A body that names what a formula never needs (ending or starting a process, files, the
//! network, the environment, `unsafe`, a compile-time read …) is not even put in: it counts as
//! not written ([`screen()`]).
//!
//! Then, in that copy:
//!
//! 1. **Build.** An exercise whose body does not compile is put back to its `todo!()` and the
//!    build is tried again, so a compile error costs only the exercise it is in; its first
//!    error goes into the report.
//! 2. **Run** every test of the graded chapters with cargo-nextest, each test in its own
//!    process with its own time limit: a `todo!()`, a panic, a stack overflow, an abort or an
//!    endless loop fails the tests it touches and no others. Each test binary goes through
//!    the [`runner`], which passes a test only when libtest reported it `ok` (a process that
//!    ended early passes nothing) and cleans what it printed ([`clean`]).
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

mod blame;
mod class;
pub mod clean;
pub mod command;
mod junit;
mod nextest;
mod render;
pub mod runner;
pub mod sandbox;
pub mod screen;
mod splice;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use super::handout;
use super::manifest::Manifest;
use super::{ToolError, files, layout};

pub use class::{ClassEntry, grade_class};
pub use junit::{MESSAGE_CHARS, panic_message, parse_junit};
pub use nextest::NEXTEST_PROFILE;
pub use render::{ChapterFeedback, PICTURE_BYTES, RenderScore};
pub use screen::screen;
pub(crate) use splice::hidden_files;
pub use splice::student_body;
pub use whitted_learn::trees::{Against, Parting};

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
    /// Build and run the student's code in a sandbox ([`sandbox`]); with `None` it runs with
    /// the grader's rights.
    pub sandbox: Option<SandboxSetup>,
    /// Render the last graded chapter's figure with the student's code, for the leaderboard
    /// ([`Grade::render`]).
    pub render: bool,
    /// For each graded chapter that lost points, render its figure with the student's code
    /// beside the book's and compare its ray trees with the reference's ([`Grade::feedback`]).
    pub feedback: bool,
    /// Refuse to compile a body that does more than compute ([`screen()`]). Always on from
    /// the command line; off only where a test proves the second lock, the runner's, alone.
    pub screen: bool,
}

/// What a sandboxed grading needs to know.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SandboxSetup {
    /// The `whitted` program, whose hidden `sandbox-run` command nextest starts each test
    /// binary with.
    pub runner: PathBuf,
    /// The worker's number: as root, its tests run as user [`sandbox::FIRST_UID`] + this.
    pub worker: usize,
    /// Namespaces (bubblewrap), or a user of its own only.
    pub level: sandbox::Level,
}

impl Default for GradeSetup {
    fn default() -> Self {
        Self {
            chapter: None,
            hidden: None,
            timeout: DEFAULT_TIMEOUT,
            target_dir: None,
            keep: false,
            sandbox: None,
            render: false,
            feedback: true,
            screen: true,
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
    /// The test's name within its target, with its module path (`ex_near_plane_half_width_…`,
    /// `sphere::ex_sphere_discriminant_…`).
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
    /// How long it ran, in seconds.
    pub time: f64,
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
    /// Where that time went.
    pub timings: Timings,
    /// The render of the leaderboard when it was asked for ([`GradeSetup::render`]): its
    /// speed and error, or why there is none.
    pub render: Option<Result<RenderScore, String>>,
    /// What the student's code draws of each graded chapter that lost points, beside the
    /// reference ([`GradeSetup::feedback`]): the picture, the first wrong number of the ray
    /// trees, or why the chapter cannot be drawn.
    pub feedback: Vec<ChapterFeedback>,
}

/// Where a grading's time went.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Timings {
    /// Copying the project and splicing the student's bodies into it.
    pub splice: Duration,
    /// Building (the student's crate and the tests, the hidden ones too, each build again
    /// after a body that did not compile).
    pub build: Duration,
    /// Running the tests (listing them, nextest, the sandbox).
    pub run: Duration,
}

/// What a report says of one chapter's feedback ([`Grade::explained`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Explained<'g> {
    /// The chapter.
    pub chapter: u8,
    /// How the student's picture compares with the book's (the binary's `compare:` line), or
    /// why there is no picture.
    pub picture_line: String,
    /// The first wrong number of the chapter's ray trees, in learn's words, and the exercise
    /// (manifest index) it points at, when a tree differs.
    pub first_wrong: Option<(Option<usize>, String)>,
    /// The PNG of the student's render, the book's figure and their difference side by side.
    pub picture: Option<&'g [u8]>,
}

impl Grade {
    /// The feedback of each chapter that lost points, worded for a report: the picture's
    /// line, and the first wrong number of its trees attributed to an exercise as `cargo
    /// learn` attributes it (the first of those that computed it whose tests did not all
    /// pass).
    #[must_use]
    pub fn explained(&self, manifest: &Manifest) -> Vec<Explained<'_>> {
        use whitted_learn::learn::State;
        use whitted_learn::trees as learn_trees;
        // an exercise not graded here has the reference's body in the graded copy
        let states: Vec<State> = (0..manifest.entries.len())
            .map(|i| match self.exercises.iter().find(|e| e.entry == i) {
                Some(e) if e.score < e.max || e.note.is_some() => State::Failing(Vec::new()),
                _ => State::Done,
            })
            .collect();
        self.feedback
            .iter()
            .map(|f| {
                let picture_line = match (&f.trouble, &f.compare) {
                    (Some(why), _) => format!("no picture: {why}"),
                    (None, Some(compare)) => compare.clone(),
                    (None, None) => "no picture".into(),
                };
                let differs = f
                    .compare
                    .as_deref()
                    .and_then(learn_trees::picture_counts)
                    .is_some_and(|(n, _)| n > 0);
                let first_wrong = learn_trees::attribute(manifest, &states, &f.against, differs)
                    .map(|w| (w.exercise, w.lines(manifest, f.against.len())));
                Explained {
                    chapter: f.chapter,
                    picture_line,
                    first_wrong,
                    picture: f.picture.as_deref(),
                }
            })
            .collect()
    }

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
        .and_then(|p| p.file_name().map(|n| clean::clean(&n.to_string_lossy())))
        .unwrap_or_else(|| clean::clean(&submission.display().to_string()));
    // the graded copy: beside the build directory when there is one, kept from one grading to
    // the next and updated file by file, so that cargo recompiles only what differs from the
    // last submission; else a fresh temporary directory
    let mut temp = None;
    // absolute: the sandbox binds the directories at their paths
    let build_dir = match &options.target_dir {
        Some(dir) => Some(std::path::absolute(dir).map_err(|e| ToolError::io(dir, e))?),
        None => None,
    };
    let project = match &build_dir {
        Some(dir) => dir.join(COPY),
        None => {
            let mut t = tempfile::Builder::new()
                .prefix("whitted-grade-")
                .tempdir()
                .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
            t.disable_cleanup(options.keep);
            let project = t.path().join("project");
            temp = Some(t);
            project
        }
    };
    // before anything is copied or built: without its sandbox, grading does not start
    let mut sandbox = match &options.sandbox {
        Some(s) => Some(
            sandbox::Sandbox::probe(&s.runner, s.worker, run_reads(&project), s.level).map_err(
                |why| {
                    ToolError::Usage(format!(
                        "the sandbox cannot be set up: {why}; as root, --sandbox user runs the tests as a user of their own without namespaces, and --unsandboxed with your rights"
                    ))
                },
            )?,
        ),
        None => None,
    };
    if let Some(s) = &mut sandbox {
        s.policy.timeout_ms = u64::try_from(options.timeout.as_millis()).ok();
    }
    let whole = |f: &Path| whole_in_copy(root, manifest, f);
    files::sync_project(root, &project, &[".config", nextest::STORE], &whole)?;
    if options.keep {
        eprintln!("grade: the graded copy is {}", project.display());
    }
    let target_dir = build_dir.unwrap_or_else(|| project.join("target"));
    std::fs::create_dir_all(&target_dir).map_err(|e| ToolError::io(&target_dir, e))?;
    let wrapper = sandbox
        .as_ref()
        .and_then(|s| s.build_wrapper(&project, &target_dir));
    let mut notes: BTreeMap<usize, String> = BTreeMap::new();
    // a body that does more than compute is not compiled at all, at every sandbox level
    let mut files = splice::splice(
        root,
        manifest,
        submission,
        &chapters,
        options.screen,
        &mut notes,
    )?;
    // the student's crate compiles while no hidden test is in the copy, so that a body cannot
    // include one; the hidden targets are added and built after it
    splice::remove_hidden(&project, &target_dir)?;
    nextest::write_profile(&project, options.timeout)?;
    let public: Vec<String> = chapter_targets(manifest, &chapters).into_iter().collect();
    let mut timings = Timings {
        splice: start.elapsed(),
        ..Timings::default()
    };
    let built = Instant::now();
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
        let errors = blame::build(&project, &target_dir, &public, wrapper.as_ref())?;
        if errors.is_empty() {
            break;
        }
        let mut broken = blame::blame(&placed, &errors);
        if broken.is_empty() {
            // not on a body's lines (an unclosed brace is reported at the end of the file):
            // every student body of the files with errors goes back to its todo!()
            broken = blame::blame_files(&files, &errors, |e| {
                chapters.contains(&manifest.entries[e].chapter) && !notes.contains_key(&e)
            });
        }
        if broken.is_empty() {
            whole.push(clean::clean(&format!(
                "the submission does not build, and not because of an exercise's body: {}",
                errors[0].1
            )));
            break;
        }
        for (entry, message) in broken {
            let e = &manifest.entries[entry];
            notes.insert(
                entry,
                clean::clean(&format!(
                    "does not compile, graded as not written: {message}"
                )),
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
    let mut hidden = Vec::new();
    if whole.is_empty() && options.hidden.is_some() {
        hidden = splice::add_hidden(&project, options.hidden.as_deref())?;
        let errors = blame::build(&project, &target_dir, &hidden, wrapper.as_ref())?;
        if let Some((_, first)) = errors.first() {
            // the student's crate built for the public tests: the hidden ones are the
            // instructor's to fix, and the public ones still count
            whole.push(format!("the hidden tests do not build: {first}"));
            splice::remove_hidden(&project, &target_dir)?;
            hidden.clear();
        }
    }
    let targets: Vec<String> = public.iter().chain(&hidden).cloned().collect();
    splice::seal_hidden(&target_dir)?;
    if let Some(s) = &sandbox {
        let mut secrets = vec![root];
        secrets.extend(options.hidden.as_deref());
        s.protect(&secrets, &target_dir, &project)?;
    }
    timings.build = built.elapsed();
    let ran = Instant::now();
    let tests = if whole.iter().all(|w| w.starts_with("the hidden tests")) {
        nextest::run(
            &project,
            &target_dir,
            &targets,
            manifest,
            &hidden,
            wrapper.as_ref(),
            sandbox.as_ref(),
            || splice::strip_hidden(&project, &target_dir),
        )
    } else {
        Ok(Vec::new())
    };
    // the hidden tests' sources and binaries leave the copy before anything else is built
    // in it, whether the run went well or not
    splice::remove_hidden(&project, &target_dir)?;
    if let Some(s) = &sandbox {
        s.reopen(&project)?;
    }
    let tests = tests?;
    let exercises = scores(manifest, &chapters, &tests, &notes);
    let render = (options.render && whole.is_empty()).then(|| {
        let last = chapters
            .iter()
            .copied()
            .max()
            .unwrap_or(crate::syllabus::LAST);
        render::measure(
            &project,
            &target_dir,
            last,
            wrapper.as_ref(),
            sandbox.as_ref(),
            options.timeout * 3,
        )
    });
    // the pictures and trees of the chapters that lost points: what learn would show
    let lost: Vec<u8> = chapters
        .iter()
        .copied()
        .filter(|&c| {
            exercises
                .iter()
                .any(|e| manifest.entries[e.entry].chapter == c && e.score < e.max)
        })
        .collect();
    if options.feedback && whole.is_empty() && lost.is_empty() {
        render::warm(&project, &target_dir, wrapper.as_ref());
    }
    let feedback = if options.feedback && whole.is_empty() && !lost.is_empty() {
        render::feedback(
            &project,
            &target_dir,
            &lost,
            wrapper.as_ref(),
            sandbox.as_ref(),
            options.timeout * 3,
        )
    } else {
        Vec::new()
    };
    timings.run = ran.elapsed();
    drop(temp);
    Ok(Grade {
        student,
        chapters,
        exercises,
        tests,
        notes: whole,
        elapsed: start.elapsed(),
        timings,
        render,
        feedback,
    })
}

/// Whether the project file `file` goes whole into the graded copy: what the student's crate
/// and its tests are built from (every manifest, the lock, cargo's settings, the syllabus, the
/// renderer with the handout's tests, the scenes), and the chapter binaries and the book's
/// figures for the leaderboard's render: all of it in the handout too. Every other file is there empty, so that a
/// body compiled in the copy cannot include the instructor's other files (a mutant list, a
/// guide, tools that quote the solutions).
fn whole_in_copy(root: &Path, manifest: &Manifest, file: &Path) -> bool {
    let name = file.file_name().map(|n| n.to_string_lossy().into_owned());
    if matches!(name.as_deref(), Some("Cargo.toml"))
        || file == Path::new("Cargo.lock")
        || file.starts_with(".cargo")
        || name
            .as_deref()
            .is_some_and(|n| n.starts_with("rust-toolchain"))
        || file.starts_with(layout::SYLLABUS)
        || file.starts_with(layout::APP)
        || file.starts_with("scenes")
        || render::needs(file)
    {
        return true;
    }
    if file.starts_with(layout::core_tests()) {
        return handout::part_of(file, &manifest.handout.tests, root) == handout::Part::Copied;
    }
    file.starts_with(layout::CORE)
}

/// What the tests read at run time, shown to them read-only: the scenes and the golden
/// images.
fn run_reads(project: &Path) -> Vec<PathBuf> {
    vec![
        project.join("scenes"),
        project.join(layout::core_tests()).join("golden"),
    ]
}

/// Each exercise of `chapters`' points: its points shared equally by its tests; `notes` are
/// what the grader noticed about an exercise (it did not compile …).
#[must_use]
pub fn scores(
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
