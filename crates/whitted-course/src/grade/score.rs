//! Points: each exercise's share of its tests that passed, and which test targets the graded
//! chapters run.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::{BTreeMap, BTreeSet};

use super::outcome::ExerciseScore;
use super::test_result::{Status, TestResult};
use crate::manifest::Manifest;

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
                known: None,
            }
        })
        .collect()
}

/// Names the known mistake each exercise of `exercises` that lost points looks like, as
/// `cargo learn` names it at the save ([`whitted_learn::known::recognise`]): its failing public
/// tests are exactly those one of `mistakes` (the project's `chapters/mistakes.json`) makes
/// fail, each with the same values.
pub fn recognise_known(
    manifest: &Manifest,
    exercises: &mut [ExerciseScore],
    tests: &[TestResult],
    mistakes: &[whitted_learn::trees::Mistake],
) {
    for e in exercises.iter_mut().filter(|e| e.score < e.max) {
        let failing: BTreeMap<String, String> = tests
            .iter()
            .filter(|t| t.exercise == Some(e.entry) && !t.hidden && t.status == Status::Failed)
            .map(|t| {
                let name = t.name.rsplit("::").next().unwrap_or(&t.name);
                (name.to_string(), t.values.clone())
            })
            .collect();
        let name = &manifest.entries[e.entry].exercise.name;
        e.known =
            whitted_learn::known::recognise(mistakes, name, &failing).map(|m| m.looks_like.clone());
    }
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
