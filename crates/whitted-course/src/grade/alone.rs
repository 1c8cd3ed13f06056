//! Each exercise judged alone: an exercise's tests run with the student's body for that
//! exercise and the reference's body for every other one, so that a mistake, a compile error
//! or a marker slip costs its own exercise and nothing else.
//!
//! The submission is built once. In the graded copy each graded exercise's region holds both
//! bodies, the student's first:
//!
//! ```text
//! // BEGIN SOLUTION sphere_coefficients
//! if crate::graded_bodies::student(11) {
//! {
//!     …the student's body…
//! }
//! } else {
//! {
//!     …the reference's body…
//! }
//! }
//! // END SOLUTION
//! ```
//!
//! and the crate gains the module `graded_bodies` ([`switch_module`]), which answers, once per
//! process, which exercise runs the student's body. The test runner names the test it starts in
//! [`GRADED_TEST_VAR`]: a test named after an exercise (`ex_NAME_…`) runs the student's body of
//! that exercise alone; any other test (the render paths, a chapter's whole picture) and any
//! program started without the variable (the chapter binaries the feedback renders with) runs
//! every body of the student's: their whole road, which the reports show beside the points.
//!
//! Each body keeps a block of its own, the final expression of its branch: there, as at the
//! top of a function's body, it may open with an inner attribute (`#![allow(…)]`).
//!
//! A student's body goes in only when it is whole on its own (its brackets, braces, quotes and
//! comments close inside it: [`whole_on_its_own`]), so it can never close the `if` around it and
//! reach the reference's body beside it.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;

use crate::manifest::Manifest;
use crate::{ToolError, files, layout};

/// The environment variable in which the test runner names the test a process runs (its libtest
/// name, module path and all): the graded copy's switch reads it.
pub const GRADED_TEST_VAR: &str = "WHITTED_GRADED_TEST";

/// The module the graded copy's crate gains (`crate::graded_bodies`).
const MODULE: &str = "graded_bodies";

/// How the graded copy judges the tests of an exercise.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Judging {
    /// Each exercise alone: its tests run with the student's body for it and the reference's
    /// for every other exercise.
    #[default]
    Alone,
    /// The whole road: every test runs with all of the student's bodies together, so that an
    /// exercise's tests fail too when an exercise they call is wrong (`--whole-road`).
    WholeRoad,
}

impl Judging {
    /// The line a report gives: how the tests were judged.
    #[must_use]
    pub fn line(self) -> &'static str {
        match self {
            Self::Alone => {
                "each exercise judged alone: its tests ran with your body for it and the reference's for every other exercise"
            }
            Self::WholeRoad => {
                "the whole road judged (--whole-road): every test ran with all of your bodies together, so a mistake also costs the exercises that call it"
            }
        }
    }
}

/// Whether `body` is whole on its own: it lexes as Rust tokens whose brackets and braces all
/// close inside it, and none of its strings or comments is left open.
#[must_use]
pub fn whole_on_its_own(body: &str) -> bool {
    body.parse::<proc_macro2::TokenStream>().is_ok()
}

/// The region's text in the graded copy when the exercise `entry` is judged alone: the
/// student's `body` and the `reference`'s side by side, each in a block of its own, chosen per
/// process by the switch; and the line (counted from the region's first line after BEGIN, from
/// 0) where the student's body ends: the `}` after it, where a syntax error in the body is
/// often reported.
#[must_use]
pub fn both_bodies(entry: usize, indent: &str, body: &str, reference: &str) -> (String, usize) {
    let ended = |s: &str| -> String {
        if s.is_empty() || s.ends_with('\n') {
            s.to_string()
        } else {
            format!("{s}\n")
        }
    };
    let student = ended(body);
    let text = format!(
        "{indent}if crate::{MODULE}::student({entry}) {{\n{indent}{{\n{student}{indent}}}\n{indent}}} else {{\n{indent}{{\n{}{indent}}}\n{indent}}}\n",
        ended(reference)
    );
    (text, 2 + student.lines().count())
}

/// The module the graded copy's crate gains: which exercise runs the student's body in this
/// process. Its names are the manifest's, in order, so that [`both_bodies`]' `entry` is the
/// manifest entry.
#[must_use]
pub fn switch_module(manifest: &Manifest) -> String {
    let names = quoted_prefixes(manifest);
    format!(
        r#"
/// Written by `whitted grade` into its graded copy: which exercise runs the student's body in
/// this process. The test runner names the test in `{GRADED_TEST_VAR}`: a test named after an
/// exercise runs the student's body of that exercise and the reference's of every other one;
/// any other test, and a program started without the variable, runs every body of the student's.
#[doc(hidden)]
pub mod {MODULE} {{
    /// Each exercise's test prefix (`ex_NAME_`), in the manifest's order.
    const PREFIXES: [&str; {count}] = [{names}];

    /// The exercise judged alone in this process, `None` for the student's whole road: read
    /// once.
    static JUDGED: std::sync::OnceLock<Option<usize>> = std::sync::OnceLock::new();

    /// Whether exercise `entry` (the manifest's order) runs the student's body here.
    #[must_use]
    pub fn student(entry: usize) -> bool {{
        JUDGED.get_or_init(judged).is_none_or(|j| j == entry)
    }}

    fn judged() -> Option<usize> {{
        let test = std::env::var("{GRADED_TEST_VAR}").ok()?;
        let own = test.rsplit("::").next().unwrap_or(&test);
        PREFIXES.iter().position(|p| own.starts_with(p))
    }}
}}
"#,
        count = names.len(),
        names = names.join(", "),
    )
}

/// Each exercise's test prefix (`ex_NAME_`) as a Rust string literal, in the manifest's order:
/// what the code written into a graded copy names the exercises by.
pub(super) fn quoted_prefixes(manifest: &Manifest) -> Vec<String> {
    manifest
        .entries
        .iter()
        .map(|e| format!("{:?}", e.exercise.test_prefix()))
        .collect()
}

/// Appends the switch ([`switch_module`]) to the graded copy's `lib.rs`, which the copy's sync
/// has just made the instructor's again: so each grading writes it once, and the crate, rebuilt
/// for the submission's bodies anyway, is rebuilt for nothing more.
pub(super) fn add_switch(project: &Path, manifest: &Manifest) -> Result<(), ToolError> {
    let lib = project.join(layout::core_src()).join("lib.rs");
    let text = std::fs::read_to_string(&lib).map_err(|e| ToolError::io(&lib, e))?;
    let module = switch_module(manifest);
    files::write_if_changed(&lib, format!("{text}{module}").as_bytes()).map(|_| ())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A body is whole when its delimiters, strings and comments close inside it: one that
    /// would close the `if` around it and reach the reference's body is not.
    #[test]
    fn a_body_that_could_close_its_block_is_not_whole() {
        for (body, whole) in [
            ("    let a = 1.0;\n    a * 2.0\n", true),
            ("    x // a comment } else {\n", true),
            ("    \"} else {\"\n", true),
            ("    } else { } if false {\n", false),
            ("    todo!() }\n", false),
            ("    /* open comment\n", false),
            ("    r#\"open raw string\n", false),
        ] {
            assert_eq!(whole_on_its_own(body), whole, "{body:?}");
        }
    }

    /// The student's body comes first, under the switch, the reference's after `else`, each in
    /// a block of its own; the line after the student's body closes its block.
    #[test]
    fn both_bodies_stand_side_by_side_under_the_switch() {
        let (text, end) = both_bodies(3, "    ", "    a + b\n", "    a - b");
        assert_eq!(
            text,
            "    if crate::graded_bodies::student(3) {\n    {\n    a + b\n    }\n    } else {\n    {\n    a - b\n    }\n    }\n"
        );
        assert_eq!(text.lines().nth(end), Some("    }"), "{text}");
        assert_eq!(text.lines().nth(end - 1), Some("    a + b"), "{text}");
    }

    /// Both bodies compile side by side, the student's opening with an inner attribute as a
    /// function's body may, and each runs where the switch says: rustc itself builds a crate
    /// of the two and its switch.
    #[test]
    fn a_body_that_opens_with_an_inner_attribute_compiles_beside_the_reference() {
        let (both, _) = both_bodies(
            0,
            "    ",
            "    #![allow(unused_variables)]\n    let unused = 1.0;\n    x * 2.0",
            "    x + 1.0",
        );
        let source = format!(
            "#![deny(unused_variables)]\nmod graded_bodies {{ pub fn student(_: usize) -> bool {{ std::env::args().count() > 1 }} }}\nfn f(x: f64) -> f64 {{\n{both}}}\nfn main() {{ println!(\"{{}}\", f(3.0)); }}\n"
        );
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("both.rs");
        std::fs::write(&file, &source).unwrap();
        let exe = dir.path().join("both");
        let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
        let built = std::process::Command::new(rustc)
            .args(["--edition", "2024", "-o"])
            .arg(&exe)
            .arg(&file)
            .output()
            .unwrap();
        assert!(
            built.status.success(),
            "{}\n{source}",
            String::from_utf8_lossy(&built.stderr)
        );
        let run = |args: &[&str]| {
            let out = std::process::Command::new(&exe)
                .args(args)
                .output()
                .unwrap();
            String::from_utf8_lossy(&out.stdout).trim().to_string()
        };
        assert_eq!(run(&[]), "4", "the reference's body");
        assert_eq!(run(&["student"]), "6", "the student's body");
    }
}
