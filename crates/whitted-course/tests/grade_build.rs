//! `whitted grade` on real copies, built and run: a class of generated submissions graded
//! together, each checked against what it must get.
//!
//! - the reference: full marks, hidden test included;
//! - a chapter-4 handout: zero for exactly its stripped exercises (every test the map
//!   `chapters/exercise-tests.toml` says needs one of them fails, and no other);
//! - a broken submission: a stack overflow, an endless loop and a compile error in three
//!   exercises: graded without crash or hang, and the tests lost are exactly those the map
//!   gives for those three exercises;
//! - a tampered handout: its test files edited to pass and its manifest's points raised, its
//!   exercises left as `todo!()`: zero, since the grader's tests and manifest are its own;
//! - one copy per hand-written mutant (`crates/whitted-course/tests/mutants/hand-written.toml`): each loses points in
//!   its exercise and its chapter.
//!
//! Ignored by default (it builds every submission: minutes); `.ci/run` runs it with
//! `cargo test --test grade_build -- --ignored`. Needs cargo-nextest.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::time::Duration;

use whitted_course::grade::{self, ClassEntry, Grade, Status};
use whitted_course::manifest::{self, Manifest};
use whitted_course::{deps, files, handout};

/// The workspace's root: this crate sits in `crates/whitted-course`.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("the crate sits two levels below the workspace's root")
        .to_path_buf()
}

fn manifest() -> Manifest {
    manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap()
}

/// The entry of the exercise named `name`.
fn index(m: &Manifest, name: &str) -> usize {
    m.by_name(name)
        .unwrap_or_else(|| panic!("no exercise named {name}"))
}

/// A copy of the reference project at `to`.
fn copy(to: &Path) {
    for f in files::project_files(&root()).unwrap() {
        let dest = to.join(&f);
        std::fs::create_dir_all(dest.parent().unwrap()).unwrap();
        std::fs::copy(root().join(&f), dest).unwrap();
    }
}

/// Replaces the body of the exercise named `id` in the copy at `dir` with `body`.
fn set_body(dir: &Path, m: &Manifest, id: &str, body: &str) {
    let r = &handout::regions(&root(), m).unwrap()[index(m, id)];
    let path = dir.join(&r.file);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.contains(&r.solution),
        "exercise {id}: the body is not in the copy"
    );
    std::fs::write(&path, text.replacen(&r.solution, &format!("{body}\n"), 1)).unwrap();
}

#[derive(serde::Deserialize)]
struct Mutants {
    mutant: Vec<Mutant>,
}

#[derive(serde::Deserialize)]
struct Mutant {
    name: String,
    exercise: String,
    why: String,
    find: String,
    replace: String,
}

fn mutants() -> Vec<Mutant> {
    let text = std::fs::read_to_string(
        root().join("crates/whitted-course/tests/mutants/hand-written.toml"),
    )
    .unwrap();
    toml::from_str::<Mutants>(&text).unwrap().mutant
}

/// The hidden test the instructor adds: exercise 1.2 at 90°, where H = N.
const HIDDEN: &str = r#"
use whitted::camera::near_plane_half_height;

#[test]
fn ex_near_plane_half_height_hidden_a_right_angle_sees_as_high_as_it_is_far() {
    assert!((near_plane_half_height(2.0, 90.0) - 2.0).abs() < 1e-6);
}
"#;

/// The tests that failed, as `target::name`.
fn failed(g: &Grade) -> BTreeSet<String> {
    g.tests
        .iter()
        .filter(|t| t.status != Status::Passed && !t.hidden)
        .map(|t| format!("{}::{}", t.target, t.name))
        .collect()
}

/// Every public test that ran, as `target::name`.
fn ran(g: &Grade) -> BTreeSet<String> {
    g.tests
        .iter()
        .filter(|t| !t.hidden)
        .map(|t| format!("{}::{}", t.target, t.name))
        .collect()
}

fn find<'a>(entries: &'a [ClassEntry], student: &str) -> &'a Grade {
    let e = entries.iter().find(|e| e.student == student).unwrap();
    e.grade
        .as_ref()
        .unwrap_or_else(|why| panic!("{student} not graded: {why}"))
}

#[test]
#[ignore = "builds and runs every submission of a class (minutes): .ci/run runs it"]
fn a_class_is_graded_as_each_submission_deserves() {
    let m = manifest();
    let map = deps::load_map(&root(), &m).unwrap();
    let work = tempfile::tempdir().unwrap();
    let class = work.path().join("class");
    // 1. the reference
    copy(&class.join("reference"));
    // 2. a handout of chapter 4
    let chapter4: Vec<usize> = (0..m.entries.len())
        .filter(|&i| m.entries[i].chapter == 4)
        .collect();
    handout::write(&root(), &m, &chapter4, &class.join("handout4")).unwrap();
    // 3. three exercises broken three ways
    let broken = class.join("broken");
    copy(&broken);
    // endless recursion, not in tail position (the optimiser would make a tail call a loop)
    set_body(
        &broken,
        &m,
        "critical_angle",
        "    std::hint::black_box(critical_angle_sine(std::hint::black_box(n1), n2))",
    );
    set_body(
        &broken,
        &m,
        "direction_colour",
        "    loop {\n        std::hint::black_box(d);\n    }",
    );
    set_body(
        &broken,
        &m,
        "facet_crossing",
        "    facet.d() + \"not a number\"",
    );
    // 4. a handout whose tests and manifest were edited to win points
    let all: Vec<usize> = (0..m.entries.len()).collect();
    let tampered = class.join("tampered");
    handout::write(&root(), &m, &all, &tampered).unwrap();
    for t in std::fs::read_dir(tampered.join("crates/whitted/tests")).unwrap() {
        let p = t.unwrap().path();
        if p.extension().is_some_and(|x| x == "rs") {
            std::fs::write(&p, "#[test]\nfn ex_viewing_basis_always() {}\n").unwrap();
        }
    }
    let mpath = tampered.join(manifest::DEFAULT_PATH);
    let text = std::fs::read_to_string(&mpath).unwrap();
    std::fs::write(&mpath, text.replace("points = ", "points = 100 + ")).unwrap();
    // 5. the hand-written mutants
    let mutants = mutants();
    assert!(mutants.len() >= 10);
    for mu in &mutants {
        let r = &handout::regions(&root(), &m).unwrap()[index(&m, &mu.exercise)];
        assert!(
            r.solution.contains(&mu.find),
            "mutant {}: `{}` is not in exercise {}'s body",
            mu.name,
            mu.find,
            mu.exercise
        );
        let dir = class.join(format!("mutant-{}", mu.name));
        copy(&dir);
        set_body(
            &dir,
            &m,
            &mu.exercise,
            r.solution.replacen(&mu.find, &mu.replace, 1).trim_end(),
        );
    }
    let hidden = work.path().join("hidden");
    std::fs::create_dir_all(&hidden).unwrap();
    std::fs::write(hidden.join("extra.rs"), HIDDEN).unwrap();

    let options = grade::GradeSetup {
        chapter: None,
        hidden: Some(hidden),
        timeout: Duration::from_secs(5),
        target_dir: Some(root().join("target").join("grade-tests")),
        keep: false,
    };
    let start = std::time::Instant::now();
    // one at a time: the dependencies are built once, and the time a submission takes is its own
    let entries = grade::grade_class(&root(), &m, &class, &options, 1, &|e| {
        if let Ok(g) = &e.grade {
            eprintln!(
                "graded {}: {:.2} / {} in {:.0} s",
                e.student,
                g.score(),
                g.max(),
                g.elapsed.as_secs_f64()
            );
        }
    })
    .unwrap();
    let total = start.elapsed().as_secs_f64();
    eprintln!(
        "{} submissions in {total:.0} s: {:.0} s a submission",
        entries.len(),
        total / entries.len() as f64
    );

    // the reference: everything, the hidden test too
    let reference = find(&entries, "reference");
    assert_eq!(
        reference.score(),
        reference.max(),
        "{:?}",
        failed(reference)
    );
    assert!(
        reference
            .tests
            .iter()
            .any(|t| t.hidden && t.status == Status::Passed)
    );
    let all_tests = ran(reference);

    // the chapter-4 handout: exactly the tests that need a chapter-4 exercise fail
    let h4 = find(&entries, "handout4");
    assert_eq!(failed(h4), deps::expected(&map, &all_tests, &chapter4));
    assert_eq!(h4.chapter(&m, 4).0, 0.0);
    for c in [1, 2, 3] {
        let (s, max) = h4.chapter(&m, c);
        assert_eq!(s, max, "chapter {c}");
    }

    // the broken one: graded, and only what those three exercises carry is lost
    let b = find(&entries, "broken");
    let three = [
        index(&m, "critical_angle"),
        index(&m, "direction_colour"),
        index(&m, "facet_crossing"),
    ];
    assert_eq!(failed(b), deps::expected(&map, &all_tests, &three));
    let own = |id: &str| -> Vec<Status> {
        let i = index(&m, id);
        b.tests
            .iter()
            .filter(|t| t.exercise == Some(i))
            .map(|t| t.status.clone())
            .collect()
    };
    assert!(
        own("critical_angle").contains(&Status::Crashed),
        "the stack overflow"
    );
    assert!(
        own("direction_colour")
            .iter()
            .all(|s| *s == Status::TimedOut),
        "the endless loop"
    );
    let e222 = b
        .exercises
        .iter()
        .find(|e| e.entry == index(&m, "facet_crossing"))
        .unwrap();
    assert!(
        e222.note
            .as_deref()
            .is_some_and(|n| n.starts_with("does not compile"))
    );
    for e in &b.exercises {
        let needs_broken = b
            .tests
            .iter()
            .filter(|t| t.exercise == Some(e.entry) && !t.hidden)
            .any(|t| {
                deps::needs_of(&map, &format!("{}::{}", t.target, t.name))
                    .iter()
                    .any(|i| three.contains(i))
            });
        if !needs_broken {
            assert_eq!(
                e.score, e.max,
                "exercise {}",
                m.entries[e.entry].exercise.id
            );
        }
    }

    // the tampered handout gains nothing from its edited tests and manifest
    let t = find(&entries, "tampered");
    assert_eq!(t.score(), 0.0);
    assert_eq!(t.max(), reference.max());

    // each mutant loses points in its exercise and its chapter
    for mu in &mutants {
        let g = find(&entries, &format!("mutant-{}", mu.name));
        let i = index(&m, &mu.exercise);
        let e = g.exercises.iter().find(|e| e.entry == i).unwrap();
        assert!(
            e.score < e.max,
            "mutant {} ({}) keeps all of exercise {}'s points",
            mu.name,
            mu.why,
            mu.exercise
        );
        let (s, max) = g.chapter(&m, m.entries[i].chapter);
        assert!(s < max);
    }
}
