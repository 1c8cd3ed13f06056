//! An exercise is known by its name, not by its place: inserting an exercise into the manifest
//! (here one in chapter 2, between the second and the third) leaves every other exercise's
//! name, solution markers, test prefix, map entries and saved state as they were; only the
//! displayed ids after it in its chapter shift.

mod common;

use common::root;

use whitted_course::learn::{self, State};
use whitted_course::manifest::{self, Manifest};
use whitted_course::map;
use whitted_course::{files, handout};

/// The exercise inserted: a function of its own in `ray.rs`, with its solution region.
const INSERTED_FN: &str = "\n/// An exercise inserted by the test.\npub fn inserted_exercise() -> u8 {\n    // BEGIN SOLUTION inserted_exercise\n    7\n    // END SOLUTION\n}\n";

/// Its manifest table.
const INSERTED_ENTRY: &str = r#"[[formula]]
function = "ray::inserted_exercise"
name = "inserted_exercise"
chapter = 2
section = "Ray Tracing Process"
formula = "7"
title = "An exercise inserted"
task = "Return 7."
hints = ["Seven.", "Return 7."]
points = 1

"#;

/// A copy of the project's sources and chapters/ with the exercise inserted before chapter 2's
/// third, and the manifests before and after.
fn inserted() -> (tempfile::TempDir, Manifest, Manifest) {
    let root = root();
    let dir = tempfile::tempdir().unwrap();
    for part in ["crates/whitted/src", "chapters"] {
        files::copy_tree(&root.join(part), &dir.path().join(part)).unwrap();
    }
    let ray = dir.path().join("crates/whitted/src/ray.rs");
    let text = std::fs::read_to_string(&ray).unwrap();
    std::fs::write(&ray, text + INSERTED_FN).unwrap();

    let path = dir.path().join(manifest::DEFAULT_PATH);
    let text = std::fs::read_to_string(&path).unwrap();
    let before = manifest::parse(&text, "before.toml").unwrap();
    let third = &before.entries[before.find("2.3").unwrap()];
    let at = text
        .find(&format!("[[formula]]\nfunction = {:?}\n", third.function))
        .unwrap();
    let text = format!("{}{INSERTED_ENTRY}{}", &text[..at], &text[at..]);
    std::fs::write(&path, &text).unwrap();
    let after = manifest::parse(&text, "after.toml").unwrap();
    (dir, before, after)
}

/// Every exercise of before is in after, by name, with the same function, test prefix and
/// marker; its displayed id is the same unless it comes after the inserted one in chapter 2,
/// where k grows by one. The inserted one is 2.3.
#[test]
fn inserting_an_exercise_shifts_only_the_displayed_ids_after_it() {
    let (dir, before, after) = inserted();
    assert_eq!(after.entries.len(), before.entries.len() + 1);
    let new = after.by_name("inserted_exercise").unwrap();
    assert_eq!(after.entries[new].exercise.id, "2.3");
    let regions_after = handout::regions(dir.path(), &after).unwrap();
    let regions_before = handout::regions(&root(), &before).unwrap();
    let mut shifted = 0;
    for (i, e) in before.entries.iter().enumerate() {
        let x = &e.exercise;
        let j = after
            .by_name(&x.name)
            .unwrap_or_else(|| panic!("{} is gone", x.name));
        let y = &after.entries[j].exercise;
        assert_eq!(after.entries[j].function, e.function, "{}", x.name);
        assert_eq!(y.test_prefix(), x.test_prefix(), "{}", x.name);
        // the marker is found in the same file around the same body
        assert_eq!(regions_after[j].file, regions_before[i].file, "{}", x.name);
        assert_eq!(
            regions_after[j].solution, regions_before[i].solution,
            "{}",
            x.name
        );
        let (chapter, k) = x.id.split_once('.').unwrap();
        let k: usize = k.parse().unwrap();
        let later = e.chapter == 2 && k >= 3;
        let want = if later {
            shifted += 1;
            format!("{chapter}.{}", k + 1)
        } else {
            x.id.clone()
        };
        assert_eq!(y.id, want, "{}", x.name);
        // the todo!() names the same exercise; only the displayed id in it can differ
        let todo_before = handout::todo_statement(e);
        let todo_after = handout::todo_statement(&after.entries[j]);
        assert_eq!(
            todo_before == todo_after,
            !later,
            "{todo_before} / {todo_after}"
        );
        assert_eq!(
            learn::todo_name(&format!("not yet implemented: {}", &todo_after[7..])),
            Some(x.name.as_str())
        );
    }
    let chapter2 = before.entries.iter().filter(|e| e.chapter == 2).count();
    assert_eq!(shifted, chapter2 - 2);
}

/// The measured map, unchanged, reads against the new manifest with the same exercises for
/// every test (by name), and a student's saved states and hints are still theirs.
#[test]
fn the_map_and_a_students_state_survive_the_insertion() {
    let (dir, before, after) = inserted();
    let map_before = map::load_map(dir.path(), &before).unwrap();
    let map_after = map::load_map(dir.path(), &after).unwrap();
    assert_eq!(map_before.len(), map_after.len());
    let names = |m: &Manifest, needs: &[usize]| -> Vec<String> {
        needs
            .iter()
            .map(|&i| m.entries[i].exercise.name.clone())
            .collect()
    };
    for (g, h) in map_before.iter().zip(&map_after) {
        assert_eq!(g.tests, h.tests);
        assert_eq!(
            names(&before, &g.needs),
            names(&after, &h.needs),
            "{:?}",
            g.tests
        );
    }

    // a student who did the first ten exercises, before the instructor inserted one
    let states: Vec<State> = (0..before.entries.len())
        .map(|i| if i < 10 { State::Done } else { State::ToDo })
        .collect();
    learn::save_states(dir.path(), &before, &states).unwrap();
    let now = learn::saved_states(dir.path(), &after);
    for (i, e) in before.entries.iter().enumerate() {
        let j = after.by_name(&e.exercise.name).unwrap();
        assert_eq!(now[j], states[i], "{}", e.exercise.name);
    }
    assert_eq!(
        now[after.by_name("inserted_exercise").unwrap()],
        State::Unknown
    );
}
