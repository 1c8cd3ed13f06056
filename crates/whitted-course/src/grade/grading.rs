//! One grading, step by step ([`grade`]): the graded copy and its sandbox, the student's
//! bodies spliced in and built, the tests run, the points, and the pictures of the chapters
//! that lost points.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;

use super::alone;
use super::build::{build_bodies, build_hidden};
use super::clean::clean;
use super::copy::{GradedCopy, run_reads};
use super::outcome::{ExerciseScore, Grade, Timings};
use super::render::{self, ChapterFeedback, RenderScore};
use super::sandbox::{Sandbox, watch};
use super::score::{chapter_targets, scores};
use super::setup::{GradeSetup, SandboxSetup};
use super::splice::Spliced;
use super::test_result::TestResult;
use super::{nextest, splice};
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
    let chapters = graded_chapters(submission, options.chapter)?;
    let student = student_of(submission);
    // 1. the graded copy and its sandbox
    let g = Grading::open(root, manifest, options)?;
    // 2. the student's bodies in it
    let mut notes: BTreeMap<usize, String> = BTreeMap::new();
    let mut files = g.splice(root, manifest, submission, &chapters, options, &mut notes)?;
    let mut timings = Timings {
        splice: start.elapsed(),
        ..Timings::default()
    };
    // 3. the build: the student's crate with its public tests, then the hidden tests
    let built = Instant::now();
    let public: Vec<String> = chapter_targets(manifest, &chapters).into_iter().collect();
    let w = g.wrapper.as_ref();
    let mut whole = build_bodies(
        &g.copy, manifest, &chapters, &mut files, &public, w, &mut notes,
    )?;
    let hidden = build_hidden(&g.copy, options.hidden.as_deref(), w, &mut whole)?;
    g.seal(root, options)?;
    timings.build = built.elapsed();
    // 4. the tests, each in its own process, and the points they earn
    let ran = Instant::now();
    let targets: Vec<String> = public.iter().chain(&hidden).cloned().collect();
    let tests = g.run_tests(manifest, &targets, &hidden, &whole)?;
    let exercises = scores(manifest, &chapters, &tests, &notes);
    // 5. the pictures: the leaderboard's, and what learn would show of each chapter that
    // lost points
    let builds = whole.is_empty();
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

/// The chapters graded: the one asked for, or all five; an error when `submission` is no
/// copy of the handout or the chapter is none of the course's.
fn graded_chapters(submission: &Path, chapter: Option<u8>) -> Result<Vec<u8>, ToolError> {
    if !submission.join(layout::core_src()).is_dir() {
        return Err(ToolError::Usage(format!(
            "{} is not a copy of the handout: it has no {}/ directory",
            submission.display(),
            layout::core_src().display()
        )));
    }
    match chapter {
        Some(c) if syllabus::chapter(c).is_some() => Ok(vec![c]),
        Some(c) => Err(ToolError::Usage(format!(
            "--chapter {c}: the chapters are {} to {}",
            syllabus::FIRST,
            syllabus::LAST
        ))),
        None => Ok(syllabus::CHAPTERS.iter().map(|c| c.number).collect()),
    }
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

    /// Splices the student's bodies of `chapters` into the copy's sources (what concerns an
    /// exercise goes into `notes`): a body that does more than compute is not compiled at
    /// all, at every sandbox level. The hidden tests leave the copy, so that the student's
    /// crate compiles while none is there for a body to include; they come back after it.
    fn splice(
        &self,
        root: &Path,
        manifest: &Manifest,
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
            (options.screen, options.judging),
            notes,
        )?;
        alone::add_switch(&self.copy.project, manifest)?;
        splice::remove_hidden(&self.copy.project, &self.copy.target_dir)?;
        nextest::write_profile(&self.copy.project, options.timeout)?;
        Ok(files)
    }

    /// Before the tests run: the hidden tests' binaries closed to other users, and at the
    /// user level the instructor's project and hidden tests checked closed and the copy
    /// closed too.
    fn seal(&self, root: &Path, options: &GradeSetup) -> Result<(), ToolError> {
        splice::seal_hidden(&self.copy.target_dir)?;
        if let Some(s) = &self.sandbox {
            let mut secrets = vec![root];
            secrets.extend(options.hidden.as_deref());
            s.protect(&secrets, &self.copy.target_dir, &self.copy.project)?;
        }
        Ok(())
    }

    /// Runs the test `targets` (of which `hidden` are the hidden tests') when the student's
    /// crate built (`whole` says nothing but of the hidden tests), each test in its own
    /// process; then the hidden tests' sources and binaries leave the copy before anything
    /// else is built in it, whether the run went well or not, and the copy opens again.
    fn run_tests(
        &self,
        manifest: &Manifest,
        targets: &[String],
        hidden: &[String],
        whole: &[String],
    ) -> Result<Vec<TestResult>, ToolError> {
        let (project, target_dir) = (&self.copy.project, &self.copy.target_dir);
        let tests = if whole.iter().all(|w| w.starts_with("the hidden tests")) {
            nextest::run(
                project,
                target_dir,
                targets,
                manifest,
                hidden,
                self.wrapper.as_ref(),
                self.sandbox.as_ref(),
                || splice::strip_hidden(project, target_dir),
            )
        } else {
            Ok(Vec::new())
        };
        splice::remove_hidden(project, target_dir)?;
        if let Some(s) = &self.sandbox {
            s.reopen(project)?;
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

/// The sandbox `s` asks for, found and tried, its tests' time limit set: a sandbox that
/// cannot be made is an error that says what to do.
fn sandbox(
    s: &SandboxSetup,
    copy: &GradedCopy,
    options: &GradeSetup,
) -> Result<Sandbox, ToolError> {
    let mut sandbox = Sandbox::probe(&s.runner, s.worker, run_reads(&copy.project), s.level)
        .map_err(|why| {
            ToolError::Usage(format!(
                "the sandbox cannot be set up: {why}; as root, --sandbox user runs the tests as a user of their own without namespaces, and --unsandboxed with your rights"
            ))
        })?;
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
