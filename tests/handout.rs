//! Handouts and the student's loop, without building anything: the solution regions, what a
//! handout holds and leaves out, and what `whitted learn` makes of a test run. Building a
//! handout and running its tests is `tests/handout_build.rs` (run by `.ci/run`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use whitted::course::handout::{self, BEGIN, END};
use whitted::course::learn::{self, State, Style, TestRun};
use whitted::course::manifest::{self, Manifest};
use whitted::course::prove::TestOutcome;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn manifest() -> Manifest {
    manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap()
}

/// Every file under `dir`, relative, with its text (binary files left out).
fn texts(dir: &Path) -> BTreeMap<PathBuf, String> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                if p.file_name().is_some_and(|n| n != "target" && n != ".git") {
                    stack.push(p);
                }
            } else if let Ok(t) = std::fs::read_to_string(&p) {
                out.insert(p.strip_prefix(dir).unwrap().to_path_buf(), t);
            }
        }
    }
    out
}

/// Every manifest function has exactly one solution region, numbered with its exercise id,
/// and no other BEGIN SOLUTION marker is in src/.
#[test]
fn every_exercise_has_one_solution_region_in_its_function() {
    let m = manifest();
    let regions = handout::regions(&root(), &m).unwrap();
    assert_eq!(regions.len(), m.entries.len());
    for (r, e) in regions.iter().zip(&m.entries) {
        assert!(
            !r.solution.trim().is_empty(),
            "{}: an empty solution",
            e.exercise.id
        );
        let text = std::fs::read_to_string(root().join(&r.file)).unwrap();
        let region = &text[r.bytes.clone()];
        assert!(
            region
                .trim_start()
                .starts_with(&format!("{BEGIN} {}", e.exercise.id))
        );
        assert!(region.trim_end().ends_with(END));
    }
}

/// The lines of each solution that appear nowhere else in the project (its files as git sees
/// them: tracked, or new and not ignored, so that no build or mutation-testing output counts):
/// the handout's test looks for them.
fn unique_lines(m: &Manifest) -> Vec<(String, Vec<String>)> {
    let root = root();
    let project: BTreeMap<PathBuf, String> = whitted::course::prove::project_files(&root)
        .unwrap()
        .into_iter()
        .filter_map(|f| Some((f.clone(), std::fs::read_to_string(root.join(&f)).ok()?)))
        .collect();
    let regions = handout::regions(&root, m).unwrap();
    let count = |line: &str| -> usize {
        project
            .values()
            .map(|t| t.lines().filter(|l| l.trim() == line).count())
            .sum()
    };
    regions
        .iter()
        .map(|r| {
            let lines: Vec<String> = r
                .solution
                .lines()
                .map(str::trim)
                .filter(|l| l.len() >= 12 && count(l) == 1)
                .map(str::to_string)
                .collect();
            (m.entries[r.entry].exercise.id.clone(), lines)
        })
        .collect()
}

/// A handout of every exercise holds none of their solutions (each has a line found nowhere
/// else in the project, and that line is nowhere in the handout), holds each exercise's
/// todo!(), keeps only the handout's test targets, and no .ci/.
#[test]
fn a_full_handout_holds_no_solution_and_no_instructor_material() {
    let m = manifest();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("student");
    let all: Vec<usize> = (0..m.entries.len()).collect();
    let made = handout::write(&root(), &m, &all, &out).unwrap();
    assert_eq!(made.stripped, all);
    let files = texts(&out);
    for (id, lines) in unique_lines(&m) {
        assert!(
            !lines.is_empty(),
            "exercise {id}: its solution has no line of its own to search for"
        );
        for line in lines {
            let found: Vec<&PathBuf> = files
                .iter()
                .filter(|(_, t)| t.lines().any(|l| l.trim() == line))
                .map(|(p, _)| p)
                .collect();
            assert!(
                found.is_empty(),
                "exercise {id}: `{line}` is still in {found:?}"
            );
        }
    }
    let all_text: String = files.values().cloned().collect();
    for e in &m.entries {
        let todo = handout::todo_statement(&root(), e);
        assert_eq!(all_text.matches(&todo).count(), 1, "{todo}");
        assert!(todo.contains(&format!("exercise {}: {}", e.exercise.id, e.exercise.title)));
    }
    // each exercise's markers stay, around its todo!() and nothing else: the student writes
    // between them, and `whitted grade` takes what is there
    let mut marked = 0;
    for (path, t) in files.iter().filter(|(p, _)| p.starts_with("src")) {
        let lines: Vec<&str> = t.lines().map(str::trim).collect();
        for (i, l) in lines.iter().enumerate() {
            if let Some(id) = l.strip_prefix(BEGIN) {
                let e = m
                    .entries
                    .iter()
                    .find(|e| e.exercise.id == id.trim())
                    .unwrap();
                assert_eq!(
                    lines[i + 1],
                    handout::todo_statement(&root(), e),
                    "{path:?}"
                );
                assert_eq!(lines[i + 2], END, "{path:?}");
                marked += 1;
            }
        }
    }
    assert_eq!(marked, m.entries.len());
    // of tests/, the handout's targets and their helpers only; no CI
    for path in files.keys() {
        let first = path
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy();
        assert_ne!(first, ".ci", "{path:?}");
        if first == "tests" && path.components().count() == 2 {
            let name = path.file_stem().unwrap().to_string_lossy();
            assert!(
                m.handout.tests.iter().any(|t| *t == name),
                "{path:?} is not a handout target"
            );
        }
    }
    for t in &m.handout.tests {
        assert!(
            files.contains_key(&PathBuf::from(format!("tests/{t}.rs"))),
            "{t}"
        );
    }
    assert!(!files.keys().any(|p| p.starts_with("tests/extremes")));
    assert!(files.contains_key(Path::new("tests/common/mod.rs")));
    assert!(files.contains_key(Path::new("chapters/formulas.toml")));
    assert!(
        files[Path::new("src/lib.rs")]
            .contains("#![allow(unused_variables, unused_imports, unused_mut, dead_code)]")
    );
}

/// The hints and tasks, which go into every handout with the manifest, never quote a line of
/// a solution that computes something: an operator or a call, 16 characters or more without
/// spaces. The calls a task must name — the recorder's `rec.…`, `self.ray`, `self.follow` —
/// and returns and struct fields do not count.
#[test]
fn the_hints_quote_no_line_of_a_solution() {
    let m = manifest();
    let squash = |s: &str| {
        s.chars()
            .filter(|c| !c.is_whitespace() && *c != '`')
            .collect::<String>()
    };
    let named = |l: &str| {
        [
            "//",
            "rec.",
            "self.ray(",
            "self.follow(",
            "return",
            "Some(",
            "RayKind::",
        ]
        .iter()
        .any(|p| l.starts_with(p))
            || l.contains("Part::")
    };
    let mut checked = 0;
    for r in handout::regions(&root(), &m).unwrap() {
        let x = &m.entries[r.entry].exercise;
        let words: Vec<String> = x.hints.iter().chain([&x.task]).map(|h| squash(h)).collect();
        for line in r.solution.lines().map(str::trim).filter(|l| !named(l)) {
            let line = squash(line.trim_end_matches(';'));
            if line.len() < 16 || !line.contains(['+', '-', '*', '/', '(', '<', '>', '=', '!']) {
                continue;
            }
            checked += 1;
            assert!(
                !words.iter().any(|w| w.contains(&line)),
                "exercise {}: a hint or the task quotes the solution's `{line}`",
                x.id
            );
        }
    }
    assert!(checked > 100, "only {checked} lines checked");
}

/// A handout of chapter 4 alone takes out chapter 4's exercises and keeps every other
/// chapter's reference code, byte for byte.
#[test]
fn a_chapter_handout_keeps_the_other_chapters_reference_code() {
    let m = manifest();
    let chapter4 = handout::select(&m, Some((4, 4)), &[]).unwrap();
    assert!(!chapter4.is_empty());
    assert!(chapter4.iter().all(|&i| m.entries[i].chapter == 4));
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("ch4");
    handout::write(&root(), &m, &chapter4, &out).unwrap();
    for r in handout::regions(&root(), &m).unwrap() {
        let text = std::fs::read_to_string(out.join(&r.file)).unwrap();
        let kept = text.contains(&r.solution);
        let todo = text.contains(&handout::todo_statement(&root(), &m.entries[r.entry]));
        if m.entries[r.entry].chapter == 4 {
            assert!(todo && !kept, "exercise {}", m.entries[r.entry].exercise.id);
        } else {
            assert!(kept && !todo, "exercise {}", m.entries[r.entry].exercise.id);
        }
    }
}

/// Choosing exercises: by id, by chapter range, or all; unknown ids and chapters are errors.
#[test]
fn exercises_are_chosen_by_id_or_chapter() {
    let m = manifest();
    assert_eq!(
        handout::select(&m, None, &[]).unwrap().len(),
        m.entries.len()
    );
    let two = handout::select(&m, None, &["2.3".into(), "1.1".into()]).unwrap();
    assert_eq!(
        two.iter()
            .map(|&i| m.entries[i].exercise.id.as_str())
            .collect::<Vec<_>>(),
        ["1.1", "2.3"]
    );
    let early = handout::select(&m, Some((1, 3)), &[]).unwrap();
    assert!(early.iter().all(|&i| m.entries[i].chapter <= 3));
    assert_eq!(
        early.len(),
        m.entries.iter().filter(|e| e.chapter <= 3).count()
    );
    assert!(handout::select(&m, None, &["9.9".into()]).is_err());
    assert!(handout::select(&m, Some((0, 2)), &[]).is_err());
    assert!(handout::select(&m, Some((4, 2)), &[]).is_err());
    assert_eq!(handout::parse_chapters("1-3"), Ok((1, 3)));
    assert_eq!(handout::parse_chapters("4"), Ok((4, 4)));
    assert!(handout::parse_chapters("a-b").is_err());
}

/// A destination that holds something is refused and left as it was, and no temporary
/// directory is left beside it.
#[test]
fn a_handout_never_writes_over_a_directory_in_use() {
    let m = manifest();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("taken");
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    let err = handout::write(&root(), &m, &[0], &out)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("exists and is not an empty directory"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("notes.txt")).unwrap(),
        "mine"
    );
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 1, "{names:?}");
}

// ── whitted learn, from a test run ──────────────────────────────────────────────────────────

/// A test run in which exercises before `done` pass and the others stop at their todo!().
fn run_with_done(m: &Manifest, done: usize) -> TestRun {
    let mut run = TestRun::default();
    for (i, e) in m.entries.iter().enumerate() {
        let name = format!("{}works", e.exercise.test_prefix());
        if i < done {
            run.outcomes.insert(name, TestOutcome::Passed);
        } else {
            run.outcomes.insert(name.clone(), TestOutcome::Failed);
            run.failures.insert(
                name,
                format!(
                    "thread 'x' panicked at src/a.rs:1:1:\nnot yet implemented: exercise {}: {}\n",
                    e.exercise.id, e.exercise.title
                ),
            );
        }
    }
    run
}

/// With nothing written, learn says 0 of N, every chapter's bar is empty, and the next
/// exercise is the first, with its failing test and the formula it checks.
#[test]
fn learn_shows_progress_and_the_next_exercise() {
    let m = manifest();
    let n = m.entries.len();
    let run = run_with_done(&m, 0);
    let states = learn::states(&m, &run);
    assert!(states.iter().all(|s| *s == State::ToDo));
    let text = learn::report(&m, &run, &states, Style::plain(), None);
    assert!(text.contains(&format!("0 of {n} exercises done")), "{text}");
    let first = &m.entries[0];
    assert!(
        text.contains(&format!(
            "next: exercise {} — {}",
            first.exercise.id, first.exercise.title
        )),
        "{text}"
    );
    assert!(
        text.contains(&format!("failing: {}works", first.exercise.test_prefix())),
        "{text}"
    );
    assert!(text.contains(&first.formula), "{text}");
    assert!(!text.contains('\x1b'), "no colour when asked for none");

    // half-way: the chapters before are full, the next exercise is the first not done
    let half = n / 2;
    let run = run_with_done(&m, half);
    let states = learn::states(&m, &run);
    let text = learn::report(&m, &run, &states, Style::plain(), None);
    assert!(
        text.contains(&format!("{half} of {n} exercises done")),
        "{text}"
    );
    assert!(
        text.contains(&format!("next: exercise {}", m.entries[half].exercise.id)),
        "{text}"
    );

    let run = run_with_done(&m, n);
    let states = learn::states(&m, &run);
    let text = learn::report(&m, &run, &states, Style::plain(), None);
    assert!(
        text.contains(&format!("{n} of {n} exercises done")),
        "{text}"
    );
    assert!(text.contains("all"), "{text}");
    assert_eq!(
        learn::newly_done(&learn::states(&m, &run_with_done(&m, 3)), &states).len(),
        n - 3
    );
}

/// A failure that is not the todo!() is "failing", an exercise without tests "no tests", and
/// a project that does not build says so instead of a list.
#[test]
fn learn_tells_written_but_wrong_from_not_written() {
    let m = manifest();
    let mut run = run_with_done(&m, 0);
    let name = format!("{}works", m.entries[0].exercise.test_prefix());
    run.failures
        .insert(name.clone(), "assertion `left == right` failed".into());
    run.outcomes
        .remove(&format!("{}works", m.entries[1].exercise.test_prefix()));
    let states = learn::states(&m, &run);
    assert_eq!(states[0], State::Failing(vec![name]));
    assert_eq!(states[1], State::NoTests);
    let list = learn::list(&m, &states, Style::plain());
    assert!(list.contains("failing") && list.contains("no tests") && list.contains("to do"));
    run.build_errors = Some("error[E0308]: mismatched types".into());
    let text = learn::report(&m, &run, &learn::states(&m, &run), Style::plain(), None);
    assert!(
        text.contains("does not build") && text.contains("E0308"),
        "{text}"
    );
}

/// libtest's failure blocks are read per test.
#[test]
fn failure_blocks_are_read_per_test() {
    let out = "running 2 tests\ntest a ... FAILED\ntest b ... FAILED\n\nfailures:\n\n---- a stdout ----\nboom a\n\n---- b stdout ----\nboom b\nmore\n\nfailures:\n    a\n    b\n\ntest result: FAILED.";
    let blocks = learn::failure_blocks(out);
    assert_eq!(blocks["a"].trim(), "boom a");
    assert_eq!(blocks["b"].trim(), "boom b\nmore");
    assert_eq!(learn::bar(3, 6, 10), "[#####-----]");
    assert_eq!(learn::bar(0, 0, 4), "[----]");
}

/// The panic of a handout's todo!() becomes one line naming the exercise.
#[test]
fn a_missing_exercise_is_one_line() {
    let payload: Box<dyn std::any::Any + Send> = Box::new(String::from(
        "not yet implemented: exercise 2.3: The sphere's discriminant — see chapters/ch02_generic_objects/README.md",
    ));
    assert_eq!(
        whitted::cli::missing_exercise(payload.as_ref()).unwrap(),
        "exercise 2.3 is not written yet: The sphere's discriminant — see chapters/ch02_generic_objects/README.md"
    );
    let other: Box<dyn std::any::Any + Send> = Box::new("index out of bounds");
    assert_eq!(whitted::cli::missing_exercise(other.as_ref()), None);
}

/// Editors' backup and swap files do not trigger a rerun; sources do.
#[test]
fn watch_ignores_editor_files() {
    assert!(learn::is_source_change(Path::new("src/shapes/sphere.rs")));
    for f in ["src/a.rs~", "src/.a.rs.swp", "src/.#a.rs", "src/4913"] {
        assert!(!learn::is_source_change(Path::new(f)), "{f}");
    }
}

/// Working in order works: each exercise's own tests run only that exercise and the ones
/// before it (by chapters/exercise-tests.toml, which CI checks against measurements), so
/// when a student reaches an exercise, the failing test points at it.
#[test]
fn an_exercises_own_tests_run_only_it_and_exercises_before_it() {
    let m = manifest();
    let map = whitted::course::deps::load_map(&root(), &m).unwrap();
    for (i, e) in m.entries.iter().enumerate() {
        let prefix = e.exercise.test_prefix();
        let own: Vec<&String> = map
            .iter()
            .flat_map(|g| g.tests.iter())
            .filter(|t| learn::test_name(t).starts_with(&prefix))
            .collect();
        assert!(
            !own.is_empty(),
            "exercise {} has no test of its own in the map",
            e.exercise.id
        );
        for t in own {
            let needs = whitted::course::deps::needs_of(&map, t);
            assert!(
                needs.contains(&i),
                "{t} does not even need exercise {}",
                e.exercise.id
            );
            let later: Vec<&str> = needs
                .iter()
                .filter(|&&j| j > i)
                .map(|&j| m.entries[j].exercise.id.as_str())
                .collect();
            assert!(later.is_empty(), "{t} needs later exercises {later:?}");
        }
    }
}

/// Colour only on a terminal, and never with NO_COLOR set to something.
#[test]
fn colour_only_on_a_terminal_without_no_color() {
    use std::ffi::OsStr;
    let painted = |s: Style| s.good("x").contains('\x1b');
    assert!(painted(Style::choose(true, None)));
    assert!(painted(Style::choose(true, Some(OsStr::new("")))));
    assert!(!painted(Style::choose(true, Some(OsStr::new("1")))));
    assert!(!painted(Style::choose(false, None)));
    assert!(!painted(Style::plain()));
}
