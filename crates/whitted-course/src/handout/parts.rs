//! What becomes of each file of the project in a handout: left out, copied, or written anew.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;

use crate::layout;

/// What becomes of a project file in a handout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// Left out: the instructor's (tools, benchmarks, CI, mutation and grading tests, hidden
    /// tests, the instructor's guide) or not needed without mdBook.
    Left,
    /// Copied as it is (or with its exercises' bodies taken out).
    Copied,
    /// A page of the course book, written with every `{{#include …}}` replaced by what it
    /// includes, so that it reads without mdBook.
    Page,
    /// The workspace's manifest, written with only the crates a handout holds.
    Workspace,
    /// Replaced by the student's README.
    Readme,
    /// Cargo's configuration, written with only the alias a student uses (`cargo learn`).
    CargoConfig,
}

/// What becomes of the project file `file` (relative to `root`) in a handout whose test
/// targets are `tests`: the renderer with the listed test targets (and the helper directories
/// of its `tests/` without a `main.rs`, such as `common/` and `golden/`), the chapter binaries,
/// the course tools without their tests, the chapters, the scenes and the book's pages.
#[must_use]
pub fn part_of(file: &Path, tests: &[String], root: &Path) -> Part {
    let path = file.to_string_lossy().replace('\\', "/");
    let under = |dir: &str| path.strip_prefix(dir).and_then(|r| r.strip_prefix('/'));
    if path == "Cargo.toml" {
        return Part::Workspace;
    }
    if path == "README.md" {
        return Part::Readme;
    }
    if path == ".cargo/config.toml" {
        return Part::CargoConfig;
    }
    if matches!(path.as_str(), "Cargo.lock" | ".gitignore") {
        return Part::Copied;
    }
    if let Some(rest) = under(&layout::core_tests().to_string_lossy()) {
        let (first, more) = match rest.split_once('/') {
            Some((a, b)) => (a, Some(b)),
            None => (rest, None),
        };
        let listed = |name: &str| tests.iter().any(|t| t == name);
        let keep = match more {
            // tests/NAME.rs is a test target
            None => first.strip_suffix(".rs").is_some_and(listed),
            // tests/NAME/…: a target when it has a main.rs, else helpers
            Some(_) => {
                !root
                    .join(layout::core_tests())
                    .join(first)
                    .join("main.rs")
                    .is_file()
                    || listed(first)
            }
        };
        return if keep { Part::Copied } else { Part::Left };
    }
    if under(layout::CORE).is_some() {
        return Part::Copied;
    }
    for krate in [layout::SYLLABUS, layout::APP, layout::LEARN] {
        if let Some(rest) = under(krate) {
            return if rest.starts_with("tests/") {
                Part::Left
            } else {
                Part::Copied
            };
        }
    }
    if under("chapters").is_some() || under("scenes").is_some() {
        return Part::Copied;
    }
    // the book's figures' list: `cargo learn` draws a figure as the student's code does
    if path == whitted_learn::figures::FIGURES {
        return Part::Copied;
    }
    if let Some(rest) = under("docs/src") {
        let instructor = rest == "instructor-guide.md";
        let unneeded = rest.starts_with("katex/") || rest.ends_with(".json");
        return match () {
            _ if instructor || unneeded => Part::Left,
            _ if rest.ends_with(".md") => Part::Page,
            _ => Part::Copied,
        };
    }
    Part::Left
}
