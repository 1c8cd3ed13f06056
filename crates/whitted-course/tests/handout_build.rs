//! Handouts built and run, as a course uses them. These tests build copies of the project,
//! so they are `#[ignore]`d in a plain `cargo test`; `.ci/run` runs them with
//! `cargo test --release --test handout_build -- --ignored --test-threads 1`.
//!
//! - A handout of every exercise builds, and its tests fail exactly as
//!   `chapters/exercise-tests.toml` says (each exercise's own tests, and the render tests
//!   that need it) — set equality; `whitted learn` in it shows 0 of N and the first
//!   exercise's failing test; a chapter binary says which exercise is missing, in one line.
//! - A handout of chapter 3 alone fails exactly chapter 3's tests (it holds none of chapters 4
//!   and 5); putting its reference bodies back one by one turns its exercises green in order,
//!   and `whitted learn`, which counts chapter 3's exercises alone, ends at N of N.
//! - A week's handout (`--chapters 3-4`) counts 0 of 11, then all 11 pass, every test it holds
//!   passes, and chapter 5's binary says chapter 5 is not part of it.
//! - Across all chapters, exercise by exercise: in a copy where every exercise from the k-th
//!   on is switched off (the poison switch of `whitted formulas prove`, one build for all
//!   steps), `whitted learn` shows k of N done and exercise k next, for k = 0 … N. In the same
//!   copy, each hand-written mutant switched on in turn (the switch of `whitted trees`): the
//!   verdict names its exercise, and the first wrong number of the chapter's ray trees and the
//!   known mistake it looks like name it too.
//! - `whitted learn watch` reruns when a file is saved by renaming, and draws the chapter.

mod common;

use common::{manifest, root, text};

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

use whitted_course::deps;
use whitted_course::handout;
use whitted_course::manifest::Manifest;

/// One target directory for every copy, so the dependencies are built once.
fn target_dir() -> PathBuf {
    root().join("target").join("handout")
}

fn cargo() -> Command {
    let mut c = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    c.env("CARGO_TARGET_DIR", target_dir())
        .env("CARGO_PROFILE_DEV_DEBUG", "0")
        .env_remove("WHITTED_POISON");
    c
}

/// Builds the handout's test targets in `project` and runs each: the failed and the passed
/// tests, as `target::name`.
fn run_tests(project: &Path, m: &Manifest) -> (BTreeSet<String>, BTreeSet<String>) {
    let exes =
        whitted_course::poison::build_tests(project, &target_dir(), &m.handout.tests, &[]).unwrap();
    let (mut failed, mut passed) = (BTreeSet::new(), BTreeSet::new());
    for (target, exe) in exes {
        let out = Command::new(&exe)
            .args(["--test-threads", "2"])
            .current_dir(project)
            .env_remove("WHITTED_POISON")
            .env_remove("WHITTED_BLESS")
            .output()
            .unwrap();
        common::sort_outcomes(&target, &out, &mut failed, &mut passed);
    }
    (failed, passed)
}

/// The tests the map (chapters/exercise-tests.toml) says fail when the exercises `stripped`
/// are missing.
fn expected(m: &Manifest, all: &BTreeSet<String>, stripped: &[usize]) -> BTreeSet<String> {
    let map = deps::load_map(&root(), m).unwrap();
    deps::expected(&map, all, stripped)
}

/// Asserts two sets of tests are equal, listing the differences.
#[track_caller]
fn assert_same(failed: &BTreeSet<String>, expected: &BTreeSet<String>) {
    let extra: Vec<_> = failed.difference(expected).collect();
    let missing: Vec<_> = expected.difference(failed).collect();
    assert!(
        extra.is_empty() && missing.is_empty(),
        "failing but not expected: {extra:?}\nexpected but passing: {missing:?}"
    );
}

/// Asserts that a `whitted learn` report counts `done` of `n` exercises done and names
/// exercise `next` (a manifest index) as the next one, or, with `None`, says that all of them
/// pass.
#[track_caller]
fn assert_progress(report: &str, m: &Manifest, n: usize, done: usize, next: Option<usize>) {
    assert!(
        report.contains(&format!("{done} of {n} exercises done")),
        "{report}"
    );
    match next {
        Some(i) => assert!(
            report.contains(&format!("✗ exercise {} —", m.entries[i].exercise.id)),
            "{report}"
        ),
        None => assert!(
            report.contains(&format!("all {n} exercises pass")),
            "{report}"
        ),
    }
}

/// A test's name without its target.
fn learn_name(t: &str) -> &str {
    whitted_course::cargo::test_name(t)
}

/// `whitted learn` (this build's) run on the project at `project`.
fn learn(project: &Path, poison: Option<String>) -> String {
    let vars: Vec<(&str, String)> = poison.map(|p| ("WHITTED_POISON", p)).into_iter().collect();
    learn_with(project, &vars)
}

/// `whitted learn` run on the project at `project` with the switches `vars` set (the poison
/// switch of `whitted formulas prove`, the mutant switch of `whitted trees`).
fn learn_with(project: &Path, vars: &[(&str, String)]) -> String {
    let mut c = Command::new(env!("CARGO_BIN_EXE_whitted"));
    c.args(["learn", "--root"])
        .arg(project)
        .env("CARGO_TARGET_DIR", target_dir())
        .env("CARGO_PROFILE_DEV_DEBUG", "0")
        .env("NO_COLOR", "1")
        .env_remove("WHITTED_POISON")
        .env_remove(whitted_course::mistakes::SWITCH_VAR);
    for (k, v) in vars {
        c.env(k, v);
    }
    let out = c.output().unwrap();
    assert!(out.status.success(), "{}", text(&out));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Exercise `i`'s file in the handout at `student`: its path, its text now, and its text with
/// the `todo!()` between the markers replaced by the reference body of region `r`.
fn reference_body_back(
    student: &Path,
    m: &Manifest,
    r: &handout::Region,
    i: usize,
) -> (PathBuf, String, String) {
    let path = student.join(&r.file);
    let now = std::fs::read_to_string(&path).unwrap();
    let todo = format!("{}{}\n", r.indent, handout::todo_statement(&m.entries[i]));
    let back = now.replacen(&todo, &r.solution, 1);
    (path, now, back)
}

#[test]
#[ignore = "builds a handout (minutes); .ci/run runs it"]
fn a_full_handout_fails_exactly_the_tests_of_its_exercises() {
    let m = manifest();
    let n = m.entries.len();
    let dir = tempfile::tempdir().unwrap();
    let student = dir.path().join("student");
    let all: Vec<usize> = (0..n).collect();
    handout::write(&root(), &m, &all, &student).unwrap();

    let built = cargo()
        .args(["build", "--locked"])
        .current_dir(&student)
        .output()
        .unwrap();
    assert!(
        built.status.success(),
        "the handout does not build: {}",
        text(&built)
    );

    let (failed, passed) = run_tests(&student, &m);
    let every: BTreeSet<String> = failed.union(&passed).cloned().collect();
    assert_same(&failed, &expected(&m, &every, &all));
    eprintln!(
        "full handout: {} of {} tests fail, as the manifest says",
        failed.len(),
        every.len()
    );

    let report = learn(&student, None);
    let first = &m.entries[0].exercise;
    assert!(
        report.contains(&format!("0 of {n} exercises done")),
        "{report}"
    );
    assert!(
        report.contains(&format!("✗ exercise {} — {}", first.id, first.title)),
        "{report}"
    );
    assert!(
        report.contains(&format!("failing: {}", first.test_prefix())),
        "{report}"
    );

    // a chapter binary over the missing exercises: one line, exit status 2
    let exe = target_dir().join("debug").join("ch02_generic_objects");
    let out = Command::new(exe)
        .args(["--width", "8", "-o"])
        .arg(dir.path().join("x.png"))
        .output()
        .unwrap();
    let err = common::one_line_error(&out, "ch02_generic_objects over missing exercises");
    assert!(
        err.starts_with("error: exercise ") && err.contains("is not written yet"),
        "{err}"
    );
    assert!(!dir.path().join("x.png").exists());
}

/// A handout of chapter 3 fails exactly the tests of its exercises. As the reference bodies come
/// back one at a time, `learn` says each passes and turns them green in order and, from the
/// first exercise on, draws what is written beside the book's picture of the same stage:
/// chapter 3's scene through chapter 2's road before anything is written, then the quantity of
/// the newest exercise written (each the same as the book's), then chapter 3's picture once
/// the chapter is green. A deliberate mistake (max(n·s, 0) unclamped) is checked first, at
/// once, and its picture differs. (Chapter 4's scene through chapter 3's road is chosen by
/// `handout.rs`'s `each_check_draws_the_stage_of_the_chapter_being_written`, and drawn in
/// `exercise_by_exercise_…`.)
#[test]
#[ignore = "builds a handout (minutes); .ci/run runs it"]
fn a_chapter_handout_fails_its_tests_and_turns_green_as_the_bodies_come_back() {
    let m = manifest();
    let chapters = handout::select(&m, Some((3, 3)), &[]).unwrap();
    // the handout counts its own exercises, chapter 3's, and nothing of chapters 4 and 5
    let n = chapters.len();
    let dir = tempfile::tempdir().unwrap();
    let student = dir.path().join("ch3");
    handout::write(&root(), &m, &chapters, &student).unwrap();
    let own = whitted_course::manifest::load(&student.join(whitted_course::manifest::DEFAULT_PATH))
        .unwrap();
    assert_eq!(own.entries.len(), n);
    // its test targets (chapters 1 to 3 and the render paths' tests of those chapters) fail
    // exactly as the map says of chapter 3's exercises: no test meets a later chapter's body
    let (failed, passed) = run_tests(&student, &own);
    let every: BTreeSet<String> = failed.union(&passed).cloned().collect();
    assert_same(&failed, &expected(&m, &every, &chapters));

    // the reference bodies back, one at a time, in order; an exercise is done once none of the
    // exercises its own tests need is missing (by the map: 5.5 waits for chapter 4 too)
    let map = deps::load_map(&root(), &m).unwrap();
    let is_done = |e: &whitted_course::manifest::Entry, missing: &[usize]| {
        every
            .iter()
            .filter(|t| learn_name(t).starts_with(&e.exercise.test_prefix()))
            .all(|t| deps::needs_of(&map, t).iter().all(|i| !missing.contains(i)))
    };
    let done_with = |missing: &[usize]| {
        chapters
            .iter()
            .filter(|&&i| is_done(&m.entries[i], missing))
            .count()
    };
    let report = learn(&student, None);
    assert!(
        report.contains(&format!("{} of {n} exercises done", done_with(&chapters))),
        "{report}"
    );
    let same = "  compare: the same as the reference";
    let picture = |report: &str, what: &str, file: &str| {
        let line = format!(
            "✓ picture: {what} as your code draws it, beside the book's and their difference: .whitted/{file}\n{same}"
        );
        assert!(report.contains(&line), "no {line:?} in:\n{report}");
        assert!(student.join(".whitted").join(file).is_file(), "{file}");
    };
    picture(
        &report,
        "chapter 3's scene through chapter 2's road (before chapter 3's exercises)",
        "ch03-flat.png",
    );
    let regions = handout::regions(&root(), &m).unwrap();
    for (j, &i) in chapters.iter().enumerate() {
        let x = &m.entries[i].exercise;
        let (path, now, back) = reference_body_back(&student, &m, &regions[i], i);
        assert_ne!(back, now, "exercise {}'s todo!() not found", x.id);
        if x.name == "lambert" {
            // a right body that the grader's screen would refuse: told at the save, at its
            // file and line, before the verdict, with a way to write it
            let refused = back.replacen(
                "n.dot(s).max(0.0)",
                "let env = std::env::var(\"LAMBERT\");\n    n.dot(s).max(0.0)",
                1,
            );
            assert_ne!(refused, back);
            std::fs::write(&path, &refused).unwrap();
            let line = refused
                .lines()
                .position(|l| l.contains("std::env::var"))
                .unwrap()
                + 1;
            let report = learn(&student, None);
            let told = format!(
                "✗ the grader would grade exercise {} (lambert) as not written: {}:{line}: `std::env::var` (`env`) reaches the environment, which a formula never needs; compute the result from the function's arguments",
                x.id,
                regions[i].file.display()
            );
            assert_eq!(report.lines().next(), Some(told.as_str()), "{report}");
            // the cosine law written without its clamp: its verdict first, its picture differs
            let wrong = back.replacen("n.dot(s).max(0.0)", "n.dot(s)", 1);
            assert_ne!(wrong, back, "the cosine law's reference body has changed");
            std::fs::write(&path, &wrong).unwrap();
            let report = learn(&student, None);
            let first = report.lines().find(|l| l.starts_with("✗ exercise"));
            assert_eq!(
                first,
                Some(
                    format!(
                        "✗ exercise {} — {} (shading::lambert, 1 point): 1 of its 1 tests fail",
                        x.id, x.title
                    )
                    .as_str()
                ),
                "{report}"
            );
            let differs = format!(
                "✗ picture: exercise {}'s quantity ({}) over its chapter's scene as your code draws it, beside the book's and their difference: .whitted/ch03-diffuse.png\n  compare: ",
                x.id, x.title
            );
            assert!(report.contains(&differs), "{report}");
            assert!(!report.contains(&format!("{differs}the same")), "{report}");
        }
        std::fs::write(&path, back).unwrap();
        let report = learn(&student, None);
        assert_progress(
            &report,
            &m,
            n,
            done_with(&chapters[j + 1..]),
            chapters.get(j + 1).copied(),
        );
        let passes = format!(
            "✓ exercise {} — {} ({}) passes",
            x.id, x.title, m.entries[i].function
        );
        assert_eq!(
            report.contains(&passes),
            is_done(&m.entries[i], &chapters[j + 1..]),
            "{passes:?} in:\n{report}"
        );
        let next = chapters.get(j + 1).map(|&k| &m.entries[k]);
        match (&x.picture, next) {
            // chapter 3 is green: its own picture
            _ if next.is_none_or(|e| e.chapter != m.entries[i].chapter) => picture(
                &report,
                &format!("chapter {}'s scene", m.entries[i].chapter),
                &format!(
                    "{}.png",
                    whitted_course::syllabus::chapter(m.entries[i].chapter)
                        .unwrap()
                        .binary
                ),
            ),
            (Some(file), _) => picture(
                &report,
                &format!(
                    "exercise {}'s quantity ({}) over its chapter's scene",
                    x.id, x.title
                ),
                file,
            ),
            (None, _) => panic!(
                "exercise {} of chapter 3 has no picture and is not the chapter's last",
                x.id
            ),
        }
    }
}

#[test]
#[ignore = "builds a poisoned copy and runs whitted learn N + 1 times, and once per known mistake (minutes); .ci/run runs it"]
fn exercise_by_exercise_learn_counts_up_to_all_of_them_and_tells_each_known_mistake() {
    let m = manifest();
    let n = m.entries.len();
    // a copy of the project with every exercise behind the poison switch, and every
    // hand-written mutant behind the mutant switch: one build for both
    let locations = whitted_course::source::locate_all(&root(), &m).unwrap();
    let poisoned =
        whitted_course::poison::PoisonedCopy::new(&root(), &m, &locations, "whitted-learn-", false)
            .unwrap();
    let copy = &poisoned.project;
    let mutants = whitted_course::mistakes::load(&root()).unwrap();
    whitted_course::mistakes::switch(copy, &m, &mutants).unwrap();

    for k in 0..=n {
        // exercises k … n−1 missing, those before written
        let poison = (k < n).then(|| format!("{k}-{}", n - 1));
        let report = learn(copy, Some(poison.unwrap_or_default()));
        assert_progress(&report, &m, n, k, (k < n).then_some(k));
        // from chapter 2 on, every verdict comes with a picture of what is written, the
        // book's (chapter 1's picture needs all of chapter 1: its exercises are the road)
        // (a ✓ beside a verdict on an exercise not written; no mark beside one that fails, as
        // the poison's todo!() does, which says the picture cannot show it yet)
        if m.entries.get(k).is_none_or(|e| e.chapter > 1) {
            let lines: Vec<&str> = report.lines().collect();
            let first = lines.iter().position(|l| {
                ["✓ picture: ", "✗ picture: ", "picture: "]
                    .iter()
                    .any(|p| l.starts_with(p))
            });
            let drawn_as_the_book = first.is_some_and(|at| {
                let (line, next) = (lines[at], lines.get(at + 1).copied().unwrap_or(""));
                line.starts_with("✓ picture: ")
                    || (line.starts_with("picture: ")
                        && next.contains("the same as the reference")
                        && lines
                            .get(at + 2)
                            .is_some_and(|l| l.contains("show exercise")))
            });
            assert!(
                drawn_as_the_book,
                "{k} exercises written: no picture, or one unlike the book's:\n{report}"
            );
        }
    }
    each_known_mistake_is_told_as_itself(copy, &m, &mutants);
}

/// Each hand-written mutant applied to the copy (all the other exercises written), as a
/// student who made that mistake and asked for the exercise's first hint runs `learn`: the
/// verdict names the mutant's exercise; the exercise's own picture, when it has one, differs
/// from the book's; the chapter's picture is drawn beside the book's; the first wrong number of its ray trees is computed in that exercise; and the mistake is told
/// by its words (`chapters/mistakes.json`), in the verdict from its tests' values and under
/// the picture from its trees. A mutant the chapter's scene cannot show (its
/// picture and trees are the reference's, so `whitted trees` kept no fingerprint of it) is
/// said to be so.
fn each_known_mistake_is_told_as_itself(
    copy: &Path,
    m: &Manifest,
    mutants: &[whitted_course::mistakes::Mutant],
) {
    let known = whitted_course::trees::MISTAKES;
    let known: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(root().join(known)).unwrap()).unwrap();
    let state = copy.join(".whitted");
    let started = std::time::Instant::now();
    for mu in mutants {
        let i = m.by_name(&mu.exercise).unwrap();
        let x = &m.entries[i].exercise;
        // a student whose last check found this exercise failing and every other one done,
        // and who has seen its first hint
        let progress: serde_json::Map<String, serde_json::Value> = m
            .entries
            .iter()
            .map(|e| {
                let word = if e.exercise.name == mu.exercise {
                    "failing"
                } else {
                    "done"
                };
                (e.exercise.name.clone(), word.into())
            })
            .collect();
        std::fs::create_dir_all(&state).unwrap();
        std::fs::write(
            state.join("progress.json"),
            serde_json::Value::Object(progress).to_string(),
        )
        .unwrap();
        std::fs::write(
            state.join("hints.json"),
            serde_json::json!({ &mu.exercise: 1 }).to_string(),
        )
        .unwrap();
        let report = learn_with(
            copy,
            &[
                ("WHITTED_POISON", String::new()),
                (whitted_course::mistakes::SWITCH_VAR, mu.name.clone()),
            ],
        );
        let said = |what: &str| {
            assert!(
                report.contains(what),
                "mutant {} ({}): the report does not say {what:?}:\n{report}",
                mu.name,
                mu.why
            );
        };
        said(&format!("✗ exercise {} —", x.id));
        // told by the values its tests print, as `whitted trees` recorded them
        said(&format!("a known mistake: this looks like {}", mu.why));
        said(&format!(
            "picture: chapter {}'s scene as your code draws it, beside the book's",
            m.entries[i].chapter
        ));
        // an exercise with a picture of its own: its quantity drawn, and differing
        if let Some(file) = &x.picture {
            said(&format!(
                "✗ picture: exercise {}'s quantity ({}) over its chapter's scene as your code draws it, beside the book's and their difference: .whitted/{file}",
                x.id, x.title
            ));
        }
        let fingerprinted = known["mistakes"]
            .as_array()
            .unwrap()
            .iter()
            .any(|k| k["name"] == mu.name.as_str() && k.get("fingerprint").is_some());
        if fingerprinted {
            said("first wrong number: pixel (");
            said(&format!("computed in exercise {} ({})", x.id, x.name));
            said(&format!("this looks like {}", mu.why));
            let told: Vec<&str> = report
                .lines()
                .filter(|l| l.contains("first wrong number") || l.contains("compare: "))
                .collect();
            eprintln!("mutant {}: {}", mu.name, told.join("\n  "));
        } else {
            said("compare: the same as the reference");
            assert!(
                !report.contains("first wrong number"),
                "mutant {}: {report}",
                mu.name
            );
            eprintln!(
                "mutant {} ({}): its chapter's picture and trees are the reference's",
                mu.name, mu.why
            );
        }
    }
    eprintln!(
        "{} known mistakes told in {:.0} s",
        mutants.len(),
        started.elapsed().as_secs_f64()
    );
}

#[test]
#[ignore = "builds a handout and watches it (a minute); .ci/run runs it"]
fn learn_watch_reruns_on_a_save_by_renaming_and_draws_the_chapter() {
    let m = manifest();
    let i = m
        .entries
        .iter()
        .position(|e| e.exercise.name == "ambient")
        .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let student = dir.path().join("w");
    handout::write(&root(), &m, &[i], &student).unwrap();
    let out = dir.path().join("watch.out");
    let mut child = Command::new(env!("CARGO_BIN_EXE_whitted"))
        .args(["learn", "watch", "--cycles", "1", "--root"])
        .arg(&student)
        .env("CARGO_TARGET_DIR", target_dir())
        .env("CARGO_PROFILE_DEV_DEBUG", "0")
        .env("NO_COLOR", "1")
        .env_remove("WHITTED_POISON")
        .stdout(std::fs::File::create(&out).unwrap())
        .spawn()
        .unwrap();
    let text = || std::fs::read_to_string(&out).unwrap_or_default();
    let started = std::time::Instant::now();
    while !text().contains("watching crates/whitted/src/") {
        assert!(
            started.elapsed().as_secs() < 600,
            "no first report: {}",
            text()
        );
        std::thread::sleep(std::time::Duration::from_millis(200));
    }
    assert!(text().contains("✗ exercise 3.1"), "{}", text());
    // the reference body back, saved as many editors save: a new file renamed over the old
    let r = &handout::regions(&root(), &m).unwrap()[i];
    let (path, _, back) = reference_body_back(&student, &m, r, i);
    std::fs::write(path.with_extension("tmp"), back).unwrap();
    std::fs::rename(path.with_extension("tmp"), &path).unwrap();
    let status = child.wait().unwrap();
    let report = text();
    assert!(status.success(), "{report}");
    // a handout of one exercise counts that one (its `[handout] exercises`), done after the
    // save, and says nothing of the others
    assert!(report.contains("0 of 1 exercises done"), "{report}");
    assert!(report.contains("1 of 1 exercises done"), "{report}");
    assert!(
        report.contains("✓ picture: chapter 3's scene as your code draws it"),
        "{report}"
    );
    let png = student.join(".whitted").join("ch03_shading.png");
    let decoded = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&png).unwrap()))
        .read_info()
        .map(|r| r.info().size());
    assert!(decoded.is_ok_and(|(w, h)| w > 0 && h > 0), "{png:?}");
}

/// Each chapter's binary renders its scene when only the exercises of the later chapters are
/// missing: chapter 1 reads only the camera and the image, and no chapter calls a function of
/// a later one. In a copy with every exercise behind the poison switch (one build), chapter N
/// renders with the exercises of chapters N + 1 … 5 poisoned, and fails with those of chapter
/// N poisoned.
#[test]
#[ignore = "builds a poisoned copy's chapter binaries (a minute); .ci/run runs it"]
fn each_chapter_renders_over_a_handout_of_the_later_chapters() {
    let m = manifest();
    let locations = whitted_course::source::locate_all(&root(), &m).unwrap();
    let poisoned = whitted_course::poison::PoisonedCopy::new(
        &root(),
        &m,
        &locations,
        "whitted-chapters-",
        false,
    )
    .unwrap();
    let copy = &poisoned.project;
    let built = cargo()
        .args(["build", "-p", "whitted-app", "--bins"])
        .current_dir(copy)
        .output()
        .unwrap();
    assert!(built.status.success(), "{}", text(&built));
    let range = |chapters: std::ops::RangeInclusive<u8>| {
        let of: Vec<usize> = (0..m.entries.len())
            .filter(|&i| chapters.contains(&m.entries[i].chapter))
            .collect();
        match (of.first(), of.last()) {
            (Some(a), Some(b)) => format!("{a}-{b}"),
            _ => String::new(),
        }
    };
    for chapter in &whitted_course::syllabus::CHAPTERS {
        let (n, name) = (chapter.number, chapter.binary);
        let exe = target_dir().join("debug").join(name);
        let png = poisoned.runs.join(format!("{name}.png"));
        let render = |poison: String| {
            Command::new(&exe)
                .arg(copy.join("scenes").join(format!("{name}.toml")))
                .args(["--width", "64", "--quiet", "-o"])
                .arg(&png)
                .env("WHITTED_POISON", poison)
                .output()
                .unwrap()
        };
        let later = render(range(n + 1..=whitted_course::syllabus::LAST));
        assert!(
            later.status.success(),
            "chapter {n} over a handout of chapters {}–5: {}",
            n + 1,
            text(&later)
        );
        assert!(png.is_file(), "chapter {n} wrote no image");
        let own = render(range(n..=n));
        assert!(
            !own.status.success(),
            "chapter {n} rendered without its own exercises"
        );
    }
}

/// While the student's code does not compile, `learn` shows the compiler's first error at the
/// student's file:line:col and exits with status 1, and `learn hint` and `learn list` still
/// answer.
#[test]
#[ignore = "builds a handout (a minute); .ci/run runs it"]
fn learn_answers_while_the_code_does_not_compile() {
    let m = manifest();
    let dir = tempfile::tempdir().unwrap();
    let student = dir.path().join("broken");
    let first = handout::select(&m, Some((1, 1)), &[]).unwrap();
    handout::write(&root(), &m, &first, &student).unwrap();
    let camera = student.join("crates/whitted/src/camera.rs");
    let text_now = std::fs::read_to_string(&camera).unwrap();
    let todo = handout::todo_statement(&m.entries[first[1]]);
    let broken = text_now.replacen(&todo, "let h: Real = near * ; h", 1);
    assert_ne!(broken, text_now);
    std::fs::write(&camera, &broken).unwrap();
    let line = broken.lines().position(|l| l.contains("near * ;")).unwrap() + 1;
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_whitted"))
            .arg("learn")
            .args(args)
            .arg("--root")
            .arg(&student)
            .env("CARGO_TARGET_DIR", target_dir())
            .env("CARGO_PROFILE_DEV_DEBUG", "0")
            .env("NO_COLOR", "1")
            .env_remove("WHITTED_POISON")
            .output()
            .unwrap()
    };
    let out = run(&[]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        report.contains("does not compile")
            && report.contains(&format!("crates/whitted/src/camera.rs:{line}:")),
        "{report}"
    );
    let hint = run(&["hint"]);
    assert!(hint.status.success(), "{}", text(&hint));
    assert!(
        String::from_utf8_lossy(&hint.stdout).contains("hint 1 of"),
        "{}",
        text(&hint)
    );
    let list = run(&["list"]);
    assert!(list.status.success(), "{}", text(&list));
    let listed = String::from_utf8_lossy(&list.stdout);
    assert!(
        listed.contains("does not compile") && listed.contains(&m.entries[0].exercise.title),
        "{listed}"
    );
}

/// A week's handout as a student meets it: `--chapters 3-4`'s first `whitted learn` counts
/// its own exercises, 0 of 11 (chapters 3 and 4's), and once the 11 bodies are back all 11
/// pass; its tests then all pass (chapter 5's are not in it), and chapter 5's binary says in
/// one line, exit status 2, that chapter 5 is not part of the handout.
#[test]
#[ignore = "builds a handout (minutes); .ci/run runs it"]
fn a_week_handout_counts_its_own_11_exercises() {
    let m = manifest();
    let week = handout::select(&m, Some((3, 4)), &[]).unwrap();
    assert_eq!(week.len(), 11, "chapters 3 and 4's exercises");
    let dir = tempfile::tempdir().unwrap();
    let student = dir.path().join("week");
    handout::write(&root(), &m, &week, &student).unwrap();
    let report = learn(&student, None);
    assert!(
        report.contains("progress — 0 of 11 exercises done"),
        "{report}"
    );
    assert!(!report.contains("chapter 5"), "{report}");
    let regions = handout::regions(&root(), &m).unwrap();
    for &i in &week {
        let (path, now, back) = reference_body_back(&student, &m, &regions[i], i);
        assert_ne!(
            back, now,
            "exercise {}'s todo!() not found",
            m.entries[i].exercise.id
        );
        std::fs::write(&path, back).unwrap();
    }
    let report = learn(&student, None);
    assert!(report.contains("✓ all 11 exercises pass"), "{report}");
    assert!(
        report.contains("progress — 11 of 11 exercises done"),
        "{report}"
    );
    let own = whitted_course::manifest::load(&student.join(whitted_course::manifest::DEFAULT_PATH))
        .unwrap();
    let (failed, passed) = run_tests(&student, &own);
    assert!(
        failed.is_empty(),
        "failing in the week's handout: {failed:?}"
    );
    assert!(
        passed.iter().any(|t| t.starts_with("render_paths::ch4_")),
        "{passed:?}"
    );
    let out = cargo()
        .args([
            "run",
            "-q",
            "--profile",
            "test",
            "-p",
            "whitted-app",
            "--bin",
            "ch05_reflection_refraction",
            "--",
            "-o",
        ])
        .arg(dir.path().join("ch5.png"))
        .current_dir(&student)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let last = stderr.lines().last().unwrap_or("");
    assert!(
        last.starts_with(
            "error: chapter 5 (reflection and refraction) is not part of this handout: exercise 5."
        ),
        "{stderr}"
    );
}
