//! What the course tools' tests share: the project, its manifest, copies of the
//! reference with one body changed, and the hand-written mutants.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

use whitted_course::manifest::{self, Manifest};
use whitted_course::{files, handout};

/// The workspace's root: this crate sits in `crates/whitted-course`.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("the crate sits two levels below the workspace's root")
        .to_path_buf()
}

/// The project's manifest.
pub fn manifest() -> Manifest {
    manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap()
}

/// The entry of the exercise named `name`.
pub fn index(m: &Manifest, name: &str) -> usize {
    m.by_name(name)
        .unwrap_or_else(|| panic!("no exercise named {name}"))
}

/// A copy of the reference project at `to`.
pub fn copy(to: &Path) {
    for f in files::project_files(&root()).unwrap() {
        let dest = to.join(&f);
        std::fs::create_dir_all(dest.parent().unwrap()).unwrap();
        std::fs::copy(root().join(&f), dest).unwrap();
    }
}

/// Replaces the body of the exercise named `id` in the copy at `dir` with `body`.
pub fn set_body(dir: &Path, m: &Manifest, id: &str, body: &str) {
    let r = &handout::regions(&root(), m).unwrap()[index(m, id)];
    let path = dir.join(&r.file);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.contains(&r.solution),
        "exercise {id}: the body is not in the copy"
    );
    std::fs::write(&path, text.replacen(&r.solution, &format!("{body}\n"), 1)).unwrap();
}

/// A mistake we expect (`crates/whitted-course/tests/mutants/hand-written.toml`).
pub use whitted_course::mistakes::Mutant;

/// The body of the mutant `mu`: its exercise's reference body with the change.
pub fn mutant_body(m: &Manifest, mu: &Mutant) -> String {
    let r = &handout::regions(&root(), m).unwrap()[index(m, &mu.exercise)];
    whitted_course::mistakes::mutated(r, mu)
        .unwrap_or_else(|e| panic!("{e}"))
        .trim_end()
        .to_string()
}

/// The hand-written mutants.
pub fn mutants() -> Vec<Mutant> {
    whitted_course::mistakes::load(&root()).unwrap()
}

/// The error a refused command printed, once the contract every whitted program keeps is
/// checked: exit status 2 and exactly one line on stderr (`context` names the case in a
/// failure's message).
pub fn one_line_error(o: &std::process::Output, context: &str) -> String {
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{context}: {err}");
    assert_eq!(err.lines().count(), 1, "{context}: {err}");
    err
}

/// A process's output, stdout then stderr, as text (for a failure's message).
pub fn text(o: &std::process::Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

/// The tests of one test executable's run (`out`, of the test target `target`), as
/// `target::name`, into `failed` and `passed`; panics with its output when libtest did not
/// finish (no summary line).
pub fn sort_outcomes(
    target: &str,
    out: &std::process::Output,
    failed: &mut std::collections::BTreeSet<String>,
    passed: &mut std::collections::BTreeSet<String>,
) {
    use whitted_course::cargo::{TestOutcome, parse_libtest};
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("test result:"),
        "{target} did not finish: {stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for (name, outcome) in parse_libtest(&stdout) {
        let id = format!("{target}::{name}");
        match outcome {
            TestOutcome::Failed => failed.insert(id),
            TestOutcome::Passed => passed.insert(id),
            TestOutcome::Ignored => false,
        };
    }
}
