//! What a grading finds: each exercise's points, and the grade of the whole submission.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::time::Duration;

use super::alone::Judging;
use super::render::{ChapterFeedback, RenderScore};
use super::test_result::{Status, TestResult};
use crate::manifest::Manifest;

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
    /// The known mistake (`chapters/mistakes.json`) its failing tests say it looks like, in
    /// words ([`super::score::recognise_known`]).
    pub known: Option<String>,
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
    /// The render of the leaderboard when it was asked for
    /// ([`GradeSetup::render`](crate::grade::GradeSetup::render)): its speed and error, or why
    /// there is none.
    pub render: Option<Result<RenderScore, String>>,
    /// What the student's code draws of each graded chapter that lost points, beside the
    /// reference ([`GradeSetup::feedback`](crate::grade::GradeSetup::feedback)): the picture,
    /// the first wrong number of the ray trees, or why the chapter cannot be drawn.
    pub feedback: Vec<ChapterFeedback>,
    /// How the tests were judged: each exercise alone, or the student's whole road.
    pub judging: Judging,
}

/// What the student's whole road does in one chapter: of the chapter's tests that are no
/// exercise's, which run every body of the student's together, how many pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Road {
    /// The chapter.
    pub chapter: u8,
    /// Its whole-road tests that passed.
    pub passed: usize,
    /// Its whole-road tests.
    pub total: usize,
}

impl Road {
    /// The report's line: whether the student's bodies, together, draw the chapter as the
    /// reference does.
    #[must_use]
    pub fn line(&self) -> String {
        let c = self.chapter;
        let (n, failed) = (self.total, self.total - self.passed);
        let what = match (n, failed) {
            (1, 0) => "its test of no exercise passes".to_string(),
            (1, _) => "its test of no exercise fails".to_string(),
            (_, 0) => format!("its {n} tests of no exercise pass"),
            _ => format!("{failed} of its {n} tests of no exercise fail"),
        };
        let draws = if failed == 0 {
            "draws as the reference's"
        } else {
            "does not yet draw as the reference's"
        };
        format!(
            "your whole road: chapter {c} {draws}: {what} with all of your bodies together (they count no points)"
        )
    }
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

    /// The tests of chapter `chapter` that are no exercise's (its render paths, its whole
    /// pictures): they run the student's whole road, every body of theirs together. `None` when
    /// the chapter has none.
    #[must_use]
    pub fn road(&self, manifest: &Manifest, chapter: u8) -> Option<Road> {
        let binary = crate::syllabus::chapter(chapter)?.binary;
        let paths = manifest
            .prove
            .filter
            .replace("{chapter}", &chapter.to_string());
        let own: Vec<&TestResult> = self
            .tests
            .iter()
            .filter(|t| t.exercise.is_none())
            .filter(|t| {
                t.target == binary
                    || (t.target == manifest.prove.test
                        && crate::cargo::test_name(&t.name).starts_with(&paths))
            })
            .collect();
        (!own.is_empty()).then(|| Road {
            chapter,
            passed: own.iter().filter(|t| t.status == Status::Passed).count(),
            total: own.len(),
        })
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
