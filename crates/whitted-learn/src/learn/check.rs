//! One check, in the order a student reads it (see [the loop's documentation](super)): what
//! changed first, then the verdict, the picture, and the progress of every chapter.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::path::Path;

use super::progress::progress;
use super::run::{check_targets, targets_of};
use super::say::Say;
use super::state::{State, calls, rooted, save_states, saved_states, states};
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
    let calls = calls(manifest, &map);
    let mut run = TestRun::default();
    // every state as the tests of this check say, else as the last check left it, with the
    // root of each failure first (an exercise waits for a failing one its tests call)
    let now = |run: &TestRun| -> Vec<State> {
        let seen = states(manifest, run)
            .into_iter()
            .enumerate()
            .map(|(i, s)| match s {
                State::Unknown => known.get(i).cloned().unwrap_or(State::Unknown),
                s => s,
            })
            .collect();
        rooted(manifest, seen, &calls)
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
    let fresh = now(&run);
    for &i in &touched {
        let x = &manifest.entries[i].exercise;
        if fresh[i] == State::Done && known.get(i) != Some(&State::Done) {
            say.report(&style.good(&format!(
                "✓ exercise {} — {} ({}) passes: all its tests pass\n",
                x.id, x.title, manifest.entries[i].function
            )));
        }
    }
    // a changed exercise that fails, or waits for one that fails: the verdict on the one
    // that fails now, whatever comes before it (one whose tests ran in this check: a failure
    // known only from the last check is found again by step 1)
    let failing = |i: usize| {
        matches!(fresh[i], State::Failing(_))
            && target_of[i]
                .as_ref()
                .is_some_and(|t| run.targets.contains(t))
    };
    let root_of = |i: usize| match &fresh[i] {
        State::Waiting(name) => manifest.by_name(name).filter(|&j| failing(j)),
        _ => Some(i).filter(|&i| failing(i)),
    };
    if let Some(i) = touched.iter().find_map(|&i| root_of(i)) {
        say.report(&verdict(manifest, &run, &fresh, i, style, Some(root)));
        say.report(&waiting_on(manifest, &fresh, &touched, i));
        shown = Some(i);
    }
    // 1. the verdict: the targets of the first exercises not done, one at a time
    while shown.is_none() {
        let next = now(&run).iter().position(|s| *s != State::Done);
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
                let fresh = now(&run);
                say.report(&verdict(manifest, &run, &fresh, next, style, Some(root)));
                say.report(&waiting_on(manifest, &fresh, &touched, next));
                shown = Some(next);
                break;
            }
        }
    }
    // the picture, before the other chapters' tests: what the student looks at next
    if draw {
        say.report(&crate::picture::report(
            root,
            manifest,
            known,
            &now(&run),
            shown,
            style,
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
    let all = rooted(manifest, states(manifest, &run), &calls);
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

/// The line under a verdict on exercise `on` naming the exercises of `changed` that wait for
/// it: their tests call it, so they are judged once it passes.
fn waiting_on(manifest: &Manifest, states: &[State], changed: &[usize], on: usize) -> String {
    let name = &manifest.entries[on].exercise.name;
    let waiting: Vec<String> = changed
        .iter()
        .filter(|&&i| i != on && states[i] == State::Waiting(name.clone()))
        .map(|&i| {
            let e = &manifest.entries[i];
            format!("{} ({})", e.exercise.id, e.function)
        })
        .collect();
    if waiting.is_empty() {
        return String::new();
    }
    format!(
        "  you changed exercise {} too: {} exercise {}, so {} judged once exercise {} passes\n",
        waiting.join(", "),
        if waiting.len() == 1 {
            "its tests call"
        } else {
            "their tests call"
        },
        manifest.entries[on].exercise.id,
        if waiting.len() == 1 {
            "it is"
        } else {
            "they are"
        },
        manifest.entries[on].exercise.id,
    )
}

/// `learn` itself: one check with its picture; `false` when the code does not compile.
pub fn once(root: &Path, manifest: &Manifest, style: Style) -> Result<bool, ToolError> {
    let known = saved_states(root, manifest);
    let checked = check(root, manifest, &known, style, true, true)?;
    Ok(checked.run.build_error.is_none())
}
