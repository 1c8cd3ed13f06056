//! Where things are in a whitted project: the one place that knows the workspace's shape.
//!
//! ```text
//! Cargo.toml                  the workspace
//! crates/whitted/             the renderer: src/ holds the exercises, tests/ the student's tests
//! crates/whitted-app/         the chapter binaries (src/bin/chNN_name.rs) and the window
//! crates/whitted-learn/       the student's loop (`cargo learn`)
//! crates/whitted-course/      the instructor's tools (`whitted formulas`, `handout`, `grade` …)
//! chapters/                   the chapters' READMEs, formulas.toml, exercise-tests.toml
//! scenes/                     the scenes, one per chapter
//! ```
//!
//! Every path here is relative to the project's root, the workspace's directory; a handout has
//! the same shape, without the instructor's files.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};

/// The marker line that opens an exercise's solution region, followed by the exercise's name:
/// `// BEGIN SOLUTION sphere_coefficients`.
pub const BEGIN: &str = "// BEGIN SOLUTION";
/// The marker line that closes it.
pub const END: &str = "// END SOLUTION";

/// The course's outline (the chapters), which every other crate reads.
pub const SYLLABUS: &str = "crates/whitted-syllabus";
/// The renderer's crate: what a student writes, and the tests that check it.
pub const CORE: &str = "crates/whitted";
/// The renderer's package name, as `cargo -p` takes it.
pub const CORE_PACKAGE: &str = "whitted";
/// The chapter binaries' crate.
pub const APP: &str = "crates/whitted-app";
/// The chapter binaries' package name.
pub const APP_PACKAGE: &str = "whitted-app";
/// The student's loop (`cargo learn`), which a handout holds.
pub const LEARN: &str = "crates/whitted-learn";
/// The student's loop's package name.
pub const LEARN_PACKAGE: &str = "whitted-learn";
/// The instructor's course tools, which a handout does not hold.
pub const COURSE: &str = "crates/whitted-course";

/// A path of this file's constants (written with `/`) with the system's separator between its
/// parts, so that a path shown to a student is written one way: `crates\whitted\src\light.rs`
/// on Windows, not `crates/whitted\src\light.rs`.
#[must_use]
pub fn native(path: &str) -> PathBuf {
    path.split('/').collect()
}

/// The renderer's sources, where every exercise is (`crates/whitted/src`).
#[must_use]
pub fn core_src() -> PathBuf {
    native(CORE).join("src")
}

/// The renderer's crate root file (`crates/whitted/src/lib.rs`).
#[must_use]
pub fn core_lib() -> PathBuf {
    core_src().join("lib.rs")
}

/// The renderer's integration tests (`crates/whitted/tests`).
#[must_use]
pub fn core_tests() -> PathBuf {
    native(CORE).join("tests")
}

/// The file of the test target `name` of the renderer (`crates/whitted/tests/NAME.rs`), where a
/// new target is written.
#[must_use]
pub fn core_test_file(name: &str) -> PathBuf {
    core_tests().join(format!("{name}.rs"))
}

/// The root file of the renderer's test target `name` in the project at `root`, as cargo finds
/// it: `crates/whitted/tests/NAME.rs`, or `crates/whitted/tests/NAME/main.rs` for a target of
/// several files (relative to `root`).
#[must_use]
pub fn core_test_target(root: &Path, name: &str) -> PathBuf {
    let dir = core_tests().join(name).join("main.rs");
    if root.join(&dir).is_file() {
        dir
    } else {
        core_test_file(name)
    }
}

/// The nearest directory at or above `start` that is a whitted project (a `Cargo.toml` beside
/// the renderer's crate), else the nearest with a `Cargo.toml`.
#[must_use]
pub fn find_root(start: &Path) -> Option<PathBuf> {
    let mut any = None;
    for dir in start.ancestors() {
        if dir.join("Cargo.toml").is_file() {
            if dir.join(CORE).join("Cargo.toml").is_file() {
                return Some(dir.to_path_buf());
            }
            any.get_or_insert_with(|| dir.to_path_buf());
        }
    }
    any
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A path shown to a student has one separator, the system's, between every part.
    #[test]
    fn a_shown_path_is_written_with_one_separator() {
        let file = core_src().join("light.rs");
        let parts: Vec<_> = file
            .iter()
            .map(|p| p.to_string_lossy().into_owned())
            .collect();
        assert_eq!(
            parts,
            ["crates", "whitted", "src", "light.rs"],
            "{}",
            file.display()
        );
        let sep = std::path::MAIN_SEPARATOR;
        let shown = file.display().to_string();
        assert_eq!(shown, format!("crates{sep}whitted{sep}src{sep}light.rs"));
        assert_eq!(
            core_test_file("ch03_shading").display().to_string(),
            format!("crates{sep}whitted{sep}tests{sep}ch03_shading.rs")
        );
    }
}
