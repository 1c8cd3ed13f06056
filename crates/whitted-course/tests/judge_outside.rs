//! The judge outside the student's process (`whitted_course::grade::outside`, the renderer's
//! `judge` module): the instructor's crate and tests judge, the student's crate serves, and
//! only values cross between them.
//!
//! `#[ignore]`d in a plain `cargo test` (it builds the project twice and a server per
//! submission, a few minutes, and runs the grader's sandbox as root); `.ci/run` runs it:
//! `cargo test -p whitted-course --test judge_outside -- --ignored --nocapture`.

mod common;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

use common::{copy, index, manifest, mutant_body, mutants, root, set_body};
use whitted_course::grade::alone::GRADED_TEST_VAR as TEST_VAR;
use whitted_course::grade::outside::{SERVER_EXAMPLE, SERVER_VAR, add_wire};
use whitted_course::grade::runner::SERVE;
use whitted_course::grade::sandbox::{self, Level};
use whitted_course::manifest::Manifest;

/// The test targets whose exercise tests are judged.
const TARGETS: [&str; 5] = [
    "ch01_camera_rays",
    "ch02_generic_objects",
    "ch03_shading",
    "ch04_shadows",
    "ch05_reflection_refraction",
];

/// Where the copies and their shared build directory live, kept between runs so that a run
/// rebuilds only what changed.
fn work() -> PathBuf {
    root().join("target/judge-tests")
}

fn cargo(project: &Path, args: &[&str]) -> std::process::Output {
    let mut c = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    c.current_dir(project)
        .args(args)
        .env("CARGO_TARGET_DIR", work().join("target"));
    let out = c.output().unwrap();
    assert!(
        out.status.success(),
        "cargo {args:?} in {}:\n{}",
        project.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// A fresh copy of the reference at `dir` (what was there removed), changed by `change`, with
/// the wire written in.
fn wired_copy(dir: &Path, m: &Manifest, change: impl FnOnce(&Path)) -> BTreeSet<usize> {
    if dir.exists() {
        // keep the copy's files' times where nothing changes: remove only the sources
        std::fs::remove_dir_all(dir.join("crates")).unwrap();
    }
    copy(dir);
    change(dir);
    let wired = add_wire(dir, m).unwrap();
    wired.crossing.into_iter().collect()
}

/// The judge: the reference with the wire, its exercise tests' binaries.
fn judge(m: &Manifest) -> (Vec<PathBuf>, BTreeSet<usize>) {
    let dir = work().join("judge");
    let crossing = wired_copy(&dir, m, |_| {});
    let mut args = vec![
        "test",
        "--locked",
        "--no-run",
        "--message-format=json",
        "-p",
        "whitted",
    ];
    for t in TARGETS {
        args.extend(["--test", t]);
    }
    let out = cargo(&dir, &args);
    let binaries = String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter_map(|v| v["executable"].as_str().map(PathBuf::from))
        .collect();
    (binaries, crossing)
}

/// A server built from the reference with `change`: its program.
fn server(m: &Manifest, change: impl FnOnce(&Path)) -> PathBuf {
    let dir = work().join("server");
    wired_copy(&dir, m, change);
    cargo(
        &dir,
        &[
            "build",
            "--locked",
            "-p",
            "whitted",
            "--example",
            SERVER_EXAMPLE,
        ],
    );
    let exe = work().join("target/debug/examples").join(SERVER_EXAMPLE);
    assert!(exe.is_file(), "{} was not built", exe.display());
    exe
}

/// Each exercise test of the judge's `binaries` (those of an exercise that crosses) run in a
/// process of its own against the server `exe`: its name and whether it passed, with its
/// output.
fn judged(
    m: &Manifest,
    binaries: &[PathBuf],
    crossing: &BTreeSet<usize>,
    exe: &Path,
) -> BTreeMap<String, (bool, String)> {
    judged_through(m, binaries, crossing, &exe.to_string_lossy(), &[])
}

/// [`judged`] with the server started by the command line `server` (its words separated by
/// `\x1f`), the judge's processes given `env` too.
fn judged_through(
    m: &Manifest,
    binaries: &[PathBuf],
    crossing: &BTreeSet<usize>,
    server: &str,
    env: &[(&str, &str)],
) -> BTreeMap<String, (bool, String)> {
    let mut results = BTreeMap::new();
    for bin in binaries {
        let list = Command::new(bin)
            .args(["--list", "--format", "terse"])
            .output()
            .unwrap();
        for line in String::from_utf8_lossy(&list.stdout).lines() {
            let Some(test) = line.strip_suffix(": test") else {
                continue;
            };
            let Some(e) = owner(m, test) else { continue };
            if !crossing.contains(&e) {
                continue;
            }
            let out = Command::new(bin)
                .args([test, "--exact", "--test-threads", "1"])
                .env(SERVER_VAR, server)
                .env(TEST_VAR, test)
                .envs(env.iter().copied())
                .output()
                .unwrap();
            results.insert(test.to_string(), (out.status.success(), common::text(&out)));
        }
    }
    results
}

/// The exercise a test is named after (its name after the module path begins `ex_NAME_`).
fn owner(m: &Manifest, test: &str) -> Option<usize> {
    let own = test.rsplit("::").next().unwrap_or(test);
    m.entries
        .iter()
        .position(|e| own.starts_with(&e.exercise.test_prefix()))
}

/// The tests that failed, by the exercise they are named after.
fn failed_by_exercise(
    m: &Manifest,
    results: &BTreeMap<String, (bool, String)>,
) -> BTreeMap<String, usize> {
    let mut by = BTreeMap::new();
    for (test, (passed, _)) in results {
        if !passed {
            let e = owner(m, test).unwrap();
            *by.entry(m.entries[e].exercise.name.clone()).or_default() += 1;
        }
    }
    by
}

/// Every exercise crosses the wire: the road's methods with their recorders' events,
/// `transmittance` with its items pulled one by one.
#[test]
fn every_exercise_crosses_the_wire() {
    let m = manifest();
    let dir = tempfile::tempdir().unwrap();
    copy(dir.path());
    let wired = add_wire(dir.path(), &m).unwrap();
    let kept: Vec<&str> = wired
        .kept
        .iter()
        .map(|(e, _)| m.entries[*e].exercise.name.as_str())
        .collect();
    assert!(kept.is_empty(), "{:?}", wired.kept);
    assert_eq!(wired.crossing.len() + kept.len(), m.entries.len());
}

/// Across the wire, the reference passes every test; each hand-written mutant, and each body
/// that forges a pass from inside its process, fails its own exercise's tests and no other's.
/// The reference and the forging bodies are judged again with their server in the grader's
/// sandbox, at both levels (as root, with bubblewrap, like `grade_build`).
#[test]
#[ignore = "builds the project twice and a server per submission, and runs the sandbox as root: .ci/run runs it"]
fn an_exercise_judged_across_the_wire_costs_only_its_own_tests() {
    let m = manifest();
    let (binaries, crossing) = judge(&m);
    assert!(binaries.len() >= TARGETS.len(), "{binaries:?}");

    let exe = server(&m, |_| {});
    let reference = judged(&m, &binaries, &crossing, &exe);
    let failing: Vec<(&String, &String)> = reference
        .iter()
        .filter(|(_, (p, _))| !p)
        .map(|(t, (_, o))| (t, o))
        .collect();
    assert!(
        failing.is_empty(),
        "the reference's server fails: {failing:#?}"
    );
    let tested: BTreeSet<usize> = reference.keys().filter_map(|t| owner(&m, t)).collect();
    assert_eq!(
        tested, crossing,
        "the exercises with tests judged across the wire"
    );
    println!(
        "the reference: {} exercise tests passed across the wire",
        reference.len()
    );
    for level in [Level::Namespaces, Level::User] {
        let results = in_sandbox(&m, &binaries, &crossing, &exe, level);
        let failing: Vec<&String> = results
            .iter()
            .filter(|(_, (p, _))| !p)
            .map(|(t, _)| t)
            .collect();
        assert_eq!(results.len(), reference.len(), "{level:?}");
        assert!(
            failing.is_empty(),
            "{level:?}: the reference's server in the sandbox fails: {failing:?}; e.g. {:?}",
            results.values().find(|(p, _)| !p)
        );
        println!(
            "the reference, its server in the sandbox ({level:?}): {} exercise tests passed",
            results.len()
        );
    }

    // a body that forges a pass: libtest's lines, a report, then its process ended with 0
    let forger = "ray_direction";
    let forged = format!(
        "    println!(\"test ch01_camera_rays::ex_{forger}_x ... ok\\n\\ntest result: ok. 1 passed; 0 failed\");\n    std::fs::write(std::env::temp_dir().join(\"results.json\"), \"{{\\\"score\\\": 119}}\").ok();\n    std::process::exit(0)"
    );
    // a body that asks the judge for its own exercise's value: the judge asks the server back
    let asker = "sphere_discriminant";
    let asks = format!(
        "    crate::judged::call::<_, Real>({}, &(ray, a, b))",
        index(&m, asker)
    );
    // (what, exercise, body, whether every one of the exercise's tests must fail)
    let mut cases: Vec<(String, String, String, bool)> = vec![
        (
            format!("forges libtest's ok, a report and exit 0 in {forger}"),
            forger.to_string(),
            forged,
            true,
        ),
        (
            format!("asks the judge for {asker}'s own value"),
            asker.to_string(),
            asks,
            true,
        ),
    ];
    for mu in mutants() {
        if crossing.contains(&index(&m, &mu.exercise)) {
            cases.push((
                mu.name.clone(),
                mu.exercise.clone(),
                mutant_body(&m, &mu),
                false,
            ));
        }
    }
    for (what, exercise, body, all) in cases {
        let exe = server(&m, |dir| set_body(dir, &m, &exercise, &body));
        let results = judged(&m, &binaries, &crossing, &exe);
        let by = failed_by_exercise(&m, &results);
        let own = by.get(&exercise).copied().unwrap_or(0);
        println!(
            "{what}: {own} of {exercise}'s tests fail; others failing: {:?}",
            {
                let mut o = by.clone();
                o.remove(&exercise);
                o
            }
        );
        assert!(
            own > 0,
            "{what}: none of {exercise}'s tests fails across the wire"
        );
        if all {
            let e = index(&m, &exercise);
            let total = results.keys().filter(|t| owner(&m, t) == Some(e)).count();
            assert_eq!(
                own, total,
                "{what}: {exercise}'s tests that fail, of its {total}: a forged pass passes none"
            );
            for level in [Level::Namespaces, Level::User] {
                let results = in_sandbox(&m, &binaries, &crossing, &exe, level);
                let by = failed_by_exercise(&m, &results);
                assert_eq!(
                    by,
                    BTreeMap::from([(exercise.clone(), total)]),
                    "{what}, its server in the sandbox ({level:?}): the tests that fail, by exercise"
                );
            }
        }
        let others: Vec<&String> = by.keys().filter(|e| **e != exercise).collect();
        assert!(
            others.is_empty(),
            "{what}: exercises other than {exercise} fail: {others:?}; e.g. {:?}",
            results.iter().find(|(t, (p, _))| !p
                && owner(&m, t).map(|e| &m.entries[e].exercise.name) != Some(&exercise))
        );
    }
}

/// [`judged`] with the server run by the grader's runner in its sandbox at `level`, as the
/// grader starts it (`whitted sandbox-run --serve SERVER`, the policy in the environment, a
/// slot of its own): the judge's pipes pass through the sandbox untouched. The server is
/// copied where the sandbox's user can run it.
fn in_sandbox(
    m: &Manifest,
    binaries: &[PathBuf],
    crossing: &BTreeSet<usize>,
    exe: &Path,
    level: Level,
) -> BTreeMap<String, (bool, String)> {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    let server = dir.path().join(SERVER_EXAMPLE);
    std::fs::copy(exe, &server).unwrap();
    let bwrap = ["/usr/bin/bwrap", "/bin/bwrap"]
        .into_iter()
        .map(PathBuf::from)
        .find(|p| p.exists())
        .expect("bubblewrap");
    // a block of users of this run's own, as a grading takes
    let lease = sandbox::Lease::take(10).expect("a block of sandbox users");
    let policy = sandbox::Policy {
        level,
        bwrap,
        uid: Some(sandbox::FIRST_UID + sandbox::SLOTS * lease.block),
        slot: 0,
        limits: sandbox::Limits::default(),
        read: Vec::new(),
        write: Vec::new(),
        timeout_ms: None,
    };
    let json = serde_json::to_string(&policy).unwrap();
    let line = format!(
        "{}\x1f{}\x1f{SERVE}\x1f{}",
        env!("CARGO_BIN_EXE_whitted"),
        sandbox::RUNNER_COMMAND,
        server.display()
    );
    judged_through(
        m,
        binaries,
        crossing,
        &line,
        &[
            (sandbox::POLICY_VAR, &json),
            ("NEXTEST_TEST_GLOBAL_SLOT", "7"),
        ],
    )
}
