//! One check, in the order a student reads it (see [the loop's documentation](super)): what
//! changed first, then the verdict, the picture, and the progress of every chapter.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::Path;

use super::progress::progress;
use super::run::{check_targets, targets_of};
use super::say::Say;
use super::state::{State, save_states, saved_states, states};
use super::style::Style;
use super::verdict::{build_failure, verdict};
use crate::ToolError;
use crate::cargo::TestRun;
use crate::layout;
use crate::manifest::Manifest;
use crate::map;

/// What one check found.
pub struct Checked {
    /// The test runs.
    pub run: TestRun,
    /// Every exercise's state.
    pub states: Vec<State>,
}

/// One check (see [`crate::learn`]): the verdict, printed as soon as it is known,
/// then (with `draw`) the picture of the newest chapter the code can draw, then the progress.
/// The report is printed only with `report`; the lines saying what is being checked go to
/// stderr either way. `known` holds the states of the last check.
pub fn check(
    root: &Path,
    manifest: &Manifest,
    known: &[State],
    style: Style,
    report: bool,
    draw: bool,
) -> Result<Checked, ToolError> {
    let say = Say { report };
    let map = map::load_map(root, manifest).unwrap_or_default();
    let target_of = targets_of(manifest, &map);
    let mut run = TestRun::default();
    let state_now = |run: &TestRun, i: usize| -> State {
        let fresh = states(manifest, run);
        match &fresh[i] {
            State::Unknown => known.get(i).cloned().unwrap_or(State::Unknown),
            s => s.clone(),
        }
    };
    // the grader's screen, on every body, before anything is built: what it would refuse is
    // told now, with its line and a way to write it
    for refused in crate::screen::refused::refused(root, manifest) {
        say.report(&style.bad(&format!("{}\n", refused.line(manifest))));
    }
    // 0. what was saved since the last check comes first: its targets, then its verdict
    let regions = crate::changes::regions(root);
    let touched = crate::changes::touched(manifest, &crate::changes::saved(root), &regions);
    let mut first_targets: Vec<String> = touched
        .iter()
        .filter_map(|&i| target_of[i].clone())
        .collect();
    first_targets.sort();
    first_targets.dedup();
    first_targets.retain(|t| manifest.handout.tests.contains(t));
    if !first_targets.is_empty() {
        let ids: Vec<&str> = touched
            .iter()
            .map(|&i| manifest.entries[i].exercise.id.as_str())
            .collect();
        say.status(&format!(
            "checking what you changed: exercise {} …",
            ids.join(", ")
        ));
        if !check_targets(root, &first_targets, &mut run, &say)? {
            say.report(&build_failure(&run, style));
            return Ok(Checked {
                states: states(manifest, &run),
                run,
            });
        }
    }
    let mut shown: Option<usize> = None;
    let fresh = states(manifest, &run);
    for &i in &touched {
        let x = &manifest.entries[i].exercise;
        if fresh[i] == State::Done && known.get(i) != Some(&State::Done) {
            say.report(&style.good(&format!(
                "✓ exercise {} — {} ({}) passes: all its tests pass\n",
                x.id, x.title, manifest.entries[i].function
            )));
        }
    }
    // a changed exercise that fails: its verdict now, whatever comes before it
    if let Some(&i) = touched
        .iter()
        .find(|&&i| matches!(fresh[i], State::Failing(_)))
    {
        say.report(&verdict(manifest, &run, &fresh, i, style, Some(root)));
        shown = Some(i);
    }
    // 1. the verdict: the targets of the first exercises not done, one at a time
    while shown.is_none() {
        let next = (0..manifest.entries.len()).find(|&i| state_now(&run, i) != State::Done);
        let Some(next) = next else { break };
        let target = target_of[next].clone();
        match target {
            Some(t) if !run.targets.contains(&t) => {
                say.status(&format!(
                    "checking exercise {} ({}) …",
                    manifest.entries[next].exercise.id,
                    layout::core_test_target(root, &t).display()
                ));
                if !check_targets(root, &[t], &mut run, &say)? {
                    say.report(&build_failure(&run, style));
                    return Ok(Checked {
                        states: states(manifest, &run),
                        run,
                    });
                }
            }
            _ => {
                let fresh = states(manifest, &run);
                say.report(&verdict(manifest, &run, &fresh, next, style, Some(root)));
                shown = Some(next);
                break;
            }
        }
    }
    // the picture, before the other chapters' tests: what the student looks at next
    if draw {
        let now: Vec<State> = (0..manifest.entries.len())
            .map(|i| state_now(&run, i))
            .collect();
        say.report(&crate::picture::report(
            root, manifest, known, &now, shown, style,
        ));
    }
    // 2. the progress: every target not run yet
    let rest: Vec<String> = manifest
        .handout
        .tests
        .iter()
        .filter(|t| !run.targets.contains(*t))
        .cloned()
        .collect();
    if !rest.is_empty() {
        say.status(&format!("checking the other tests ({}) …", rest.join(", ")));
        if !check_targets(root, &rest, &mut run, &say)? {
            say.report(&build_failure(&run, style));
            return Ok(Checked {
                states: states(manifest, &run),
                run,
            });
        }
    }
    let all = states(manifest, &run);
    let next = all.iter().position(|s| *s != State::Done);
    let mut out = String::new();
    match (next, shown) {
        (None, _) => {
            out += &style.good(&format!(
                "✓ all {} exercises pass: {}\n",
                all.len(),
                super::progress::written_road(manifest)
            ));
        }
        (Some(n), Some(s)) if n == s => {}
        (Some(n), _) => {
            if shown.is_some() {
                let why = if known.get(n) == Some(&State::Done) {
                    "passed at the last check and fails now, so it comes first"
                } else {
                    "is the first exercise not done"
                };
                out += &format!(
                    "\nnote: exercise {} {why}:\n",
                    manifest.entries[n].exercise.id
                );
            }
            out += &verdict(manifest, &run, &all, n, style, Some(root));
        }
    }
    out.push('\n');
    out += &progress(manifest, &all, style);
    say.report(&out);
    save_states(root, manifest, &all)?;
    crate::changes::save(root, &regions)?;
    Ok(Checked { run, states: all })
}

/// `learn` itself: one check with its picture; `false` when the code does not compile.
pub fn once(root: &Path, manifest: &Manifest, style: Style) -> Result<bool, ToolError> {
    let known = saved_states(root, manifest);
    let checked = check(root, manifest, &known, style, true, true)?;
    Ok(checked.run.build_error.is_none())
}
