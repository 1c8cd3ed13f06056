//! The loop's verdict tells the truth: the root of a failure first (an exercise whose tests
//! call a failing one waits for it), the known mistake named from the exercise's own tests on
//! the save that makes it, and pictures that follow the failing exercise.

mod common;

use std::collections::BTreeMap;

use common::{manifest, root};
use whitted_course::cargo::{TestOutcome, TestRun};
use whitted_course::learn::{self, State, Style};
use whitted_course::manifest::Manifest;
use whitted_course::picture::{Stage, choose};
use whitted_learn::known;
use whitted_learn::trees::load_mistakes;

/// A run of every handout target in which each exercise has one test, `works`, passing but for
/// the exercises `failing` (by name), whose tests fail with `values` (by exercise name) or a
/// message with no value.
fn run_failing(m: &Manifest, failing: &[&str], values: &BTreeMap<&str, &str>) -> TestRun {
    let mut run = TestRun {
        targets: m.handout.tests.iter().cloned().collect(),
        ..TestRun::default()
    };
    for e in &m.entries {
        let binary = whitted_course::syllabus::chapter(e.chapter).unwrap().binary;
        let id = format!("{binary}::{}works", e.exercise.test_prefix());
        if failing.contains(&e.exercise.name.as_str()) {
            run.outcomes.insert(id.clone(), TestOutcome::Failed);
            let message = values.get(e.exercise.name.as_str()).unwrap_or(&"wrong");
            run.failures.insert(
                id,
                format!("thread 'x' panicked at tests/a.rs:1:1:\n{message}\n"),
            );
        } else {
            run.outcomes.insert(id, TestOutcome::Passed);
        }
    }
    run
}

fn rooted(m: &Manifest, run: &TestRun) -> Vec<State> {
    let map = whitted_learn::map::load_map(&root(), m).unwrap();
    let calls = learn::calls(m, &map);
    learn::rooted(m, learn::states(m, run), &calls)
}

/// 3.4 (mirror_direction) wrong and 3.5 (highlight), whose tests call it, failing with it:
/// 3.5 waits for 3.4 and is not told as failing; 3.4 is, and the first exercise not done.
#[test]
fn a_caller_waits_for_the_failing_exercise_it_calls() {
    let m = manifest();
    let run = run_failing(&m, &["mirror_direction", "highlight"], &BTreeMap::new());
    let states = rooted(&m, &run);
    let at = |name: &str| states[m.by_name(name).unwrap()].clone();
    assert!(
        matches!(at("mirror_direction"), State::Failing(_)),
        "3.4: {:?}",
        at("mirror_direction")
    );
    assert_eq!(
        at("highlight"),
        State::Waiting("mirror_direction".into()),
        "3.5 should wait for 3.4"
    );
    let first = states.iter().position(|s| *s != State::Done).unwrap();
    assert_eq!(
        m.entries[first].exercise.name, "mirror_direction",
        "the first exercise not done"
    );
    // the verdict on the caller says what it waits for, not that it fails
    let i = m.by_name("highlight").unwrap();
    let text = learn::verdict(&m, &run, &states, i, Style::plain(), None);
    let head = text.lines().next().unwrap_or_default();
    assert!(
        head.contains("its tests call exercise 3.4 (mirror_direction), which is not done"),
        "{head}"
    );
    // alone, 3.5's failure is its own
    let run = run_failing(&m, &["highlight"], &BTreeMap::new());
    let states = rooted(&m, &run);
    assert!(
        matches!(states[i], State::Failing(_)),
        "3.5 alone: {:?}",
        states[i]
    );
}

/// An exercise whose tests call nothing else keeps its failure, whatever else fails.
#[test]
fn the_first_exercise_is_its_own_root() {
    let m = manifest();
    let run = run_failing(&m, &["viewing_basis", "ambient"], &BTreeMap::new());
    let states = rooted(&m, &run);
    for name in ["viewing_basis", "ambient"] {
        let s = &states[m.by_name(name).unwrap()];
        assert!(matches!(s, State::Failing(_)), "{name}: {s:?}");
    }
}

/// Every known mistake of `chapters/mistakes.json` is told by its exercise's own tests: its
/// recorded values are there, and they name it and no other mistake.
#[test]
fn every_known_mistake_is_told_by_its_tests() {
    let mistakes = load_mistakes(&root());
    let mutants = whitted_course::mistakes::load(&root()).unwrap();
    assert_eq!(
        mistakes.len(),
        mutants.len(),
        "chapters/mistakes.json holds {} mistakes, the hand-written mutants are {}",
        mistakes.len(),
        mutants.len()
    );
    for m in &mistakes {
        assert!(
            !m.tests.is_empty(),
            "mistake {} ({}): no test value recorded",
            m.name,
            m.exercise
        );
        let told = known::recognise(&mistakes, &m.exercise, &m.tests).map(|k| k.name.as_str());
        assert_eq!(
            told,
            Some(m.name.as_str()),
            "mistake {}'s own values",
            m.name
        );
    }
}

/// The verdict on 3.4 with r's sign turned names the known mistake, from the values its tests
/// print, with no hint asked; another value names none.
#[test]
fn the_verdict_names_the_known_mistake_without_a_hint() {
    let m = manifest();
    let mistakes = load_mistakes(&root());
    let sign = mistakes
        .iter()
        .find(|k| k.name == "mirror-sign")
        .expect("mirror-sign in chapters/mistakes.json");
    // the student's run prints what the mutant's did
    let mut run = TestRun {
        targets: m.handout.tests.iter().cloned().collect(),
        ..TestRun::default()
    };
    let i = m.by_name("mirror_direction").unwrap();
    for e in &m.entries {
        let binary = whitted_course::syllabus::chapter(e.chapter).unwrap().binary;
        let id = format!("{binary}::{}works", e.exercise.test_prefix());
        run.outcomes.insert(id, TestOutcome::Passed);
    }
    for (name, values) in &sign.tests {
        let id = format!("ch03_shading::{name}");
        run.outcomes.insert(id.clone(), TestOutcome::Failed);
        run.failures.insert(
            id,
            format!("thread '{name}' panicked at tests/ch03_shading.rs:99:5:\n{values}\n"),
        );
    }
    let states = learn::states(&m, &run);
    let text = learn::verdict(&m, &run, &states, i, Style::plain(), Some(&root()));
    assert!(
        text.contains(&format!(
            "a known mistake: this looks like {}",
            sign.looks_like
        )),
        "the verdict on 3.4 does not name r's sign:\n{text}"
    );
    // other values: no name
    for value in run.failures.values_mut() {
        *value = value.replace('0', "7");
    }
    let text = learn::verdict(&m, &run, &states, i, Style::plain(), Some(&root()));
    assert!(
        !text.contains("a known mistake"),
        "other values named a mistake:\n{text}"
    );
}

/// One save that finishes chapter 3 and breaks 4.4: the picture follows 4.4, not chapter 3
/// turned green.
#[test]
fn the_picture_follows_the_failing_exercise() {
    let m = manifest();
    let last3 = (0..m.entries.len())
        .rfind(|&i| m.entries[i].chapter == 3)
        .unwrap();
    let broken = m.by_name("send_feeler").unwrap();
    let mut before = vec![State::Done; m.entries.len()];
    before[last3] = State::Failing(Vec::new());
    let mut now = vec![State::Done; m.entries.len()];
    now[broken] = State::Failing(Vec::new());
    let chosen = choose(&m, &before, &now, Some(broken));
    assert!(
        !chosen.contains(&Stage::Chapter(3)),
        "the picture is chapter 3's, though 4.4 fails: {chosen:?}"
    );
    // with nothing broken, the chapter that turned green is the picture
    let chosen = choose(&m, &before, &vec![State::Done; m.entries.len()], None);
    assert_eq!(chosen, vec![Stage::Chapter(3)]);
}

/// 3.4 wrong, the rest of chapter 3 written and waiting for it: chapter 3's picture is drawn
/// (what waits for a written exercise is written too), and no picture waits for a `todo!()`.
#[test]
fn exercises_waiting_for_a_failing_one_are_written() {
    let m = manifest();
    let mirror = m.by_name("mirror_direction").unwrap();
    let mut now = vec![State::Done; m.entries.len()];
    now[mirror] = State::Failing(Vec::new());
    for (s, e) in now.iter_mut().zip(&m.entries).skip(mirror + 1) {
        if e.chapter == 3 {
            *s = State::Waiting("mirror_direction".into());
        }
    }
    let chosen = choose(&m, &now, &now, Some(mirror));
    assert!(
        chosen.contains(&Stage::Chapter(3)),
        "chapter 3 is written (3.4 wrong): {chosen:?}"
    );
    // waiting for a todo!(): not written, no chapter picture
    now[mirror] = State::ToDo;
    let chosen = choose(&m, &now, &now, Some(mirror));
    assert!(
        !chosen.contains(&Stage::Chapter(3)),
        "3.4 not written: {chosen:?}"
    );
}
