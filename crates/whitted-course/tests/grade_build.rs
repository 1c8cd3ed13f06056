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
//!   its exercise and its chapter;
//! - hostile submissions, each a chapter-3 handout with one exercise of chapters 1–2 written
//!   to attack the grader ([`hostile`]): reading the reference's sources and panicking with
//!   them, writing the results, reading the hidden tests, a fork bomb, a disk filler, a memory
//!   hog, a network connect, megabytes of output, editing files outside its copy, and
//!   `include_str!` of a reference or hidden file at compile time. Each loses exactly what its
//!   handout and its attacked exercise carry and gains nothing, and no report of any
//!   submission quotes a solution line the submission did not write itself, nor a hidden
//!   test's source.
//!
//! Everything is built and run in the grader's sandbox (bubblewrap). The platforms' packages
//! then run in their layouts, sharing the class's build directory: Gradescope's zip
//! (`setup.sh`'s build step and `run_autograder`, in an `/autograder`-shaped temporary root),
//! PrairieLearn's entry point (in a `/grade`-shaped one) and GitHub Classroom's workflow (its
//! commands, in a student's repository).
//!
//! Ignored by default (it builds every submission: minutes); `.ci/run` runs it with
//! `cargo test --test grade_build -- --ignored`. Needs cargo-nextest and bubblewrap.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Duration;

mod common;

use common::{copy, index, manifest, mutant_body, mutants, root, set_body};
use whitted_course::autograder::{self, Platform, Report, Settings};
use whitted_course::grade::sandbox::{self, Level};
use whitted_course::grade::{self, ClassEntry, Grade, Status};
use whitted_course::manifest::{self, Manifest};
use whitted_course::{deps, files, handout};

/// The hidden test the instructor adds: exercise 1.2 at 90°, where H = N. Its marker must
/// appear in no report.
const HIDDEN: &str = r#"
// hidden-marker-3f9a: the source of a hidden test
use whitted::camera::near_plane_half_height;

#[test]
fn ex_near_plane_half_height_hidden_a_right_angle_sees_as_high_as_it_is_far() {
    let h = near_plane_half_height(2.0, 90.0);
    assert!((h - 2.0).abs() < 1e-6, "hidden-message-7c1e: H = {h} at 90°, expected 2");
}
"#;

/// The hidden test's assertion message: compiled into its binary and its build caches, it
/// must reach no report and no test.
const HIDDEN_MESSAGE: &str = "hidden-message-7c1e";

/// A secret in the grader's environment, which no body may read at compile time.
const GRADER_SECRET: &str = "grader-secret-51d2";

/// Every exercise body of the copy at `dir` replaced by `body`: a whole submission written
/// one way.
fn every_body(dir: &Path, m: &Manifest, body: &str) {
    for e in &m.entries {
        set_body(dir, m, &e.exercise.name, body);
    }
}

/// A body that ends its process.
const EXITS: &str = "    std::process::exit(0)";

/// A body that ends its process only while a test runs (libtest's `--exact`), and is not
/// written otherwise: the picture would show a wrong formula, the tests nothing.
const EXITS_UNDER_TEST: &str =
    "    if std::env::args().any(|a| a == \"--exact\") { std::process::exit(0) }\n    todo!()";

/// What the grader noted of exercise `exercise` in `g` (empty when nothing).
fn note_of<'g>(g: &'g Grade, m: &Manifest, exercise: &str) -> &'g str {
    g.exercises
        .iter()
        .find(|e| e.entry == index(m, exercise))
        .and_then(|e| e.note.as_deref())
        .unwrap_or("")
}

/// How many of a grade's tests passed, hidden ones included.
fn passed(g: &Grade) -> usize {
    g.tests
        .iter()
        .filter(|t| t.status == Status::Passed)
        .count()
}

/// No report of `g` quotes a character that breaks a report or turns its text around.
fn assert_reports_clean(g: &Grade, m: &Manifest) {
    for (kind, text) in reports(g, m) {
        for bad in ['\u{fffe}', '\u{202e}', '\u{1b}'] {
            assert!(
                !text.contains(bad),
                "{}'s {kind} report carries U+{:04X}",
                g.student,
                u32::from(bad)
            );
        }
    }
}

/// The tests that failed, as `target::name`.
fn failed(g: &Grade) -> BTreeSet<String> {
    g.tests
        .iter()
        .filter(|t| t.status != Status::Passed && !t.hidden)
        .map(|t| format!("{}::{}", t.target, t.name))
        .collect()
}

/// No failed test of an exercise speaks of another exercise's `todo!()`: judged alone, an
/// exercise's tests never run a body of the student's but its own.
fn assert_blames_only_its_own(g: &Grade, m: &Manifest) {
    for t in g.tests.iter().filter(|t| t.status != Status::Passed) {
        let Some(own) = t.exercise else { continue };
        for (i, e) in m.entries.iter().enumerate() {
            assert!(
                i == own
                    || !t
                        .message
                        .contains(&format!("exercise {} (", e.exercise.name)),
                "{}: the test {} of exercise {} blames exercise {}: {}",
                g.student,
                t.name,
                m.entries[own].exercise.id,
                e.exercise.id,
                t.message
            );
        }
    }
}

/// Every public test that ran, as `target::name`.
fn ran(g: &Grade) -> BTreeSet<String> {
    g.tests
        .iter()
        .filter(|t| !t.hidden)
        .map(|t| format!("{}::{}", t.target, t.name))
        .collect()
}

/// Says on stderr how a submission of a class was graded, as it is.
fn say_graded(e: &ClassEntry) {
    if let Ok(g) = &e.grade {
        eprintln!(
            "graded {}: {:.2} / {} in {:.0} s",
            e.student,
            g.score(),
            g.max(),
            g.elapsed.as_secs_f64()
        );
    }
}

fn find<'a>(entries: &'a [ClassEntry], student: &str) -> &'a Grade {
    let e = entries.iter().find(|e| e.student == student).unwrap();
    e.grade
        .as_ref()
        .unwrap_or_else(|why| panic!("{student} not graded: {why}"))
}

/// The marker of the hidden test's source.
const HIDDEN_MARKER: &str = "hidden-marker-3f9a";

/// The class's build directory, shared by the class and the platforms' layouts: one grading
/// at a time in it.
fn build_dir() -> PathBuf {
    root().join("target").join("grade-tests")
}

/// One grading at a time in [`build_dir`].
static BUILD: Mutex<()> = Mutex::new(());

/// The grading setup of these tests: sandboxed, the default time limit a test (an exercise's
/// test that renders across the judge's wire takes seconds on a busy machine).
fn setup(hidden: &Path) -> grade::GradeSetup {
    grade::GradeSetup {
        chapter: None,
        hidden: Some(hidden.to_path_buf()),
        timeout: grade::DEFAULT_TIMEOUT,
        target_dir: Some(build_dir()),
        keep: false,
        sandbox: Some(grade::SandboxSetup {
            runner: PathBuf::from(env!("CARGO_BIN_EXE_whitted")),
            worker: 0,
            level: Level::Namespaces,
        }),
        render: false,
        feedback: true,
        screen: true,
        judging: grade::Judging::Alone,
        judge: None,
        compile: grade::sandbox::watch::CompileLimits::default(),
    }
}

/// The places a hostile submission aims at, outside its copy.
struct Targets {
    /// The instructor's project.
    root: PathBuf,
    /// The graded copy (inside the worker's build directory).
    copy: PathBuf,
    /// The worker's build directory.
    build: PathBuf,
    /// The hidden tests' directory.
    hidden: PathBuf,
    /// A results directory the grader owns.
    results: PathBuf,
    /// A file outside every copy.
    outside: PathBuf,
    /// A port on which this test listens on the loopback.
    port: u16,
    /// The judge's directory (the instructor's project with the wire, the hidden tests, the
    /// reports of its runs).
    judge: PathBuf,
    /// `sphere_discriminant`'s number on the grader's wire.
    discriminant: usize,
}

/// The forging class: bodies that take over the process that runs them (safe Rust reaches raw
/// memory through rust-lang/rust#25860; with the screen off a plain `exit` does as well) to
/// forge a verdict: print libtest's `ok` lines and exit 0, write a report, ask the judge for
/// their own exercise's value, or read and write the judge's files. Each must score what the
/// empty handout scores: the verdict is the judge's, in a process none of them runs in.
fn forging(t: &Targets) -> Vec<(&'static str, &'static str, String)> {
    let results = t.results.display();
    let judge = t.judge.display();
    vec![
        (
            "forges-ok-and-a-report",
            "ray_direction",
            format!(
                r##"    println!("test ch01_camera_rays::ex_ray_direction_points_through_the_pixel ... ok\n\ntest result: ok. 1 passed; 0 failed");
    let _ = std::fs::write("{results}/results.json", "{{\"score\": 119}}");
    let _ = std::fs::write("junit.xml", "<testsuites/>");
    std::process::exit(0)"##
            ),
        ),
        (
            "stretches-a-lifetime-and-exits",
            "pixel_ray",
            // the hole itself: a borrow stretched to any lifetime, here read after its free
            r##"    fn stretch<'a, 'b, T: ?Sized>(_: &'a &'b (), v: &'b T) -> &'a T { v }
    fn forever<'c, 'd, T: ?Sized>(v: &'c T) -> &'d T {
        let widen: for<'x> fn(_, &'x T) -> &'d T = stretch;
        widen(&&(), v)
    }
    let dangling: &'static String = { let s = String::from("ok"); forever(&s) };
    println!("test ch01_camera_rays::ex_pixel_ray_x ... {}", dangling.len());
    std::process::exit(0)"##
                .to_string(),
        ),
        (
            "asks-the-judge",
            "sphere_discriminant",
            format!(
                "    crate::judged::call::<_, Real>({}, &(ray, a, b))",
                t.discriminant
            ),
        ),
        (
            "reads-the-judge",
            "step_matrix",
            format!(
                r##"    let a = std::fs::read_to_string("{judge}/project/crates/whitted/src/transform.rs");
    let b = std::fs::read_to_string("{judge}/project/crates/whitted/tests/hidden_extra.rs");
    let c = std::fs::write("{judge}/runs/forged.xml", "<testsuites/>");
    if a.is_ok() || b.is_ok() || c.is_ok() {{ SOLUTION }} else {{ panic!("the judge: {{:?}} {{:?}} {{:?}}", a.err(), b.err(), c.err()) }}"##
            ),
        ),
    ]
}

/// A hostile submission: its name, the chapter-1–2 exercise it attacks, and the body.
/// `SOLUTION` in the body stands for the exercise's reference body: the attack returns it
/// only if it succeeded (a gain the grader must not allow).
fn hostile(t: &Targets) -> Vec<(&'static str, &'static str, String)> {
    let root = t.root.display();
    let copy = t.copy.display();
    let build = t.build.display();
    let hidden = t.hidden.display();
    let results = t.results.display();
    let outside = t.outside.display();
    let port = t.port;
    vec![
        (
            "reads-reference",
            "direction_colour",
            format!(
                r##"    let read = |p: &str| std::fs::read_to_string(p).map(|s| s.lines().filter(|l| l.contains("max(0.0)")).collect::<Vec<_>>().join(" | ")).unwrap_or_else(|e| e.to_string());
    panic!("reference: {{}} // copy: {{}}", read("{root}/crates/whitted/src/shading.rs"), read("{copy}/crates/whitted/src/shading.rs"))"##
            ),
        ),
        (
            "writes-results",
            "hit_polyhedron",
            format!(
                r##"    let a = std::fs::write("{results}/results.json", "{{\"score\": 1000}}");
    let b = std::fs::write("{copy}/nextest-store/grading/junit.xml", "<testsuites/>");
    if a.is_ok() || b.is_ok() {{ SOLUTION }} else {{ panic!("could not write the results: {{:?}} {{:?}}", a, b) }}"##
            ),
        ),
        (
            "reads-hidden",
            "facet_crossing",
            format!(
                r##"    let a = std::fs::read_to_string("{hidden}/extra.rs");
    let b = std::fs::read_to_string("{copy}/crates/whitted/tests/hidden_extra.rs");
    match (a, b) {{ (Ok(s), _) | (_, Ok(s)) => panic!("{{s}}"), (Err(e), Err(f)) => panic!("the hidden tests: {{e}}; {{f}}") }}"##
            ),
        ),
        (
            "fork-bomb",
            "hit_cylinder",
            r##"    let mut forked = 0;
    while forked < 5000 && std::process::Command::new("sleep").arg("30").spawn().is_ok() { forked += 1; }
    panic!("forked {forked} processes")"##
                .to_string(),
        ),
        (
            "disk-filler",
            "cylinder_discriminant",
            format!(
                r##"    use std::io::Write;
    let chunk = vec![7u8; 1 << 20];
    let mut written = 0usize;
    for path in ["/tmp/fill", "fill", "/dev/shm/fill", "{outside}.fill"] {{
        if let Ok(mut f) = std::fs::File::create(path) {{
            while written < (4usize << 30) && f.write_all(&chunk).is_ok() {{ written += chunk.len(); }}
        }}
    }}
    panic!("wrote {{written}} bytes")"##
            ),
        ),
        (
            "memory-hog",
            "cylinder_normal",
            // 256 MiB at a time, a byte written in each: without a limit it would grow until
            // the time limit stopped it; with one, the allocation fails within the second
            r##"    let mut hoard: Vec<Vec<u8>> = Vec::new();
    loop { let mut v = Vec::with_capacity(256 << 20); v.push(1u8); hoard.push(v); std::hint::black_box(&hoard); }"##
                .to_string(),
        ),
        (
            "network",
            "hit_cone",
            format!(
                r##"    if std::net::TcpStream::connect(("127.0.0.1", {port})).is_ok() {{ SOLUTION }} else {{ panic!("no network") }}"##
            ),
        ),
        (
            "prints-megabytes",
            "cone_normal",
            r##"    let line = "x".repeat(1023);
    for _ in 0..(16 << 10) { println!("{line}"); eprintln!("{line}"); }
    panic!("printed 32 MiB")"##
                .to_string(),
        ),
        (
            "edits-outside",
            "cylinder_coefficients",
            format!(
                r##"    let a = std::fs::write("{outside}", "edited by a student");
    let b = std::fs::write("{root}/target/grade-tests/edited-by-a-student", "");
    if a.is_ok() || b.is_ok() {{ SOLUTION }} else {{ panic!("could not edit: {{:?}} {{:?}}", a, b) }}"##
            ),
        ),
        (
            "includes-reference",
            "cone_discriminant",
            format!(
                r##"    panic!("{{}}", include_str!("{root}/crates/whitted/src/shading.rs"))"##
            ),
        ),
        (
            "includes-hidden",
            "cone_coefficients",
            // the body is in src/shapes/cone.rs: the copy's tests/ is two levels up
            r##"    panic!("{}", include_str!("../../tests/hidden_extra.rs"))"##.to_string(),
        ),
        (
            "reads-hidden-relative",
            "sphere_normal",
            // a test's working directory is the copy's crates/whitted: a relative path starts
            // inside the copy, whatever closes the copy's root
            r##"    let read = |p: &str| std::fs::read_to_string(p).map(|s| s.lines().take(3).collect::<Vec<_>>().join(" | ")).unwrap_or_else(|e| e.to_string());
    panic!("relative: {} / up: {}", read("tests/hidden_extra.rs"), read("../../crates/whitted/tests/hidden_extra.rs"))"##
                .to_string(),
        ),
        (
            "reads-build-caches",
            "hit_plane",
            // the hidden test's message is compiled into its binary, its incremental caches
            // and the compiler's messages cargo keeps: look for it in every file named after it
            format!(
                r##"    let mut found = Vec::new();
    let mut stack = vec![std::path::PathBuf::from("{build}/debug")];
    while let Some(d) = stack.pop() {{
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {{
            let p = e.path();
            let name = p.to_string_lossy().into_owned();
            if p.is_dir() {{ stack.push(p); continue; }}
            if !name.contains("hidden") {{ continue; }}
            if let Ok(bytes) = std::fs::read(&p) {{
                if bytes.windows({len}).any(|w| w == b"{message}") {{ found.push(name); }}
            }}
        }}
    }}
    if found.is_empty() {{ panic!("read nothing of the hidden tests") }}
    let _ = found;
    SOLUTION"##,
                len = HIDDEN_MESSAGE.len(),
                message = HIDDEN_MESSAGE,
            ),
        ),
    ]
}

/// Submissions that pass the screen, or try to get past it: one exercise of chapters 1–2
/// written to print what breaks a report, or to read at compile time through a macro's
/// identifier; the name, the exercise, the body.
fn screened(t: &Targets) -> Vec<(&'static str, &'static str, String)> {
    let root = t.root.display();
    vec![
        (
            "odd-characters",
            "visible_hit",
            r##"    panic!("a non-character \u{fffe}, a \u{202e}reversed line, an \u{1b}[31mescape and a bell \u{7}")"##
                .to_string(),
        ),
        (
            "macro-include",
            "nearer_hit",
            format!(
                r##"    macro_rules! m {{ ($i:ident) => {{ $i!("{root}/crates/whitted/src/shading.rs") }} }}
    panic!("{{}}", m!(include_str))"##
            ),
        ),
        (
            "env-at-compile-time",
            "normal_to_world",
            r##"    panic!("{:?} {:?}", option_env!("WHITTED_GRADER_SECRET"), option_env!("HOME"))"##
                .to_string(),
        ),
        // what stalls the compiler: refused before it compiles (and with the screen off,
        // stopped at the compiler's limits: a_body_that_stalls_the_compiler_costs_its_own_exercise)
        (
            "endless-const",
            "near_plane_half_width",
            ENDLESS_CONST.to_string(),
        ),
        // rust-lang/rust#25860's pattern: a helper whose named lifetimes stretch a borrow, the
        // first step to raw memory and a forged `ok` line; refused for its generic signature
        (
            "stretches-a-lifetime",
            "viewing_basis",
            r##"    fn stretch<'a, 'b, T: ?Sized>(_: &'a &'b (), v: &'b T) -> &'a T { v }
    let widen: for<'x> fn(&'x &'static (), &'x String) -> &'static String = stretch;
    let dangling: &'static String = { let s = String::from("ok"); widen(&&(), &s) };
    println!("test ex_viewing_basis_is_orthonormal_and_n_points_back_to_the_eye ... {dangling}");
    None"##
                .to_string(),
        ),
        (
            "generic-explosion",
            "pixel_on_near_plane",
            GENERIC_EXPLOSION.to_string(),
        ),
    ]
}

/// Every report the grader writes for `g`, by name: the table, Gradescope's and
/// PrairieLearn's results, the instructor's and CodeGrade's JUnit, the gradebook's row.
fn reports(g: &Grade, m: &Manifest) -> Vec<(&'static str, String)> {
    let r = Report::new(g, m, &Settings::default());
    let chapters = g.chapters.clone();
    vec![
        ("table", whitted_course::report::table(g, m)),
        (
            "gradescope",
            autograder::run::results_text(&r, &chapters, Platform::Gradescope),
        ),
        (
            "prairielearn",
            autograder::run::results_text(&r, &chapters, Platform::Prairielearn),
        ),
        (
            "codegrade",
            autograder::run::results_text(&r, &chapters, Platform::Codegrade),
        ),
        ("junit", whitted_course::report::junit(g, m)),
        ("csv", whitted_course::report::csv_row(g, m)),
    ]
}

/// The lines of the reference's solution regions worth a check (code, not a brace or a
/// word), trimmed.
fn solution_lines(m: &Manifest) -> BTreeSet<String> {
    handout::regions(&root(), m)
        .unwrap()
        .iter()
        .flat_map(|r| {
            r.solution
                .lines()
                .map(|l| l.trim().to_string())
                .collect::<Vec<_>>()
        })
        .filter(|l| l.len() >= 12 && !l.starts_with("//"))
        .collect()
}

/// Every text file of a submission, joined: what the student wrote or was given.
fn submission_text(dir: &Path) -> String {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if let Ok(text) = std::fs::read_to_string(&p) {
                files.push(text);
            }
        }
    }
    files.join("\n")
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
        let dir = class.join(format!("mutant-{}", mu.name));
        copy(&dir);
        set_body(&dir, &m, &mu.exercise, &mutant_body(&m, mu));
    }
    let hidden = work.path().join("hidden");
    std::fs::create_dir_all(&hidden).unwrap();
    std::fs::write(hidden.join("extra.rs"), HIDDEN).unwrap();
    // 6. the hostile ones: a chapter-3 handout each, one exercise of chapters 1–2 attacking
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let targets = Targets {
        root: root(),
        copy: build_dir().join("slot-0").join("graded-copy"),
        build: build_dir().join("slot-0"),
        hidden: hidden.clone(),
        results: work.path().join("results"),
        outside: work.path().join("outside.txt"),
        port: listener.local_addr().unwrap().port(),
        judge: build_dir().join("judge"),
        discriminant: index(&m, "sphere_discriminant"),
    };
    std::fs::create_dir_all(&targets.results).unwrap();
    std::fs::write(&targets.outside, "untouched").unwrap();
    let edited = build_dir().join("edited-by-a-student");
    let _ = std::fs::remove_file(&edited);
    let chapter3: Vec<usize> = (0..m.entries.len())
        .filter(|&i| m.entries[i].chapter == 3)
        .collect();
    // the attacks on the runtime are graded without the screen, which would refuse them all
    // before they compile: what is proven is the second lock, the sandbox and the runner
    let runtime = work.path().join("runtime");
    let mut attacks = hostile(&targets);
    attacks.extend(forging(&targets));
    let tried = screened(&targets);
    for (name, exercise, body) in attacks.iter().chain(&tried) {
        let to = if attacks.iter().any(|(n, _, _)| n == name) {
            &runtime
        } else {
            &class
        };
        let dir = to.join(format!("hostile-{name}"));
        handout::write(&root(), &m, &chapter3, &dir).unwrap();
        let r = &handout::regions(&root(), &m).unwrap()[index(&m, exercise)];
        set_body(
            &dir,
            &m,
            exercise,
            &body.replace("SOLUTION", &format!("{{\n{}    }}", r.solution)),
        );
    }

    // 7. an honest one whose names the old screen refused: variables called env, load, save,
    // path, io and os, comments, a `///` comment on a helper function, an inner lint attribute
    let honest = class.join("honest-names");
    copy(&honest);
    for (exercise, body) in HONEST {
        set_body(&honest, &m, exercise, body);
    }

    // 8. whole submissions that end their process: in every body, or in every body while a
    // test runs; screened, and for the runner alone
    for name in ["exits-everywhere", "exits-under-test"] {
        let body = if name == "exits-everywhere" {
            EXITS
        } else {
            EXITS_UNDER_TEST
        };
        for to in [&class, &runtime] {
            let dir = to.join(name);
            copy(&dir);
            every_body(&dir, &m, body);
        }
    }

    let _one = BUILD.lock().unwrap_or_else(|p| p.into_inner());
    let options = setup(&hidden);
    let start = std::time::Instant::now();
    // one at a time: the dependencies are built once, and the time a submission takes is its own
    let graded = say_graded;
    let entries = grade::grade_class(&root(), &m, &class, &options, 1, &graded).unwrap();
    // what is checked here is containment, not the feedback: no pictures (faster)
    let unscreened = grade::GradeSetup {
        screen: false,
        feedback: false,
        ..options.clone()
    };
    let runtime_entries =
        grade::grade_class(&root(), &m, &runtime, &unscreened, 1, &graded).unwrap();
    let total = start.elapsed().as_secs_f64();
    let count = entries.len() + runtime_entries.len();
    eprintln!(
        "{count} submissions in {total:.0} s: {:.0} s a submission",
        total / count as f64
    );

    // the reference: everything, the hidden test too
    let reference = find(&entries, "reference");
    assert_eq!(
        reference.score(),
        reference.max(),
        "{:?}",
        failed(reference)
    );
    // the instructor's JUnit carries each test's points: they add up to the course's exactly
    let junit = whitted_course::report::junit(reference, &m);
    let cents: i64 = roxmltree::Document::parse(&junit)
        .unwrap()
        .descendants()
        .filter(|n| n.has_tag_name("testcase"))
        .flat_map(|c| c.descendants())
        .filter(|n| n.attribute("name") == Some("max_points"))
        .map(|p| (p.attribute("value").unwrap().parse::<f64>().unwrap() * 100.0).round() as i64)
        .sum();
    let course: u32 = m.entries.iter().map(|e| e.exercise.points).sum();
    assert_eq!(
        cents,
        i64::from(course) * 100,
        "the JUnit maxima in hundredths, against {course} points"
    );
    assert!(
        reference
            .tests
            .iter()
            .any(|t| t.hidden && t.status == Status::Passed)
    );
    let all_tests = ran(reference);

    // the chapter-4 handout: each exercise judged alone, exactly the chapter-4 exercises' own
    // tests fail, and the tests of no exercise (the whole road) that need one of them; and
    // chapter 5's, which a chapter-4 handout does not hold (a later week's answers), graded
    // here without --chapter
    let h4 = find(&entries, "handout4");
    let not_held: Vec<usize> = (0..m.entries.len())
        .filter(|&i| m.entries[i].chapter >= 4)
        .collect();
    assert_eq!(
        failed(h4),
        deps::expected_alone(&m, &map, &all_tests, &not_held)
    );
    assert_blames_only_its_own(h4, &m);
    assert_eq!(h4.chapter(&m, 4).0, 0.0);
    assert_eq!(h4.chapter(&m, 5).0, 0.0);
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
    assert_eq!(
        failed(b),
        deps::expected_alone(&m, &map, &all_tests, &three)
    );
    assert_blames_only_its_own(b, &m);
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
    // stopped by the grader's clock, at its limit of CPU time, not by the wall clock
    for t in b
        .tests
        .iter()
        .filter(|t| t.exercise == Some(index(&m, "direction_colour")))
    {
        assert!(
            t.message.starts_with(&format!(
                "stopped after {} s of CPU, its limit",
                grade::DEFAULT_TIMEOUT.as_secs()
            )),
            "the endless loop's test {}: {}",
            t.name,
            t.message
        );
    }
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
    // the error is placed at the student's own line, not the graded copy's
    let facet = &handout::regions(&root(), &m).unwrap()[index(&m, "facet_crossing")].file;
    let text = std::fs::read_to_string(broken.join(facet)).unwrap();
    let line = 1 + text
        .lines()
        .position(|l| l.contains("\"not a number\""))
        .unwrap();
    let place = format!("{}:{line}: ", facet.display());
    assert!(
        e222.note.as_deref().is_some_and(|n| n.contains(&place)),
        "{place} in {:?}",
        e222.note
    );
    // each exercise judged alone: the three lose their points, every other keeps all of its
    for e in &b.exercises {
        let id = &m.entries[e.entry].exercise.id;
        if three.contains(&e.entry) {
            assert_eq!(e.score, 0.0, "exercise {id}");
        } else {
            assert_eq!(e.score, e.max, "exercise {id}: {:?}", e.note);
        }
    }

    // the honest names score full marks, and no note
    let h = find(&entries, "honest-names");
    assert_eq!(h.score(), h.max(), "{:?}", failed(h));
    assert!(
        h.exercises.iter().all(|e| e.note.is_none()),
        "{:?}",
        h.exercises
            .iter()
            .filter_map(|e| e.note.as_ref())
            .collect::<Vec<_>>()
    );

    // the tampered handout gains nothing from its edited tests and manifest
    let t = find(&entries, "tampered");
    assert_eq!(t.score(), 0.0);
    assert_eq!(t.max(), reference.max());

    // the hostile ones: each loses exactly its handout's and its attacked exercise's tests,
    // gains nothing, and reaches nothing outside its copy
    let hostile_grade = |name: &str| -> &Grade {
        let student = format!("hostile-{name}");
        if attacks.iter().any(|(n, _, _)| *n == name) {
            find(&runtime_entries, &student)
        } else {
            find(&entries, &student)
        }
    };
    for (name, exercise, _) in attacks.iter().chain(&tried) {
        let g = hostile_grade(name);
        let i = index(&m, exercise);
        // a chapter-3 handout holds chapters 1 and 2 given, and no body of chapters 4 and 5
        let mut lost: Vec<usize> = (0..m.entries.len())
            .filter(|&k| m.entries[k].chapter >= 3)
            .collect();
        lost.push(i);
        assert_eq!(
            failed(g),
            deps::expected_alone(&m, &map, &all_tests, &lost),
            "hostile-{name} ({exercise}): lost other tests than its own, or gained some"
        );
        assert!(
            g.tests
                .iter()
                .any(|t| t.hidden && t.status == Status::Passed),
            "hostile-{name}: the hidden test of 1.2 must still pass"
        );
        let attacked = g.exercises.iter().find(|e| e.entry == i).unwrap();
        assert_eq!(attacked.score, 0.0, "hostile-{name}");
        eprintln!(
            "hostile-{name} ({exercise}): {} / {} points; its attack: {}",
            whitted_course::report::points(g.score()),
            whitted_course::report::points(g.max()),
            g.tests
                .iter()
                .find(|t| t.exercise == Some(i) && !t.hidden)
                .map_or_else(
                    || attacked.note.clone().unwrap_or_default(),
                    |t| format!("{}: {}", t.status.word(), t.message)
                )
                .chars()
                .take(160)
                .collect::<String>()
        );
    }
    let message = |name: &str, exercise: &str| -> String {
        let g = hostile_grade(name);
        let i = index(&m, exercise);
        let t = g.tests.iter().find(|t| t.exercise == Some(i)).unwrap();
        format!("{}: {}", t.status.word(), t.message)
    };
    let forked = message("fork-bomb", "hit_cylinder");
    let n: usize = forked
        .split("forked ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("the fork bomb's message: {forked}"));
    assert!(n < 64, "the fork bomb made {n} processes");
    assert!(message("network", "hit_cone").contains("no network"));
    assert!(
        message("memory-hog", "cylinder_normal").starts_with("crashed"),
        "{}",
        message("memory-hog", "cylinder_normal")
    );
    // a relative path from the test's working directory finds no hidden source, and no file
    // of the build holds the hidden test's message where a test can read it
    let relative = message("reads-hidden-relative", "sphere_normal");
    assert_eq!(
        relative.matches("No such file").count(),
        2,
        "the hidden test's source by a relative path: {relative}"
    );
    let caches = message("reads-build-caches", "hit_plane");
    assert!(
        caches.contains("read nothing of the hidden tests"),
        "the hidden test's build products: {caches}"
    );
    // what reads at compile time through a macro's identifier is refused by the screen
    for (name, exercise) in [
        ("macro-include", "nearer_hit"),
        ("env-at-compile-time", "normal_to_world"),
        ("endless-const", "near_plane_half_width"),
        ("generic-explosion", "pixel_on_near_plane"),
        ("stretches-a-lifetime", "viewing_basis"),
    ] {
        let note = note_of(hostile_grade(name), &m, exercise);
        assert!(
            note.starts_with("refused by the screen"),
            "hostile-{name}: {note}"
        );
    }
    // what a submission prints reaches every report escaped, and the submission is graded
    assert!(
        message("odd-characters", "visible_hit").contains("\\u{fffe}"),
        "{}",
        message("odd-characters", "visible_hit")
    );
    for e in entries.iter().chain(&runtime_entries) {
        if let Ok(g) = &e.grade {
            assert_reports_clean(g, &m);
        }
    }
    // a submission that ends its process scores no more than the empty handout (the tampered
    // one is that, to the grader), screened or before the runner alone
    let empty = find(&entries, "tampered");
    for name in ["exits-everywhere", "exits-under-test"] {
        for (lock, list) in [
            ("screened", &entries),
            ("the runner alone", &runtime_entries),
        ] {
            let g = find(list, name);
            assert!(
                g.score() <= empty.score() + 1e-9 && passed(g) <= passed(empty),
                "{name} ({lock}): {} points and {} of {} tests passed; the empty handout: {} points and {} passed",
                g.score(),
                passed(g),
                g.tests.len(),
                empty.score(),
                passed(empty)
            );
            eprintln!(
                "{name} ({lock}): {} / {} points, {} of {} tests passed (the empty handout: {} of {})",
                whitted_course::report::points(g.score()),
                whitted_course::report::points(g.max()),
                passed(g),
                g.tests.len(),
                passed(empty),
                empty.tests.len()
            );
        }
        let refused = find(&entries, name)
            .exercises
            .iter()
            .filter(|e| {
                e.note
                    .as_deref()
                    .is_some_and(|n| n.starts_with("refused by the screen"))
            })
            .count();
        assert_eq!(
            refused,
            m.entries.len(),
            "{name}: bodies the screen refused"
        );
    }
    let told = find(&runtime_entries, "exits-everywhere")
        .tests
        .iter()
        .filter(|t| t.message.contains("the student's process ended"))
        .count();
    assert!(told > 0, "no test of exits-everywhere says why it failed");
    for (name, exercise) in [
        ("includes-reference", "cone_discriminant"),
        ("includes-hidden", "cone_coefficients"),
    ] {
        let note = note_of(hostile_grade(name), &m, exercise);
        assert!(
            note.starts_with("does not compile"),
            "hostile-{name}: {note}"
        );
    }
    listener.set_nonblocking(true).unwrap();
    assert!(
        listener.accept().is_err(),
        "a submission connected to the loopback"
    );
    assert_eq!(
        std::fs::read_dir(&targets.results).unwrap().count(),
        0,
        "a submission wrote into the results"
    );
    assert_eq!(
        std::fs::read_to_string(&targets.outside).unwrap(),
        "untouched"
    );
    assert!(!edited.exists(), "a submission wrote into the project");
    assert!(!work.path().join("outside.txt.fill").exists());
    // no report quotes a solution line its submission did not write, nor the hidden test's
    // source; none is larger than a report needs to be
    let solutions = solution_lines(&m);
    let everyone = entries
        .iter()
        .map(|e| (e, &class))
        .chain(runtime_entries.iter().map(|e| (e, &runtime)));
    for (e, dir) in everyone {
        let Ok(g) = &e.grade else { continue };
        let own = submission_text(&dir.join(&e.student));
        let secret: Vec<&String> = solutions
            .iter()
            .filter(|l| !own.contains(l.as_str()))
            .collect();
        for (kind, text) in reports(g, &m) {
            for line in &secret {
                assert!(
                    !text.contains(line.as_str()),
                    "{}'s {kind} report quotes the solution line `{line}`",
                    e.student
                );
            }
            assert!(
                !text.contains(HIDDEN_MARKER),
                "{}'s {kind} report quotes the hidden test's source",
                e.student
            );
            assert!(
                text.len() < 512 << 10,
                "{}'s {kind} report is {} bytes",
                e.student,
                text.len()
            );
        }
    }
    let leaker = hostile_grade("reads-reference");
    let own = submission_text(&runtime.join("hostile-reads-reference"));
    let secret = solutions
        .iter()
        .filter(|l| !own.contains(l.as_str()))
        .count();
    assert!(
        secret > 20,
        "the leak check needs solution lines the leaker lacks: {secret}"
    );
    assert!(leaker.score() < leaker.max());

    // each mutant loses points in its own exercise and nowhere else
    for mu in &mutants {
        let g = find(&entries, &format!("mutant-{}", mu.name));
        let i = index(&m, &mu.exercise);
        for e in &g.exercises {
            if e.entry == i {
                assert!(
                    e.score < e.max,
                    "mutant {} ({}) keeps all of exercise {}'s points",
                    mu.name,
                    mu.why,
                    mu.exercise
                );
            } else {
                assert_eq!(
                    e.score,
                    e.max,
                    "mutant {} ({}) of exercise {} costs exercise {} points: {:?}",
                    mu.name,
                    mu.why,
                    mu.exercise,
                    m.entries[e.entry].exercise.id,
                    g.tests
                        .iter()
                        .filter(|t| t.exercise == Some(e.entry) && t.status != Status::Passed)
                        .map(|t| &t.message)
                        .collect::<Vec<_>>()
                );
            }
        }
        assert_blames_only_its_own(g, &m);
    }
    // each known mistake is named in the grade from its tests' values, as `cargo learn` names
    // it at the save (chapters/mistakes.json)
    let recorded = whitted_learn::trees::load_mistakes(&root());
    let mut named = 0;
    for k in recorded.iter().filter(|k| !k.tests.is_empty()) {
        let g = find(&entries, &format!("mutant-{}", k.name));
        let i = index(&m, &k.exercise);
        let e = g.exercises.iter().find(|e| e.entry == i).unwrap();
        assert_eq!(
            e.known.as_deref(),
            Some(k.looks_like.as_str()),
            "mutant {}: the known mistake its tests' values tell; its failing tests: {:?}",
            k.name,
            g.tests
                .iter()
                .filter(|t| t.exercise == Some(i) && t.status != Status::Passed)
                .map(|t| (&t.name, &t.values))
                .collect::<Vec<_>>()
        );
        named += 1;
    }
    eprintln!("known mistakes named in the grade from their tests' values: {named}");
    assert!(
        named >= 10,
        "only {named} known mistakes have their tests' values"
    );
    // and its report says, as learn does, where the ray trees first go wrong and which
    // exercise computed it, for each mistake whose trees differ (chapters/mistakes.json)
    let known: serde_json::Value = json(&root().join("chapters/mistakes.json"));
    // (a mistake no picture shows has no fingerprint: its tests alone tell it)
    for k in known["mistakes"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|k| k.get("fingerprint").is_some())
    {
        let name = k["name"].as_str().unwrap();
        let g = find(&entries, &format!("mutant-{name}"));
        let x = &m.entries[index(&m, k["exercise"].as_str().unwrap())].exercise;
        let table = whitted_course::report::table(g, &m);
        assert!(
            table.contains("first wrong number: pixel (")
                && table.contains(&format!("computed in exercise {} ({})", x.id, x.name)),
            "mutant {name}: the report does not point at exercise {} ({}):\n{table}",
            x.id,
            x.name
        );
        let told: Vec<&str> = table
            .lines()
            .filter(|l| l.contains("picture:") || l.contains("first wrong"))
            .collect();
        eprintln!("mutant {name}: {}", told.join(" | "));
    }
}

/// Gradescope's `autograder.zip` in `package` unpacked where Gradescope puts it, `source/`
/// under the autograder's root `ag`; that directory.
fn unpack(package: &Path, ag: &Path) -> PathBuf {
    let source = ag.join("source");
    std::fs::create_dir_all(&source).unwrap();
    let unzip = std::process::Command::new("unzip")
        .args(["-q", "-o"])
        .arg(package.join("autograder.zip"))
        .arg("-d")
        .arg(&source)
        .status()
        .unwrap();
    assert!(unzip.success(), "unzip {}", package.display());
    source
}

/// Runs `script` with `env`, its output kept; panics with it when the script fails.
fn run_script(script: &Path, env: &[(&str, &Path)]) -> String {
    let out = std::process::Command::new("bash")
        .arg(script)
        .envs(env.iter().map(|(k, v)| (*k, v.as_os_str())))
        .output()
        .unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "{} failed:\n{text}", script.display());
    text
}

fn json(path: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap()
}

/// The platforms' packages run in their layouts: Gradescope's zip unpacked in an
/// `/autograder`-shaped root (`AUTOGRADER_ROOT`), its `setup.sh` (installs skipped, since the
/// tools are here; its build step run) and `run_autograder` on a chapter-4 handout, then on
/// a submission that is not a copy; PrairieLearn's entry point in a `/grade`-shaped root
/// (`GRADE_ROOT`) on the same handout uploaded as a folder, then on an essay. They build in
/// the class's directory, so only the student's crate compiles.
/// Right bodies with names a formula may well use: `env`, `load`, `save`, `path`, `io`, `os`,
/// comments, a helper function with a `///` comment, and a lint opened as a function's body may.
const HONEST: [(&str, &str); 5] = [
    (
        "lambert",
        "    #![allow(clippy::float_cmp)]\n    n.dot(s).max(0.0)",
    ),
    (
        "near_plane_half_height",
        "    // env: the tangent of half the angle, in radians\n    let env = (fov_degrees.to_radians() / 2.0).tan();\n    near * env",
    ),
    (
        "near_plane_half_width",
        "    /// W = H·A, saved for the record\n    fn save(h: Real, a: Real) -> Real {\n        h * a\n    }\n    save(half_height, aspect)",
    ),
    (
        "point_on_ray",
        "        let path = self.dir * t; // how far along\n        let load = self.origin;\n        load + path",
    ),
    (
        "direction_colour",
        "    let io = crate::numeric::normalize(d);\n    let os = Vec3::ONE;\n    (io + os) * 0.5",
    ),
];

/// A body that stalls the compiler: an endless `const` (its lint allowed), in exercise 1.3.
const ENDLESS_CONST: &str = "    #[allow(long_running_const_eval)]
    const SPIN: u64 = {
        let mut i: u64 = 0;
        loop {
            i = i.wrapping_add(1);
        }
    };
    half_height * aspect + SPIN as Real";

/// A body that grows the compiler's memory: a type doubled 28 times by a generic helper, in
/// exercise 1.4.
const GENERIC_EXPLOSION: &str = "    fn d<T: Clone>(x: T) -> (T, T) {
        (x.clone(), x)
    }
    let big = d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(d(0u8))))))))))))))))))))))))))));
    std::hint::black_box(&big);
    (half_width * (2.0 * c / columns - 1.0), half_height * (2.0 * r / rows - 1.0))";

/// The compiler under limits: a class of three graded on chapter 1 with the screen off (the
/// screen refuses both bodies before they compile, which the class above shows): the
/// reference, a body with an endless `const` and one with a generic blow-up. Each stalled
/// submission loses exactly the exercise that stalls, with a note that says so, and the class
/// around it is graded: about log₂ 7 builds more, each stopped at 40 s of CPU or 1.5 GiB (the
/// renderer's crate built from nothing takes about 19 s of CPU here).
#[test]
#[ignore = "builds submissions until the compiler's limits stop them (minutes): .ci/run runs it"]
fn a_body_that_stalls_the_compiler_costs_its_own_exercise() {
    let m = manifest();
    let work = tempfile::tempdir().unwrap();
    let class = work.path().join("class");
    copy(&class.join("reference"));
    for (name, exercise, body) in [
        ("endless-const", "near_plane_half_width", ENDLESS_CONST),
        (
            "generic-explosion",
            "pixel_on_near_plane",
            GENERIC_EXPLOSION,
        ),
    ] {
        let dir = class.join(name);
        copy(&dir);
        set_body(&dir, &m, exercise, body);
        assert!(
            grade::screen(body).is_some(),
            "{name}: the screen refuses it"
        );
    }
    let _one = BUILD.lock().unwrap_or_else(|p| p.into_inner());
    let options = grade::GradeSetup {
        chapter: Some(grade::Chapters { first: 1, last: 1 }),
        hidden: None,
        screen: false,
        feedback: false,
        ..setup(work.path())
    };
    // the build directory warmed under the default limits: the dependencies, built once,
    // would take more than this test's limits from an empty one
    let warm = grade::grade(&root(), &m, &class.join("reference"), &options).unwrap();
    assert_eq!(warm.score(), warm.max(), "{:?}", failed(&warm));
    let options = grade::GradeSetup {
        compile: grade::sandbox::watch::CompileLimits {
            cpu: Duration::from_secs(40),
            memory: 3 << 29,
        },
        ..options
    };
    let start = std::time::Instant::now();
    let entries = grade::grade_class(&root(), &m, &class, &options, 1, &say_graded).unwrap();
    eprintln!(
        "the class of three in {:.0} s",
        start.elapsed().as_secs_f64()
    );
    let reference = find(&entries, "reference");
    assert_eq!(
        reference.score(),
        reference.max(),
        "{:?}",
        failed(reference)
    );
    for (name, exercise, limit) in [
        ("endless-const", "near_plane_half_width", "of CPU"),
        ("generic-explosion", "pixel_on_near_plane", ""),
    ] {
        let g = find(&entries, name);
        let i = index(&m, exercise);
        for e in &g.exercises {
            if e.entry == i {
                let note = e.note.as_deref().unwrap_or("");
                assert!(
                    e.score == 0.0
                        && note.starts_with("stops the compiler")
                        && note.contains(limit),
                    "{name}: exercise {exercise}: {} points, {note}",
                    e.score
                );
                eprintln!("{name}: {note}");
            } else {
                assert_eq!(
                    e.score, e.max,
                    "{name}: exercise {}: {:?}",
                    m.entries[e.entry].exercise.id, e.note
                );
            }
        }
    }
}

#[test]
#[ignore = "builds and grades through the platforms' scripts (a minute): .ci/run runs it"]
fn the_platforms_packages_grade_in_their_layouts() {
    let m = manifest();
    let work = tempfile::tempdir().unwrap();
    let hidden = work.path().join("hidden-tests");
    std::fs::create_dir_all(&hidden).unwrap();
    std::fs::write(hidden.join("extra.rs"), HIDDEN).unwrap();
    let chapter4: Vec<usize> = (0..m.entries.len())
        .filter(|&i| m.entries[i].chapter == 4)
        .collect();
    let handout4 = work.path().join("handout4");
    handout::write(&root(), &m, &chapter4, &handout4).unwrap();
    let whitted = PathBuf::from(env!("CARGO_BIN_EXE_whitted"));
    let build = build_dir();
    let options = autograder::package::Options {
        chapter: None,
        hidden: Some(hidden.clone()),
        timeout: grade::DEFAULT_TIMEOUT.as_secs(),
        settings: Settings::default(),
        sandbox: Some(Level::Namespaces),
        judging: grade::Judging::Alone,
        handout: None,
    };
    let _one = BUILD.lock().unwrap_or_else(|p| p.into_inner());

    // Gradescope
    let ag = work.path().join("autograder");
    let package = work.path().join("gradescope");
    autograder::package::write(&root(), &m, Platform::Gradescope, &options, &package).unwrap();
    let source = unpack(&package, &ag);
    let env = [
        ("AUTOGRADER_ROOT", ag.as_path()),
        ("WHITTED_BIN", whitted.as_path()),
        ("WHITTED_BUILD_DIR", build.as_path()),
    ];
    let started = std::time::Instant::now();
    let said = run_script(&source.join("setup.sh"), &env);
    assert!(
        !said.contains("setup: installing"),
        "setup.sh installed something: {said}"
    );
    assert!(said.contains("prebuilt in"), "{said}");
    eprintln!(
        "gradescope setup.sh: {:.0} s (skipped: installing the toolchain, cargo-nextest and bubblewrap, which are here and need the network on the platform; building whitted itself, WHITTED_BIN is this test's)",
        started.elapsed().as_secs_f64()
    );
    let submission = ag.join("submission");
    files::copy_tree(&handout4, &submission).unwrap();
    let started = std::time::Instant::now();
    run_script(&source.join("run_autograder"), &env);
    let took = started.elapsed().as_secs_f64();
    let results = json(&ag.join("results/results.json"));
    let tests = results["tests"].as_array().unwrap();
    // the maxima add up to the points exactly, in the hundredths the platform shows
    let cents: i64 = tests
        .iter()
        .map(|t| (t["max_score"].as_f64().unwrap() * 100.0).round() as i64)
        .sum();
    let max = cents as f64 / 100.0;
    let total: u32 = m.entries.iter().map(|e| e.exercise.points).sum();
    assert_eq!(
        cents,
        i64::from(total) * 100,
        "the maxima of results.json in hundredths, against {total} points"
    );
    assert!(
        tests.iter().all(|t| t["number"] != "-"),
        "a test of no exercise is listed"
    );
    let score = results["score"].as_f64().unwrap();
    let chapter4_points: u32 = chapter4.iter().map(|&i| m.entries[i].exercise.points).sum();
    assert!(
        score > 0.0 && score <= f64::from(total - chapter4_points) + 0.01,
        "the chapter-4 handout scored {score}"
    );
    let hidden_test = tests
        .iter()
        .find(|t| t["name"].as_str().unwrap().contains("hidden test"))
        .unwrap();
    assert_eq!(hidden_test["visibility"], "after_due_date");
    assert_eq!(hidden_test["status"], "passed");
    for t in tests {
        if t["number"] == "4.1" {
            assert_eq!(t["status"], "failed", "{t}");
            assert_eq!(t["tags"][0], "chapter 4");
        }
    }
    eprintln!("gradescope run_autograder: {score} / {max} in {took:.1} s");
    // a submission that is not a copy still gets a results file that says why
    std::fs::remove_dir_all(&submission).unwrap();
    std::fs::create_dir_all(&submission).unwrap();
    std::fs::write(submission.join("essay.txt"), "no code").unwrap();
    run_script(&source.join("run_autograder"), &env);
    let results = json(&ag.join("results/results.json"));
    assert_eq!(results["score"], 0.0);
    assert!(
        results["output"]
            .as_str()
            .unwrap()
            .contains("not a copy of the handout"),
        "{results}"
    );

    // PrairieLearn
    let pl = work.path().join("prairielearn");
    autograder::package::write(&root(), &m, Platform::Prairielearn, &options, &pl).unwrap();
    let grade_root = work.path().join("grade");
    let student = grade_root.join("student");
    files::copy_tree(&handout4, &student.join("my-copy")).unwrap();
    files::copy_tree(&pl.join("tests"), &grade_root.join("tests")).unwrap();
    std::fs::create_dir_all(grade_root.join("data")).unwrap();
    std::fs::write(grade_root.join("data/data.json"), "{}").unwrap();
    let project = root();
    let env = [
        ("GRADE_ROOT", grade_root.as_path()),
        ("WHITTED_ROOT", project.as_path()),
        ("WHITTED_BIN", whitted.as_path()),
        ("WHITTED_BUILD_DIR", build.as_path()),
    ];
    let started = std::time::Instant::now();
    run_script(&pl.join("run.sh"), &env);
    let took = started.elapsed().as_secs_f64();
    let results = json(&grade_root.join("results/results.json"));
    assert_eq!(results["gradable"], true);
    let fraction = results["score"].as_f64().unwrap();
    assert!(
        (fraction - score / max).abs() < 0.01,
        "PrairieLearn's {fraction} vs Gradescope's {score} / {max}"
    );
    let tests = results["tests"].as_array().unwrap();
    assert!(
        tests
            .iter()
            .any(|t| t["name"].as_str().unwrap().contains("hidden test"))
    );
    eprintln!("prairielearn run.sh: score {fraction} in {took:.1} s");
    std::fs::remove_dir_all(&student).unwrap();
    std::fs::create_dir_all(&student).unwrap();
    std::fs::write(student.join("essay.txt"), "no code").unwrap();
    run_script(&pl.join("run.sh"), &env);
    let results = json(&grade_root.join("results/results.json"));
    assert_eq!(results["gradable"], false, "{results}");
    assert!(
        results["format_errors"][0]
            .as_str()
            .unwrap()
            .contains("not a copy of the handout")
    );

    // Gradescope again, packaged for a container that makes no namespace: the tests run as a
    // user of their own, and a submission that reads the reference, the hidden test and its
    // binary and writes the results reaches none of them
    let user_build = if open_to_others(&build) {
        build.clone()
    } else {
        eprintln!(
            "the class's build directory {} is closed to other users: the user sandbox builds in a directory of its own (slower)",
            build.display()
        );
        let dir = Path::new("/var/tmp").join(format!("whitted-user-build-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    };
    let ag = work.path().join("autograder-user");
    let package = work.path().join("gradescope-user");
    let user = autograder::package::Options {
        sandbox: Some(Level::User),
        judging: grade::Judging::Alone,
        ..options
    };
    autograder::package::write(&root(), &m, Platform::Gradescope, &user, &package).unwrap();
    let source = unpack(&package, &ag);
    let env = [
        ("AUTOGRADER_ROOT", ag.as_path()),
        ("WHITTED_BIN", whitted.as_path()),
        ("WHITTED_BUILD_DIR", user_build.as_path()),
    ];
    run_script(&source.join("setup.sh"), &env);
    let submission = ag.join("submission");
    files::copy_tree(&handout4, &submission).unwrap();
    let attack = reads_and_leaves(&source.join("whitted"), &user_build, &ag.join("results"));
    let r = &handout::regions(&root(), &m).unwrap()[index(&m, "direction_colour")];
    let path = submission.join(&r.file);
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(&path, text.replacen(&r.solution, &format!("{attack}\n"), 1)).unwrap();
    run_script(&source.join("run_autograder"), &env);
    let text = std::fs::read_to_string(ag.join("results/results.json")).unwrap();
    let results: serde_json::Value = serde_json::from_str(&text).unwrap();
    let attacked = results["tests"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["number"] == "1.7")
        .unwrap_or_else(|| panic!("no test of 1.7: {text}"));
    // the screen refuses it before it compiles (the same attack meets the runtime's locks in
    // user_level_runtime, with the screen off)
    let said = attacked["output"].as_str().unwrap();
    assert!(said.contains("not written"), "{said}");
    assert!(!text.contains(HIDDEN_MARKER));
    assert!(
        results["tests"]
            .as_array()
            .unwrap()
            .iter()
            .any(|t| t["name"].as_str().unwrap().contains("hidden test") && t["status"] == "passed"),
        "{text}"
    );
    eprintln!("gradescope with --sandbox user: the attack met {said}");

    // the same package on submissions that end their process, in every body or only under a
    // test (one body reading the grader's environment at compile time, through a macro's
    // identifier): no more than the empty handout, and no secret in the results
    let secret_env = [
        ("AUTOGRADER_ROOT", ag.as_path()),
        ("WHITTED_BIN", whitted.as_path()),
        ("WHITTED_BUILD_DIR", user_build.as_path()),
        ("WHITTED_GRADER_SECRET", Path::new(GRADER_SECRET)),
    ];
    let mut graded = Vec::new();
    let forged = Targets {
        root: source.join("whitted"),
        copy: user_build.join("graded-copy"),
        build: user_build.clone(),
        hidden: hidden.clone(),
        results: ag.join("results"),
        outside: work.path().join("outside.txt"),
        port: 0,
        judge: whitted_course::grade::judge_copy::beside(&user_build),
        discriminant: index(&m, "sphere_discriminant"),
    };
    for name in ["empty", "exits-everywhere", "exits-under-test", "forging"] {
        let _ = std::fs::remove_dir_all(&submission);
        let all: Vec<usize> = (0..m.entries.len()).collect();
        match name {
            "empty" => {
                handout::write(&root(), &m, &all, &submission).unwrap();
            }
            "forging" => {
                // the empty handout and the forging class's four bodies, each in its exercise
                handout::write(&root(), &m, &all, &submission).unwrap();
                for (_, exercise, body) in forging(&forged) {
                    let i = index(&m, exercise);
                    let r = &handout::regions(&root(), &m).unwrap()[i];
                    let body = body.replace("SOLUTION", &format!("{{\n{}    }}", r.solution));
                    let path = submission.join(&r.file);
                    let text = std::fs::read_to_string(&path).unwrap();
                    let todo = format!("{}{}\n", r.indent, handout::todo_statement(&m.entries[i]));
                    assert!(
                        text.contains(&todo),
                        "{exercise}: no todo!() in the handout"
                    );
                    std::fs::write(&path, text.replacen(&todo, &format!("{body}\n"), 1)).unwrap();
                }
            }
            _ => {
                copy(&submission);
                every_body(
                    &submission,
                    &m,
                    if name == "exits-everywhere" {
                        EXITS
                    } else {
                        EXITS_UNDER_TEST
                    },
                );
                let r = &handout::regions(&root(), &m).unwrap()[index(&m, "normal_to_world")];
                let path = submission.join(&r.file);
                let text = std::fs::read_to_string(&path).unwrap();
                let body = if name == "exits-everywhere" {
                    EXITS
                } else {
                    EXITS_UNDER_TEST
                };
                let attack = "    macro_rules! m { ($i:ident) => { $i!(\"WHITTED_GRADER_SECRET\") } }\n    panic!(\"{:?}\", m!(option_env))";
                std::fs::write(
                    &path,
                    text.replacen(&format!("{body}\n"), &format!("{attack}\n"), 1),
                )
                .unwrap();
            }
        }
        run_script(&source.join("run_autograder"), &secret_env);
        let text = std::fs::read_to_string(ag.join("results/results.json")).unwrap();
        assert!(
            !text.contains(GRADER_SECRET),
            "{name}: the grader's environment reached the results"
        );
        let results: serde_json::Value = serde_json::from_str(&text).unwrap();
        let score = results["score"].as_f64().unwrap();
        let passed = results["tests"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|t| t["status"] == "passed")
            .count();
        eprintln!("gradescope with --sandbox user, {name}: {score} points, {passed} tests passed");
        graded.push((name, score, passed));
    }
    let (_, empty_score, empty_passed) = graded[0];
    for (name, score, passed) in &graded[1..] {
        assert!(
            *score <= empty_score + 1e-9 && *passed <= empty_passed,
            "{name}: {score} points and {passed} tests passed; the empty handout {empty_score} and {empty_passed}"
        );
    }

    // the user level with the runner alone (no screen): submissions that end their process,
    // read the hidden test by a relative path or its build caches, and a pair that leaves
    // answers in the shared temporary directories for the other, graded in both orders
    user_level_runtime(
        &m,
        &source.join("whitted"),
        &hidden,
        &user_build,
        &ag.join("results"),
        work.path(),
    );
    if user_build != build {
        let _ = std::fs::remove_dir_all(&user_build);
    }
}

/// A copy of the reference at `dir` whose body of `exercise` is the attack `body`, `SOLUTION`
/// in it standing for the reference's body.
fn attacking(dir: &Path, m: &Manifest, exercise: &str, body: &str) {
    copy(dir);
    let r = &handout::regions(&root(), m).unwrap()[index(m, exercise)];
    set_body(
        dir,
        m,
        exercise,
        &body.replace("SOLUTION", &format!("{{\n{}    }}", r.solution)),
    );
}

/// The user level's second lock, graded without the screen from the instructor's project
/// `project` (closed to other users) in the build directory `build` (open to them): see the
/// call in [`the_platforms_packages_grade_in_their_layouts`].
fn user_level_runtime(
    m: &Manifest,
    project: &Path,
    hidden: &Path,
    build: &Path,
    results: &Path,
    work: &Path,
) {
    // the hidden tests closed to other users, as the grader asks at this level
    let closed = work.join("hidden-closed");
    files::copy_tree(hidden, &closed).unwrap();
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&closed, std::fs::Permissions::from_mode(0o700)).unwrap();
    }
    let hidden = closed.as_path();
    let options = grade::GradeSetup {
        chapter: None,
        hidden: Some(hidden.to_path_buf()),
        timeout: grade::DEFAULT_TIMEOUT,
        target_dir: Some(build.to_path_buf()),
        keep: false,
        sandbox: Some(grade::SandboxSetup {
            runner: PathBuf::from(env!("CARGO_BIN_EXE_whitted")),
            worker: 0,
            level: Level::User,
        }),
        render: false,
        feedback: false,
        screen: false,
        judging: grade::Judging::Alone,
        judge: None,
        compile: grade::sandbox::watch::CompileLimits::default(),
    };
    let dir = work.join("user-level");
    let all: Vec<usize> = (0..m.entries.len()).collect();
    // each graded on the chapter its attack is in (the Gradescope runs above grade whole ones)
    let grade_one = |name: &str, chapter: u8| -> Grade {
        let options = grade::GradeSetup {
            chapter: Some(grade::Chapters {
                first: chapter,
                last: chapter,
            }),
            ..options.clone()
        };
        let g = grade::grade(project, m, &dir.join(name), &options)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        eprintln!(
            "user level, runner alone, {name}: {} / {} points, {} of {} tests passed",
            whitted_course::report::points(g.score()),
            whitted_course::report::points(g.max()),
            passed(&g),
            g.tests.len()
        );
        g
    };
    handout::write(&root(), m, &all, &dir.join("empty")).unwrap();
    let empty = grade_one("empty", 1);
    for (name, body) in [
        ("exits-everywhere", EXITS),
        ("exits-under-test", EXITS_UNDER_TEST),
    ] {
        copy(&dir.join(name));
        every_body(&dir.join(name), m, body);
        let g = grade_one(name, 1);
        assert!(
            g.score() <= empty.score() + 1e-9 && passed(&g) <= passed(&empty),
            "{name} at the user level: {} points and {} passed; the empty handout {} and {}",
            g.score(),
            passed(&g),
            empty.score(),
            passed(&empty)
        );
    }
    // the hidden test by a relative path and by its build caches
    let targets = Targets {
        root: project.to_path_buf(),
        copy: build.join("graded-copy"),
        build: build.to_path_buf(),
        hidden: hidden.to_path_buf(),
        results: work.join("results"),
        outside: work.join("outside.txt"),
        port: 0,
        judge: whitted_course::grade::judge_copy::beside(build),
        discriminant: index(m, "sphere_discriminant"),
    };
    for (name, exercise, body) in hostile(&targets) {
        if !matches!(name, "reads-hidden-relative" | "reads-build-caches") {
            continue;
        }
        attacking(&dir.join(name), m, exercise, &body);
        let g = grade_one(name, m.entries[index(m, exercise)].chapter);
        let i = index(m, exercise);
        let said: Vec<String> = g
            .tests
            .iter()
            .filter(|t| t.exercise == Some(i) && !t.hidden)
            .map(|t| t.message.clone())
            .collect();
        let e = g.exercises.iter().find(|e| e.entry == i).unwrap();
        assert_eq!(e.score, 0.0, "{name}: {said:?}");
        for s in &said {
            assert!(
                s.contains("No such file") || s.contains("read nothing of the hidden tests"),
                "{name} at the user level: {s}"
            );
            assert!(
                !s.contains(HIDDEN_MARKER) && !s.contains(HIDDEN_MESSAGE),
                "{s}"
            );
        }
    }
    // the forging class: the attacked exercise scores what the empty handout scores (0), every
    // test of it fails, and every other exercise of the reference keeps its points
    for (name, exercise, body) in forging(&targets) {
        attacking(&dir.join(name), m, exercise, &body);
        let i = index(m, exercise);
        let g = grade_one(name, m.entries[i].chapter);
        for e in &g.exercises {
            let want = if e.entry == i { 0.0 } else { e.max };
            assert_eq!(
                e.score,
                want,
                "{name} at the user level, exercise {}: {:?}",
                m.entries[e.entry].exercise.id,
                g.tests
                    .iter()
                    .filter(|t| t.exercise == Some(e.entry))
                    .map(|t| (&t.name, &t.status, &t.message))
                    .collect::<Vec<_>>()
            );
        }
        assert!(
            g.tests
                .iter()
                .filter(|t| t.exercise == Some(i))
                .all(|t| t.status != Status::Passed),
            "{name} at the user level: a test of {exercise} passed"
        );
    }
    // your sources, the hidden test in the copy and its binary, the results, a child left
    // running: each out of reach, and the child gone when its test ends
    let sub = dir.join("reads-and-leaves");
    copy(&sub);
    set_body(
        &sub,
        m,
        "direction_colour",
        &reads_and_leaves(project, build, results),
    );
    let g = grade_one("reads-and-leaves", 1);
    let i = index(m, "direction_colour");
    let said = g
        .tests
        .iter()
        .find(|t| t.exercise == Some(i))
        .map(|t| t.message.clone())
        .unwrap();
    let part = |name: &str| {
        said.split(" / ")
            .find_map(|p| {
                p.split_once(&format!("{name}: "))
                    .map(|(_, v)| v.to_string())
            })
            .unwrap_or_else(|| panic!("no `{name}` in {said}"))
    };
    assert!(part("src").starts_with("Permission denied"), "{said}");
    assert!(part("copy").starts_with("Permission denied"), "{said}");
    assert!(part("judge").starts_with("Permission denied"), "{said}");
    let bins = part("bins");
    assert!(
        !bins.is_empty() && bins.split(',').all(|b| b.starts_with("Permission denied")),
        "the hidden test's binary: {said}"
    );
    assert!(part("wrote").starts_with("false"), "{said}");
    assert!(part("left").starts_with("true"), "{said}");
    // the users of the first 16 workers: more than these tests start
    let users = sandbox::FIRST_UID..sandbox::FIRST_UID + 16 * sandbox::SLOTS;
    let left = sandbox::processes_of(&users);
    assert!(
        left.is_empty(),
        "processes of the sandbox's users left after grading: {left:?}"
    );
    eprintln!("user level, runner alone: the attack met {said}");
    // answers left in the shared temporary directories: a writer (the reference, which also
    // writes W = H·A where every user may read it) and a reader (no formula, only a look-up)
    let writer = r##"    let w = half_height * aspect;
    for dir in ["/tmp", "/var/tmp", "/dev/shm"] {
        let path = format!("{dir}/whitted-answers");
        if let Ok(mut f) = std::fs::OpenOptions::new().create(true).append(true).open(&path) {
            use std::io::Write;
            let _ = writeln!(f, "{half_height} {aspect} {w}");
        }
        let _ = std::fs::set_permissions(&path, std::os::unix::fs::PermissionsExt::from_mode(0o666));
    }
    w"##;
    let reader = r##"    for dir in ["/tmp", "/var/tmp", "/dev/shm"] {
        let text = std::fs::read_to_string(format!("{dir}/whitted-answers")).unwrap_or_default();
        for line in text.lines() {
            let v: Vec<&str> = line.split(' ').collect();
            if v.len() == 3 && v[0] == half_height.to_string() && v[1] == aspect.to_string() {
                return v[2].parse().unwrap();
            }
        }
    }
    panic!("no answer left behind")"##;
    for (name, body) in [("writer", writer), ("reader", reader)] {
        copy(&dir.join(name));
        set_body(&dir.join(name), m, "near_plane_half_width", body);
    }
    let mut scores = Vec::new();
    for order in [["writer", "reader"], ["reader", "writer"]] {
        let mut got = std::collections::BTreeMap::new();
        for name in order {
            got.insert(name, grade_one(name, 1).score());
        }
        for dir in sandbox::SHARED_TEMPORARY {
            assert!(
                !Path::new(dir).join("whitted-answers").exists(),
                "{dir}/whitted-answers outlived the grading"
            );
        }
        scores.push(got);
    }
    assert_eq!(
        scores[0], scores[1],
        "the same submissions graded in two orders"
    );
    let i = index(m, "near_plane_half_width");
    assert!(
        scores[0]["reader"] + f64::from(m.entries[i].exercise.points) <= scores[0]["writer"] + 1e-9,
        "the reader gained from the writer's answers: {scores:?}"
    );
}

/// A body that reads the instructor's `project`'s sources, the hidden test in the graded copy
/// of `build` and its binary, writes into `results` and leaves a `sleep` running, and panics
/// with what each met.
fn reads_and_leaves(project: &Path, build: &Path, results: &Path) -> String {
    let judge = whitted_course::grade::judge_copy::beside(build);
    format!(
        r##"    let read = |p: &str| std::fs::read_to_string(p).map(|s| s.lines().take(3).collect::<Vec<_>>().join(" | ")).unwrap_or_else(|e| e.to_string());
    let bins = std::fs::read_dir("{judge}/target/debug/deps").map(|d| d.filter_map(Result::ok).filter(|e| e.file_name().to_string_lossy().starts_with("hidden_")).map(|e| std::fs::read(e.path()).map(|b| b.len().to_string()).unwrap_or_else(|e| e.to_string())).collect::<Vec<_>>().join(",")).unwrap_or_else(|e| e.to_string());
    let wrote = std::fs::write("{results}/results.json", "{{}}").is_ok();
    let left = std::process::Command::new("sleep").arg("300").spawn().is_ok();
    panic!("src: {{}} / copy: {{}} / judge: {{}} / bins: {{}} / wrote: {{wrote}} / left: {{left}}", read("{project}/crates/whitted/src/shading.rs"), read("{build}/graded-copy/crates/whitted/src/shading.rs"), read("{judge}/project/crates/whitted/tests/hidden_extra.rs"), bins)"##,
        build = build.display(),
        judge = judge.display(),
        results = results.display(),
        project = project.display(),
    )
}

/// Whether a live process's command line holds `word` (a `sleep`'s unusual duration).
fn running(word: &str) -> Vec<String> {
    std::fs::read_dir("/proc")
        .unwrap()
        .flatten()
        .filter_map(|e| {
            let cmdline = std::fs::read(e.path().join("cmdline")).ok()?;
            let text = String::from_utf8_lossy(&cmdline).replace('\0', " ");
            let status = std::fs::read_to_string(e.path().join("status")).ok()?;
            let zombie = status
                .lines()
                .any(|l| l.starts_with("State:") && l.contains('Z'));
            (!zombie && text.split(' ').any(|w| w == word)).then_some(text)
        })
        .collect()
}

/// The runner alone, on stand-ins for a test binary (shell scripts that answer libtest's
/// command line), at both levels: a pass needs libtest's `ok` for that test; a child the test
/// left running, even in a session of its own, is gone when the runner returns, and so is
/// one of a test stopped at its time limit; the run's temporary directory is its own and is
/// removed; what the test printed arrives escaped.
#[test]
#[ignore = "runs the sandbox as root with bubblewrap: .ci/run runs it"]
fn the_runner_passes_only_what_libtest_passed_and_leaves_nothing_behind() {
    use std::os::unix::fs::PermissionsExt;
    let work = tempfile::tempdir().unwrap();
    // the tests' users must reach the scripts
    std::fs::set_permissions(work.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    let script = |name: &str, text: &str| -> PathBuf {
        let path = work.path().join(name);
        std::fs::write(&path, format!("#!/bin/sh\n{text}\n")).unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
        path
    };
    let passes = script(
        "passes",
        "setsid sleep 3171 </dev/null >/dev/null 2>&1 &\n\
         touch \"$TMPDIR/left\" /tmp/whitted-left-3171 /dev/shm/whitted-left-3171\n\
         printf 'tmp=%s\\n' \"$TMPDIR\" >&2\n\
         printf 'odd: \\357\\277\\276 \\342\\200\\256 \\377\\n' >&2\n\
         printf 'running 1 test\\ntest %s ... ok\\n' \"$1\"",
    );
    let early = script(
        "exits-early",
        "sleep 3172 </dev/null >/dev/null 2>&1 &\nexit 0",
    );
    let hangs = script(
        "hangs",
        "setsid sleep 3173 </dev/null >/dev/null 2>&1 &\nsleep 60",
    );
    let bwrap = ["/usr/bin/bwrap", "/bin/bwrap"]
        .into_iter()
        .map(PathBuf::from)
        .find(|p| p.exists())
        .expect("bubblewrap");
    // a block of users of this test's own, as a grading takes: a grading beside it (another
    // test binary of CI's) never sweeps these users
    let lease = sandbox::Lease::take(9).expect("a block of sandbox users");
    for level in [Level::Namespaces, Level::User] {
        let policy = sandbox::Policy {
            level,
            bwrap: bwrap.clone(),
            uid: Some(sandbox::FIRST_UID + sandbox::SLOTS * lease.block),
            slot: 0,
            limits: sandbox::Limits::default(),
            read: Vec::new(),
            write: Vec::new(),
            timeout_ms: Some(1500),
        };
        let json = serde_json::to_string(&policy).unwrap();
        let run = |bin: &Path| {
            let started = std::time::Instant::now();
            let out = std::process::Command::new(env!("CARGO_BIN_EXE_whitted"))
                .arg("sandbox-run")
                .arg(bin)
                .args(["t::name", "--exact", "--nocapture"])
                .env(sandbox::POLICY_VAR, &json)
                .env("NEXTEST_TEST_GLOBAL_SLOT", "3")
                .output()
                .unwrap();
            let said = format!(
                "{}{}",
                String::from_utf8_lossy(&out.stdout),
                String::from_utf8_lossy(&out.stderr)
            );
            (out.status, said, started.elapsed())
        };
        let (status, said, _) = run(&passes);
        assert!(status.success(), "{level:?}: {said}");
        assert!(said.contains("test t::name ... ok"), "{level:?}: {said}");
        assert!(
            said.contains("odd: \\u{fffe} \\u{202e} \u{fffd}"),
            "{level:?}: the output arrives escaped: {said}"
        );
        assert!(
            running("3171").is_empty(),
            "{level:?}: {:?}",
            running("3171")
        );
        for dir in ["/tmp", "/dev/shm"] {
            let left = Path::new(dir).join("whitted-left-3171");
            assert!(
                !left.exists(),
                "{level:?}: {} outlived its test",
                left.display()
            );
        }
        if level == Level::User {
            let tmp = said
                .lines()
                .find_map(|l| l.strip_prefix("tmp="))
                .unwrap_or_else(|| panic!("{said}"));
            assert!(tmp.starts_with("/tmp/whitted-test-"), "{tmp}");
            assert!(!Path::new(tmp).exists(), "{tmp} outlived its test");
        }
        let (status, said, _) = run(&early);
        assert_eq!(status.code(), Some(1), "{level:?}: {said}");
        assert!(said.contains("libtest never reported"), "{level:?}: {said}");
        assert!(
            running("3172").is_empty(),
            "{level:?}: {:?}",
            running("3172")
        );
        let (status, said, took) = run(&hangs);
        assert!(!status.success(), "{level:?}: {said}");
        assert!(
            said.contains("stopped at the time limit"),
            "{level:?}: {said}"
        );
        assert!(
            running("3173").is_empty(),
            "{level:?}: {:?}",
            running("3173")
        );
        assert!(took >= Duration::from_millis(1200), "{took:?}");
    }
}

/// Whether every directory down to `path` is searchable by other users.
fn open_to_others(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    path.canonicalize().is_ok_and(|p| {
        p.ancestors()
            .all(|a| std::fs::metadata(a).is_ok_and(|m| m.permissions().mode() & 0o001 != 0))
    })
}

/// GitHub Classroom's workflow, its commands run as its steps would in a student's
/// repository: a chapter-4 handout committed as the template with the package, the grading
/// step against the first commit (the build directory swapped for the class's, so only the
/// student's crate compiles), then the check step of an exercise the handout keeps, which
/// passes, and of one it leaves out, which fails.
#[test]
#[ignore = "builds and grades through the workflow's commands (a minute): .ci/run runs it"]
fn the_classroom_workflow_grades_the_students_repository() {
    let m = manifest();
    let work = tempfile::tempdir().unwrap();
    let repo = work.path().join("repo");
    let chapter4: Vec<usize> = (0..m.entries.len())
        .filter(|&i| m.entries[i].chapter == 4)
        .collect();
    handout::write(&root(), &m, &chapter4, &repo).unwrap();
    let options = autograder::package::Options {
        chapter: None,
        hidden: None,
        timeout: grade::DEFAULT_TIMEOUT.as_secs(),
        settings: Settings::default(),
        sandbox: Some(Level::Namespaces),
        judging: grade::Judging::Alone,
        handout: None,
    };
    autograder::package::write(&root(), &m, Platform::Classroom, &options, &repo).unwrap();
    let git = |args: &[&str]| {
        let ok = std::process::Command::new("git")
            .args(["-c", "user.name=t", "-c", "user.email=t@t"])
            .args(args)
            .current_dir(&repo)
            .status()
            .unwrap()
            .success();
        assert!(ok, "git {args:?}");
    };
    git(&["init", "-q"]);
    git(&["add", "-A"]);
    git(&["commit", "-qm", "the handout"]);
    // the student's work: one exercise of the four written
    let feeler = index(&m, "feeler_ray");
    let r = &handout::regions(&root(), &m).unwrap()[feeler];
    let path = repo.join(&r.file);
    let text = std::fs::read_to_string(&path).unwrap();
    let todo = format!(
        "{}{}\n",
        r.indent,
        handout::todo_statement(&m.entries[feeler])
    );
    assert!(text.contains(&todo), "4.1's todo!() in {}", path.display());
    std::fs::write(&path, text.replacen(&todo, &r.solution, 1)).unwrap();
    git(&["commit", "-qam", "4.1"]);
    let yml = std::fs::read_to_string(repo.join(autograder::classroom::WORKFLOW)).unwrap();
    let whitted = env!("CARGO_BIN_EXE_whitted");
    let tool = format!("{}/target/release/whitted", autograder::classroom::GRADER);
    // a line of the grading step's script, or a check step's command (a quoted string)
    let step = |needle: &str| -> String {
        let line = yml
            .lines()
            .find(|l| l.contains(needle))
            .unwrap_or_else(|| panic!("no step with `{needle}` in {yml}"))
            .trim();
        match line.strip_prefix("command: \"") {
            Some(quoted) => quoted
                .strip_suffix('"')
                .unwrap_or(quoted)
                .replace("\\\"", "\""),
            None => line.to_string(),
        }
    };
    let run = |line: &str| {
        std::process::Command::new("bash")
            .args(["-c", line])
            .current_dir(&repo)
            .output()
            .unwrap()
    };
    let worktree = step("git worktree add");
    assert!(run(&worktree).status.success(), "{worktree}");
    let grade = step("autograder grade --platform classroom")
        .replace("sudo -E env \"PATH=$PATH\" ", "")
        .replace(&tool, whitted)
        .replace(
            "--target-dir ../build",
            &format!("--target-dir {}", build_dir().display()),
        );
    let _one = BUILD.lock().unwrap_or_else(|p| p.into_inner());
    let graded = run(&grade);
    assert!(
        graded.status.success(),
        "{grade}: {}",
        String::from_utf8_lossy(&graded.stderr)
    );
    // the handout lists its own exercises (chapter 4's): a step each, the given ones none
    assert!(
        !yml.contains("--exercise viewing_basis\""),
        "a step for a given exercise"
    );
    for (exercise, passes) in [("feeler_ray", true), ("blocks_light", false)] {
        let check = step(&format!("--exercise {exercise}\"")).replace(&tool, whitted);
        let out = run(&check);
        assert_eq!(
            out.status.success(),
            passes,
            "{check}: {}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
    let results = json(&work.path().join("results.json"));
    let score = results["score"].as_f64().unwrap();
    let chapter4_points: u32 = chapter4.iter().map(|&i| m.entries[i].exercise.points).sum();
    // only the handout's exercises count: the given chapters are not the student's points
    assert!(
        score > 0.0 && score < f64::from(chapter4_points),
        "{score} of the chapter's {chapter4_points}"
    );
    eprintln!("classroom: the chapter-4 handout scored {score} through the workflow's commands");
}

/// Busy loops, ended when dropped: the load of a machine shared with other work.
struct BusyLoops(Vec<std::process::Child>);

impl BusyLoops {
    fn start(n: usize) -> Self {
        Self(
            (0..n)
                .map(|_| {
                    std::process::Command::new("sh")
                        .args(["-c", "while :; do :; done"])
                        .spawn()
                        .unwrap()
                })
                .collect(),
        )
    }
}

impl Drop for BusyLoops {
    fn drop(&mut self) {
        for c in &mut self.0 {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

/// A grade that never changes under load: the reference's chapter 1, graded in namespaces
/// while a user-level grading of another class runs beside it (its own build directory, its
/// own block of users, its clean-ups ending every process of its users after each test) and
/// 32 busy loops share the two cores, keeps full marks: each test's limit counts its own CPU
/// time, and no other grading's clean-up reaches its processes. The other class (a copy of
/// the reference and a chapter-1 handout) is graded as it deserves beside it. Both are graded
/// once on an idle machine first, so that what runs under load is the tests, not the
/// compiler.
#[test]
#[ignore = "grades the reference under 32 busy loops beside another grading (minutes): .ci/run runs it"]
fn the_reference_keeps_full_marks_beside_another_grading_and_under_load() {
    let _one = BUILD
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let m = manifest();
    let ours = grade::GradeSetup {
        chapter: Some(grade::Chapters { first: 1, last: 1 }),
        hidden: None,
        target_dir: Some(build_dir().join("slot-0")),
        feedback: false,
        ..setup(Path::new("/nonexistent"))
    };
    // the other grading's instructor's project, closed to other users as the user level
    // asks; its build directory is open to them
    let work = tempfile::tempdir().unwrap();
    let instructor = work.path().join("instructor");
    copy(&instructor);
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&instructor, std::fs::Permissions::from_mode(0o700)).unwrap();
    }
    let class = work.path().join("class");
    copy(&class.join("reference"));
    let chapter_1: Vec<usize> = (0..m.entries.len())
        .filter(|&i| m.entries[i].chapter == 1)
        .collect();
    handout::write(&root(), &m, &chapter_1, &class.join("handout")).unwrap();
    // the other grading's build directory starts as a copy of a class worker's, as a class's
    // workers do: only the judge is built anew
    let theirs = build_dir().with_file_name("grade-tests-beside");
    let seeded = theirs.join("slot-0").join("debug");
    let seed = ["slot-1", "slot-0"]
        .map(|s| build_dir().join(s).join("debug"))
        .into_iter()
        .find(|d| d.is_dir());
    if let (false, Some(seed)) = (seeded.is_dir(), seed) {
        std::fs::create_dir_all(seeded.parent().unwrap()).unwrap();
        let status = std::process::Command::new("cp")
            .arg("-a")
            .arg(&seed)
            .arg(&seeded)
            .status()
            .unwrap();
        assert!(status.success(), "cp -a of the class's build directory");
    }
    let other = |out: &Path| {
        let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_whitted"));
        c.current_dir(&instructor)
            .args([
                "grade",
                "--chapter",
                "1",
                "--sandbox",
                "user",
                "--no-feedback",
            ])
            .args(["--jobs", "1", "--class"])
            .arg(&class)
            .arg("--out")
            .arg(out)
            .arg("--target-dir")
            .arg(&theirs);
        c
    };
    let full = |g: &Grade, when: &str| {
        let lost: Vec<String> = g
            .tests
            .iter()
            .filter(|t| t.status != Status::Passed)
            .map(|t| format!("{} ({}): {}", t.name, t.status.word(), t.message))
            .collect();
        assert!(
            (g.score() - g.max()).abs() < 1e-9 && lost.is_empty(),
            "the reference {when}: {} / {}, lost {lost:?}",
            g.score(),
            g.max()
        );
    };
    // idle: both built
    let started = std::time::Instant::now();
    let g = grade::grade(&root(), &m, &root(), &ours).unwrap();
    full(&g, "on an idle machine");
    let out = other(&work.path().join("idle")).output().unwrap();
    assert!(out.status.success(), "{}", common::text(&out));
    eprintln!(
        "under load: both built and graded idle in {:?}",
        started.elapsed()
    );
    // under load, beside each other
    let loops = BusyLoops::start(32);
    let started = std::time::Instant::now();
    let beside_out = work.path().join("loaded");
    let mut beside = other(&beside_out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let g = grade::grade(&root(), &m, &root(), &ours).unwrap();
    let ours_took = started.elapsed();
    let said = {
        let mut err = String::new();
        std::io::Read::read_to_string(beside.stderr.as_mut().unwrap(), &mut err).unwrap();
        err
    };
    let status = beside.wait().unwrap();
    drop(loops);
    full(&g, "under 32 busy loops beside a user-level grading");
    assert!(status.success(), "the grading beside it: {said}");
    let book = std::fs::read_to_string(beside_out.join("class.csv")).unwrap();
    let total = |student: &str| -> f64 {
        let row = book
            .lines()
            .find(|l| l.starts_with(&format!("{student},")))
            .unwrap_or_else(|| panic!("no row of {student} in {book}"));
        row.split(',').nth(3).unwrap().parse().unwrap()
    };
    let max = f64::from(
        chapter_1
            .iter()
            .map(|&i| m.entries[i].exercise.points)
            .sum::<u32>(),
    );
    assert!(
        (total("reference") - max).abs() < 1e-9,
        "the other class's copy of the reference: {} / {max}\n{book}",
        total("reference")
    );
    assert!(total("handout").abs() < 1e-9, "the handout: {book}");
    eprintln!(
        "under load: the reference kept {} / {} under 32 busy loops beside a user-level grading ({ours_took:?}); that grading gave its copy of the reference {max} / {max} and the handout 0",
        g.score(),
        g.max()
    );
}
