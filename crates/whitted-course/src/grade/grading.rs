//! One grading, step by step ([`grade`]): the judge, the graded copy and its sandbox, the
//! student's bodies spliced in and built into the server, the judge's tests run against it,
//! the points, and the pictures of the chapters that lost points.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

use super::alone::Judging;
use super::build::build_bodies;
use super::clean::clean;
use super::copy::{GradedCopy, run_reads};
use super::judge_copy::{self, Judge};
use super::outcome::{ExerciseScore, Grade, Timings};
use super::outside::{SERVER_EXAMPLE, SERVER_VAR, WHOLE_ROAD_VAR, Wire};
use super::render::{self, ChapterFeedback, RenderScore};
use super::runner::SERVE;
use super::sandbox::{POLICY_VAR, RUNNER_COMMAND, Sandbox, watch};
use super::score::{chapter_targets, scores};
use super::setup::{Chapters, GradeSetup, SandboxSetup};
use super::splice::Spliced;
use super::test_result::TestResult;
use super::{clock, nextest, splice};
use crate::cargo::Wrapper;
use crate::manifest::Manifest;
use crate::{ToolError, layout, syllabus};

/// Grades the submission at `submission` with the instructor's project at `root`.
pub fn grade(
    root: &Path,
    manifest: &Manifest,
    submission: &Path,
    options: &GradeSetup,
) -> Result<Grade, ToolError> {
    let start = Instant::now();
    let chapters = graded_chapters(submission, manifest, options.chapter)?;
    let student = student_of(submission);
    // 1. the graded copy and its sandbox (without its sandbox, nothing is built), and the
    // judge: the class's, or this grading's own
    let g = Grading::open(root, manifest, options)?;
    let judged = Instant::now();
    let judge = match &options.judge {
        Some(j) => Arc::clone(j),
        None => Arc::new(judge_for(
            root,
            manifest,
            &chapters,
            options,
            options
                .target_dir
                .as_deref()
                .map(judge_copy::beside)
                .as_deref(),
        )?),
    };
    // building the judge counts as building (a class builds it once, before its gradings)
    let judge_time = judged.elapsed();
    // 2. the student's bodies in it, with the wire
    let mut notes: BTreeMap<usize, String> = BTreeMap::new();
    let mut files = g.splice(
        root,
        (manifest, &judge.wire),
        submission,
        &chapters,
        options,
        &mut notes,
    )?;
    let mut timings = Timings {
        splice: start.elapsed().saturating_sub(judge_time),
        ..Timings::default()
    };
    // 3. the build: the student's server
    let built = Instant::now();
    let w = g.wrapper.as_ref();
    let server = [SERVER_EXAMPLE.to_string()];
    let whole = build_bodies(
        &g.copy, manifest, &chapters, &mut files, &server, w, &mut notes,
    )?;
    let builds = whole.is_empty();
    g.seal(root, options, &judge)?;
    timings.build = built.elapsed() + judge_time;
    // 4. the tests, each in its own process, judged outside the server, and their points
    let ran = Instant::now();
    let tests = if builds {
        g.run_tests(manifest, &judge, options)?
    } else {
        Vec::new()
    };
    let mut exercises = scores(manifest, &chapters, &tests, &notes);
    // the known mistakes, told by the tests' values as `cargo learn` tells them
    let mistakes = whitted_learn::trees::load_mistakes(root);
    super::score::recognise_known(manifest, &mut exercises, &tests, &mistakes);
    // 5. the pictures: the leaderboard's, and what learn would show of each chapter that
    // lost points
    let render = (options.render && builds).then(|| g.leaderboard(&chapters, options));
    let feedback = if options.feedback && builds {
        g.pictures(&lost_chapters(manifest, &chapters, &exercises), options)
    } else {
        Vec::new()
    };
    timings.run = ran.elapsed();
    g.copy.close();
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
        judging: options.judging,
    })
}

/// The chapters graded: those asked for, or all five; an error when `submission` is no copy
/// of the handout.
fn graded_chapters(
    submission: &Path,
    manifest: &Manifest,
    chapter: Option<Chapters>,
) -> Result<Vec<u8>, ToolError> {
    if !submission.join(layout::core_src()).is_dir() {
        return Err(ToolError::Usage(format!(
            "{} is not a copy of the handout: it has no {}/ directory",
            submission.display(),
            layout::core_src().display()
        )));
    }
    Ok(chapters_asked(manifest, chapter))
}

/// The chapters `--chapter` asks for: those named (checked when read), or every chapter that
/// holds an exercise of `manifest` (all five, unless it is a handout's with a list of its own).
pub(super) fn chapters_asked(manifest: &Manifest, chapter: Option<Chapters>) -> Vec<u8> {
    let mut chapters = Chapters::or_all(chapter);
    if chapter.is_none() {
        chapters.retain(|&c| manifest.entries.iter().any(|e| e.chapter == c));
    }
    chapters
}

/// The judge of a grading of `chapters` (their test targets, and the hidden tests `options`
/// name), made and built in `dir` (a temporary directory when `None`).
pub(super) fn judge_for(
    root: &Path,
    manifest: &Manifest,
    chapters: &[u8],
    options: &GradeSetup,
    dir: Option<&Path>,
) -> Result<Judge, ToolError> {
    let public: Vec<String> = chapter_targets(manifest, chapters).into_iter().collect();
    judge_copy::prepare(root, manifest, &public, options.hidden.as_deref(), dir)
}

/// The submission's name in the reports: its directory's name, cleaned.
fn student_of(submission: &Path) -> String {
    submission
        .canonicalize()
        .ok()
        .and_then(|p| p.file_name().map(|n| clean(&n.to_string_lossy())))
        .unwrap_or_else(|| clean(&submission.display().to_string()))
}

/// A grading under way: the graded copy, the sandbox its tests run in and the wrapper its
/// builds run in (none unsandboxed).
struct Grading {
    /// The copy of the project.
    copy: GradedCopy,
    /// The sandbox of the tests.
    sandbox: Option<Sandbox>,
    /// The sandbox of the builds.
    wrapper: Option<Wrapper>,
}

impl Grading {
    /// Places the graded copy and sets its sandbox up before anything is copied or built
    /// (without its sandbox, grading does not start), then brings the copy up to date with
    /// the project at `root`.
    fn open(root: &Path, manifest: &Manifest, options: &GradeSetup) -> Result<Self, ToolError> {
        let copy = GradedCopy::place(options)?;
        let sandbox = match &options.sandbox {
            Some(s) => Some(sandbox(s, &copy, options)?),
            None => None,
        };
        copy.sync(root, manifest, options.keep)?;
        // the build runs under the compiler's limits, inside its sandbox when there is one
        let wrapper = match (&options.sandbox, &sandbox) {
            (Some(setup), Some(s)) => Some(watch::watched(
                &setup.runner,
                options.compile,
                s.build_wrapper(&copy.project, &copy.target_dir),
            )),
            _ => None,
        };
        Ok(Self {
            copy,
            sandbox,
            wrapper,
        })
    }

    /// Splices the student's bodies of `chapters` into the copy's sources with the `wire` of
    /// the judge outside (planned once, with the judge) (what concerns an exercise goes into `notes`): a body that does more than
    /// compute is not compiled at all, at every sandbox level. No hidden test is ever in the
    /// copy (they are the judge's); those an older grading left are removed.
    fn splice(
        &self,
        root: &Path,
        (manifest, wire): (&Manifest, &Wire),
        submission: &Path,
        chapters: &[u8],
        options: &GradeSetup,
        notes: &mut BTreeMap<usize, String>,
    ) -> Result<Vec<Spliced>, ToolError> {
        let files = splice::splice(
            root,
            manifest,
            submission,
            chapters,
            options.screen,
            wire,
            notes,
        )?;
        wire.write_table(&self.copy.project)?;
        splice::remove_hidden(&self.copy.project, &self.copy.target_dir)?;
        Ok(files)
    }

    /// Before the tests run: at the user level the instructor's project, the hidden tests and
    /// the judge checked closed, and the copy closed too.
    fn seal(&self, root: &Path, options: &GradeSetup, judge: &Judge) -> Result<(), ToolError> {
        if let Some(s) = &self.sandbox {
            let mut secrets = vec![root, judge.dir.as_path()];
            secrets.extend(options.hidden.as_deref());
            s.protect(&secrets, &self.copy.target_dir, &self.copy.project)?;
        }
        Ok(())
    }

    /// Runs the judge's tests, each in its own process, against the copy's server: started in
    /// the run sandbox through the runner (`whitted sandbox-run --serve`) when there is one.
    /// Then the copy opens again, whether the run went well or not.
    fn run_tests(
        &self,
        manifest: &Manifest,
        judge: &Judge,
        options: &GradeSetup,
    ) -> Result<Vec<TestResult>, ToolError> {
        let server = self
            .copy
            .target_dir
            .join("debug")
            .join("examples")
            .join(SERVER_EXAMPLE);
        let mut env: Vec<(OsString, OsString)> = Vec::new();
        match &self.sandbox {
            Some(s) => {
                let mut line = s.runner.clone().into_os_string();
                for word in [RUNNER_COMMAND, SERVE] {
                    line.push("\x1f");
                    line.push(word);
                }
                line.push("\x1f");
                line.push(&server);
                env.push((SERVER_VAR.into(), line));
                // the server reads nothing of the copy: the judge reads the scenes and images
                let mut policy = s.policy.clone();
                policy.read.clear();
                let policy = serde_json::to_string(&policy)
                    .map_err(|e| ToolError::Usage(format!("the sandbox's policy: {e}")))?;
                env.push((POLICY_VAR.into(), policy.into()));
            }
            None => env.push((SERVER_VAR.into(), server.into_os_string())),
        }
        // every test of the whole road sends every call across the wire: the time limit of a
        // test of no exercise for all of them
        let mut timeout = options.timeout;
        if options.judging == Judging::WholeRoad {
            env.push((WHOLE_ROAD_VAR.into(), "1".into()));
            timeout *= nextest::WHOLE_ROAD_TIMES;
        }
        // each test under its limit of CPU time, when there is a `whitted` to run the clock
        let clocked = match &self.sandbox {
            Some(s) => {
                env.extend(
                    clock::runner_env(&s.runner, &s.triple, timeout, nextest::WHOLE_ROAD_TIMES)
                        .map_err(ToolError::Usage)?,
                );
                true
            }
            None => false,
        };
        let run = judge_copy::run_dir(judge)?;
        let tests = nextest::run(
            &judge.project,
            &judge.target_dir,
            &judge.listed,
            run.path(),
            (timeout, clocked),
            &env,
            (manifest, &judge.hidden),
        );
        if let Some(s) = &self.sandbox {
            s.reopen(&self.copy.project)?;
        }
        tests
    }

    /// The leaderboard's render: the last graded chapter's figure drawn by the student's
    /// code, its speed and its error.
    fn leaderboard(&self, chapters: &[u8], options: &GradeSetup) -> Result<RenderScore, String> {
        let last = chapters.iter().copied().max().unwrap_or(syllabus::LAST);
        render::measure(
            &self.copy.project,
            &self.copy.target_dir,
            last,
            self.wrapper.as_ref(),
            self.sandbox.as_ref(),
            options.timeout * 3,
        )
    }

    /// The feedback of the chapters that lost points (`lost`): each one's picture beside the
    /// book's and its ray trees against the reference's. With none lost, the chapter
    /// binaries are built when the project's manifests changed since they last were, so that
    /// a later grading's feedback finds them ready.
    fn pictures(&self, lost: &[u8], options: &GradeSetup) -> Vec<ChapterFeedback> {
        let (project, target_dir) = (&self.copy.project, &self.copy.target_dir);
        if lost.is_empty() {
            render::warm(project, target_dir, self.wrapper.as_ref());
            return Vec::new();
        }
        render::feedback(
            project,
            target_dir,
            lost,
            self.wrapper.as_ref(),
            self.sandbox.as_ref(),
            options.timeout * 3,
        )
    }
}

/// Whether the sandbox `options` ask for can be made here: a class asks before it builds its
/// judge, so that a grading that cannot start builds nothing.
pub(super) fn check_sandbox(options: &GradeSetup) -> Result<(), ToolError> {
    match &options.sandbox {
        Some(s) => Sandbox::probe(&s.runner, s.worker, Vec::new(), s.level)
            .map(|_| ())
            .map_err(unmade),
        None => Ok(()),
    }
}

/// The error of a sandbox that cannot be made, `why`: what to do instead.
fn unmade(why: String) -> ToolError {
    ToolError::Usage(format!(
        "the sandbox cannot be set up: {why}; as root, --sandbox user runs the tests as a user of their own without namespaces, and --unsandboxed with your rights"
    ))
}

/// The sandbox `s` asks for, found and tried, its tests' time limit set: a sandbox that
/// cannot be made is an error that says what to do.
fn sandbox(
    s: &SandboxSetup,
    copy: &GradedCopy,
    options: &GradeSetup,
) -> Result<Sandbox, ToolError> {
    let mut sandbox =
        Sandbox::probe(&s.runner, s.worker, run_reads(&copy.project), s.level).map_err(unmade)?;
    sandbox.policy.timeout_ms = u64::try_from(options.timeout.as_millis()).ok();
    Ok(sandbox)
}

/// The graded chapters in which some exercise lost points.
fn lost_chapters(manifest: &Manifest, chapters: &[u8], exercises: &[ExerciseScore]) -> Vec<u8> {
    chapters
        .iter()
        .copied()
        .filter(|&c| {
            exercises
                .iter()
                .any(|e| manifest.entries[e.entry].chapter == c && e.score < e.max)
        })
        .collect()
}
