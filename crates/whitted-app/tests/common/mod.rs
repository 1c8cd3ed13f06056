//! What the tests of the programs share: the workspace's root, and the chapter binaries found
//! by their chapter (their names are the syllabus's, so no test lists them).

// each test file uses only some of these
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use whitted::render::Chapter;

/// The workspace's root: this crate sits in `crates/whitted-app`.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("the crate sits two levels below the workspace's root")
        .to_path_buf()
}

/// The built binary named `name`. Cargo builds a package's binaries before its integration
/// tests, into the directory above the tests' own (`target/debug/deps/..`).
pub fn exe_named(name: &str) -> PathBuf {
    let test = std::env::current_exe().expect("the test knows its own path");
    let dir = test
        .parent()
        .and_then(Path::parent)
        .expect("the test runs from target/PROFILE/deps");
    let path = dir.join(format!("{name}{}", std::env::consts::EXE_SUFFIX));
    assert!(
        path.is_file(),
        "no binary {} (cargo test builds every binary of the package first)",
        path.display()
    );
    path
}

/// The built binary of `chapter`.
pub fn exe(chapter: Chapter) -> PathBuf {
    exe_named(chapter.about().binary)
}

/// The chapter's own scene, as a path from the workspace's root.
pub fn scene(chapter: Chapter) -> PathBuf {
    root().join(chapter.about().scene())
}

/// Runs `exe` with `args` in `dir`.
pub fn run(exe: &Path, args: &[&str], dir: &Path) -> Output {
    Command::new(exe)
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("{} does not run: {e}", exe.display()))
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
