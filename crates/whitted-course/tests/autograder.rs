//! `whitted autograder` without building anything: each platform's file is checked against
//! the fields its documentation lists, from one report; the packages hold what each platform
//! runs; a submission is found in what a platform hands over; the sandbox's command line
//! holds what its promise rests on. The packages run in their platforms' layouts in
//! tests/grade_build.rs.

mod common;

use std::collections::BTreeSet;
use std::io::Read;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use common::{manifest, root};
use whitted_course::autograder::codegrade::{self, Audience};
use whitted_course::autograder::{
    self, Board, Image, Platform, Report, Settings, classroom, gradescope, package, prairielearn,
};
use whitted_course::grade::sandbox::{Level, Limits, Policy};
use whitted_course::grade::{self, Grade};
use whitted_course::manifest::Manifest;

/// Chapter 4 graded: exercise 4.1 (its one test passed), 4.2 (one public test failed, one
/// hidden test passed), and the rest with no test in this report.
const JUNIT: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<testsuites name="nextest-run" tests="3" failures="1">
  <testsuite name="whitted::ch04_shadows" tests="2" failures="1">
    <testcase name="ex_feeler_ray_feeler_starts_at_the_point_and_reaches_the_light_at_u_one" classname="whitted::ch04_shadows" time="0.25"/>
    <testcase name="ex_blocks_light_an_occluder_between_point_and_light_shadows_it" classname="whitted::ch04_shadows" time="0.5">
      <failure type="test failure with exit code 101">thread 'x' panicked at src/shadow.rs:1:1:
the occluder was missed</failure>
    </testcase>
  </testsuite>
  <testsuite name="whitted::hidden_more" tests="1" failures="0">
    <testcase name="ex_blocks_light_the_instructors_own_check" classname="whitted::hidden_more" time="1.0"/>
  </testsuite>
</testsuites>
"#;

fn grade_of(m: &Manifest) -> Grade {
    let tests = grade::parse_junit(JUNIT, m, &["hidden_more".to_string()]).unwrap();
    let exercises = grade::scores(m, &[4], &tests, &Default::default());
    Grade {
        student: "grace".into(),
        chapters: vec![4],
        exercises,
        tests,
        notes: vec!["exercise 4.3: does not compile".into()],
        elapsed: Duration::from_millis(7_400),
        timings: Default::default(),
        render: None,
        feedback: Vec::new(),
        judging: grade::Judging::Alone,
    }
}

fn report(m: &Manifest) -> Report {
    let g = grade_of(m);
    assert_eq!(g.tests.len(), 3, "the fixture's tests: {:?}", g.tests);
    Report::new(&g, m, &Settings::default())
}

/// Gradescope's fields: top level `score`, `execution_time`, `output`, `output_format`,
/// `visibility`, `stdout_visibility`, `extra_data`, `leaderboard` (when asked for), `tests`;
/// per test `score`, `max_score`, `status`, `name`, `number`, `output`, `tags`,
/// `visibility`, hidden tests after the due date.
#[test]
fn gradescope_results_carry_every_field_gradescope_lists() {
    let m = manifest();
    let mut r = report(&m);
    let json = gradescope::results(&r);
    let keys: BTreeSet<&str> = json
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    for key in [
        "score",
        "execution_time",
        "output",
        "output_format",
        "visibility",
        "stdout_visibility",
        "extra_data",
        "tests",
    ] {
        assert!(keys.contains(key), "{key} missing: {keys:?}");
    }
    assert!(
        !keys.contains("leaderboard"),
        "a leaderboard nobody asked for"
    );
    assert_eq!(json["execution_time"], 7);
    assert_eq!(json["output_format"], "md");
    assert_eq!(json["stdout_visibility"], "hidden");
    assert!(
        json["output"]
            .as_str()
            .unwrap()
            .contains("4.3: does not compile")
    );
    let tests = json["tests"].as_array().unwrap();
    for t in tests {
        for key in [
            "score",
            "max_score",
            "status",
            "name",
            "number",
            "output",
            "tags",
            "visibility",
        ] {
            assert!(!t[key].is_null(), "{key} missing in {t}");
        }
        assert!(t["status"] == "passed" || t["status"] == "failed", "{t}");
    }
    let feeler = tests.iter().find(|t| t["number"] == "4.1").unwrap();
    assert_eq!(
        feeler["tags"],
        serde_json::json!(["chapter 4", "feeler_ray"])
    );
    assert_eq!(feeler["visibility"], "visible");
    let hidden = tests
        .iter()
        .find(|t| t["name"].as_str().unwrap().contains("hidden test"))
        .unwrap();
    assert_eq!(hidden["visibility"], "after_due_date");
    assert_eq!(hidden["number"], "4.2");
    assert!(!json.to_string().contains("instructors_own_check"));
    let sum: f64 = tests.iter().map(|t| t["score"].as_f64().unwrap()).sum();
    assert!(
        (sum - json["score"].as_f64().unwrap()).abs() < 0.02,
        "{sum} vs {}",
        json["score"]
    );

    r.leaderboard = vec![Board {
        name: "M pixels/s".into(),
        value: 3.5,
        order: "desc".into(),
    }];
    r.settings.hidden_visibility = "hidden".into();
    let json = gradescope::results(&r);
    assert_eq!(
        json["leaderboard"],
        serde_json::json!([{"name": "M pixels/s", "value": 3.5, "order": "desc"}])
    );
    let hidden = json["tests"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"].as_str().unwrap().contains("hidden test"))
        .unwrap()
        .clone();
    assert_eq!(hidden["visibility"], "hidden");
}

/// A submission that cannot be graded still gets a Gradescope file that says why, a
/// PrairieLearn file that is `gradable: false` (no attempt used) and a JUnit error.
#[test]
fn a_submission_that_cannot_be_graded_gets_a_file_that_says_why() {
    let why = "it is not a copy of the handout";
    let r = Report::ungradable("x", why, 119.0, 0.5);
    let gs = gradescope::results(&r);
    assert_eq!(gs["score"], 0.0);
    assert!(gs["output"].as_str().unwrap().contains(why));
    assert_eq!(gs["tests"], serde_json::json!([]));
    let pl = prairielearn::results(&r);
    assert_eq!(pl["gradable"], false);
    assert_eq!(pl["format_errors"], serde_json::json!([why]));
    assert!(pl.get("score").is_none(), "{pl}");
    let xml = codegrade::junit(&r, &[1, 2], Audience::Student);
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let error = doc.descendants().find(|n| n.has_tag_name("error")).unwrap();
    assert_eq!(error.attribute("message"), Some(why));
}

/// PrairieLearn's fields: `gradable`, `score` in 0–1, `message`, `output`, `images` as data
/// URLs, per test `name`, `description`, `points`, `max_points`, `message`, `output`.
#[test]
fn prairielearn_results_carry_every_field_prairielearn_lists() {
    let m = manifest();
    let mut r = report(&m);
    r.images.push(Image {
        label: "the difference".into(),
        png: b"Man".to_vec(),
    });
    let json = prairielearn::results(&r);
    assert_eq!(json["gradable"], true);
    let score = json["score"].as_f64().unwrap();
    assert!(
        (score - r.score / r.max).abs() < 1e-4,
        "{score} vs {}",
        r.score / r.max
    );
    assert!((0.0..=1.0).contains(&score));
    assert_eq!(
        json["images"],
        serde_json::json!([{"label": "the difference", "url": "data:image/png;base64,TWFu"}])
    );
    let tests = json["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 3);
    for t in tests {
        for key in [
            "name",
            "description",
            "points",
            "max_points",
            "message",
            "output",
        ] {
            assert!(!t[key].is_null(), "{key} missing in {t}");
        }
    }
    let points: f64 = tests.iter().map(|t| t["points"].as_f64().unwrap()).sum();
    let max: f64 = tests
        .iter()
        .map(|t| t["max_points"].as_f64().unwrap())
        .sum();
    assert!((points / max - score).abs() < 0.01 || r.max > max);
    assert!(!json.to_string().contains("instructors_own_check"));
    for (bytes, text) in [
        (&b""[..], ""),
        (b"f", "Zg=="),
        (b"fo", "Zm8="),
        (b"foo", "Zm9v"),
        (b"foobar", "Zm9vYmFy"),
    ] {
        assert_eq!(prairielearn::base64(bytes), text);
    }
}

/// CodeGrade's JUnit: suites, cases with their time, a failure per failed test; the student's
/// file hides the hidden test's name, the instructor's names it.
#[test]
fn codegrade_junit_is_well_formed_and_keeps_hidden_tests_hidden() {
    let m = manifest();
    let r = report(&m);
    for audience in [Audience::Student, Audience::Instructor] {
        let xml = codegrade::junit(&r, &[4], audience);
        let doc = roxmltree::Document::parse(&xml).unwrap();
        let cases: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("testcase"))
            .collect();
        assert_eq!(cases.len(), 3);
        let times: f64 = cases
            .iter()
            .map(|c| c.attribute("time").unwrap().parse::<f64>().unwrap())
            .sum();
        assert!((times - 1.75).abs() < 1e-9, "{times}");
        let failures = doc
            .descendants()
            .filter(|n| n.has_tag_name("failure"))
            .count();
        assert_eq!(failures, 1);
        assert_eq!(
            xml.contains("instructors_own_check"),
            audience == Audience::Instructor,
            "{audience:?}: {xml}"
        );
    }
}

/// Classroom's workflow: a step per exercise worth its points, each reported to the
/// reporter under its id; the course tool's workspace points at the handout's crates.
#[test]
fn the_classroom_workflow_scores_every_exercise_once() {
    let m = manifest();
    let options = package::Options {
        chapter: None,
        hidden: None,
        timeout: 20,
        settings: Settings::default(),
        sandbox: Some(Level::Namespaces),
        judging: grade::Judging::Alone,
        handout: None,
    };
    let yml = classroom::workflow(&m, &options);
    // each exercise judged alone unless the instructor asks for the whole road
    assert!(!yml.contains("--whole-road"), "{yml}");
    let whole = classroom::workflow(
        &m,
        &package::Options {
            judging: grade::Judging::WholeRoad,
            ..options.clone()
        },
    );
    assert!(whole.contains(" --whole-road"), "{whole}");
    let ids: Vec<String> = m
        .entries
        .iter()
        .map(|e| classroom::step_id(&e.exercise.id))
        .collect();
    let runners = yml
        .lines()
        .find_map(|l| l.trim().strip_prefix("runners: "))
        .unwrap();
    assert_eq!(runners, ids.join(","));
    for (e, id) in m.entries.iter().zip(&ids) {
        assert!(yml.contains(&format!("      id: {id}\n")), "{id}");
        assert!(
            yml.contains(&format!(
                "{}_RESULTS: \"${{{{steps.{id}.outputs.result}}}}\"",
                id.to_uppercase()
            )),
            "{id}"
        );
        assert!(yml.contains(&format!("--exercise {}\"", e.exercise.name)));
    }
    let total: u32 = yml
        .lines()
        .filter_map(|l| l.trim().strip_prefix("max-score: "))
        .map(|n| n.parse::<u32>().unwrap())
        .sum();
    let points: u32 = m.entries.iter().map(|e| e.exercise.points).sum();
    assert_eq!(total, points);
    assert!(yml.contains("classroom-resources/autograding-grading-reporter@v1"));
    let manifest_text = std::fs::read_to_string(root().join("Cargo.toml")).unwrap();
    let grader = classroom::grader_manifest(&manifest_text);
    assert!(
        grader.contains("members = [\"whitted-course\"]"),
        "{grader}"
    );
    assert!(
        grader.contains("path = \"../../crates/whitted-learn\""),
        "{grader}"
    );
    assert!(grader.contains("path = \"whitted-course\""), "{grader}");
    assert!(
        !grader.contains("The workspace of whitted"),
        "the project's header: {grader}"
    );
}

/// `check` passes an exercise with all its points and fails one without.
#[test]
fn check_says_whether_an_exercise_got_all_its_points() {
    let m = manifest();
    let dir = tempfile::tempdir().unwrap();
    let results = dir.path().join("results.json");
    std::fs::write(
        &results,
        autograder::json_text(&gradescope::results(&report(&m))),
    )
    .unwrap();
    let check = |exercise: &str| {
        Command::new(env!("CARGO_BIN_EXE_whitted"))
            .args(["autograder", "check", "--exercise", exercise, "--results"])
            .arg(&results)
            .output()
            .unwrap()
    };
    let full = check("feeler_ray");
    assert_eq!(
        full.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&full.stdout)
    );
    let half = check("blocks_light");
    assert_eq!(half.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&half.stdout).starts_with("exercise blocks_light: "));
    let none = check("4.3");
    assert_eq!(
        none.status.code(),
        Some(1),
        "an exercise without a test is not full"
    );
}

/// The Gradescope zip holds `setup.sh` and `run_autograder` at its root, executable, the
/// project under `whitted/` and the hidden tests under `hidden/` only.
#[test]
fn the_gradescope_zip_holds_its_scripts_at_the_root() {
    let dir = tempfile::tempdir().unwrap();
    let hidden = dir.path().join("hidden-tests");
    std::fs::create_dir_all(&hidden).unwrap();
    std::fs::write(
        hidden.join("more.rs"),
        "#[test]\nfn ex_blocks_light_x() {}\n",
    )
    .unwrap();
    let out = dir.path().join("out");
    let m = manifest();
    let options = package::Options {
        chapter: None,
        hidden: Some(hidden),
        timeout: 9,
        settings: Settings::default(),
        sandbox: Some(Level::Namespaces),
        judging: grade::Judging::Alone,
        handout: None,
    };
    package::write(&root(), &m, Platform::Gradescope, &options, &out).unwrap();
    let file = std::fs::File::open(out.join("autograder.zip")).unwrap();
    let mut zip = zip::ZipArchive::new(file).unwrap();
    let names: BTreeSet<String> = zip.file_names().map(|n| n.unwrap().into_owned()).collect();
    for script in ["setup.sh", "run_autograder"] {
        let mut f = zip.by_name(script).unwrap();
        assert_eq!(
            f.unix_mode().unwrap() & 0o111,
            0o111,
            "{script} is not executable"
        );
        let mut text = String::new();
        f.read_to_string(&mut text).unwrap();
        assert!(text.starts_with("#!/usr/bin/env bash\n"), "{script}");
        assert!(text.contains("${AUTOGRADER_ROOT:-/autograder}"), "{script}");
    }
    assert!(names.contains("whitted/Cargo.toml"));
    assert!(names.contains("whitted/chapters/formulas.toml"));
    assert!(names.contains("hidden/more.rs"));
    let hidden_elsewhere: Vec<&String> = names
        .iter()
        .filter(|n| n.ends_with("more.rs") && !n.starts_with("hidden/"))
        .collect();
    assert!(hidden_elsewhere.is_empty(), "{hidden_elsewhere:?}");
    let mut run = String::new();
    zip.by_name("run_autograder")
        .unwrap()
        .read_to_string(&mut run)
        .unwrap();
    assert!(run.contains("--timeout 9"), "{run}");
    assert!(run.contains("--hidden \"$SRC/hidden\""), "{run}");
    assert!(run.contains("results/results.json"));
    assert!(!run.contains("--unsandboxed"), "{run}");
    // packaged for a container without namespaces, every grading says --unsandboxed
    let bare = dir.path().join("bare");
    let options = package::Options {
        sandbox: None,
        judging: grade::Judging::Alone,
        ..options
    };
    package::write(&root(), &m, Platform::Gradescope, &options, &bare).unwrap();
    let mut zip =
        zip::ZipArchive::new(std::fs::File::open(bare.join("autograder.zip")).unwrap()).unwrap();
    for script in ["setup.sh", "run_autograder"] {
        let mut text = String::new();
        zip.by_name(script)
            .unwrap()
            .read_to_string(&mut text)
            .unwrap();
        assert!(text.contains("--unsandboxed"), "{script}: {text}");
    }
}

/// PrairieLearn's package: the entry point, the image, the question's hidden tests.
#[test]
fn the_prairielearn_package_has_its_entry_point_and_image() {
    let dir = tempfile::tempdir().unwrap();
    let hidden = dir.path().join("h");
    std::fs::create_dir_all(&hidden).unwrap();
    std::fs::write(hidden.join("more.rs"), "").unwrap();
    let out = dir.path().join("pl");
    let options = package::Options {
        chapter: Some(grade::Chapters { first: 4, last: 4 }),
        hidden: Some(hidden),
        timeout: 20,
        settings: Settings::default(),
        sandbox: Some(Level::Namespaces),
        judging: grade::Judging::Alone,
        handout: None,
    };
    package::write(&root(), &manifest(), Platform::Prairielearn, &options, &out).unwrap();
    let run = std::fs::read_to_string(out.join("run.sh")).unwrap();
    assert!(run.contains("${GRADE_ROOT:-/grade}"));
    assert!(run.contains("--submission \"$GRADE/student\""));
    assert!(run.contains("$GRADE/results/results.json"));
    assert!(run.contains("--chapter 4"));
    assert!(out.join("tests/hidden/more.rs").is_file());
    let setup = std::fs::read_to_string(out.join("setup.sh")).unwrap();
    assert!(
        !setup.contains("--hidden"),
        "the image is built without the question's tests"
    );
    let docker = std::fs::read_to_string(out.join("Dockerfile")).unwrap();
    assert!(docker.contains("bubblewrap") && docker.contains("cargo-nextest"));
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("info.json")).unwrap()).unwrap();
    assert_eq!(
        info["externalGradingOptions"]["entrypoint"],
        "/whitted/run.sh"
    );
}

/// What a platform hands over: the copy itself, a folder holding it, or the exercise files
/// one by one (each put where its file is in the project); anything else is not a copy.
#[test]
fn a_submission_is_found_in_what_the_platform_hands_over() {
    let m = manifest();
    let dir = tempfile::tempdir().unwrap();
    let scratch = dir.path().join("scratch");
    std::fs::create_dir_all(&scratch).unwrap();
    let folder = dir.path().join("folder");
    std::fs::create_dir_all(folder.join("ada/crates/whitted/src")).unwrap();
    assert_eq!(
        autograder::locate(&root(), &m, &folder, &scratch).unwrap(),
        folder.join("ada")
    );
    assert_eq!(
        autograder::locate(&root(), &m, &folder.join("ada"), &scratch).unwrap(),
        folder.join("ada")
    );
    let flat = dir.path().join("flat");
    std::fs::create_dir_all(&flat).unwrap();
    std::fs::write(flat.join("sphere.rs"), "// mine\n").unwrap();
    std::fs::write(flat.join("camera.rs"), "// mine too\n").unwrap();
    std::fs::write(flat.join("notes.txt"), "").unwrap();
    let found = autograder::locate(&root(), &m, &flat, &scratch).unwrap();
    assert_eq!(
        std::fs::read_to_string(found.join("crates/whitted/src/shapes/sphere.rs")).unwrap(),
        "// mine\n"
    );
    assert!(found.join("crates/whitted/src/camera.rs").is_file());
    let empty = dir.path().join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    std::fs::write(empty.join("essay.txt"), "").unwrap();
    let why = autograder::locate(&root(), &m, &empty, &scratch).unwrap_err();
    assert!(why.contains("not a copy of the handout"), "{why}");
}

/// A command's program and arguments, as text.
fn words(c: &Command) -> Vec<String> {
    std::iter::once(c.get_program())
        .chain(c.get_args())
        .map(|a| a.to_string_lossy().into_owned())
        .collect()
}

/// The run sandbox's command: no namespace shared, the test binary read-only and nothing of
/// the project but what is listed, a private /tmp, the limits, an empty environment, and (as
/// root) a user of its own without capabilities; at the user level, the same user and limits
/// without bubblewrap.
#[test]
fn the_run_sandbox_shares_nothing_but_what_the_tests_read() {
    let policy = Policy {
        level: Level::Namespaces,
        bwrap: "/usr/bin/bwrap".into(),
        uid: Some(61_003),
        slot: 0,
        limits: Limits::default(),
        read: vec!["/nowhere/scenes".into()],
        write: Vec::new(),
        timeout_ms: None,
    };
    let bin = Path::new("/w/target/debug/deps/ch01-abc");
    let command = policy.command(bin, Path::new("/w/copy/crates/whitted"));
    let args = words(&command);
    let text = args.join(" ");
    assert_eq!(args[0], "/usr/bin/bwrap");
    for needed in [
        "--unshare-net",
        "--unshare-pid",
        "--unshare-ipc",
        "--die-with-parent",
        "--new-session",
        "--ro-bind /w/target/debug/deps/ch01-abc /w/target/debug/deps/ch01-abc",
        "--tmpfs /tmp",
        "setpriv --reuid=61003 --regid=61003 --clear-groups --inh-caps=-all --bounding-set=-all",
        "--nproc=64",
        "--core=0",
    ] {
        assert!(text.contains(needed), "{needed} missing: {text}");
    }
    // a listed path that does not exist is not bound; nothing writable is bound
    assert!(!text.contains("/nowhere"), "{text}");
    assert!(!args.iter().any(|a| a == "--bind"), "{text}");
    assert!(text.ends_with("-- /w/target/debug/deps/ch01-abc"), "{text}");
    let env: Vec<String> = command
        .get_envs()
        .filter(|(_, v)| v.is_some())
        .map(|(k, _)| k.to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        env,
        ["HOME", "NO_COLOR", "PATH", "RUST_BACKTRACE", "TMPDIR"],
        "the test's environment"
    );
    // a directory made writable for one run is bound read-write at its path
    let out = tempfile::tempdir().unwrap();
    let mut writing = policy.clone();
    writing.write.push(out.path().to_path_buf());
    let text = words(&writing.command(bin, Path::new("/tmp"))).join(" ");
    let p = out.path().display();
    assert!(text.contains(&format!("--bind {p} {p}")), "{text}");
    // the test in nextest's slot 3 runs as a user of its own, in its worker's group
    let slot = Policy {
        slot: 3,
        ..policy.clone()
    };
    let text = words(&slot.command(bin, Path::new("/tmp"))).join(" ");
    assert!(
        text.contains("setpriv --reuid=61006 --regid=61003 --clear-groups"),
        "{text}"
    );
    let user = Policy {
        uid: None,
        ..policy.clone()
    };
    let args = words(&user.command(bin, Path::new("/tmp")));
    assert!(args.contains(&"--unshare-all".to_string()));
    assert!(!args.contains(&"setpriv".to_string()));
    let level = Policy {
        level: Level::User,
        ..policy
    };
    let args = words(&level.command(bin, Path::new("/tmp")));
    assert_eq!(args[0], "setpriv", "{args:?}");
    assert!(args.contains(&"--reuid=61003".to_string()));
    assert!(args.contains(&"prlimit".to_string()));
    assert!(
        !args
            .iter()
            .any(|a| a.contains("bwrap") || a.starts_with("--unshare"))
    );
}

/// At the user level the grader refuses while the project is open to other users, or the
/// build directory closed to them, and closes the graded copy while the tests run.
#[test]
fn the_user_sandbox_keeps_the_project_closed() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let open = |p: &Path, mode: u32| {
        std::fs::create_dir_all(p).unwrap();
        std::fs::set_permissions(p, std::fs::Permissions::from_mode(mode)).unwrap();
    };
    // the temporary directory is the owner's only: make a path open to others below it
    open(dir.path(), 0o755);
    let project = dir.path().join("project");
    let build = dir.path().join("build");
    let copy = build.join("graded-copy");
    open(&project, 0o755);
    open(&build, 0o755);
    open(&copy, 0o755);
    let sandbox = grade::sandbox::Sandbox {
        policy: Policy {
            level: Level::User,
            bwrap: "".into(),
            uid: Some(61_000),
            slot: 0,
            limits: Limits::default(),
            read: vec![],
            write: Vec::new(),
            timeout_ms: None,
        },
        runner: "/w/whitted".into(),
        triple: "x86_64-unknown-linux-gnu".into(),
        lease: None,
    };
    let why = sandbox
        .protect(&[&project], &build, &copy)
        .unwrap_err()
        .to_string();
    assert!(why.contains("is open to other users"), "{why}");
    open(&project, 0o700);
    sandbox.protect(&[&project], &build, &copy).unwrap();
    let mode = std::fs::metadata(&copy).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o700, "the graded copy while the tests run");
    sandbox.reopen(&copy).unwrap();
    let mode = std::fs::metadata(&copy).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o755);
    open(&build, 0o700);
    let why = sandbox
        .protect(&[&project], &build, &copy)
        .unwrap_err()
        .to_string();
    assert!(why.contains("closed to other users"), "{why}");
}

/// A chapter that lost points carries its feedback into every report, as `cargo learn` would
/// say it: the picture's line, the first wrong number of its ray trees under the exercise
/// they point at (a failed public test's output, Gradescope's Markdown, JUnit's failure, the
/// terminal table), the picture for PrairieLearn; a hidden test still says only that it
/// failed.
#[test]
fn the_feedback_of_a_chapter_reaches_every_report() {
    use whitted_course::grade::{Against, Parting};
    let m = manifest();
    let mut g = grade_of(&m);
    let between = m.by_name("blocks_light").unwrap();
    let text = "pixel (7, 9), camera ray → hit `floor` → light 0 → feeler: the objects crossed: `ceiling` (the reference: nothing)";
    let png = b"\x89PNG\r\n\x1a\n and the rest of it".to_vec();
    g.feedback = vec![grade::ChapterFeedback {
        chapter: 4,
        compare: Some(
            "compare: 312 of 28800 pixels differ by more than 2/255 (1.08%), by up to 87/255; the first at (17, 40)"
                .into(),
        ),
        against: vec![
            Against {
                pixel: (7, 9),
                differs: true,
                first: Some(Parting {
                    path: vec!["camera ray".into(), "hit `floor`".into()],
                    nodes: vec![
                        "camera ray".into(),
                        "hit".into(),
                        "light".into(),
                        "feeler".into(),
                    ],
                    quantity: "crossings".into(),
                    functions: vec![m.entries[between].function.clone()],
                    text: text.into(),
                    ..Parting::default()
                }),
            },
            Against {
                pixel: (1, 1),
                ..Against::default()
            },
        ],
        picture: Some(png.clone()),
        trouble: None,
    }];
    let explained = g.explained(&m);
    assert_eq!(explained.len(), 1);
    let (at, lines) = explained[0].first_wrong.clone().unwrap();
    assert_eq!(at, Some(between), "{lines}");
    let x = &m.entries[between].exercise;
    let computed = format!("computed in exercise {} ({})", x.id, x.name);
    assert!(lines.contains(text) && lines.contains(&computed), "{lines}");

    let table = whitted_course::report::table(&g, &m);
    assert!(
        table.contains("  picture: compare: 312 of 28800"),
        "{table}"
    );
    assert!(
        table.contains(&format!("first wrong number: {text}")),
        "{table}"
    );

    let r = Report::new(&g, &m, &Settings::default());
    let failed = r
        .tests
        .iter()
        .find(|t| !t.hidden && t.tags.contains(&x.name) && t.status != grade::Status::Passed)
        .unwrap();
    assert!(failed.output.contains(&computed), "{}", failed.output);
    assert_eq!(failed.first_wrong, lines.trim_end());
    for t in r.tests.iter().filter(|t| t.hidden) {
        assert!(
            t.first_wrong.is_empty() && !t.output.contains("first wrong"),
            "{t:?}"
        );
    }
    assert!(
        r.output.contains("chapter 4 picture: compare: 312"),
        "{}",
        r.output
    );
    assert_eq!(r.images.len(), 1);
    assert_eq!(r.images[0].png, png);

    let gs = gradescope::results(&r);
    let shown = gs["tests"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| {
            t["number"] == x.id.as_str()
                && t["status"] == "failed"
                && !t["name"].as_str().unwrap().contains("hidden")
        })
        .unwrap();
    assert_eq!(shown["output_format"], "md");
    assert!(
        shown["output"].as_str().unwrap().contains(&computed),
        "{shown}"
    );

    let pl = prairielearn::results(&r);
    let url = pl["images"][0]["url"].as_str().unwrap();
    assert!(
        url.starts_with("data:image/png;base64,iVBORw0KGgo"),
        "{url}"
    );

    let junit = codegrade::junit(&r, &[4], Audience::Student);
    assert!(junit.contains(&computed), "{junit}");
}

/// An exercise's tests carry shares of its points that add up to them exactly, in the
/// hundredths the platforms show (three tests of a 2-point exercise: 0.66 and 0.67, never
/// 3 × 0.67 = 2.01); a test of no exercise carries none and is not listed to students.
#[test]
fn the_maxima_add_up_and_no_pointless_test_is_listed() {
    let m = manifest();
    let i = m.by_name("blocks_light").unwrap();
    let points = m.entries[i].exercise.points;
    let case = |name: &str| {
        format!(
            "    <testcase name=\"{name}\" classname=\"whitted::ch04_shadows\" time=\"0.1\"/>\n"
        )
    };
    let junit = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"nextest-run\" tests=\"4\" failures=\"0\">\n  <testsuite name=\"whitted::ch04_shadows\" tests=\"4\" failures=\"0\">\n{}{}{}{}  </testsuite>\n</testsuites>\n",
        case("ex_blocks_light_one"),
        case("ex_blocks_light_two"),
        case("ex_blocks_light_three"),
        case("shadows_of_the_whole_road"),
    );
    let tests = grade::parse_junit(&junit, &m, &[]).unwrap();
    let g = Grade {
        tests,
        ..grade_of(&m)
    };
    let r = Report::new(&g, &m, &Settings::default());
    let json = gradescope::results(&r);
    let listed = json["tests"].as_array().unwrap();
    assert_eq!(
        listed.len(),
        3,
        "the tests listed: {:?}",
        listed.iter().map(|t| &t["name"]).collect::<Vec<_>>()
    );
    assert!(listed.iter().all(|t| t["number"] != "-"), "{listed:?}");
    let cents: i64 = listed
        .iter()
        .map(|t| (t["max_score"].as_f64().unwrap() * 100.0).round() as i64)
        .sum();
    assert_eq!(
        cents,
        i64::from(points) * 100,
        "the maxima of blocks_light's 3 tests in hundredths, against its {points} points"
    );
    let scored: i64 = listed
        .iter()
        .map(|t| (t["score"].as_f64().unwrap() * 100.0).round() as i64)
        .sum();
    assert_eq!(
        scored, cents,
        "every test passed: the scores are the maxima"
    );
    // CodeGrade's JUnit: each test case's `max_points`, and its suite's, add up the same
    let junit = codegrade::junit(&r, &[4], Audience::Student);
    let doc = roxmltree::Document::parse(&junit).unwrap();
    let property = |node: roxmltree::Node, name: &str| -> i64 {
        let p = node
            .children()
            .filter(|n| n.has_tag_name("properties"))
            .flat_map(|n| n.children())
            .find(|n| n.attribute("name") == Some(name))
            .unwrap_or_else(|| panic!("no {name} in {junit}"));
        (p.attribute("value").unwrap().parse::<f64>().unwrap() * 100.0).round() as i64
    };
    let cases: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("testcase"))
        .collect();
    assert_eq!(cases.len(), 3, "{junit}");
    let junit_cents: i64 = cases.iter().map(|&c| property(c, "max_points")).sum();
    assert_eq!(
        junit_cents,
        i64::from(points) * 100,
        "the JUnit maxima of blocks_light's 3 tests in hundredths, against its {points} points: {junit}"
    );
    let suite = doc
        .descendants()
        .find(|n| n.has_tag_name("testsuite"))
        .unwrap();
    assert_eq!(property(suite, "max_points"), junit_cents, "{junit}");
    assert_eq!(property(suite, "points"), junit_cents, "{junit}");
}

/// A package made for a week's handout (`whitted autograder --handout DIR`) carries the
/// handout's own list of exercises in its manifest, so that its gradings count what the
/// handout gave the students to write and not the earlier chapters' code it gave them: a
/// chapter-4 handout's package counts chapter 4's points, and a test of chapter 3 counts for
/// no exercise.
#[test]
fn a_package_for_a_weeks_handout_counts_only_its_exercises() {
    let m = manifest();
    let work = tempfile::tempdir().unwrap();
    let chapter4: Vec<usize> = (0..m.entries.len())
        .filter(|&i| m.entries[i].chapter == 4)
        .collect();
    let handout4 = work.path().join("handout4");
    whitted_course::handout::write(&root(), &m, &chapter4, &handout4).unwrap();
    let names = whitted_course::handout::later::listed_in(&handout4).unwrap();
    let expected: Vec<String> = chapter4
        .iter()
        .map(|&i| m.entries[i].exercise.name.clone())
        .collect();
    assert_eq!(names, expected, "the chapter-4 handout's own list");
    let options = package::Options {
        chapter: None,
        hidden: None,
        timeout: 20,
        settings: Settings::default(),
        sandbox: Some(Level::Namespaces),
        judging: grade::Judging::Alone,
        handout: Some(names),
    };
    let out = work.path().join("codegrade");
    package::write(&root(), &m, Platform::Codegrade, &options, &out).unwrap();
    let path = out
        .join("whitted")
        .join(whitted_course::manifest::DEFAULT_PATH);
    let packaged =
        whitted_course::manifest::parse(&std::fs::read_to_string(&path).unwrap(), "packaged")
            .unwrap();
    let points = |m: &Manifest| m.entries.iter().map(|e| e.exercise.points).sum::<u32>();
    let chapter4_points: u32 = chapter4.iter().map(|&i| m.entries[i].exercise.points).sum();
    assert_eq!(
        points(&packaged),
        chapter4_points,
        "the package's manifest counts {} points, chapter 4 holds {chapter4_points}",
        points(&packaged)
    );
    // an exercise of chapter 3, which the chapter-4 handout gives
    let ch3 = &m
        .entries
        .iter()
        .find(|e| e.chapter == 3)
        .unwrap()
        .exercise
        .name;
    let junit = format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"nextest-run\" tests=\"2\" failures=\"0\">\n  <testsuite name=\"whitted::ch03_shading\" tests=\"2\" failures=\"0\">\n    <testcase name=\"ex_{ch3}_given\" classname=\"whitted::ch03_shading\" time=\"0.1\"/>\n    <testcase name=\"ex_blocks_light_mine\" classname=\"whitted::ch04_shadows\" time=\"0.1\"/>\n  </testsuite>\n</testsuites>\n"
    );
    let tests = grade::parse_junit(&junit, &packaged, &[]).unwrap();
    let of = |name: &str| {
        tests
            .iter()
            .find(|t| t.name.starts_with(name))
            .unwrap()
            .exercise
    };
    assert_eq!(
        of(&format!("ex_{ch3}")),
        None,
        "a given exercise's test counts"
    );
    assert!(
        of("ex_blocks_light").is_some(),
        "4's test counts for nothing"
    );
}
