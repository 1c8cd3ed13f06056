//! `whitted grade` without building anything: taking a student's bodies from their markers,
//! reading nextest's JUnit report, sharing an exercise's points over its tests, and the
//! reports (the table, Gradescope's results.json, JUnit, CSV). The grading of real copies —
//! the reference, a handout, a broken submission, a class — is in tests/grade_build.rs.

mod common;

use common::{manifest, root};

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::time::Duration;

use whitted_course::grade::{self, Grade, Status, TestResult};
use whitted_course::handout::{self, Region};
use whitted_course::manifest::Manifest;
use whitted_course::report;

/// The region of exercise `id` (a name or a displayed id) in the reference.
fn region(m: &Manifest, id: &str) -> Region {
    let i = m.find(id).unwrap();
    handout::regions(&root(), m).unwrap().swap_remove(i)
}

fn write(dir: &Path, file: &Path, text: &str) {
    let path = dir.join(file);
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, text).unwrap();
}

/// What a student wrote between the markers is taken, line for line; a missing or unclosed
/// marker is a reason, not a crash.
#[test]
fn the_students_body_is_what_lies_between_the_markers() {
    let m = manifest();
    let r = region(&m, "1.2");
    let dir = tempfile::tempdir().unwrap();
    let file = "fn a() {\n    // BEGIN SOLUTION near_plane_half_height\n    let x = 1; // mine\n    x * 2\n    // END SOLUTION\n}\n";
    write(dir.path(), &r.file, file);
    assert_eq!(
        grade::student_body(dir.path(), &r, "near_plane_half_height").unwrap(),
        "    let x = 1; // mine\n    x * 2\n"
    );
    write(dir.path(), &r.file, "fn a() { 1 }\n");
    let why = grade::student_body(dir.path(), &r, "near_plane_half_height").unwrap_err();
    assert!(
        why.contains("`// BEGIN SOLUTION near_plane_half_height` is missing"),
        "{why}"
    );
    write(
        dir.path(),
        &r.file,
        "    // BEGIN SOLUTION near_plane_half_height\n    1\n}\n",
    );
    let why = grade::student_body(dir.path(), &r, "near_plane_half_height").unwrap_err();
    assert!(why.contains("not closed"), "{why}");
    // another exercise's marker before the END does not close this one
    write(
        dir.path(),
        &r.file,
        "// BEGIN SOLUTION near_plane_half_height\n1\n// BEGIN SOLUTION near_plane_half_width\n// END SOLUTION\n",
    );
    assert!(grade::student_body(dir.path(), &r, "near_plane_half_height").is_err());
    let missing =
        grade::student_body(&dir.path().join("nowhere"), &r, "near_plane_half_height").unwrap_err();
    assert!(missing.contains("cannot read"), "{missing}");
}

/// A JUnit report as nextest 0.9 writes it: a pass, a panic, a `todo!()`, a timeout, an
/// abort, and a hidden test.
const JUNIT: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<testsuites name="nextest-run" tests="6" failures="5">
  <testsuite name="whitted::ch01_camera_rays" tests="5" failures="4">
    <testcase name="ex_near_plane_half_height_half_height_is_near_times_tangent_of_half_the_angle" classname="whitted::ch01_camera_rays" time="0.01"/>
    <testcase name="ex_near_plane_half_height_viewing_angle_is_converted_from_degrees" classname="whitted::ch01_camera_rays" time="0.1">
      <failure message="thread panicked" type="test failure with exit code 101">thread &apos;ex_near_plane_half_height_viewing_angle_is_converted_from_degrees&apos; (9915) panicked at tests/ch01_camera_rays.rs:2:28:
assertion `left == right` failed: H for 90° &amp; N = 1
  left: 0.5
 right: 1
note: run with `RUST_BACKTRACE=1` environment variable to display a backtrace</failure>
    </testcase>
    <testcase name="ex_near_plane_half_width_half_width_is_half_height_times_aspect" classname="whitted::ch01_camera_rays" time="0.1">
      <failure message="thread panicked" type="test failure with exit code 101">thread &apos;x&apos; panicked at src/camera.rs:43:5:
not yet implemented: exercise near_plane_half_width (1.3): Half the near plane's width — see chapters/ch01_camera_rays/README.md</failure>
    </testcase>
    <testcase name="ex_pixel_on_near_plane_pixel_formula_spans_the_near_plane_corner_to_corner" classname="whitted::ch01_camera_rays" time="20.0">
      <failure type="test timeout"/>
    </testcase>
    <testcase name="ex_direction_colour_ray_colour_is_unit_direction_plus_one_over_two" classname="whitted::ch01_camera_rays" time="0.01">
      <failure message="process aborted with signal 6 (SIGABRT)" type="test abort">process aborted with signal 6 (SIGABRT)</failure>
    </testcase>
  </testsuite>
  <testsuite name="whitted::ch02_generic_objects" tests="1" failures="0">
    <testcase name="sphere::ex_hit_sphere_sphere_two_hits_with_the_point_as_normal" classname="whitted::ch02_generic_objects" time="0.01"/>
  </testsuite>
  <testsuite name="whitted::hidden_extra" tests="1" failures="1">
    <testcase name="ex_near_plane_half_height_secret_check" classname="whitted::hidden_extra" time="0.01">
      <failure type="test failure with exit code 101">thread &apos;y&apos; panicked at tests/hidden_extra.rs:3:5:
the secret value</failure>
    </testcase>
  </testsuite>
</testsuites>
"#;

fn junit_results(m: &Manifest) -> Vec<TestResult> {
    grade::parse_junit(JUNIT, m, &["hidden_extra".to_string()]).unwrap()
}

/// Each test case becomes a result: its status, its exercise by name, hidden or not, and its
/// message in a line.
#[test]
fn nextests_junit_report_is_read_test_by_test() {
    let m = manifest();
    let results = junit_results(&m);
    assert_eq!(results.len(), 7);
    let by = |name: &str| results.iter().find(|t| t.name == name).unwrap();
    let id = |t: &TestResult| m.entries[t.exercise.unwrap()].exercise.id.clone();
    let pass = by("ex_near_plane_half_height_half_height_is_near_times_tangent_of_half_the_angle");
    assert_eq!(
        (pass.status.clone(), id(pass), pass.hidden),
        (Status::Passed, "1.2".into(), false)
    );
    assert_eq!(pass.target, "ch01_camera_rays");
    let fail = by("ex_near_plane_half_height_viewing_angle_is_converted_from_degrees");
    assert_eq!(fail.status, Status::Failed);
    assert_eq!(
        fail.message,
        "assertion `left == right` failed: H for 90° & N = 1 /   left: 0.5 /  right: 1"
    );
    let todo = by("ex_near_plane_half_width_half_width_is_half_height_times_aspect");
    assert!(
        todo.message
            .starts_with("not written (not yet implemented: exercise near_plane_half_width (1.3)")
    );
    let slow = by("ex_pixel_on_near_plane_pixel_formula_spans_the_near_plane_corner_to_corner");
    assert_eq!(slow.status, Status::TimedOut);
    let crash = by("ex_direction_colour_ray_colour_is_unit_direction_plus_one_over_two");
    assert_eq!(crash.status, Status::Crashed);
    assert!(crash.message.contains("SIGABRT") && crash.message.contains("stack overflow"));
    let secret = by("ex_near_plane_half_height_secret_check");
    assert!(secret.hidden && secret.target == "hidden_extra");
    assert_eq!(id(secret), "1.2");
    // a test in a module of its target keeps its module path, and its exercise by its own name
    let module = by("sphere::ex_hit_sphere_sphere_two_hits_with_the_point_as_normal");
    assert_eq!(
        (module.target.as_str(), id(module), module.status.clone()),
        (
            "ch02_generic_objects",
            m.entries[m.find("hit_sphere").unwrap()].exercise.id.clone(),
            Status::Passed
        )
    );
    assert!(grade::parse_junit("<testsuites", &m, &[]).is_err());
}

/// A grade by hand: exercise 1.2 (1 point) has three tests, one passed; 1.3 (1 point) one
/// test, failed; 1.4 (2 points) one test, timed out; 1.7 one crash; the rest of chapter 1
/// has no test in this report.
fn graded(m: &Manifest) -> Grade {
    let mut tests = junit_results(m);
    tests.retain(|t| t.exercise.is_some_and(|e| m.entries[e].chapter == 1));
    let notes = m
        .entries
        .iter()
        .position(|e| e.exercise.id == "1.3")
        .map(|i| (i, "does not compile".to_string()))
        .into_iter()
        .collect();
    let exercises = grade::scores(m, &[1], &tests, &notes);
    Grade {
        student: "ada, l.".into(),
        chapters: vec![1],
        exercises,
        tests,
        notes: vec![],
        elapsed: Duration::from_secs(42),
        timings: Default::default(),
        render: None,
        feedback: Vec::new(),
        judging: grade::Judging::Alone,
    }
}

/// Gradescope's file: the total, one entry per test whose scores add up to it, hidden tests
/// without their names or messages.
#[test]
fn gradescope_results_add_up_and_hide_the_hidden_tests() {
    let m = manifest();
    let g = graded(&m);
    let json = report::gradescope(&g, &m);
    let tests = json["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 6);
    let sum: f64 = tests.iter().map(|t| t["score"].as_f64().unwrap()).sum();
    assert!((sum - json["score"].as_f64().unwrap()).abs() < 0.02);
    // exercise 1.2 is worth 1 point over 3 tests: one passed
    let p12 = m
        .entries
        .iter()
        .find(|e| e.exercise.id == "1.2")
        .unwrap()
        .exercise
        .points;
    assert!((json["score"].as_f64().unwrap() - f64::from(p12) / 3.0).abs() < 0.01);
    for t in tests {
        for key in [
            "name",
            "score",
            "max_score",
            "status",
            "output",
            "visibility",
        ] {
            assert!(!t[key].is_null(), "{key} missing in {t}");
        }
    }
    let hidden = tests
        .iter()
        .find(|t| t["name"].as_str().unwrap().contains("hidden"))
        .unwrap();
    assert_eq!(hidden["name"], "exercise 1.2, hidden test 1");
    assert_eq!(
        hidden["output"], "```text\nfailed\n```\n",
        "a hidden test says only that it failed"
    );
    let text = json.to_string();
    assert!(
        !text.contains("secret"),
        "a hidden test's name or message leaked: {text}"
    );
    assert!(
        json["output"]
            .as_str()
            .unwrap()
            .contains("exercise 1.3: does not compile")
    );
}

/// The table explains every lost point: the exercise, its formula, each failed test and why;
/// the instructor sees hidden tests by name.
#[test]
fn the_table_explains_each_lost_point() {
    let m = manifest();
    let g = graded(&m);
    let t = report::table(&g, &m);
    assert!(t.starts_with("ada, l.: 0.33 / 13 points"), "{t}");
    assert!(t.contains("chapter 1  camera rays"));
    let e13 = &m.entries.iter().find(|e| e.exercise.id == "1.3").unwrap();
    assert!(t.contains(&e13.formula), "{t}");
    assert!(t.contains("note: does not compile"));
    assert!(t.contains(
        "✗ ex_pixel_on_near_plane_pixel_formula_spans_the_near_plane_corner_to_corner: timed out"
    ));
    assert!(
        t.contains("✗ ex_near_plane_half_height_secret_check (hidden): failed: the secret value")
    );
}

/// The reports say how the tests were judged, and for each chapter whether the student's
/// whole road (the tests of no exercise: the render paths, a whole picture) draws it; those
/// tests count no points.
#[test]
fn the_reports_say_how_it_was_judged_and_what_the_whole_road_draws() {
    let m = manifest();
    let mut g = graded(&m);
    let before = g.score();
    let whole = |target: &str, name: &str, status: Status| TestResult {
        time: 0.1,
        hidden: false,
        name: name.into(),
        target: target.into(),
        exercise: None,
        status,
        message: String::new(),
        values: String::new(),
    };
    g.tests
        .push(whole("render_paths", "ch1_road", Status::Failed));
    g.tests.push(whole(
        "ch01_camera_rays",
        "centre_pixel_of_a_chapter_one_image_is_the_colour_of_minus_n",
        Status::Passed,
    ));
    g.tests
        .push(whole("render_paths", "ch2_road", Status::Passed));
    assert_eq!(
        g.road(&m, 1),
        Some(grade::Road {
            chapter: 1,
            passed: 1,
            total: 2
        })
    );
    assert_eq!(g.road(&m, 3), None);
    let table = report::table(&g, &m);
    let second = table.lines().nth(1).unwrap_or("");
    assert_eq!(second.trim(), grade::Judging::Alone.line(), "{table}");
    assert!(
        table.contains("your whole road: chapter 1 does not yet draw as the reference's: 1 of its 2 tests of no exercise fail with all of your bodies together (they count no points)"),
        "{table}"
    );
    let json = report::gradescope(&g, &m);
    let output = json["output"].as_str().unwrap_or("");
    assert!(
        output.contains(grade::Judging::Alone.line())
            && output.contains("your whole road: chapter 1"),
        "{output}"
    );
    g.judging = grade::Judging::WholeRoad;
    assert!(report::table(&g, &m).contains("--whole-road"));
    assert_eq!(
        g.score(),
        before,
        "the tests of no exercise count no points"
    );
}

/// JUnit is well-formed XML with a suite per chapter and the failures; the CSV row has a
/// column for each header column, the name quoted.
#[test]
fn junit_and_csv_reports_are_well_formed() {
    let m = manifest();
    let g = graded(&m);
    let xml = report::junit(&g, &m);
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let failures = doc
        .descendants()
        .filter(|n| n.has_tag_name("failure"))
        .count();
    assert_eq!(failures, 5);
    assert!(xml.contains("H for 90° &amp; N = 1"));
    let header = report::csv_header(&m, &[1]);
    let row = report::csv_row(&g, &m);
    assert!(row.starts_with("\"ada, l.\",0.33,13,0.33,"), "{row}");
    // the quoted name holds one comma
    assert_eq!(header.split(',').count() + 1, row.split(',').count());
    assert!(header.starts_with("student,total,max,chapter 1,ex 1.1,"));
}

/// Points print with at most two decimals and no trailing zeros.
#[test]
fn points_print_short() {
    assert_eq!(report::points(13.0), "13");
    assert_eq!(report::points(2.0 / 3.0), "0.67");
    assert_eq!(report::points(0.5), "0.5");
    assert_eq!(report::points(-0.0), "0");
}

/// A test's message is the panic's, up to three lines; a `todo!()` says "not written".
#[test]
fn a_failures_message_is_its_panic() {
    assert_eq!(
        grade::panic_message("thread 'a' panicked at src/x.rs:1:1:\nboom\nnote: run with"),
        "boom"
    );
    assert_eq!(
        grade::panic_message("no panic here\nsecond"),
        "no panic here"
    );
    assert!(
        grade::panic_message(
            "thread 'a' panicked at x:\nnot yet implemented: exercise step_matrix (2.1): t"
        )
        .starts_with("not written")
    );
}

/// Runs `whitted` with `args` in the project.
fn whitted(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_whitted"))
        .args(args)
        .current_dir(root())
        .output()
        .unwrap()
}

/// A directory that is not a copy of the project, a chapter out of range or a range the wrong
/// way round, hidden tests that are not a directory, a hidden test named after no exercise:
/// one line of error each, exit status 2, before anything is built.
#[test]
fn grading_something_that_cannot_be_graded_is_one_line_of_error() {
    let empty = tempfile::tempdir().unwrap();
    let dir = empty.path().to_str().unwrap();
    let work = tempfile::tempdir().unwrap();
    let submission = work.path().join("ada");
    std::fs::create_dir_all(submission.join("crates/whitted/src")).unwrap();
    let hidden = work.path().join("hidden");
    std::fs::create_dir_all(&hidden).unwrap();
    std::fs::write(
        hidden.join("mine.rs"),
        "#[test]\nfn ex_viewing_basis_fine() {}\n#[test]\nfn viewing_basis_no_prefix() {}\n",
    )
    .unwrap();
    let target = work.path().join("build");
    let (submission, hidden, target) = (
        submission.to_str().unwrap(),
        hidden.to_str().unwrap(),
        target.to_str().unwrap(),
    );
    let named_after_none = format!(
        "{hidden}/mine.rs:4:4: hidden test `viewing_basis_no_prefix` is named after no exercise"
    );
    for (args, says) in [
        (vec!["grade", "--chapter", "3-1"], "--chapter"),
        (
            vec![
                "grade",
                submission,
                "--hidden",
                hidden,
                "--unsandboxed",
                "--target-dir",
                target,
            ],
            named_after_none.as_str(),
        ),
        (
            vec!["grade", dir],
            "is not a copy of the handout: it has no crates/whitted/src/ directory",
        ),
        (vec!["grade", "--chapter", "7"], "--chapter"),
        (
            vec!["grade", "--hidden", "Cargo.toml"],
            "--hidden Cargo.toml: not a directory",
        ),
        (
            vec!["grade", "--class", dir, "--out", dir],
            "no submission directory in it",
        ),
        (vec!["grade", "--class", dir], "--out"),
    ] {
        let out = whitted(&args);
        let err = common::one_line_error(&out, &format!("{args:?}"));
        assert!(
            err.starts_with("error: ") && err.contains(says),
            "{args:?}: {err}"
        );
    }
}

/// Without bubblewrap the grader says so in one line and grades nothing: no copy, no build;
/// `--unsandboxed` is named as the way to grade anyway.
#[test]
fn without_its_sandbox_grading_refuses_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let submission = dir.path().join("ada");
    std::fs::create_dir_all(submission.join("crates/whitted/src")).unwrap();
    let target = dir.path().join("build");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_whitted"))
        .arg("grade")
        .arg(&submission)
        .arg("--target-dir")
        .arg(&target)
        .current_dir(root())
        // a PATH without bwrap
        .env("PATH", dir.path())
        .output()
        .unwrap();
    let err = common::one_line_error(&out, "grade without bwrap on the PATH");
    assert!(
        err.starts_with("error: the sandbox cannot be set up: bubblewrap (bwrap) is not installed")
            && err.contains("--unsandboxed"),
        "{err}"
    );
    assert!(
        !target.join("graded-copy").exists(),
        "it copied the project"
    );
}

/// A body that does more than compute is refused before it compiles, at every sandbox level,
/// by any spelling: a path into the process, files or the environment, `unsafe`, items
/// (`extern`, `fn`, `mod`, `macro_rules!`), attributes other than lints, the compile-time
/// readers, the renderer's own file and exit functions; a body that closes its function. Names
/// are free: a variable called `env`, `load`, `save`, `path`, `io`, `os`, `exit` or
/// `include_str`, a `///` comment, a name in a string or a comment.
#[test]
fn a_body_that_does_more_than_compute_is_refused() {
    for (body, found) in [
        ("    near * (fov.to_radians() / 2.0).tan()\n", None),
        (
            "std::process::exit(0)",
            Some("`std::process::exit` (`process`)"),
        ),
        (
            "::std::process::abort()",
            Some("`std::process::abort` (`process`)"),
        ),
        (
            "use std::process as p; p::exit(0)",
            Some("`use` of `process`"),
        ),
        ("r#process::exit(0)", Some("`process::exit` (`process`)")),
        (
            "{ let _ = [libc::exit(0)]; 0.0 }",
            Some("`libc::exit` (`libc`)"),
        ),
        ("let exit = t1.max(t0); exit", None),
        (
            "std::os::unix::process::CommandExt::exec",
            Some("`std::os::unix::process::CommandExt::exec` (`os`)"),
        ),
        ("use std::io::Write; 0.0", Some("`use` of `io`")),
        (
            "std::fs::read_to_string(\"x\")",
            Some("`std::fs::read_to_string` (`fs`)"),
        ),
        ("std::env::var(\"HOME\")", Some("`std::env::var` (`env`)")),
        ("unsafe { 0.0 }", Some("`unsafe`")),
        ("extern \"C\" { fn exit(c: i32); }", Some("`extern`")),
        (
            "macro_rules! m { ($i:ident) => { $i!(\"x\") } }\nm!(include_str)",
            Some("`macro_rules`"),
        ),
        ("m!(include_str, \"x\")", Some("`m!`")),
        ("option_env!(\"HOME\")", Some("`option_env!`")),
        (
            "include_bytes /* spaced */ ! (\"x\")",
            Some("`include_bytes!`"),
        ),
        ("#[path = \"/x.rs\"] mod m;", Some("`#[path]`")),
        ("#[no_mangle] fn f() {} 0.0", Some("`#[no_mangle]`")),
        (
            "#[cfg_attr(all(), path = \"x\")] fn f() {} 0.0",
            Some("`#[cfg_attr]`"),
        ),
        ("#![no_mangle] 0.0", Some("`#[no_mangle]`")),
        ("#[allow(unused)] let x = 1.0; x", None),
        (
            "std::panic::set_hook(Box::new(|_| {}))",
            Some("`std::panic::set_hook` (`panic`)"),
        ),
        (
            "whitted_syllabus::words::leave_after_args(true, || {}, || {})",
            Some("`whitted_syllabus::words::leave_after_args` (`leave_after_args`)"),
        ),
        (
            "crate::output::save(fb, p, e)",
            Some("`crate::output::save` (`save`)"),
        ),
        ("let include_str = 1.0; include_str * 2.0", None),
        (
            "let env = 1.0; let load = 2.0; let save = 3.0; let path = 4.0; let io = 5.0; let os = 6.0;\nenv + load + save + path + io + os",
            None,
        ),
        ("/// half of it\nlet h = 0.5 * w;\nh", None),
        ("fn helper(x: f64) -> f64 { x } helper(1.0)", None),
        (
            "fn stretch<'a, 'b, T>(_: &'a &'b (), v: &'b T) -> &'a T { v }",
            Some("`fn stretch<…>`"),
        ),
        ("struct S; 0.0", Some("`struct`")),
        (
            "const N: u64 = { let mut i = 0; loop { i += 1 } }; 0.0",
            Some("`const`"),
        ),
        ("let f = |x: &'static f64| *x; 0.0", Some("`'static`")),
        (
            "0.0 }\nfn evil() -> &'static str { \"\" ",
            Some("a bracket, brace, quote or comment"),
        ),
        (
            "// std::process::exit(0)\n\"process exit unsafe\".len() as f64",
            None,
        ),
    ] {
        assert_eq!(grade::screen(body).as_deref(), found, "{body}");
    }
}

/// The screen refuses nothing a right or a plausibly wrong answer writes: every reference
/// body, and every hand-written mutant, passes it.
#[test]
fn every_reference_body_and_every_mutant_passes_the_screen() {
    let m = manifest();
    for r in handout::regions(&root(), &m).unwrap() {
        let name = &m.entries[r.entry].exercise.name;
        assert_eq!(
            grade::screen(&r.solution),
            None,
            "the reference body of {name}"
        );
    }
    let mutants = common::mutants();
    assert!(mutants.len() >= 10);
    for mu in &mutants {
        let body = common::mutant_body(&m, mu);
        assert_eq!(grade::screen(&body), None, "mutant {}: {body}", mu.name);
    }
}

/// The screen reads a one-segment name (`save(…)`) as the student's own, so no file that holds
/// an exercise may bring a refused name into scope: each of their `use` lines passes the same
/// screen a body does.
#[test]
fn no_file_with_an_exercise_imports_what_the_screen_refuses() {
    let m = manifest();
    let files: BTreeSet<PathBuf> = handout::regions(&root(), &m)
        .unwrap()
        .into_iter()
        .map(|r| r.file)
        .collect();
    assert!(files.len() > 10, "{files:?}");
    for file in files {
        let text = std::fs::read_to_string(root().join(&file)).unwrap();
        let mut statement = String::new();
        for line in text.lines() {
            let l = line.trim_start();
            if statement.is_empty() && !(l.starts_with("use ") || l.starts_with("pub use ")) {
                continue;
            }
            statement += l.trim_start_matches("pub ");
            statement.push('\n');
            if l.trim_end().ends_with(';') {
                assert_eq!(
                    whitted_learn::screen::screen(&statement),
                    None,
                    "{}: {statement}",
                    file.display()
                );
                statement.clear();
            }
        }
    }
}

/// Every file of the renderer and the syllabus that opens a file or ends the process is one
/// the screen knows, and each of its public functions that takes a path (or the type that
/// holds it) is refused by name: a new one fails here until the screen refuses it.
#[test]
fn the_screen_knows_every_function_of_the_project_that_reaches_files_or_exits() {
    use whitted_course::grade::screen::REFUSED_OF_THE_PROJECT;
    let known = [
        "crates/whitted/src/output.rs",
        "crates/whitted/src/scene/load.rs",
        "crates/whitted/src/render/inspect/against.rs",
        "crates/whitted-syllabus/src/words.rs",
        "crates/whitted-syllabus/src/tree.rs",
        // the grader's wire starts the student's process and ends a judge whose wire broke; a
        // path through `judge` or `judged` is refused (the screen's own tests)
        "crates/whitted/src/judge.rs",
    ];
    let mut stack = vec![
        root().join("crates/whitted/src"),
        root().join("crates/whitted-syllabus/src"),
    ];
    let mut touching = Vec::new();
    while let Some(dir) = stack.pop() {
        for e in std::fs::read_dir(&dir).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
                continue;
            }
            let text = std::fs::read_to_string(&p).unwrap();
            if ["fs::", "File::", "process::", "Command::"]
                .iter()
                .any(|w| text.contains(w))
            {
                let rel = p
                    .strip_prefix(root())
                    .unwrap()
                    .to_string_lossy()
                    .into_owned();
                touching.push(rel);
            }
        }
    }
    touching.sort();
    let mut expected: Vec<String> = known.iter().map(|s| (*s).to_string()).collect();
    expected.sort();
    assert_eq!(
        touching, expected,
        "the files that reach files or processes"
    );
    for file in known {
        let text = std::fs::read_to_string(root().join(file)).unwrap();
        let mut owner = String::new();
        for line in text.lines() {
            let l = line.trim();
            if let Some(rest) = l.strip_prefix("impl ") {
                owner = rest.split([' ', '<', '{']).next().unwrap_or("").to_string();
            }
            let Some(rest) = l.strip_prefix("pub fn ") else {
                continue;
            };
            let name = rest.split(['(', '<']).next().unwrap();
            let reaches = l.contains("Path") || name == "leave_after_args";
            if reaches {
                assert!(
                    REFUSED_OF_THE_PROJECT.contains(&name)
                        || REFUSED_OF_THE_PROJECT.contains(&owner.as_str()),
                    "{file}: `{name}` (of `{owner}`) reaches files or ends the process, and the screen lets a body call it"
                );
            }
        }
    }
}

/// The grader names the known mistake an exercise looks like from its tests' values, as `cargo
/// learn` does at the save: a judge's report in which the tests of exercise 3.4 fail with the
/// values r's wrong sign makes them compute (`chapters/mistakes.json`) names that mistake in
/// the table, in Gradescope's output (the exercise's and each failing test's) and in the
/// student's JUnit; the same tests failing with other values name nothing.
#[test]
fn a_known_mistake_is_named_in_every_report_from_the_tests_values() {
    let m = manifest();
    let mistakes = whitted_learn::trees::load_mistakes(&root());
    let mistake = mistakes
        .iter()
        .find(|k| !k.tests.is_empty() && k.chapter == 3)
        .expect("a known mistake of chapter 3 with its tests' values");
    let i = m.by_name(&mistake.exercise).unwrap();
    let junit_of = |values: &dyn Fn(&str) -> String| {
        let cases: String = mistake
            .tests
            .iter()
            .map(|(name, recorded)| {
                format!(
                    "    <testcase name=\"{name}\" classname=\"whitted::ch03_shading\" time=\"0.2\">\n      <failure type=\"test failure\" message=\"test failed\">test failed</failure>\n      <system-err>thread '{name}' panicked at crates/whitted/tests/ch03_shading.rs:40:5:\n{}\nnote: run with `RUST_BACKTRACE=1` environment variable to display a backtrace\n</system-err>\n    </testcase>\n",
                    values(recorded)
                        .replace('&', "&amp;")
                        .replace('<', "&lt;")
                        .replace('>', "&gt;")
                )
            })
            .collect();
        format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"nextest-run\">\n  <testsuite name=\"whitted::ch03_shading\">\n{cases}  </testsuite>\n</testsuites>\n"
        )
    };
    let graded = |junit: &str| {
        let tests = grade::parse_junit(junit, &m, &[]).unwrap();
        let mut exercises = grade::scores(&m, &[3], &tests, &Default::default());
        grade::recognise_known(&m, &mut exercises, &tests, &mistakes);
        Grade {
            student: "ada".into(),
            chapters: vec![3],
            exercises,
            tests,
            notes: vec![],
            elapsed: Duration::from_secs(1),
            timings: Default::default(),
            render: None,
            feedback: Vec::new(),
            judging: grade::Judging::Alone,
        }
    };
    let g = graded(&junit_of(&|recorded| recorded.to_string()));
    let e = g.exercises.iter().find(|e| e.entry == i).unwrap();
    assert_eq!(
        e.known.as_deref(),
        Some(mistake.looks_like.as_str()),
        "the known mistake of {} from its tests' values",
        mistake.exercise
    );
    let line = format!("a known mistake: this looks like {}", mistake.looks_like);
    let table = report::table(&g, &m);
    assert!(table.contains(&line), "the table:\n{table}");
    let results = report::gradescope(&g, &m);
    assert!(
        results["output"].as_str().unwrap().contains(&line),
        "Gradescope's output: {}",
        results["output"]
    );
    for t in results["tests"].as_array().unwrap() {
        assert!(
            t["output"].as_str().unwrap().contains(&line),
            "Gradescope's failing test: {t}"
        );
    }
    let audience = whitted_course::autograder::codegrade::Audience::Student;
    let report_of = whitted_course::autograder::Report::new(
        &g,
        &m,
        &whitted_course::autograder::Settings::default(),
    );
    let junit = whitted_course::autograder::codegrade::junit(&report_of, &[3], audience);
    assert!(
        junit.contains(&line.replace('\'', "&apos;")),
        "the student's JUnit:\n{junit}"
    );
    // other values: the same tests fail, but not as that mistake makes them
    let other = graded(&junit_of(&|recorded| recorded.replace('0', "7")));
    let e = other.exercises.iter().find(|e| e.entry == i).unwrap();
    assert_eq!(e.known, None, "named from values the mistake does not make");
    assert!(!report::table(&other, &m).contains("a known mistake"));
}
