//! Where each exercise stands ([`State`]): read from the outcomes of its own tests after a
//! run, and kept between checks by exercise name in `.whitted/progress.json`.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use crate::ToolError;
use crate::cargo::{TestOutcome, TestRun, test_name};
use crate::manifest::Manifest;

/// Where `whitted learn` keeps its state and the images it renders, in the project.
pub const STATE_DIR: &str = ".whitted";

/// Where an exercise stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum State {
    /// All its own tests pass.
    Done,
    /// A test stopped at its `todo!()`: not written yet.
    ToDo,
    /// Written, but these of its own tests fail.
    Failing(Vec<String>),
    /// Its tests stop at the `todo!()` of this other exercise (its name), which comes first.
    Waiting(String),
    /// It has no test in the handout's targets (a mistake of the course, not the student's).
    NoTests,
    /// Not checked (its tests did not run, or the project does not build).
    Unknown,
}

impl State {
    /// A word for the list.
    #[must_use]
    pub fn word(&self) -> String {
        match self {
            State::Done => "done".into(),
            State::ToDo => "to do".into(),
            State::Failing(_) => "failing".into(),
            State::Waiting(name) => format!("waits for {name}"),
            State::NoTests => "no tests".into(),
            State::Unknown => "?".into(),
        }
    }

    /// The state a word of [`State::word`] names, as `.whitted/progress.json` keeps it (the
    /// failing tests are not kept).
    #[must_use]
    pub fn from_word(word: &str) -> State {
        match word {
            "done" => State::Done,
            "to do" => State::ToDo,
            "failing" => State::Failing(Vec::new()),
            "no tests" => State::NoTests,
            w => match w.strip_prefix("waits for ") {
                Some(name) => State::Waiting(name.to_string()),
                None => State::Unknown,
            },
        }
    }
}

/// The name of the exercise whose `todo!()` a test's output `text` stopped at.
#[must_use]
pub fn todo_name(text: &str) -> Option<&str> {
    whitted_syllabus::todo::find(text).map(|t| t.name)
}

/// The state of every exercise of `manifest` (in its order) after the test run `run`: those
/// whose tests did not run are [`State::Unknown`].
#[must_use]
pub fn states(manifest: &Manifest, run: &TestRun) -> Vec<State> {
    manifest
        .entries
        .iter()
        .map(|e| {
            if run.build_error.is_some() {
                return State::Unknown;
            }
            let prefix = e.exercise.test_prefix();
            let own: Vec<(&String, &TestOutcome)> = run
                .outcomes
                .iter()
                .filter(|(name, _)| test_name(name).starts_with(&prefix))
                .collect();
            if own.is_empty() {
                return if run.targets.len() == manifest.handout.tests.len() {
                    State::NoTests
                } else {
                    State::Unknown
                };
            }
            let failed: Vec<String> = own
                .iter()
                .filter(|(_, o)| **o == TestOutcome::Failed)
                .map(|(n, _)| (*n).clone())
                .collect();
            if failed.is_empty() {
                return State::Done;
            }
            let stopped_at: Vec<&str> = failed
                .iter()
                .filter_map(|n| run.failures.get(n).and_then(|t| todo_name(t)))
                .collect();
            // a failure that printed nothing says nothing of where it stopped (a panic on a
            // thread that another test spawned prints in that test's output)
            let telling = failed
                .iter()
                .filter(|n| {
                    run.failures
                        .get(*n)
                        .is_some_and(|t| !message_lines(t).is_empty())
                })
                .count();
            if stopped_at.contains(&e.exercise.name.as_str()) {
                State::ToDo
            } else if !stopped_at.is_empty() && stopped_at.len() == telling {
                // every failing test that tells stopped at another exercise's todo!(): that
                // one comes first
                State::Waiting(stopped_at[0].to_string())
            } else {
                State::Failing(failed)
            }
        })
        .collect()
}

/// For each exercise (by manifest index), the other exercises its own tests call, by the
/// measured map `map` (each test table whose tests are the exercise's own, `ex_NAME_…`), in
/// the manifest's order.
#[must_use]
pub fn calls(manifest: &Manifest, map: &[crate::map::Group]) -> Vec<Vec<usize>> {
    manifest
        .entries
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let prefix = e.exercise.test_prefix();
            let own = |t: &String| {
                t.split_once("::")
                    .is_some_and(|(_, n)| n.starts_with(&prefix))
            };
            let called: BTreeSet<usize> = map
                .iter()
                .filter(|g| g.tests.iter().any(own))
                .flat_map(|g| g.needs.iter().copied())
                .filter(|&j| j != i)
                .collect();
            called.into_iter().collect()
        })
        .collect()
}

/// `states` with the root of each failure first: an exercise whose tests fail while an
/// exercise they call ([`calls`]) is not done waits for that one (the first such, or what
/// it waits for in turn) and is not told as failing, since its own code may be right.
#[must_use]
pub fn rooted(manifest: &Manifest, states: Vec<State>, calls: &[Vec<usize>]) -> Vec<State> {
    let not_done = |s: &State| matches!(s, State::Failing(_) | State::ToDo | State::Waiting(_));
    let mut out = states.clone();
    for (i, state) in states.iter().enumerate() {
        if !matches!(state, State::Failing(_)) {
            continue;
        }
        let Some(&j) = calls
            .get(i)
            .and_then(|c| c.iter().find(|&&j| states.get(j).is_some_and(not_done)))
        else {
            continue;
        };
        // the root of the root: a called exercise that itself waits names what it waits for
        let mut root = manifest.entries[j].exercise.name.clone();
        for _ in 0..states.len() {
            let next = match manifest.by_name(&root).map(|k| &out[k]) {
                Some(State::Waiting(k)) if *k != root => k.clone(),
                _ => break,
            };
            root = next;
        }
        out[i] = State::Waiting(root);
    }
    out
}

/// The lines of a failed test's output worth showing: the panic's place and message, without
/// the notes on backtraces (the first panic of a test process prints `note: run with
/// RUST_BACKTRACE=1 …`, in whichever test panicked first: it would come and go).
#[must_use]
pub fn message_lines(text: &str) -> Vec<&str> {
    text.lines()
        .filter(|l| {
            let backtrace_note = l.starts_with("note: ") && l.contains("RUST_BACKTRACE");
            !l.trim().is_empty() && !backtrace_note
        })
        .collect()
}

/// The exercises' states at the last check, kept by exercise name (`.whitted/progress.json`).
#[must_use]
pub fn saved_states(root: &Path, manifest: &Manifest) -> Vec<State> {
    let saved: BTreeMap<String, String> =
        std::fs::read_to_string(root.join(STATE_DIR).join("progress.json"))
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok())
            .unwrap_or_default();
    manifest
        .entries
        .iter()
        .map(|e| {
            saved
                .get(&e.exercise.name)
                .map_or(State::Unknown, |w| State::from_word(w))
        })
        .collect()
}

/// Keeps the states of a complete check for the next one.
pub fn save_states(root: &Path, manifest: &Manifest, states: &[State]) -> Result<(), ToolError> {
    let saved: BTreeMap<&str, String> = manifest
        .entries
        .iter()
        .zip(states)
        .filter(|(_, s)| **s != State::Unknown)
        .map(|(e, s)| (e.exercise.name.as_str(), s.word()))
        .collect();
    let dir = root.join(STATE_DIR);
    std::fs::create_dir_all(&dir).map_err(|e| ToolError::io(&dir, e))?;
    let text = serde_json::to_string_pretty(&saved)
        .map_err(|e| ToolError::Cargo(format!("cannot write the progress: {e}")))?;
    crate::files::write_file(&dir.join("progress.json"), text.as_bytes())
}

/// The exercises that are done in `now` but were not in `before`.
#[must_use]
pub fn newly_done(before: &[State], now: &[State]) -> BTreeSet<usize> {
    (0..now.len())
        .filter(|&i| now[i] == State::Done && before.get(i) != Some(&State::Done))
        .collect()
}
