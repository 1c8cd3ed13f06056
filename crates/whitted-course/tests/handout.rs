//! Handouts and the student's loop, without building anything: the solution regions, what a
//! handout holds and leaves out, and what `whitted learn` makes of a test run. Building a
//! handout and running its tests is `tests/handout_build.rs` (run by `.ci/run`).

mod common;

use common::{manifest, root};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use whitted_course::cargo::TestOutcome;
use whitted_course::cargo::{TestRun, test_name};
use whitted_course::handout::{self, BEGIN, END};
use whitted_course::learn::{self, State, Style};
use whitted_course::manifest::Manifest;
use whitted_course::picture;
use whitted_course::syllabus::todo;

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

/// Every manifest function has exactly one solution region, marked with its exercise's name,
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
                .starts_with(&format!("{BEGIN} {}\n", e.exercise.name))
        );
        assert!(region.trim_end().ends_with(END));
    }
}

/// The lines of each solution that appear nowhere else in the project (its files as git sees
/// them: tracked, or new and not ignored, so that no build or mutation-testing output counts):
/// the handout's test looks for them.
fn unique_lines(m: &Manifest) -> Vec<(String, Vec<String>)> {
    let root = root();
    let project: BTreeMap<PathBuf, String> = whitted_course::files::project_files(&root)
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
/// todo!(), keeps only the handout's test targets, and no instructor's file: no CI, no
/// cargo-mutants configuration, no tools or benchmarks, no tests of the course tools or the
/// programs (nor the hand-written mutants), no instructor's guide. Its README is the student's,
/// its workspace holds the three crates, and its book pages read without mdBook.
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
        let todo = handout::todo_statement(e);
        assert_eq!(all_text.matches(&todo).count(), 1, "{todo}");
        let readme = whitted_course::syllabus::chapter(e.chapter)
            .unwrap()
            .readme();
        assert_eq!(
            todo,
            format!(
                "todo!(\"exercise {} ({}): {} — see {readme}\")",
                e.exercise.name,
                e.exercise.id,
                e.exercise.title.replace('"', "\\\"")
            )
        );
        assert!(root().join(&readme).is_file(), "{readme}");
    }
    // each exercise's markers stay, around its todo!() and nothing else: the student writes
    // between them, and `whitted grade` takes what is there
    let mut marked = 0;
    for (path, t) in files
        .iter()
        .filter(|(p, _)| p.starts_with("crates/whitted/src"))
    {
        let lines: Vec<&str> = t.lines().map(str::trim).collect();
        for (i, l) in lines.iter().enumerate() {
            if let Some(name) = l.strip_prefix(BEGIN) {
                let e = &m.entries[m.by_name(name.trim()).unwrap()];
                assert_eq!(lines[i + 1], handout::todo_statement(e), "{path:?}");
                assert_eq!(lines[i + 2], END, "{path:?}");
                marked += 1;
            }
        }
    }
    assert_eq!(marked, m.entries.len());
    // of the renderer's tests/, the handout's targets and their helpers only
    let tests = Path::new("crates/whitted/tests");
    for path in files.keys() {
        if let Ok(rest) = path.strip_prefix(tests)
            && rest.components().count() == 1
        {
            let name = path.file_stem().unwrap().to_string_lossy();
            assert!(
                m.handout.tests.iter().any(|t| *t == name),
                "{path:?} is not a handout target"
            );
        }
    }
    for t in &m.handout.tests {
        let file = tests.join(format!("{t}.rs"));
        let dir = tests.join(t).join("main.rs");
        assert!(files.contains_key(&file) || files.contains_key(&dir), "{t}");
    }
    // a target of several files goes whole: chapter 2's, one module per shape
    assert!(files.contains_key(&tests.join("ch02_generic_objects/sphere.rs")));
    assert!(files.contains_key(&tests.join("common/mod.rs")));
    assert!(files.contains_key(Path::new("chapters/formulas.toml")));
    assert!(files.contains_key(Path::new(".cargo/config.toml")));
    // nothing of the instructor's
    for path in files.keys() {
        let p = path.to_string_lossy();
        for instructor in [
            ".ci/",
            ".cargo/mutants.toml",
            "tools/",
            "benches/",
            "tests/",
            "crates/whitted-app/tests/",
            "crates/whitted-course/tests/",
            "crates/whitted-course/handout/",
            "docs/src/instructor-guide.md",
            "docs/performance-log.md",
        ] {
            assert!(!p.starts_with(instructor), "{p} is the instructor's");
        }
        assert!(!p.contains("hand-written") && !p.contains("hidden"), "{p}");
    }
    assert!(
        files[Path::new("crates/whitted/src/lib.rs")]
            .contains("#![allow(unused_variables, unused_imports, unused_mut, dead_code)]")
    );
    // the student's README, the handout's workspace, pages without raw includes
    let readme = &files[Path::new("README.md")];
    let all = format!("all {} exercises", m.entries.len());
    assert!(
        readme.contains("cargo learn") && readme.contains(&all),
        "{readme}"
    );
    assert!(
        !readme.contains("whitted grade") && !readme.contains("{exercises}"),
        "{readme}"
    );
    let workspace: toml::Table = files[Path::new("Cargo.toml")].parse().unwrap();
    let members: Vec<&str> = workspace["workspace"]["members"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(toml::Value::as_str)
        .collect();
    assert_eq!(
        members,
        [
            "crates/whitted-syllabus",
            "crates/whitted",
            "crates/whitted-app",
            "crates/whitted-learn"
        ],
        "the handout's workspace holds the student's crates only"
    );
    let pages: Vec<&PathBuf> = files
        .keys()
        .filter(|p| p.starts_with("docs/src") && p.extension().is_some_and(|e| e == "md"))
        .collect();
    assert!(pages.len() > 10, "{pages:?}");
    for page in pages {
        assert!(
            !files[page].contains("{{#include"),
            "{page:?} has a raw include"
        );
    }
    assert!(!files[Path::new("docs/src/SUMMARY.md")].contains("instructor"));
    // cargo's configuration: the student's one alias, and no command of the instructor's
    let config: toml::Table = files[Path::new(".cargo/config.toml")].parse().unwrap();
    let aliases = config["alias"].as_table().unwrap();
    assert_eq!(aliases.keys().collect::<Vec<_>>(), ["learn"], "{config:?}");
    assert!(aliases["learn"].as_str().unwrap().contains("whitted-learn"));
}

/// The hints and tasks, which go into every handout with the manifest, never quote a line of
/// a solution that computes something: an operator or a call, 16 characters or more without
/// spaces. The calls a task must name — the recorder's `rec.…`, `self.ray`, `self.trace_branch` —
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
            "self.trace_branch(",
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

/// A handout of chapter 4 alone takes out chapter 4's exercises, keeps every earlier
/// chapter's reference code byte for byte, and holds chapter 5's bodies as the panic that says
/// chapter 5 is not part of it (`tests/handout_week.rs` proves the rest of a week's handout).
#[test]
fn a_chapter_handout_keeps_the_earlier_chapters_reference_code_and_no_later_one() {
    let m = manifest();
    let chapter4 = handout::select(&m, Some((4, 4)), &[]).unwrap();
    assert!(!chapter4.is_empty());
    assert!(chapter4.iter().all(|&i| m.entries[i].chapter == 4));
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("ch4");
    handout::write(&root(), &m, &chapter4, &out).unwrap();
    for r in handout::regions(&root(), &m).unwrap() {
        let e = &m.entries[r.entry];
        let text = std::fs::read_to_string(out.join(&r.file)).unwrap();
        let kept = text.contains(&r.solution);
        let todo = text.contains(&handout::todo_statement(e));
        let later = text.contains(&handout::later::later_statement(e));
        let want = match e.chapter {
            4 => (false, true, false),
            5 => (false, false, true),
            _ => (true, false, false),
        };
        assert_eq!(
            (kept, todo, later),
            want,
            "exercise {} of chapter {}: (reference kept, todo!(), later chapter's panic)",
            e.exercise.id,
            e.chapter
        );
    }
}

/// Choosing exercises: by name or displayed id, by chapter range, or all; unknown exercises
/// and chapters are errors.
#[test]
fn exercises_are_chosen_by_name_id_or_chapter() {
    let m = manifest();
    assert_eq!(
        handout::select(&m, None, &[]).unwrap().len(),
        m.entries.len()
    );
    let two = handout::select(&m, None, &["2.3".into(), "viewing_basis".into()]).unwrap();
    assert_eq!(
        two.iter()
            .map(|&i| m.entries[i].exercise.id.as_str())
            .collect::<Vec<_>>(),
        ["1.1", "2.3"]
    );
    assert_eq!(m.entries[two[0]].exercise.name, "viewing_basis");
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

/// The binary (and test target) of chapter `n`.
fn binary(n: u8) -> &'static str {
    whitted_course::syllabus::chapter(n).unwrap().binary
}

/// A test run of every handout target in which exercises before `done` pass and the others
/// stop at their todo!().
fn run_with_done(m: &Manifest, done: usize) -> TestRun {
    let mut run = TestRun {
        targets: m.handout.tests.iter().cloned().collect(),
        ..TestRun::default()
    };
    for (i, e) in m.entries.iter().enumerate() {
        let name = format!("{}::{}works", binary(e.chapter), e.exercise.test_prefix());
        if i < done {
            run.outcomes.insert(name, TestOutcome::Passed);
        } else {
            run.outcomes.insert(name.clone(), TestOutcome::Failed);
            run.failures.insert(
                name,
                format!(
                    "thread 'x' panicked at src/a.rs:1:1:\nnot yet implemented: {}\n",
                    todo::message(&e.exercise.name, &e.exercise.id, &e.exercise.title, "R.md")
                ),
            );
        }
    }
    run
}

/// With nothing written, the verdict names the first exercise, not written yet, with its
/// failing test and the formula it checks, and the progress says 0 of N; half-way, the next
/// is the first not done; at the end, N of N and the picture of the last chapter.
#[test]
fn learn_gives_the_verdict_and_the_progress() {
    let m = manifest();
    let n = m.entries.len();
    let run = run_with_done(&m, 0);
    let states = learn::states(&m, &run);
    assert!(states.iter().all(|s| *s == State::ToDo), "{states:?}");
    let first = &m.entries[0];
    let text = learn::verdict(&m, &run, &states, 0, Style::plain(), None);
    assert!(
        text.contains(&format!(
            "✗ exercise {} — {}",
            first.exercise.id, first.exercise.title
        )) && text.contains("not written yet"),
        "{text}"
    );
    assert!(
        text.contains(&format!("failing: {}works", first.exercise.test_prefix())),
        "{text}"
    );
    assert!(text.contains(&first.formula), "{text}");
    assert!(text.contains("`cargo learn hint`"), "{text}");
    assert!(!text.contains('\x1b'), "no colour when asked for none");
    let progress = learn::progress(&m, &states, Style::plain());
    assert!(
        progress.contains(&format!("0 of {n} exercises done")),
        "{progress}"
    );
    assert_eq!(picture::drawable_chapter(&m, &states), None);

    // half-way: the chapters before are full, the next exercise is the first not done
    let half = n / 2;
    let states = learn::states(&m, &run_with_done(&m, half));
    assert_eq!(states.iter().position(|s| *s != State::Done), Some(half));
    let progress = learn::progress(&m, &states, Style::plain());
    assert!(
        progress.contains(&format!("{half} of {n} exercises done")),
        "{progress}"
    );
    let chapter = m.entries[half].chapter;
    assert_eq!(picture::drawable_chapter(&m, &states), Some(chapter - 1));

    let states = learn::states(&m, &run_with_done(&m, n));
    let progress = learn::progress(&m, &states, Style::plain());
    assert!(
        progress.contains(&format!("{n} of {n} exercises done")),
        "{progress}"
    );
    assert_eq!(picture::drawable_chapter(&m, &states), Some(5));
    // the picture: the chapter that turned green, else the next exercise's, else the last
    let i31 = m.find("3.1").unwrap();
    let mut before = states.clone();
    before[i31] = State::ToDo;
    assert_eq!(picture::picture_chapter(&m, &before, &states), 3);
    assert_eq!(picture::picture_chapter(&m, &states, &states), 5);
    // the first exercise of chapter 3 turns chapters 3 to 5 green at once (their road's tests
    // waited for it): the picture is chapter 3's, where the student was working
    let mut waiting = states.clone();
    for (j, e) in m.entries.iter().enumerate().filter(|(_, e)| e.chapter >= 3) {
        if e.exercise.name == "ambient" || j == m.entries.len() - 1 {
            waiting[j] = State::Waiting("ambient".into());
        }
    }
    waiting[i31] = State::ToDo;
    assert_eq!(picture::picture_chapter(&m, &waiting, &states), 3);
    // with nothing turning green, the chapter of the next exercise: 2.2 after eight
    let eight = learn::states(&m, &run_with_done(&m, 8));
    assert_eq!(m.entries[8].chapter, 2);
    assert_eq!(picture::picture_chapter(&m, &eight, &eight), 2);
    // chapter 1 turning green shows chapter 1, though the next exercise is chapter 2's
    let seven = learn::states(&m, &run_with_done(&m, 7));
    let six = learn::states(&m, &run_with_done(&m, 6));
    assert_eq!(m.entries[7].chapter, 2);
    assert_eq!(picture::picture_chapter(&m, &six, &seven), 1);
    assert_eq!(
        learn::newly_done(&learn::states(&m, &run_with_done(&m, 3)), &states).len(),
        n - 3
    );
}

/// The pictures of a check while a chapter is written: a fresh handout draws chapter 1 (which
/// cannot render yet); three exercises of chapter 3 written draw the last one's quantity; a
/// written exercise that fails draws its own quantity, and its chapter too once all of the
/// chapter is written; a chapter none of whose pictured exercises is written draws its scene
/// through the chapter before; a chapter turning green draws its own picture. Each stage is a
/// figure of the book's list, of the chapter's scene.
#[test]
fn each_check_draws_the_stage_of_the_chapter_being_written() {
    use picture::Stage;
    let m = manifest();
    let figures = whitted_course::figures::read_figures(&root().join("docs/figures.toml")).unwrap();
    let n = m.entries.len();
    let at = |name: &str| common::index(&m, name);
    let chapter_of =
        |c: u8| -> Vec<usize> { (0..n).filter(|&i| m.entries[i].chapter == c).collect() };
    let file = |stage: Stage| picture::figure_of(&m, &figures, stage).map(|f| f.file.clone());

    let fresh = vec![State::ToDo; n];
    assert_eq!(
        picture::choose(&m, &fresh, &fresh, None),
        vec![Stage::Chapter(1)]
    );
    // a first check knows nothing of before: chapters 1 and 2 done turn nothing green
    let unknown = vec![State::Unknown; n];

    // chapters 1 and 2 done, 3.1 to 3.3 written: the cosine law's picture
    let mut three = vec![State::ToDo; n];
    for (state, e) in three.iter_mut().zip(&m.entries) {
        if e.chapter < 3 {
            *state = State::Done;
        }
    }
    for name in ["ambient", "attenuation", "lambert"] {
        three[at(name)] = State::Done;
    }
    let chosen = picture::choose(&m, &three, &three, None);
    assert_eq!(chosen, vec![Stage::Exercise(at("lambert"))]);
    assert_eq!(picture::choose(&m, &unknown, &three, None), chosen);
    assert_eq!(file(chosen[0]).as_deref(), Some("ch03-diffuse.png"));

    // the cosine law written wrong, and the rest of the chapter written: both pictures
    let mut wrong = vec![State::Done; n];
    wrong[at("lambert")] = State::Failing(vec!["ex_lambert_x".into()]);
    assert_eq!(
        picture::choose(&m, &wrong, &wrong, None),
        vec![Stage::Exercise(at("lambert")), Stage::Chapter(3)]
    );
    // a cone's normal written wrong: the normals, then chapter 2's picture
    let mut cone = vec![State::Done; n];
    cone[at("cone_normal")] = State::Failing(vec!["ex_cone_normal_x".into()]);
    let chosen = picture::choose(&m, &cone, &cone, None);
    assert_eq!(
        chosen,
        vec![Stage::Exercise(at("cone_normal")), Stage::Chapter(2)]
    );
    assert_eq!(file(chosen[0]).as_deref(), Some("ch02-normals.png"));

    // nothing of chapter 4 written: its scene through chapter 3's road, and so on
    let mut four = vec![State::ToDo; n];
    for i in (0..n).filter(|&i| m.entries[i].chapter < 4) {
        four[i] = State::Done;
    }
    assert_eq!(
        picture::choose(&m, &four, &four, None),
        vec![Stage::Before(4)]
    );
    for (c, expected) in [
        (3, "ch03-flat.png"),
        (4, "ch04-no-shadows.png"),
        (5, "ch05-depth-0.png"),
    ] {
        assert_eq!(
            file(Stage::Before(c)).as_deref(),
            Some(expected),
            "chapter {c}"
        );
    }
    assert_eq!(
        file(Stage::Before(2)).as_deref(),
        Some("ch02-camera-rays.png")
    );
    assert_eq!(
        file(Stage::Before(1)),
        None,
        "no chapter comes before the first"
    );

    // chapter 3 turning green: its own picture
    let mut green = four.clone();
    for i in chapter_of(3) {
        four[i] = State::Failing(vec![]);
        green[i] = State::Done;
    }
    assert_eq!(
        picture::choose(&m, &four, &green, None),
        vec![Stage::Chapter(3)]
    );
    assert_eq!(file(Stage::Chapter(3)).as_deref(), Some("ch03_shading.png"));
    let all = vec![State::Done; n];
    assert_eq!(
        picture::choose(&m, &all, &all, None),
        vec![Stage::Chapter(5)]
    );
}

/// Every exercise's picture is a figure of the book's list, drawn from its chapter's scene by
/// its chapter's binary, and every chapter after the first has its scene drawn by the chapter
/// before (the picture before the chapter's first exercise).
#[test]
fn every_picture_of_the_manifest_is_a_figure_of_its_chapters_scene() {
    use picture::Stage;
    let m = manifest();
    let figures = whitted_course::figures::read_figures(&root().join("docs/figures.toml")).unwrap();
    let mut pictured = 0;
    for (i, e) in m.entries.iter().enumerate() {
        let Some(file) = &e.exercise.picture else {
            continue;
        };
        pictured += 1;
        let about = whitted_course::syllabus::chapter(e.chapter).unwrap();
        let figure = picture::figure_of(&m, &figures, Stage::Exercise(i));
        let figure = figure.unwrap_or_else(|| {
            panic!(
                "{}: picture {file} is no figure of docs/figures.toml",
                e.exercise.name
            )
        });
        assert_eq!(
            (figure.binary.as_str(), figure.scene()),
            (about.binary, Some(about.scene().as_str())),
            "{}: {file}",
            e.exercise.name
        );
        assert!(
            root().join(figure.path()).is_file(),
            "{} is not committed",
            figure.file
        );
    }
    assert!(pictured >= 12, "{pictured} exercises have a picture");
    for c in 2..=5 {
        assert!(
            picture::figure_of(&m, &figures, Stage::Before(c)).is_some(),
            "chapter {c}"
        );
    }
}

/// A failure that is not the todo!() is "failing", a failure at another exercise's todo!()
/// "waits for" it, an exercise without tests "no tests", one whose target did not run is not
/// known, and nothing is known when the project does not build; the list says each, aligned,
/// with a summary line.
#[test]
fn learn_tells_written_but_wrong_from_not_written() {
    let m = manifest();
    let mut run = run_with_done(&m, 0);
    let name = |i: usize| {
        format!(
            "{}::{}works",
            binary(m.entries[i].chapter),
            m.entries[i].exercise.test_prefix()
        )
    };
    run.failures
        .insert(name(0), "assertion `left == right` failed".into());
    run.outcomes.remove(&name(1));
    let other = &m.entries[0].exercise;
    run.failures.insert(
        name(2),
        format!(
            "panicked at x:\nnot yet implemented: {}\n",
            todo::message(&other.name, &other.id, "…", "R.md")
        ),
    );
    let states = learn::states(&m, &run);
    assert_eq!(states[0], State::Failing(vec![name(0)]));
    assert_eq!(states[1], State::NoTests);
    assert_eq!(states[2], State::Waiting(other.name.clone()));
    let list = learn::list(&m, &states, Style::plain());
    for word in [
        "failing",
        "no tests",
        "to do",
        &format!("waits for {}", other.id),
    ] {
        assert!(list.contains(word), "{word}: {list}");
    }
    let widths: std::collections::BTreeSet<usize> = list
        .lines()
        .filter(|l| l.starts_with("  "))
        .map(|l| l[..l.find(" pt").unwrap_or(0)].chars().count())
        .collect();
    assert_eq!(widths.len(), 1, "the points column is aligned: {list}");
    assert!(
        list.lines()
            .last()
            .unwrap()
            .contains(&format!("0 done, {} to do", m.entries.len() - 3)),
        "{list}"
    );
    // a target that did not run: its exercises are not known
    run.targets.clear();
    assert_eq!(learn::states(&m, &run)[1], State::Unknown);
    run.build_error = Some((
        "crates/whitted/src/camera.rs:3:5: mismatched types".into(),
        String::new(),
    ));
    assert!(learn::states(&m, &run).iter().all(|s| *s == State::Unknown));
}

/// The name in a todo!()'s panic message is read back, wherever the message sits.
#[test]
fn the_todo_message_names_its_exercise() {
    assert_eq!(
        learn::todo_name(
            "thread 't' panicked at a.rs:1:1:\nnot yet implemented: exercise hit_plane (2.13): The plane — see …"
        ),
        Some("hit_plane")
    );
    assert_eq!(learn::todo_name("assertion failed"), None);
}

/// libtest's failure blocks are read per test.
#[test]
fn failure_blocks_are_read_per_test() {
    let out = "running 2 tests\ntest a ... FAILED\ntest b ... FAILED\n\nfailures:\n\n---- a stdout ----\nboom a\n\n---- b stdout ----\nboom b\nmore\n\nfailures:\n    a\n    b\n\ntest result: FAILED.";
    let blocks = whitted_course::cargo::failure_blocks(out);
    assert_eq!(blocks["a"].trim(), "boom a");
    assert_eq!(blocks["b"].trim(), "boom b\nmore");
    assert_eq!(learn::bar(3, 6, 10), "[#####-----]");
    assert_eq!(learn::bar(0, 0, 4), "[----]");
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
    let map = whitted_course::deps::load_map(&root(), &m).unwrap();
    for (i, e) in m.entries.iter().enumerate() {
        let prefix = e.exercise.test_prefix();
        let own: Vec<&String> = map
            .iter()
            .flat_map(|g| g.tests.iter())
            .filter(|t| test_name(t).starts_with(&prefix))
            .collect();
        assert!(
            !own.is_empty(),
            "exercise {} has no test of its own in the map",
            e.exercise.id
        );
        for t in own {
            let needs = whitted_course::deps::needs_of(&map, t);
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

/// A wrong 1.2 fails both of its tests; the verdict shows both, the manifest's first check
/// first (its message says what to do), and a test whose message shows values before one that
/// shows none.
#[test]
fn learn_shows_every_failing_test_the_telling_one_first() {
    let m = manifest();
    let i = m.find("near_plane_half_height").unwrap();
    let x = &m.entries[i].exercise;
    assert_eq!(
        x.first_check.as_deref(),
        Some("viewing_angle_is_converted_from_degrees")
    );
    let target = binary(1);
    let id = |rest: &str| format!("{target}::{}{rest}", x.test_prefix());
    let mut run = run_with_done(&m, i);
    // its tests, written and failing (not the todo!() of run_with_done)
    run.outcomes.remove(&id("works"));
    run.failures.remove(&id("works"));
    let general = id("half_height_is_near_times_tangent_of_half_the_angle");
    let telling = id("viewing_angle_is_converted_from_degrees");
    let silent = id("zz_silent");
    for (name, message) in [
        (
            &general,
            "thread 'a' panicked at tests/ch01.rs:34:5:\nassert_abs_diff_eq!(near_plane_half_height(1.0, 90.0), 1.0)\n    left  = 1.6197751905438615\n    right = 1.0\n",
        ),
        (
            &telling,
            "thread 'b' panicked at tests/ch01.rs:63:5:\nθ must be converted to radians first\n",
        ),
        (
            &silent,
            "thread 'c' panicked at tests/ch01.rs:99:5:\nassertion failed: ok\n",
        ),
    ] {
        run.outcomes.insert(name.clone(), TestOutcome::Failed);
        run.failures.insert(name.clone(), message.to_string());
    }
    let order: Vec<&str> = learn::telling_order(x, &run)
        .into_iter()
        .map(String::as_str)
        .collect();
    assert_eq!(order, [telling.as_str(), general.as_str(), silent.as_str()]);
    let states = learn::states(&m, &run);
    let text = learn::verdict(&m, &run, &states, i, Style::plain(), None);
    let at = |needle: &str| {
        text.find(needle)
            .unwrap_or_else(|| panic!("the verdict should show {needle:?}:\n{text}"))
    };
    assert!(at("radians first") < at("right = 1.0"), "{text}");
    assert!(at("right = 1.0") < at("assertion failed: ok"), "{text}");
    assert!(!text.contains("more of its tests"), "{text}");
}

/// The todo!() panic of exercise `name`, as a test's output shows it.
fn stopped_at(m: &Manifest, name: &str) -> String {
    let x = &m.entries[m.find(name).unwrap()].exercise;
    format!(
        "thread 't' panicked at crates/whitted/src/shadow.rs:50:5:\nnot yet implemented: {}\n",
        todo::message(&x.name, &x.id, &x.title, "R.md")
    )
}

/// An exercise whose failing tests stop at an earlier exercise's todo!() waits for it, though
/// one of them printed nothing (a panic on a thread another test started prints in that
/// test's output): 4.4 on a handout of chapter 4 waits for 4.1, in the state and in the list.
/// When all of its failures are silent, nothing says it waits: it is failing.
#[test]
fn an_exercise_whose_tests_stop_at_an_earlier_todo_waits_though_one_printed_nothing() {
    let m = manifest();
    let i = m.find("send_feeler").unwrap();
    let mut run = run_with_done(&m, i);
    let target = binary(4);
    let id = |rest: &str| format!("{target}::{}{rest}", m.entries[i].exercise.test_prefix());
    run.outcomes.remove(&id("works"));
    run.failures.remove(&id("works"));
    for (rest, text) in [
        ("a", stopped_at(&m, "feeler_ray")),
        ("b", stopped_at(&m, "feeler_ray")),
        ("silent", String::new()),
    ] {
        run.outcomes.insert(id(rest), TestOutcome::Failed);
        run.failures.insert(id(rest), text);
    }
    // a silent test libtest printed no block for at all
    run.outcomes.insert(id("unprinted"), TestOutcome::Failed);
    let states = learn::states(&m, &run);
    assert_eq!(states[i], State::Waiting("feeler_ray".into()));
    let list = learn::list(&m, &states, Style::plain());
    let line = list
        .lines()
        .find(|l| l.contains(&m.entries[i].exercise.title))
        .unwrap_or_else(|| panic!("the list has no line for 4.4:\n{list}"));
    assert!(
        line.contains(&format!("waits for {}", m.display("feeler_ray"))),
        "{line}"
    );
    // nothing but silence: failing, as far as anyone can tell
    for rest in ["a", "b"] {
        run.failures.insert(id(rest), String::new());
    }
    assert!(
        matches!(learn::states(&m, &run)[i], State::Failing(_)),
        "{:?}",
        learn::states(&m, &run)[i]
    );
}

/// The note of the first panic of a test process (`note: run with RUST_BACKTRACE=1 …`), and
/// the one of a backtrace, never reach the verdict, whichever test carries them; the runner
/// runs the tests with RUST_BACKTRACE=0 whatever the student's environment holds.
#[test]
fn the_backtrace_notes_never_reach_the_verdict() {
    let m = manifest();
    let i = m.find("near_plane_half_height").unwrap();
    let x = &m.entries[i].exercise;
    let mut run = run_with_done(&m, i);
    let id = format!("{}::{}works", binary(1), x.test_prefix());
    run.failures.insert(
        id.clone(),
        "\nthread 't' panicked at tests/ch01.rs:40:9:\nH for N = 1, θ = 60° = 1.7320508075688772, expected 0.5773502691896258 (tolerance 1e-12, off by 1.1547005383792515e0)\nnote: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\nnote: Some details are omitted, run with `RUST_BACKTRACE=full` for a verbose backtrace.\n".into(),
    );
    let states = learn::states(&m, &run);
    assert!(matches!(states[i], State::Failing(_)), "{:?}", states[i]);
    let text = learn::verdict(&m, &run, &states, i, Style::plain(), None);
    assert!(text.contains("H for N = 1, θ = 60° = 1.73"), "{text}");
    assert!(!text.contains("RUST_BACKTRACE"), "{text}");
    assert_eq!(
        learn::message_lines(&run.failures[&id]).len(),
        2,
        "the panic's place and its message"
    );
}

/// The runner sets RUST_BACKTRACE=0 for the test executables it runs (a script standing for
/// one prints what it finds in its failure's block).
#[cfg(unix)]
#[test]
fn the_runner_runs_tests_without_backtraces() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let exe = dir.path().join("fake-tests");
    std::fs::write(
        &exe,
        "#!/bin/sh\nprintf 'running 1 test\\ntest t ... FAILED\\n\\nfailures:\\n\\n---- t stdout ----\\nRUST_BACKTRACE=%s\\n\\nfailures:\\n    t\\n\\ntest result: FAILED. 0 passed; 1 failed\\n' \"$RUST_BACKTRACE\"\nexit 101\n",
    )
    .unwrap();
    std::fs::set_permissions(&exe, std::fs::Permissions::from_mode(0o755)).unwrap();
    let run = learn::run_tests("fake", &exe, dir.path()).unwrap();
    assert_eq!(run.outcomes["fake::t"], TestOutcome::Failed);
    assert_eq!(run.failures["fake::t"].trim(), "RUST_BACKTRACE=0");
}

/// Long titles, with characters of several bytes, keep the columns of `list` and the bars of
/// the progress aligned (widths in characters, measured on the widest).
#[test]
fn the_list_and_the_progress_stay_aligned_with_long_titles() {
    let mut m = manifest();
    m.entries[2].exercise.title =
        "M⁻¹, (M⁻¹)ᵀ and a title much longer than the others — ½ of it".into();
    let states = learn::states(&m, &run_with_done(&m, 5));
    let list = learn::list(&m, &states, Style::plain());
    let column = |needle: &str| -> std::collections::BTreeSet<usize> {
        list.lines()
            .filter(|l| l.starts_with("  "))
            .map(|l| l[..l.find(needle).unwrap_or(0)].chars().count())
            .collect()
    };
    assert_eq!(column(" pt").len(), 1, "the points column:\n{list}");
    for e in &m.entries {
        let function = format!("  {}  ", e.function);
        assert!(list.contains(&function), "{function:?}:\n{list}");
    }
    let at = |l: &str, needle: &str| l[..l.find(needle).unwrap()].chars().count();
    let functions: std::collections::BTreeSet<usize> = list
        .lines()
        .filter(|l| l.starts_with("  "))
        .zip(&m.entries)
        .map(|(l, e)| at(l, &format!("  {}", e.function)))
        .collect();
    assert_eq!(functions.len(), 1, "the functions' column:\n{list}");
    assert!(
        list.lines().last().unwrap().contains("5 done,"),
        "the summary line: {list}"
    );
    let progress = learn::progress(&m, &states, Style::plain());
    let bars: std::collections::BTreeSet<usize> = progress
        .lines()
        .filter(|l| l.contains('['))
        .map(|l| at(l, "["))
        .collect();
    assert_eq!(bars.len(), 1, "the bars:\n{progress}");
}
